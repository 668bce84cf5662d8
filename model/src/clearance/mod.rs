//! Certified clearance: the critical jump over a box of uncertain data (`model clear`).
//!
//! For an aircraft whose file has an `[uncertainty]` table, [`clear`] bounds the minimum over the
//! box of the critical jump roll rate (the first fold of the primary branch, as
//! [`crate::analysis::analyze`] defines it) and of |delta_a| at it: `lo` is proven by the branch
//! and bound of [`bound`] (no aircraft of the box has a primary-branch jump below it), `hi` is
//! attained by a reported aircraft of the box, computed by the exact `analyze`. What exactly is
//! proven is in `docs/clearance.md`.
//!
//! ```
//! use model::aircraft::{Aircraft, Param, Uncertain};
//! use model::clearance::{sample, split_box, Rng};
//! use num_rational::BigRational;
//!
//! // Aircraft A with l_p uncertain in [-22, -21.5] 1/s, and n_r given as a zero-width interval.
//! let q = |n: i64, d: i64| BigRational::new(n.into(), d.into());
//! let mut a = Aircraft::a();
//! let n_r = a.exact(Param::Nr).clone();
//! a.uncertainty = vec![
//!     Uncertain::param(Param::Lp, q(-22, 1), q(-43, 2)),
//!     Uncertain::param(Param::Nr, n_r.clone(), n_r),
//! ];
//! // The box has one dimension; every sample of it is an aircraft inside it.
//! let (base, wide) = split_box(&a);
//! assert_eq!(wide.len(), 1);
//! let mut rng = Rng::new(7);
//! for _ in 0..10 {
//!     let l_p = sample(&base, &wide, &mut rng).value(Param::Lp);
//!     assert!((-22.0..=-21.5).contains(&l_p), "{l_p}");
//! }
//! ```

pub mod bound;
pub mod monte_carlo;
pub mod run;

use crate::aircraft::{Aircraft, Param, Uncertain};
use crate::analysis::primary::TURN_STEP;
use crate::analysis::{analyze_with, AnalysisError, JumpPoint};
use crate::interval::I;
use bound::{BoxPolys, Failure, LiftedBox, OtherTrim};
use num_rational::BigRational;
use rayon::prelude::*;
use serde::Serialize;
use std::sync::Arc;
use std::time::Instant;

/// Settings of a clearance run.
#[derive(Clone, Debug)]
pub struct Settings {
    /// Elevator deflection, rad.
    pub delta_e_rad: f64,
    /// Tolerance on the roll-rate gap hi - lo, rad/s.
    pub tolerance_p0: f64,
    /// Tolerance on the aileron gap, deg.
    pub tolerance_deg: f64,
    /// An outer guard on the wall-clock time of the branch and bound, s: not a budget (the
    /// budgets are of work, so that the same input gives the same answer on any machine under
    /// any load); a run it stops says so in its note, as an answer that depends on the machine.
    pub wall_clock_guard_s: f64,
    /// Most boxes the branch and bound may hold.
    pub max_boxes: usize,
    /// Most slabs the branch and bound may certify.
    pub max_slabs: usize,
    /// Seed of the random candidates for the worst case.
    pub seed: u64,
    /// Random candidates tried for the worst case (exact analyses).
    pub candidates: usize,
    /// Further candidates for the worst case, as box coordinates (one per `[uncertainty]`
    /// entry, in its order; each clamped into the box): `model clear` passes the Monte Carlo's
    /// lowest samples ([`monte_carlo::MonteCarlo::lowest_at`]), so that hi is at most what
    /// they attain (to within the certified route's brackets, 1e-9 relative). One of another
    /// length, or that the exact path refuses, is skipped.
    pub candidates_at: Vec<Vec<f64>>,
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            delta_e_rad: 2f64.to_radians(),
            tolerance_p0: 1e-3,
            tolerance_deg: 0.01,
            wall_clock_guard_s: 600.0,
            max_boxes: 20_000,
            max_slabs: 500_000,
            seed: 1,
            candidates: 64,
            candidates_at: Vec::new(),
        }
    }
}

/// A certified interval for a minimum over the box.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct Bounds {
    /// Proven lower bound (infinite, null in JSON, when no aircraft of the box has a critical
    /// jump).
    pub lo: f64,
    /// Attained by the worst-case aircraft (null when no aircraft of the box has a critical jump).
    pub hi: Option<f64>,
    /// `hi - lo` (null without `hi`).
    pub gap: Option<f64>,
    /// Whether the gap is within the tolerance.
    pub converged: bool,
}

/// One aircraft of the box: every parameter by its TOML key, and its critical jump.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct CaseAircraft {
    /// Every parameter by its TOML key (exact values rounded once to f64).
    #[serde(flatten)]
    pub parameters: std::collections::BTreeMap<String, f64>,
    /// Its critical jump roll rate, rad/s.
    pub p0: f64,
    /// The aileron at it, deg.
    pub delta_a_deg: f64,
    /// The exact aircraft (not serialized).
    #[serde(skip)]
    pub aircraft: Aircraft,
    /// Its exact coordinates in the box (not serialized).
    #[serde(skip)]
    pub coordinates: Vec<BigRational>,
}

/// The result of [`clear`].
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct Clearance {
    /// Aircraft name.
    pub aircraft: String,
    /// Elevator deflection, rad.
    pub delta_e_rad: f64,
    /// The uncertain parameters (TOML keys) and their intervals.
    #[serde(rename = "box")]
    pub box_: Vec<(String, f64, f64)>,
    /// Bounds on the minimum critical jump roll rate, rad/s.
    pub critical_p0: Bounds,
    /// Bounds on the minimum |delta_a| at the critical jump, deg.
    pub critical_delta_a_deg: Bounds,
    /// The aircraft attaining `critical_p0.hi`.
    pub worst_case: Option<CaseAircraft>,
    /// The aircraft attaining `critical_delta_a_deg.hi`.
    pub worst_case_aileron: Option<CaseAircraft>,
    /// Cleared against the aileron limit (null without a limit, or when undecided).
    pub cleared: Option<bool>,
    /// Proven: no aircraft of the box has a critical jump (every primary branch leaves the
    /// aileron range `analyze` follows it to before any jump). Then both `lo` are infinite
    /// (null in JSON: the minimum over an empty set), both `hi` null, and `converged` true.
    pub no_critical_jump: bool,
    /// An aircraft of the box with a critical jump within the aileron limit.
    pub counterexample: Option<CaseAircraft>,
    /// Why the branch and bound stopped (and, when not converged, what limited it).
    pub note: String,
    /// Boxes examined and slabs tried.
    pub boxes: usize,
    /// Slabs tried.
    pub slabs: usize,
    /// Wall-clock time of the proof, s: in the text output only, so that the JSON of one input
    /// is the same bytes on every machine and run.
    #[serde(skip)]
    pub seconds: f64,
}

/// Why a clearance cannot be computed.
#[derive(Debug, thiserror::Error)]
pub enum ClearError {
    /// The exact analysis of an aircraft of the box failed.
    #[error("{0}")]
    Analysis(#[from] AnalysisError),
}

/// The critical jump of one exact aircraft by the exact path: the jump part of `analyze`
/// alone, whose critical jump is the same point; the departure part (Hopf points, landings)
/// would cost up to seconds per aircraft with aileron yaw and decide nothing here.
pub fn critical(aircraft: &Aircraft, delta_e_rad: f64) -> Result<Option<JumpPoint>, AnalysisError> {
    Ok(analyze_with(aircraft, delta_e_rad, false)?.critical)
}

/// How one coordinate of a box enters the data, enclosed: what the branch and bound
/// ([`bound::BoxPolys`]) and the Monte Carlo ([`monte_carlo::run`]) both build on.
#[derive(Clone, Debug)]
pub(crate) enum Coordinate {
    /// The value of a parameter.
    Param(Param),
    /// A coefficient of a nondimensional file: each parameter `p` it moves is its fixed value
    /// plus `a_p (x - nominal)` (enclosures of the exact `a_p` and nominal).
    Coefficient { nominal: I, moves: Vec<(Param, I)> },
}

impl Coordinate {
    /// The coordinate of an uncertain entry.
    pub(crate) fn of(u: &Uncertain) -> Coordinate {
        match &u.coefficient {
            None => Coordinate::Param(u.param),
            Some(c) => Coordinate::Coefficient {
                nominal: I::from_q(&c.nominal),
                moves: c.moves.iter().map(|(p, a)| (*p, I::from_q(a))).collect(),
            },
        }
    }

    /// The parameters it moves.
    pub(crate) fn params(&self) -> Vec<Param> {
        match self {
            Coordinate::Param(p) => vec![*p],
            Coordinate::Coefficient { moves, .. } => moves.iter().map(|(p, _)| *p).collect(),
        }
    }
}

/// The box of an aircraft: its uncertain parameters of nonzero width with their exact ends, and
/// the aircraft with every zero-width parameter set to its value.
pub fn split_box(aircraft: &Aircraft) -> (Aircraft, Vec<Uncertain>) {
    let mut base = aircraft.clone();
    let mut wide = Vec::new();
    for u in &aircraft.uncertainty {
        if u.lo == u.hi {
            base = u.moved(base, &u.lo);
        } else {
            wide.push(u.clone());
        }
    }
    base.uncertainty = Vec::new();
    (base, wide)
}

/// The aircraft at exact coordinates `x` of the box.
pub fn at(base: &Aircraft, params: &[Uncertain], x: &[BigRational]) -> Aircraft {
    params
        .iter()
        .zip(x)
        .fold(base.clone(), |a, (u, v)| u.moved(a, v))
}

/// f64 coordinates of the box as exact values within the exact ends ([`clamp_exact`] each).
pub fn exact_coordinates(params: &[Uncertain], x: &[f64]) -> Vec<BigRational> {
    params
        .iter()
        .zip(x)
        .map(|(u, v)| clamp_exact(u, *v))
        .collect()
}

/// An f64 coordinate of the box as an exact value within the exact ends.
pub fn clamp_exact(u: &Uncertain, v: f64) -> BigRational {
    let q = BigRational::from_float(v).unwrap_or_else(|| u.lo.clone());
    if q < u.lo {
        u.lo.clone()
    } else if q > u.hi {
        u.hi.clone()
    } else {
        q
    }
}

/// The aircraft `a` at coordinates `x` of the box `params` with its critical jump `j`: every
/// parameter by its key, and each uncertain coefficient of a nondimensional file by its key.
fn case(a: &Aircraft, params: &[Uncertain], x: &[BigRational], j: &JumpPoint) -> CaseAircraft {
    let coefficients = params
        .iter()
        .zip(x)
        .filter(|(u, _)| u.coefficient.is_some())
        .map(|(u, v)| (u.key().to_string(), crate::aircraft::rational_to_f64(v)));
    CaseAircraft {
        parameters: Param::ALL
            .iter()
            .map(|p| (p.key().to_string(), a.value(*p)))
            .chain(coefficients)
            .collect(),
        p0: j.p0,
        delta_a_deg: j.delta_a_deg,
        aircraft: a.clone(),
        coordinates: x.to_vec(),
    }
}

/// The seeded generator of the samples and candidates.
pub use crate::random::Rng;

/// A uniform random aircraft of the box.
pub fn sample(base: &Aircraft, params: &[Uncertain], rng: &mut Rng) -> Aircraft {
    at(base, params, &sample_coordinates(params, rng))
}

/// Uniform random (exact) coordinates in the box.
pub fn sample_coordinates(params: &[Uncertain], rng: &mut Rng) -> Vec<BigRational> {
    params
        .iter()
        .map(|u| {
            let b = I::from_q_pair(&u.lo, &u.hi);
            clamp_exact(u, b.lo + rng.unit() * (b.hi - b.lo))
        })
        .collect()
}

/// The worst cases found so far, by the exact path.
struct Worst<'a> {
    base: &'a Aircraft,
    params: &'a [Uncertain],
    p0: Option<(f64, CaseAircraft)>,
    da: Option<(f64, CaseAircraft)>,
    limit_hit: Option<CaseAircraft>,
    limit_deg: Option<f64>,
    delta_e_rad: f64,
}

impl Worst<'_> {
    /// Evaluates the aircraft at coordinates `x`; returns its critical (p0, |delta_a| deg) if
    /// it has one.
    fn try_at(&mut self, x: &[BigRational]) -> Result<Option<(f64, f64)>, ClearError> {
        let a = at(self.base, self.params, x);
        let j = critical(&a, self.delta_e_rad)?;
        Ok(self.record(&a, x, j))
    }

    /// Keeps `a` (at coordinates `x`) if its critical jump `j` lowers either minimum (or hits
    /// the limit).
    fn record(
        &mut self,
        a: &Aircraft,
        x: &[BigRational],
        j: Option<JumpPoint>,
    ) -> Option<(f64, f64)> {
        let j = j?;
        let da = j.delta_a_deg.abs();
        let case = |a: &Aircraft| case(a, self.params, x, &j);
        if self.lowers_p0(j.p0) {
            self.p0 = Some((j.p0, case(a)));
        }
        if self.lowers_da(da) {
            self.da = Some((da, case(a)));
        }
        if self.first_within_limit(da) {
            self.limit_hit = Some(case(a));
        }
        Some((j.p0, da))
    }

    /// Whether a critical roll rate `p0` is below the lowest so far.
    fn lowers_p0(&self, p0: f64) -> bool {
        self.p0.as_ref().is_none_or(|(p, _)| p0 < *p)
    }

    /// Whether an |delta_a| (deg) at a critical jump is below the lowest so far.
    fn lowers_da(&self, da: f64) -> bool {
        self.da.as_ref().is_none_or(|(d, _)| da < *d)
    }

    /// Whether an |delta_a| (deg) at a critical jump is within the aileron limit, and the first
    /// such.
    fn first_within_limit(&self, da: f64) -> bool {
        self.limit_hit.is_none() && self.limit_deg.is_some_and(|l| da <= l)
    }

    /// Tries the sub-box `theta` for the worst case of the minimum `by_p0` works on (the
    /// critical roll rate, else |delta_a|): the branch and bound's lowest sub-box is where that
    /// minimum lies, and hi, unlike lo, moves only when an aircraft attains a lower value. A
    /// minimum inside the box is out of reach of the candidates and the vertex search; so is
    /// one where the critical jump vanishes (a cusp, where the fold pair of the jump merges:
    /// |delta_a| at the jump tends to its infimum there, attained by no aircraft), which the
    /// lowest sub-box closes in on while its centre has no jump at all. So: the centre first;
    /// without a critical jump there, a bisection between the best aircraft so far and the
    /// centre towards where the jump vanishes, keeping the lowest aircraft with one it meets.
    ///
    /// Each point is screened by the certified route (about a hundredth of the exact path's
    /// time); the best one found, if it would lower either minimum or hit the limit, is
    /// analysed by the exact path, which alone sets hi. A probe is only ever a candidate: one
    /// the exact path refuses (e.g. two jump roots that round to the same double, next to a
    /// cusp) is dropped, and the proof goes on.
    fn probe(&mut self, theta: &[I], by_p0: bool) {
        let key = |f: &Screened| if by_p0 { f.p0 } else { f.da_deg };
        let centre: Vec<f64> = theta.iter().map(|t| t.mid()).collect();
        if let Some(found) = self.screen(&centre) {
            return self.offer(found);
        }
        let best = if by_p0 { &self.p0 } else { &self.da };
        let Some((_, case)) = best else {
            return;
        };
        let mut yes: Vec<f64> = case
            .coordinates
            .iter()
            .map(|q| I::from_q(q).mid())
            .collect();
        let mut no = centre;
        let mut found: Option<Screened> = None;
        for _ in 0..PROBE_BISECTIONS {
            let m: Vec<f64> = yes
                .iter()
                .zip(&no)
                .map(|(a, b)| 0.5 * a + 0.5 * b)
                .collect();
            if m == yes || m == no {
                break;
            }
            match self.screen(&m) {
                Some(f) => {
                    if found.as_ref().is_none_or(|b| key(&f) < key(b)) {
                        found = Some(f);
                    }
                    yes = m;
                }
                None => no = m,
            }
        }
        if let Some(f) = found {
            self.offer(f);
        }
    }

    /// The aircraft at the f64 coordinates `x` (each clamped into the box as an exact value)
    /// if the certified route proves that it has a critical jump (the Monte Carlo's lean
    /// route, [`crate::analysis::fast::critical_of`], without the exact path's fallback: next to
    /// a cusp that fallback is the slow one, and an uncertified point only ends a bisection).
    fn screen(&self, x: &[f64]) -> Option<Screened> {
        let x = exact_coordinates(self.params, x);
        let aircraft = at(self.base, self.params, &x);
        let lift = || crate::certified::Values::of(&aircraft, self.delta_e_rad, 0.0);
        let bound = aircraft.aileron_range();
        let data = crate::certified::Values::data(&aircraft);
        let width = crate::analysis::fast::MAX_WIDTH;
        let (p0, da) =
            crate::analysis::fast::critical_of(&data, self.delta_e_rad, &lift, bound, width)
                .ok()??;
        Some(Screened {
            x,
            p0,
            da_deg: da.to_degrees().abs(),
        })
    }

    /// Analyses a screened aircraft by the exact path if it would lower a minimum or hit the
    /// limit (its exact answer, not the screen's, is what is kept; nothing, if the exact path
    /// refuses it).
    fn offer(&mut self, f: Screened) {
        if self.lowers_p0(f.p0) || self.lowers_da(f.da_deg) || self.first_within_limit(f.da_deg) {
            // An aircraft the exact path refuses is no candidate (hi is only ever its answer).
            let _ = self.try_at(&f.x);
        }
    }
}

/// An aircraft of the box with a critical jump, found by [`Worst::screen`]: its exact
/// coordinates, and its critical roll rate and |delta_a| (deg) by the certified route.
struct Screened {
    x: Vec<BigRational>,
    p0: f64,
    da_deg: f64,
}

/// Bisection steps of [`Worst::probe`] towards where the critical jump vanishes: 2^-40 of the
/// segment, far below any tolerance, at about 40 certified analyses.
const PROBE_BISECTIONS: usize = 40;

/// Greedy vertex search from `start`: each coordinate in turn moved to the end of its interval
/// that lowers `key` (the critical p0 or |delta_a|), repeated while it improves. A point the
/// exact path refuses is no candidate and is passed over (`start` itself must be analysed).
fn descend(
    worst: &mut Worst,
    params: &[Uncertain],
    start: Vec<BigRational>,
    key: fn(f64, f64) -> f64,
) -> Result<(), ClearError> {
    let mut x = start;
    let mut best = match worst.try_at(&x)? {
        Some((p, d)) => key(p, d),
        None => f64::INFINITY,
    };
    for _pass in 0..3 {
        let mut improved = false;
        for i in 0..params.len() {
            for end in [&params[i].lo, &params[i].hi] {
                if x[i] == *end {
                    continue;
                }
                let mut y = x.clone();
                y[i] = end.clone();
                if let Ok(Some((p, d))) = worst.try_at(&y) {
                    if key(p, d) < best {
                        best = key(p, d);
                        x = y;
                        improved = true;
                    }
                }
            }
        }
        if !improved {
            break;
        }
    }
    Ok(())
}

/// A leaf of the branch and bound: a sub-box certified from P0 = 0 to `depth`.
#[derive(Clone, Debug)]
struct Leaf {
    theta: Vec<I>,
    /// The box lifted once for all its slabs; dropped once the sub-box is retired
    /// ([`Leaf::retired`]: about 125 kB each with 17 uncertain parameters, which thousands of
    /// sub-boxes held to the end), and made again from `theta` and `side` should it be
    /// stepped after all.
    lifted: Option<Arc<LiftedBox>>,
    /// The branch's side of the dropped lifted data ([`LiftedBox::side`]), to lift it again as
    /// it was.
    side: Option<f64>,
    depth: f64,
    step: f64,
    /// Lower bound of |delta_a| (rad) of the primary branch at `depth` over the box.
    da_lo: f64,
    /// The depth at which `da_lo` first exceeded the aileron range `analyze` follows the
    /// primary branch to (`None` while it has not, or when the trim at P0 = 0 needs aileron).
    beyond_at: Option<f64>,
    /// Why its latest slab failed (`None` after a certified one).
    last: Option<Failure>,
    stuck: Option<Failure>,
    /// Certified slabs whose *other* trim may hold a jump within the aileron range
    /// ([`BoxPolys::other_trim`]), in increasing P0, above `barrier`: a branch that turns in
    /// P0 beyond the depth and comes back on that trim could meet it, so the sub-box's bound
    /// is the lowest.
    doubts: Vec<I>,
    /// The top of the highest run of consecutive slabs, at least `TURN_STEP` long, whose other
    /// trim lies beyond the aileron range ([`OtherTrim::BeyondRange`]): a branch coming back
    /// down on that trim has a step end in it, checked against the range, so it ends there
    /// and never reaches the slabs below.
    barrier: f64,
    /// Where the current run of such slabs (up to the depth) starts.
    run_from: Option<f64>,
    /// The depth at which the search for a barrier above the lowest doubt
    /// ([`Walk::search_barrier`]) last failed (not tried again there).
    searched_at: Option<f64>,
    /// The top of the certified turn zone above the depth ([`BoxPolys::turn_back`]): every
    /// aircraft's branch turns back in P0 below it with no jump, and comes back down through
    /// the depth on its other trim, so only the doubts bound the sub-box (and none: finished).
    turned: Option<f64>,
    /// Whether the sub-box has been probed for the worst case ([`Worst::probe`]), which is
    /// done once, the first time it is the lowest.
    probed: bool,
}

/// How far past the roll rate where |delta_a| exceeds the aileron range a sub-box must be
/// certified before it is finished: two steps of the primary-branch walk of `analyze`, which
/// checks the range at steps at most [`MAX_STEP`](crate::analysis::primary::MAX_STEP) apart
/// (the second step in case the f64 value at the first rounds onto the range).
const BEYOND_MARGIN: f64 = 2.0 * crate::analysis::primary::MAX_STEP;

/// The largest roll rate the proof certifies to, rad/s. A sub-box is followed until its
/// branch leaves the aileron range, which for a box without jumps can lie far out (aircraft A
/// at delta_e = 0 reaches 90 deg of aileron near 80 rad/s); this cap keeps every enclosure
/// finite (the criterion polynomials have degree up to about 30 in P0) and the work bounded. A
/// sub-box that reaches it unfinished keeps it as its depth: no jump below it is proven.
pub const MAX_ROLL_RATE: f64 = 1000.0;

impl Leaf {
    /// The sub-box `theta` of `polys`, certified nowhere yet, its first slab `step` wide.
    fn new(polys: &BoxPolys, theta: &[I], step: f64) -> Leaf {
        Leaf {
            lifted: Some(Arc::new(polys.lift(theta))),
            side: None,
            theta: theta.to_vec(),
            depth: 0.0,
            step,
            da_lo: 0.0,
            beyond_at: None,
            last: None,
            stuck: None,
            doubts: Vec::new(),
            searched_at: None,
            barrier: 0.0,
            run_from: None,
            turned: None,
            probed: false,
        }
    }

    /// The box lifted, made again from `theta` and `side` if it was dropped.
    fn lifted(&mut self, polys: &BoxPolys) -> Arc<LiftedBox> {
        let (theta, side) = (&self.theta, self.side);
        Arc::clone(
            self.lifted
                .get_or_insert_with(|| Arc::new(polys.lift_on_side(theta, side))),
        )
    }

    /// Drops the lifted data, keeping the branch's side to lift it again with.
    fn drop_lifted(&mut self) {
        if let Some(l) = self.lifted.take() {
            self.side = l.side();
        }
    }

    /// Whether the sub-box is done with: finished or stuck, or at or past both targets, the
    /// roll rate `reach` and the aileron bound `da_target` (which only go down while a worst
    /// case is known, as hi does). It may still be stepped: as the lowest sub-box while a stuck
    /// one holds a bound below the target, or when a first worst case sets the aileron target;
    /// it is then lifted again (and the proof is the same, only slower).
    fn retired(&self, reach: f64, da_target: f64) -> bool {
        self.finished()
            || self.stuck.is_some()
            || (self.p0_key() >= reach && self.da_key() >= da_target)
    }

    /// Whether the sub-box is proven to have no critical jump: along every aircraft's primary
    /// branch, |delta_a| (monotone before the first fold, Section 5 of docs/clearance.md)
    /// exceeds the aileron range at `beyond_at` with no jump, fold or divergence up to
    /// `beyond_at + BEYOND_MARGIN`, so `analyze`'s walk ends beyond the range (`Unbounded`)
    /// before it can meet a jump; or every branch turns back in P0 above the depth with no jump
    /// ([`Leaf::turned`]) and comes back down on an other trim that holds no jump within the
    /// range or ends at a barrier (no doubt left, docs/clearance.md step 6).
    fn finished(&self) -> bool {
        self.beyond_at
            .is_some_and(|d| self.depth >= d + BEYOND_MARGIN)
            || (self.turned.is_some() && self.doubts.is_empty())
    }

    /// The proven lower bound of the critical jump roll rate on the sub-box: the certified
    /// depth or, below it, the lowest slab whose other trim may hold a jump; infinity for a
    /// finished sub-box (no critical jump at all: the minimum over an empty set).
    fn p0_key(&self) -> f64 {
        if self.finished() {
            f64::INFINITY
        } else {
            self.doubt().map_or(self.depth, |d| d.lo.min(self.depth))
        }
    }

    /// The lowest doubtful slab, which bounds the sub-box.
    fn doubt(&self) -> Option<I> {
        self.doubts.first().copied()
    }

    /// Records the other trim of the certified slab `slab`, the deepest so far.
    fn record_other_trim(&mut self, slab: I, other: OtherTrim) {
        match other {
            OtherTrim::BeyondRange => {
                let from = *self.run_from.get_or_insert(slab.lo);
                if slab.hi - from >= TURN_STEP {
                    self.raise_barrier(slab.hi);
                }
            }
            OtherTrim::NoJump => self.run_from = None,
            OtherTrim::MayJump => {
                self.run_from = None;
                self.doubts.push(slab);
            }
        }
    }

    /// The lower bound of |delta_a| at the critical jump, or infinity for a finished sub-box.
    fn da_key(&self) -> f64 {
        if self.finished() {
            f64::INFINITY
        } else {
            self.da_lo
        }
    }

    /// Raises the barrier to `top` and drops what it shields of the doubts: those below it
    /// whole, and the part below it of one it cuts (a barrier found by
    /// [`Walk::search_barrier`] need not end on a slab's edge).
    fn raise_barrier(&mut self, top: f64) {
        self.barrier = self.barrier.max(top);
        let barrier = self.barrier;
        self.doubts.retain(|d| d.hi > barrier);
        for d in &mut self.doubts {
            *d = I::new(d.lo.max(barrier), d.hi);
        }
    }

    /// The proven minima over `leaves`: of the critical jump roll rate and of |delta_a| at it
    /// (each infinite when every sub-box is finished).
    fn minima(leaves: &[Leaf]) -> (f64, f64) {
        let min = |key: fn(&Leaf) -> f64| leaves.iter().map(key).fold(f64::INFINITY, f64::min);
        (min(Leaf::p0_key), min(Leaf::da_key))
    }

    /// Raises `da_lo` to `lower` (a lower bound at `depth`) and records where it first exceeds
    /// `range`, the aileron range (infinite when |delta_a| is not monotone from 0).
    fn raise_aileron(&mut self, lower: f64, range: f64) {
        self.da_lo = self.da_lo.max(lower);
        if self.beyond_at.is_none() && self.da_lo > range * (1.0 + 1e-9) {
            self.beyond_at = Some(self.depth);
        }
    }
}

/// The widest turn zone tried above a sub-box held where its branch may turn
/// ([`BoxPolys::turn_back`]), rad/s.
const TURN_ZONE: f64 = 0.5;

/// Leaves of the branch and bound stepped at once (in parallel on rayon's threads).
const BATCH: usize = 8;

/// What one step of a leaf needs: the box's polynomials, the initial box, the roll rate no
/// slab goes beyond, and the slab widths.
struct Walk<'a> {
    polys: &'a BoxPolys,
    theta0: &'a [I],
    limit: f64,
    min_step: f64,
    first_step: f64,
    /// The aileron range `analyze` follows the primary branch to, rad (infinite when the trim
    /// at P0 = 0 needs aileron for some aircraft: then |delta_a| is not bounded from 0).
    range: f64,
}

impl Walk<'_> {
    /// One step of `leaf`: its next slab certified (the leaf deeper, its step doubled), or
    /// not (the step quartered; at the smallest step the box split in two, or the leaf stuck
    /// when it cannot be). Returns the leaf and the other half of a split.
    fn step(&self, leaf: &Leaf) -> (Leaf, Option<Leaf>) {
        let (polys, mut leaf) = (self.polys, leaf.clone());
        let lifted = leaf.lifted(polys);
        if let Some(doubt) = leaf.doubt() {
            // The doubt, not the depth, bounds this sub-box. Look for a barrier above it (once
            // per depth), else clear the doubt on halves of its slab while it is wider than the
            // smallest step. A doubt that neither clears stays, and the sub-box goes deeper as
            // usual: it may be finished (its branch leaves the range first), find a barrier
            // further up, reach a jump, or split (its halves check the doubt again).
            if leaf.searched_at != Some(leaf.depth) {
                leaf.searched_at = Some(leaf.depth);
                if self.search_barrier(&mut leaf, &lifted, doubt.hi) {
                    return (leaf, None);
                }
            }
            if doubt.width() > self.min_step {
                let m = doubt.mid();
                let halves = [I::new(doubt.lo, m), I::new(m, doubt.hi)];
                let left: Vec<I> = halves
                    .into_iter()
                    .filter(|h| !polys.other_trim(&lifted, *h, self.range).is_clear())
                    .collect();
                leaf.doubts.splice(0..1, left);
                return (leaf, None);
            }
            if leaf.turned.is_some() {
                // The branch turns back below the turn zone's top: going deeper proves nothing
                // more. The halves check the doubt again on their smaller boxes.
                return self.split(leaf, &lifted, doubt, Failure::Jump);
            }
        }
        let top = (leaf.depth + leaf.step).min(self.limit.max(leaf.depth + self.min_step));
        let slab = I::new(leaf.depth, top);
        let why = match polys.certify_with_other(&lifted, slab, self.range) {
            Ok((_, other)) => {
                leaf.record_other_trim(slab, other);
                leaf.last = None;
                leaf.depth = top;
                leaf.step *= 2.0;
                if let Some(lower) = polys.aileron_lower(&lifted, top) {
                    leaf.raise_aileron(lower, self.range);
                }
                return (leaf, None);
            }
            Err(why) => why,
        };
        leaf.last = Some(why);
        if leaf.step > self.min_step {
            leaf.step = (leaf.step / 4.0).max(self.min_step);
            return (leaf, None);
        }
        if why == Failure::Turn {
            // Before splitting: the branch may turn back, for every aircraft of the sub-box,
            // within a zone that holds no jump.
            let zone = polys.turn_back(&lifted, leaf.depth, self.min_step, TURN_ZONE);
            if let Some(top) = zone {
                leaf.turned = Some(top);
                return (leaf, None);
            }
        }
        self.split(leaf, &lifted, slab, why)
    }

    /// Looks, from the depth down to `from` (the top of the lowest doubt), for a slab of at
    /// least `TURN_STEP` whose other trim lies beyond the aileron range
    /// ([`BoxPolys::other_beyond_range`]; a sub-box's own slabs may not show one where its
    /// halves do), in 32 slabs at most; the highest one found becomes the barrier, and the doubts
    /// below it are dropped. Returns whether one was found.
    fn search_barrier(&self, leaf: &mut Leaf, lifted: &LiftedBox, from: f64) -> bool {
        let w = ((leaf.depth - from) / 32.0).max(TURN_STEP);
        let mut hi = leaf.depth;
        while hi - w >= from {
            let slab = I::new(hi - w, hi);
            if self.polys.other_beyond_range(lifted, slab, self.range) {
                leaf.raise_barrier(slab.hi);
                return true;
            }
            hi -= w;
        }
        false
    }

    /// Splits `leaf` (lifted: `parent`) in two because the slab `slab` failed with `why` at the
    /// smallest step (or the leaf stuck when it cannot be split); each half re-checks the other
    /// trim of its doubtful slabs on its smaller box.
    fn split(
        &self,
        mut leaf: Leaf,
        parent: &LiftedBox,
        slab: I,
        why: Failure,
    ) -> (Leaf, Option<Leaf>) {
        let polys = self.polys;
        // Split the coordinate that spreads the failing quantity most (its partial derivative
        // times the coordinate's width); the widest one (relative to the initial box) when that
        // cannot be told.
        let theta0 = self.theta0;
        let widest = (0..leaf.theta.len())
            .max_by(|a, b| {
                let r = |j: usize| leaf.theta[j].width() / theta0[j].width();
                r(*a).total_cmp(&r(*b))
            })
            .unwrap_or(0);
        let k = polys.split_coordinate(parent, slab, why).unwrap_or(widest);
        let t = leaf.theta[k];
        let m = t.mid();
        if m <= t.lo || m >= t.hi {
            leaf.stuck = Some(why);
            return (leaf, None);
        }
        let mut other = leaf.clone();
        leaf.theta[k] = I::new(t.lo, m);
        other.theta[k] = I::new(m, t.hi);
        leaf.step = self.first_step.max(self.min_step);
        other.step = leaf.step;
        (leaf.probed, other.probed) = (false, false);
        // The halves bound |delta_a| at their depth more tightly than the whole, and may clear
        // the other trim where the whole could not.
        for half in [&mut leaf, &mut other] {
            let lifted = Arc::new(polys.lift_part(&half.theta, parent));
            half.doubts
                .retain(|d| !polys.other_trim(&lifted, *d, self.range).is_clear());
            half.searched_at = None;
            if let Some(lower) = polys.aileron_lower(&lifted, half.depth) {
                half.raise_aileron(lower, self.range);
            }
            half.lifted = Some(lifted);
        }
        (leaf, Some(other))
    }
}

/// Runs the clearance of `aircraft`'s `[uncertainty]` box; `progress` gets a fraction in [0, 1].
pub fn clear(
    aircraft: &Aircraft,
    settings: &Settings,
    progress: &mut dyn FnMut(f64),
) -> Result<Clearance, ClearError> {
    let start = Instant::now();
    let de = settings.delta_e_rad;
    let (base, params) = split_box(aircraft);
    let mut worst = Worst {
        base: &base,
        params: &params,
        p0: None,
        da: None,
        limit_hit: None,
        limit_deg: aircraft.limits.aileron_deg,
        delta_e_rad: de,
    };
    let box_ = params
        .iter()
        .map(|u| {
            let b = I::from_q_pair(&u.lo, &u.hi);
            (u.key().to_string(), b.lo, b.hi)
        })
        .collect();
    let finish = |worst: Worst,
                  p0_lo: f64,
                  da_lo_deg: f64,
                  note: String,
                  boxes: usize,
                  slabs: usize|
     -> Clearance {
        // No critical jump anywhere in the box (proven): the minimum over an empty set, lo =
        // infinity (null in JSON), exact.
        let none = p0_lo == f64::INFINITY && worst.p0.is_none();
        let bounds = |lo: f64, hi: Option<f64>, tol: f64| {
            let gap = hi.map(|h| (h - lo).max(0.0));
            Bounds {
                lo,
                hi,
                gap,
                converged: gap.is_some_and(|g| g <= tol) || none,
            }
        };
        let hi_p0 = worst.p0.as_ref().map(|(p, _)| *p);
        let hi_da = worst.da.as_ref().map(|(d, _)| *d);
        let cleared = worst.limit_deg.and_then(|l| {
            if worst.limit_hit.is_some() {
                Some(false)
            } else if da_lo_deg > l {
                Some(true)
            } else {
                None
            }
        });
        Clearance {
            aircraft: aircraft.name.clone(),
            delta_e_rad: de,
            box_,
            critical_p0: bounds(p0_lo, hi_p0, settings.tolerance_p0),
            critical_delta_a_deg: bounds(da_lo_deg, hi_da, settings.tolerance_deg),
            worst_case: worst.p0.map(|(_, c)| c),
            worst_case_aileron: worst.da.map(|(_, c)| c),
            cleared,
            no_critical_jump: none,
            counterexample: worst.limit_hit,
            note,
            boxes,
            slabs,
            seconds: start.elapsed().as_secs_f64(),
        }
    };

    if params.is_empty() {
        // A point: the exact analysis is the proof.
        let (lo, da) = match worst.try_at(&[])? {
            Some((p, d)) => (p, d),
            None => (f64::INFINITY, f64::INFINITY),
        };
        let note = "zero-width box: the exact analysis of its one aircraft".to_string();
        return Ok(finish(worst, lo, da, note, 0, 0));
    }

    // Candidates for the worst case: the centre, seeded random points, and a greedy vertex
    // search from the best of them for each of the two minima.
    let centre: Vec<BigRational> = params
        .iter()
        .map(|u| (&u.lo + &u.hi) / BigRational::from_integer(2.into()))
        .collect();
    worst.try_at(&centre)?;
    // The random candidates analysed on rayon's threads, kept in their seeded order.
    let mut rng = Rng::new(settings.seed);
    let candidates: Vec<(Vec<BigRational>, Aircraft)> = (0..settings.candidates)
        .map(|_| {
            let x = sample_coordinates(&params, &mut rng);
            let a = at(&base, &params, &x);
            (x, a)
        })
        .collect();
    let found: Vec<_> = candidates
        .par_iter()
        .map(|(_, a)| critical(a, de))
        .collect();
    for ((x, a), j) in candidates.iter().zip(found) {
        worst.record(a, x, j?);
    }
    for x in settings
        .candidates_at
        .iter()
        .filter(|x| x.len() == params.len())
    {
        // An aircraft the exact path refuses is no candidate (hi is only ever its answer).
        let _ = worst.try_at(&exact_coordinates(&params, x));
    }
    progress(0.05);
    let coords = |c: &Option<(f64, CaseAircraft)>| -> Vec<BigRational> {
        match c {
            Some((_, w)) => w.coordinates.clone(),
            None => centre.clone(),
        }
    };
    let from_p0 = coords(&worst.p0);
    descend(&mut worst, &params, from_p0, |p, _| p)?;
    let from_da = coords(&worst.da);
    descend(&mut worst, &params, from_da, |_, d| d)?;
    progress(0.1);

    let polys = BoxPolys::of_box(&base, &params, de);
    let theta0: Vec<I> = params
        .iter()
        .map(|u| I::from_q_pair(&u.lo, &u.hi))
        .collect();
    let hi_p0 = worst.p0.as_ref().map_or(f64::INFINITY, |(p, _)| *p);
    let first_step = if hi_p0.is_finite() {
        hi_p0 / 32.0
    } else {
        0.05
    };
    let min_step = settings.tolerance_p0 / 8.0;
    let mut leaves = vec![Leaf::new(&polys, &theta0, first_step)];
    let range = if polys.symmetric {
        aircraft.aileron_range()
    } else {
        f64::INFINITY
    };
    let (mut boxes, mut slabs) = (1usize, 0usize);
    let tol_da = settings.tolerance_deg.to_radians();
    let note;
    loop {
        // How deep every sub-box must be certified: to the worst case found (less the
        // tolerance), or, when no aircraft tried has a critical jump, until every sub-box is
        // finished (its branch leaves the aileron range first) or reaches the cap. The worst
        // case found only ever goes down (`Worst::probe`).
        let hi_p0 = worst.p0.as_ref().map_or(f64::INFINITY, |(p, _)| *p);
        let reach = if hi_p0.is_finite() {
            hi_p0 - settings.tolerance_p0
        } else {
            MAX_ROLL_RATE
        };
        let hi_da_rad = worst
            .da
            .as_ref()
            .map_or(f64::INFINITY, |(d, _)| d.to_radians());
        let (lo, lo_da) = Leaf::minima(&leaves);
        let done_p0 = lo >= reach;
        // Without a worst case (hi), the aileron bound rides on the roll-rate walk.
        let done_da = !polys.symmetric || lo_da >= hi_da_rad - tol_da || !hi_p0.is_finite();
        progress(0.1 + 0.9 * (lo / reach).clamp(0.0, 1.0));
        if done_p0 && done_da {
            note = if lo == f64::INFINITY {
                "converged: no box's primary branch meets a jump before it leaves the aileron \
                 range"
                    .to_string()
            } else if !hi_p0.is_finite() {
                // No worst case, and some sub-box stopped at the cap unfinished.
                format!(
                    "stopped: no aircraft tried has a critical jump, and a box reached the cap \
                     of the proof, P0 = {MAX_ROLL_RATE} rad/s, without leaving the aileron range"
                )
            } else {
                "converged: both gaps within the tolerance".to_string()
            };
            break;
        }
        if leaves.len() >= settings.max_boxes {
            note = format!("stopped at the budget of {} boxes", settings.max_boxes);
            break;
        }
        if slabs >= settings.max_slabs {
            note = format!("stopped at the budget of {} slabs", settings.max_slabs);
            break;
        }
        if start.elapsed().as_secs_f64() > settings.wall_clock_guard_s {
            note = format!(
                "stopped by the wall-clock guard of {} s with {} boxes and {slabs} slabs, not \
                 by a budget of work: this answer depends on the machine's speed and load",
                settings.wall_clock_guard_s,
                leaves.len()
            );
            break;
        }
        // Work on the leaves that limit the larger relative gap: the lowest few still short
        // of it, one step each, in parallel. A fixed number of them, so that the answer does
        // not depend on the number of cores; every leaf has to reach the target anyway, so
        // taking the next-lowest ones along adds little work.
        let by_p0 = !done_p0;
        let key = |l: &Leaf| if by_p0 { l.p0_key() } else { l.da_key() };
        let target = if by_p0 { reach } else { hi_da_rad - tol_da };
        let mut batch: Vec<usize> = (0..leaves.len())
            .filter(|i| {
                let l = &leaves[*i];
                l.stuck.is_none() && !l.finished() && l.depth < MAX_ROLL_RATE
            })
            .collect();
        let lowest =
            |a: &usize, b: &usize| key(&leaves[*a]).total_cmp(&key(&leaves[*b])).then(a.cmp(b));
        if batch.len() > BATCH {
            batch.select_nth_unstable_by(BATCH - 1, lowest);
            batch.truncate(BATCH);
        }
        batch.sort_by(lowest);
        let Some(first) = batch.first().copied() else {
            note = if leaves.iter().any(|l| l.stuck.is_some()) {
                "every remaining box is stuck at a point where the proof cannot continue"
                    .to_string()
            } else {
                format!(
                    "every remaining box reached the cap of the proof, P0 = {MAX_ROLL_RATE} rad/s"
                )
            };
            break;
        };
        batch.retain(|i| *i == first || key(&leaves[*i]) < target);
        if !leaves[first].probed {
            leaves[first].probed = true;
            worst.probe(&leaves[first].theta, by_p0);
        }
        let limit = if by_p0 { hi_p0 } else { f64::INFINITY }.min(MAX_ROLL_RATE);
        let walk = Walk {
            polys: &polys,
            theta0: &theta0,
            limit,
            min_step,
            first_step,
            range,
        };
        let steps: Vec<(Leaf, Option<Leaf>)> =
            batch.par_iter().map(|i| walk.step(&leaves[*i])).collect();
        // Sub-boxes done with drop their lifted data (the targets are those this batch
        // worked to; they only go down while a worst case is known).
        let da_target = if polys.symmetric && hi_p0.is_finite() {
            hi_da_rad - tol_da
        } else {
            f64::NEG_INFINITY
        };
        let keep = |mut leaf: Leaf| {
            if leaf.retired(reach, da_target) {
                leaf.drop_lifted();
            }
            leaf
        };
        for (i, (leaf, other)) in batch.into_iter().zip(steps) {
            slabs += 1;
            leaves[i] = keep(leaf);
            if let Some(other) = other {
                leaves.push(keep(other));
                boxes += 1;
            }
        }
    }
    let (mut lo, mut lo_da) = Leaf::minima(&leaves);
    let mut note = note;
    if !polys.symmetric {
        lo_da = 0.0;
        note += "; the trim at P0 = 0 needs aileron for some aircraft of the box, so |delta_a| \
                 is not monotone from 0 along the branch and its lower bound is 0";
    }
    // A sub-box held up where its branch may turn (its latest slab failed so, stuck there or
    // not) keeps its bound: past the turn the branch comes back on its other trim, and every
    // slab below the bound has that trim certified free of jumps within the aileron range
    // (docs/clearance.md, step 6).
    if let Some(l) = leaves
        .iter()
        .filter(|l| !l.finished() && l.turned.is_none())
        .find(|l| l.stuck == Some(Failure::Turn) || l.last == Some(Failure::Turn))
    {
        note += &format!(
            "; the primary branch may turn in P0 near {:.4} rad/s for part of the box: lo also \
             bounds the jumps met after the turn, on the other trim",
            l.depth
        );
    }
    // Sub-boxes whose branch turns back in P0 (certified zones, step 6 of docs/clearance.md).
    let zones = leaves
        .iter()
        .filter_map(|l| l.turned.map(|top| (l.depth, top)))
        .fold(None, |z: Option<(f64, f64)>, (a, b)| {
            Some(z.map_or((a, b), |(lo, hi)| (lo.min(a), hi.max(b))))
        });
    if let Some((from, to)) = zones {
        let whose = if leaves.iter().all(|l| l.turned.is_some()) {
            "for every aircraft of the box"
        } else {
            "for part of the box"
        };
        note += &format!(
            "; {whose} the primary branch turns back in P0 between {from:.4} and {to:.4} rad/s \
             (proven, with no jump there) and comes back down on its other trim, whose jumps \
             within the aileron range, if any, bound lo"
        );
    }
    if let Some(d) = leaves
        .iter()
        .filter(|l| !l.finished())
        .filter_map(Leaf::doubt)
        .min_by(|a, b| a.lo.total_cmp(&b.lo))
        .filter(|d| d.lo <= lo)
    {
        note += &format!(
            "; lo is held at {:.6} rad/s by a possible jump on the other trim of the trim \
             condition (P0 in [{:.6}, {:.6}]), which a branch turning in P0 beyond its \
             certified depth could come back to",
            d.lo, d.lo, d.hi
        );
    }
    let cases: Vec<&CaseAircraft> = [&worst.p0, &worst.da]
        .into_iter()
        .filter_map(|c| c.as_ref().map(|(_, c)| c))
        .collect();
    if let Some(c) = contradiction(&leaves, &cases) {
        // Never expected: the exact path found a critical jump where the proof says there is
        // none, so an assumption of the proof (docs/clearance.md: that `analyze`'s walk follows
        // the exact curve) fails for this box, and nothing below is proven.
        lo = 0.0;
        lo_da = 0.0;
        note += &format!(
            "; INCONSISTENT: an aircraft of the box has a critical jump (exact path, P0 = {:.6} \
             rad/s) inside a sub-box the proof found free of them, so no bound is proven (lo = 0)",
            c.p0
        );
    }
    if let Some(hi) = worst.p0.as_ref().map(|(p, _)| *p) {
        lo = lo.min(hi);
    }
    if let Some(hi) = worst.da.as_ref().map(|(d, _)| d.to_radians()) {
        lo_da = lo_da.min(hi);
    }
    progress(1.0);
    Ok(finish(worst, lo, lo_da.to_degrees(), note, boxes, slabs))
}

/// The first of `cases` (aircraft the exact path found a critical jump for) that lies in a
/// finished sub-box of `leaves`, one the proof found free of critical jumps: a contradiction.
fn contradiction<'a>(leaves: &[Leaf], cases: &[&'a CaseAircraft]) -> Option<&'a CaseAircraft> {
    use num_traits::ToPrimitive;
    cases.iter().copied().find(|c| {
        let x: Vec<f64> = c
            .coordinates
            .iter()
            .map(|v| v.to_f64().unwrap_or(f64::NAN))
            .collect();
        leaves.iter().filter(|l| l.finished()).any(|l| {
            l.theta.len() == x.len()
                && l.theta
                    .iter()
                    .zip(&x)
                    .all(|(t, v)| t.lo <= *v && *v <= t.hi)
        })
    })
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;

    /// The committed `aircraft/a_uncertain.toml` (four uncertain derivatives).
    pub(crate) fn a_uncertain() -> Aircraft {
        let path =
            std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../aircraft/a_uncertain.toml");
        crate::aircraft::load(&path).expect("the committed uncertain aircraft")
    }

    /// An aircraft the exact path finds a critical jump for, inside a sub-box the proof calls
    /// free of them (here one turned without doubts), is a contradiction; outside every such
    /// sub-box, or inside an unfinished one, it is not.
    #[test]
    fn a_jump_inside_a_box_proven_free_of_jumps_is_a_contradiction() {
        let a = Aircraft::a();
        let polys = BoxPolys::new(&a, &[Param::Lp], 0.0);
        let mut finished = Leaf::new(&polys, &[I::new(-22.0, -21.0)], 0.1);
        finished.turned = Some(1.5);
        let unfinished = Leaf::new(&polys, &[I::new(-21.0, -20.0)], 0.1);
        let case = |l_p: f64| CaseAircraft {
            parameters: Default::default(),
            p0: 1.7,
            delta_a_deg: 10.0,
            aircraft: a.clone(),
            coordinates: vec![BigRational::from_float(l_p).expect("finite")],
        };
        let leaves = [finished, unfinished];
        let (inside, outside, unproven) = (case(-21.5), case(-23.0), case(-20.5));
        assert_eq!(contradiction(&leaves, &[&outside, &inside]), Some(&inside));
        assert_eq!(contradiction(&leaves, &[&outside, &unproven]), None);
    }

    /// A barrier shields only what lies below it: a doubt it cuts keeps its part above it, and
    /// one wholly below it goes.
    #[test]
    fn a_barrier_shields_only_what_lies_below_it() {
        let polys = BoxPolys::new(&Aircraft::a(), &[Param::Lp], 0.0);
        let mut leaf = Leaf::new(&polys, &[I::new(-22.0, -21.0)], 0.1);
        leaf.doubts = vec![I::new(1.0, 1.5), I::new(2.0, 2.4)];
        leaf.raise_barrier(2.375);
        assert_eq!(leaf.doubts, vec![I::new(2.375, 2.4)]);
        assert_eq!(leaf.doubt().map(|d| d.lo), Some(2.375));
        leaf.raise_barrier(2.4);
        assert!(leaf.doubts.is_empty());
    }

    /// A sub-box that dropped its lifted data (retired) and is stepped after all is lifted
    /// again from its box and its branch's side, and steps as it would have: the same depth,
    /// step, aileron bound and failure, slab after slab.
    #[test]
    fn a_retired_sub_box_stepped_again_steps_as_before() {
        let a = Aircraft::a();
        let polys = BoxPolys::new(&a, &[Param::Lp], 0.0);
        let theta0 = [I::new(-22.0, -21.0)];
        let walk = Walk {
            polys: &polys,
            theta0: &theta0,
            limit: 1.8,
            min_step: 1e-4,
            first_step: 0.05,
            range: a.aileron_range(),
        };
        let (mut kept, mut dropped) = (Leaf::new(&polys, &theta0, 0.05), None);
        for slab in 0..12 {
            let mut again = dropped.unwrap_or_else(|| kept.clone());
            again.lifted = None;
            let (k, _) = walk.step(&kept);
            let (d, _) = walk.step(&again);
            let show = |l: &Leaf| (l.depth, l.step, l.da_lo, l.last, l.theta.clone());
            assert_eq!(show(&k), show(&d), "slab {slab}");
            assert!(d.lifted.is_some(), "slab {slab}: lifted again");
            (kept, dropped) = (k, Some(d));
        }
        assert!(kept.depth > 1.0, "the walk went on: {}", kept.depth);
        // Lifted again, a part keeps the branch's side it was given (by `lift_part`, its
        // parent's), not one computed afresh: a side the fresh lift would not give it.
        let fresh = polys.lift(&theta0).side().expect("a certain side");
        let mut part = Leaf::new(&polys, &theta0, 0.05);
        part.lifted = Some(Arc::new(polys.lift_on_side(&theta0, Some(-fresh))));
        part.drop_lifted();
        assert!(part.lifted.is_none());
        assert_eq!(part.lifted(&polys).side(), Some(-fresh));
    }

    /// The branch and bound steps a fixed number of leaves at a time, so its answer (bounds,
    /// worst cases, boxes, slabs) does not depend on how many threads run them.
    #[test]
    fn the_proof_does_not_depend_on_the_threads() {
        let a = a_uncertain();
        let settings = Settings::default();
        let run = |threads: usize| {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .expect("a thread pool");
            let mut c = pool
                .install(|| clear(&a, &settings, &mut |_| {}))
                .expect("a proof");
            c.seconds = 0.0;
            c
        };
        let one = run(1);
        assert!(one.critical_p0.converged, "{one:?}");
        assert!(one.boxes > 1, "the box is split: {one:?}");
        assert_eq!(run(2), one);
        assert_eq!(run(3), one);
    }

    /// A budget of work stops the proof at the same place on every run, and says which budget
    /// it was; the wall-clock guard, when it stops a proof, says that the answer depends on
    /// the machine.
    #[test]
    fn the_budgets_are_of_work_and_the_wall_clock_guard_says_so() {
        let a = a_uncertain();
        let run = |settings: &Settings| {
            let mut c = clear(&a, settings, &mut |_| {}).expect("a proof");
            c.seconds = 0.0;
            c
        };
        let few_slabs = Settings {
            max_slabs: 3,
            ..Settings::default()
        };
        let stopped = run(&few_slabs);
        assert!(!stopped.critical_p0.converged, "{stopped:?}");
        assert_eq!(stopped.note, "stopped at the budget of 3 slabs");
        assert!(stopped.slabs >= 3 && stopped.slabs < 3 + 64, "{stopped:?}");
        assert_eq!(run(&few_slabs), stopped);
        let guarded = run(&Settings {
            wall_clock_guard_s: 0.0,
            ..Settings::default()
        });
        assert!(
            guarded.note.contains("wall-clock guard") && guarded.note.contains("depends on"),
            "{}",
            guarded.note
        );
    }
}
