//! The numbers the criterion polynomials are built and evaluated in: intervals ([`I`], one
//! aircraft's data enclosed) and intervals with a gradient ([`Dual`], a box of uncertain data,
//! for mean-value enclosures). One construction serves both: it is written over [`Num`].
//!
//! ```
//! use model::certified::num::Dual;
//! use model::interval::I;
//!
//! // f(x, y) = x y + x over x in [1, 2], y in [3, 4]: the value and both partial derivatives
//! // (df/dx = y + 1, df/dy = x) enclosed, outward-rounded.
//! let x = Dual::variable(I::new(1.0, 2.0), 0, 2);
//! let y = Dual::variable(I::new(3.0, 4.0), 1, 2);
//! let f = x * y + x;
//! let holds = |i: I, lo: f64, hi: f64| i.lo <= lo && i.hi >= hi && i.hi - i.lo < hi - lo + 1e-12;
//! assert!(holds(f.v, 4.0, 10.0) && holds(f.g[0], 4.0, 5.0) && holds(f.g[1], 1.0, 2.0));
//! ```

use crate::interval::I;
use std::fmt::Debug;
use std::ops::{Add, Mul, Neg, Sub};

/// Arithmetic the criterion's construction needs; every result encloses the exact result on
/// any reals the operands enclose.
pub trait Num:
    Copy + Debug + Add<Output = Self> + Sub<Output = Self> + Mul<Output = Self> + Neg<Output = Self>
{
    /// An exact constant, given by its enclosure (independent of any uncertain parameter).
    fn constant(c: I) -> Self;
    /// Whether this is an exact zero: a structural zero (a term of a parameter that is exactly
    /// zero), which polynomials drop from their top so that degrees stay exact.
    fn is_exact_zero(&self) -> bool;
    /// Whether the value may be zero.
    fn may_vanish(&self) -> bool;
    /// `self / o`, or `None` when `o` may vanish.
    fn div(self, o: Self) -> Option<Self>;
    /// The common part of two enclosures of the same value (`None` if they are disjoint, which
    /// only a wrong enclosure can give).
    fn meet(self, o: Self) -> Option<Self>;
    /// The square root, or `None` when the value may be negative.
    fn sqrt(self) -> Option<Self>;
    /// The enclosure alone, when that is all the number carries (an [`I`]; `None` for a
    /// [`Dual`], whose gradient a plain enclosure would drop): what allows evaluations in f64
    /// with a rounding error bound instead of interval operations
    /// ([`super::compiled::Compiled::lift`]).
    fn interval(&self) -> Option<I> {
        None
    }
    /// `self = self x + c`, by the same operations as the expression (in place for a
    /// [`Dual`], whose copies cost more than its arithmetic): Horner's step.
    fn mul_add_assign(&mut self, x: &Self, c: &Self) {
        *self = *self * *x + *c;
    }
    /// `self = self + a b`, by the same operations as the expression (in place for a
    /// [`Dual`]): a product's term summed into its coefficient.
    fn add_product_assign(&mut self, a: &Self, b: &Self) {
        *self = *self + *a * *b;
    }
    /// `self^k`.
    fn powi(self, k: u32) -> Self {
        match k {
            0 => Self::constant(I::point(1.0)),
            1 => self,
            _ => {
                let h = self.powi(k / 2);
                let sq = h * h;
                if k % 2 == 0 {
                    sq
                } else {
                    sq * self
                }
            }
        }
    }
}

impl Num for I {
    fn constant(c: I) -> I {
        c
    }
    fn is_exact_zero(&self) -> bool {
        I::is_exact_zero(*self)
    }
    fn may_vanish(&self) -> bool {
        self.contains_zero()
    }
    fn div(self, o: I) -> Option<I> {
        self.checked_div(o)
    }
    fn meet(self, o: I) -> Option<I> {
        self.intersect(o)
    }
    fn sqrt(self) -> Option<I> {
        if self.lo < 0.0 {
            return None;
        }
        I::sqrt(self)
    }
    fn powi(self, k: u32) -> I {
        I::powi(self, k)
    }
    fn interval(&self) -> Option<I> {
        Some(*self)
    }
}

/// Most uncertain parameters a [`Dual`] carries a derivative for (every parameter of the
/// model, and P0).
pub const GRADIENT: usize = 19;

/// An enclosure of a function of the box's coordinates over the box: the value and the
/// gradient (in the first `n` coordinates), each an interval over the whole box. The
/// mean-value form `f(c) + sum_i g_i (x_i - c_i)` then encloses `f` over the box far more
/// tightly than the value alone when the box is small.
#[derive(Clone, Copy, Debug)]
pub struct Dual {
    /// The enclosure of the value.
    pub v: I,
    /// The enclosures of the partial derivatives.
    pub g: [I; GRADIENT],
    /// How many coordinates the gradient has.
    pub n: usize,
}

impl Dual {
    /// The coordinate `i` of `n` ranging over `x`.
    pub fn variable(x: I, i: usize, n: usize) -> Dual {
        let mut g = [I::point(0.0); GRADIENT];
        g[i] = I::point(1.0);
        Dual { v: x, g, n }
    }
}

// The operations work in place on their first operand: a `Dual` is 328 bytes, and building
// each result afresh copied it several times per operation. Every entry of a gradient beyond
// its `n` is an exact zero (every constructor above keeps it so), and each entry below the
// result's `n` is computed by the same interval operations as the product and sum rules.

impl Add for Dual {
    type Output = Dual;
    #[inline]
    fn add(mut self, o: Dual) -> Dual {
        let n = self.n.max(o.n);
        self.v = self.v + o.v;
        for (a, b) in self.g[..n].iter_mut().zip(&o.g[..n]) {
            *a = *a + *b;
        }
        self.n = n;
        self
    }
}

impl Sub for Dual {
    type Output = Dual;
    /// `self + -o`, entry by entry: `-o` has exact zeros beyond its `n`.
    #[inline]
    fn sub(mut self, o: Dual) -> Dual {
        let n = self.n.max(o.n);
        self.v = self.v + -o.v;
        for (i, a) in self.g[..n].iter_mut().enumerate() {
            let b = if i < o.n { -o.g[i] } else { I::point(0.0) };
            *a = *a + b;
        }
        self.n = n;
        self
    }
}

impl Neg for Dual {
    type Output = Dual;
    #[inline]
    fn neg(mut self) -> Dual {
        self.v = -self.v;
        for a in &mut self.g[..self.n] {
            *a = -*a;
        }
        self
    }
}

impl Mul for Dual {
    type Output = Dual;
    // The product rule adds: (a b)' = a b' + b a'.
    #[allow(clippy::suspicious_arithmetic_impl)]
    #[inline]
    fn mul(mut self, o: Dual) -> Dual {
        let n = self.n.max(o.n);
        let a = self.v;
        self.v = a * o.v;
        for (ga, gb) in self.g[..n].iter_mut().zip(&o.g[..n]) {
            *ga = a * *gb + o.v * *ga;
        }
        self.n = n;
        self
    }
}

impl Num for Dual {
    fn mul_add_assign(&mut self, x: &Dual, c: &Dual) {
        // The product's gradient has exact zeros from `max(n, x.n)` on, to which `c`'s adds.
        let (np, n) = (self.n.max(x.n), self.n.max(x.n).max(c.n));
        let a = self.v;
        self.v = a * x.v + c.v;
        for (i, g) in self.g[..n].iter_mut().enumerate() {
            let p = if i < np {
                a * x.g[i] + x.v * *g
            } else {
                I::point(0.0)
            };
            *g = p + c.g[i];
        }
        self.n = n;
    }
    fn add_product_assign(&mut self, a: &Dual, b: &Dual) {
        let (np, n) = (a.n.max(b.n), self.n.max(a.n.max(b.n)));
        self.v = self.v + a.v * b.v;
        for (i, g) in self.g[..n].iter_mut().enumerate() {
            let p = if i < np {
                a.v * b.g[i] + b.v * a.g[i]
            } else {
                I::point(0.0)
            };
            *g = *g + p;
        }
        self.n = n;
    }
    fn sqrt(self) -> Option<Dual> {
        // (sqrt a)' = a' / (2 sqrt a), a > 0 on the whole box.
        if self.v.lo <= 0.0 {
            return None;
        }
        let r = self.v.sqrt()?;
        let two_r = I::point(2.0) * r;
        let mut g = [I::point(0.0); GRADIENT];
        for (i, gi) in g.iter_mut().enumerate().take(self.n) {
            *gi = self.g[i].checked_div(two_r)?;
        }
        Some(Dual { v: r, g, n: self.n })
    }
    fn constant(c: I) -> Dual {
        Dual {
            v: c,
            g: [I::point(0.0); GRADIENT],
            n: 0,
        }
    }
    fn is_exact_zero(&self) -> bool {
        self.v.is_exact_zero() && self.g[..self.n].iter().all(|g| g.is_exact_zero())
    }
    fn may_vanish(&self) -> bool {
        self.v.contains_zero()
    }
    fn div(self, o: Dual) -> Option<Dual> {
        // (a / b)' = (a' - (a / b) b') / b.
        let q = self.v.checked_div(o.v)?;
        let n = self.n.max(o.n);
        let mut g = [I::point(0.0); GRADIENT];
        for (i, gi) in g.iter_mut().enumerate().take(n) {
            *gi = (self.g[i] - q * o.g[i]).checked_div(o.v)?;
        }
        Some(Dual { v: q, g, n })
    }
    fn meet(self, o: Dual) -> Option<Dual> {
        let n = self.n.max(o.n);
        let mut g = [I::point(0.0); GRADIENT];
        for (i, gi) in g.iter_mut().enumerate().take(n) {
            *gi = self.g[i].intersect(o.g[i])?;
        }
        Some(Dual {
            v: self.v.intersect(o.v)?,
            g,
            n,
        })
    }
}
