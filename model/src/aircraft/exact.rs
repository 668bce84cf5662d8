//! Exact numbers: a decimal literal as the rational it denotes, an f64 as the rational of its
//! shortest round-trip decimal, and an exact rational rounded once to f64.

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{ToPrimitive, Zero};
use std::str::FromStr;

/// Parses a decimal literal (`-13.52504`, `1e-3`, `2.5E+2`) into the exact rational it denotes.
pub fn decimal_to_rational(s: &str) -> Option<BigRational> {
    let s = s.trim();
    let (mantissa, exp) = match s.find(['e', 'E']) {
        Some(i) => (&s[..i], i64::from_str(&s[i + 1..]).ok()?),
        None => (s, 0),
    };
    let (neg, digits) = match mantissa.strip_prefix('-') {
        Some(rest) => (true, rest),
        None => (false, mantissa.strip_prefix('+').unwrap_or(mantissa)),
    };
    let (int_part, frac_part) = match digits.find('.') {
        Some(i) => (&digits[..i], &digits[i + 1..]),
        None => (digits, ""),
    };
    if int_part.is_empty() && frac_part.is_empty() {
        return None;
    }
    if !int_part
        .chars()
        .chain(frac_part.chars())
        .all(|c| c.is_ascii_digit())
    {
        return None;
    }
    let all = format!("{int_part}{frac_part}");
    let mut num = BigInt::from_str(if all.is_empty() { "0" } else { &all }).ok()?;
    if neg {
        num = -num;
    }
    let scale = exp - frac_part.len() as i64;
    if scale.unsigned_abs() > 400 {
        return None;
    }
    let ten = BigInt::from(10);
    let p = num_traits::pow(ten, scale.unsigned_abs() as usize);
    Some(if scale >= 0 {
        BigRational::from_integer(num * p)
    } else {
        crate::algebra::big_rational::reduced(num, p)
    })
}

/// The exact rational denoted by the shortest decimal that round-trips to `x`.
///
/// For values computed in f64 (the ISA density, the principal-axis rotation, random test
/// aircraft): Rust prints the shortest decimal that round-trips, so this is the simplest exact
/// rational that rounds to `x`. (TOML numbers do not go through it: the loader reads the literal
/// the user wrote.) Returns `None` for NaN or inf.
pub fn f64_to_rational(x: f64) -> Option<BigRational> {
    if !x.is_finite() {
        return None;
    }
    decimal_to_rational(&format!("{x:e}"))
}

/// Rounds an exact rational to the nearest f64 (within one ulp).
pub fn rational_to_f64(q: &BigRational) -> f64 {
    if q.is_zero() {
        return 0.0;
    }
    q.to_f64().unwrap_or(f64::NAN)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn decimals_enter_as_the_exact_rational_they_denote() {
        let q = decimal_to_rational("-13.52504").unwrap();
        assert_eq!(q, BigRational::new((-1352504).into(), 100000.into()));
        assert_eq!(
            decimal_to_rational("2.5e-3").unwrap(),
            BigRational::new(1.into(), 400.into())
        );
        assert_eq!(
            f64_to_rational(-110.45).unwrap(),
            decimal_to_rational("-110.45").unwrap()
        );
        assert!(f64_to_rational(f64::NAN).is_none());
        assert!(decimal_to_rational("1.2.3").is_none());
    }
}
