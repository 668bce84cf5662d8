//! The closed-form trims traced as curves, alongside continuation: the equilibrium curves of
//! Figs 1-4 and 9 and the det K curves of Figs 7, 8, 11, as the data `plot` draws
//! ([`super::diagram`]).
//!
//! * Unconstrained roll (Figs 1-4): the trim is a function of P0 (Eqs 3-4), so sweeping P0
//!   through the closed form traces every PSS equilibrium with delta_r = 0; the aileron that
//!   holds it comes from the roll equation. Branches break where det A = 0 (Eq. 5: the trims
//!   blow up). Stability from the eigenvalues of the compiled Jacobian (nalgebra); folds are the
//!   exact roots of det K from [`crate::analysis`], Hopf points are located by bisection on the
//!   count of unstable complex eigenvalues. [`hopf_points`] gives the closed form's Hopf points
//!   (`crate::analysis`, beyond the paper) for any diagram of Figs 1-4.
//! * Zero sideslip (Fig. 9): the zero-sideslip branch is the closed form of Eq. 35; with the
//!   rudder on the schedule ([`RudderSchedule`]) the other equilibria solve
//!   `delta_a(P0, delta_r(delta_a)) = delta_a`, a curve in the (delta_a, P0) plane traced by a
//!   small pseudo-arclength tracer. The transcritical points are the roots of the zero-sideslip
//!   det K.
//! * det K (Figs 7, 8, 11): the exact rational function `det J5 / d` of P0, i.e. `jump /
//!   d_det_a` (both carry det(A)^2, see [`det_k_ratio`]) and its zero-sideslip counterpart, with
//!   common factors cancelled, evaluated in f64.
//!
//! ```
//! use model::analysis::trim_curves::det_k_ratio;
//! use model::roots::UPoly;
//!
//! // A common factor (P0 - 1) of numerator and denominator cancels exactly: P0 = 1 is neither
//! // a root nor a pole of det K = (P0 - 1)(P0 - 2) / ((P0 - 1)(P0 + 3)).
//! let jump = UPoly::from_i64s(&[2, -3, 1]);
//! let d_den = UPoly::from_i64s(&[-3, 2, 1]);
//! let (num, den) = det_k_ratio(&jump, &d_den);
//! assert_eq!((num.degree(), den.degree()), (Some(1), Some(1)));
//! assert_eq!(num.eval_f64(1.0) / den.eval_f64(1.0), -0.25);
//! ```

use super::diagram::{
    BifurcationData, DetKData, DiagramError, SpecialKind, SpecialPoint, ZeroSideslipData,
};
use crate::aircraft::Aircraft;
use crate::analysis::{analyze, Analysis};
use crate::continuation::{Branch, Point as BranchPoint};
use crate::derivation::Derivation;
use crate::equations::symbols;
use crate::pss_model::PssModel;
use crate::roots::{positive_roots, UPoly};
use crate::simulation::{bisect, Equilibrium, RudderSchedule, Trims};
use crate::specialise::{cancel, in_aileron, specialisation, univariate, InAileron};
use nalgebra::Matrix5;

/// Samples of the P0 sweep of a diagram.
const SAMPLES: usize = 3001;

/// Unstable eigenvalue counts: (real, complex), and whether all eigenvalues are stable; or
/// undecided, when J5's eigenvalues cannot be computed (drawn as not stable, never a Hopf
/// point's end).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Spectrum {
    real_unstable: usize,
    complex_unstable: usize,
    decided: bool,
}

impl Spectrum {
    const UNDECIDED: Spectrum = Spectrum {
        real_unstable: 0,
        complex_unstable: 0,
        decided: false,
    };

    fn of(model: &PssModel, e: &Equilibrium) -> Spectrum {
        let j = model.jacobian(&e.x, &e.controls);
        let m = Matrix5::from_fn(|i, k| j[i][k]);
        let mut s = Spectrum {
            real_unstable: 0,
            complex_unstable: 0,
            decided: true,
        };
        let Some(eigenvalues) = crate::spectrum::eigenvalues(&m) else {
            return Spectrum::UNDECIDED;
        };
        for ev in eigenvalues.iter() {
            if ev.re >= 0.0 {
                if ev.im.abs() > 1e-9 * (1.0 + ev.re.abs()) {
                    s.complex_unstable += 1;
                } else {
                    s.real_unstable += 1;
                }
            }
        }
        s
    }

    fn stable(self) -> bool {
        self.decided && self.real_unstable + self.complex_unstable == 0
    }
}

fn point(e: &Equilibrium, stable: bool) -> BranchPoint {
    BranchPoint {
        param: e.controls.delta_a,
        alpha: e.x[0],
        beta: e.x[1],
        p: e.x[2],
        q: e.x[3],
        r: e.x[4],
        stable,
    }
}

/// Rounds `v` up to a multiple of `step`.
fn round_up(v: f64, step: f64) -> f64 {
    (v / step).ceil() * step
}

/// Figs 1-4: every PSS equilibrium with delta_r = 0 for |P0| up to 1.6 times the largest
/// special roll rate (fold, divergence, pole; at least 3 rad/s), with folds and Hopf points.
///
/// The PSS equations with delta_r = 0 are invariant under (beta, p, r, delta_a) -> -(beta, p,
/// r, delta_a), so the folds at negative P0 mirror those at positive P0.
pub fn unconstrained_diagram(
    aircraft: &Aircraft,
    delta_e: f64,
) -> Result<BifurcationData, DiagramError> {
    let analysis = analyze(aircraft, delta_e).map_err(DiagramError::Analysis)?;
    let trims = Trims::new(aircraft, delta_e).map_err(DiagramError::Simulation)?;
    let model = trims.model();
    let specials = analysis
        .jump
        .iter()
        .map(|j| j.p0)
        .chain(analysis.divergence_roll_rates.iter().copied())
        .chain(analysis.det_k_poles.iter().map(|j| j.p0))
        .fold(2.0, f64::max);
    let p_max = round_up(1.6 * specials, 0.5).min(50.0);
    let at = |p0: f64| trims.unconstrained(p0, 0.0);

    let mut branches: Vec<Branch> = Vec::new();
    let mut special: Vec<SpecialPoint> = Vec::new();
    let mut cur = Branch::default();
    let mut prev: Option<(f64, Spectrum)> = None;
    for k in 0..SAMPLES {
        let p0 = -p_max + 2.0 * p_max * k as f64 / (SAMPLES - 1) as f64;
        let e = at(p0);
        let crosses_pole = prev.is_some_and(|(pp, _)| trims.det_a(pp) * trims.det_a(p0) <= 0.0);
        match e {
            Some(e) if !crosses_pole => {
                let s = Spectrum::of(model, &e);
                if let Some((pp, ps)) = prev {
                    if let Some(h) = hopf_between(&trims, pp, ps, p0, s) {
                        special.push(h);
                    }
                }
                cur.points.push(point(&e, s.stable()));
                prev = Some((p0, s));
            }
            _ => {
                if cur.points.len() > 1 {
                    branches.push(std::mem::take(&mut cur));
                }
                cur = Branch::default();
                prev = None;
                if let Some(e) = e {
                    let s = Spectrum::of(model, &e);
                    cur.points.push(point(&e, s.stable()));
                    prev = Some((p0, s));
                }
            }
        }
    }
    if cur.points.len() > 1 {
        branches.push(cur);
    }
    let names = ["a", "b", "c", "d", "e", "f", "g", "h"];
    for (i, j) in analysis
        .jump
        .iter()
        .enumerate()
        .filter(|(_, j)| j.p0 <= p_max)
    {
        for sign in [1.0, -1.0] {
            if let Some(e) = at(sign * j.p0) {
                special.push(SpecialPoint {
                    kind: SpecialKind::Fold,
                    point: point(&e, false),
                    label: (sign > 0.0).then(|| {
                        names
                            .get(i)
                            .map_or_else(|| format!("{}", i + 1), |s| s.to_string())
                    }),
                });
            }
        }
    }
    let divergence_p = analysis
        .divergence_roll_rates
        .iter()
        .flat_map(|p| [*p, -p])
        .collect();
    Ok(BifurcationData {
        title: format!(
            "{}: PSS equilibria, \u{3b4}e = {} deg, \u{3b4}r = 0 (cf. Figs 1\u{2013}4)",
            aircraft.name,
            trim_num(delta_e.to_degrees())
        ),
        branches,
        special,
        divergence_p,
        delta_a_range_deg: None,
    })
}

/// The closed-form Hopf points of an analysis (beyond the paper: [`crate::analysis::HopfPoint`],
/// where `det(A)^10 Delta4` vanishes with `omega^2 > 0`) as special points of the diagram of
/// Figs 1-4, each with its mirror image: with delta_r = 0 the PSS equations are invariant under
/// (beta, p, r, delta_a) -> -(beta, p, r, delta_a), so a Hopf point at P0 has one at -P0.
pub fn hopf_points(analysis: &Analysis) -> Vec<SpecialPoint> {
    analysis
        .hopf
        .iter()
        .flat_map(|h| {
            let j = &h.point;
            [1.0, -1.0].map(|sign| SpecialPoint {
                kind: SpecialKind::HopfClosedForm,
                point: BranchPoint {
                    param: sign * j.delta_a_rad,
                    alpha: j.alpha,
                    beta: sign * j.beta,
                    p: sign * j.p0,
                    q: j.q,
                    r: sign * j.r,
                    stable: false,
                },
                label: None,
            })
        })
        .collect()
}

/// A number with at most 3 decimals, trailing zeros removed.
fn trim_num(v: f64) -> String {
    let s = format!("{v:.3}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" {
        "0".into()
    } else {
        s.replace('-', "\u{2212}")
    }
}

/// A Hopf point between two samples: the count of unstable complex eigenvalues changes by two
/// while the real ones stay; located by bisection on the counts.
fn hopf_between(trims: &Trims, a: f64, sa: Spectrum, b: f64, sb: Spectrum) -> Option<SpecialPoint> {
    let total = |s: Spectrum| s.real_unstable + s.complex_unstable;
    if !(sa.decided && sb.decided)
        || sa.real_unstable != sb.real_unstable
        || total(sa).abs_diff(total(sb)) != 2
    {
        return None;
    }
    let (mut lo, mut hi) = (a, b);
    for _ in 0..60 {
        let m = 0.5 * (lo + hi);
        let e = trims.unconstrained(m, 0.0)?;
        if Spectrum::of(trims.model(), &e) == sa {
            lo = m;
        } else {
            hi = m;
        }
    }
    let e = trims.unconstrained(0.5 * (lo + hi), 0.0)?;
    Some(SpecialPoint {
        kind: SpecialKind::Hopf,
        point: point(&e, false),
        label: None,
    })
}

/// det K as the reduced rational function `num / den` sampled on `[0, p_max]`.
/// The P0 samples of the det K figures.
fn sample_grid(p_max: f64) -> Vec<f64> {
    const N: usize = 2001;
    (0..N).map(|k| p_max * k as f64 / (N - 1) as f64).collect()
}

fn sample_ratio(num: &UPoly, den: &UPoly, p_max: f64) -> (Vec<f64>, Vec<f64>) {
    let (n, d) = (num.to_f64(), den.to_f64());
    let p0 = sample_grid(p_max);
    let v = p0.iter().map(|x| n.eval(*x) / d.eval(*x)).collect();
    (p0, v)
}

/// det K = det J5 / d along a trim curve as an exact rational function of P0, reduced: both
/// were cleared with the same power of the trim's denominator (step 8, `TRIM_DEGREE`), so
/// `det K = jump / d_den`.
pub fn det_k_ratio(jump: &UPoly, d_den: &UPoly) -> (UPoly, UPoly) {
    cancel(jump, d_den)
}

/// det K of the unconstrained roll (delta_r = 0) at `p0` on the trim of smallest |delta_a| (the
/// branch that continues the trim without aileron yaw), in f64; NaN where there is no trim.
fn det_k_on_trim(g: &InAileron, jump_at: &InAileron, d_at: &InAileron, p0: f64) -> f64 {
    g.aileron_roots(p0)
        .into_iter()
        .min_by(|a, b| a.abs().total_cmp(&b.abs()))
        .map_or(f64::NAN, |da| jump_at.eval(p0, da) / d_at.eval(p0, da))
}

/// The reduced det K of the zero-sideslip trims.
fn zs_det_k_ratio(d: &Derivation) -> (UPoly, UPoly) {
    let s = symbols();
    let u = |p| univariate(p, s.p0);
    det_k_ratio(&u(d.zs_jump()), &u(d.zs_d_det()))
}

/// Figs 7, 8: det K versus P0 for delta_r = 0, with its roots (the jump points) and poles.
pub fn det_k_curve(aircraft: &Aircraft, delta_e: f64) -> Result<DetKData, DiagramError> {
    let analysis = analyze(aircraft, delta_e).map_err(DiagramError::Analysis)?;
    let d = Derivation::derive(&specialisation(aircraft, delta_e));
    let roots: Vec<f64> = analysis.jump.iter().map(|j| j.p0).collect();
    let poles: Vec<f64> = analysis.det_k_poles.iter().map(|j| j.p0).collect();
    let top = roots
        .iter()
        .chain(poles.iter())
        .chain(analysis.divergence_roll_rates.iter())
        .fold(2.0f64, |m, v| m.max(*v));
    let p_max = round_up(1.2 * top, 0.5);
    let s = symbols();
    let (p0, det_k) = if d.jump_at().contains(s.delta_a) {
        // With aileron yaw det K is two-valued in P0; the curve follows the trim of smallest
        // |delta_a|.
        let (g, j, dd) = (
            in_aileron(d.trim_condition()),
            in_aileron(d.jump_at()),
            in_aileron(d.d_at()),
        );
        let p0 = sample_grid(p_max);
        let v = p0.iter().map(|x| det_k_on_trim(&g, &j, &dd, *x)).collect();
        (p0, v)
    } else {
        let u = |p| univariate(p, s.p0);
        let (num, den) = det_k_ratio(&u(d.jump_at()), &u(d.d_at()));
        sample_ratio(&num, &den, p_max)
    };
    Ok(DetKData {
        title: format!(
            "{}: det K versus trim roll rate, \u{3b4}e = {} deg, \u{3b4}r = 0 (cf. Figs 7, 8)",
            aircraft.name,
            trim_num(delta_e.to_degrees())
        ),
        p0,
        det_k,
        roots,
        poles,
        divergence: analysis.divergence_roll_rates.clone(),
    })
}

/// Fig. 11: det K versus P0 along the zero-sideslip trims, with its roots (the departure points)
/// and poles.
pub fn zero_sideslip_det_k_curve(
    aircraft: &Aircraft,
    delta_e: f64,
) -> Result<DetKData, DiagramError> {
    let analysis = analyze(aircraft, delta_e).map_err(DiagramError::Analysis)?;
    let d = Derivation::derive(&specialisation(aircraft, delta_e));
    let (num, den) = zs_det_k_ratio(&d);
    let roots: Vec<f64> = analysis
        .zero_sideslip
        .departure
        .iter()
        .map(|j| j.p0)
        .collect();
    let poles: Vec<f64> = positive_roots(&den).iter().map(|r| r.value).collect();
    let top = roots
        .iter()
        .chain(poles.iter())
        .fold(2.0f64, |m, v| m.max(*v));
    let p_max = round_up(1.15 * top, 0.5);
    let (p0, det_k) = sample_ratio(&num, &den, p_max);
    Ok(DetKData {
        title: format!(
            "{}: det K along the zero-sideslip trims, \u{3b4}e = {} deg (cf. Fig. 11)",
            aircraft.name,
            trim_num(delta_e.to_degrees())
        ),
        p0,
        det_k,
        roots,
        poles: poles.into_iter().filter(|p| *p <= p_max).collect(),
        divergence: Vec::new(),
    })
}

/// Fig. 9: the zero-sideslip rudder schedule and the PSS equilibria with the rudder on it, over
/// +-1.5 times the aileron of the first departure point (at least +-5 deg).
pub fn zero_sideslip_diagram(
    aircraft: &Aircraft,
    delta_e: f64,
) -> Result<ZeroSideslipData, DiagramError> {
    let analysis = analyze(aircraft, delta_e).map_err(DiagramError::Analysis)?;
    let trims = Trims::new(aircraft, delta_e).map_err(DiagramError::Simulation)?;
    let schedule = RudderSchedule::new(trims.clone()).map_err(DiagramError::Simulation)?;
    let (slo, shi) = schedule.range();
    let departure: Vec<_> = analysis
        .zero_sideslip
        .departure
        .iter()
        .filter(|d| (slo..=shi).contains(&d.delta_a_rad))
        .collect();
    let first = departure.first().map_or(0.0, |d| d.delta_a_deg.abs());
    let half = round_up((1.5 * first).max(5.0), 1.0)
        .min(shi.to_degrees())
        .min(-slo.to_degrees());
    let (alo, ahi) = (-half.to_radians(), half.to_radians());
    let model = trims.model();

    // The zero-sideslip branch itself.
    let mut zs = Branch::default();
    for (da, p0) in schedule
        .table()
        .iter()
        .filter(|(d, _)| (alo..=ahi).contains(d))
    {
        if let Some(e) = trims.zero_sideslip(*p0) {
            let _ = da;
            zs.points.push(point(&e, Spectrum::of(model, &e).stable()));
        }
    }
    let p_hi = zs.points.iter().map(|p| p.p.abs()).fold(2.0, f64::max) * 1.6;

    let curves = off_branch_curves(&trims, &schedule, (alo, ahi), p_hi);
    let mut branches = vec![zs];
    for c in curves {
        let mut b = Branch::default();
        for (da, p0) in c {
            let Ok(dr) = schedule.delta_r(da) else {
                continue;
            };
            if let Some(e) = trims.unconstrained(p0, dr) {
                b.points.push(point(&e, Spectrum::of(model, &e).stable()));
            }
        }
        // A traced copy of the zero-sideslip branch (beta = 0 throughout) is dropped.
        if b.points.len() > 1 && b.points.iter().any(|p| p.beta.abs() > 1e-6) {
            branches.push(b);
        }
    }
    let mut special = Vec::new();
    for d in departure {
        for sign in [1.0, -1.0] {
            if let Some(e) = trims.zero_sideslip(sign * d.p0) {
                special.push(SpecialPoint {
                    kind: SpecialKind::Transcritical,
                    point: point(&e, false),
                    label: None,
                });
            }
        }
    }
    let sched = schedule
        .table()
        .iter()
        .filter(|(d, _)| (alo..=ahi).contains(d))
        .filter_map(|(_, p0)| {
            trims
                .zero_sideslip(*p0)
                .map(|e| (e.controls.delta_a, e.controls.delta_r))
        })
        .collect();
    Ok(ZeroSideslipData {
        schedule: sched,
        diagram: BifurcationData {
            title: format!(
                "{}: zero-sideslip roll, rudder on the schedule, \u{3b4}e = {} deg (cf. Fig. 9)",
                aircraft.name,
                trim_num(delta_e.to_degrees())
            ),
            branches,
            special,
            divergence_p: Vec::new(),
            delta_a_range_deg: Some((-half, half)),
        },
    })
}

/// The equilibria off the zero-sideslip branch with the rudder on `schedule`, the zero set of
/// F(delta_a, P0) = delta_a(P0, delta_r(delta_a)) - delta_a over the aileron range `alo..ahi`
/// (rad) and |P0| up to `p_hi`: seeds by sign changes of F along lines of constant aileron
/// (away from det A = 0 and from the zero-sideslip trim), each traced by [`Tracer`] unless a
/// curve already traced passes near it. Each curve is a list of (delta_a, P0).
fn off_branch_curves(
    trims: &Trims,
    schedule: &RudderSchedule,
    (alo, ahi): (f64, f64),
    p_hi: f64,
) -> Vec<Vec<(f64, f64)>> {
    // F(delta_a, P0) = 0.
    let f = |da: f64, p0: f64| -> Option<f64> {
        let dr = schedule.delta_r(da).ok()?;
        trims.unconstrained(p0, dr).map(|e| e.controls.delta_a - da)
    };
    let tracer = Tracer {
        f: &f,
        scale: (ahi - alo, 2.0 * p_hi),
        lo: (alo, -p_hi),
        hi: (ahi, p_hi),
    };
    let mut curves: Vec<Vec<(f64, f64)>> = Vec::new();
    const LINES: usize = 24;
    const SCAN: usize = 240;
    for i in 0..LINES {
        let da = alo + (ahi - alo) * (i as f64 + 0.5) / LINES as f64;
        let Ok(on_zs) = schedule.trim(da) else {
            continue;
        };
        let p_zs = on_zs.x[2];
        let Ok(dr) = schedule.delta_r(da) else {
            continue;
        };
        let g = |p0: f64| trims.unconstrained(p0, dr).map(|e| e.controls.delta_a - da);
        let mut prev: Option<(f64, f64)> = None;
        for k in 0..=SCAN {
            let p0 = -p_hi + 2.0 * p_hi * k as f64 / SCAN as f64;
            let cur = g(p0).map(|v| (p0, v));
            if let (Some((pa, va)), Some((pb, vb))) = (prev, cur) {
                let pole = trims.det_a(pa) * trims.det_a(pb) <= 0.0;
                let contains_zs = (pa - p_zs) * (pb - p_zs) <= 0.0;
                if va * vb < 0.0 && !pole && !contains_zs {
                    let seed = (da, bisect(&|p| g(p).unwrap_or(f64::NAN), pa, pb, va));
                    if !curves.iter().any(|c| tracer.near(c, seed)) {
                        let c = tracer.trace(seed);
                        if c.len() > 1 {
                            curves.push(c);
                        }
                    }
                }
            }
            prev = cur;
        }
    }
    curves
}

/// Traces the zero set of a scalar function of two variables (pseudo-arclength: tangent
/// predictor, minimal-norm Newton corrector) inside a box, in coordinates scaled by `scale`.
struct Tracer<'a> {
    f: &'a dyn Fn(f64, f64) -> Option<f64>,
    scale: (f64, f64),
    lo: (f64, f64),
    hi: (f64, f64),
}

impl Tracer<'_> {
    /// Step length in scaled coordinates (the box is about 1 x 1).
    const H: f64 = 0.004;
    const MAX_STEPS: usize = 4000;

    fn g(&self, u: (f64, f64)) -> Option<f64> {
        (self.f)(u.0 * self.scale.0, u.1 * self.scale.1)
    }

    fn grad(&self, u: (f64, f64)) -> Option<(f64, f64)> {
        let e = 1e-7;
        let gx = (self.g((u.0 + e, u.1))? - self.g((u.0 - e, u.1))?) / (2.0 * e);
        let gy = (self.g((u.0, u.1 + e))? - self.g((u.0, u.1 - e))?) / (2.0 * e);
        (gx.is_finite() && gy.is_finite() && (gx != 0.0 || gy != 0.0)).then_some((gx, gy))
    }

    fn correct(&self, mut u: (f64, f64)) -> Option<(f64, f64)> {
        for _ in 0..12 {
            let v = self.g(u)?;
            if v.abs() < 1e-13 {
                return Some(u);
            }
            let (gx, gy) = self.grad(u)?;
            let n2 = gx * gx + gy * gy;
            u = (u.0 - v * gx / n2, u.1 - v * gy / n2);
        }
        (self.g(u)?.abs() < 1e-10).then_some(u)
    }

    fn inside(&self, u: (f64, f64)) -> bool {
        let (x, y) = (u.0 * self.scale.0, u.1 * self.scale.1);
        (self.lo.0..=self.hi.0).contains(&x) && (self.lo.1..=self.hi.1).contains(&y)
    }

    fn scaled(&self, p: (f64, f64)) -> (f64, f64) {
        (p.0 / self.scale.0, p.1 / self.scale.1)
    }

    /// Whether `p` (unscaled) lies within a few steps of the traced curve `c`.
    fn near(&self, c: &[(f64, f64)], p: (f64, f64)) -> bool {
        let s = self.scaled(p);
        c.iter().any(|q| {
            let t = self.scaled(*q);
            (t.0 - s.0).hypot(t.1 - s.1) < 3.0 * Self::H
        })
    }

    /// The curve through `seed` (unscaled), both directions, in order along the curve.
    fn trace(&self, seed: (f64, f64)) -> Vec<(f64, f64)> {
        let Some(s) = self.correct(self.scaled(seed)) else {
            return Vec::new();
        };
        let Some((gx, gy)) = self.grad(s) else {
            return Vec::new();
        };
        let n = gx.hypot(gy);
        let t0 = (-gy / n, gx / n);
        let back = self.walk(s, (-t0.0, -t0.1));
        let fwd = self.walk(s, t0);
        let unscale = |u: (f64, f64)| (u.0 * self.scale.0, u.1 * self.scale.1);
        back.into_iter()
            .rev()
            .chain(std::iter::once(s))
            .chain(fwd)
            .map(unscale)
            .collect()
    }

    fn walk(&self, start: (f64, f64), dir: (f64, f64)) -> Vec<(f64, f64)> {
        let mut out = Vec::new();
        let (mut u, mut t) = (start, dir);
        let mut h = Self::H;
        for _ in 0..Self::MAX_STEPS {
            let pred = (u.0 + h * t.0, u.1 + h * t.1);
            let next = self.correct(pred).and_then(|v| {
                let (gx, gy) = self.grad(v)?;
                let n = gx.hypot(gy);
                let mut tn = (-gy / n, gx / n);
                if tn.0 * t.0 + tn.1 * t.1 < 0.0 {
                    tn = (-tn.0, -tn.1);
                }
                let moved = (v.0 - u.0).hypot(v.1 - u.1);
                (tn.0 * t.0 + tn.1 * t.1 > 0.95 && moved < 2.0 * h).then_some((v, tn))
            });
            match next {
                Some((v, tn)) => {
                    if !self.inside(v) {
                        break;
                    }
                    out.push(v);
                    if out.len() > 10 && (v.0 - start.0).hypot(v.1 - start.1) < h {
                        break; // closed curve
                    }
                    u = v;
                    t = tn;
                    h = (h * 1.2).min(Self::H);
                }
                None => {
                    h *= 0.5;
                    if h < 1e-6 {
                        break;
                    }
                }
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn det_k_curve_is_det_j5_over_d() {
        // The identity det J5 = d det K, evaluated directly at the f64 trims.
        let s = symbols();
        for ac in [Aircraft::a(), Aircraft::b()] {
            let de = 2f64.to_radians();
            let d = Derivation::derive(&specialisation(&ac, de));
            let t = Trims::new(&ac, de).unwrap();
            let u = |p| univariate(p, s.p0);
            let (n, m) = det_k_ratio(&u(d.jump_at()), &u(d.d_at()));
            let (zn, zm) = zs_det_k_ratio(&d);
            for p0 in [0.0, 0.7, 1.9, 2.5] {
                for (e, (n, m)) in [
                    (t.unconstrained(p0, 0.0).unwrap(), (&n, &m)),
                    (t.zero_sideslip(p0).unwrap(), (&zn, &zm)),
                ] {
                    let j = t.model().jacobian(&e.x, &e.controls);
                    let det = Matrix5::from_fn(|i, k| j[i][k]).determinant();
                    let look = |sym| {
                        let i = [s.alpha0, s.beta0, s.p0, s.q0, s.r0]
                            .iter()
                            .position(|t| *t == sym);
                        i.map_or(f64::NAN, |i| e.x[i])
                    };
                    let want = det / d.d.eval_f64(&look);
                    let got = n.eval_f64(p0) / m.eval_f64(p0);
                    assert!(
                        (got - want).abs() < 1e-9 * want.abs().max(1.0),
                        "{} {p0}: {got} vs {want}",
                        ac.name
                    );
                }
            }
        }
    }

    #[test]
    fn unconstrained_equilibria_are_symmetric_in_roll() {
        let t = Trims::new(&Aircraft::b(), 2f64.to_radians()).unwrap();
        for p0 in [0.7, 2.2, 3.4] {
            let (a, b) = (
                t.unconstrained(p0, 0.0).unwrap(),
                t.unconstrained(-p0, 0.0).unwrap(),
            );
            assert!((a.controls.delta_a + b.controls.delta_a).abs() < 1e-12);
            assert!((a.x[0] - b.x[0]).abs() < 1e-12 && (a.x[1] + b.x[1]).abs() < 1e-12);
            assert!((a.x[3] - b.x[3]).abs() < 1e-12 && (a.x[4] + b.x[4]).abs() < 1e-12);
        }
    }
}
