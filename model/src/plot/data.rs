//! The plain data Figs 1-11 are drawn from (SI units: rad, rad/s). Bifurcation diagrams take
//! branches of equilibria and special points, whoever computed them: the closed-form trims of
//! [`super::closed_form`] or a continuation.
//!
//! ```
//! use model::plot::figures::bifurcation_figure;
//! use model::plot::{BifurcationData, Branch, BranchPoint, SpecialKind, SpecialPoint};
//!
//! // Two equilibria (aileron in rad) and a fold between them; the figure plots degrees.
//! let at = |param: f64, p: f64| BranchPoint {
//!     param,
//!     alpha: 0.0,
//!     beta: 0.0,
//!     p,
//!     q: 0.0,
//!     r: 0.0,
//!     stable: true,
//! };
//! let data = BifurcationData {
//!     title: "two equilibria".into(),
//!     branches: vec![Branch { points: vec![at(0.0, 0.0), at(-0.1, 2.0)] }],
//!     special: vec![SpecialPoint { kind: SpecialKind::Fold, point: at(-0.05, 1.0), label: None }],
//!     divergence_p: vec![],
//!     delta_a_range_deg: None,
//! };
//! let fig = bifurcation_figure(&data).unwrap();
//! let fold = &fig.panels[0].markers[0];
//! assert!((fold.x - (-0.05f64).to_degrees()).abs() < 1e-12 && fold.y == 1.0);
//! assert_eq!(fold.label.as_deref(), Some(SpecialKind::Fold.describe()));
//! ```

use crate::simulation::TimeHistory;
use serde::Serialize;

/// An equilibrium on a branch (the continuation's point): the parameter (aileron deflection,
/// rad), the state and its stability.
pub use crate::continuation::Point as BranchPoint;

/// A branch of equilibria, ordered along the branch (the continuation's branch).
pub use crate::continuation::Branch;

impl BranchPoint {
    /// The value of a state variable in SI units.
    pub fn get(&self, v: State) -> f64 {
        match v {
            State::Alpha => self.alpha,
            State::Beta => self.beta,
            State::P => self.p,
            State::Q => self.q,
            State::R => self.r,
        }
    }
}

/// A state variable of the PSS model.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum State {
    /// Angle of attack.
    Alpha,
    /// Sideslip.
    Beta,
    /// Roll rate.
    P,
    /// Pitch rate.
    Q,
    /// Yaw rate.
    R,
}

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

/// A variable of a time history.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum Variable {
    /// Angle of attack (plotted in deg).
    Alpha,
    /// Sideslip (deg).
    Beta,
    /// Roll rate (rad/s).
    P,
    /// Pitch rate (rad/s).
    Q,
    /// Yaw rate (rad/s).
    R,
    /// Bank angle (deg; 7th-order model only).
    Phi,
    /// Pitch attitude (deg; 7th-order model only).
    Theta,
    /// Aileron (deg).
    DeltaA,
    /// Rudder (deg).
    DeltaR,
}

impl Variable {
    /// Axis label with unit.
    pub fn label(self) -> &'static str {
        match self {
            Variable::Alpha => "angle of attack \u{3b1} (deg)",
            Variable::Beta => "sideslip \u{3b2} (deg)",
            Variable::P => "roll rate p (rad/s)",
            Variable::Q => "pitch rate q (rad/s)",
            Variable::R => "yaw rate r (rad/s)",
            Variable::Phi => "bank angle \u{3c6} (deg)",
            Variable::Theta => "pitch attitude \u{3b8} (deg)",
            Variable::DeltaA => "aileron \u{3b4}a (deg)",
            Variable::DeltaR => "rudder \u{3b4}r (deg)",
        }
    }

    /// The samples in plot units (angles in deg, rates in rad/s).
    pub fn series(self, h: &TimeHistory) -> Vec<f64> {
        let deg = |v: &[f64]| v.iter().map(|x| x.to_degrees()).collect();
        match self {
            Variable::Alpha => deg(&h.alpha),
            Variable::Beta => deg(&h.beta),
            Variable::P => h.p.clone(),
            Variable::Q => h.q.clone(),
            Variable::R => h.r.clone(),
            Variable::Phi => deg(&h.phi),
            Variable::Theta => deg(&h.theta),
            Variable::DeltaA => deg(&h.delta_a),
            Variable::DeltaR => deg(&h.delta_r),
        }
    }
}

/// Time histories of a family of runs (Figs 5, 6, 10): one panel per variable, one line per
/// run; `overlay` runs (e.g. the PSS model) are drawn dashed in the colour of the run with the
/// same index.
#[derive(Clone, Debug, PartialEq)]
pub struct TimeHistoryData<'a> {
    /// Figure title.
    pub title: String,
    /// Runs, drawn solid, one colour each (ordered, e.g. by aileron).
    pub runs: &'a [TimeHistory],
    /// Runs drawn dashed in the colours of `runs` (may be empty).
    pub overlay: &'a [TimeHistory],
    /// Variables, one panel each, top to bottom.
    pub variables: Vec<Variable>,
}
