//! The coefficient rings of the criterion polynomials in delta_a ([`Coeff`]: polynomials in P0,
//! or numbers at one roll rate) and the elimination of the aileron by the resultant with the
//! trim condition ([`eliminate`]), written once over both.

use super::dense::Dense;
use super::isolate::Uncertified;
use super::num::Num;
use crate::interval::I;

/// The coefficient rings of the criterion polynomials in delta_a: polynomials in P0
/// ([`Dense`]) when the polynomials are built, numbers ([`Num`]) when they are evaluated at
/// one roll rate. [`eliminate`] is written once over both.
pub trait Coeff: Clone {
    /// `a + b`.
    fn add(&self, o: &Self) -> Self;
    /// `a - b`.
    fn sub(&self, o: &Self) -> Self;
    /// `a * b`.
    fn mul(&self, o: &Self) -> Self;
    /// `a^k`.
    fn pow(&self, k: u32) -> Self;
    /// `a / d` for an exact division (`None` when it cannot be certified).
    fn div_exact(&self, d: &Self) -> Option<Self>;
    /// Zero.
    fn zero() -> Self;
    /// The constant `c`.
    fn constant(c: I) -> Self;
}

impl<T: Num> Coeff for Dense<T> {
    fn add(&self, o: &Dense<T>) -> Dense<T> {
        Dense::add(self, o)
    }
    fn sub(&self, o: &Dense<T>) -> Dense<T> {
        Dense::sub(self, o)
    }
    fn mul(&self, o: &Dense<T>) -> Dense<T> {
        Dense::mul(self, o)
    }
    fn pow(&self, k: u32) -> Dense<T> {
        Dense::pow(self, k)
    }
    fn div_exact(&self, d: &Dense<T>) -> Option<Dense<T>> {
        Dense::div_exact(self, d)
    }
    fn zero() -> Dense<T> {
        Dense::zero()
    }
    fn constant(c: I) -> Dense<T> {
        Dense::constant(T::constant(c))
    }
}

/// A number as a [`Coeff`] (the ring of values at one roll rate).
#[derive(Clone, Copy, Debug)]
pub struct Scalar<T>(pub T);

impl<T: Num> Coeff for Scalar<T> {
    fn add(&self, o: &Self) -> Self {
        Scalar(self.0 + o.0)
    }
    fn sub(&self, o: &Self) -> Self {
        Scalar(self.0 - o.0)
    }
    fn mul(&self, o: &Self) -> Self {
        Scalar(self.0 * o.0)
    }
    fn pow(&self, k: u32) -> Self {
        Scalar(self.0.powi(k))
    }
    fn div_exact(&self, d: &Self) -> Option<Self> {
        self.0.div(d.0).map(Scalar)
    }
    fn zero() -> Self {
        Scalar(T::constant(I::point(0.0)))
    }
    fn constant(c: I) -> Self {
        Scalar(T::constant(c))
    }
}

/// The resultant in delta_a of the trim condition `g` and a trim quantity `f` (the enclosure of
/// [`crate::derivation::eliminate_aileron`] on numeric data, up to sign): `f` itself when
/// delta_a does not occur in `f` and `g` is linear in it; `g1^n f(-g0/g1)` for a linear `g`;
/// for a quadratic `g` and `f` (aileron yaw) Bezout's form
/// `(g2 f0 - g0 f2)^2 - (g2 f1 - g1 f2)(g1 f0 - g0 f1)`, divided by `det(A)^4`, which divides the
/// resultant of every aircraft with aileron yaw (Jacobi's identity for the 2x2 minors of
/// adj(A): the delta_a-parts of the trim numerators are columns of adj(A)).
pub fn eliminate<C: Coeff>(g: &[C], f: &[C], det_a: &C) -> Result<C, Uncertified> {
    let (Some(dg), Some(df)) = (g.len().checked_sub(1), f.len().checked_sub(1)) else {
        return Err(Uncertified::Degenerate);
    };
    let at = |p: &[C], i: usize| p.get(i).cloned().unwrap_or_else(C::zero);
    match (dg, df) {
        // f free of delta_a (no aileron yaw): the resultant is f itself, kept as it is (each
        // product by the exact 1 = g1^0 would widen it by an ulp).
        (1, 0) => Ok(f[0].clone()),
        (1, _) => {
            // g1^n f(-g0 / g1) = sum_i f_i (-g0)^i g1^(n - i).
            let (g0, g1) = (C::zero().sub(&g[0]), &g[1]);
            Ok((0..=df).fold(C::zero(), |acc, i| {
                acc.add(&f[i].mul(&g0.pow(i as u32)).mul(&g1.pow((df - i) as u32)))
            }))
        }
        // Every trim quantity of the criterion (det J5, d) is quadratic in delta_a with aileron
        // yaw; the factor det(A)^4 is established for that case only.
        (2, 2) => {
            let (g0, g1, g2) = (&g[0], &g[1], &g[2]);
            let (f0, f1, f2) = (at(f, 0), at(f, 1), at(f, 2));
            let a = g2.mul(&f0).sub(&g0.mul(&f2));
            let b = g2.mul(&f1).sub(&g1.mul(&f2));
            let c = g1.mul(&f0).sub(&g0.mul(&f1));
            let res = a.mul(&a).sub(&b.mul(&c));
            res.div_exact(&det_a.pow(4)).ok_or(Uncertified::Degenerate)
        }
        _ => Err(Uncertified::Degenerate),
    }
}
