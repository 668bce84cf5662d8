//! Dyadic rationals `m / 2^k`: conversions to ℚ and to correctly rounded `f64`.

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};

/// `m / 2^k` as a reduced rational (no gcd needed: only factors of two can cancel).
pub(super) fn dyadic_to_rational(m: &BigInt, k: u64) -> BigRational {
    let tz = m.trailing_zeros().unwrap_or(k).min(k);
    BigRational::new_raw(m >> tz, BigInt::one() << (k - tz))
}

/// `m / 2^k` correctly rounded (ties to even) to `f64`, including subnormals and overflow.
pub(super) fn dyadic_to_f64(m: &BigInt, k: u64) -> f64 {
    if m.is_zero() {
        return 0.0;
    }
    let mag = m.magnitude();
    let sign = if m.is_negative() { -1.0 } else { 1.0 };
    let e = mag.bits() as i64 - 1 - k as i64; // exponent of the leading bit
    if e > 1023 {
        return sign * f64::INFINITY;
    }
    let u = (e - 52).max(-1074); // exponent of the last kept bit
    let s = u + k as i64;
    let q = if s <= 0 {
        (mag << (-s) as u64).to_u64().unwrap_or(0)
    } else {
        let s = s as u64;
        let mut q = (mag >> s).to_u64().unwrap_or(0);
        let half = mag.bit(s - 1);
        let sticky = mag.trailing_zeros().is_some_and(|t| t < s - 1);
        if half && (sticky || q & 1 == 1) {
            q += 1;
        }
        q
    };
    // q ≤ 2^53 and q·2^u is representable, so both products below are exact (or overflow to
    // infinity); 2^u itself may be subnormal, hence the two steps.
    let v = if u >= -1022 {
        q as f64 * pow2(u)
    } else {
        (q as f64 * pow2(u + 600)) * pow2(-600)
    };
    sign * v
}

/// `2^e` for `-1022 ≤ e ≤ 1023`.
pub(super) fn pow2(e: i64) -> f64 {
    f64::from_bits(((e + 1023) as u64) << 52)
}
