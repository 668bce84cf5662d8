//! What `model analyze` computes: divergence roll rates (Eq. 5, Table 1), jump roll rates
//! (roots of det K, Figs 7-8), the poles of det K, and the zero-sideslip departure points
//! (Fig. 11), each with its trim and aileron deflection.
//!
//! The derivation is specialised to the aircraft's exact data and the elevator setting, so the
//! criterion polynomials are univariate in P0 with exact rational coefficients. det K is the
//! rational function `jump / (d det(A)^2)` (both carry det(A)^2 from clearing the trim's
//! denominators); common factors are cancelled exactly by
//! univariate gcds before any root is sought, so a pole is never reported as a root, however
//! close a true root lies.

use crate::aircraft::{Aircraft, Param};
use crate::algebra::{Poly, Sym, Q};
use crate::derivation::{Derivation, Ratio, TRIM_DEGREE};
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
    #[error("delta_e = {0:e} rad: expected a finite elevator deflection of at most 90 deg")]
    DeltaE(f64),
    /// det J5 or det A vanishes identically along the trim curve: every trim is singular and
    /// det K is not defined (e.g. an aircraft with no roll damping, roll stiffness nor E).
    #[error(
        "{0} vanishes identically along the trim curve for this aircraft: the criterion is \
         undefined (check the roll derivatives and the inertias)"
    )]
    Degenerate(&'static str),
    /// n_delta_a != 0 couples the aileron into the yaw equation.
    #[error(
        "n_delta_a = {0}: the closed-form criterion needs n_delta_a = 0 (with aileron yaw the \
         trim for a given P0 is no longer linear in alpha, beta, q, r); set n_delta_a = 0"
    )]
    AileronYaw(f64),
    /// A reported value is not a finite f64 (the data's magnitudes overflow or underflow the
    /// f64 evaluation of the trim): refused rather than printed.
    #[error(
        "{0}: not a finite number in f64 for this data (its magnitudes overflow or underflow \
         double precision); no answer is given rather than a wrong one"
    )]
    NotFinite(String),
    /// Two distinct exact roots round to the same f64.
    #[error(
        "{what}: distinct exact roots that both round to P0 = {p0:e} rad/s, so they cannot be \
         told apart in f64 (they differ by less than one f64 step, {ulp:e} rad/s)"
    )]
    Indistinct {
        /// Which roots (e.g. a jump root and a pole of det K).
        what: String,
        /// Their common f64 value, rad/s.
        p0: f64,
        /// The f64 spacing at `p0`, rad/s: a bound on their separation.
        ulp: f64,
    },
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
    if !delta_e_rad.is_finite() || delta_e_rad.abs() > std::f64::consts::FRAC_PI_2 {
        return Err(AnalysisError::DeltaE(delta_e_rad));
    }
    let nda = aircraft.value(Param::NDeltaA);
    if nda != 0.0 {
        return Err(AnalysisError::AileronYaw(nda));
    }
    let s = symbols();
    let d = CriterionPolys::new(&Derivation::parametric(), aircraft, delta_e_rad);
    let u = |p: &Poly| univariate(p, s.p0);

    let det_a = u(&d.det_a);
    if det_a.is_zero() {
        return Err(AnalysisError::Degenerate("det A"));
    }
    if d.jump.is_zero() {
        return Err(AnalysisError::Degenerate("det J5"));
    }
    let divergence_roll_rates = positive_roots(&det_a).iter().map(|r| r.value).collect();

    let (poles_num, _) = cancel(&u(&d.d_det_a), &det_a);
    let det_k_poles = positive_roots(&poles_num).iter().map(|r| r.value).collect();

    // A root shared with det A after cancellation has no finite trim: not a jump point.
    let jump_num = strip(&cancel(&u(&d.jump), &u(&d.d_det_a)).0, &det_a);
    let trim_u: Vec<UPoly> = d.trim.iter().map(u).collect();
    let jump = positive_roots(&jump_num)
        .iter()
        .map(|root| {
            let p0 = root.value;
            let [alpha, beta, q, r] = trim_at(&trim_u, &det_a, p0)[..] else {
                unreachable!("four trim states")
            };
            let da = eval_trim(
                &d.delta_a,
                &[
                    (s.alpha0, alpha),
                    (s.beta0, beta),
                    (s.p0, p0),
                    (s.q0, q),
                    (s.r0, r),
                ],
            );
            JumpPoint {
                p0,
                delta_a_rad: da,
                delta_a_deg: da.to_degrees(),
                alpha,
                beta,
                q,
                r,
            }
        })
        .collect();

    let zs_det = u(&d.zs_det);
    let zs_num = strip(&cancel(&u(&d.zs_jump), &u(&d.zs_d_det)).0, &zs_det);
    let zs_trim_u: Vec<UPoly> = d.zs_trim.iter().map(u).collect();
    let departure = positive_roots(&zs_num)
        .iter()
        .map(|root| {
            let p0 = root.value;
            let [alpha, q, r] = trim_at(&zs_trim_u, &zs_det, p0)[..] else {
                unreachable!("three trim states")
            };
            let da = eval_trim(
                &d.zs_delta_a,
                &[
                    (s.alpha0, alpha),
                    (s.beta0, 0.0),
                    (s.p0, p0),
                    (s.q0, q),
                    (s.r0, r),
                ],
            );
            DeparturePoint {
                p0,
                delta_a_rad: da,
                delta_a_deg: da.to_degrees(),
                alpha,
                q,
                r,
            }
        })
        .collect();

    let analysis = Analysis {
        aircraft: aircraft.name.clone(),
        delta_e_rad,
        divergence_roll_rates,
        jump,
        det_k_poles,
        zero_sideslip: ZeroSideslip { departure },
    };
    check(&analysis)?;
    Ok(analysis)
}

/// The checks every answer passes before it is reported: every number finite, and no two
/// distinct exact roots (of one list, or a jump root and a pole) that look the same in f64.
fn check(a: &Analysis) -> Result<(), AnalysisError> {
    let finite = |what: String, v: &[f64]| {
        if v.iter().all(|x| x.is_finite()) {
            Ok(())
        } else {
            Err(AnalysisError::NotFinite(what))
        }
    };
    let jumps: Vec<f64> = a.jump.iter().map(|j| j.p0).collect();
    let departures: Vec<f64> = a.zero_sideslip.departure.iter().map(|d| d.p0).collect();
    let same = |what: &str, x: f64| AnalysisError::Indistinct {
        what: what.to_string(),
        p0: x,
        ulp: f64::from_bits(x.to_bits() + 1) - x,
    };
    for (what, v) in [
        ("two divergence roll rates", &a.divergence_roll_rates),
        ("two poles of det K", &a.det_k_poles),
        ("two jump roots", &jumps),
        ("two zero-sideslip departure roots", &departures),
    ] {
        if let Some(w) = v.windows(2).find(|w| w[0] == w[1]) {
            return Err(same(what, w[0]));
        }
    }
    if let Some(x) = jumps.iter().find(|x| a.det_k_poles.contains(x)) {
        return Err(same("a jump root and a pole of det K", *x));
    }
    finite("a divergence roll rate".into(), &a.divergence_roll_rates)?;
    finite("a pole of det K".into(), &a.det_k_poles)?;
    for (i, j) in a.jump.iter().enumerate() {
        let v = [
            j.p0,
            j.delta_a_rad,
            j.delta_a_deg,
            j.alpha,
            j.beta,
            j.q,
            j.r,
        ];
        finite(
            format!("the trim of jump point {} (P0 = {:e} rad/s)", i + 1, j.p0),
            &v,
        )?;
    }
    for (i, d) in a.zero_sideslip.departure.iter().enumerate() {
        let v = [d.p0, d.delta_a_rad, d.delta_a_deg, d.alpha, d.q, d.r];
        finite(
            format!(
                "the trim of zero-sideslip departure {} (P0 = {:e} rad/s)",
                i + 1,
                d.p0
            ),
            &v,
        )?;
    }
    Ok(())
}

/// The criterion polynomials of one aircraft and elevator setting, univariate in P0, each
/// exact up to a positive or negative constant factor (which moves no root and cancels in
/// every ratio used: the trim `trim_i / det_a`, det K `jump / d_det_a`).
///
/// Built from the parametric derivation by substituting the data into the small trim-level
/// results (det A, the trim numerators, det J5 and d in the trim symbols) with every
/// denominator cleared by one integer scale per group, and only then clearing the trim's
/// denominator (step 8) on dense univariate polynomials.
/// `tests/tests/derivation.rs` checks that they are proportional to the fully specialised
/// derivation's.
#[derive(Clone, Debug)]
pub struct CriterionPolys {
    /// det A (Eq. 4), up to a constant.
    pub det_a: Poly,
    /// Numerators of [alpha0, beta0, Q0, R0] over `det_a`.
    pub trim: [Poly; 4],
    /// The aileron of a trim, in trim symbols (from the parametric derivation, data substituted).
    pub delta_a: Ratio,
    /// `det J5 det(A)^2` in P0, up to a constant.
    pub jump: Poly,
    /// `d det(A)^2` in P0, up to the same constant as `jump` times a constant.
    pub d_det_a: Poly,
    /// det A1 of the zero-sideslip trim, up to a constant.
    pub zs_det: Poly,
    /// Numerators of [alpha0, Q0, R0] of the zero-sideslip trim over `zs_det`.
    pub zs_trim: [Poly; 3],
    /// The aileron of a zero-sideslip trim, in trim symbols.
    pub zs_delta_a: Ratio,
    /// `det J5 det(A1)^2` at the zero-sideslip trim, up to a constant.
    pub zs_jump: Poly,
    /// `d det(A1)^2` at the zero-sideslip trim, up to a constant.
    pub zs_d_det: Poly,
}

impl CriterionPolys {
    /// Specialises the parametric derivation `par` to an aircraft at `delta_e_rad`, delta_r = 0.
    pub fn new(par: &Derivation, aircraft: &Aircraft, delta_e_rad: f64) -> CriterionPolys {
        let s = symbols();
        let values = specialisation(aircraft, delta_e_rad);
        let ratio = |r: &Ratio| Ratio {
            num: r.num.subs_values(&values),
            den: r.den.subs_values(&values),
        };
        // One scale for det A and the numerators keeps every trim ratio exact.
        let cleared = |ps: &[&Poly]| {
            Poly::subs_values_cleared(ps, &values)
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
        let t4 = [s.alpha0, s.beta0, s.q0, s.r0];
        let det_j5 = cleared(&[&par.det_j5])[0].clone();
        let d = cleared(&[&par.d])[0].clone();
        let jump = clear_denominators(&det_j5, &t4, &trim, &det_a);
        let d_det_a = clear_denominators(&d, &t4, &trim, &det_a);

        let z = cleared(&[
            &par.zs_det,
            &par.zs_trim[0],
            &par.zs_trim[1],
            &par.zs_trim[2],
        ]);
        let (zs_det, zs_trim) = (z[0].clone(), [z[1].clone(), z[2].clone(), z[3].clone()]);
        let t3 = [s.alpha0, s.q0, s.r0];
        let beta0_zero = [(s.beta0, Q::ZERO)];
        let zs_jump = clear_denominators(&det_j5.subs_values(&beta0_zero), &t3, &zs_trim, &zs_det);
        let zs_d_det = clear_denominators(&d.subs_values(&beta0_zero), &t3, &zs_trim, &zs_det);
        CriterionPolys {
            det_a,
            trim,
            delta_a: ratio(&par.delta_a),
            jump,
            d_det_a,
            zs_det,
            zs_trim,
            zs_delta_a: ratio(&par.zs_delta_a),
            zs_jump,
            zs_d_det,
        }
    }
}

/// Step 8 for a specialised derivation: `f(t = num / den) den^k` as a polynomial in P0, where
/// `f` is a polynomial in the trim symbols `t` and P0 and k = [`TRIM_DEGREE`]. Same result as
/// [`homogenize`], computed on dense univariate polynomials: f is grouped by its monomial in
/// `t` and each product of numerators is formed once.
fn clear_denominators(f: &Poly, t: &[Sym], num: &[Poly], den: &Poly) -> Poly {
    let s = symbols();
    let k = TRIM_DEGREE as usize;
    assert!(
        f.degree_in(t) as usize <= k,
        "degree in the trim states above {k}"
    );
    let num: Vec<UPoly> = num.iter().map(|n| univariate(n, s.p0)).collect();
    let den = univariate(den, s.p0);
    let mut den_pows = vec![UPoly::new(vec![BigRational::from_integer(1.into())])];
    for i in 0..k {
        let next = den_pows[i].mul(&den);
        den_pows.push(next);
    }
    let mut groups: Vec<(Vec<u32>, Poly)> = Vec::new();
    for (m, c) in f.terms() {
        let e: Vec<u32> = t.iter().map(|x| m.exp(*x)).collect();
        let mut rest = *m;
        for x in t {
            rest.set(*x, 0);
        }
        let term = Poly::term(rest, c.clone());
        match groups.iter_mut().find(|(g, _)| *g == e) {
            Some((_, p)) => *p = &*p + &term,
            None => groups.push((e, term)),
        }
    }
    let mut acc = UPoly::new(vec![]);
    for (e, c) in groups {
        let mut prod = den_pows[k - e.iter().sum::<u32>() as usize].clone();
        for (i, ei) in e.iter().enumerate() {
            for _ in 0..*ei {
                prod = prod.mul(&num[i]);
            }
        }
        acc = acc.add(&univariate(&c, s.p0).mul(&prod));
    }
    let p0 = Poly::var(s.p0);
    acc.coeffs().iter().rev().fold(Poly::zero(), |a, c| {
        &(&a * &p0) + &Poly::constant(Q::from_big(c.clone()))
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
    if n.is_zero() || d.is_zero() {
        return (n, d);
    }
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
    if p.is_zero() || q.is_zero() {
        return p;
    }
    loop {
        let g = p.gcd(q);
        if g.degree().unwrap_or(0) == 0 {
            return p;
        }
        p = p.div_rem(&g).0;
    }
}

/// Trim states `num_i(P0) / den(P0)` at `p0`, evaluated in f64 (Horner on the correctly
/// rounded coefficients). Jump points are never at roots of det A (those are stripped), so
/// the quotient is well conditioned; `tests/tests/paper.rs` checks the PSS residuals.
fn trim_at(nums: &[UPoly], den: &UPoly, p0: f64) -> Vec<f64> {
    let dv = den.eval_f64(p0);
    nums.iter().map(|n| n.eval_f64(p0) / dv).collect()
}

fn eval_trim(r: &Ratio, values: &[(Sym, f64)]) -> f64 {
    let look = |s: Sym| {
        values
            .iter()
            .find(|(t, _)| *t == s)
            .map_or(f64::NAN, |(_, v)| *v)
    };
    r.num.eval_f64(&look) / r.den.eval_f64(&look)
}
