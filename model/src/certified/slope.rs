//! Numbers with their derivative in the roll rate, both enclosed over a piece of roll rates
//! ([`Slope`]): what the mean-value form of the walk along the primary branch is evaluated in.
//!
//! Interval evaluation over a piece `X` of roll rates overestimates the range of the Hopf
//! determinant on the branch by orders of magnitude (its ingredients are polynomials of high
//! degree whose terms cancel). The mean-value form `f(c) + f'(X) (X - c)`, with `f(c)` enclosed
//! at one roll rate `c` of the piece (tight) and the derivative `f'(X)` enclosed over it,
//! overestimates only by the derivative's own overestimate times the piece's width, so it
//! tends to the true range as the piece shrinks.
//!
//! That overestimate is of the order of the piece's width times the sum of the magnitudes of
//! the second-order terms (no cancellation of the determinant's large terms survives an
//! interval evaluation of the derivative), so the mean-value form decides only narrow pieces.
//! The second-order Taylor form `f(c) + f'(c) (X - c) + f''(X) (X - c)^2 / 2` ([`Taylor2`]),
//! with `f'(c)` enclosed at the centre (tight, the cancellation kept), moves that overestimate
//! to the square of the piece's width: pieces many times wider are decided.

use super::num::Num;
use crate::interval::I;
use std::ops::{Add, Mul, Neg, Sub};

/// Numbers that carry derivatives in the roll rate over a piece of it.
pub(super) trait InRollRate: Num {
    /// The polynomial with coefficients `c` (in increasing powers) in the roll rate over the
    /// piece `x`, with its derivatives: Horner's scheme on the value and the derivatives
    /// together, each step a product by the roll rate alone (whose derivative is 1).
    fn polynomial(c: &[I], x: I) -> Self;
}

impl InRollRate for Slope {
    fn polynomial(c: &[I], x: I) -> Slope {
        let zero = I::point(0.0);
        let (v, d) = c
            .iter()
            .rev()
            .fold((zero, zero), |(v, d), k| (v * x + *k, d * x + v));
        Slope { v, d }
    }
}

impl InRollRate for Taylor2 {
    fn polynomial(c: &[I], x: I) -> Taylor2 {
        let zero = I::point(0.0);
        let two = I::point(2.0);
        let (v, d, dd) = c.iter().rev().fold((zero, zero, zero), |(v, d, dd), k| {
            (v * x + *k, d * x + v, dd * x + two * d)
        });
        Taylor2 { v, d, dd }
    }
}

/// A function of the roll rate over a piece of roll rates: enclosures of its values and of its
/// derivative over the piece.
#[derive(Clone, Copy, Debug)]
pub(super) struct Slope {
    /// The values over the piece.
    pub(super) v: I,
    /// The derivatives over the piece.
    pub(super) d: I,
}

impl Slope {
    /// The roll rate itself over the piece `x`.
    #[cfg(test)]
    pub(super) fn variable(x: I) -> Slope {
        Slope {
            v: x,
            d: I::point(1.0),
        }
    }

    /// The mean-value form over the piece `x` from the enclosure `at_c` of the value at `c`:
    /// `at_c + d (x - c)`, within the values' own enclosure.
    pub(super) fn mean_value(self, x: I, c: f64, at_c: I) -> I {
        let form = at_c + self.d * (x - I::point(c));
        form.intersect(self.v).unwrap_or(form)
    }
}

impl Add for Slope {
    type Output = Slope;
    fn add(self, o: Slope) -> Slope {
        Slope {
            v: self.v + o.v,
            d: self.d + o.d,
        }
    }
}

impl Sub for Slope {
    type Output = Slope;
    fn sub(self, o: Slope) -> Slope {
        Slope {
            v: self.v - o.v,
            d: self.d - o.d,
        }
    }
}

impl Neg for Slope {
    type Output = Slope;
    fn neg(self) -> Slope {
        Slope {
            v: -self.v,
            d: -self.d,
        }
    }
}

impl Mul for Slope {
    type Output = Slope;
    // The product rule adds: (a b)' = a b' + b a'.
    #[allow(clippy::suspicious_arithmetic_impl)]
    fn mul(self, o: Slope) -> Slope {
        Slope {
            v: self.v * o.v,
            d: self.v * o.d + o.v * self.d,
        }
    }
}

impl Num for Slope {
    fn constant(c: I) -> Slope {
        Slope {
            v: c,
            d: I::point(0.0),
        }
    }
    fn is_exact_zero(&self) -> bool {
        self.v.is_exact_zero() && self.d.is_exact_zero()
    }
    fn may_vanish(&self) -> bool {
        self.v.contains_zero()
    }
    fn div(self, o: Slope) -> Option<Slope> {
        // (a / b)' = (a' - (a / b) b') / b, b free of zero over the whole piece.
        let q = self.v.checked_div(o.v)?;
        Some(Slope {
            v: q,
            d: (self.d - q * o.d).checked_div(o.v)?,
        })
    }
    fn meet(self, o: Slope) -> Option<Slope> {
        Some(Slope {
            v: self.v.intersect(o.v)?,
            d: self.d.intersect(o.d)?,
        })
    }
    fn sqrt(self) -> Option<Slope> {
        // (sqrt a)' = a' / (2 sqrt a), a > 0 over the whole piece.
        if self.v.lo <= 0.0 {
            return None;
        }
        let r = self.v.sqrt()?;
        Some(Slope {
            v: r,
            d: self.d.checked_div(I::point(2.0) * r)?,
        })
    }
}

/// A function of the roll rate over a piece of roll rates to second order: enclosures of its
/// values, first and second derivatives over the piece.
#[derive(Clone, Copy, Debug)]
pub(super) struct Taylor2 {
    /// The values over the piece.
    pub(super) v: I,
    /// The first derivatives over the piece.
    pub(super) d: I,
    /// The second derivatives over the piece.
    pub(super) dd: I,
}

impl Taylor2 {
    /// The roll rate itself over the piece `x`.
    #[cfg(test)]
    pub(super) fn variable(x: I) -> Taylor2 {
        Taylor2 {
            v: x,
            d: I::point(1.0),
            dd: I::point(0.0),
        }
    }

    /// The value and first derivative alone.
    pub(super) fn slope(self) -> Slope {
        Slope {
            v: self.v,
            d: self.d,
        }
    }

    /// The Taylor form over the piece `x` around `c` from enclosures of the value `at_c` and
    /// derivative `slope_c` at `c`: `at_c + slope_c (x - c) + dd (x - c)^2 / 2`, within the
    /// mean-value form and the values' own enclosure.
    pub(super) fn taylor(self, x: I, c: f64, at_c: I, slope_c: I) -> I {
        let t = x - I::point(c);
        let form = at_c + slope_c * t + I::point(0.5) * self.dd * t.sqr();
        let form = form
            .intersect(self.slope().mean_value(x, c, at_c))
            .unwrap_or(form);
        form.intersect(self.v).unwrap_or(form)
    }
}

impl Add for Taylor2 {
    type Output = Taylor2;
    fn add(self, o: Taylor2) -> Taylor2 {
        Taylor2 {
            v: self.v + o.v,
            d: self.d + o.d,
            dd: self.dd + o.dd,
        }
    }
}

impl Sub for Taylor2 {
    type Output = Taylor2;
    fn sub(self, o: Taylor2) -> Taylor2 {
        Taylor2 {
            v: self.v - o.v,
            d: self.d - o.d,
            dd: self.dd - o.dd,
        }
    }
}

impl Neg for Taylor2 {
    type Output = Taylor2;
    fn neg(self) -> Taylor2 {
        Taylor2 {
            v: -self.v,
            d: -self.d,
            dd: -self.dd,
        }
    }
}

impl Mul for Taylor2 {
    type Output = Taylor2;
    // Leibniz's rule adds: (a b)'' = a'' b + 2 a' b' + a b''.
    #[allow(clippy::suspicious_arithmetic_impl)]
    fn mul(self, o: Taylor2) -> Taylor2 {
        Taylor2 {
            v: self.v * o.v,
            d: self.v * o.d + o.v * self.d,
            dd: self.dd * o.v + I::point(2.0) * self.d * o.d + self.v * o.dd,
        }
    }
}

impl Num for Taylor2 {
    fn constant(c: I) -> Taylor2 {
        Taylor2 {
            v: c,
            d: I::point(0.0),
            dd: I::point(0.0),
        }
    }
    fn is_exact_zero(&self) -> bool {
        self.v.is_exact_zero() && self.d.is_exact_zero() && self.dd.is_exact_zero()
    }
    fn may_vanish(&self) -> bool {
        self.v.contains_zero()
    }
    fn div(self, o: Taylor2) -> Option<Taylor2> {
        // q = a / b: q' = (a' - q b') / b, q'' = (a'' - 2 q' b' - q b'') / b, b free of zero
        // over the whole piece.
        let q = self.v.checked_div(o.v)?;
        let d = (self.d - q * o.d).checked_div(o.v)?;
        let dd = (self.dd - I::point(2.0) * d * o.d - q * o.dd).checked_div(o.v)?;
        Some(Taylor2 { v: q, d, dd })
    }
    fn meet(self, o: Taylor2) -> Option<Taylor2> {
        Some(Taylor2 {
            v: self.v.intersect(o.v)?,
            d: self.d.intersect(o.d)?,
            dd: self.dd.intersect(o.dd)?,
        })
    }
    fn sqrt(self) -> Option<Taylor2> {
        // r = sqrt a: r' = a' / (2 r), r'' = (a'' - 2 r'^2) / (2 r), a > 0 over the piece.
        if self.v.lo <= 0.0 {
            return None;
        }
        let r = self.v.sqrt()?;
        let two_r = I::point(2.0) * r;
        let d = self.d.checked_div(two_r)?;
        let dd = (self.dd - I::point(2.0) * d.sqr()).checked_div(two_r)?;
        Some(Taylor2 { v: r, d, dd })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mean_value_form_encloses_a_quotient_over_a_piece_tighter_than_its_values() {
        // f(x) = (x^2 + 1) / (x + 3) over [0.9, 1.1]: f(1) = 0.5, f' = (x^2 + 6x - 1) / (x + 3)^2
        // (0.375 at 1); the true range, by f's monotonicity there, is [f(0.9), f(1.1)].
        let x = I::new(0.9, 1.1);
        let s = Slope::variable(x);
        let one = Slope::constant(I::point(1.0));
        let f = (s * s + one)
            .div(s + Slope::constant(I::point(3.0)))
            .unwrap();
        let exact = |x: f64| (x * x + 1.0) / (x + 3.0);
        let form = f.mean_value(x, 1.0, I::point(0.5));
        assert!(form.lo <= exact(0.9) && form.hi >= exact(1.1));
        assert!(form.width() < f.v.width() && form.width() < 1.5 * (exact(1.1) - exact(0.9)));
        assert!(f.d.lo <= 0.375 && f.d.hi >= 0.375);
    }

    #[test]
    fn taylor_form_encloses_a_quotient_and_a_root_over_a_piece_tighter_than_the_mean_value_form() {
        // f(x) = sqrt(x^2 + 1) / (x + 3) over [0.5, 1.5] around 1: f(1) = sqrt(2) / 4,
        // f'(x) = (3 x - 1) / ((x + 3)^2 sqrt(x^2 + 1)), so f'(1) = sqrt(2) / 32; the true range,
        // f being increasing there (3 x > 1), is [f(0.5), f(1.5)].
        let x = I::new(0.5, 1.5);
        let f = |s: Taylor2| {
            let one = Taylor2::constant(I::point(1.0));
            (s * s + one)
                .sqrt()
                .unwrap()
                .div(s + Taylor2::constant(I::point(3.0)))
                .unwrap()
        };
        let exact = |x: f64| (x * x + 1.0).sqrt() / (x + 3.0);
        let r2 = I::point(2.0).sqrt().unwrap();
        let (at_c, slope_c) = (r2 * I::point(0.25), r2 * I::point(1.0 / 32.0));
        let over = f(Taylor2::variable(x));
        let form = over.taylor(x, 1.0, at_c, slope_c);
        assert!(form.lo <= exact(0.5) && form.hi >= exact(1.5), "{form:?}");
        let mean = over.slope().mean_value(x, 1.0, at_c);
        assert!(form.width() < 0.8 * mean.width(), "{form:?} vs {mean:?}");
        // f'' at 1 by central differences lies in the enclosure of f'' over the piece.
        let h = 1e-4;
        let second = (exact(1.0 + h) - 2.0 * exact(1.0) + exact(1.0 - h)) / (h * h);
        assert!(
            over.dd.lo <= second && second <= over.dd.hi,
            "{:?}",
            over.dd
        );
    }

    #[test]
    fn a_polynomial_in_the_roll_rate_has_the_derivatives_of_its_products() {
        // 1 - 2 x + 3 x^3 over [0.5, 0.75]: by Horner's scheme on the value and derivatives
        // and by the ring's products, both holding the exact values and derivatives at the
        // ends (f' = -2 + 9 x^2, f'' = 18 x).
        let c = [I::point(1.0), I::point(-2.0), I::point(0.0), I::point(3.0)];
        let x = I::new(0.5, 0.75);
        let t = Taylor2::polynomial(&c, x);
        let v = Taylor2::variable(x);
        let k = Taylor2::constant;
        let r = k(c[0]) + k(c[1]) * v + k(c[3]) * v * v * v;
        for y in [0.5, 0.75] {
            let (f, d, dd) = (
                1.0 - 2.0 * y + 3.0 * y * y * y,
                -2.0 + 9.0 * y * y,
                18.0 * y,
            );
            for (e, a, b) in [(f, t.v, r.v), (d, t.d, r.d), (dd, t.dd, r.dd)] {
                assert!(
                    a.lo <= e && e <= a.hi && b.lo <= e && e <= b.hi,
                    "{e} {a:?} {b:?}"
                );
            }
        }
        let s = Slope::polynomial(&c, x);
        assert!(s.v.lo == t.v.lo && s.d.hi == t.d.hi);
    }
}
