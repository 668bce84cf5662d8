//! Continuation and bifurcation analysis of the PSS equilibria: what the paper does
//! with AUTO2000 for Figs 1-4 (section II.B) and Fig. 9 (section V.B), so that every special
//! point can be set against the analytical criterion of section IV (`model::analysis`).
//!
//! * Equilibria of the PSS model of Appendix A.2, `f(x, u) = 0` with `x = [alpha, beta, p, q,
//!   r]`, are continued in one control ([`ContinuationParam`]: delta_a by default) by
//!   pseudo-arclength continuation with an adaptive step and a Newton corrector on the bordered
//!   system, using the model's symbolic Jacobian ([`crate::pss_model::PssModel`]); no finite
//!   differences anywhere.
//! * Stability of every point from the eigenvalues of J5. Folds (saddle-nodes: the jump points of
//!   section IV, Figs 1, 2, 7, 8), Hopf points (with their frequency; the filled squares of
//!   Fig. 2) and branch points are detected by test functions and located along the branch
//!   (folds and Hopf points to `locate_tol` in arclength; branch points, where the corrector is
//!   singular, from a cubic through nearby regular points, to about 1e-12 in practice); at each
//!   branch point the crossing branch is traced too.
//! * Every branch in the range is traced, not only the primary one: start points are the
//!   equilibria on a grid of roll rates, which the PSS equations give in closed form (section
//!   II.A; see `seeds` for the general case), so that the separate pieces of aircraft B's
//!   diagram (Fig. 2) are found without hand-picked starts. Traced branches claim the grid points
//!   they pass, so nothing is traced twice.
//! * A branch ends cleanly where the parameter leaves `[min, max]`, where a state reaches
//!   `max_state` in absolute value (near the divergence roll rates of Eq. 5 the trims blow up),
//!   or where it closes on itself; its last point then lies exactly on the bound.
//! * Zero sideslip (section V.B, the extended bifurcation analysis): step 1 continues
//!   `f = 0, beta = 0` with the rudder freed (Eq. 36) from the level trim, giving the rudder
//!   schedule delta_r(delta_a) up to its first turning point; step 2 continues the unconstrained
//!   model with the schedule substituted (Eq. 37). The schedule used in step 2 is the exact
//!   closed-form zero-sideslip trim (Eqs 32-35), parametrised by its roll rate; the
//!   zero-sideslip branch loses stability at a transcritical (branch) point, the departure of
//!   Fig. 9, where the crossing branch is traced by branch switching.
//!
//! ```
//! use model::aircraft::Aircraft;
//! use model::continuation::{continue_equilibria, Settings, SpecialKind};
//!
//! // Aircraft A for delta_a in [-0.1, 0.1] rad (the paper's range is +-0.8), roll rates up to
//! // 5 rad/s: the primary branch folds at its first jump on either side (Fig. 1).
//! let settings = Settings { min: -0.1, max: 0.1, max_state: 5.0, ..Settings::default() };
//! let d = continue_equilibria(&Aircraft::a(), &settings, &mut |_| {}).unwrap();
//! let folds: Vec<_> = d.special(SpecialKind::Fold).collect();
//! assert_eq!(folds.len(), 2);
//! // Mirror images: P0 -> -P0 with delta_a -> -delta_a; negative aileron rolls to positive p.
//! assert!((folds[0].p + folds[1].p).abs() < 1e-8 && folds.iter().all(|f| f.p * f.param < 0.0));
//! ```

mod engine;
mod seeds;
mod systems;

use crate::aircraft::Aircraft;
use crate::pss_model::{Controls, PssModel};
use engine::{End, Engine, Found, Half, Kind, Limits, Node, System, Verdict, V6};
use seeds::{Sections, SeedBook};
use serde::ser::{SerializeMap, SerializeSeq};
use serde::{Deserialize, Serialize, Serializer};
use systems::{Schedule, Unconstrained, ZsConstrained, ZsScheduled};

/// The control that is continued.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ContinuationParam {
    /// Aileron deflection delta_a, rad (the paper's choice, Figs 1-4 and 9).
    DeltaA,
    /// Elevator deflection delta_e, rad.
    DeltaE,
    /// Rudder deflection delta_r, rad.
    DeltaR,
}

impl ContinuationParam {
    /// The name used as the parameter's key in JSON and CSV: `delta_a`, `delta_e`, `delta_r`.
    pub fn name(self) -> &'static str {
        match self {
            ContinuationParam::DeltaA => "delta_a",
            ContinuationParam::DeltaE => "delta_e",
            ContinuationParam::DeltaR => "delta_r",
        }
    }

    fn index(self) -> usize {
        match self {
            ContinuationParam::DeltaA => 0,
            ContinuationParam::DeltaE => 1,
            ContinuationParam::DeltaR => 2,
        }
    }
}

impl std::str::FromStr for ContinuationParam {
    type Err = ContinuationError;

    /// Parses `delta_a`, `delta_e` or `delta_r` (also `da`, `de`, `dr`; any case, `-` for `_`).
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        match s.to_ascii_lowercase().replace('-', "_").as_str() {
            "delta_a" | "da" => Ok(ContinuationParam::DeltaA),
            "delta_e" | "de" => Ok(ContinuationParam::DeltaE),
            "delta_r" | "dr" => Ok(ContinuationParam::DeltaR),
            _ => Err(ContinuationError::Settings(format!(
                "unknown parameter `{s}`: expected delta_a, delta_e or delta_r"
            ))),
        }
    }
}

/// What to continue and how. Angles in rad, rates in rad/s. [`Settings::default`] is the paper's
/// setting for Figs 1-2: delta_a in [-0.8, 0.8] rad, delta_e = 2 deg, delta_r = 0.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Settings {
    /// The continued control. Default delta_a.
    pub param: ContinuationParam,
    /// Lower end of the parameter range, rad. Default -0.8.
    pub min: f64,
    /// Upper end of the parameter range, rad. Default 0.8.
    pub max: f64,
    /// Elevator deflection when it is not the parameter, rad. Default 2 deg (the paper's).
    pub delta_e: f64,
    /// Aileron deflection when it is not the parameter, rad. Default 0.
    pub delta_a: f64,
    /// Rudder deflection when it is not the parameter, rad. Default 0 (ignored with
    /// `zero_sideslip`, where the rudder follows the schedule).
    pub delta_r: f64,
    /// The zero-sideslip roll of section V.B (extended bifurcation analysis); needs delta_a as
    /// the parameter. Default false.
    pub zero_sideslip: bool,
    /// Branches end where any state reaches this bound in absolute value (rad, rad/s).
    /// Default 20. It also bounds the roll rates searched for start points.
    pub max_state: f64,
    /// Spacing of the roll-rate grid of start points, rad/s. A piece of branch whose roll rates
    /// span less than this may be missed. Default 0.02.
    pub seed_spacing: f64,
    /// First step, in arclength of (state, parameter). Default 0.01.
    pub ds_initial: f64,
    /// Smallest step before a branch is given up. Default 1e-7.
    pub ds_min: f64,
    /// Largest step. Default 0.1.
    pub ds_max: f64,
    /// Largest angle between the tangents of consecutive points, rad (guards against jumping
    /// between branches). Default 0.2.
    pub max_angle: f64,
    /// Newton stops when the correction is below `tol * (1 + |z|)`. Default 1e-11.
    pub tol: f64,
    /// Newton iterations per corrector. Default 8.
    pub max_newton: usize,
    /// Folds and Hopf points are located to this arclength (branch points: see the
    /// module docs). Default 1e-12.
    pub locate_tol: f64,
    /// Points per branch direction before it is given up. Default 20 000.
    pub max_points: usize,
    /// Branches in all before the search stops. Default 200.
    pub max_branches: usize,
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            param: ContinuationParam::DeltaA,
            min: -0.8,
            max: 0.8,
            delta_e: 2f64.to_radians(),
            delta_a: 0.0,
            delta_r: 0.0,
            zero_sideslip: false,
            max_state: 20.0,
            seed_spacing: 0.02,
            ds_initial: 0.01,
            ds_min: 1e-7,
            ds_max: 0.1,
            max_angle: 0.2,
            tol: 1e-11,
            max_newton: 8,
            locate_tol: 1e-12,
            max_points: 20_000,
            max_branches: 200,
        }
    }
}

/// One point of a branch: an equilibrium, the parameter that holds it and its stability (also
/// the point of a figure's branch, `plot::BranchPoint`).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Point {
    /// The parameter value, rad.
    pub param: f64,
    /// Angle of attack, rad.
    pub alpha: f64,
    /// Sideslip, rad.
    pub beta: f64,
    /// Roll rate, rad/s.
    pub p: f64,
    /// Pitch rate, rad/s.
    pub q: f64,
    /// Yaw rate, rad/s.
    pub r: f64,
    /// Every eigenvalue of J5 has a negative real part.
    pub stable: bool,
}

/// A connected piece of the equilibrium curve, its points in order along it (also a figure's
/// branch, `plot::Branch`).
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct Branch {
    /// The points, in order of arclength.
    pub points: Vec<Point>,
}

/// The kind of a special point.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum SpecialKind {
    /// Saddle-node (turning point in the parameter): a jump point of section IV.
    Fold,
    /// A complex pair of eigenvalues crosses the imaginary axis.
    Hopf,
    /// Two branches cross (transcritical or pitchfork), e.g. the zero-sideslip departure.
    Branch,
}

impl SpecialKind {
    /// `fold`, `hopf` or `branch`.
    pub fn name(self) -> &'static str {
        match self {
            SpecialKind::Fold => "fold",
            SpecialKind::Hopf => "hopf",
            SpecialKind::Branch => "branch",
        }
    }
}

/// A located special point.
#[derive(Clone, Debug, PartialEq)]
pub struct SpecialPoint {
    /// What it is.
    pub kind: SpecialKind,
    /// The parameter value, rad.
    pub param: f64,
    /// Angle of attack, rad.
    pub alpha: f64,
    /// Sideslip, rad.
    pub beta: f64,
    /// Roll rate P0, rad/s.
    pub p: f64,
    /// Pitch rate, rad/s.
    pub q: f64,
    /// Yaw rate, rad/s.
    pub r: f64,
    /// Hopf points: the imaginary part of the critical pair, rad/s.
    pub frequency: Option<f64>,
    /// Index into [`Diagram::branches`] of the branch it was found on.
    pub branch: usize,
    /// Whether the controls there are within the aircraft's `[limits]` (None: no limit given).
    pub within_limits: Option<bool>,
    /// Whether alpha and beta are within the aircraft's `[validity]` range.
    pub valid: bool,
}

/// A point of the zero-sideslip rudder schedule (EBA step 1).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct SchedulePoint {
    /// Aileron deflection, rad.
    pub delta_a: f64,
    /// Rudder deflection holding beta = 0, rad.
    pub delta_r: f64,
    /// Roll rate, rad/s.
    pub p: f64,
}

/// The bifurcation diagram. Serialises as
/// `{"aircraft", "parameter", "branches": [{"points": [{<parameter>, alpha, beta, p, q, r,
/// stable}]}], "special_points": [{kind, <parameter>, p, alpha, beta, q, r, [frequency]}]}`
/// plus `"rudder_schedule"` for a zero-sideslip diagram; `<parameter>` is the parameter's name.
#[derive(Clone, Debug, PartialEq)]
pub struct Diagram {
    /// Aircraft name.
    pub aircraft: String,
    /// The parameter's name: `delta_a`, `delta_e` or `delta_r`.
    pub parameter: String,
    /// Every branch found, in the order found (deterministic).
    pub branches: Vec<Branch>,
    /// Folds, then Hopf points, then branch points, each ascending in the parameter.
    pub special_points: Vec<SpecialPoint>,
    /// Zero-sideslip diagrams: the rudder schedule of EBA step 1, along the branch; else empty.
    pub rudder_schedule: Vec<SchedulePoint>,
}

/// Why a continuation cannot run.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum ContinuationError {
    /// A setting is out of its domain.
    #[error("invalid continuation settings: {0}")]
    Settings(String),
    /// The model does not have the structure the start-point search relies on.
    #[error("model: {0}")]
    Model(String),
    /// The zero-sideslip analysis cannot run for this aircraft or setting.
    #[error("zero-sideslip analysis: {0}")]
    ZeroSideslip(String),
}

fn check(settings: &Settings) -> Result<(), ContinuationError> {
    let bad = |m: &str| Err(ContinuationError::Settings(m.to_string()));
    let s = settings;
    if ![s.min, s.max, s.delta_a, s.delta_e, s.delta_r]
        .iter()
        .all(|v| v.is_finite())
    {
        return bad("min, max and the control values must be finite");
    }
    if s.min >= s.max {
        return bad("min must be below max");
    }
    if !(s.max_state > 0.0 && s.max_state.is_finite()) {
        return bad("max_state must be positive");
    }
    if !(s.seed_spacing > 0.0 && s.max_state / s.seed_spacing <= 1e6) {
        return bad("seed_spacing must be positive and at least max_state / 1e6");
    }
    let pos = [
        s.ds_initial,
        s.ds_min,
        s.ds_max,
        s.max_angle,
        s.tol,
        s.locate_tol,
    ];
    if !pos.iter().all(|v| *v > 0.0 && v.is_finite()) {
        return bad("step sizes, angle and tolerances must be positive");
    }
    if !(s.ds_min <= s.ds_initial && s.ds_initial <= s.ds_max) {
        return bad("need ds_min <= ds_initial <= ds_max");
    }
    if s.max_angle >= std::f64::consts::FRAC_PI_2 {
        return bad("max_angle must be below pi/2");
    }
    if s.max_newton == 0 || s.max_points == 0 || s.max_branches == 0 {
        return bad("max_newton, max_points and max_branches must be positive");
    }
    if s.zero_sideslip && s.param != ContinuationParam::DeltaA {
        return Err(ContinuationError::ZeroSideslip(
            "the zero-sideslip analysis continues in delta_a (section V.B); use param delta_a"
                .into(),
        ));
    }
    Ok(())
}

fn limits(s: &Settings, mu_lo: f64, mu_hi: f64) -> Limits {
    Limits {
        mu_lo,
        mu_hi,
        max_state: s.max_state,
        ds_init: s.ds_initial,
        ds_min: s.ds_min,
        ds_max: s.ds_max,
        tol: s.tol,
        max_iter: s.max_newton,
        max_angle: s.max_angle,
        locate_tol: s.locate_tol,
        max_points: s.max_points,
        stop_at_fold: false,
    }
}

/// Computes the bifurcation diagram of the PSS equilibria of `ac` (see the module docs).
///
/// `progress` is called with the fraction done, from 0 to 1, a few hundred times at most.
pub fn continue_equilibria(
    ac: &Aircraft,
    settings: &Settings,
    progress: &mut dyn FnMut(f64),
) -> Result<Diagram, ContinuationError> {
    check(settings)?;
    let model = PssModel::new(ac);
    let mut out = Collect::default();
    let rudder_schedule = if settings.zero_sideslip {
        zero_sideslip(&model, settings, &mut out, progress)?
    } else {
        unconstrained(&model, settings, &mut out, progress)?;
        Vec::new()
    };
    progress(1.0);
    let mut diagram = out.finish(
        ac.name.clone(),
        settings.param.name().to_string(),
        rudder_schedule,
    );
    mark(ac, settings, &mut diagram);
    Ok(diagram)
}

/// Marks every special point with the aircraft's limits and validity range. The controls there
/// are the settings' with the continuation parameter at the point's value; on a zero-sideslip
/// diagram the rudder is the schedule's at the point's aileron (linear between its points).
fn mark(ac: &Aircraft, settings: &Settings, d: &mut Diagram) {
    let schedule = &d.rudder_schedule;
    let rudder_at = |da: f64| -> Option<f64> {
        let w = schedule
            .windows(2)
            .find(|w| (w[0].delta_a - da) * (w[1].delta_a - da) <= 0.0)?;
        let (a, b) = (&w[0], &w[1]);
        let t = if b.delta_a == a.delta_a {
            0.0
        } else {
            (da - a.delta_a) / (b.delta_a - a.delta_a)
        };
        Some(a.delta_r + t * (b.delta_r - a.delta_r))
    };
    for sp in &mut d.special_points {
        let (mut da, mut de, mut dr) = (settings.delta_a, settings.delta_e, Some(settings.delta_r));
        match settings.param {
            ContinuationParam::DeltaA => da = sp.param,
            ContinuationParam::DeltaE => de = sp.param,
            ContinuationParam::DeltaR => dr = Some(sp.param),
        }
        if settings.zero_sideslip {
            dr = rudder_at(da);
        }
        sp.within_limits = ac.within_limits(da, de, dr);
        sp.valid = ac.valid(sp.alpha, sp.beta);
    }
}

/// Branches and special points as they are found.
#[derive(Default)]
struct Collect {
    branches: Vec<Branch>,
    /// The continuation points of each branch.
    paths: Vec<Vec<V6>>,
    specials: Vec<SpecialPoint>,
    /// Located points (z) of each special point, for de-duplication, with the branches it was
    /// found on.
    seen: Vec<(SpecialKind, V6, Vec<usize>)>,
}

impl Collect {
    /// Adds a branch made of `minus` (reversed), `start` and `plus`; returns the branch points
    /// that are new (not yet seen) for branch switching.
    fn add<S: System>(
        &mut self,
        sys: &S,
        start: &Node,
        plus: Half,
        minus: Option<Half>,
    ) -> Vec<Node> {
        let id = self.branches.len();
        let to_point = |n: &Node| {
            let (x, mu) = sys.physical(&n.z);
            Point {
                param: mu,
                alpha: x[0],
                beta: x[1],
                p: x[2],
                q: x[3],
                r: x[4],
                stable: n.stable,
            }
        };
        let mut nodes: Vec<&Node> = Vec::new();
        let mut found: Vec<Found> = Vec::new();
        if let Some(m) = &minus {
            nodes.extend(m.nodes.iter().rev());
        }
        nodes.push(start);
        nodes.extend(plus.nodes.iter());
        self.branches.push(Branch {
            points: nodes.iter().map(|n| to_point(n)).collect(),
        });
        self.paths.push(nodes.iter().map(|n| n.z).collect());
        if let Some(m) = minus {
            found.extend(m.found);
        }
        found.extend(plus.found);
        let mut new_bps = Vec::new();
        for f in found {
            let kind = match f.kind {
                Kind::Fold => SpecialKind::Fold,
                Kind::Hopf => SpecialKind::Hopf,
                Kind::Branch => SpecialKind::Branch,
            };
            let z = f.node.z;
            if let Some(i) = self.find(kind, &z) {
                if !self.seen[i].2.contains(&id) {
                    self.seen[i].2.push(id);
                }
                continue;
            }
            self.seen.push((kind, z, vec![id]));
            let (x, mu) = sys.physical(&z);
            self.specials.push(SpecialPoint {
                kind,
                param: mu,
                alpha: x[0],
                beta: x[1],
                p: x[2],
                q: x[3],
                r: x[4],
                frequency: f.frequency,
                branch: id,
                within_limits: None,
                valid: true,
            });
            if kind == SpecialKind::Branch {
                new_bps.push(f.node);
            }
        }
        new_bps
    }

    /// The index in `seen` of a special point of this kind at `z`.
    fn find(&self, kind: SpecialKind, z: &V6) -> Option<usize> {
        self.seen
            .iter()
            .position(|(k, w, _)| *k == kind && (w - z).norm() <= 1e-6 * (1.0 + z.norm()))
    }

    /// Whether a traced branch passes through `z`.
    fn on_a_branch(&self, z: &V6) -> bool {
        let tol = 1e-6 * (1.0 + z.norm());
        self.paths.iter().any(|p| {
            p.windows(2)
                .any(|w| engine::dist_to_segment(z, &w[0], &w[1]) <= tol)
        })
    }

    /// Whether both branches through a branch point have been traced.
    fn crossed_twice(&self, z: &V6) -> bool {
        self.find(SpecialKind::Branch, z)
            .is_some_and(|i| self.seen[i].2.len() >= 2)
    }

    fn finish(
        mut self,
        aircraft: String,
        parameter: String,
        rudder_schedule: Vec<SchedulePoint>,
    ) -> Diagram {
        // A turning point in the parameter exactly at a branch point (the rolling branch at a
        // pitchfork of the symmetric branch) is the branch point, not a saddle-node.
        let bps: Vec<V6> = self
            .seen
            .iter()
            .filter(|s| s.0 == SpecialKind::Branch)
            .map(|s| s.1)
            .collect();
        let mut keep = self.seen.iter().map(|(k, z, _)| {
            *k != SpecialKind::Fold
                || !bps
                    .iter()
                    .any(|b| (b - z).norm() <= 1e-5 * (1.0 + z.norm()))
        });
        self.specials.retain(|_| keep.next().unwrap_or(true));
        self.specials.sort_by(|a, b| {
            a.kind
                .cmp(&b.kind)
                .then(a.param.total_cmp(&b.param))
                .then(a.p.total_cmp(&b.p))
        });
        Diagram {
            aircraft,
            parameter,
            branches: self.branches,
            special_points: self.specials,
            rudder_schedule,
        }
    }
}

/// The unconstrained diagram: every seed on the P0 grid not yet passed by a branch starts one;
/// every new branch point starts the crossing branch.
fn unconstrained(
    model: &PssModel,
    s: &Settings,
    out: &mut Collect,
    progress: &mut dyn FnMut(f64),
) -> Result<(), ContinuationError> {
    let base = Controls {
        delta_a: s.delta_a,
        delta_e: s.delta_e,
        delta_r: s.delta_r,
    };
    let control = s.param.index();
    let sys = Unconstrained {
        model,
        base,
        control,
    };
    let eng = Engine {
        sys: &sys,
        lim: limits(s, s.min, s.max),
    };
    let sections = Sections::new(model, base, control)?;
    let mut book = SeedBook::build(&sections, s.seed_spacing, s.max_state, s.min, s.max);
    let e_p = V6::new(0.0, 0.0, 1.0, 0.0, 0.0, 0.0);
    let e_mu = V6::new(0.0, 0.0, 0.0, 0.0, 0.0, 1.0);
    let n_k = book.seeds.len();
    let mut last_report = 0usize;
    for k in 0..n_k {
        if 200 * k >= (last_report + 1) * n_k {
            last_report = 200 * k / n_k;
            progress(k as f64 / n_k as f64);
        }
        for i in 0..book.seeds[k].len() {
            if out.branches.len() >= s.max_branches {
                return Ok(());
            }
            let seed = &book.seeds[k][i];
            if seed.owner.is_some() {
                continue;
            }
            let line = seed.line;
            if line && out.on_a_branch(&seed.z) {
                book.seeds[k][i].owner = Some(usize::MAX);
                continue;
            }
            // Polish at fixed P0 (or, on a line of constant p, at fixed parameter).
            let n = if line { e_mu } else { e_p };
            let Some(start) = eng.start(seed.z, &n, |t| if t[2] != 0.0 { t[2] } else { t[5] })
            else {
                book.seeds[k][i].owner = Some(usize::MAX);
                continue;
            };
            let id = out.branches.len();
            book.seeds[k][i].owner = Some(id);
            let bps = trace_both(&eng, &start, id, Some(&mut book), out, false);
            switch_all(&eng, bps, Some(&mut book), out, s.max_branches);
        }
    }
    Ok(())
}

/// Traces both directions from `start` as branch `id`; adds it unless it duplicates known
/// branches (both directions ran onto them, or a switched branch ran onto one). Returns the new
/// branch points on it.
fn trace_both<S: System>(
    eng: &Engine<'_, S>,
    start: &Node,
    id: usize,
    mut book: Option<&mut SeedBook>,
    out: &mut Collect,
    switched: bool,
) -> Vec<Node> {
    let exact = |z: &V6, p0: f64| {
        let e_p = V6::new(0.0, 0.0, 1.0, 0.0, 0.0, 0.0);
        eng.correct(*z, &e_p, p0).map(|(z, _)| z)
    };
    let mut watch = |a: &V6, b: &V6| match book.as_deref_mut() {
        Some(bk) => bk.crossed(a, b, id, &exact),
        None => Verdict::Continue,
    };
    let plus = eng.trace(start, &mut watch);
    let minus = (plus.end != End::Loop).then(|| eng.trace(&start.reversed(), &mut watch));
    let known = |h: &Half| h.end == End::Known;
    let duplicate = match &minus {
        Some(m) => (known(&plus) && known(m)) || (switched && (known(&plus) || known(m))),
        None => switched && known(&plus),
    };
    if duplicate {
        return Vec::new();
    }
    out.add(eng.sys, start, plus, minus)
}

/// Branch switching at each new branch point, depth first, until none is left.
fn switch_all<S: System>(
    eng: &Engine<'_, S>,
    mut stack: Vec<Node>,
    mut book: Option<&mut SeedBook>,
    out: &mut Collect,
    max_branches: usize,
) {
    while let Some(bp) = stack.pop() {
        if out.branches.len() >= max_branches {
            return;
        }
        if out.crossed_twice(&bp.z) {
            continue;
        }
        let Some(start) = eng.switch(&bp) else {
            continue;
        };
        let id = out.branches.len();
        let more = trace_both(eng, &start, id, book.as_deref_mut(), out, true);
        stack.extend(more.into_iter().rev());
    }
}

/// Section V.B: EBA step 1 (the rudder schedule, by continuation of Eq. 36), then step 2
/// (Eq. 37 with the exact schedule), with branch switching at the departure.
fn zero_sideslip(
    model: &PssModel,
    s: &Settings,
    out: &mut Collect,
    progress: &mut dyn FnMut(f64),
) -> Result<Vec<SchedulePoint>, ContinuationError> {
    let schedule = Schedule::new(model, s.delta_e).ok_or_else(|| {
        ContinuationError::ZeroSideslip(
            "l_delta_a or n_delta_r is zero: no rudder schedule exists".into(),
        )
    })?;
    let level = schedule.at(0.0).ok_or_else(|| {
        ContinuationError::ZeroSideslip("no level zero-sideslip trim at P0 = 0".into())
    })?;
    if level.delta_a < s.min || level.delta_a > s.max {
        return Err(ContinuationError::ZeroSideslip(format!(
            "the level trim needs delta_a = {} rad, outside [min, max]",
            level.delta_a
        )));
    }
    // Step 1: z = (alpha, p, q, r, delta_r, delta_a), from the level trim both ways, each to the
    // range end or the schedule's first fold in delta_a.
    let step1 = ZsConstrained {
        model,
        delta_e: s.delta_e,
    };
    let mut lim1 = limits(s, s.min, s.max);
    lim1.stop_at_fold = true;
    let eng1 = Engine {
        sys: &step1,
        lim: lim1,
    };
    let x = level.x;
    let z1 = V6::new(x[0], x[2], x[3], x[4], level.delta_r, level.delta_a);
    let e_p1 = V6::new(0.0, 1.0, 0.0, 0.0, 0.0, 0.0);
    let start1 = eng1
        .start(z1, &e_p1, |t| t[1])
        .ok_or_else(|| ContinuationError::ZeroSideslip("the level trim is singular".into()))?;
    let mut never = |_: &V6, _: &V6| Verdict::Continue;
    let up = eng1.trace(&start1, &mut never);
    let down = eng1.trace(&start1.reversed(), &mut never);
    progress(0.2);
    let nodes: Vec<&Node> = down
        .nodes
        .iter()
        .rev()
        .chain(std::iter::once(&start1))
        .chain(up.nodes.iter())
        .collect();
    let rudder_schedule: Vec<SchedulePoint> = nodes
        .iter()
        .map(|n| SchedulePoint {
            delta_a: n.z[5],
            delta_r: n.z[4],
            p: n.z[1],
        })
        .collect();
    let (s_lo, s_hi) = (nodes[0].z[1], nodes[nodes.len() - 1].z[1]);
    if s_lo.is_nan() || s_hi.is_nan() || s_lo >= s_hi {
        return Err(ContinuationError::ZeroSideslip(
            "the rudder schedule is empty".into(),
        ));
    }
    // Step 2: z = (alpha, beta, p, q, r, s), s the schedule's roll rate, from the level trim.
    let step2 = ZsScheduled { schedule };
    let eng2 = Engine {
        sys: &step2,
        lim: limits(s, s_lo, s_hi),
    };
    let z2 = V6::new(x[0], x[1], x[2], x[3], x[4], 0.0);
    let e_s = V6::new(0.0, 0.0, 0.0, 0.0, 0.0, 1.0);
    let start2 = eng2
        .start(z2, &e_s, |t| t[5])
        .ok_or_else(|| ContinuationError::ZeroSideslip("the level trim is singular".into()))?;
    let bps = trace_both(&eng2, &start2, 0, None, out, false);
    progress(0.6);
    switch_all(&eng2, bps, None, out, s.max_branches);
    Ok(rudder_schedule)
}

/// Serialises a value under a map key chosen at run time (the parameter's name).
struct Keyed<'a, T>(&'a str, &'a T);

impl Serialize for Keyed<'_, Point> {
    fn serialize<S: Serializer>(&self, ser: S) -> Result<S::Ok, S::Error> {
        let p = self.1;
        let mut m = ser.serialize_map(Some(7))?;
        m.serialize_entry(self.0, &p.param)?;
        m.serialize_entry("alpha", &p.alpha)?;
        m.serialize_entry("beta", &p.beta)?;
        m.serialize_entry("p", &p.p)?;
        m.serialize_entry("q", &p.q)?;
        m.serialize_entry("r", &p.r)?;
        m.serialize_entry("stable", &p.stable)?;
        m.end()
    }
}

impl Serialize for Keyed<'_, Branch> {
    fn serialize<S: Serializer>(&self, ser: S) -> Result<S::Ok, S::Error> {
        let mut m = ser.serialize_map(Some(1))?;
        m.serialize_entry("points", &Keyed(self.0, &self.1.points))?;
        m.end()
    }
}

impl Serialize for Keyed<'_, SpecialPoint> {
    fn serialize<S: Serializer>(&self, ser: S) -> Result<S::Ok, S::Error> {
        let p = self.1;
        let mut m = ser.serialize_map(Some(7 + usize::from(p.frequency.is_some())))?;
        m.serialize_entry("kind", p.kind.name())?;
        m.serialize_entry(self.0, &p.param)?;
        m.serialize_entry("p", &p.p)?;
        m.serialize_entry("alpha", &p.alpha)?;
        m.serialize_entry("beta", &p.beta)?;
        m.serialize_entry("q", &p.q)?;
        m.serialize_entry("r", &p.r)?;
        if let Some(w) = p.frequency {
            m.serialize_entry("frequency", &w)?;
        }
        m.end()
    }
}

impl<T> Serialize for Keyed<'_, Vec<T>>
where
    for<'b> Keyed<'b, T>: Serialize,
{
    fn serialize<S: Serializer>(&self, ser: S) -> Result<S::Ok, S::Error> {
        let mut seq = ser.serialize_seq(Some(self.1.len()))?;
        for item in self.1 {
            seq.serialize_element(&Keyed(self.0, item))?;
        }
        seq.end()
    }
}

impl Serialize for Diagram {
    fn serialize<S: Serializer>(&self, ser: S) -> Result<S::Ok, S::Error> {
        let key = self.parameter.as_str();
        let n = 4 + usize::from(!self.rudder_schedule.is_empty());
        let mut m = ser.serialize_map(Some(n))?;
        m.serialize_entry("aircraft", &self.aircraft)?;
        m.serialize_entry("parameter", &self.parameter)?;
        m.serialize_entry("branches", &Keyed(key, &self.branches))?;
        m.serialize_entry("special_points", &Keyed(key, &self.special_points))?;
        if !self.rudder_schedule.is_empty() {
            m.serialize_entry("rudder_schedule", &self.rudder_schedule)?;
        }
        m.end()
    }
}

impl Diagram {
    /// One row per point under the header
    /// `branch,<parameter>_rad,alpha_rad,beta_rad,p_rad_s,q_rad_s,r_rad_s,stable` (units in
    /// the names; shortest round-trip decimals, `stable` as 1 or 0).
    pub fn to_csv(&self) -> String {
        let mut s = format!(
            "branch,{}_rad,alpha_rad,beta_rad,p_rad_s,q_rad_s,r_rad_s,stable\n",
            self.parameter
        );
        for (i, b) in self.branches.iter().enumerate() {
            for p in &b.points {
                s += &format!(
                    "{i},{},{},{},{},{},{},{}\n",
                    p.param,
                    p.alpha,
                    p.beta,
                    p.p,
                    p.q,
                    p.r,
                    u8::from(p.stable)
                );
            }
        }
        s
    }

    /// The special points of one kind, in the order of [`Diagram::special_points`].
    pub fn special(&self, kind: SpecialKind) -> impl Iterator<Item = &SpecialPoint> {
        self.special_points.iter().filter(move |p| p.kind == kind)
    }
}
