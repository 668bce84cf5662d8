//! Exact rational coefficients with a machine-integer fast path.
//!
//! All coefficients of the model equations are integers, so the parametric derivation lives in
//! Z[parameters] and almost every coefficient fits an `i64`; only an aircraft's decimal data
//! (`-13.52504 = -338126/25000`) and their products need big rationals. [`Q`] keeps integers that
//! fit in an `i64` inline and promotes to a [`BigRational`] on overflow or division, so exactness
//! is never traded for speed. Big values reduce by Lehmer's gcd ([`big_rational`]).

use super::big_rational;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};
use std::cmp::Ordering;
use std::fmt;
use std::ops::{Add, Mul, Neg, Sub};

/// An exact rational number. Canonical: an integer that fits an `i64` is always `Int`.
#[derive(Clone, PartialEq, Eq, Hash)]
pub struct Q(Repr);

#[derive(Clone, PartialEq, Eq, Hash)]
enum Repr {
    Int(i64),
    Big(Box<BigRational>),
}

impl Q {
    /// Zero.
    pub const ZERO: Q = Q(Repr::Int(0));
    /// One.
    pub const ONE: Q = Q(Repr::Int(1));

    /// The integer `n`.
    pub const fn int(n: i64) -> Q {
        Q(Repr::Int(n))
    }

    /// The exact value of a big rational, in canonical form.
    pub fn from_big(r: BigRational) -> Q {
        if r.is_integer() {
            if let Some(n) = r.numer().to_i64() {
                return Q(Repr::Int(n));
            }
        }
        Q(Repr::Big(Box::new(r)))
    }

    /// `num / den` exactly. Panics if `den` is zero (a bug in the caller, never user input).
    pub fn ratio(num: i64, den: i64) -> Q {
        assert!(den != 0, "Q::ratio: zero denominator");
        Q::from_big(BigRational::new(BigInt::from(num), BigInt::from(den)))
    }

    /// This value as a big rational.
    pub fn to_big(&self) -> BigRational {
        match &self.0 {
            Repr::Int(n) => BigRational::from_integer(BigInt::from(*n)),
            Repr::Big(b) => (**b).clone(),
        }
    }

    /// The integer value if this is an integer that fits an `i64`.
    pub fn as_i64(&self) -> Option<i64> {
        match self.0 {
            Repr::Int(n) => Some(n),
            Repr::Big(_) => None,
        }
    }

    /// True for zero.
    pub fn is_zero(&self) -> bool {
        matches!(self.0, Repr::Int(0))
    }

    /// True for one.
    pub fn is_one(&self) -> bool {
        matches!(self.0, Repr::Int(1))
    }

    /// True when strictly negative.
    pub fn is_negative(&self) -> bool {
        match &self.0 {
            Repr::Int(n) => *n < 0,
            Repr::Big(b) => b.is_negative(),
        }
    }

    /// True when the value is an integer (of any size).
    pub fn is_integer(&self) -> bool {
        match &self.0 {
            Repr::Int(_) => true,
            Repr::Big(b) => b.is_integer(),
        }
    }

    /// Absolute value.
    pub fn abs(&self) -> Q {
        if self.is_negative() {
            -self
        } else {
            self.clone()
        }
    }

    /// This value as a big rational, borrowed where it is one.
    fn big(&self) -> std::borrow::Cow<'_, BigRational> {
        match &self.0 {
            Repr::Int(n) => std::borrow::Cow::Owned(BigRational::from_integer(BigInt::from(*n))),
            Repr::Big(b) => std::borrow::Cow::Borrowed(b),
        }
    }

    /// Nearest f64.
    pub fn to_f64(&self) -> f64 {
        match &self.0 {
            Repr::Int(n) => *n as f64,
            Repr::Big(b) => b.to_f64().unwrap_or(f64::NAN),
        }
    }

    /// Exact quotient. Panics on division by zero (a bug in the caller).
    pub fn div(&self, other: &Q) -> Q {
        assert!(!other.is_zero(), "Q::div by zero");
        if let (Repr::Int(a), Repr::Int(b)) = (&self.0, &other.0) {
            if *b != 0 && a % b == 0 {
                if let Some(q) = a.checked_div(*b) {
                    return Q::int(q);
                }
            }
        }
        let inverse = match &other.0 {
            Repr::Int(n) => BigRational::new(BigInt::one(), BigInt::from(*n)),
            Repr::Big(b) => b.recip(),
        };
        Q::from_big(big_rational::mul(&self.to_big(), &inverse))
    }

    /// `self^k` exactly.
    pub fn pow(&self, k: u32) -> Q {
        let mut acc = Q::ONE;
        for _ in 0..k {
            acc = &acc * self;
        }
        acc
    }

    /// Adds `other` into `self` in place (the hot path of polynomial multiplication).
    pub fn add_assign_ref(&mut self, other: &Q) {
        if let (Repr::Int(a), Repr::Int(b)) = (&mut self.0, &other.0) {
            if let Some(s) = a.checked_add(*b) {
                *a = s;
                return;
            }
        }
        *self = &*self + other;
    }

    /// Sign as an ordering against zero.
    pub fn signum_cmp(&self) -> Ordering {
        match &self.0 {
            Repr::Int(n) => n.cmp(&0),
            Repr::Big(b) => {
                if b.is_zero() {
                    Ordering::Equal
                } else if b.is_positive() {
                    Ordering::Greater
                } else {
                    Ordering::Less
                }
            }
        }
    }
}

impl From<i64> for Q {
    fn from(n: i64) -> Q {
        Q::int(n)
    }
}

impl From<BigRational> for Q {
    fn from(r: BigRational) -> Q {
        Q::from_big(r)
    }
}

impl Add for &Q {
    type Output = Q;
    fn add(self, o: &Q) -> Q {
        if let (Repr::Int(a), Repr::Int(b)) = (&self.0, &o.0) {
            if let Some(s) = a.checked_add(*b) {
                return Q::int(s);
            }
        }
        Q::from_big(big_rational::add(&self.big(), &o.big()))
    }
}

impl Sub for &Q {
    type Output = Q;
    fn sub(self, o: &Q) -> Q {
        if let (Repr::Int(a), Repr::Int(b)) = (&self.0, &o.0) {
            if let Some(s) = a.checked_sub(*b) {
                return Q::int(s);
            }
        }
        Q::from_big(big_rational::add(&self.big(), &(-o).big()))
    }
}

impl Mul for &Q {
    type Output = Q;
    fn mul(self, o: &Q) -> Q {
        match (&self.0, &o.0) {
            (Repr::Int(a), Repr::Int(b)) => match a.checked_mul(*b) {
                Some(p) => Q::int(p),
                None => Q::from_big(BigRational::from_integer(
                    BigInt::from(*a) * BigInt::from(*b),
                )),
            },
            (Repr::Int(0), _) | (_, Repr::Int(0)) => Q::ZERO,
            (Repr::Int(1), _) => o.clone(),
            (_, Repr::Int(1)) => self.clone(),
            _ => Q::from_big(big_rational::mul(&self.big(), &o.big())),
        }
    }
}

impl Neg for &Q {
    type Output = Q;
    fn neg(self) -> Q {
        match &self.0 {
            Repr::Int(n) => match n.checked_neg() {
                Some(m) => Q::int(m),
                None => Q::from_big(-self.to_big()),
            },
            Repr::Big(b) => Q::from_big(-(**b).clone()),
        }
    }
}

impl Neg for Q {
    type Output = Q;
    fn neg(self) -> Q {
        -&self
    }
}

impl Zero for Q {
    fn zero() -> Q {
        Q::ZERO
    }
    fn is_zero(&self) -> bool {
        Q::is_zero(self)
    }
}

impl Add for Q {
    type Output = Q;
    fn add(self, o: Q) -> Q {
        &self + &o
    }
}

impl Mul for Q {
    type Output = Q;
    fn mul(self, o: Q) -> Q {
        &self * &o
    }
}

impl One for Q {
    fn one() -> Q {
        Q::ONE
    }
}

impl fmt::Debug for Q {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(self, f)
    }
}

impl fmt::Display for Q {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.0 {
            Repr::Int(n) => write!(f, "{n}"),
            Repr::Big(b) => write!(f, "{b}"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn integer_overflow_promotes_to_big_and_stays_exact() {
        let big = Q::int(i64::MAX);
        let s = &big + &Q::ONE;
        assert_eq!(
            s.to_big(),
            BigRational::from_integer(BigInt::from(i64::MAX) + 1)
        );
        let back = &s - &Q::ONE;
        assert_eq!(
            back,
            Q::int(i64::MAX),
            "canonical form returns to the fast path"
        );
        let p = &big * &big;
        assert_eq!(p.div(&big), big);
    }

    #[test]
    fn rationals_are_exact() {
        let third = Q::ratio(1, 3);
        let one = &(&third + &third) + &third;
        assert!(one.is_one());
        assert_eq!(Q::ratio(6, 3), Q::int(2));
        assert_eq!(Q::int(7).div(&Q::int(2)), Q::ratio(7, 2));
    }
}
