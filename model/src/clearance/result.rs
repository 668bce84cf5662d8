//! What a clearance run answers: the certified bounds on the two minima over the box (the
//! critical jump roll rate and |delta_a| at it), the aircraft of the box that attain them, and
//! why a clearance could not be computed.

use crate::aircraft::Aircraft;
use crate::analysis::AnalysisError;
use num_rational::BigRational;
use serde::Serialize;

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

/// The result of [`super::clear`].
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
    /// Which way the clearance against the aileron limit went (null without a limit): a
    /// verdict the tolerance leaves undecided is tightened past it until decided or the budget
    /// runs out.
    pub verdict: Option<super::Verdict>,
    /// Why: the proven bound above the limit, the counterexample within it, or how far the
    /// tightening got and what stopped it.
    pub verdict_reason: String,
    /// The gap left on each side of the limit when undecided (null otherwise).
    pub gap_to_limit: Option<super::LimitGap>,
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
