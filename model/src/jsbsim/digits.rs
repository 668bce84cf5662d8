//! Numbers in messages: a value read from the user (a `--set`, an altitude) or found in a model
//! may be as large as 1e308, whose plain decimal form is 309 digits that bury the message; both
//! forms here switch to exponent notation where the plain one grows long.

/// A number for a message: at most 4 decimals, no trailing zeros; from 1e9 on four significant
/// decimals in exponent notation (`1e308`, `1.2346e11`).
pub fn short(x: f64) -> String {
    if x.is_finite() && x.abs() >= 1e9 {
        let s = format!("{x:.4e}");
        let (mantissa, exponent) = s.split_once('e').unwrap_or((&s, "0"));
        let mantissa = mantissa.trim_end_matches('0').trim_end_matches('.');
        return format!("{mantissa}e{exponent}");
    }
    let s = format!("{x:.4}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" {
        "0".into()
    } else {
        s.into()
    }
}

/// A number for a message with every digit (the shortest that reads back to it), in exponent
/// notation from 1e16 on and below 1e-5 in magnitude, as Rust's `{:?}` switches (`1e308`,
/// `256.29046420839387`, `3000`).
pub fn every_digit(x: f64) -> String {
    let a = x.abs();
    if x.is_finite() && a != 0.0 && !(1e-5..1e16).contains(&a) {
        format!("{x:e}")
    } else {
        format!("{x}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_short() {
        assert_eq!(short(5.0), "5");
        assert_eq!(short(0.257), "0.257");
        assert_eq!(short(-0.00002), "0");
        assert_eq!(short(1.23456), "1.2346");
        assert_eq!(short(86_000.0), "86000");
        assert_eq!(short(1e308), "1e308");
        assert_eq!(short(-123_456_789_012.0), "-1.2346e11");
        assert_eq!(short(f64::NAN), "NaN");
    }

    #[test]
    fn every_digit_is_kept_without_hundreds_of_them() {
        assert_eq!(every_digit(1e308), "1e308");
        assert_eq!(every_digit(-1.5e-300), "-1.5e-300");
        assert_eq!(every_digit(256.290_464_208_393_87), "256.29046420839387");
        assert_eq!(every_digit(3000.0), "3000");
        assert_eq!(every_digit(0.0), "0");
        assert_eq!(every_digit(f64::INFINITY), "inf");
        assert_eq!(every_digit(1e308).parse::<f64>(), Ok(1e308));
    }
}
