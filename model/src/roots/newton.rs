//! The floating-point proposal of step 4: Newton's iteration with compensated Horner on a
//! double-double copy of the factor, safeguarded by bisection.

use super::*;

use num_bigint::{BigInt, Sign};
use num_traits::{ToPrimitive, Zero};

/// `x · 2^e` without intermediate overflow or underflow of the factor.
fn ldexp(mut x: f64, mut e: i64) -> f64 {
    while e > 1000 {
        x *= pow2(1000);
        e -= 1000;
    }
    while e < -1000 {
        x *= pow2(-1000);
        e += 1000;
    }
    x * pow2(e)
}

/// A double-double copy of `2^(σ·i − E)·cᵢ` (with `E` making the largest coefficient about 1),
/// i.e. the polynomial in `y = x / 2^σ`, for floating-point guesses only.
struct FloatPoly {
    pub(super) hi: Vec<f64>,
    pub(super) lo: Vec<f64>,
}

impl FloatPoly {
    pub(super) fn new(p: &[BigInt], sigma: i64) -> Self {
        let e = p
            .iter()
            .enumerate()
            .filter(|(_, c)| !c.is_zero())
            .map(|(i, c)| c.bits() as i64 + sigma * i as i64)
            .max()
            .unwrap_or(0);
        let (mut hi, mut lo) = (Vec::with_capacity(p.len()), Vec::with_capacity(p.len()));
        for (i, c) in p.iter().enumerate() {
            let s = (c.bits() as i64 - 106).max(0);
            let top = (c >> s as u64).to_i128().unwrap_or(0);
            let h = top as f64;
            let l = (top - h as i128) as f64;
            let sc = s + sigma * i as i64 - e;
            hi.push(ldexp(h, sc));
            lo.push(ldexp(l, sc));
        }
        FloatPoly { hi, lo }
    }

    /// Compensated Horner value (error ≈ ε·|p(y)| + O(ε²)·Σ|cᵢ||y|ⁱ) and plain derivative.
    pub(super) fn eval(&self, y: f64) -> (f64, f64) {
        fn two_sum(a: f64, b: f64) -> (f64, f64) {
            let s = a + b;
            let bb = s - a;
            (s, (a - (s - bb)) + (b - bb))
        }
        fn split(a: f64) -> (f64, f64) {
            let t = 134_217_729.0 * a;
            let h = t - (t - a);
            (h, a - h)
        }
        fn two_prod(a: f64, b: f64) -> (f64, f64) {
            let p = a * b;
            let ((ah, al), (bh, bl)) = (split(a), split(b));
            (p, ((ah * bh - p) + ah * bl + al * bh) + al * bl)
        }
        let n = self.hi.len() - 1;
        let (mut s, mut c, mut d) = (self.hi[n], self.lo[n], 0.0);
        for i in (0..n).rev() {
            d = d * y + s + c;
            let (pr, pe) = two_prod(s, y);
            let (s2, se) = two_sum(pr, self.hi[i]);
            c = c * y + (pe + se + self.lo[i]);
            s = s2;
        }
        (s + c, d)
    }
}

/// Safeguarded Newton iteration in floating point inside `iv` (bisection when Newton leaves
/// the bracket). Only a guess: it may be wrong without harm.
pub(super) fn newton_guess(p: &[BigInt], iv: &Isolated) -> Option<f64> {
    let (a, b) = (dyadic_to_f64(&iv.a, iv.k), dyadic_to_f64(&iv.b, iv.k));
    let big = a.abs().max(b.abs());
    if !big.is_finite() || big == 0.0 {
        return None;
    }
    let sigma = ((big.to_bits() >> 52) & 0x7ff) as i64 - 1022;
    let fp = FloatPoly::new(p, sigma);
    let (mut lo, mut hi) = (ldexp(a, -sigma), ldexp(b, -sigma));
    let plus_right = iv.sb == Sign::Plus;
    let mut y = 0.5 * (lo + hi);
    for _ in 0..100 {
        let (v, dv) = fp.eval(y);
        if !v.is_finite() || !dv.is_finite() {
            return None;
        }
        if v == 0.0 {
            break;
        }
        if (v > 0.0) == plus_right {
            hi = y;
        } else {
            lo = y;
        }
        let newton = y - v / dv;
        if newton == y {
            break; // the Newton step is below half an ulp
        }
        let next = if newton > lo && newton < hi {
            newton
        } else {
            0.5 * (lo + hi)
        };
        if next == y || hi <= lo {
            break;
        }
        let small = (next - y).abs() <= 4.0 * f64::EPSILON * y.abs();
        y = next;
        if small {
            // one more step polishes the last bit
            let (v, dv) = fp.eval(y);
            let polished = y - v / dv;
            if polished.is_finite() && polished > lo && polished < hi {
                y = polished;
            }
            break;
        }
    }
    let x = ldexp(y, sigma);
    (x.is_finite() && x != 0.0).then_some(x)
}
