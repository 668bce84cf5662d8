//! How the lifted results are evaluated ([`Mode`]): the ring of step 8 as polynomials in P0 and
//! delta_a ([`InP0`], to build the criterion polynomials) or as polynomials in delta_a at one
//! roll rate ([`AtP0`], to evaluate them there tightly through the trim) or over a piece of roll
//! rates with their derivative in it ([`OverPiece`], for mean-value forms along a branch).

use super::compiled::Cleared;
use super::dense::{Dense, Dense2};
use super::elimination::{Coeff, Scalar};
use super::isolate::Uncertified;
use super::num::Num;
use super::slope::InRollRate;
use crate::derivation::{Clearing, TrimProducts};
use crate::interval::I;
use std::borrow::Cow;

/// How the lifted results are evaluated: the ring of step 8 (polynomials in delta_a over
/// [`Mode::Coef`]) and the lift of a lifted polynomial into it.
pub(super) trait Mode: Clearing {
    /// The numbers.
    type Num: Num;
    /// Coefficients of the polynomials in delta_a.
    type Coef: Coeff;
    /// A lifted result as a value of the ring.
    fn lifted(&self, p: &Dense2<Self::Num>) -> Self::Value {
        self.lifted_ref(p).into_owned()
    }
    /// [`Mode::lifted`], borrowed where the value is the lifted result itself.
    fn lifted_ref<'a>(&self, p: &'a Dense2<Self::Num>) -> Cow<'a, Self::Value>;
    /// The coefficients of `delta_a^0, delta_a^1, ...` (trailing exact zeros dropped).
    fn in_aileron(v: &Self::Value) -> Vec<Self::Coef>;
    /// Step 8 of a grouped result whose group coefficients are `lifted`, on the trim of
    /// `products` (extended and reused).
    fn clear_with(
        &mut self,
        c: &Cleared,
        lifted: &[Dense2<Self::Num>],
        num: &[Self::Value],
        den: &Self::Value,
        products: &mut TrimProducts<Self::Value>,
    ) -> Self::Value
    where
        Self: Sized,
    {
        c.groups
            .clear_with(self, num, den, products, |m, i| m.lifted_ref(&lifted[i]))
    }
    /// The value when delta_a does not occur.
    fn univariate(v: &Self::Value) -> Result<Self::Coef, Uncertified> {
        let mut c = Self::in_aileron(v);
        match c.len() {
            0 => Ok(Self::Coef::zero()),
            1 => Ok(c.remove(0)),
            _ => Err(Uncertified::Degenerate),
        }
    }
}

/// Whether a trim with numerators `num` is the origin: every numerator exactly zero (the
/// zero-sideslip trim at `delta_e = 0`, whose numerators of Eq. 35 are multiples of it).
pub(super) fn at_origin<M: Mode>(num: &[M::Value]) -> bool {
    num.iter().all(|n| M::in_aileron(n).is_empty())
}

/// A constant step 8 lifts through the ring (only 0 and 1: the coefficients come lifted).
pub(super) fn constant(p: &crate::algebra::Poly) -> I {
    let c = p
        .as_constant()
        .expect("step 8 lifts only constants through the ring");
    match c.as_i64() {
        Some(n) if n.unsigned_abs() <= 1 << 53 => I::point(n as f64),
        _ => I::from_q(&c.to_big()),
    }
}

/// The criterion polynomials in P0 (and delta_a): values are [`Dense2`].
pub(super) struct InP0<T>(std::marker::PhantomData<T>);

impl<T> InP0<T> {
    pub(super) fn new() -> InP0<T> {
        InP0(std::marker::PhantomData)
    }
}

impl<T: Num> Clearing for InP0<T> {
    type Value = Dense2<T>;
    fn lift(&mut self, p: &crate::algebra::Poly) -> Dense2<T> {
        Dense2::new(vec![Dense::constant(T::constant(constant(p)))])
    }
    fn add(&mut self, a: &Dense2<T>, b: &Dense2<T>) -> Dense2<T> {
        a.add(b)
    }
    fn mul(&mut self, a: &Dense2<T>, b: &Dense2<T>) -> Dense2<T> {
        a.mul(b)
    }
    fn add_product(&mut self, acc: &mut Dense2<T>, a: &Dense2<T>, b: &Dense2<T>) {
        acc.add_product(a, b);
    }
}

impl<T: Num> Mode for InP0<T> {
    type Num = T;
    type Coef = Dense<T>;
    fn lifted_ref<'a>(&self, p: &'a Dense2<T>) -> Cow<'a, Dense2<T>> {
        Cow::Borrowed(p)
    }
    fn in_aileron(v: &Dense2<T>) -> Vec<Dense<T>> {
        v.0.clone()
    }
}

/// The criterion at one roll rate `.0`: values are polynomials in delta_a ([`Da`]).
pub(super) struct AtP0<T>(pub(super) T);

/// A polynomial in delta_a of degree at most 3 (no allocation).
#[derive(Clone, Copy, Debug)]
pub(super) struct Da<T> {
    pub(super) c: [T; 4],
    pub(super) len: usize,
}

impl<T: Num> Da<T> {
    pub(super) fn new(c: [T; 4]) -> Da<T> {
        let len = Da::degree_bound(&c);
        Da { c, len }
    }

    /// How many coefficients are left when the trailing exact zeros of `c` are dropped.
    fn degree_bound(c: &[T; 4]) -> usize {
        c.iter()
            .rposition(|x| !x.is_exact_zero())
            .map_or(0, |i| i + 1)
    }

    pub(super) fn anything() -> Da<T> {
        Da::new([T::constant(I::entire()); 4])
    }

    /// A constant of step 8.
    pub(super) fn lift(p: &crate::algebra::Poly) -> Da<T> {
        let mut c = [T::constant(I::point(0.0)); 4];
        c[0] = T::constant(constant(p));
        Da::new(c)
    }

    pub(super) fn add(&self, b: &Da<T>) -> Da<T> {
        Da::new(std::array::from_fn(|i| self.c[i] + b.c[i]))
    }

    pub(super) fn mul(&self, b: &Da<T>) -> Da<T> {
        let mut c = [T::constant(I::point(0.0)); 4];
        for i in 0..self.len {
            for j in 0..b.len {
                // Step 8's products stay within degree 3 in delta_a (trim numerators are affine
                // in it, every trim quantity at most quadratic in the trim states); a product
                // beyond would be no value at all, never a truncated one.
                let Some(slot) = c.get_mut(i + j) else {
                    return Da::anything();
                };
                slot.add_product_assign(&self.c[i], &b.c[j]);
            }
        }
        Da::new(c)
    }

    /// `self + a b` in place, by the same interval operations as [`Da::mul`] then [`Da::add`]
    /// (each coefficient of the product summed from 0 in the same order, then added), without
    /// the two polynomials in between.
    fn add_product(&mut self, a: &Da<T>, b: &Da<T>) {
        if a.len > 0 && b.len > 0 && a.len + b.len > 5 {
            let term = a.mul(b);
            *self = self.add(&term);
            return;
        }
        for k in 0..4 {
            let mut t = T::constant(I::point(0.0));
            for i in 0..a.len.min(k + 1) {
                if k - i < b.len {
                    t.add_product_assign(&a.c[i], &b.c[k - i]);
                }
            }
            self.c[k] = self.c[k] + t;
        }
        self.len = Da::degree_bound(&self.c);
    }

    /// The value at the aileron `da`.
    pub(super) fn at(&self, da: T) -> T {
        super::dense::horner(&self.c[..self.len], da)
    }
}

impl<T: Num> Clearing for AtP0<T> {
    type Value = Da<T>;
    fn lift(&mut self, p: &crate::algebra::Poly) -> Da<T> {
        Da::lift(p)
    }
    fn add(&mut self, a: &Da<T>, b: &Da<T>) -> Da<T> {
        a.add(b)
    }
    fn mul(&mut self, a: &Da<T>, b: &Da<T>) -> Da<T> {
        a.mul(b)
    }
    fn add_product(&mut self, acc: &mut Da<T>, a: &Da<T>, b: &Da<T>) {
        acc.add_product(a, b);
    }
}

impl<T: Num> Mode for AtP0<T> {
    type Num = T;
    type Coef = Scalar<T>;
    fn lifted_ref<'a>(&self, p: &'a Dense2<T>) -> Cow<'a, Da<T>> {
        Cow::Owned(in_aileron_each(&p.0, |c| c.eval(self.0)))
    }
    fn in_aileron(v: &Da<T>) -> Vec<Scalar<T>> {
        v.c[..v.len].iter().map(|c| Scalar(*c)).collect()
    }
}

/// The criterion over a piece of roll rates `x` with its derivatives in the roll rate (numbers
/// `T`, a [`super::slope::Slope`] or [`super::slope::Taylor2`]): values are polynomials in
/// delta_a with such coefficients, lifted from the same interval results as [`AtP0`].
pub(super) struct OverPiece<T> {
    x: I,
    of: std::marker::PhantomData<T>,
}

impl<T> OverPiece<T> {
    /// Over the roll rates `x`.
    pub(super) fn over(x: I) -> OverPiece<T> {
        OverPiece {
            x,
            of: std::marker::PhantomData,
        }
    }
}

impl<T: InRollRate> Clearing for OverPiece<T> {
    type Value = Da<T>;
    fn lift(&mut self, p: &crate::algebra::Poly) -> Da<T> {
        Da::lift(p)
    }
    fn add(&mut self, a: &Da<T>, b: &Da<T>) -> Da<T> {
        a.add(b)
    }
    fn mul(&mut self, a: &Da<T>, b: &Da<T>) -> Da<T> {
        a.mul(b)
    }
}

impl<T: InRollRate> Mode for OverPiece<T> {
    type Num = I;
    type Coef = Scalar<T>;
    fn lifted_ref<'a>(&self, p: &'a Dense2<I>) -> Cow<'a, Da<T>> {
        Cow::Owned(in_aileron_each(&p.0, |c| T::polynomial(&c.0, self.x)))
    }
    fn in_aileron(v: &Da<T>) -> Vec<Scalar<T>> {
        v.c[..v.len].iter().map(|c| Scalar(*c)).collect()
    }
}

/// The polynomial in delta_a whose coefficients are `f` of each of `coefs` (lowest degree
/// first), or [`Da::anything`] beyond the degree a [`Da`] holds: how the pointwise and the
/// piecewise modes lift a result in P0 and delta_a.
pub(super) fn in_aileron_each<C, T: Num>(coefs: &[C], f: impl Fn(&C) -> T) -> Da<T> {
    if coefs.len() > 4 {
        return Da::anything();
    }
    let mut out = [T::constant(I::point(0.0)); 4];
    for (o, c) in out.iter_mut().zip(coefs) {
        *o = f(c);
    }
    Da::new(out)
}
