//! Numbers with their derivative in the roll rate, both enclosed over a piece of roll rates
//! ([`Slope`]): what the mean-value form of the walk along the primary branch is evaluated in.
//!
//! Interval evaluation over a piece `X` of roll rates overestimates the range of the Hopf
//! determinant on the branch by orders of magnitude (its ingredients are polynomials of high
//! degree whose terms cancel). The mean-value form `f(c) + f'(X) (X - c)`, with `f(c)` enclosed
//! at one roll rate `c` of the piece (tight) and the derivative `f'(X)` enclosed over it,
//! overestimates only by the derivative's own overestimate times the piece's width, so it
//! tends to the true range as the piece shrinks.

use super::num::Num;
use crate::interval::I;
use std::ops::{Add, Mul, Neg, Sub};

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
}
