//! Exact rationals whose reduction waits for the result: the conversion's few dozen sums,
//! products and quotients of a file's decimals stay exact as plain numerator and denominator,
//! and each result is reduced (or rounded to f64) once. A gcd after every operation, as
//! num-rational takes, was most of the time of loading an imported aircraft.

use crate::algebra::big_rational::reduced;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, ToPrimitive, Zero};
use std::ops::{Add, Div, Mul, Neg, Sub};

/// `n / d` with `d > 0`, not necessarily in lowest terms.
#[derive(Clone, Debug)]
pub(super) struct Unreduced {
    n: BigInt,
    d: BigInt,
}

impl Unreduced {
    /// The integer `i`.
    pub(super) fn integer(i: i64) -> Unreduced {
        Unreduced {
            n: i.into(),
            d: 1.into(),
        }
    }

    /// Whether the value is zero.
    pub(super) fn is_zero(&self) -> bool {
        self.n.is_zero()
    }

    /// The value in lowest terms.
    pub(super) fn reduced(&self) -> BigRational {
        reduced(self.n.clone(), self.d.clone())
    }

    /// The value rounded to the nearest f64 (num-rational's rounding is correct for any
    /// representation of the value, reduced or not); infinite beyond f64.
    pub(super) fn to_f64(&self) -> f64 {
        if self.n.is_zero() {
            return 0.0;
        }
        BigRational::new_raw(self.n.clone(), self.d.clone())
            .to_f64()
            .unwrap_or(f64::NAN)
    }
}

impl From<&BigRational> for Unreduced {
    fn from(x: &BigRational) -> Unreduced {
        Unreduced {
            n: x.numer().clone(),
            d: x.denom().clone(),
        }
    }
}

impl Add for &Unreduced {
    type Output = Unreduced;
    fn add(self, o: &Unreduced) -> Unreduced {
        if self.d == o.d {
            return Unreduced {
                n: &self.n + &o.n,
                d: self.d.clone(),
            };
        }
        Unreduced {
            n: &self.n * &o.d + &o.n * &self.d,
            d: &self.d * &o.d,
        }
    }
}

impl Neg for &Unreduced {
    type Output = Unreduced;
    fn neg(self) -> Unreduced {
        Unreduced {
            n: -&self.n,
            d: self.d.clone(),
        }
    }
}

impl Sub for &Unreduced {
    type Output = Unreduced;
    fn sub(self, o: &Unreduced) -> Unreduced {
        self + &-o
    }
}

impl Mul for &Unreduced {
    type Output = Unreduced;
    fn mul(self, o: &Unreduced) -> Unreduced {
        Unreduced {
            n: &self.n * &o.n,
            d: &self.d * &o.d,
        }
    }
}

impl Div for &Unreduced {
    type Output = Unreduced;
    /// `self / o` for `o != 0`.
    fn div(self, o: &Unreduced) -> Unreduced {
        let (n, d) = (&self.n * &o.d, &self.d * &o.n);
        if d.is_negative() {
            Unreduced { n: -n, d: -d }
        } else {
            Unreduced { n, d }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn q(n: i64, d: i64) -> BigRational {
        BigRational::new(n.into(), d.into())
    }

    proptest! {
        /// Every operation, reduced at the end, equals num-rational's reduced result, and the
        /// rounding to f64 equals num-rational's of the reduced value.
        #[test]
        fn deferred_reduction_equals_num_rational(
            (a, b, c, d) in (any::<i32>(), 1..i64::MAX, any::<i64>(), 1..i32::MAX),
        ) {
            let (x, y) = (q(a.into(), b), q(c, d.into()));
            let (ux, uy) = (Unreduced::from(&x), Unreduced::from(&y));
            let mut cases = vec![
                (&ux + &uy, &x + &y),
                (&ux - &uy, &x - &y),
                (&ux * &uy, &x * &y),
                (-&ux, -x.clone()),
                (&(&ux * &uy) + &ux, &x * &y + &x),
            ];
            if !y.is_zero() {
                cases.push((&ux / &uy, &x / &y));
            }
            for (got, want) in cases {
                prop_assert_eq!(got.reduced(), want.clone());
                let f = if want.is_zero() { 0.0 } else { want.to_f64().unwrap() };
                prop_assert_eq!(got.to_f64().to_bits(), f.to_bits());
            }
        }
    }
}
