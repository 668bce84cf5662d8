//! Step 4: refinement of an isolated root to its `f64` rounding cell (certified by two exact
//! signs), Abbott's quadratic interval refinement as the fallback, and step 5's exact ordering
//! of roots of different factors.

use super::*;
use std::cmp::Ordering;

use num_bigint::{BigInt, Sign};
use num_rational::BigRational;
use num_traits::{ToPrimitive, Zero};

/// `|value|` of an exact homogeneous evaluation as `mant · 2^exp` (for secant guesses only).
#[derive(Clone, Copy)]
struct Mag {
    pub(super) mant: f64,
    pub(super) exp: i64,
}

impl Mag {
    pub(super) fn new(v: &BigInt, k: u64, deg: usize) -> Self {
        if v.is_zero() {
            return Mag { mant: 0.0, exp: 0 };
        }
        let bits = v.bits() as i64;
        let sh = (bits - 60).max(0);
        let mant = (v.magnitude() >> sh as u64).to_f64().unwrap_or(1.0);
        Mag {
            mant,
            exp: sh - (k as i64) * (deg as i64),
        }
    }

    /// `|p(a)| / (|p(a)| + |p(b)|)`, the secant position of the root in `(a, b)`.
    fn secant(a: Mag, b: Mag) -> f64 {
        if a.mant == 0.0 {
            return 0.0;
        }
        if b.mant == 0.0 {
            return 1.0;
        }
        let d = (b.exp - a.exp).clamp(-2000, 2000) as i32;
        let r = (b.mant / a.mant) * 2f64.powi(d);
        1.0 / (1.0 + r)
    }
}

/// A refined root: exact (`a == b`) or strictly inside `(a/2^k, b/2^k)`, with `sb` as in
/// [`Isolated`].
pub(super) struct Refined {
    pub(super) a: BigInt,
    pub(super) b: BigInt,
    pub(super) k: u64,
    pub(super) exact: bool,
    pub(super) sb: Sign,
}

impl Refined {
    pub(super) fn exact(mut m: BigInt, mut k: u64) -> Self {
        let mut m2 = m.clone();
        normalize(&mut m, &mut m2, &mut k);
        Refined {
            a: m,
            b: m2,
            k,
            exact: true,
            sb: Sign::NoSign,
        }
    }
}

/// Whether the interval is narrow enough: both ends round to the same `f64`, or relative
/// width below 2⁻⁶⁸, or absolute width below 2⁻¹¹⁰⁰.
pub(super) fn refined_enough(a: &BigInt, b: &BigInt, k: u64) -> bool {
    let wb = (b - a).bits() as i64;
    if wb - (k as i64) < -1100 {
        return true;
    }
    let mb = a.bits().max(b.bits()) as i64;
    if wb + 56 <= mb {
        return dyadic_to_f64(a, k) == dyadic_to_f64(b, k) || wb + 68 <= mb;
    }
    false
}

const MAX_QIR_LOG: u32 = 32;

/// Refines the unique root of square-free `p` in `iv` to full `f64` accuracy.
///
/// Fast path: a floating-point Newton guess (compensated Horner on a double-double copy of
/// `p`) is certified by the exact signs at the boundaries of its `f64` rounding cell — two
/// exact evaluations for a correctly rounded result. Whatever the guess, only exact signs
/// decide; if it cannot be certified, quadratic interval refinement takes over.
pub(super) fn refine(p: &[BigInt], mut iv: Isolated) -> Refined {
    if let Some(x) = newton_guess(p, &iv) {
        if let Some(r) = certify_cell(p, &mut iv, x) {
            return r;
        }
    }
    qir(p, iv)
}

/// `(m, k)` with `m / 2^k == x` exactly, for finite `x`.
fn f64_to_dyadic(x: f64) -> (BigInt, u64) {
    let bits = x.to_bits();
    let exp = ((bits >> 52) & 0x7ff) as i64;
    let frac = bits & ((1u64 << 52) - 1);
    let (mant, e) = if exp == 0 {
        (frac, -1074)
    } else {
        (frac | (1u64 << 52), exp - 1075)
    };
    let m = if x.is_sign_negative() {
        -BigInt::from(mant)
    } else {
        BigInt::from(mant)
    };
    if e >= 0 {
        (m << e as u64, 0)
    } else {
        (m, (-e) as u64)
    }
}

/// The next `f64` towards `+∞` (`up`) or `−∞`, for finite non-zero `x`.
fn f64_step(x: f64, up: bool) -> f64 {
    let b = x.to_bits();
    if (x > 0.0) == up {
        f64::from_bits(b + 1)
    } else {
        f64::from_bits(b - 1)
    }
}

/// Boundaries of the rounding cell of `x`: the midpoints to its two neighbours, at a common
/// scale `k`. `None` for zero or when a neighbour is infinite.
fn rounding_cell(x: f64) -> Option<(BigInt, BigInt, u64)> {
    if x == 0.0 || !x.is_finite() {
        return None;
    }
    let (lo, hi) = (f64_step(x, false), f64_step(x, true));
    if !lo.is_finite() || !hi.is_finite() {
        return None;
    }
    let (ml, kl) = f64_to_dyadic(lo);
    let (mx, kx) = f64_to_dyadic(x);
    let (mh, kh) = f64_to_dyadic(hi);
    let k = kl.max(kx).max(kh);
    let (ml, mx, mh) = (ml << (k - kl), mx << (k - kx), mh << (k - kh));
    Some((&ml + &mx, &mx + &mh, k + 1))
}

/// Narrows `iv` to the side of the dyadic `m/2^km` that holds its root; returns the root if it
/// is exactly `m/2^km`. Points outside `iv` are classified without evaluation.
fn narrow(p: &[BigInt], iv: &mut Isolated, m: BigInt, km: u64) -> Option<Refined> {
    let k = iv.k.max(km);
    let (mut a, mut b, m) = (&iv.a << (k - iv.k), &iv.b << (k - iv.k), m << (k - km));
    if m <= a || m >= b {
        return None;
    }
    let v = eval_dyadic(p, &m, k);
    if v.is_zero() {
        return Some(Refined::exact(m, k));
    }
    if v.sign() == iv.sb {
        b = m;
    } else {
        a = m;
    }
    let mut k = k;
    normalize(&mut a, &mut b, &mut k);
    (iv.a, iv.b, iv.k) = (a, b, k);
    None
}

/// Tries to certify that the root of `iv` rounds to `x` (or to one of its next few neighbours)
/// by exact signs at rounding-cell boundaries. On failure `iv` has still been narrowed.
pub(super) fn certify_cell(p: &[BigInt], iv: &mut Isolated, mut x: f64) -> Option<Refined> {
    for _ in 0..4 {
        let (lo, hi, k) = rounding_cell(x)?;
        if let Some(r) = narrow(p, iv, lo.clone(), k) {
            return Some(r);
        }
        if let Some(r) = narrow(p, iv, hi.clone(), k) {
            return Some(r);
        }
        // Now iv ⊆ (lo, hi) exactly when the root lies in x's cell.
        let ka = iv.k.max(k);
        let below = (&iv.b << (ka - iv.k)) <= (&lo << (ka - k));
        let above = (&iv.a << (ka - iv.k)) >= (&hi << (ka - k));
        if !below && !above {
            return Some(Refined {
                a: iv.a.clone(),
                b: iv.b.clone(),
                k: iv.k,
                exact: false,
                sb: iv.sb,
            });
        }
        x = f64_step(x, above);
    }
    None
}

/// Quadratic interval refinement (Abbott) of the unique root of square-free `p` in `(a, b)`.
///
/// Only points strictly inside the current interval are evaluated; a zero there is the root.
pub(super) fn qir(p: &[BigInt], iv: Isolated) -> Refined {
    let deg = p.len() - 1;
    let Isolated {
        mut a,
        mut b,
        mut k,
        sb,
    } = iv;
    // End-point magnitudes only steer the secant guess (a zero just gives a poor guess).
    let mut fb = Mag::new(&eval_dyadic(p, &b, k), k, deg);
    let mut fa = Mag::new(&eval_dyadic(p, &a, k), k, deg);
    let mut nlog: u32 = 2;
    while !refined_enough(&a, &b, k) {
        let nn = 1u64 << nlog;
        let t = Mag::secant(fa, fb);
        let i = ((t * nn as f64).round() as u64).clamp(1, nn - 1);
        let w = &b - &a;
        let k2 = k + u64::from(nlog);
        let base = &a << nlog;
        let m = &base + &w * i;
        let vm = eval_dyadic(p, &m, k2);
        if vm.is_zero() {
            return Refined::exact(m, k2);
        }
        let fm = Mag::new(&vm, k2, deg);
        let success;
        if vm.sign() == sb {
            // root in (a, m)
            if i == 1 {
                (a, b, fb, success) = (base, m, fm, true);
            } else {
                let l = &m - &w;
                let vl = eval_dyadic(p, &l, k2);
                if vl.is_zero() {
                    return Refined::exact(l, k2);
                }
                let fl = Mag::new(&vl, k2, deg);
                if vl.sign() != sb {
                    (a, b, fa, fb, success) = (l, m, fl, fm, true);
                } else {
                    (a, b, fb, success) = (base, l, fl, false);
                }
            }
        } else {
            // root in (m, b)
            if i == nn - 1 {
                (a, b, fa, success) = (m, b << nlog, fm, true);
            } else {
                let r = &m + &w;
                let vr = eval_dyadic(p, &r, k2);
                if vr.is_zero() {
                    return Refined::exact(r, k2);
                }
                let fr = Mag::new(&vr, k2, deg);
                if vr.sign() == sb {
                    (a, b, fa, fb, success) = (m, r, fm, fr, true);
                } else {
                    (a, b, fa, success) = (r, b << nlog, fr, false);
                }
            }
        }
        k = k2;
        // The magnitudes carry their own scale, so normalising the end points is harmless.
        normalize(&mut a, &mut b, &mut k);
        nlog = if success {
            (nlog * 2).min(MAX_QIR_LOG)
        } else {
            (nlog / 2).max(1)
        };
    }
    Refined {
        a,
        b,
        k,
        exact: false,
        sb,
    }
}

/// One exact bisection step of a non-exact refined root of square-free `p`.
pub(super) fn bisect_once(p: &[BigInt], r: &mut Refined) {
    if r.exact {
        return;
    }
    let m = &r.a + &r.b;
    let k1 = r.k + 1;
    let vm = eval_dyadic(p, &m, k1);
    if vm.is_zero() {
        *r = Refined::exact(m, k1);
        return;
    }
    let (mut a, mut b) = if vm.sign() == r.sb {
        (&r.a << 1u32, m)
    } else {
        (m, &r.b << 1u32)
    };
    let mut k = k1;
    normalize(&mut a, &mut b, &mut k);
    (r.a, r.b, r.k) = (a, b, k);
}

/// Compares `m1/2^k1` with `m2/2^k2` exactly.
pub(super) fn cmp_dyadic(m1: &BigInt, k1: u64, m2: &BigInt, k2: u64) -> Ordering {
    if k1 >= k2 {
        m1.cmp(&(m2 << (k1 - k2)))
    } else {
        (m1 << (k2 - k1)).cmp(m2)
    }
}

/// Compares `m/2^k` with the rational `x` exactly.
pub(super) fn cmp_dyadic_rational(m: &BigInt, k: u64, x: &BigRational) -> Ordering {
    (m * x.denom()).cmp(&(x.numer() << k))
}

/// Position of the unique root `r ∈ (a, b)` of square-free `p` relative to `x`: `r.cmp(x)`.
pub(super) fn root_cmp(p: &[BigInt], iv: &Isolated, x: &BigRational) -> Ordering {
    if cmp_dyadic_rational(&iv.a, iv.k, x) != Ordering::Less {
        return Ordering::Greater; // x ≤ a < r
    }
    if cmp_dyadic_rational(&iv.b, iv.k, x) != Ordering::Greater {
        return Ordering::Less; // r < b ≤ x
    }
    match sign_at_rational(p, x) {
        Sign::NoSign => Ordering::Equal,
        s if s == iv.sb => Ordering::Less, // x ∈ (r, b)
        _ => Ordering::Greater,            // x ∈ (a, r)
    }
}
