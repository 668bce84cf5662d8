//! Bounds on the roots of a polynomial with interval coefficients: Kioustelidis' bound on the
//! positive roots and Fujiwara's bound on every root's modulus, rounded up to powers of two.

use super::*;

/// A bound on the positive roots (Kioustelidis: `2 max (|a_i| / a_n)^(1/(n-i))` over the
/// coefficients that may have the sign opposite to the leading one), rounded up to a power of
/// two; `None` when no coefficient can have that sign (no positive root at all). The leading
/// coefficient must exclude zero.
pub(super) fn positive_root_bound(c: &[I]) -> Option<f64> {
    let n = c.len() - 1;
    let lead = c[n];
    let opposite = |a: &I| {
        if lead.lo > 0.0 {
            a.lo < 0.0
        } else {
            a.hi > 0.0
        }
    };
    let m = (0..n)
        .filter(|i| opposite(&c[*i]))
        .map(|i| (c[i].mag() / lead.mig()).powf(1.0 / (n - i) as f64))
        .fold(None, |acc: Option<f64>, r| {
            Some(acc.map_or(r, |a| a.max(r)))
        })?;
    let b = 2.0 * m * (1.0 + 1e-9);
    Some(if b.is_finite() && b > 0.0 {
        2f64.powi(b.log2().ceil() as i32)
    } else {
        f64::INFINITY
    })
}

/// Fujiwara's bound, `2 max |a_{n-i} / a_n|^(1/i)` (every root modulus is below it), rounded up
/// generously to a power of two.
pub(super) fn root_bound(c: &[I]) -> f64 {
    let n = c.len() - 1;
    let lead = c[n].mig();
    let m = (1..=n)
        .map(|i| {
            let r = c[n - i].mag() / lead;
            let i = i as f64;
            if i == n as f64 {
                (r / 2.0).powf(1.0 / i)
            } else {
                r.powf(1.0 / i)
            }
        })
        .fold(0.0f64, f64::max);
    let b = 2.0 * m * (1.0 + 1e-9);
    if b.is_finite() && b > 0.0 {
        2f64.powi(b.log2().ceil() as i32 + 1)
    } else {
        f64::INFINITY
    }
}
