//! [`UPoly`], dense univariate polynomials over ℚ (exact arithmetic, gcd, square-free
//! decomposition), and [`F64Poly`], their `f64` rounding for Horner evaluation.

use super::*;
use crate::algebra::big_rational;

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Zero};

/// Dense univariate polynomial over ℚ.
///
/// Coefficients are stored in ascending powers (`coeffs[i]` multiplies `xⁱ`) without trailing
/// zeros, so the zero polynomial is the empty vector and equality is structural.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct UPoly {
    coeffs: Vec<BigRational>,
}

/// A univariate polynomial with `f64` coefficients (ascending powers), evaluated by Horner's
/// scheme: the one f64 polynomial evaluation of the crate (display, plotting, simulation).
///
/// ```
/// use model::roots::F64Poly;
/// // 1 + 2x + 3x^2 at x = 2
/// assert_eq!(F64Poly(vec![1.0, 2.0, 3.0]).eval(2.0), 17.0);
/// ```
#[derive(Clone, Debug, Default, PartialEq)]
pub struct F64Poly(pub Vec<f64>);

impl F64Poly {
    /// Value at `x` by Horner's scheme.
    pub fn eval(&self, x: f64) -> f64 {
        self.eval_lanes([x])[0]
    }

    /// Values at the `N` points `x`, lane by lane: each lane is [`F64Poly::eval`] at its point,
    /// the same operations in the same order (so the same value to the bit), and the lanes'
    /// Horner chains are independent, so they overlap instead of waiting on one another.
    pub fn eval_lanes<const N: usize>(&self, x: [f64; N]) -> [f64; N] {
        self.0.iter().rev().fold([0.0; N], |acc, c| {
            std::array::from_fn(|l| acc[l] * x[l] + c)
        })
    }
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
        Self::new(
            coeffs
                .iter()
                .map(|&c| BigRational::from_integer(c.into()))
                .collect(),
        )
    }

    /// The monic polynomial `∏ (x − rᵢ)` (the constant `1` for an empty slice).
    pub fn from_roots(roots: &[BigRational]) -> Self {
        roots
            .iter()
            .fold(Self::constant(BigRational::one()), |acc, r| {
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

    /// Exact value at `x` (homogeneous integer Horner scheme, a single reduction at the end).
    pub fn eval(&self, x: &BigRational) -> BigRational {
        let Some(n) = self.degree() else {
            return BigRational::zero();
        };
        let (z, l) = common_denominator(self);
        let (num, den) = (x.numer(), x.denom());
        let mut acc = z[n].clone();
        let mut pw = BigInt::one();
        for c in z[..n].iter().rev() {
            pw *= den;
            acc = acc * num + c * &pw;
        }
        big_rational::reduced(acc, l * pw)
    }

    /// Approximate value at `x` in `f64` (coefficients rounded to `f64`, then Horner).
    ///
    /// Only for display and plotting: never use it to decide whether something is a root.
    pub fn eval_f64(&self, x: f64) -> f64 {
        self.to_f64().eval(x)
    }

    /// The coefficients rounded once to `f64` (each to the nearest double).
    pub fn to_f64(&self) -> F64Poly {
        F64Poly(
            self.coeffs
                .iter()
                .map(crate::aircraft::rational_to_f64)
                .collect(),
        )
    }

    /// The derivative.
    pub fn derivative(&self) -> UPoly {
        Self::new(
            self.coeffs
                .iter()
                .enumerate()
                .skip(1)
                .map(|(i, c)| big_rational::mul(c, &BigRational::from_integer(i.into())))
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
                    (Some(a), Some(b)) => big_rational::add(a, b),
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
        // Integer convolution over a common denominator: one reduction per coefficient.
        let ((za, la), (zb, lb)) = (common_denominator(self), common_denominator(o));
        let mut out = vec![BigInt::zero(); za.len() + zb.len() - 1];
        for (i, a) in za.iter().enumerate().filter(|(_, a)| !a.is_zero()) {
            for (j, b) in zb.iter().enumerate() {
                out[i + j] += a * b;
            }
        }
        let den = la * lb;
        Self::new(
            out.into_iter()
                .map(|c| big_rational::reduced(c, den.clone()))
                .collect(),
        )
    }

    /// The scalar multiple `c · self`.
    pub fn scale(&self, c: &BigRational) -> UPoly {
        Self::new(
            self.coeffs
                .iter()
                .map(|a| big_rational::mul(a, c))
                .collect(),
        )
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

    /// The exact quotient `self / d` when `d` divides `self`, `None` otherwise (and for `d = 0`).
    /// It divides in `ℤ[x]` by the primitive part of `d` (Gauss's lemma: a primitive divisor in
    /// `ℚ[x]` divides in `ℤ[x]`), so no coefficient outgrows the quotient's, where the
    /// pseudo-division of [`UPoly::div_rem`] multiplies every coefficient by `lc(d)` at each step.
    pub fn div_exact(&self, d: &UPoly) -> Option<UPoly> {
        let lc = d.leading_coeff()?;
        let dz = to_primitive_z(d);
        let (pz, lp) = common_denominator(self);
        let q = z_checked_div(&pz, &dz)?;
        // d = dz · lc / lc(dz), self = pz / lp.
        let scale = big_rational::mul(&BigRational::new(dz[dz.len() - 1].clone(), lp), &lc.recip());
        Some(z_to_upoly(&q).scale(&scale))
    }

    /// Euclidean division: `(q, r)` with `self = q·d + r` and `deg r < deg d`.
    ///
    /// # Panics
    ///
    /// Panics if `d` is the zero polynomial (division by zero); that is the only panic.
    pub fn div_rem(&self, d: &UPoly) -> (UPoly, UPoly) {
        let n = d
            .degree()
            .expect("UPoly::div_rem: division by the zero polynomial");
        if self.coeffs.len() <= n {
            return (Self::zero(), self.clone());
        }
        // Pseudo-division in ℤ[x]: with self = P/lp and d = D/ld (integer P, D),
        // lc(D)^e·P = Q·D + R, hence q = Q·ld/(lc^e·lp) and r = R/(lc^e·lp).
        let ((pz, lp), (dz, ld)) = (common_denominator(self), common_denominator(d));
        let lc = &dz[n];
        let mut r = pz;
        let mut q = vec![BigInt::zero(); r.len() - n];
        let mut lc_pow = BigInt::one();
        for s in (0..q.len()).rev() {
            let c = r[s + n].clone();
            if !lc.is_one() {
                for x in q[s + 1..].iter_mut().chain(r[..s + n].iter_mut()) {
                    *x *= lc;
                }
                lc_pow *= lc;
            }
            if !c.is_zero() {
                for (j, dc) in dz.iter().enumerate().take(n) {
                    r[s + j] -= &c * dc;
                }
            }
            r[s + n] = BigInt::zero();
            q[s] = c;
        }
        r.truncate(n);
        let den = lc_pow * lp;
        let q = q
            .into_iter()
            .map(|c| big_rational::reduced(c * &ld, den.clone()));
        let r = r.into_iter().map(|c| big_rational::reduced(c, den.clone()));
        (Self::new(q.collect()), Self::new(r.collect()))
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
    /// Runs in `ℤ[x]` on the primitive part (all gcds primitive, all quotients exact).
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
