//! Time histories of the 7th-order model (Appendix A.1) and of the PSS model (Appendix A.2)
//! from a trimmed start: the simulations of section III (Figs 5 and 6, roll rate for a family of
//! aileron steps) and section V.C (Fig. 10, sideslip with the zero-sideslip rudder schedule), and
//! the jump detection that compares them with the criterion's folds (Figs 1, 2, 7, 8).
//!
//! * The PSS right-hand side is the compiled [`PssModel`](crate::pss_model::PssModel); the
//!   7th-order model adds the gravity terms of [`crate::equations::gravity_and_attitude`] to the
//!   alpha and beta equations.
//! * Attitude: the phi/theta equations of A.1 are singular at theta = +-90 deg, which the PSS
//!   trim's steady pitch rate (Q0 = -0.18 rad/s for aircraft A at delta_e = 2 deg) reaches within
//!   seconds when the roll rate is small. We integrate the same kinematics as the direction of
//!   gravity in body axes, `gamma = (-sin theta, cos theta sin phi, cos theta cos phi)`,
//!   `d gamma/dt = gamma x omega`, which has no singularity, and recover phi (unwrapped) and
//!   theta from it for the gravity terms and the output. Where the Euler angles are defined this
//!   is identical to A.1 (checked against `gravity_and_attitude` by a unit test).
//! * Start: the closed-form trim with delta_a = 0 ([`Trims::trim_at_zero_aileron`]), with the
//!   given elevator and the rudder of the run; the 7th-order model starts wings level, phi =
//!   theta = 0. For an aircraft whose file gives its trim (an import), the 7th-order model
//!   starts instead on its own steady path with gravity, wings level and the path horizontal
//!   ([`flight_start`]): at 1 g that is the trimmed level flight itself. The aileron is a step at t = 0 or a ramp from t = 0.
//! * Integrator: ode_solvers' Dopri5 (explicit Runge-Kutta 5(4), Dormand-Prince) with its
//!   continuous (4th-order dense) output, sampled every `dt`; default tolerances
//!   rtol = 1e-8, atol = 1e-10 ([`Tolerances::default`]). Ramps are integrated in two segments so
//!   that no step straddles the kink.
//!
//! Sign convention (ours and the paper's): `l_delta_a < 0`, so a negative aileron deflection
//! rolls the aircraft with positive roll rate; the paper's jumps (Figs 5, 6) and the sideslip
//! build-up (Fig. 10) are at negative delta_a with positive p.
//!
//! ```
//! use model::aircraft::Aircraft;
//! use model::simulation::{simulate, Model, SimSettings};
//!
//! // Aircraft A, PSS model, an aileron step of -2 deg (short of its first fold, Fig. 5).
//! let settings = SimSettings::step(Model::Pss, 2f64.to_radians(), -2f64.to_radians());
//! let run = simulate(&Aircraft::a(), &settings).unwrap();
//! assert_eq!(run.t.len(), 1001); // every 0.02 s over the default 20 s
//! // The roll rate settles at a positive value (negative aileron rolls to positive p) through
//! // a decaying pitch-yaw oscillation: narrower over the last second than the last ten.
//! let (last, before) = (run.steady(1.0), run.steady(10.0));
//! assert!(last.p_mean > 0.0);
//! assert!(last.p_max - last.p_min < 0.5 * (before.p_max - before.p_min), "{last:?}");
//! ```

// The model's files: what defines a run (`settings.rs`), why one fails (`error.rs`), its result
// (`history.rs`), the simulator that runs it (`simulator.rs`) through the right-hand sides and
// the integrator (`integrate.rs`, `attitude.rs`), the trims and rudder schedule (`trim.rs`),
// threads (`parallel.rs`) and the jump sweep (`sweep.rs`).
mod attitude;
mod error;
mod flight_start;
mod history;
mod integrate;
mod parallel;
mod settings;
mod simulator;
mod sweep;
mod trim;

pub use error::SimError;
pub use flight_start::flight_start;
pub use history::{RunStats, Steady, TimeHistory};
pub(crate) use parallel::parallel_map;
pub use parallel::THREADS;
use settings::validate;
pub use settings::{Aileron, Model, Rudder, SimSettings, Tolerances, MAX_SAMPLES, MAX_SWEEP_RUNS};
pub use simulator::{simulate, Simulator};
pub use sweep::{jump_sweep, jump_sweep_with_progress, Jump, Sweep, SweepPoint, SweepSettings};
pub(crate) use trim::bisect;
pub use trim::{Equilibrium, RudderSchedule, Trims};
