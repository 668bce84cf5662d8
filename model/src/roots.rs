//! Exact univariate polynomials over ℚ and certified isolation of their real roots.
//!
//! After an aircraft's data are substituted, every criterion is a univariate polynomial (or a
//! quotient of two) with big rational coefficients, and the tool needs *all* of its positive
//! real roots with their multiplicities, to full `f64` accuracy. Everything here is exact:
//! arithmetic is done in ℚ (or, internally, in ℤ on primitive polynomials), multiplicities come
//! from an exact square-free decomposition, root counts come from exact Sturm sequences and
//! refinement decides sides by exact signs. No floating-point tolerance ever decides whether
//! something is a root, so
//!
//! * a pole of a rational function `N/D` is never reported as a root: common factors are
//!   cancelled exactly with [`UPoly::gcd`] / [`UPoly::div_rem`] before roots are sought, and a
//!   root of `N` that is merely *close* to a root of `D` survives the cancellation;
//! * roots that are 10⁻⁹ (or 10⁻³⁰) apart are still separated and counted correctly;
//! * a rational root that a bisection point hits exactly is reported exactly (`lo == hi`).
//!
//! # Method
//!
//! 1. The input is scaled to a primitive integer polynomial and a factor `x^z` is split off
//!    (roots at exactly zero are reported with multiplicity `z`).
//! 2. The Sturm sequence of the remaining polynomial `g` is computed with the primitive
//!    pseudo-remainder sequence (each remainder divided by its positive content, signs chosen so
//!    that all quotient constants are positive). Its last element is `gcd(g, g')`; when it is a
//!    constant (the usual case) `g` is square-free and the chain is used directly, otherwise
//!    Yun's algorithm ([`UPoly::square_free_factors`]) splits `g = c·∏ fᵢⁱ` and every `fᵢ` gets
//!    its own Sturm sequence. The factors are pairwise coprime, so every root is found once,
//!    with multiplicity `i`.
//! 3. Isolation: bisection of a dyadic interval `(−2ᴷ, 2ᴷ]` (Fujiwara's bound, rounded up to a
//!    power of two, strictly exceeds every root modulus) driven by exact Sturm counts
//!    `V(a) − V(b) = #{roots in (a, b]}`. Sturm was chosen over Descartes/VCA because its count
//!    is exact rather than an upper bound: intervals are split only while they hold two or more
//!    roots, the half-open `(a, b]` convention is handled without special cases (also when an
//!    end point is itself a root), and the chain costs a single pseudo-remainder sequence that
//!    also serves as the square-freeness test. All end points are dyadic, so signs are
//!    evaluated with homogeneous integer Horner schemes (no rational normalisation, no gcds).
//! 4. Refinement: Abbott's quadratic interval refinement — a secant guess picks one of `N`
//!    sub-intervals, two exact sign evaluations confirm it (then `N ← N²`, capped at 2³²) or
//!    the interval still shrinks and `N ← √N`. It stops when both end points round to the same
//!    `f64` (so `value` is the correctly rounded root), or the width is below 2⁻⁶⁸ relative
//!    (2⁻¹¹⁰⁰ absolute).
//! 5. Roots of different square-free factors are ordered exactly; overlapping intervals are
//!    bisected until they are disjoint.
//!
//! A degree-12 polynomial with ~40-digit rational coefficients takes a few tens of microseconds
//! in release builds (see the ignored `timing` test).

use std::cmp::Ordering;

use num_bigint::{BigInt, Sign};
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};

/// Dense univariate polynomial over ℚ.
///
/// Coefficients are stored in ascending powers (`coeffs[i]` multiplies `xⁱ`) without trailing
/// zeros, so the zero polynomial is the empty vector and equality is structural.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct UPoly {
    coeffs: Vec<BigRational>,
}

impl UPoly {
    /// Builds a polynomial from ascending coefficients, trimming trailing zeros.
    pub fn new(mut coeffs: Vec<BigRational>) -> Self {
        while coeffs.last().is_some_and(Zero::is_zero) {
            coeffs.pop();
        }
        Self { coeffs }
    }

    /// The zero polynomial.
    pub fn zero() -> Self {
        Self { coeffs: Vec::new() }
    }

    /// The constant polynomial `c`.
    pub fn constant(c: BigRational) -> Self {
        Self::new(vec![c])
    }

    /// Builds a polynomial from ascending integer coefficients.
    pub fn from_i64s(coeffs: &[i64]) -> Self {
        Self::new(coeffs.iter().map(|&c| BigRational::from_integer(c.into())).collect())
    }

    /// The monic polynomial `∏ (x − rᵢ)` (the constant `1` for an empty slice).
    pub fn from_roots(roots: &[BigRational]) -> Self {
        roots.iter().fold(Self::constant(BigRational::one()), |acc, r| {
            acc.mul(&Self::new(vec![-r.clone(), BigRational::one()]))
        })
    }

    /// The coefficients in ascending powers (empty for the zero polynomial).
    pub fn coeffs(&self) -> &[BigRational] {
        &self.coeffs
    }

    /// The degree, `None` for the zero polynomial.
    pub fn degree(&self) -> Option<usize> {
        self.coeffs.len().checked_sub(1)
    }

    /// Whether this is the zero polynomial.
    pub fn is_zero(&self) -> bool {
        self.coeffs.is_empty()
    }

    /// The leading coefficient, `None` for the zero polynomial.
    pub fn leading_coeff(&self) -> Option<&BigRational> {
        self.coeffs.last()
    }

    /// Exact value at `x` (Horner's scheme).
    pub fn eval(&self, x: &BigRational) -> BigRational {
        let mut acc = BigRational::zero();
        for c in self.coeffs.iter().rev() {
            acc = acc * x + c;
        }
        acc
    }

    /// Approximate value at `x` in `f64` (coefficients rounded to `f64`, then Horner).
    ///
    /// Only for display and plotting: never use it to decide whether something is a root.
    pub fn eval_f64(&self, x: f64) -> f64 {
        let mut acc = 0.0;
        for c in self.coeffs.iter().rev() {
            acc = acc * x + c.to_f64().unwrap_or(f64::NAN);
        }
        acc
    }

    /// The derivative.
    pub fn derivative(&self) -> UPoly {
        Self::new(
            self.coeffs
                .iter()
                .enumerate()
                .skip(1)
                .map(|(i, c)| c * BigRational::from_integer(i.into()))
                .collect(),
        )
    }

    /// The sum `self + o`.
    #[allow(clippy::should_implement_trait)]
    pub fn add(&self, o: &UPoly) -> UPoly {
        let n = self.coeffs.len().max(o.coeffs.len());
        Self::new(
            (0..n)
                .map(|i| match (self.coeffs.get(i), o.coeffs.get(i)) {
                    (Some(a), Some(b)) => a + b,
                    (Some(a), None) => a.clone(),
                    (None, Some(b)) => b.clone(),
                    (None, None) => BigRational::zero(),
                })
                .collect(),
        )
    }

    /// The difference `self − o`.
    #[allow(clippy::should_implement_trait)]
    pub fn sub(&self, o: &UPoly) -> UPoly {
        self.add(&o.scale(&-BigRational::one()))
    }

    /// The product `self · o`.
    #[allow(clippy::should_implement_trait)]
    pub fn mul(&self, o: &UPoly) -> UPoly {
        if self.is_zero() || o.is_zero() {
            return Self::zero();
        }
        let mut out = vec![BigRational::zero(); self.coeffs.len() + o.coeffs.len() - 1];
        for (i, a) in self.coeffs.iter().enumerate() {
            if a.is_zero() {
                continue;
            }
            for (j, b) in o.coeffs.iter().enumerate() {
                out[i + j] += a * b;
            }
        }
        Self::new(out)
    }

    /// The scalar multiple `c · self`.
    pub fn scale(&self, c: &BigRational) -> UPoly {
        Self::new(self.coeffs.iter().map(|a| a * c).collect())
    }

    /// `self` divided by its leading coefficient (zero stays zero).
    pub fn monic(&self) -> UPoly {
        match self.leading_coeff() {
            Some(lc) if !lc.is_one() => {
                let inv = lc.recip();
                self.scale(&inv)
            }
            _ => self.clone(),
        }
    }

    /// Euclidean division: `(q, r)` with `self = q·d + r` and `deg r < deg d`.
    ///
    /// # Panics
    ///
    /// Panics if `d` is the zero polynomial (division by zero); that is the only panic.
    pub fn div_rem(&self, d: &UPoly) -> (UPoly, UPoly) {
        let dl = d.leading_coeff().expect("UPoly::div_rem: division by the zero polynomial");
        let n = d.coeffs.len() - 1;
        if self.coeffs.len() <= n {
            return (Self::zero(), self.clone());
        }
        let inv = dl.recip();
        let mut r = self.coeffs.clone();
        let mut q = vec![BigRational::zero(); r.len() - n];
        for s in (0..q.len()).rev() {
            let c = &r[s + n] * &inv;
            if !c.is_zero() {
                for (j, dc) in d.coeffs.iter().enumerate().take(n) {
                    r[s + j] -= &c * dc;
                }
            }
            r[s + n] = BigRational::zero();
            q[s] = c;
        }
        r.truncate(n);
        (Self::new(q), Self::new(r))
    }

    /// Monic greatest common divisor (zero if both are zero).
    ///
    /// Computed with the primitive pseudo-remainder sequence over ℤ, so intermediate
    /// coefficients stay as small as the subresultants.
    pub fn gcd(&self, other: &UPoly) -> UPoly {
        match (self.is_zero(), other.is_zero()) {
            (true, true) => Self::zero(),
            (false, true) => self.monic(),
            (true, false) => other.monic(),
            (false, false) => {
                let g = z_gcd(&to_primitive_z(self), &to_primitive_z(other));
                z_to_upoly(&g).monic()
            }
        }
    }

    /// Square-free decomposition by Yun's algorithm.
    ///
    /// Returns the non-constant monic factors `fᵢ` with their multiplicities `i`, in increasing
    /// multiplicity, such that `self = c · ∏ fᵢⁱ` for the constant `c` = leading coefficient; the
    /// `fᵢ` are square-free and pairwise coprime. Empty for zero and constant polynomials.
    ///
    /// Runs in ℤ[x] on the primitive part (all gcds primitive, all quotients exact).
    pub fn square_free_factors(&self) -> Vec<(UPoly, u32)> {
        if self.degree().unwrap_or(0) == 0 {
            return Vec::new();
        }
        z_yun(&to_primitive_z(self))
            .into_iter()
            .map(|(f, i)| (z_to_upoly(&f).monic(), i))
            .collect()
    }
}

/// A real root of a polynomial.
///
/// `lo < root ≤ hi` with `hi − lo` tiny (both end points round to `value`, or the width is below
/// 2⁻⁶⁸ relative); when the root is rational and was hit exactly, `lo == hi == root`.
#[derive(Clone, Debug)]
pub struct RealRoot {
    /// The root rounded to `f64` (correctly rounded whenever the interval allows it).
    pub value: f64,
    /// Multiplicity of the root in the polynomial.
    pub multiplicity: u32,
    /// Exclusive lower end of the isolating interval (equal to `hi` for an exact root).
    pub lo: BigRational,
    /// Inclusive upper end of the isolating interval.
    pub hi: BigRational,
}

/// All distinct real roots of `p` in ascending order, with multiplicities.
///
/// The zero polynomial (every number is a root) and non-zero constants give an empty `Vec`.
pub fn real_roots(p: &UPoly) -> Vec<RealRoot> {
    find_roots(p, Range::All)
}

/// The distinct real roots of `p` in the half-open interval `(lo, hi]`, ascending.
///
/// Empty when `lo >= hi` and for the zero polynomial.
pub fn roots_in(p: &UPoly, lo: &BigRational, hi: &BigRational) -> Vec<RealRoot> {
    if lo >= hi {
        return Vec::new();
    }
    find_roots(p, Range::Between(lo, hi))
}

/// The distinct real roots `> 0` of `p`, ascending; roots at exactly zero are excluded.
///
/// Empty for the zero polynomial.
pub fn positive_roots(p: &UPoly) -> Vec<RealRoot> {
    find_roots(p, Range::Positive)
}

// ---------------------------------------------------------------------------------------------
// Integer polynomials (ascending coefficients, no trailing zeros).

type ZPoly = Vec<BigInt>;

fn trim_z(v: &mut ZPoly) {
    while v.last().is_some_and(Zero::is_zero) {
        v.pop();
    }
}

/// Non-negative gcd of two integers: Euclid with remainders while the operands are big (one
/// division collapses a big/small pair, where num-bigint's binary gcd would crawl), finished
/// in machine integers.
fn int_gcd(a: &BigInt, b: &BigInt) -> BigInt {
    let (mut x, mut y) = (a.magnitude().clone(), b.magnitude().clone());
    if x < y {
        std::mem::swap(&mut x, &mut y);
    }
    while !y.is_zero() {
        if let (Some(xs), Some(ys)) = (x.to_u128(), y.to_u128()) {
            return BigInt::from(xs.gcd(&ys));
        }
        let r = &x % &y;
        x = std::mem::replace(&mut y, r);
    }
    BigInt::from(x)
}

/// Positive gcd of the coefficients (zero for the zero polynomial). Starts from the smallest
/// coefficient so that every further gcd begins with a cheap remainder.
fn content(v: &[BigInt]) -> BigInt {
    let Some(smallest) = v.iter().filter(|c| !c.is_zero()).min_by_key(|c| c.bits()) else {
        return BigInt::zero();
    };
    let mut g = smallest.abs();
    for c in v {
        if g.is_one() {
            break;
        }
        if !c.is_zero() {
            g = int_gcd(c, &g);
        }
    }
    g
}

/// Divides by the positive content (the sign is kept).
fn make_primitive(v: &mut ZPoly) {
    let g = content(v);
    if !g.is_zero() && !g.is_one() {
        for c in v.iter_mut() {
            *c = &*c / &g;
        }
    }
}

fn make_lc_positive(v: &mut ZPoly) {
    if v.last().is_some_and(Signed::is_negative) {
        for c in v.iter_mut() {
            *c = -&*c;
        }
    }
}

/// Primitive integer polynomial with positive leading coefficient, a positive multiple of `p`.
///
/// With reduced fractions `nᵢ/dᵢ` and `L = lcm(dᵢ)`, the content of `L·p` is `gcd(nᵢ)`, so only
/// gcds of the (small) input numerators and denominators are needed, never of the products.
fn to_primitive_z(p: &UPoly) -> ZPoly {
    let l = p.coeffs().iter().fold(BigInt::one(), |l, c| {
        let d = c.denom();
        if d.is_one() || &l == d {
            l
        } else {
            &l / int_gcd(&l, d) * d
        }
    });
    let mut g = BigInt::zero();
    for c in p.coeffs().iter().filter(|c| !c.is_zero()) {
        g = if g.is_zero() { c.numer().abs() } else { int_gcd(&g, c.numer()) };
        if g.is_one() {
            break;
        }
    }
    let mut v: ZPoly = p
        .coeffs()
        .iter()
        .map(|c| {
            let n = if g.is_one() { c.numer().clone() } else { c.numer() / &g };
            if c.denom() == &l {
                n
            } else {
                n * (&l / c.denom())
            }
        })
        .collect();
    make_lc_positive(&mut v);
    v
}

fn z_to_upoly(v: &[BigInt]) -> UPoly {
    UPoly::new(v.iter().cloned().map(BigRational::from_integer).collect())
}

fn z_derivative(v: &[BigInt]) -> ZPoly {
    v.iter()
        .enumerate()
        .skip(1)
        .map(|(i, c)| c * BigInt::from(i))
        .collect()
}

fn z_sub(a: &[BigInt], b: &[BigInt]) -> ZPoly {
    let mut out: ZPoly = (0..a.len().max(b.len()))
        .map(|i| match (a.get(i), b.get(i)) {
            (Some(x), Some(y)) => x - y,
            (Some(x), None) => x.clone(),
            (None, Some(y)) => -y,
            (None, None) => BigInt::zero(),
        })
        .collect();
    trim_z(&mut out);
    out
}

/// Pseudo-remainder of `a` by non-zero `b`: `lc(b)^s · a = q·b + r` with `deg r < deg b`.
fn prem(a: &[BigInt], b: &[BigInt]) -> ZPoly {
    let n = b.len() - 1;
    let lb = &b[n];
    let mut r = a.to_vec();
    while r.len() > n {
        let m = r.len() - 1;
        let lr = r[m].clone();
        let shift = m - n;
        if !lb.is_one() {
            for c in r.iter_mut() {
                *c *= lb;
            }
        }
        for (j, bc) in b.iter().enumerate().take(n) {
            r[j + shift] -= &lr * bc;
        }
        r.pop();
        trim_z(&mut r);
    }
    r
}

/// Primitive gcd with positive leading coefficient (primitive pseudo-remainder sequence).
/// Zero only if both inputs are zero.
fn z_gcd(a: &[BigInt], b: &[BigInt]) -> ZPoly {
    let (mut r0, mut r1) = if a.len() >= b.len() {
        (a.to_vec(), b.to_vec())
    } else {
        (b.to_vec(), a.to_vec())
    };
    make_primitive(&mut r0);
    make_primitive(&mut r1);
    loop {
        if r1.is_empty() {
            make_lc_positive(&mut r0);
            return r0;
        }
        if r1.len() == 1 {
            return vec![BigInt::one()];
        }
        let mut r = prem(&r0, &r1);
        make_primitive(&mut r);
        r0 = std::mem::replace(&mut r1, r);
    }
}

/// Exact quotient `a / b` in ℤ[x]; `b` must divide `a` (e.g. `b` primitive and a divisor of `a`
/// in ℚ[x], by Gauss's lemma).
fn z_exact_div(a: &[BigInt], b: &[BigInt]) -> ZPoly {
    let n = b.len() - 1;
    if a.len() <= n {
        return Vec::new();
    }
    let mut r = a.to_vec();
    let mut q = vec![BigInt::zero(); a.len() - n];
    for s in (0..q.len()).rev() {
        let c = &r[s + n] / &b[n];
        if !c.is_zero() {
            for (j, bc) in b.iter().enumerate() {
                r[s + j] -= &c * bc;
            }
        }
        q[s] = c;
    }
    q
}

/// Yun's square-free decomposition of a primitive `f` (degree ≥ 1), entirely in ℤ[x]: every gcd
/// is primitive, so all quotients are integral. Returns the non-constant factors (primitive,
/// positive leading coefficient) with their multiplicities, in increasing multiplicity.
fn z_yun(f: &[BigInt]) -> Vec<(ZPoly, u32)> {
    let df = z_derivative(f);
    let a0 = z_gcd(f, &df);
    if a0.len() == 1 {
        let mut g = f.to_vec();
        make_lc_positive(&mut g);
        return vec![(g, 1)];
    }
    let mut b = z_exact_div(f, &a0);
    let c = z_exact_div(&df, &a0);
    let mut d = z_sub(&c, &z_derivative(&b));
    let mut out = Vec::new();
    let mut i = 1u32;
    while b.len() > 1 {
        let a = z_gcd(&b, &d);
        b = z_exact_div(&b, &a);
        let c = z_exact_div(&d, &a);
        d = z_sub(&c, &z_derivative(&b));
        if a.len() > 1 {
            out.push((a, i));
        }
        i += 1;
    }
    out
}

/// Primes below 2⁶³ (checked with a deterministic Miller–Rabin test).
const SQUARE_FREE_PRIMES: [u64; 3] = [
    2_305_843_009_213_693_951, // 2^61 − 1
    4_611_686_018_427_387_847, // 2^62 − 57
    4_611_686_018_427_387_817, // 2^62 − 87
];

fn mul_mod(a: u64, b: u64, q: u64) -> u64 {
    ((u128::from(a) * u128::from(b)) % u128::from(q)) as u64
}

fn inv_mod(a: u64, q: u64) -> u64 {
    // Fermat: a^(q−2), q prime.
    let (mut base, mut e, mut acc) = (a, q - 2, 1u64);
    while e > 0 {
        if e & 1 == 1 {
            acc = mul_mod(acc, base, q);
        }
        base = mul_mod(base, base, q);
        e >>= 1;
    }
    acc
}

/// Degree of `gcd(a, b)` over 𝔽_q (inputs reduced, trailing zeros trimmed, `a` non-zero).
fn gcd_degree_mod(mut a: Vec<u64>, mut b: Vec<u64>, q: u64) -> usize {
    while !b.is_empty() {
        let n = b.len() - 1;
        let inv = inv_mod(b[n], q);
        while a.len() > n {
            let m = a.len() - 1;
            let c = mul_mod(a[m], inv, q);
            for (j, &bc) in b.iter().enumerate() {
                let t = mul_mod(c, bc, q);
                let x = &mut a[m - n + j];
                *x = if *x >= t { *x - t } else { *x + (q - t) };
            }
            while a.last() == Some(&0) {
                a.pop();
            }
        }
        std::mem::swap(&mut a, &mut b);
    }
    a.len() - 1
}

/// Certifies that `f` (degree ≥ 1, positive leading coefficient) is square-free: if for a prime
/// `q` not dividing `lc(f)` (and `q > deg f`) `gcd(f mod q, f' mod q)` is constant, then so is
/// `gcd(f, f')` over ℚ (its reduction would divide both with the same degree). `false` means
/// "not certified", after which the exact decomposition decides.
fn certainly_square_free(f: &[BigInt]) -> bool {
    SQUARE_FREE_PRIMES.iter().any(|&q| {
        let bq = BigInt::from(q);
        let red: Vec<u64> = f
            .iter()
            .map(|c| c.mod_floor(&bq).to_u64().unwrap_or(0))
            .collect();
        if red.last() == Some(&0) {
            return false;
        }
        let mut der: Vec<u64> = red
            .iter()
            .enumerate()
            .skip(1)
            .map(|(i, &c)| mul_mod(c, i as u64 % q, q))
            .collect();
        while der.last() == Some(&0) {
            der.pop();
        }
        gcd_degree_mod(red, der, q) == 0
    })
}

/// `2^(k·deg p) · p(m / 2^k)` — the sign of `p` at the dyadic point `m/2^k`, exactly.
pub static EVALS: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
pub static T_ISO: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(0);
pub static T_REF: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(0);
pub static T_PRE: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(0);
pub static NODES: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
fn eval_dyadic(p: &[BigInt], m: &BigInt, k: u64) -> BigInt {
    EVALS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
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
fn sign_at_rational(p: &[BigInt], x: &BigRational) -> Sign {
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
fn root_bound_log2(p: &[BigInt]) -> i64 {
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
fn normalize(a: &mut BigInt, b: &mut BigInt, k: &mut u64) {
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
    let tz = q.iter().filter_map(BigInt::trailing_zeros).min().unwrap_or(0);
    if tz > 0 {
        for c in q.iter_mut() {
            *c >>= tz;
        }
    }
}

/// Descartes' bound on the number of roots of `q` in `(0, 1)`: the sign variations of
/// `(x+1)^n q(1/(x+1))`; exact when it is 0 or 1. Stops counting at 2.
fn descartes_0_1(q: &[BigInt]) -> u32 {
    NODES.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let mut t: ZPoly = q.iter().rev().cloned().collect();
    taylor_shift_1(&mut t);
    let mut count = 0;
    let mut last = Sign::NoSign;
    for c in &t {
        let s = c.sign();
        if s != Sign::NoSign {
            if last != Sign::NoSign && s != last {
                count += 1;
                if count == 2 {
                    break;
                }
            }
            last = s;
        }
    }
    count
}

/// An open interval `(a/2^k, b/2^k)` holding exactly one root `r` of a square-free polynomial
/// `p`, which has the sign `sb` on `(r, b)` and `−sb` on `(a, r)`. The end points themselves
/// may be (other) roots, so their signs are never relied on.
struct Isolated {
    a: BigInt,
    b: BigInt,
    k: u64,
    sb: Sign,
}

/// Isolates the roots of the square-free `f` in the open interval `(l/2^k, r/2^k)` by
/// Descartes' rule of signs with bisection (Vincent–Collins–Akritas). Isolating intervals go to
/// `out`; roots hit exactly by a bisection point go to `exact` as `(m, k)` meaning `m/2^k`.
fn isolate(
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
    strip_pow2(&mut q);
    // Node (j, d) is the sub-interval (l + j·w/2^d, l + (j+1)·w/2^d) at scale k.
    let mut stack = vec![(q, BigInt::zero(), 0u64)];
    while let Some((q, j, d)) = stack.pop() {
        match descartes_0_1(&q) {
            0 => {}
            1 => {
                let a = (l << d) + &j * &w;
                let b = &a + &w;
                let (mut a, mut b, mut kk) = (a, b, k + d);
                normalize(&mut a, &mut b, &mut kk);
                // q is a positive multiple of f on the node, so f just right of `a` has the
                // sign of q's lowest non-zero coefficient, and the opposite sign after the root.
                let s_left = q.iter().map(BigInt::sign).find(|s| *s != Sign::NoSign);
                let sb = -s_left.unwrap_or(Sign::Plus);
                out.push(Isolated { a, b, k: kk, sb });
            }
            _ => {
                // left: 2^m q(x/2) on (0, 1); right: the same shifted by one.
                let m = q.len() - 1;
                let mut left: ZPoly = q
                    .iter()
                    .enumerate()
                    .map(|(i, c)| c << (m - i))
                    .collect();
                strip_pow2(&mut left);
                let mut right = left.clone();
                taylor_shift_1(&mut right);
                let j2: BigInt = &j << 1u32;
                let jr = &j2 + 1u32;
                if right[0].is_zero() {
                    // The midpoint is a root: record it and divide it out of the right half.
                    exact.push(((l << (d + 1)) + &jr * &w, k + d + 1));
                    right.remove(0);
                }
                stack.push((right, jr, d + 1));
                stack.push((left, j2, d + 1));
            }
        }
    }
}

/// `|value|` of an exact homogeneous evaluation as `mant · 2^exp` (for secant guesses only).
#[derive(Clone, Copy)]
struct Mag {
    mant: f64,
    exp: i64,
}

impl Mag {
    fn new(v: &BigInt, k: u64, deg: usize) -> Self {
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
struct Refined {
    a: BigInt,
    b: BigInt,
    k: u64,
    exact: bool,
    sb: Sign,
}

impl Refined {
    fn exact(mut m: BigInt, mut k: u64) -> Self {
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
fn refined_enough(a: &BigInt, b: &BigInt, k: u64) -> bool {
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

/// Quadratic interval refinement (Abbott) of the unique root of square-free `p` in `(a, b)`.
///
/// Only points strictly inside the current interval are evaluated; a zero there is the root.
fn refine(p: &[BigInt], iv: Isolated) -> Refined {
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
fn bisect_once(p: &[BigInt], r: &mut Refined) {
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
fn cmp_dyadic(m1: &BigInt, k1: u64, m2: &BigInt, k2: u64) -> Ordering {
    if k1 >= k2 {
        m1.cmp(&(m2 << (k1 - k2)))
    } else {
        (m1 << (k2 - k1)).cmp(m2)
    }
}

/// Compares `m/2^k` with the rational `x` exactly.
fn cmp_dyadic_rational(m: &BigInt, k: u64, x: &BigRational) -> Ordering {
    (m * x.denom()).cmp(&(x.numer() << k))
}

/// Position of the unique root `r ∈ (a, b)` of square-free `p` relative to `x`: `r.cmp(x)`.
fn root_cmp(p: &[BigInt], iv: &Isolated, x: &BigRational) -> Ordering {
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

#[derive(Clone, Copy)]
enum Range<'a> {
    All,
    Positive,
    Between(&'a BigRational, &'a BigRational),
}

impl Range<'_> {
    fn contains_zero(self) -> bool {
        match self {
            Range::All => true,
            Range::Positive => false,
            Range::Between(lo, hi) => lo.is_negative() && !hi.is_negative(),
        }
    }
}

/// Square-free factors of `g` (primitive, `g(0) ≠ 0`, degree ≥ 1) with their multiplicities.
/// The usual square-free case is certified cheaply modulo a prime; otherwise Yun decides.
fn square_free_parts(g: &[BigInt]) -> Vec<(ZPoly, u32)> {
    if certainly_square_free(g) {
        vec![(g.to_vec(), 1)]
    } else {
        z_yun(g)
    }
}

/// A root found for one square-free factor, before ordering.
struct Found {
    factor: usize,
    multiplicity: u32,
    root: Refined,
}

fn find_roots(p: &UPoly, range: Range<'_>) -> Vec<RealRoot> {
    if p.is_zero() {
        return Vec::new();
    }
    let f = to_primitive_z(p);
    let z = f.iter().take_while(|c| c.is_zero()).count();
    let g = &f[z..];
    let mut found = Vec::new();
    if z > 0 && range.contains_zero() {
        found.push(Found {
            factor: usize::MAX,
            multiplicity: z as u32,
            root: Refined::exact(BigInt::zero(), 0),
        });
    }
    let t0 = std::time::Instant::now();
    let factors = if g.len() >= 2 {
        let x = square_free_parts(g);
        T_PRE.fetch_add(t0.elapsed().as_nanos() as u64, std::sync::atomic::Ordering::Relaxed);
        x
    } else {
        Vec::new()
    };
    for (idx, (fz, mult)) in factors.iter().enumerate() {
        let kb = root_bound_log2(fz);
        let (bound, k0) = if kb >= 0 {
            (BigInt::one() << kb as u64, 0u64)
        } else {
            (BigInt::one(), (-kb) as u64)
        };
        let (l, r) = match range {
            Range::All => (-bound.clone(), bound),
            Range::Positive => (BigInt::zero(), bound),
            Range::Between(lo, hi) => {
                let a = (lo.floor().to_integer() << k0).max(-bound.clone());
                let b = (hi.ceil().to_integer() << k0).min(bound);
                (a, b)
            }
        };
        if l >= r {
            continue;
        }
        // Descartes counts roots in the open interval (l, r). A root at l ≤ lo is never wanted
        // (and ±2^K are not roots); a root at r = ceil(hi) is recorded here and filtered below.
        let mut isolated = Vec::new();
        let mut exact = Vec::new();
        if eval_dyadic(fz, &r, k0).is_zero() {
            exact.push((r.clone(), k0));
        }
        let t0 = std::time::Instant::now();
        isolate(fz, &l, &r, k0, &mut isolated, &mut exact);
        T_ISO.fetch_add(t0.elapsed().as_nanos() as u64, std::sync::atomic::Ordering::Relaxed);
        let in_range = |c: &dyn Fn(&BigRational) -> Ordering| match range {
            Range::Between(lo, hi) => {
                c(lo) == Ordering::Greater && c(hi) != Ordering::Greater
            }
            _ => true,
        };
        for (m, k) in exact {
            if in_range(&|x| cmp_dyadic_rational(&m, k, x)) {
                found.push(Found {
                    factor: idx,
                    multiplicity: *mult,
                    root: Refined::exact(m, k),
                });
            }
        }
        for iv in isolated {
            if in_range(&|x| root_cmp(fz, &iv, x)) {
                found.push(Found {
                    factor: idx,
                    multiplicity: *mult,
                    root: { let t0 = std::time::Instant::now(); let r = refine(fz, iv); T_REF.fetch_add(t0.elapsed().as_nanos() as u64, std::sync::atomic::Ordering::Relaxed); r },
                });
            }
        }
    }
    separate_and_sort(&mut found, &factors);
    found.into_iter().map(to_real_root).collect()
}

/// Sorts the roots exactly, bisecting intervals of different factors until they are disjoint.
fn separate_and_sort(found: &mut [Found], factors: &[(ZPoly, u32)]) {
    // Lower end first; at equal lower ends an exact root precedes an open interval (whose root
    // is strictly greater).
    let by_lo = |x: &Found, y: &Found| {
        cmp_dyadic(&x.root.a, x.root.k, &y.root.a, y.root.k)
            .then_with(|| y.root.exact.cmp(&x.root.exact))
    };
    // Distinct roots always separate; the cap only guards against an unforeseen bug.
    for _ in 0..100_000 {
        found.sort_by(by_lo);
        let mut clean = true;
        for i in 1..found.len() {
            let (l, r) = found.split_at_mut(i);
            let (x, y) = (&mut l[i - 1], &mut r[0]);
            if cmp_dyadic(&x.root.b, x.root.k, &y.root.a, y.root.k) == Ordering::Greater {
                clean = false;
                for f in [x, y] {
                    if let Some((fz, _)) = factors.get(f.factor) {
                        bisect_once(fz, &mut f.root);
                    }
                }
            }
        }
        if clean {
            return;
        }
    }
}

/// `m / 2^k` as a reduced rational (no gcd needed: only factors of two can cancel).
fn dyadic_to_rational(m: &BigInt, k: u64) -> BigRational {
    let tz = m.trailing_zeros().unwrap_or(k).min(k);
    BigRational::new_raw(m >> tz, BigInt::one() << (k - tz))
}

fn to_real_root(f: Found) -> RealRoot {
    let r = f.root;
    let value = if r.exact {
        dyadic_to_f64(&r.a, r.k)
    } else {
        dyadic_to_f64(&(&r.a + &r.b), r.k + 1)
    };
    RealRoot {
        value,
        multiplicity: f.multiplicity,
        lo: dyadic_to_rational(&r.a, r.k),
        hi: dyadic_to_rational(&r.b, r.k),
    }
}

/// `m / 2^k` correctly rounded (ties to even) to `f64`, including subnormals and overflow.
fn dyadic_to_f64(m: &BigInt, k: u64) -> f64 {
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
fn pow2(e: i64) -> f64 {
    f64::from_bits(((e + 1023) as u64) << 52)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64, d: i64) -> BigRational {
        BigRational::new(n.into(), d.into())
    }

    fn int(n: i64) -> BigRational {
        q(n, 1)
    }

    /// Parses a decimal such as `-1.25e-3` exactly.
    fn dec(s: &str) -> BigRational {
        let (mant, exp) = match s.split_once(['e', 'E']) {
            Some((m, e)) => (m, e.parse::<i64>().unwrap()),
            None => (s, 0),
        };
        let (ip, fp) = mant.split_once('.').unwrap_or((mant, ""));
        let digits: BigInt = format!("{ip}{fp}").parse().unwrap();
        let e = exp - fp.len() as i64;
        let ten = BigInt::from(10);
        if e >= 0 {
            BigRational::from_integer(digits * num_traits::pow(ten, e as usize))
        } else {
            BigRational::new(digits, num_traits::pow(ten, (-e) as usize))
        }
    }

    fn poly_with_roots(roots: &[(BigRational, u32)]) -> UPoly {
        let mut p = UPoly::constant(int(1));
        for (r, m) in roots {
            for _ in 0..*m {
                p = p.mul(&UPoly::from_roots(std::slice::from_ref(r)));
            }
        }
        p
    }

    /// Checks that the reported interval brackets the exact root and `value` is its nearest f64.
    fn assert_root(found: &RealRoot, exact: &BigRational, mult: u32) {
        assert!(
            (found.lo < *exact && *exact <= found.hi) || (found.lo == found.hi && found.lo == *exact),
            "root {exact} not in ({}, {}]",
            found.lo,
            found.hi
        );
        assert_eq!(found.multiplicity, mult, "multiplicity of {exact}");
        assert_eq!(found.value, exact.to_f64().unwrap(), "value of {exact}");
    }

    fn values(r: &[RealRoot]) -> Vec<f64> {
        r.iter().map(|r| r.value).collect()
    }

    #[test]
    fn simple_cubic() {
        let p = UPoly::from_roots(&[int(1), int(2), int(3)]);
        let r = real_roots(&p);
        assert_eq!(values(&r), [1.0, 2.0, 3.0]);
        for (x, k) in r.iter().zip(1..) {
            assert_root(x, &int(k), 1);
        }
    }

    #[test]
    fn double_root_is_reported_once_with_multiplicity_two() {
        let p = poly_with_roots(&[(int(1), 2), (int(-2), 1)]);
        let r = real_roots(&p);
        assert_eq!(r.len(), 2);
        assert_root(&r[0], &int(-2), 1);
        assert_root(&r[1], &int(1), 2);
    }

    #[test]
    fn roots_one_nanometre_apart_are_both_found() {
        let a = int(1);
        let b = int(1) + q(1, 1_000_000_000);
        let p = UPoly::from_roots(&[a.clone(), b.clone()]).scale(&q(-7, 3));
        let r = positive_roots(&p);
        assert_eq!(r.len(), 2);
        assert_root(&r[0], &a, 1);
        assert_root(&r[1], &b, 1);
        assert!(r[0].value < r[1].value);
    }

    #[test]
    fn roots_of_different_factors_closer_than_f64_resolution_are_ordered_exactly() {
        let a = q(1, 3);
        let b = q(1, 3) + BigRational::new(1.into(), num_traits::pow(BigInt::from(10), 30));
        let p = poly_with_roots(&[(a.clone(), 2), (b.clone(), 1)]);
        let r = real_roots(&p);
        assert_eq!(r.len(), 2);
        assert!(r[0].lo < a && a <= r[0].hi && r[0].multiplicity == 2);
        assert!(r[1].lo < b && b <= r[1].hi && r[1].multiplicity == 1);
        assert!(r[0].hi <= r[1].lo);
    }

    #[test]
    fn gcd_cancels_a_pole_exactly_but_keeps_a_nearby_root() {
        // N/D with N = (x−2)(x−2.0001)(x²+1), D = (x−2)(x+3): the common root 2 is a removable
        // singularity, 2.0001 is a genuine root 10⁻⁴ away from it.
        let close = dec("2.0001");
        let n = UPoly::from_roots(&[int(2), close.clone()]).mul(&UPoly::from_i64s(&[1, 0, 1]));
        let d = UPoly::from_roots(&[int(2), int(-3)]);
        let g = n.gcd(&d);
        assert_eq!(g, UPoly::from_roots(&[int(2)]));
        let (nq, rem) = n.div_rem(&g);
        assert!(rem.is_zero());
        let r = positive_roots(&nq);
        assert_eq!(r.len(), 1);
        assert_root(&r[0], &close, 1);
    }

    #[test]
    fn wilkinson_twelve() {
        let roots: Vec<_> = (1..=12).map(int).collect();
        let p = UPoly::from_roots(&roots);
        let r = positive_roots(&p);
        assert_eq!(r.len(), 12);
        for (x, k) in r.iter().zip(1..) {
            assert!((x.value - k as f64).abs() <= 1e-12 * k as f64);
            assert_root(x, &int(k), 1);
        }
    }

    #[test]
    fn big_decimal_coefficients() {
        // Roots given with 30 decimals, times an irreducible quadratic with 30-digit data, so
        // the coefficients carry denominators up to 10^90.
        let r1 = dec("0.123456789012345678901234567891");
        let r2 = dec("3.141592653589793238462643383279");
        let r3 = dec("3.141592653589793238462643383280"); // 10⁻³⁰ above r2
        let quad = UPoly::new(vec![
            dec("2.718281828459045235360287471352"),
            dec("-1.000000000000000000000000000001"),
            dec("1.5e-3"),
        ]);
        assert!(real_roots(&quad).is_empty() || quad.coeffs()[1].is_zero() || {
            // discriminant b² − 4ac < 0 ⇔ no real roots; checked exactly:
            let c = quad.coeffs();
            &c[1] * &c[1] - int(4) * &c[0] * &c[2] >= int(0)
        });
        let p = UPoly::from_roots(&[r1.clone(), r2.clone(), r3.clone(), int(-5)]).mul(&quad);
        let found = positive_roots(&p);
        let quad_roots = real_roots(&quad);
        assert_eq!(found.len(), 3 + quad_roots.iter().filter(|r| r.value > 0.0).count());
        let ours: Vec<_> = found
            .iter()
            .filter(|x| quad_roots.iter().all(|y| y.value != x.value))
            .collect();
        assert_eq!(ours.len(), 3);
        assert_root(ours[0], &r1, 1);
        assert!(ours[1].lo < r2 && r2 <= ours[1].hi);
        assert!(ours[2].lo < r3 && r3 <= ours[2].hi);
        // Every reported root is a genuine sign change of the exact polynomial.
        for x in &found {
            if x.lo != x.hi {
                assert!(p.eval(&x.lo).signum() != p.eval(&x.hi).signum());
            }
        }
    }

    #[test]
    fn no_positive_roots() {
        assert!(positive_roots(&UPoly::from_i64s(&[1, 0, 1])).is_empty());
        assert!(positive_roots(&UPoly::from_roots(&[int(-1), int(-2), q(-1, 7)])).is_empty());
        assert!(real_roots(&UPoly::from_i64s(&[1, 0, 1])).is_empty());
    }

    #[test]
    fn roots_at_zero_are_excluded_from_positive_roots() {
        // x³ (x − 1)
        let p = UPoly::from_i64s(&[0, 0, 0, -1, 1]);
        let pos = positive_roots(&p);
        assert_eq!(pos.len(), 1);
        assert_root(&pos[0], &int(1), 1);
        let all = real_roots(&p);
        assert_eq!(all.len(), 2);
        assert_root(&all[0], &int(0), 3);
        assert_root(&all[1], &int(1), 1);
    }

    #[test]
    fn biquadratic() {
        let p = UPoly::from_i64s(&[4, 0, -5, 0, 1]);
        let pos = positive_roots(&p);
        assert_eq!(values(&pos), [1.0, 2.0]);
        assert_eq!(values(&real_roots(&p)), [-2.0, -1.0, 1.0, 2.0]);
    }

    #[test]
    fn roots_in_is_half_open() {
        let p = UPoly::from_roots(&[int(1), int(2), int(3)]);
        assert_eq!(values(&roots_in(&p, &int(1), &int(3))), [2.0, 3.0]);
        assert_eq!(values(&roots_in(&p, &q(1, 2), &q(5, 2))), [1.0, 2.0]);
        assert!(roots_in(&p, &int(3), &int(1)).is_empty());
        // Bounds closer to a root than any isolating interval is wide.
        let eps = BigRational::new(1.into(), num_traits::pow(BigInt::from(10), 40));
        let r = roots_in(&p, &(int(2) - &eps), &(int(3) - &eps));
        assert_eq!(values(&r), [2.0]);
        let r = roots_in(&p, &(int(2) + &eps), &(int(3) + &eps));
        assert_eq!(values(&r), [3.0]);
        // Irrational root √2 against tight rational bounds on either side.
        let s = UPoly::from_i64s(&[-2, 0, 1]);
        let below = dec("1.41421356237309504880168872420969807");
        let above = dec("1.41421356237309504880168872420969808");
        assert_eq!(roots_in(&s, &below, &above).len(), 1);
        assert!(roots_in(&s, &above, &int(2)).is_empty());
        assert!(roots_in(&s, &int(0), &below).is_empty());
        // Zero root counted only when 0 ∈ (lo, hi].
        let z = UPoly::from_i64s(&[0, 1]);
        assert_eq!(roots_in(&z, &int(-1), &int(0)).len(), 1);
        assert!(roots_in(&z, &int(0), &int(1)).is_empty());
    }

    #[test]
    fn zero_and_constant_polynomials_have_no_roots() {
        assert!(real_roots(&UPoly::zero()).is_empty());
        assert!(positive_roots(&UPoly::zero()).is_empty());
        assert!(real_roots(&UPoly::from_i64s(&[5])).is_empty());
        assert_eq!(UPoly::from_i64s(&[0, 0]), UPoly::zero());
        assert_eq!(UPoly::zero().degree(), None);
    }

    #[test]
    fn irrational_roots_are_correctly_rounded() {
        let p = UPoly::from_i64s(&[-2, 0, 1]);
        let r = real_roots(&p);
        assert_eq!(values(&r), [-std::f64::consts::SQRT_2, std::f64::consts::SQRT_2]);
        // x³ − 2
        let r = real_roots(&UPoly::from_i64s(&[-2, 0, 0, 1]));
        assert_eq!(r.len(), 1);
        assert!((r[0].value - 2f64.cbrt()).abs() <= f64::EPSILON * 2.0);
        let lo3 = &r[0].lo * &r[0].lo * &r[0].lo;
        let hi3 = &r[0].hi * &r[0].hi * &r[0].hi;
        assert!(lo3 < int(2) && int(2) < hi3);
    }

    #[test]
    fn tiny_and_huge_roots() {
        let tiny = dec("1.5e-300");
        let huge = dec("2.5e300");
        let p = UPoly::from_roots(&[tiny.clone(), huge.clone(), dec("7e-5")]);
        let r = positive_roots(&p);
        assert_eq!(r.len(), 3);
        assert_root(&r[0], &tiny, 1);
        assert_root(&r[1], &dec("7e-5"), 1);
        assert_root(&r[2], &huge, 1);
    }

    #[test]
    fn cluster_of_sixteen_roots_within_a_thousandth() {
        let roots: Vec<_> = (0..16).map(|i| q(1, 1) + q(i, 16_000)).collect();
        let p = UPoly::from_roots(&roots);
        let r = positive_roots(&p);
        assert_eq!(r.len(), 16);
        for (x, e) in r.iter().zip(&roots) {
            assert_root(x, e, 1);
        }
    }

    #[test]
    fn square_free_factorisation() {
        let p = poly_with_roots(&[(int(1), 3), (int(-2), 2), (int(5), 1)]).scale(&q(3, 4));
        let f = p.square_free_factors();
        let expect = vec![
            (UPoly::from_roots(&[int(5)]), 1),
            (UPoly::from_roots(&[int(-2)]), 2),
            (UPoly::from_roots(&[int(1)]), 3),
        ];
        assert_eq!(f, expect);
        let back = f.iter().fold(UPoly::constant(q(3, 4)), |acc, (g, i)| {
            (0..*i).fold(acc, |acc, _| acc.mul(g))
        });
        assert_eq!(back, p);
        assert!(UPoly::from_i64s(&[7]).square_free_factors().is_empty());
    }

    #[test]
    fn arithmetic() {
        let a = UPoly::from_i64s(&[1, 2, 3]);
        let b = UPoly::from_i64s(&[-1, 1]);
        let (qq, r) = a.div_rem(&b);
        assert_eq!(qq.mul(&b).add(&r), a);
        assert_eq!(r.degree(), Some(0));
        assert_eq!(r.coeffs()[0], a.eval(&int(1)));
        assert_eq!(a.sub(&a), UPoly::zero());
        assert_eq!(a.derivative(), UPoly::from_i64s(&[2, 6]));
        assert_eq!(a.eval_f64(2.0), 17.0);
        assert_eq!(a.gcd(&UPoly::zero()), a.monic());
        assert_eq!(UPoly::zero().gcd(&UPoly::zero()), UPoly::zero());
        assert_eq!(a.gcd(&b), UPoly::from_i64s(&[1]));
    }

    #[test]
    #[should_panic(expected = "division by the zero polynomial")]
    fn division_by_zero_panics() {
        let _ = UPoly::from_i64s(&[1, 1]).div_rem(&UPoly::zero());
    }

    #[test]
    fn dyadic_rounding() {
        for x in [1.0, 0.1, 3.5e-310, 5e-324, 1.7976931348623157e308, -2.5, 1e-300] {
            let r = BigRational::from_float(x).unwrap();
            let (n, d) = (r.numer().clone(), r.denom().clone());
            let k = d.bits() - 1;
            assert_eq!(dyadic_to_f64(&n, k), x);
        }
        // Ties to even: 1 + 2^-53 rounds to 1, 1 + 3·2^-53 rounds to 1 + 2^-51.
        assert_eq!(dyadic_to_f64(&((BigInt::one() << 53u32) + 1), 53), 1.0);
        assert_eq!(
            dyadic_to_f64(&((BigInt::one() << 53u32) + 3), 53),
            1.0 + 2f64.powi(-51)
        );
        assert_eq!(dyadic_to_f64(&(BigInt::one() << 1100u32), 0), f64::INFINITY);
    }

    /// Tiny deterministic linear congruential generator (no extra dependencies).
    struct Lcg(u64);

    impl Lcg {
        fn next(&mut self) -> u64 {
            self.0 = self
                .0
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            self.0 >> 33
        }

        fn below(&mut self, n: u64) -> u64 {
            self.next() % n
        }
    }

    #[test]
    fn random_polynomials_from_known_roots() {
        let mut rng = Lcg(0x5eed);
        for case in 0..300 {
            let mut roots: Vec<(BigRational, u32)> = Vec::new();
            let count = 1 + rng.below(6);
            while roots.len() < count as usize {
                let r = match rng.below(4) {
                    // a small rational
                    0 | 1 => q(rng.below(401) as i64 - 200, 1 + rng.below(60) as i64),
                    // a near-twin of an existing root
                    2 if !roots.is_empty() => {
                        let i = rng.below(roots.len() as u64) as usize;
                        let d = 1 + rng.below(9) as i64;
                        &roots[i].0 + q(d, 10i64.pow(1 + rng.below(12) as u32))
                    }
                    // a decimal with many digits
                    _ => dec(&format!(
                        "{}.{:09}{:09}",
                        rng.below(50) as i64 - 25,
                        rng.below(1_000_000_000),
                        rng.below(1_000_000_000)
                    )),
                };
                if roots.iter().all(|(x, _)| *x != r) {
                    roots.push((r, 1 + rng.below(3) as u32));
                }
            }
            let mut p = poly_with_roots(&roots).scale(&q(rng.below(1000) as i64 + 1, 37));
            if rng.below(2) == 0 {
                // times an irreducible quadratic x² + c, c > 0
                p = p.mul(&UPoly::new(vec![q(1 + rng.below(100) as i64, 7), int(0), int(1)]));
            }
            roots.sort_by(|a, b| a.0.cmp(&b.0));
            let found = real_roots(&p);
            assert_eq!(found.len(), roots.len(), "case {case}: {roots:?}");
            for (f, (r, m)) in found.iter().zip(&roots) {
                assert_root(f, r, *m);
            }
            let pos: Vec<_> = roots.iter().filter(|(r, _)| r.is_positive()).collect();
            let fpos = positive_roots(&p);
            assert_eq!(fpos.len(), pos.len(), "case {case}");
            for (f, (r, m)) in fpos.iter().zip(pos) {
                assert_root(f, r, *m);
            }
        }
    }

    /// Degree-12 polynomial with ~40-digit rational coefficients.
    fn timing_poly(rng: &mut Lcg) -> UPoly {
        let roots: Vec<_> = (0..12)
            .map(|_| {
                let n = rng.below(1_000_000) as i64 - 300_000;
                let d = 1 + rng.below(999) as i64;
                q(n, d * 1000)
            })
            .collect();
        UPoly::from_roots(&roots).scale(&q(rng.below(1_000_000) as i64 + 1, 999_983))
    }

    #[test]
    #[ignore = "timing; run with --release -- --ignored --nocapture"]
    fn timing() {
        const REPS: usize = 20;
        let mut rng = Lcg(42);
        let polys: Vec<_> = (0..200).map(|_| timing_poly(&mut rng)).collect();
        let digits: usize = polys[0]
            .coeffs()
            .iter()
            .map(|c| c.numer().to_string().len() + c.denom().to_string().len())
            .max()
            .unwrap();
        let start = std::time::Instant::now();
        let mut n = 0;
        for _ in 0..REPS {
            for p in &polys {
                n += positive_roots(p).len();
            }
        }
        n /= REPS;
        let per = start.elapsed() / (REPS * polys.len()) as u32;
        println!("iso {} ref {} pre {}", T_ISO.swap(0, std::sync::atomic::Ordering::Relaxed)/4000, T_REF.swap(0, std::sync::atomic::Ordering::Relaxed)/4000, T_PRE.swap(0, std::sync::atomic::Ordering::Relaxed)/4000);
        println!("evals {} nodes {}", EVALS.load(std::sync::atomic::Ordering::Relaxed), NODES.load(std::sync::atomic::Ordering::Relaxed));
        println!("degree 12, up to {digits} digits per coefficient: {per:?} per positive_roots ({n} roots)");
        // random dense polynomials with 40-digit rational coefficients
        let polys: Vec<_> = (0..200)
            .map(|_| {
                UPoly::new(
                    (0..13)
                        .map(|_| {
                            let n: BigInt = format!("{}{:018}", rng.below(1 << 30), rng.next()).parse().unwrap();
                            let d: BigInt = format!("{}{:018}", 1 + rng.below(1 << 30), rng.next()).parse().unwrap();
                            let s = if rng.below(2) == 0 { -1 } else { 1 };
                            BigRational::new(n * s, d)
                        })
                        .collect(),
                )
            })
            .collect();
        let start = std::time::Instant::now();
        let mut n = 0;
        for _ in 0..REPS {
            for p in &polys {
                n += positive_roots(p).len();
            }
        }
        n /= REPS;
        let per = start.elapsed() / (REPS * polys.len()) as u32;
        println!("random dense degree 12, 40-digit coefficients: {per:?} per positive_roots ({n} roots)");
    }
}
#[cfg(test)]
mod dbg {
    use super::*;
    #[test]
    fn dbg_cubic() {
        let p = UPoly::from_i64s(&[-6, 11, -6, 1]);
        for r in real_roots(&p) { println!("{} {} {} {}", r.value, r.multiplicity, r.lo, r.hi); }
    }
}
