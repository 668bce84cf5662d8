//! What the closed-form trims of [`super::trim_curves`] or a continuation give a figure: the
//! bifurcation diagrams versus aileron deflection (Figs 1-4, 9) with their special points (folds,
//! Hopf and transcritical points), the det K curves versus trim roll rate (Figs 7, 8, 11), and
//! why a diagram could not be computed. SI units throughout (rad, rad/s); `plot` draws them.

use crate::analysis::AnalysisError;
use crate::continuation::{Branch, Point as BranchPoint};
use crate::simulation::SimError;
use serde::Serialize;

/// Kind of a special point.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum SpecialKind {
    /// Saddle-node (fold, turning point): det K = 0, the jump points (Figs 1, 2).
    Fold,
    /// Hopf bifurcation (filled squares of Fig. 2), as a continuation or an eigenvalue scan
    /// locates it.
    Hopf,
    /// Hopf point of the closed form (beyond the paper, [`crate::analysis::HopfPoint`]: the
    /// Hopf polynomial `det(A)^10 Delta4` vanishes with `omega^2 > 0`).
    HopfClosedForm,
    /// Transcritical bifurcation (empty square of Fig. 9): departure from zero sideslip.
    Transcritical,
}

impl SpecialKind {
    /// Legend text.
    pub fn describe(self) -> &'static str {
        match self {
            SpecialKind::Fold => "saddle-node (det K = 0)",
            SpecialKind::Hopf => "Hopf bifurcation",
            SpecialKind::HopfClosedForm => "closed-form Hopf point (\u{394}\u{2084} = 0)",
            SpecialKind::Transcritical => "transcritical (det K = 0)",
        }
    }
}

/// A special point on a branch. State components may be NaN when unknown (the point is then
/// not marked in the panels of those variables).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct SpecialPoint {
    /// Kind.
    pub kind: SpecialKind,
    /// The equilibrium (its `stable` flag is ignored).
    pub point: BranchPoint,
    /// Short text drawn next to the marker (e.g. the paper's a, b, c, d).
    pub label: Option<String>,
}

/// A bifurcation diagram versus aileron deflection (Figs 1-4, 9).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct BifurcationData {
    /// Figure title.
    pub title: String,
    /// Branches of equilibria.
    pub branches: Vec<Branch>,
    /// Special points.
    pub special: Vec<SpecialPoint>,
    /// Roll rates (rad/s) drawn as horizontal reference lines: the divergence roll rates of
    /// Eq. 5 (det A = 0, trims blow up), both signs.
    pub divergence_p: Vec<f64>,
    /// Aileron range to show, deg (`None`: from the special points).
    pub delta_a_range_deg: Option<(f64, f64)>,
}

/// det K versus trim roll rate P0 (Figs 7, 8, 11).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct DetKData {
    /// Figure title.
    pub title: String,
    /// Trim roll rates, rad/s, ascending.
    pub p0: Vec<f64>,
    /// det K at each P0, 1/s^4 (infinite or NaN at a pole).
    pub det_k: Vec<f64>,
    /// Roots of det K (jump or departure points), rad/s.
    pub roots: Vec<f64>,
    /// Poles of det K (the "discontinuities" of Fig. 8), rad/s.
    pub poles: Vec<f64>,
    /// Divergence roll rates (det A = 0, Eq. 5), rad/s, drawn as reference lines.
    pub divergence: Vec<f64>,
}

/// The zero-sideslip diagram of Fig. 9: the rudder schedule and the equilibria with it.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ZeroSideslipData {
    /// The aileron-rudder interconnect: (delta_a, delta_r) pairs, rad, ascending in delta_a.
    pub schedule: Vec<(f64, f64)>,
    /// Equilibria of the PSS model with the rudder on the schedule.
    pub diagram: BifurcationData,
}

/// Why a closed-form diagram could not be computed.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum DiagramError {
    /// The closed-form analysis failed.
    #[error(transparent)]
    Analysis(AnalysisError),
    /// The closed-form trims or the rudder schedule failed.
    #[error(transparent)]
    Simulation(SimError),
}
