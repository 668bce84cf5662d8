//! What `model analyze` computes: the first jump on the primary branch (the critical point),
//! divergence roll rates (Eq. 5, Table 1), jump roll rates (roots of det K, Figs 7-8), the poles
//! of det K, and the zero-sideslip departure points (Fig. 11), each with its trim, control
//! deflections and whether it lies within the aircraft's limits and validity range.
//!
//! With aileron yaw (`n_delta_a != 0`) a roll rate has up to two trims (the trim condition is
//! quadratic in delta_a); jump points are then the roots of the resultant that eliminates delta_a
//! between the trim condition and det J5, each reported with the aileron of its trim.
//!
//! The derivation is specialised to the aircraft's exact data and the elevator setting, so the
//! criterion polynomials are univariate in P0 with exact rational coefficients. det K is the
//! rational function `jump / (d det(A)^2)` (both carry det(A)^2 from clearing the trim's
//! denominators); common factors are cancelled exactly by
//! univariate gcds before any root is sought, so a pole is never reported as a root, however
//! close a true root lies.
//!
//! ```
//! use model::aircraft::Aircraft;
//! use model::analysis::analyze_with;
//!
//! // Aircraft A of the paper at delta_e = 2 deg, the jump analysis alone (no Hopf points).
//! let a = analyze_with(&Aircraft::a(), 2f64.to_radians(), false).unwrap();
//! // Table 1: A has no pitch-yaw divergence; Fig. 7: det K has two positive roots.
//! assert!(a.divergence_roll_rates.is_empty());
//! assert_eq!(a.jump.len(), 2);
//! // The critical jump is the first fold met from P0 = 0: the smaller root, reached with
//! // negative aileron (l_delta_a < 0 rolls to positive p).
//! let critical = a.critical.as_ref().unwrap();
//! assert_eq!(critical.p0, a.jump[0].p0);
//! assert!(critical.delta_a_rad < 0.0 && critical.within_validity);
//! ```

use crate::aircraft::Aircraft;
use crate::algebra::{Poly, Sym};
use crate::derivation::{eliminate_aileron, zero_sideslip_step8, Derivation, Ratio};
use crate::equations::symbols;
use crate::roots::{positive_roots, UPoly};
use serde::Serialize;

mod departure;
#[cfg(feature = "cli")]
pub mod diagram;
mod exact_jump;
pub mod fast;
pub(crate) mod primary;
#[cfg(feature = "cli")]
pub mod trim_curves;
pub mod unstable_trim;
pub use crate::specialise::{
    cancel, exact_f64, in_aileron, in_aileron_all, parametric, parametric_characteristic,
    quadratic_roots, specialisation, univariate, InAileron,
};
use crate::specialise::{on_trim, OnTrim};
pub use departure::{omega_at, AtTrim, FirstDeparture, HopfPoint, HopfPolys, Landing, LocalPolys};
pub(crate) use exact_jump::{exact_jump_part, ExactJumpPart};
pub use primary::Outcome;
use primary::Walk;

/// A trim on the unconstrained roll (delta_r = 0) at which something happens: a jump point (a
/// positive root of det K, i.e. of det J5 on the equilibrium curve) or a pole of det K (d = 0).
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
    /// Whether the aileron (and elevator) deflections are within the aircraft's `[limits]`;
    /// `None` when the file gives no limit for them.
    pub within_limits: Option<bool>,
    /// Whether |alpha| and |beta| are within the `[validity]` range of the linear aerodynamics.
    pub within_validity: bool,
    /// For a jump point: the stable equilibria at the same aileron the jump can land on (empty:
    /// divergence); absent for poles and Hopf points.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lands_at: Option<Vec<Landing>>,
}

impl JumpPoint {
    /// Its numbers (roll rate, aileron in rad and deg, trim state): what must be finite before
    /// it is reported.
    fn numbers(&self) -> [f64; 7] {
        [
            self.p0,
            self.delta_a_rad,
            self.delta_a_deg,
            self.alpha,
            self.beta,
            self.q,
            self.r,
        ]
    }
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
    /// Rudder deflection the zero-sideslip schedule needs here, rad.
    pub delta_r_rad: f64,
    /// The same in degrees.
    pub delta_r_deg: f64,
    /// Whether aileron, rudder (and elevator) are within `[limits]`; `None` without limits.
    pub within_limits: Option<bool>,
    /// Whether |alpha| is within the `[validity]` range (beta = 0 here).
    pub within_validity: bool,
}

/// The zero-sideslip part of the analysis (section V).
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct ZeroSideslip {
    /// Positive roots of det K at the zero-sideslip trims, ascending.
    pub departure: Vec<DeparturePoint>,
    /// Hopf roll rates of the zero-sideslip trims (omega^2 > 0), rad/s, ascending.
    pub hopf_roll_rates: Vec<f64>,
    /// Why the section is withheld (its numbers are not finite in f64, or two of its roots
    /// cannot be told apart there; both lists are then empty), `None` when it is answered. A
    /// secondary input such as a tiny elevator deflection can do that to this section alone,
    /// and the rest of the analysis stands.
    pub withheld: Option<String>,
}

/// Everything `model analyze` reports (angles in rad, rates in rad/s, lists ascending in P0).
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct Analysis {
    /// Aircraft name.
    pub aircraft: String,
    /// Elevator deflection, rad: the increment from `trim` when there is one.
    pub delta_e_rad: f64,
    /// The trim the aircraft's derivatives were taken at (an import), which the states and
    /// the elevator of every row are increments from; absent from JSON for the paper's
    /// aircraft, whose angles are measured from zero lift.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub trim: Option<crate::aircraft::TrimState>,
    /// The first jump on the primary branch (from P0 = 0, delta_a = 0): the answer a user comes
    /// for, or `None` when the branch diverges or runs off to |delta_a| = 90 deg without a fold
    /// (see `critical_note`). Its aileron is negative for `l_delta_a < 0`; by the symmetry of
    /// the model the same magnitude of the opposite sign gives the mirror jump at -P0.
    pub critical: Option<JumpPoint>,
    /// Why there is no critical jump, or `None` when there is one.
    pub critical_note: Option<String>,
    /// The aircraft's aileron limit (`[limits]`), deg; `None` when the file gives none.
    pub aileron_limit_deg: Option<f64>,
    /// The margin of the critical jump to the aileron limit, deg: the limit minus the critical
    /// |delta_a|. Zero or positive: a full-stick roll reaches the jump, with this much travel
    /// to spare; negative: the jump lies this far beyond the stick's travel. The envelope's
    /// `margin_deg` is the same quantity. `None` without a limit or a critical jump.
    pub margin_deg: Option<f64>,
    /// The range of |alpha| and |beta| the aircraft's linear aerodynamics are trusted in
    /// (`[validity]`, 30 deg each by default): each row's `within_validity` is checked against it.
    pub validity: crate::aircraft::Validity,
    /// The aircraft's [`warnings`](crate::aircraft::Aircraft::warnings): what its file gives
    /// that no rigid body has, analysed as given (absent from JSON when empty).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub warnings: Vec<String>,
    /// Eq. 5: positive roots of det A (pitch-yaw divergence), Table 1.
    pub divergence_roll_rates: Vec<f64>,
    /// Positive roots of det K (saddle-node jump points), Figs 7-8.
    pub jump: Vec<JumpPoint>,
    /// Trims where the static-residual denominator d vanishes (poles of det K), Fig. 8.
    pub det_k_poles: Vec<JumpPoint>,
    /// Section V: zero-sideslip roll.
    pub zero_sideslip: ZeroSideslip,
    /// Hopf points (a complex pair of J5 on the imaginary axis), ascending in P0.
    pub hopf: Vec<HopfPoint>,
    /// The first loss of stability along the primary branch (an unstable trim at its start, a
    /// jump or a Hopf point), `None` when the branch never loses stability within the aileron
    /// range (or diverges first).
    pub first_departure: Option<FirstDeparture>,
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

/// Runs the analysis for one aircraft at elevator deflection `delta_e_rad`.
pub fn analyze(aircraft: &Aircraft, delta_e_rad: f64) -> Result<Analysis, AnalysisError> {
    analyze_with(aircraft, delta_e_rad, true)
}

/// [`analyze`], with the Hopf points, landings and first departure (beyond the paper) only when
/// `departures` is true; `false` gives the jump analysis alone (empty `hopf`, no `lands_at`,
/// no `first_departure`), the baseline of the benchmark.
pub fn analyze_with(
    aircraft: &Aircraft,
    delta_e_rad: f64,
    departures: bool,
) -> Result<Analysis, AnalysisError> {
    if !delta_e_rad.is_finite() || delta_e_rad.abs() > std::f64::consts::FRAC_PI_2 {
        return Err(AnalysisError::DeltaE(delta_e_rad));
    }
    let ExactJumpPart {
        d,
        found,
        walk,
        mut analysis,
        critical,
    } = exact_jump_part(aircraft, delta_e_rad)?;
    if departures {
        let hp = HopfPolys::new(&d, aircraft, delta_e_rad);
        let roots = |p: &UPoly| positive_roots(p).iter().map(|r| r.value).collect();
        let landing_roots = analysis
            .jump
            .iter()
            .map(|j| departure::landing_roots(&d, j))
            .collect();
        let input = Departures {
            at: hp.at_trim(),
            hopf_roots: roots(&hp.hopf),
            hopf_at: in_aileron(&hp.hopf_at),
            zs_hopf_roots: roots(&hp.zs_hopf),
            landing_roots,
        };
        let marks = (aircraft, delta_e_rad);
        found.add_departures(&mut analysis, critical, &input, marks, &walk);
    }
    withhold_zero_sideslip(&mut analysis);
    check(&analysis)?;
    Ok(analysis)
}

/// What the departure part of the analysis (Hopf points, landings, first departure) needs beyond
/// the jump part, from either route: the f64 evaluation at trims, the positive roots of the Hopf
/// polynomials and the real roots of the trim condition at each fold's aileron.
pub(crate) struct Departures<'a> {
    /// J5, `c1..c5` and the model's derivatives at trims.
    pub at: AtTrim<'a>,
    /// Positive roots of the Hopf polynomial, ascending.
    pub hopf_roots: Vec<f64>,
    /// The Hopf polynomial in P0 and delta_a (for the aileron of a root).
    pub hopf_at: InAileron,
    /// Positive roots of the zero-sideslip Hopf polynomial, ascending.
    pub zs_hopf_roots: Vec<f64>,
    /// For each jump point (in the order of `Analysis::jump`), the real roots of the trim
    /// condition at its aileron (det A's removed), ascending.
    pub landing_roots: Vec<Vec<f64>>,
}

/// The aileron and rudder of a zero-sideslip trim given as symbol values (the trim symbols).
pub(crate) type ZsControls<'a> = dyn Fn(&[(Sym, f64)]) -> (f64, f64) + 'a;

/// What a route (exact or certified floating point) has found for one aircraft: the positive
/// roots of the criterion polynomials, and the polynomials in f64 that give the trim, the
/// aileron and the primary branch at them.
pub(crate) struct Found {
    /// Positive roots of det A (Eq. 5).
    pub divergence: Vec<f64>,
    /// Positive roots of the jump polynomial, common roots with the poles and det A removed.
    pub jump_roots: Vec<f64>,
    /// Positive roots of the pole polynomial, common roots with det A removed.
    pub pole_roots: Vec<f64>,
    /// Positive roots of det K at the zero-sideslip trims (poles and det A1 removed).
    pub zs_roots: Vec<f64>,
    /// The trim condition.
    pub g: InAileron,
    /// det A and the numerators of [alpha0, beta0, Q0, R0], under one scale.
    pub trims: Vec<InAileron>,
    /// `det J5 det(A)^2` on the trim.
    pub jump_at: InAileron,
    /// `d det(A)^2` on the trim.
    pub d_at: InAileron,
    /// det A1 and the numerators of [alpha0, Q0, R0] of the zero-sideslip trim.
    pub zs_trims: Vec<InAileron>,
    /// Whether the roll and yaw equations can hold zero sideslip with aileron and rudder.
    pub lateral_authority: bool,
}

/// The aileron limit of `aircraft` minus the |delta_a| of `point`, deg (see
/// [`Analysis::margin_deg`]); `None` without a limit.
pub fn margin_deg(aircraft: &Aircraft, point: &JumpPoint) -> Option<f64> {
    aircraft
        .limits
        .aileron_deg
        .map(|limit| limit - point.delta_a_deg.abs())
}

impl Found {
    /// The jump part of the analysis (no Hopf points, landings or first departure) and the
    /// index of the critical jump in its `jump` list; `walk` is the primary branch's
    /// ([`Found::walk`]).
    pub(crate) fn assemble(
        &self,
        aircraft: &Aircraft,
        delta_e_rad: f64,
        zs_controls: &ZsControls<'_>,
        walk: &Walk,
    ) -> (Analysis, Option<usize>) {
        let s = symbols();
        let point = |p0: f64, f: &InAileron| -> JumpPoint {
            let da = aileron_of_root(&self.g, f, p0);
            departure::trim_point(p0, da, &self.trims, (aircraft, delta_e_rad))
        };
        let det_k_poles = self
            .pole_roots
            .iter()
            .map(|p0| point(*p0, &self.d_at))
            // As for jump points below: a root without a real trim is no pole on the curve.
            .filter(|j| j.delta_a_rad.is_finite())
            .collect();
        let jump: Vec<JumpPoint> = self
            .jump_roots
            .iter()
            .map(|p0| {
                let da = branch_aileron(&self.g, *p0, aileron_of_root(&self.g, &self.jump_at, *p0));
                departure::trim_point(*p0, da, &self.trims, (aircraft, delta_e_rad))
            })
            // A root where the common aileron of the trim condition and det J5 is complex (a
            // conjugate pair shared by both) has no real trim.
            .filter(|j| j.delta_a_rad.is_finite())
            .collect();
        let roots: Vec<(f64, f64)> = jump.iter().map(|j| (j.p0, j.delta_a_rad)).collect();
        let bound = aircraft.aileron_range();
        let (critical, critical_note) = match walk.first(&roots).0 {
                Outcome::Jump(i) => (Some(i), None),
                Outcome::Divergence(p) => (
                    None,
                    Some(format!(
                        "the primary branch diverges (det A = 0, Eq. 5) near P0 = {p:.4} rad/s before any jump"
                    )),
                ),
                Outcome::Unbounded => (
                    None,
                    Some(format!(
                        "the primary branch reaches |delta_a| = {:.1} deg without a jump",
                        bound.to_degrees()
                    )),
                ),
                Outcome::Lost(why) => {
                    (None, Some(format!("the primary branch is not defined: {why}")))
                }
            };
        let zs_roots: &[f64] = if self.lateral_authority {
            &self.zs_roots
        } else {
            &[]
        };
        let departure = zs_roots
            .iter()
            .map(|&p0| {
                let z = &self.zs_trims;
                let dv = z[0].eval(p0, 0.0);
                let [alpha, q, r] = std::array::from_fn(|i| z[i + 1].eval(p0, 0.0) / dv);
                let at = [
                    (s.alpha0, alpha),
                    (s.beta0, 0.0),
                    (s.p0, p0),
                    (s.q0, q),
                    (s.r0, r),
                ];
                let (da, dr) = zs_controls(&at);
                DeparturePoint {
                    p0,
                    delta_a_rad: da,
                    delta_a_deg: da.to_degrees(),
                    alpha,
                    q,
                    r,
                    delta_r_rad: dr,
                    delta_r_deg: dr.to_degrees(),
                    within_limits: aircraft.within_limits(da, delta_e_rad, Some(dr)),
                    within_validity: aircraft.valid(alpha, 0.0),
                }
            })
            .collect();
        let analysis = Analysis {
            aircraft: aircraft.name.clone(),
            delta_e_rad,
            trim: aircraft.trim_state(),
            critical: critical.map(|i: usize| jump[i].clone()),
            margin_deg: critical.and_then(|i| margin_deg(aircraft, &jump[i])),
            aileron_limit_deg: aircraft.limits.aileron_deg,
            validity: aircraft.validity,
            critical_note,
            warnings: aircraft.warnings.clone(),
            divergence_roll_rates: self.divergence.clone(),
            jump,
            det_k_poles,
            zero_sideslip: ZeroSideslip {
                departure,
                hopf_roll_rates: Vec::new(),
                withheld: None,
            },
            hopf: Vec::new(),
            first_departure: None,
        };
        (analysis, critical)
    }

    /// The f64 walk of the primary branch ([`primary::follow`]) on these polynomials, up to
    /// `aircraft`'s aileron range: made once, read by [`Found::assemble`] and
    /// [`Found::add_departures`].
    pub(crate) fn walk(&self, aircraft: &Aircraft) -> Walk {
        Walk::new(
            &self.g,
            &self.trims[0],
            &self.divergence,
            aircraft.aileron_range(),
        )
    }

    /// Adds the departure part to the jump part `analysis` (whose critical jump is `critical`):
    /// the landings of each jump, the Hopf points, the first departure and the zero-sideslip
    /// Hopf roll rates, the same on both routes; `walk` is the primary branch's
    /// ([`Found::walk`]).
    pub(crate) fn add_departures(
        &self,
        analysis: &mut Analysis,
        critical: Option<usize>,
        d: &Departures<'_>,
        marks: (&Aircraft, f64),
        walk: &Walk,
    ) {
        let (g, trims) = (&self.g, &self.trims);
        for (j, roots) in analysis.jump.iter_mut().zip(&d.landing_roots) {
            j.lands_at = Some(departure::landings(&d.at, trims, j, roots));
        }
        if let Some(i) = critical {
            analysis.critical = Some(analysis.jump[i].clone());
        }
        analysis.hopf = departure::hopf_points(&d.at, &d.hopf_roots, &d.hopf_at, g, trims, marks);
        analysis.first_departure = departure::first_departure(
            departure::start(&d.at, trims),
            &analysis.jump,
            &analysis.hopf,
            walk,
        );
        analysis.zero_sideslip.hopf_roll_rates =
            departure::zs_hopf_roll_rates(&d.at, &d.zs_hopf_roots, &self.zs_trims)
                .iter()
                .map(|(p, _)| *p)
                .collect();
    }
}

/// Empties the zero-sideslip section and says why when it fails its checks (every number
/// finite, no two distinct roots the same in f64), so that the rest of the analysis is
/// reported.
pub(crate) fn withhold_zero_sideslip(a: &mut Analysis) {
    if let Err(e) = check_zero_sideslip(&a.zero_sideslip) {
        a.zero_sideslip = ZeroSideslip {
            departure: Vec::new(),
            hopf_roll_rates: Vec::new(),
            withheld: Some(e.to_string()),
        };
    }
}

/// The checks of the zero-sideslip section (see [`check`]).
fn check_zero_sideslip(z: &ZeroSideslip) -> Result<(), AnalysisError> {
    let departures: Vec<f64> = z.departure.iter().map(|d| d.p0).collect();
    if let Some(x) = first_repeat(&departures) {
        return Err(indistinct("two zero-sideslip departure roots", x));
    }
    for (i, d) in z.departure.iter().enumerate() {
        let v = [
            d.p0,
            d.delta_a_rad,
            d.delta_a_deg,
            d.alpha,
            d.q,
            d.r,
            d.delta_r_rad,
            d.delta_r_deg,
        ];
        finite(
            &|| {
                format!(
                    "the trim of zero-sideslip departure {} (P0 = {:e} rad/s)",
                    i + 1,
                    d.p0
                )
            },
            &v,
        )?;
    }
    finite(
        &|| "a zero-sideslip Hopf roll rate".into(),
        &z.hopf_roll_rates,
    )
}

/// The checks every answer passes before it is reported: every number finite, and no two
/// distinct exact roots (of one list, or a jump root and a pole) that look the same in f64.
/// The zero-sideslip section has its own ([`withhold_zero_sideslip`]).
fn check(a: &Analysis) -> Result<(), AnalysisError> {
    let jumps: Vec<f64> = a.jump.iter().map(|j| j.p0).collect();
    let poles: Vec<f64> = a.det_k_poles.iter().map(|j| j.p0).collect();
    for (what, v) in [
        ("two divergence roll rates", &a.divergence_roll_rates),
        ("two poles of det K", &poles),
        ("two jump roots", &jumps),
    ] {
        if let Some(x) = first_repeat(v) {
            return Err(indistinct(what, x));
        }
    }
    if let Some(x) = jumps.iter().find(|x| poles.contains(x)) {
        return Err(indistinct("a jump root and a pole of det K", *x));
    }
    finite(
        &|| "a divergence roll rate".into(),
        &a.divergence_roll_rates,
    )?;
    for (i, j) in a.jump.iter().chain(&a.det_k_poles).enumerate() {
        let v = j.numbers();
        finite(
            &|| format!("the trim at P0 = {:e} rad/s (point {})", j.p0, i + 1),
            &v,
        )?;
    }
    departure::check_finite(a).map_err(AnalysisError::NotFinite)?;
    Ok(())
}

/// `Ok` when every number of `v` is finite, else [`AnalysisError::NotFinite`] naming `what`
/// (written only then: the checks run on every answer).
fn finite(what: &dyn Fn() -> String, v: &[f64]) -> Result<(), AnalysisError> {
    if v.iter().all(|x| x.is_finite()) {
        Ok(())
    } else {
        Err(AnalysisError::NotFinite(what()))
    }
}

/// The first value of the ascending list `v` that is also the next one.
fn first_repeat(v: &[f64]) -> Option<f64> {
    v.windows(2).find(|w| w[0] == w[1]).map(|w| w[0])
}

/// Two distinct exact roots `what` that round to the same f64 `x`.
fn indistinct(what: &str, x: f64) -> AnalysisError {
    AnalysisError::Indistinct {
        what: what.to_string(),
        p0: x,
        ulp: f64::from_bits(x.to_bits() + 1) - x,
    }
}

/// The aileron of the trim at `p0` next to `da` on the trim condition `g`: one Newton step in
/// delta_a from `da`. At a jump the branch's aileron is stationary in P0 (the fold), so a roll
/// rate known to within a bracket gives this aileron to the square of the bracket's width,
/// where the common root of `g` and det J5 ([`aileron_of_root`]) moves with P0 at first order
/// (70 rad per rad/s at the T-38's 7,400 m, Mach 0.91), and whose coefficients' rounding (2e-12
/// rad there) splits the fold's double root into two landings. Without aileron yaw `g` is linear
/// in delta_a and `da` is already its root; `da` itself too where the step is not small (the
/// trim condition's slope in delta_a vanishing).
pub(crate) fn branch_aileron(g: &InAileron, p0: f64, da: f64) -> f64 {
    let c = g.at(p0);
    if c.len() < 3 {
        return da;
    }
    let (value, slope) = c
        .iter()
        .rev()
        .fold((0.0, 0.0), |(v, s), ci| (v * da + ci, s * da + v));
    let step = value / slope;
    if step.is_finite() && step.abs() <= 1e-6 * (1.0 + da.abs()) {
        da - step
    } else {
        da
    }
}

/// The aileron of the trim at a root `p0` of the resultant of `g` and `f` in delta_a: their
/// common root.
///
/// With aileron yaw both are quadratic in delta_a, and `g2 f - f2 g` is linear in it and
/// vanishes at the common root: `delta_a = -(g2 f0 - f2 g0) / (g2 f1 - f2 g1)`. This is
/// rational in the coefficients, so it stays accurate where the two trims of `p0` nearly merge
/// (there the quadratic formula's square root of a vanishing discriminant amplifies rounding a
/// millionfold). Where the linear form degenerates (its coefficient cancels: `g` and `f`
/// nearly proportional) the root of the trim condition at which `f` is smallest (relative to
/// its size) is the candidate; where the two trims merge, the vertex of the quadratic. NaN
/// when the common root is not real: a conjugate pair shared by both, with no real trim.
pub(crate) fn aileron_of_root(g: &InAileron, f: &InAileron, p0: f64) -> f64 {
    let relative = |h: &InAileron, da: f64| {
        let c = h.at(p0);
        let scale: f64 = c
            .iter()
            .enumerate()
            .map(|(i, ci)| (ci * da.powi(i as i32)).abs())
            .sum();
        h.eval(p0, da).abs() / scale.max(f64::MIN_POSITIVE)
    };
    let (gc, fc) = (g.at(p0), f.at(p0));
    if let (3, 3) = (gc.len(), fc.len()) {
        let lead = gc[2] * fc[1] - fc[2] * gc[1];
        let size = (gc[2] * fc[1]).abs() + (fc[2] * gc[1]).abs();
        if lead.abs() > 1e-8 * size {
            let da = -(gc[2] * fc[0] - fc[2] * gc[0]) / lead;
            if relative(g, da) < 1e-6 {
                return da;
            }
        }
    }
    let mut candidates = g.aileron_roots(p0).to_vec();
    if candidates.is_empty() {
        if let (Some(c1), Some(c2)) = (gc.get(1), gc.get(2)) {
            candidates.push(-c1 / (2.0 * c2));
        }
    }
    candidates
        .into_iter()
        .filter(|da| relative(g, *da) < 1e-6)
        .min_by(|a, b| relative(f, *a).total_cmp(&relative(f, *b)))
        .unwrap_or(f64::NAN)
}

/// The criterion polynomials of one aircraft and elevator setting, each exact up to a positive
/// or negative constant factor (which moves no root and cancels in every ratio used: the trim
/// `trim_i / det_a`, det K `jump_at / d_at`).
///
/// Built from the parametric derivation by substituting the data into the small trim-level
/// results (det A, the trim numerators, det J5, d and the roll equation in the trim symbols) with
/// every denominator cleared by one integer scale per group, and only then clearing the trim's
/// denominator (step 8, [`crate::derivation::homogenize`]) and eliminating the aileron ([`eliminate_aileron`]).
/// `tests/tests/derivation.rs` checks that they are proportional to the fully specialised
/// derivation's.
#[derive(Clone, Debug)]
pub struct CriterionPolys {
    /// det A (Eq. 4), up to a constant.
    pub det_a: Poly,
    /// Numerators of [alpha0, beta0, Q0, R0] over `det_a`, in P0 and delta_a.
    pub trim: [Poly; 4],
    /// The aileron of a trim, in trim symbols (from the parametric derivation, data substituted).
    pub delta_a: Ratio,
    /// The trim condition `det(A)^2 p_dot` in P0 and delta_a.
    pub trim_condition: Poly,
    /// `det J5 det(A)^2` in P0 and delta_a, up to a constant.
    pub jump_at: Poly,
    /// `d det(A)^2` in P0 and delta_a, up to a constant.
    pub d_at: Poly,
    /// The jump polynomial in P0 (delta_a eliminated).
    pub jump: UPoly,
    /// The pole polynomial in P0 (delta_a eliminated).
    pub poles: UPoly,
    /// det A1 of the zero-sideslip trim, up to a constant.
    pub zs_det: Poly,
    /// Numerators of [alpha0, Q0, R0] of the zero-sideslip trim over `zs_det`.
    pub zs_trim: [Poly; 3],
    /// The aileron of a zero-sideslip trim, in trim symbols.
    pub zs_delta_a: Ratio,
    /// The rudder of a zero-sideslip trim, in trim symbols.
    pub zs_delta_r: Ratio,
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
        // One scale for the zero-sideslip determinant and its numerators keeps every trim
        // ratio exact (the unconstrained trim's are cleared the same way by `on_trim`).
        let cleared = |ps: &[&Poly]| {
            Poly::subs_values_cleared(ps, &values)
                .expect("the parametric derivation has integer coefficients")
        };
        let OnTrim {
            det_a,
            trim,
            det_j5,
            d,
            trim_condition,
            jump_at,
            d_at,
        } = on_trim(par, &values);
        let jump = univariate(&eliminate_aileron(&trim_condition, &jump_at), s.p0);
        let poles = univariate(&eliminate_aileron(&trim_condition, &d_at), s.p0);

        let z = cleared(&[
            &par.zs_det,
            &par.zs_trim[0],
            &par.zs_trim[1],
            &par.zs_trim[2],
        ]);
        let (zs_det, zs_trim) = (z[0].clone(), [z[1].clone(), z[2].clone(), z[3].clone()]);
        let zs_jump = zero_sideslip_step8(&det_j5, &zs_trim, &zs_det);
        let zs_d_det = zero_sideslip_step8(&d, &zs_trim, &zs_det);
        CriterionPolys {
            det_a,
            trim,
            delta_a: ratio(&par.delta_a),
            trim_condition,
            jump_at,
            d_at,
            jump,
            poles,
            zs_det,
            zs_trim,
            zs_delta_a: ratio(&par.zs_delta_a),
            zs_delta_r: ratio(&par.zs_delta_r),
            zs_jump,
            zs_d_det,
        }
    }
}

/// Removes from `p` every root it shares with `q` (all multiplicities).
fn strip(p: &UPoly, q: &UPoly) -> UPoly {
    let mut p = p.clone();
    if p.is_zero() || q.is_zero() {
        return p;
    }
    // Whole copies of q first (det A^4 in the Hopf polynomial): an exact division is cheap,
    // each gcd below a pseudo-remainder sequence on p's large coefficients. Both remove monic
    // factors of p, so the result is the same exact polynomial.
    if q.degree().unwrap_or(0) > 0 {
        let monic = q.monic();
        while let Some(quotient) = p.div_exact(&monic) {
            p = quotient;
        }
    }
    loop {
        let g = p.gcd(q);
        if g.degree().unwrap_or(0) == 0 {
            return p;
        }
        p = p.div_exact(&g).expect("the gcd divides p");
    }
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
