//! What a continuation is asked for: the control continued, its range, the step and tolerance
//! settings, the zero-sideslip switch; the checks that refuse settings out of their domain, and
//! why a continuation cannot run.

use super::engine::Limits;
use serde::{Deserialize, Serialize};

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

    pub(super) fn index(self) -> usize {
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

/// Refuses settings out of their domain (see [`ContinuationError::Settings`]).
pub(super) fn check(settings: &Settings) -> Result<(), ContinuationError> {
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

/// The engine's limits for the settings `s` with the parameter range `[mu_lo, mu_hi]`.
pub(super) fn limits(s: &Settings, mu_lo: f64, mu_hi: f64) -> Limits {
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
