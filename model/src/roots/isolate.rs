//! Step 3: isolation by bisection with Descartes' rule of signs on the integer Bernstein
//! coefficients (de Casteljau by Taylor shifts), and exact signs at dyadic points.

use super::*;

use num_bigint::{BigInt, Sign};
use num_rational::BigRational;
use num_traits::{One, Zero};

/// `2^(k·deg p) · p(m / 2^k)` — the sign of `p` at the dyadic point `m/2^k`, exactly.
pub(super) fn eval_dyadic(p: &[BigInt], m: &BigInt, k: u64) -> BigInt {
    let n = p.len() - 1;
    let mut acc = p[n].clone();
    for i in (0..n).rev() {
        acc *= m;
        if !p[i].is_zero() {
            acc += &p[i] << (k * (n - i) as u64);
        }
    }
    acc
}

/// Sign of `p(x)` at a rational `x` (homogeneous Horner with the reduced numerator/denominator).
pub(super) fn sign_at_rational(p: &[BigInt], x: &BigRational) -> Sign {
    let (num, den) = (x.numer(), x.denom());
    let n = p.len() - 1;
    let mut acc = p[n].clone();
    let mut pw = BigInt::one();
    for i in (0..n).rev() {
        pw *= den;
        acc = acc * num + &p[i] * &pw;
    }
    acc.sign()
}

/// `K` such that every complex root `z` of `p` (with `p(0) ≠ 0`, degree ≥ 1) has `|z| < 2^K`:
/// Fujiwara's bound `2·maxᵢ |a_{n−i}/a_n|^{1/i}` rounded up to a power of two, strictly.
pub(super) fn root_bound_log2(p: &[BigInt]) -> i64 {
    let n = p.len() - 1;
    let ln = p[n].bits() as i64;
    let mut best = i64::MIN;
    for i in 1..=n {
        let c = &p[n - i];
        if c.is_zero() {
            continue;
        }
        // log2 |c / a_n| < e, hence |c/a_n|^{1/i} < 2^ceil(e/i).
        let e = c.bits() as i64 - ln + 1;
        let i = i as i64;
        best = best.max(-(-e).div_euclid(i));
    }
    best + 1
}

/// Common scale exponent of a dyadic interval `(a/2^k, b/2^k]`; removes shared factors of two.
pub(super) fn normalize(a: &mut BigInt, b: &mut BigInt, k: &mut u64) {
    let tz = match (a.trailing_zeros(), b.trailing_zeros()) {
        (Some(x), Some(y)) => x.min(y),
        (Some(x), None) | (None, Some(x)) => x,
        (None, None) => *k,
    }
    .min(*k);
    if tz > 0 {
        *a >>= tz;
        *b >>= tz;
        *k -= tz;
    }
}

/// In-place Taylor shift `q(x) ← q(x + 1)` (additions only).
fn taylor_shift_1(q: &mut [BigInt]) {
    let n = q.len();
    for i in 0..n.saturating_sub(1) {
        for j in (i..n - 1).rev() {
            let (lo, hi) = q.split_at_mut(j + 1);
            lo[j] += &hi[0];
        }
    }
}

/// In-place Taylor shift `q(x) ← q(x + s)`.
fn taylor_shift(q: &mut [BigInt], s: &BigInt) {
    if s.is_zero() {
        return;
    }
    if s.is_one() {
        return taylor_shift_1(q);
    }
    let n = q.len();
    for i in 0..n.saturating_sub(1) {
        for j in (i..n - 1).rev() {
            let t = &q[j + 1] * s;
            q[j] += t;
        }
    }
}

/// Divides all coefficients by their common power of two.
fn strip_pow2(q: &mut [BigInt]) {
    let tz = q
        .iter()
        .filter_map(BigInt::trailing_zeros)
        .min()
        .unwrap_or(0);
    if tz > 0 {
        for c in q.iter_mut() {
            *c >>= tz;
        }
    }
}

/// Sign variations of a coefficient sequence (zeros skipped), counted up to 2.
fn sign_variations(v: &[BigInt]) -> u32 {
    let mut count = 0;
    let mut last = Sign::NoSign;
    for s in v.iter().map(BigInt::sign).filter(|s| *s != Sign::NoSign) {
        if last != Sign::NoSign && s != last {
            count += 1;
            if count == 2 {
                break;
            }
        }
        last = s;
    }
    count
}

/// An open interval `(a/2^k, b/2^k)` holding exactly one root `r` of a square-free polynomial
/// `p`, which has the sign `sb` on `(r, b)` and `−sb` on `(a, r)`. The end points themselves
/// may be (other) roots, so their signs are never relied on.
pub(super) struct Isolated {
    pub(super) a: BigInt,
    pub(super) b: BigInt,
    pub(super) k: u64,
    pub(super) sb: Sign,
}

/// Isolates the roots of the square-free `f` in the open interval `(l/2^k, r/2^k)`.
///
/// Descartes' rule of signs in the Bernstein basis with bisection (the Bernstein form of the
/// Vincent–Collins–Akritas method): the number of sign variations of the Bernstein coefficients
/// of `f` on an interval bounds the number of roots inside, exactly when it is 0 or 1, and one
/// de Casteljau step (additions and shifts only) yields the coefficients of both halves.
/// Isolating intervals go to `out`; roots hit exactly by a bisection point go to `exact` as
/// `(m, k)` meaning `m/2^k`.
pub(super) fn isolate(
    f: &[BigInt],
    l: &BigInt,
    r: &BigInt,
    k: u64,
    out: &mut Vec<Isolated>,
    exact: &mut Vec<(BigInt, u64)>,
) {
    let n = f.len() - 1;
    let w = r - l;
    // q(x) = 2^(k·n) · f((l + w·x) / 2^k): the interval mapped onto (0, 1).
    let mut q: ZPoly = f
        .iter()
        .enumerate()
        .map(|(i, c)| c << (k * (n - i) as u64))
        .collect();
    taylor_shift(&mut q, l);
    let mut pw = BigInt::one();
    for c in q.iter_mut().skip(1) {
        pw *= &w;
        *c *= &pw;
    }
    // (x+1)^n q(1/(x+1)) = Σ bᵢ·C(n,i)·x^(n−i) for the Bernstein coefficients bᵢ of q on
    // [0, 1]; scaling by L = lcm C(n,i) keeps them integral.
    let mut t: ZPoly = q.into_iter().rev().collect();
    taylor_shift_1(&mut t);
    let mut binom = vec![BigInt::one(); n + 1];
    for i in 1..=n {
        binom[i] = &binom[i - 1] * BigInt::from(n + 1 - i) / BigInt::from(i);
    }
    let lcm = binom.iter().fold(BigInt::one(), |acc, c| {
        crate::algebra::big_rational::lcm(&acc, c)
    });
    let mut bern: ZPoly = (0..=n).map(|i| &t[n - i] * (&lcm / &binom[i])).collect();
    strip_pow2(&mut bern);
    // Node (j, d) is the sub-interval (l + j·w/2^d, l + (j+1)·w/2^d) at scale k.
    let mut stack = vec![(bern, BigInt::zero(), 0u64)];
    while let Some((mut work, j, d)) = stack.pop() {
        match sign_variations(&work) {
            0 => {}
            1 => {
                let (mut a, mut kk) = ((l << d) + &j * &w, k + d);
                let mut b = &a + &w;
                normalize(&mut a, &mut b, &mut kk);
                // Near its left end f has the sign of the first non-zero Bernstein
                // coefficient, and the opposite sign after the root.
                let s_left = work.iter().map(BigInt::sign).find(|s| *s != Sign::NoSign);
                let sb = -s_left.unwrap_or(Sign::Plus);
                out.push(Isolated { a, b, k: kk, sb });
            }
            _ => {
                // de Casteljau at 1/2 on integers: level i of the triangle is 2^i times the
                // true one, so both halves are scaled by 2^n with shifts of n − i.
                let mut left = Vec::with_capacity(n + 1);
                let mut right = vec![BigInt::zero(); n + 1];
                left.push(&work[0] << n);
                right[n] = &work[n] << n;
                for lvl in 1..=n {
                    for i in 0..=(n - lvl) {
                        let (lo, hi) = work.split_at_mut(i + 1);
                        lo[i] += &hi[0];
                    }
                    left.push(&work[0] << (n - lvl));
                    right[n - lvl] = &work[n - lvl] << (n - lvl);
                }
                let j2: BigInt = &j << 1u32;
                let jr = &j2 + 1u32;
                if right[0].is_zero() {
                    // The midpoint is a root. It stays a zero end coefficient of both halves,
                    // which the variation count ignores.
                    exact.push(((l << (d + 1)) + &jr * &w, k + d + 1));
                }
                strip_pow2(&mut left);
                strip_pow2(&mut right);
                stack.push((right, jr, d + 1));
                stack.push((left, j2, d + 1));
            }
        }
    }
}
