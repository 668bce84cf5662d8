//! What defines one run: the model, the aileron and rudder inputs, the integrator's tolerances,
//! the end time and output spacing, and the checks that refuse settings out of range.

use super::SimError;
use serde::Serialize;

/// Which model to integrate.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
pub enum Model {
    /// The 7th-order model of Appendix A.1: PSS plus the g/V terms and the attitude.
    SeventhOrder,
    /// The 5th-order pseudo-steady-state model of Appendix A.2.
    Pss,
}

impl Model {
    /// Short name for labels and file names: `7th-order` or `PSS`.
    pub fn name(self) -> &'static str {
        match self {
            Model::SeventhOrder => "7th-order",
            Model::Pss => "PSS",
        }
    }
}

/// The aileron input, starting at t = 0 from the trim at delta_a = 0.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub enum Aileron {
    /// A step to `delta_a` (rad) at t = 0.
    Step {
        /// Final deflection, rad.
        delta_a: f64,
    },
    /// A linear ramp from 0 at t = 0 to `delta_a` (rad) at t = `duration` (s), then held.
    Ramp {
        /// Final deflection, rad.
        delta_a: f64,
        /// Ramp time, s (> 0).
        duration: f64,
    },
}

impl Aileron {
    /// The deflection at time `t` (rad).
    pub fn at(&self, t: f64) -> f64 {
        match *self {
            Aileron::Step { delta_a } => delta_a,
            Aileron::Ramp { delta_a, duration } => delta_a * (t / duration).clamp(0.0, 1.0),
        }
    }

    /// The final deflection (rad).
    pub fn final_value(&self) -> f64 {
        match *self {
            Aileron::Step { delta_a } | Aileron::Ramp { delta_a, .. } => delta_a,
        }
    }
}

/// The rudder during a run.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub enum Rudder {
    /// Held at this deflection (rad) throughout, including the initial trim.
    Fixed(f64),
    /// Follows the zero-sideslip schedule delta_r(delta_a) of [`RudderSchedule`](super::RudderSchedule) (the
    /// aileron-rudder interconnect of Fig. 9, section V).
    ZeroSideslip,
}

/// Error tolerances of the adaptive integrator (Dopri5's mixed error test
/// `|err_i| <= atol + rtol max(|y_i|, |y_new_i|)`, RMS over the components).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Tolerances {
    /// Relative tolerance.
    pub rtol: f64,
    /// Absolute tolerance (rad, rad/s).
    pub atol: f64,
}

impl Default for Tolerances {
    /// rtol = 1e-8, atol = 1e-10.
    fn default() -> Self {
        Tolerances {
            rtol: 1e-8,
            atol: 1e-10,
        }
    }
}

/// Everything that defines one simulation run (angles in rad, times in s).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct SimSettings {
    /// Model to integrate.
    pub model: Model,
    /// Elevator deflection, rad (fixed).
    pub delta_e: f64,
    /// Aileron input.
    pub aileron: Aileron,
    /// Rudder: fixed or scheduled.
    pub rudder: Rudder,
    /// End time, s.
    pub t_end: f64,
    /// Output spacing, s.
    pub dt: f64,
    /// Integrator tolerances.
    pub tolerances: Tolerances,
}

impl SimSettings {
    /// Default end time of a run, s (the paper's time histories span about 20 s).
    pub const T_END: f64 = 20.0;
    /// Default output spacing, s.
    pub const DT: f64 = 0.02;

    /// An aileron step `delta_a` (rad) at elevator `delta_e` (rad), rudder fixed at 0, 20 s,
    /// output every 0.02 s, default tolerances.
    pub fn step(model: Model, delta_e: f64, delta_a: f64) -> SimSettings {
        SimSettings {
            model,
            delta_e,
            aileron: Aileron::Step { delta_a },
            rudder: Rudder::Fixed(0.0),
            t_end: Self::T_END,
            dt: Self::DT,
            tolerances: Tolerances::default(),
        }
    }
}

/// Most aileron steps of one sweep (each a run of 20 s by default): a sweep asked to go further
/// is refused rather than left running for hours.
pub const MAX_SWEEP_RUNS: usize = 10_000;

/// Largest number of output samples of one run.
pub const MAX_SAMPLES: usize = 10_000_000;

/// Refuses settings that are not finite, not positive where they must be, or that would produce
/// more than [`MAX_SAMPLES`] output samples.
pub(super) fn validate(s: &SimSettings) -> Result<(), SimError> {
    let finite = |name: &'static str, value: f64| {
        if value.is_finite() {
            Ok(())
        } else {
            Err(SimError::NotFinite { name, value })
        }
    };
    let positive = |name: &'static str, value: f64| {
        finite(name, value)?;
        if value > 0.0 {
            Ok(())
        } else {
            Err(SimError::NotPositive {
                name,
                value,
                extra: "",
            })
        }
    };
    finite("delta_e", s.delta_e)?;
    finite("delta_a", s.aileron.final_value())?;
    if let Aileron::Ramp { duration, .. } = s.aileron {
        positive("ramp duration", duration)?;
    }
    if let Rudder::Fixed(v) = s.rudder {
        finite("delta_r", v)?;
    }
    positive("t_end", s.t_end)?;
    positive("dt", s.dt)?;
    positive("rtol", s.tolerances.rtol)?;
    positive("atol", s.tolerances.atol)?;
    let samples = s.t_end / s.dt;
    if samples > MAX_SAMPLES as f64 {
        return Err(SimError::TooManySamples(samples));
    }
    Ok(())
}
