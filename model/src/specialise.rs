//! Specialisation: the symbol values of an aircraft, exact rationals of f64 inputs, and the
//! specialised derivation's polynomials as univariate ([`UPoly`]) or bivariate ([`InAileron`])
//! polynomials in P0.
//!
//! The helpers shared by `analysis`, `simulation`, `plot` and `emit`; they depend only on
//! `algebra`, `aircraft`, `equations`, `derivation` and `roots`, so data flows one way.
//!
//! ```
//! use model::aircraft::Aircraft;
//! use model::specialise::{exact_f64, specialisation};
//!
//! let values = specialisation(&Aircraft::a(), 0.0349);
//! // every parameter, the elevator and the rudder (delta_r = 0)
//! assert_eq!(values.len(), model::aircraft::Param::ALL.len() + 2);
//! assert_eq!(exact_f64(0.5).to_f64(), 0.5);
//! ```

use crate::aircraft::{Aircraft, Param};
use crate::algebra::{Poly, Sym, Q};
use crate::derivation::{homogenize, Derivation, TRIM_DEGREE};
use crate::equations::symbols;
use crate::roots::{F64Poly, UPoly};
use num_rational::BigRational;
use num_traits::Zero;
use std::sync::OnceLock;

pub mod hopf;
pub mod hopf_in_aileron;

/// The symbol values of an aircraft's data (every [`Param`], exact), without any control.
pub fn aircraft_values(aircraft: &Aircraft) -> Vec<(Sym, Q)> {
    let s = symbols();
    Param::ALL
        .iter()
        .map(|p| (s.param(*p), Q::from_big(aircraft.exact(*p).clone())))
        .collect()
}

/// The symbol values that specialise the derivation to an aircraft and elevator setting
/// (delta_r = 0 for the unconstrained roll).
pub fn specialisation(aircraft: &Aircraft, delta_e_rad: f64) -> Vec<(Sym, Q)> {
    let s = symbols();
    let mut values = aircraft_values(aircraft);
    values.push((s.delta_e, exact_f64(delta_e_rad)));
    values.push((s.delta_r, Q::ZERO));
    values
}

/// The exact rational value of a finite f64.
pub fn exact_f64(x: f64) -> Q {
    Q::from_big(BigRational::from_float(x).unwrap_or_default())
}

/// The parametric derivation, derived once per process (every analysis specialises it).
pub fn parametric() -> &'static Derivation {
    static P: OnceLock<Derivation> = OnceLock::new();
    P.get_or_init(Derivation::parametric)
}

/// The characteristic coefficients `c1..c5` of J5 at the trim of the parametric derivation
/// ([`crate::derivation::hopf::characteristic_coefficients`]), in the trim symbols; computed once.
pub fn parametric_characteristic() -> &'static [Poly; 5] {
    static C: OnceLock<[Poly; 5]> = OnceLock::new();
    C.get_or_init(|| crate::derivation::hopf::characteristic_coefficients(&parametric().jacobian))
}

/// A polynomial in `x` alone as a dense univariate polynomial. Panics if another symbol occurs
/// (the specialised derivation leaves only P0 by construction).
pub fn univariate(p: &Poly, x: Sym) -> UPoly {
    let c = p
        .univariate_coeffs(x)
        .expect("specialised criterion polynomials are univariate in P0");
    UPoly::new(c.iter().map(Q::to_big).collect())
}

/// A dense univariate polynomial in P0 as a [`Poly`] (the inverse of [`univariate`] in P0).
pub fn from_univariate(u: &UPoly) -> Poly {
    let s = symbols();
    Poly::from_terms(u.coeffs().iter().enumerate().map(|(i, c)| {
        (
            crate::algebra::Mono::var(s.p0, i as u32),
            Q::from_big(c.clone()),
        )
    }))
}

/// Cancels every common factor of `num / den` exactly; returns the reduced pair.
pub fn cancel(num: &UPoly, den: &UPoly) -> (UPoly, UPoly) {
    let (mut n, mut d) = (num.clone(), den.clone());
    if n.is_zero() || d.is_zero() {
        return (n, d);
    }
    loop {
        let g = n.gcd(&d);
        if g.degree().unwrap_or(0) == 0 {
            return (n, d);
        }
        n = n.div_exact(&g).expect("the gcd divides the numerator");
        d = d.div_exact(&g).expect("the gcd divides the denominator");
    }
}

/// The unconstrained roll's step-8 results for data `values` (all parameters, or some left
/// symbolic as in a clearance box): det A and the trim numerators under one integer scale (so
/// every trim ratio stays exact), det J5 and d in the trim symbols with their denominators
/// cleared, and the trim condition, `det J5 det(A)^2` and `d det(A)^2` on the trim, in P0,
/// delta_a and the symbols `values` leaves free. Each is exact up to a constant factor.
#[derive(Clone, Debug)]
pub struct OnTrim {
    /// det A (Eq. 4).
    pub det_a: Poly,
    /// Numerators of [alpha0, beta0, Q0, R0] over `det_a`.
    pub trim: [Poly; 4],
    /// det J5 in the trim symbols.
    pub det_j5: Poly,
    /// The static-residual denominator d (Eq. 22) in the trim symbols.
    pub d: Poly,
    /// The trim condition `det(A)^2 p_dot` on the trim.
    pub trim_condition: Poly,
    /// `det J5 det(A)^2` on the trim.
    pub jump_at: Poly,
    /// `d det(A)^2` on the trim.
    pub d_at: Poly,
}

/// [`OnTrim`] of the parametric derivation `par` with `values` substituted into its small
/// trim-level results first (step 8 then runs on the small specialised polynomials).
pub fn on_trim(par: &Derivation, values: &[(Sym, Q)]) -> OnTrim {
    let s = symbols();
    let cleared = |ps: &[&Poly]| {
        Poly::subs_values_cleared(ps, values)
            .expect("the parametric derivation has integer coefficients")
    };
    let t = cleared(&[
        &par.det_a,
        &par.trim[0],
        &par.trim[1],
        &par.trim[2],
        &par.trim[3],
    ]);
    let (det_a, trim) = (
        t[0].clone(),
        [t[1].clone(), t[2].clone(), t[3].clone(), t[4].clone()],
    );
    let det_j5 = cleared(&[&par.det_j5])[0].clone();
    let d = cleared(&[&par.d])[0].clone();
    let roll = cleared(&[&par.roll_at_trim])[0].clone();
    let t4 = [s.alpha0, s.beta0, s.q0, s.r0];
    let step8 = |f: &Poly| homogenize(f, &t4, &trim, &det_a, TRIM_DEGREE);
    OnTrim {
        trim_condition: step8(&roll),
        jump_at: step8(&det_j5),
        d_at: step8(&d),
        det_a,
        trim,
        det_j5,
        d,
    }
}

/// A polynomial in P0 and delta_a (specialised: no other symbol) as [`InAileron`], scaled by a
/// power of two (see [`in_aileron_all`]).
pub fn in_aileron(p: &Poly) -> InAileron {
    in_aileron_all(&[p]).remove(0)
}

/// Polynomials in P0 and delta_a as [`InAileron`]s, all scaled by the same power of two, which
/// brings their largest coefficient near 1 so that f64 evaluation neither overflows nor
/// underflows for any aircraft (cleared criterion polynomials carry integer scales of hundreds
/// of digits) and ratios of them are unchanged.
pub fn in_aileron_all(ps: &[&Poly]) -> Vec<InAileron> {
    let s = symbols();
    let cs: Vec<Vec<UPoly>> = ps
        .iter()
        .map(|p| {
            p.coeffs(s.delta_a)
                .iter()
                .map(|c| univariate(c, s.p0))
                .collect()
        })
        .collect();
    let log2 = |q: &BigRational| q.numer().bits() as i64 - q.denom().bits() as i64;
    let e = cs
        .iter()
        .flatten()
        .flat_map(|c| c.coeffs().iter().filter(|q| !q.is_zero()).map(log2))
        .max()
        .unwrap_or(0);
    let two = BigRational::from_integer(2.into());
    let scale = if e >= 0 {
        num_traits::pow(two.recip(), e as usize)
    } else {
        num_traits::pow(two, (-e) as usize)
    };
    cs.into_iter()
        .map(|c| InAileron(c.iter().map(|u| u.scale(&scale).to_f64()).collect()))
        .collect()
}

/// A polynomial in P0 and delta_a for f64 evaluation: `coeffs[i]` (a polynomial in P0, its
/// exact coefficients rounded once to f64) multiplies `delta_a^i`.
#[derive(Clone, Debug)]
pub struct InAileron(pub Vec<F64Poly>);

impl InAileron {
    /// The coefficients of the polynomial in delta_a at `p0`, in f64.
    pub fn at(&self, p0: f64) -> Vec<f64> {
        self.0.iter().map(|c| c.eval(p0)).collect()
    }

    /// Value at `(p0, delta_a)` in f64 (Horner in delta_a over Horner in P0).
    pub fn eval(&self, p0: f64, delta_a: f64) -> f64 {
        self.eval_lanes([p0], delta_a)[0]
    }

    /// [`InAileron::eval`] at each roll rate of `p0` (at the same `delta_a`), lane by lane with
    /// [`F64Poly::eval_lanes`]: the same values to the bit.
    pub fn eval_lanes<const N: usize>(&self, p0: [f64; N], delta_a: f64) -> [f64; N] {
        self.0.iter().rev().fold([0.0; N], |acc, c| {
            let c = c.eval_lanes(p0);
            std::array::from_fn(|l| acc[l] * delta_a + c[l])
        })
    }

    /// The real roots in delta_a at `p0` (at most two: the trim condition is at most quadratic),
    /// by the cancellation-free form of the quadratic formula.
    pub fn aileron_roots(&self, p0: f64) -> Roots {
        self.aileron_roots_lanes([p0])[0]
    }

    /// [`InAileron::aileron_roots`] at each roll rate of `p0`, the coefficients evaluated lane by
    /// lane with [`F64Poly::eval_lanes`]: the same roots to the bit.
    pub fn aileron_roots_lanes<const N: usize>(&self, p0: [f64; N]) -> [Roots; N] {
        let get = |i: usize| self.0.get(i).map_or([0.0; N], |c| c.eval_lanes(p0));
        let (c2, c1, c0) = (get(2), get(1), get(0));
        std::array::from_fn(|l| quadratic_roots(c2[l], c1[l], c0[l]))
    }
}

/// At most two real roots, ascending, without allocation.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Roots {
    r: [f64; 2],
    n: usize,
}

impl Roots {
    fn of(r: &[f64]) -> Roots {
        let mut out = Roots::default();
        for x in r {
            out.r[out.n] = *x;
            out.n += 1;
        }
        out
    }

    /// The roots as a slice.
    pub fn as_slice(&self) -> &[f64] {
        &self.r[..self.n]
    }

    /// The roots as a vector.
    pub fn to_vec(&self) -> Vec<f64> {
        self.as_slice().to_vec()
    }

    /// The root nearest to `target` (the first of two equally near ones, as
    /// [`Iterator::min_by`] picks), without going through memory: the walk of the primary
    /// branch asks this every step.
    pub fn nearest(&self, target: f64) -> Option<f64> {
        let [r0, r1] = self.r;
        match self.n {
            0 => None,
            1 => Some(r0),
            _ => Some(
                if (r1 - target).abs().total_cmp(&(r0 - target).abs()).is_lt() {
                    r1
                } else {
                    r0
                },
            ),
        }
    }

    /// The two roots `[lower, upper]` when there are two.
    pub fn pair(&self) -> Option<[f64; 2]> {
        (self.n == 2).then_some(self.r)
    }

    /// Whether there is no root.
    pub fn is_empty(&self) -> bool {
        self.n == 0
    }

    /// How many roots.
    pub fn len(&self) -> usize {
        self.n
    }
}

impl IntoIterator for Roots {
    type Item = f64;
    type IntoIter = std::iter::Take<std::array::IntoIter<f64, 2>>;
    fn into_iter(self) -> Self::IntoIter {
        self.r.into_iter().take(self.n)
    }
}

/// Real roots of `a x^2 + b x + c` (linear when `a = 0`), without cancellation, ascending.
pub fn quadratic_roots(a: f64, b: f64, c: f64) -> Roots {
    if a == 0.0 {
        return if b == 0.0 {
            Roots::default()
        } else {
            Roots::of(&[-c / b])
        };
    }
    let disc = b * b - 4.0 * a * c;
    if disc < 0.0 {
        return Roots::default();
    }
    let q = -0.5 * (b + b.signum() * disc.sqrt());
    if q == 0.0 {
        return Roots::of(&[0.0]);
    }
    let (x, y) = (q / a, c / q);
    if x <= y {
        Roots::of(&[x, y])
    } else {
        Roots::of(&[y, x])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quadratic_roots_are_accurate_without_cancellation() {
        // x^2 - 1e8 x + 1 = 0: roots 1e8 and 1e-8; the textbook formula loses the small one.
        let r = quadratic_roots(1.0, -1e8, 1.0).to_vec();
        assert_eq!(r.len(), 2);
        assert!((r[0] - 1e-8).abs() < 1e-22, "{r:?}");
        assert!((r[1] - 1e8).abs() < 1e-6);
        assert_eq!(quadratic_roots(0.0, 2.0, -1.0).to_vec(), vec![0.5]);
        assert!(quadratic_roots(1.0, 0.0, 1.0).is_empty());
    }
}
