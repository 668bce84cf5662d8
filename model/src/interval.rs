//! Closed intervals of f64 with outward rounding, enough for polynomial enclosures.
//!
//! Every operation computes its ends in round-to-nearest and then moves each end one ulp
//! outwards (`next_down` / `next_up` on the bits). Round-to-nearest is within half an ulp of the
//! exact result, so the widened interval contains the exact result of the operation on any
//! reals of the operands: every result encloses the true range. Sums, products and quotients
//! of two exact doubles whose result is exact (checked by error-free transformations: Knuth's
//! TwoSum, Dekker's product) stay points, so that exact zeros and small integers stay exact.
//! Exact rationals enter through [`I::from_q`], which brackets the rational between two adjacent
//! doubles exactly.
//!
//! ```
//! use model::interval::I;
//!
//! // 0.1 + 0.2 rounds to 0.30000000000000004 in f64; the enclosure keeps 0.3 inside.
//! let s = I::point(0.1) + I::point(0.2);
//! assert!(s.lo <= 0.3 && 0.3 <= s.hi && s.lo < s.hi);
//! // A square is never negative, unlike x * x over an interval through 0.
//! let x = I::new(-1.0, 2.0);
//! assert!(x.sqr().lo >= 0.0 && (x * x).lo < 0.0);
//! ```

use num_rational::BigRational;
use num_traits::ToPrimitive;
use std::ops::{Add, Mul, Neg, Sub};

/// A closed interval `[lo, hi]` of reals (lo <= hi, both finite unless an overflow made the
/// enclosure unbounded, which every test below treats as "may contain anything").
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct I {
    /// Lower end.
    pub lo: f64,
    /// Upper end.
    pub hi: f64,
}

/// The next double below `x` (`x` itself for -inf and NaN).
pub fn next_down(x: f64) -> f64 {
    -next_up(-x)
}

/// The next double above `x` (`x` itself for +inf and NaN; the smallest positive double for
/// either zero). Every interval operation rounds its ends out by this, so it is written to be
/// cheap: one predictable branch, then a step of one in the bits towards +inf (up for a
/// positive double, down for a negative one), `-0` first made `+0`.
pub fn next_up(x: f64) -> f64 {
    if x.is_nan() || x == f64::INFINITY {
        return x;
    }
    // -0 + 0 = +0 in round-to-nearest; every other value is unchanged.
    let b = (x + 0.0).to_bits() as i64;
    // +1 for a sign bit clear, -1 for one set.
    f64::from_bits(b.wrapping_add((b >> 63) | 1) as u64)
}

impl I {
    /// The degenerate interval `[x, x]` (exact).
    pub fn point(x: f64) -> I {
        I { lo: x, hi: x }
    }

    /// `[lo, hi]` as given (exact ends).
    pub fn new(lo: f64, hi: f64) -> I {
        I { lo, hi }
    }

    fn out(lo: f64, hi: f64) -> I {
        if lo.is_nan() || hi.is_nan() {
            return I::entire();
        }
        I {
            lo: next_down(lo),
            hi: next_up(hi),
        }
    }

    /// The whole real line.
    pub fn entire() -> I {
        I {
            lo: f64::NEG_INFINITY,
            hi: f64::INFINITY,
        }
    }

    /// The tightest double interval containing the exact rational `q`.
    pub fn from_q(q: &BigRational) -> I {
        I::from_small_q(q).unwrap_or_else(|| I::from_big_q(q))
    }

    /// [`I::from_q`] in big integers: `q = n / d` against `x = m 2^e` exactly.
    fn from_big_q(q: &BigRational) -> I {
        let x = q.to_f64().unwrap_or(f64::NAN);
        if !x.is_finite() {
            return I::entire();
        }
        // Compare q = n / d (d > 0) with x = m 2^e exactly: n 2^-e against m d, in integers.
        let (mantissa, exponent, sign) = num_traits::float::FloatCore::integer_decode(x);
        let m = num_bigint::BigInt::from(mantissa) * i64::from(sign);
        let (n, d) = (q.numer(), q.denom());
        let (lhs, rhs) = if exponent >= 0 {
            (n.clone(), (m << exponent as usize) * d)
        } else {
            (n << (-exponent) as usize, m * d)
        };
        match lhs.cmp(&rhs) {
            std::cmp::Ordering::Equal => I::point(x),
            std::cmp::Ordering::Greater => I::new(x, next_up(x)),
            std::cmp::Ordering::Less => I::new(next_down(x), x),
        }
    }

    /// [`I::from_q`] for `n / d` with `|n|` and `d` below 2^53 (typical aircraft data: a
    /// decimal with at most 15 digits, integers and simple fractions; longer decimals take the
    /// big-integer path of [`I::from_q`]), without big integers: `x = fl(n / d)` is the
    /// nearest double (normal: `|x| > 2^-53` as `|n| >= 1` and `d < 2^53`), and the exact sign
    /// of `n - x d` says on which side of it `q` lies. `x d` is split exactly into `p + e`
    /// (Dekker's product; no overflow or underflow here: `x d` is within a relative `2^-53` of
    /// `n`, a nonzero integer below 2^53), and `n - p` is exact (within a factor two of each
    /// other, Sterbenz), so the sign of `(n - p) - e` is that of `n - x d`.
    fn from_small_q(q: &BigRational) -> Option<I> {
        const LIMIT: i64 = 1 << 53;
        let (n, d) = (q.numer().to_i64()?, q.denom().to_i64()?);
        if !(n.unsigned_abs() < LIMIT as u64 && d > 0 && d < LIMIT) {
            return None;
        }
        if n == 0 {
            return Some(I::point(0.0));
        }
        let (nf, df) = (n as f64, d as f64);
        let x = nf / df;
        let p = x * df;
        let e = exact_product_error(x, df, p);
        let r = (nf - p) - e;
        Some(if r == 0.0 {
            I::point(x)
        } else if r > 0.0 {
            I::new(x, next_up(x))
        } else {
            I::new(next_down(x), x)
        })
    }

    /// The enclosure of `[lo, hi]` for exact ends.
    pub fn from_q_pair(lo: &BigRational, hi: &BigRational) -> I {
        I::new(I::from_q(lo).lo, I::from_q(hi).hi)
    }

    /// Midpoint (a double inside the interval).
    pub fn mid(self) -> f64 {
        let m = 0.5 * self.lo + 0.5 * self.hi;
        m.clamp(self.lo, self.hi)
    }

    /// Midpoint `m` ([`I::mid`]) and a radius `r` rounded up, so that `[m - r, m + r]` (in
    /// exact arithmetic) holds the interval: the midpoint-radius form of the f64 bounds in
    /// [`crate::certified`]. Not finite when an end is not.
    pub fn mid_rad(self) -> (f64, f64) {
        let m = self.mid();
        (m, next_up((self.hi - m).max(m - self.lo)))
    }

    /// Width `hi - lo` (rounded up).
    pub fn width(self) -> f64 {
        next_up(self.hi - self.lo)
    }

    /// Whether 0 lies in the interval (always true for an unbounded or NaN enclosure).
    pub fn contains_zero(self) -> bool {
        !(self.lo > 0.0 || self.hi < 0.0)
    }

    /// Integer power (even powers are non-negative).
    pub fn powi(self, k: u32) -> I {
        match k {
            0 => I::point(1.0),
            1 => self,
            _ => {
                let mut r = self;
                for _ in 1..k {
                    r = r * self;
                }
                if k % 2 == 0 {
                    r.lo = r.lo.max(0.0);
                }
                r
            }
        }
    }

    /// Square, non-negative.
    pub fn sqr(self) -> I {
        self.powi(2)
    }

    /// Square root of the non-negative part; `None` when the interval has no non-negative part.
    pub fn sqrt(self) -> Option<I> {
        if self.hi < 0.0 || self.hi.is_nan() {
            return None;
        }
        let lo = self.lo.max(0.0).sqrt();
        Some(I::new(next_down(lo).max(0.0), next_up(self.hi.sqrt())))
    }

    /// `self / o`; `None` when `o` contains 0.
    pub fn checked_div(self, o: I) -> Option<I> {
        if o.contains_zero() {
            return None;
        }
        if self.is_point() && o.is_point() {
            let q = self.lo / o.lo;
            if exact_product(q, o.lo) == Some(self.lo) {
                return Some(I::point(q));
            }
        }
        let c = [
            self.lo / o.lo,
            self.lo / o.hi,
            self.hi / o.lo,
            self.hi / o.hi,
        ];
        Some(I::out(min4(c), max4(c)))
    }

    /// The sign of the whole interval: `Some(1.0)` if > 0, `Some(-1.0)` if < 0, else `None`.
    pub fn sign(self) -> Option<f64> {
        if self.lo > 0.0 {
            Some(1.0)
        } else if self.hi < 0.0 {
            Some(-1.0)
        } else {
            None
        }
    }

    /// The convex hull of two intervals.
    pub fn hull(self, o: I) -> I {
        I::new(self.lo.min(o.lo), self.hi.max(o.hi))
    }

    /// The largest magnitude in the interval.
    pub fn mag(self) -> f64 {
        self.lo.abs().max(self.hi.abs())
    }

    /// The smallest magnitude in the interval (0 when it contains 0).
    pub fn mig(self) -> f64 {
        if self.contains_zero() {
            0.0
        } else {
            self.lo.abs().min(self.hi.abs())
        }
    }

    /// The intersection of two enclosures of the same value; `None` when they are disjoint
    /// (one of them is then wrong, and nothing can be concluded).
    pub fn intersect(self, o: I) -> Option<I> {
        let (lo, hi) = (self.lo.max(o.lo), self.hi.min(o.hi));
        (lo <= hi).then_some(I::new(lo, hi))
    }

    /// Whether the interval is a single (exact) double.
    pub fn is_point(self) -> bool {
        self.lo == self.hi
    }

    /// Whether the interval is exactly `[0, 0]` (an exact zero, e.g. a term of a parameter
    /// that is exactly zero).
    pub fn is_exact_zero(self) -> bool {
        self.lo == 0.0 && self.hi == 0.0
    }

    /// `self * 2^k` (exact for normal results; outward otherwise).
    pub fn scale2(self, k: i32) -> I {
        let f = 2f64.powi(k);
        if f == 0.0 || !f.is_finite() {
            // 2^k itself is no double (it underflows to 0 or overflows to inf, which would
            // give an exact 0 or an infinite end for any input): two factors that are, each
            // product rounded outwards.
            let h = k / 2;
            return self.scale2(h).scale2(k - h);
        }
        let r = I::new(self.lo * f, self.hi * f);
        if r.lo / f == self.lo && r.hi / f == self.hi && r.lo.is_finite() && r.hi.is_finite() {
            r
        } else {
            self * I::point(f)
        }
    }
}

fn min4(c: [f64; 4]) -> f64 {
    c.iter().copied().fold(f64::INFINITY, f64::min)
}

fn max4(c: [f64; 4]) -> f64 {
    c.iter().copied().fold(f64::NEG_INFINITY, f64::max)
}

/// `a + b` when it is exact in f64 (Knuth's TwoSum error is zero), so that sums of exact
/// values (above all of exact zeros) stay points instead of widening by an ulp.
fn exact_sum(a: f64, b: f64) -> Option<f64> {
    let s = a + b;
    let bb = s - a;
    let err = (a - (s - bb)) + (b - bb);
    (err == 0.0 && s.is_finite()).then_some(s)
}

impl Add for I {
    type Output = I;
    fn add(self, o: I) -> I {
        if self.lo == self.hi && o.lo == o.hi {
            if let Some(s) = exact_sum(self.lo, o.lo) {
                return I::point(s);
            }
        }
        I::out(self.lo + o.lo, self.hi + o.hi)
    }
}

impl Sub for I {
    type Output = I;
    fn sub(self, o: I) -> I {
        self + -o
    }
}

impl Neg for I {
    type Output = I;
    fn neg(self) -> I {
        I::new(-self.hi, -self.lo)
    }
}

/// `a b - p` for `p = fl(a b)`, exactly (Dekker's product with Veltkamp's split into halves
/// of 26 bits; valid away from overflow and underflow).
fn exact_product_error(a: f64, b: f64, p: f64) -> f64 {
    fn split(x: f64) -> (f64, f64) {
        let c = 134_217_729.0 * x; // 2^27 + 1
        let hi = c - (c - x);
        (hi, x - hi)
    }
    let ((ah, al), (bh, bl)) = (split(a), split(b));
    ((ah * bh - p) + ah * bl + al * bh) + al * bl
}

/// `a * b` when it is exact in f64 (Dekker's product error is zero), so that products of
/// exact values stay points.
fn exact_product(a: f64, b: f64) -> Option<f64> {
    let p = a * b;
    // Near underflow Dekker's error term underflows too (a product that rounds to zero would
    // read as exact): only a zero factor makes a product that small exact here.
    let tiny = p.abs() < 1e-290 && a != 0.0 && b != 0.0;
    if !p.is_finite() || a.abs() > 1e300 || b.abs() > 1e300 || tiny {
        return None;
    }
    (exact_product_error(a, b, p) == 0.0).then_some(p)
}

impl Mul for I {
    type Output = I;
    fn mul(self, o: I) -> I {
        if (self.lo == 0.0 && self.hi == 0.0) || (o.lo == 0.0 && o.hi == 0.0) {
            return I::point(0.0);
        }
        if self.lo == self.hi && o.lo == o.hi {
            if let Some(p) = exact_product(self.lo, o.lo) {
                return I::point(p);
            }
        }
        let c = [
            self.lo * o.lo,
            self.lo * o.hi,
            self.hi * o.lo,
            self.hi * o.hi,
        ];
        I::out(min4(c), max4(c))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `scale2` encloses x 2^k for every k, exactly where the result is a normal double, also
    /// where 2^k alone under- or overflows (which gave an exact 0, or an infinite end for a
    /// finite result, when 2^k was taken as one factor).
    #[test]
    fn scale2_encloses_every_power_of_two() {
        use num_bigint::BigInt;
        let two = BigRational::from_integer(BigInt::from(2));
        let q = |x: f64| BigRational::from_float(x).unwrap();
        for x in [1.0, -3.0, 1e-300, -7.5e300, 5e-324, 0.1] {
            for k in (-2300..=2300).step_by(37).chain([-1100, 1100, -1075, 1024]) {
                let r = I::point(x).scale2(k);
                let exact = q(x) * num_traits::pow::Pow::pow(&two, k);
                assert!(
                    r.lo == f64::NEG_INFINITY || q(r.lo) <= exact,
                    "{x} 2^{k}: {r:?}"
                );
                assert!(
                    r.hi == f64::INFINITY || q(r.hi) >= exact,
                    "{x} 2^{k}: {r:?}"
                );
                let e = exact.to_f64().unwrap();
                if e.is_normal() {
                    assert_eq!((r.lo, r.hi), (e, e), "{x} 2^{k}: exact, a normal double");
                }
                if e.is_finite() {
                    assert!(r.lo.is_finite() && r.hi.is_finite(), "{x} 2^{k}: {r:?}");
                }
                if exact != BigRational::from_integer(0.into()) {
                    assert!(
                        !r.is_exact_zero(),
                        "{x} 2^{k}: a nonzero value enclosed as 0"
                    );
                }
            }
        }
    }

    /// Small rationals are rounded without big integers exactly as with them.
    #[test]
    fn small_rationals_round_as_in_big_integers() {
        let mut bits = 0x2545_f491_4f6c_dd1du64;
        let mut next = move || {
            bits ^= bits << 13;
            bits ^= bits >> 7;
            bits ^= bits << 17;
            bits
        };
        for k in 0..200_000 {
            let limit = 1i64 << [53, 20, 7, 53][k % 4];
            let n = (next() % (2 * limit as u64 - 1)) as i64 - (limit - 1);
            let d = 1 + (next() % (limit as u64 - 1)) as i64;
            let q = BigRational::new(n.into(), d.into());
            let small = I::from_small_q(&q).expect("within 2^53");
            assert_eq!(small, I::from_big_q(&q), "{n}/{d}");
        }
        let big = BigRational::new((1i64 << 53).into(), 3.into());
        assert!(I::from_small_q(&big).is_none());
        let most_negative = BigRational::new(i64::MIN.into(), 7.into());
        assert!(I::from_small_q(&most_negative).is_none());
        assert_eq!(I::from_q(&most_negative), I::from_big_q(&most_negative));
    }

    /// The neighbours are the standard library's (`f64::next_up`, `f64::next_down`) on the
    /// special values and on doubles of every binade and sign.
    #[test]
    fn neighbours_are_the_standard_ones() {
        let mut xs = vec![
            0.0,
            -0.0,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::MAX,
            -f64::MAX,
            f64::MIN_POSITIVE,
            -f64::MIN_POSITIVE,
            f64::from_bits(1),
            -f64::from_bits(1),
            1.0,
            -1.0,
        ];
        let mut bits = 0x9e37_79b9_7f4a_7c15u64;
        for _ in 0..100_000 {
            bits ^= bits << 13;
            bits ^= bits >> 7;
            bits ^= bits << 17;
            xs.push(f64::from_bits(bits));
        }
        for x in xs {
            let same = |a: f64, b: f64| a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan());
            assert!(same(next_up(x), x.next_up()), "next_up({x:e})");
            assert!(same(next_down(x), x.next_down()), "next_down({x:e})");
        }
    }

    #[test]
    fn enclosures_contain_the_exact_results() {
        // 0.1 is not a double: [0.1] brackets it, and 3 * [0.1] contains 3/10 exactly.
        let tenth = BigRational::new(1.into(), 10.into());
        let t = I::from_q(&tenth);
        assert!(t.lo < t.hi);
        let three = I::point(3.0) * t;
        let exact = BigRational::new(3.into(), 10.into());
        assert!(BigRational::from_float(three.lo).unwrap() < exact);
        assert!(BigRational::from_float(three.hi).unwrap() > exact);
        assert!(I::new(-1.0, 2.0).sqr().lo == 0.0);
        assert!(I::new(-1.0, 2.0).checked_div(I::new(-1.0, 1.0)).is_none());
        assert_eq!(next_up(1.0), 1.0 + f64::EPSILON);
        assert_eq!(next_down(0.0), -f64::from_bits(1));
    }

    /// Products of exact points that underflow are not exact (Dekker's error term underflows
    /// with them): found by the point-enclosure property test, where a subnormal coefficient
    /// times a small negative x gave the point [0, 0] for a value of about -2e-324.
    #[test]
    fn underflowing_products_of_points_are_enclosed_not_rounded() {
        let q = |v: f64| BigRational::from_float(v).expect("finite");
        for (a, b) in [
            (8.289046e-317, -2.273489482017882e-8),
            (f64::from_bits(3), 0.5),
            (1e-200, 1e-200),
            (-1e-160, 3e-160),
        ] {
            let p = I::point(a) * I::point(b);
            let exact = q(a) * q(b);
            assert!(q(p.lo) <= exact && exact <= q(p.hi), "{a} * {b}: {p:?}");
            assert!(p.lo < p.hi, "{a} * {b} is not a double: {p:?}");
        }
        // A zero factor stays an exact zero.
        assert_eq!(I::point(0.0) * I::point(1e-300), I::point(0.0));
    }
}
