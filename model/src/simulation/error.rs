//! Why a simulation could not be run.

use super::{MAX_SAMPLES, MAX_SWEEP_RUNS};

/// Why a simulation could not be run.
#[derive(Clone, Debug, thiserror::Error, PartialEq)]
pub enum SimError {
    /// A setting is NaN or infinite.
    #[error("{name} = {value} is not a finite number")]
    NotFinite {
        /// Name of the setting.
        name: &'static str,
        /// Its value.
        value: f64,
    },
    /// End time, output spacing, ramp time, averaging window or tolerance out of range.
    #[error("{name} = {value} must be positive{extra}")]
    NotPositive {
        /// Name of the setting.
        name: &'static str,
        /// Its value.
        value: f64,
        /// Further explanation (may be empty).
        extra: &'static str,
    },
    /// A sweep would make more runs than [`MAX_SWEEP_RUNS`].
    #[error("a sweep of {0} aileron steps; at most {MAX_SWEEP_RUNS} are allowed")]
    TooManyRuns(usize),
    /// The run would produce more output samples than [`MAX_SAMPLES`].
    #[error("t_end / dt = {0} output samples; at most {MAX_SAMPLES} are allowed")]
    TooManySamples(f64),
    /// `l_delta_a = 0`: the aileron cannot hold a roll.
    #[error("l_delta_a = 0: the aileron has no roll authority")]
    NoAileronAuthority,
    /// `n_delta_r = 0`: no rudder schedule can hold zero sideslip.
    #[error("n_delta_r = 0: the rudder cannot hold zero sideslip")]
    NoRudderAuthority,
    /// No finite trim with delta_a = 0 within |P0| <= 20 rad/s.
    #[error("no trim with delta_a = 0 for delta_r = {delta_r} rad within |P0| <= 20 rad/s")]
    NoTrim {
        /// The rudder deflection of the attempted trim, rad.
        delta_r: f64,
    },
    /// The zero-sideslip branch through P0 = 0 has no finite trim.
    #[error("the zero-sideslip trim branch through P0 = 0 is not finite")]
    NoZeroSideslipTrim,
    /// The aileron deflection lies outside the zero-sideslip schedule.
    #[error(
        "delta_a = {delta_a} rad is outside the zero-sideslip rudder schedule [{lo}, {hi}] rad"
    )]
    ScheduleRange {
        /// The requested deflection, rad.
        delta_a: f64,
        /// Lower end of the schedule, rad.
        lo: f64,
        /// Upper end of the schedule, rad.
        hi: f64,
    },
    /// The settings' elevator differs from the simulator's.
    #[error(
        "settings have delta_e = {settings} rad but the simulator was built for {simulator} rad"
    )]
    ElevatorMismatch {
        /// Elevator in the settings, rad.
        settings: f64,
        /// Elevator of the simulator, rad.
        simulator: f64,
    },
    /// The integrator failed (step-size underflow, too many steps, stiffness, divergence).
    #[error("{model} integration failed at t = {t} s: {message}")]
    Integration {
        /// The model being integrated.
        model: &'static str,
        /// Time of failure, s.
        t: f64,
        /// The integrator's message.
        message: String,
    },
}
