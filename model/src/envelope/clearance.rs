//! The certified clearance of one grid point (`envelope --uncertainty`): [`crate::clearance::clear`]
//! of the imported aircraft with its `[uncertainty]` box at the point's elevator increment, as
//! `model clear` runs it but for the work per point (no Monte Carlo, [`CANDIDATES`] random
//! candidates instead of 64, and budgets of [`MAX_BOXES`] boxes and [`MAX_SLABS`] slabs instead
//! of 20,000 and 500,000: every exact analysis of an imported jet with aileron yaw costs tenths
//! of a second, a box of all 15 coefficients can keep the proof busy for minutes, and the points
//! are many). `lo` stays proven whatever the candidates and budgets: fewer candidates can only
//! leave `hi` higher and the proof more work, and a budget that runs out leaves the gap wider
//! and, when the limit lies inside it, the verdict undecided (`undecided_budget`, with the gap
//! reached), never wrong.

use crate::aircraft::Aircraft;
use crate::clearance::{clear, ClearError, LimitGap, Settings, Verdict};
use serde::Serialize;

/// The random candidates for the worst case tried at each point (besides the box's centre and
/// the greedy vertex search).
pub const CANDIDATES: usize = 4;

/// The most boxes the branch and bound of one point may hold.
pub const MAX_BOXES: usize = 2_000;

/// The most slabs the branch and bound of one point may certify.
pub const MAX_SLABS: usize = 10_000;

/// The clearance settings of a point at the elevator increment `delta_e_rad`: `model clear`'s
/// tolerances, [`CANDIDATES`] random candidates and the budgets [`MAX_BOXES`], [`MAX_SLABS`].
pub fn settings(delta_e_rad: f64) -> Settings {
    Settings {
        delta_e_rad,
        candidates: CANDIDATES,
        max_boxes: MAX_BOXES,
        max_slabs: MAX_SLABS,
        ..Settings::default()
    }
}

/// What a grid point reports of its clearance.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct PointClearance {
    /// The box's coordinates of nonzero width.
    pub uncertain: usize,
    /// Proven lower bound of the critical jump roll rate over the box, rad/s; null when no
    /// aircraft of the box has a critical jump (proven).
    pub p0_lo: Option<f64>,
    /// The lowest critical jump roll rate found (an aircraft of the box attains it), rad/s.
    pub p0_hi: Option<f64>,
    /// Proven lower bound of |delta_a| at the critical jump over the box, deg; null when no
    /// aircraft of the box has a critical jump (proven).
    pub delta_a_lo_deg: Option<f64>,
    /// The lowest |delta_a| at a critical jump found, deg.
    pub delta_a_hi_deg: Option<f64>,
    /// Proven: no aircraft of the box has a critical jump.
    pub no_critical_jump: bool,
    /// `cleared`, `not_cleared`, `undecided_budget` or `undecided` against the aileron limit
    /// (null without a limit).
    pub verdict: Option<Verdict>,
    /// Why: the proven bound above the limit, the counterexample within it, or the gap reached.
    pub verdict_reason: String,
    /// The counterexample's critical aileron (signed, deg) when not cleared.
    pub counterexample_delta_a_deg: Option<f64>,
    /// The gap left on each side of the limit when undecided.
    pub gap_to_limit: Option<LimitGap>,
    /// Why the branch and bound stopped.
    pub note: String,
}

/// The clearance of `aircraft`'s box at `delta_e_rad`.
pub fn clear_point(aircraft: &Aircraft, delta_e_rad: f64) -> Result<PointClearance, ClearError> {
    let c = clear(aircraft, &settings(delta_e_rad), &mut |_| {})?;
    let finite = |x: f64| Some(x).filter(|v| v.is_finite());
    Ok(PointClearance {
        uncertain: c.box_.len(),
        p0_lo: finite(c.critical_p0.lo),
        p0_hi: c.critical_p0.hi,
        delta_a_lo_deg: finite(c.critical_delta_a_deg.lo),
        delta_a_hi_deg: c.critical_delta_a_deg.hi,
        no_critical_jump: c.no_critical_jump,
        verdict: c.verdict,
        verdict_reason: c.verdict_reason,
        counterexample_delta_a_deg: c.counterexample.map(|x| x.delta_a_deg),
        gap_to_limit: c.gap_to_limit,
        note: c.note,
    })
}
