//! The plain data Figs 1-11 are drawn from (SI units: rad, rad/s). Bifurcation diagrams take
//! branches of equilibria and special points, whoever computed them: the closed-form trims of
//! [`crate::analysis::trim_curves`] or a continuation.
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

pub use crate::analysis::diagram::{
    BifurcationData, DetKData, SpecialKind, SpecialPoint, ZeroSideslipData,
};

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
