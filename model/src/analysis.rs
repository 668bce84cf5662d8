//! What `model analyze` computes: divergence roll rates (Eq. 5, Table 1), jump roll rates
//! (roots of det K, Figs 7-8), the poles of det K, and the zero-sideslip departure points
//! (Fig. 11), each with its trim and aileron deflection.
//!
//! The derivation is specialised to the aircraft's exact data and the elevator setting, so the
//! criterion polynomials are univariate in P0 with exact rational coefficients. det K is the
//! rational function `jump / (det A * d det A)`; common factors are cancelled exactly by
//! univariate gcds before any root is sought, so a pole is never reported as a root, however
//! close a true root lies.

use crate::aircraft::{Aircraft, Param};
use crate::algebra::{Poly, Q, Sym};
use crate::derivation::{Derivation, Ratio};
use crate::equations::symbols;
use crate::roots::{positive_roots, UPoly};
use num_rational::BigRational;
use serde::Serialize;

/// A jump point: a positive root of det K on the unconstrained roll (delta_r = 0).
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct JumpPoint {
    /// Trim roll rate, rad/s.
    pub p0: f64,
    /// Aileron deflection holding this trim, rad.
    pub delta_a_rad: f64,
    /// The same in degrees.
    pub delta_a_deg: f64,
    /// Trim angle of attack, rad.
    pub alpha: f64,
    /// Trim sideslip, rad.
    pub beta: f64,
    /// Trim pitch rate, rad/s.
    pub q: f64,
    /// Trim yaw rate, rad/s.
    pub r: f64,
}

/// A departure point of the zero-sideslip roll: a positive root of det K at the beta = 0 trim.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct DeparturePoint {
    /// Trim roll rate, rad/s.
    pub p0: f64,
    /// Aileron deflection holding this trim, rad.
    pub delta_a_rad: f64,
    /// The same in degrees.
    pub delta_a_deg: f64,
    /// Trim angle of attack, rad.
    pub alpha: f64,
    /// Trim pitch rate, rad/s.
    pub q: f64,
    /// Trim yaw rate, rad/s.
    pub r: f64,
}

/// The zero-sideslip part of the analysis (section V).
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct ZeroSideslip {
    /// Positive roots of det K at the zero-sideslip trims, ascending.
    pub departure: Vec<DeparturePoint>,
}

/// Everything `model analyze` reports (angles in rad, rates in rad/s, lists ascending in P0).
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct Analysis {
    /// Aircraft name.
    pub aircraft: String,
    /// Elevator deflection, rad.
    pub delta_e_rad: f64,
    /// Eq. 5: positive roots of det A (pitch-yaw divergence), Table 1.
    pub divergence_roll_rates: Vec<f64>,
    /// Positive roots of det K (saddle-node jump points), Figs 7-8.
    pub jump: Vec<JumpPoint>,
    /// Positive roots of the static-residual denominator d (poles of det K), Fig. 8.
    pub det_k_poles: Vec<f64>,
    /// Section V: zero-sideslip roll.
    pub zero_sideslip: ZeroSideslip,
}

/// Why an aircraft cannot be analysed in closed form.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum AnalysisError {
    /// The elevator deflection is not a finite number.
    #[error("delta_e = {0} is not a finite angle")]
    DeltaE(f64),
    /// n_delta_a != 0 couples the aileron into the yaw equation.
    #[error(
        "n_delta_a = {0}: the closed-form criterion needs n_delta_a = 0 (with aileron yaw the \
         trim for a given P0 is no longer linear in alpha, beta, q, r); set n_delta_a = 0"
    )]
    AileronYaw(f64),
}

/// The symbol values that specialise the derivation to an aircraft and elevator setting
/// (delta_r = 0 for the unconstrained roll).
pub fn specialisation(aircraft: &Aircraft, delta_e_rad: f64) -> Vec<(Sym, Q)> {
    let s = symbols();
    let mut values: Vec<(Sym, Q)> = Param::ALL
        .iter()
        .map(|p| (s.param(*p), Q::from_big(aircraft.exact(*p).clone())))
        .collect();
    values.push((s.delta_e, exact_f64(delta_e_rad)));
    values.push((s.delta_r, Q::ZERO));
    values
}

/// The exact rational value of a finite f64.
pub fn exact_f64(x: f64) -> Q {
    Q::from_big(BigRational::from_float(x).unwrap_or_default())
}

/// Runs the analysis for one aircraft at elevator deflection `delta_e_rad`.
pub fn analyze(aircraft: &Aircraft, delta_e_rad: f64) -> Result<Analysis, AnalysisError> {
    if !delta_e_rad.is_finite() {
        return Err(AnalysisError::DeltaE(delta_e_rad));
    }
    let nda = aircraft.value(Param::NDeltaA);
    if nda != 0.0 {
        return Err(AnalysisError::AileronYaw(nda));
    }
    let s = symbols();
    let d = Derivation::derive(&specialisation(aircraft, delta_e_rad));
    let u = |p: &Poly| univariate(p, s.p0);

    let det_a = u(&d.det_a);
    let divergence_roll_rates = positive_roots(&det_a).iter().map(|r| r.value).collect();

    let (poles_num, _) = cancel(&u(&d.d_det_a), &det_a);
    let det_k_poles = positive_roots(&poles_num).iter().map(|r| r.value).collect();

    // A root shared with det A after cancellation has no finite trim: not a jump point.
    let jump_num = strip(&cancel(&u(&d.jump), &det_a.mul(&u(&d.d_det_a))).0, &det_a);
    let trim_u: Vec<UPoly> = d.trim.iter().map(u).collect();
    let jump = positive_roots(&jump_num)
        .iter()
        .map(|root| {
            let p0 = root.value;
            let [alpha, beta, q, r] = trim_at(&trim_u, &det_a, p0)[..] else {
                unreachable!("four trim states")
            };
            let da = eval_trim(&d.delta_a, &[(s.alpha0, alpha), (s.beta0, beta), (s.p0, p0), (s.q0, q), (s.r0, r)]);
            JumpPoint { p0, delta_a_rad: da, delta_a_deg: da.to_degrees(), alpha, beta, q, r }
        })
        .collect();

    let zs_det = u(&d.zs_det);
    let zs_num = strip(&cancel(&u(&d.zs_jump), &zs_det.mul(&u(&d.zs_d_det))).0, &zs_det);
    let zs_trim_u: Vec<UPoly> = d.zs_trim.iter().map(u).collect();
    let departure = positive_roots(&zs_num)
        .iter()
        .map(|root| {
            let p0 = root.value;
            let [alpha, q, r] = trim_at(&zs_trim_u, &zs_det, p0)[..] else {
                unreachable!("three trim states")
            };
            let da = eval_trim(&d.zs_delta_a, &[(s.alpha0, alpha), (s.beta0, 0.0), (s.p0, p0), (s.q0, q), (s.r0, r)]);
            DeparturePoint { p0, delta_a_rad: da, delta_a_deg: da.to_degrees(), alpha, q, r }
        })
        .collect();

    Ok(Analysis {
        aircraft: aircraft.name.clone(),
        delta_e_rad,
        divergence_roll_rates,
        jump,
        det_k_poles,
        zero_sideslip: ZeroSideslip { departure },
    })
}

/// A polynomial in `x` alone as a dense univariate polynomial. Panics if another symbol occurs
/// (the specialised derivation leaves only P0 by construction).
pub fn univariate(p: &Poly, x: Sym) -> UPoly {
    let c = p
        .univariate_coeffs(x)
        .expect("specialised criterion polynomials are univariate in P0");
    UPoly::new(c.iter().map(Q::to_big).collect())
}

/// Cancels every common factor of `num / den` exactly; returns the reduced pair.
pub fn cancel(num: &UPoly, den: &UPoly) -> (UPoly, UPoly) {
    let (mut n, mut d) = (num.clone(), den.clone());
    loop {
        let g = n.gcd(&d);
        if g.degree().unwrap_or(0) == 0 {
            return (n, d);
        }
        n = n.div_rem(&g).0;
        d = d.div_rem(&g).0;
    }
}

/// Removes from `p` every root it shares with `q` (all multiplicities).
fn strip(p: &UPoly, q: &UPoly) -> UPoly {
    let mut p = p.clone();
    loop {
        let g = p.gcd(q);
        if g.degree().unwrap_or(0) == 0 {
            return p;
        }
        p = p.div_rem(&g).0;
    }
}

/// Trim states `num_i(P0) / den(P0)` evaluated exactly at the f64 `p0`, then rounded.
fn trim_at(nums: &[UPoly], den: &UPoly, p0: f64) -> Vec<f64> {
    let x = exact_f64(p0).to_big();
    let dv = den.eval(&x);
    nums.iter()
        .map(|n| Q::from_big(n.eval(&x) / dv.clone()).to_f64())
        .collect()
}

fn eval_trim(r: &Ratio, values: &[(Sym, f64)]) -> f64 {
    let look = |s: Sym| values.iter().find(|(t, _)| *t == s).map_or(f64::NAN, |(_, v)| *v);
    r.num.eval_f64(&look) / r.den.eval_f64(&look)
}
