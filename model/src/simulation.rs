//! Time histories of the 7th-order model (Appendix A.1) and of the PSS model (Appendix A.2)
//! from a trimmed start: the simulations of section III (Figs 5 and 6, roll rate for a family of
//! aileron steps) and section V.C (Fig. 10, sideslip with the zero-sideslip rudder schedule), and
//! the jump detection that compares them with the criterion's folds (Figs 1, 2, 7, 8).
//!
//! * The PSS right-hand side is the compiled [`PssModel`]; the 7th-order model adds the gravity
//!   terms of [`crate::equations::gravity_and_attitude`] to the alpha and beta equations.
//! * Attitude: the phi/theta equations of A.1 are singular at theta = +-90 deg, which the PSS
//!   trim's steady pitch rate (Q0 = -0.18 rad/s for aircraft A at delta_e = 2 deg) reaches within
//!   seconds when the roll rate is small. We integrate the same kinematics as the direction of
//!   gravity in body axes, `gamma = (-sin theta, cos theta sin phi, cos theta cos phi)`,
//!   `d gamma/dt = gamma x omega`, which has no singularity, and recover phi (unwrapped) and
//!   theta from it for the gravity terms and the output. Where the Euler angles are defined this
//!   is identical to A.1 (checked against `gravity_and_attitude` by a unit test).
//! * Start: the closed-form trim with delta_a = 0 ([`Trims::trim_at_zero_aileron`]), with the
//!   given elevator and the rudder of the run; the 7th-order model starts wings level, phi =
//!   theta = 0. The aileron is a step at t = 0 or a ramp from t = 0.
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

mod sweep;
mod trim;

pub use sweep::{jump_sweep, jump_sweep_with_progress, Jump, Sweep, SweepPoint, SweepSettings};
pub(crate) use trim::bisect;
pub use trim::{Equilibrium, RudderSchedule, Trims};

use crate::aircraft::Aircraft;
use crate::equations::gravity_and_attitude;
use crate::pss_model::{Controls, PssModel};
use ode_solvers::continuous_output_model::ContinuousOutputModel;
use ode_solvers::{Dopri5, SVector, System};
use serde::Serialize;
use std::fmt::Write as _;

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
    /// Follows the zero-sideslip schedule delta_r(delta_a) of [`RudderSchedule`] (the
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

/// Most aileron steps of one sweep (each a run of 20 s by default): a sweep asked to go further
/// is refused rather than left running for hours.
pub const MAX_SWEEP_RUNS: usize = 10_000;

/// Largest number of output samples of one run.
pub const MAX_SAMPLES: usize = 10_000_000;

/// Integrator statistics of one run.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
pub struct RunStats {
    /// Right-hand-side evaluations.
    pub evaluations: u32,
    /// Accepted steps.
    pub accepted: u32,
    /// Rejected steps.
    pub rejected: u32,
}

/// A simulated time history, sampled every `dt` from t = 0 (angles in rad, rates in rad/s).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct TimeHistory {
    /// The settings of the run.
    pub settings: SimSettings,
    /// The trim the run starts from.
    pub start: [f64; 5],
    /// Time, s.
    pub t: Vec<f64>,
    /// Angle of attack, rad.
    pub alpha: Vec<f64>,
    /// Sideslip, rad.
    pub beta: Vec<f64>,
    /// Roll rate, rad/s.
    pub p: Vec<f64>,
    /// Pitch rate, rad/s.
    pub q: Vec<f64>,
    /// Yaw rate, rad/s.
    pub r: Vec<f64>,
    /// Bank angle phi, rad, unwrapped (7th-order model only; empty for the PSS model, which has
    /// no attitude).
    pub phi: Vec<f64>,
    /// Pitch attitude theta, rad, in [-pi/2, pi/2] (7th-order model only; empty for PSS).
    pub theta: Vec<f64>,
    /// Aileron deflection, rad.
    pub delta_a: Vec<f64>,
    /// Rudder deflection, rad.
    pub delta_r: Vec<f64>,
    /// Integrator statistics.
    pub stats: RunStats,
}

/// End-of-run (steady) values of a time history over its last `window` seconds.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Steady {
    /// Mean roll rate, rad/s.
    pub p_mean: f64,
    /// Smallest roll rate in the window, rad/s.
    pub p_min: f64,
    /// Largest roll rate in the window, rad/s.
    pub p_max: f64,
    /// Mean sideslip, rad.
    pub beta_mean: f64,
    /// Largest |sideslip| in the window, rad.
    pub beta_max_abs: f64,
    /// Largest |sideslip| over the whole run, rad.
    pub beta_peak_abs: f64,
}

impl TimeHistory {
    /// The history as CSV: a header line, then one line per sample (shortest round-trip
    /// decimals). Columns `t_s, alpha_rad, beta_rad, p_rad_s, q_rad_s, r_rad_s, [phi_rad,
    /// theta_rad,] delta_a_rad, delta_r_rad`; phi and theta only for the 7th-order model.
    pub fn to_csv(&self) -> String {
        let attitude = !self.phi.is_empty();
        let mut s = String::from("t_s,alpha_rad,beta_rad,p_rad_s,q_rad_s,r_rad_s,");
        if attitude {
            s += "phi_rad,theta_rad,";
        }
        s += "delta_a_rad,delta_r_rad\n";
        for i in 0..self.t.len() {
            let _ = write!(
                s,
                "{},{},{},{},{},{},",
                self.t[i], self.alpha[i], self.beta[i], self.p[i], self.q[i], self.r[i]
            );
            if attitude {
                let _ = write!(s, "{},{},", self.phi[i], self.theta[i]);
            }
            let _ = writeln!(s, "{},{}", self.delta_a[i], self.delta_r[i]);
        }
        s
    }

    /// Steady values over the last `window` seconds (the whole run if it is shorter).
    pub fn steady(&self, window: f64) -> Steady {
        let t_end = self.t.last().copied().unwrap_or(0.0);
        let from = self
            .t
            .partition_point(|t| *t < t_end - window)
            .min(self.t.len().saturating_sub(1));
        let p = &self.p[from..];
        let b = &self.beta[from..];
        let n = p.len().max(1) as f64;
        Steady {
            p_mean: p.iter().sum::<f64>() / n,
            p_min: p.iter().copied().fold(f64::INFINITY, f64::min),
            p_max: p.iter().copied().fold(f64::NEG_INFINITY, f64::max),
            beta_mean: b.iter().sum::<f64>() / n,
            beta_max_abs: b.iter().fold(0.0, |m, v| m.max(v.abs())),
            beta_peak_abs: self.beta.iter().fold(0.0, |m, v| m.max(v.abs())),
        }
    }
}

/// A simulator for one aircraft and elevator setting: the compiled model, the closed-form trims
/// and the zero-sideslip rudder schedule, built once and shared by many runs.
#[derive(Clone, Debug)]
pub struct Simulator {
    trims: Trims,
    schedule: Result<RudderSchedule, SimError>,
    speed: f64,
    /// |delta_r| limit of the aircraft's `[limits]`, rad: the schedule saturates there.
    rudder_limit: Option<f64>,
}

impl Simulator {
    /// Builds the simulator for `aircraft` at elevator `delta_e` (rad).
    pub fn new(aircraft: &Aircraft, delta_e: f64) -> Result<Simulator, SimError> {
        if !(aircraft.speed.is_finite() && aircraft.speed > 0.0) {
            return Err(SimError::NotPositive {
                name: "speed",
                value: aircraft.speed,
                extra: " (m/s, for the g/V terms)",
            });
        }
        let trims = Trims::new(aircraft, delta_e)?;
        let schedule = RudderSchedule::new(trims.clone());
        Ok(Simulator {
            trims,
            schedule,
            speed: aircraft.speed,
            rudder_limit: aircraft.limits.rudder_deg.map(f64::to_radians),
        })
    }

    /// The closed-form trims.
    pub fn trims(&self) -> &Trims {
        &self.trims
    }

    /// The zero-sideslip rudder schedule (an error if the aircraft has none).
    pub fn schedule(&self) -> Result<&RudderSchedule, SimError> {
        self.schedule.as_ref().map_err(Clone::clone)
    }

    /// The rudder deflection of `rudder` at aileron `delta_a` (rad). The zero-sideslip schedule
    /// saturates at the aircraft's rudder limit: beyond it the rudder stays at the limit and
    /// the sideslip is no longer held at zero.
    pub fn rudder_at(&self, rudder: Rudder, delta_a: f64) -> Result<f64, SimError> {
        match rudder {
            Rudder::Fixed(v) => Ok(v),
            Rudder::ZeroSideslip => {
                let dr = self.schedule()?.delta_r(delta_a)?;
                Ok(self.rudder_limit.map_or(dr, |l| dr.clamp(-l, l)))
            }
        }
    }

    /// Where the zero-sideslip schedule reaches the rudder limit: for each aileron direction
    /// (negative first), the aileron deflection (rad) nearest zero at which |delta_r| reaches
    /// the limit, by bisection on the schedule; `None` for a direction where the schedule stays
    /// inside the limit (or when there is no limit or no schedule).
    pub fn rudder_saturation(&self) -> [Option<f64>; 2] {
        let (Some(limit), Ok(schedule)) = (self.rudder_limit, self.schedule()) else {
            return [None, None];
        };
        let over = |da: f64| schedule.delta_r(da).map_or(f64::NAN, |dr| dr.abs() - limit);
        let (lo, hi) = schedule.range();
        let side = |end: f64| -> Option<f64> {
            // March from 0 to the end of the schedule; the first crossing, refined.
            const STEPS: usize = 400;
            let mut prev = 0.0;
            for k in 1..=STEPS {
                let da = end * k as f64 / STEPS as f64;
                if over(da) >= 0.0 {
                    let (mut a, mut b) = (prev, da);
                    for _ in 0..60 {
                        let m = 0.5 * (a + b);
                        if over(m) >= 0.0 {
                            b = m;
                        } else {
                            a = m;
                        }
                    }
                    return Some(b);
                }
                prev = da;
            }
            None
        };
        [side(lo), side(hi)]
    }

    /// Runs one simulation.
    pub fn run(&self, s: &SimSettings) -> Result<TimeHistory, SimError> {
        validate(s)?;
        if s.delta_e != self.trims.delta_e() {
            return Err(SimError::ElevatorMismatch {
                settings: s.delta_e,
                simulator: self.trims.delta_e(),
            });
        }
        let delta_r0 = self.rudder_at(s.rudder, 0.0)?;
        let start = self.trims.trim_at_zero_aileron(delta_r0)?;
        let inputs = Inputs::new(self, s.aileron, s.rudder)?;
        // Output grid t_k = k dt; the last sample is t_end itself.
        let n = (s.t_end / s.dt).floor() as usize;
        let mut t: Vec<f64> = (0..=n).map(|k| k as f64 * s.dt).collect();
        if t.last().is_some_and(|l| s.t_end - l > 1e-9 * s.dt) {
            t.push(s.t_end);
        }
        let breaks: Vec<f64> = match s.aileron {
            Aileron::Ramp { duration, .. } if duration < s.t_end => vec![0.0, duration, s.t_end],
            _ => vec![0.0, s.t_end],
        };
        let model = self.trims.model();
        let (cols, stats) = match s.model {
            Model::Pss => {
                let sys = || PssSystem {
                    model,
                    inputs: &inputs,
                };
                let y0 = SVector::<f64, 5>::from(start.x);
                let (y, stats) = integrate(sys, y0, &breaks, &t, &s.tolerances, s.model)?;
                (columns(&y), stats)
            }
            Model::SeventhOrder => {
                let sys = || FullSystem {
                    model,
                    inputs: &inputs,
                    speed: self.speed,
                };
                let mut y0 = SVector::<f64, 8>::zeros();
                y0.fixed_rows_mut::<5>(0).copy_from_slice(&start.x);
                y0[7] = 1.0; // gravity along body z: phi = theta = 0
                let (y, stats) = integrate(sys, y0, &breaks, &t, &s.tolerances, s.model)?;
                (columns(&y), stats)
            }
        };
        let mut cols = cols.into_iter();
        let mut next = || cols.next().unwrap_or_default();
        let (alpha, beta, p, q, r) = (next(), next(), next(), next(), next());
        let (mut phi, mut theta) = (Vec::new(), Vec::new());
        if s.model == Model::SeventhOrder {
            let (gx, gy, gz) = (next(), next(), next());
            for k in 0..gx.len() {
                let (ph, th) = euler(&[gx[k], gy[k], gz[k]]);
                phi.push(phi.last().map_or(ph, |prev| unwrap_angle(*prev, ph)));
                theta.push(th);
            }
        }
        let mut delta_a = Vec::with_capacity(t.len());
        let mut delta_r = Vec::with_capacity(t.len());
        for &tk in &t {
            let u = inputs.controls(tk);
            delta_a.push(u.delta_a);
            delta_r.push(u.delta_r);
        }
        Ok(TimeHistory {
            settings: *s,
            start: start.x,
            alpha,
            beta,
            p,
            q,
            r,
            t,
            phi,
            theta,
            delta_a,
            delta_r,
            stats,
        })
    }

    /// Runs aileron steps of `delta_a` (rad, one run each) with the other settings of `base`,
    /// on up to two threads; results in the order of `delta_a`.
    pub fn step_family(
        &self,
        base: &SimSettings,
        delta_a: &[f64],
    ) -> Result<Vec<TimeHistory>, SimError> {
        let runs: Vec<SimSettings> = delta_a
            .iter()
            .map(|&d| SimSettings {
                aileron: Aileron::Step { delta_a: d },
                ..*base
            })
            .collect();
        self.run_all(&runs)
    }

    /// Runs all `settings`, on up to two threads; results in input order.
    pub fn run_all(&self, settings: &[SimSettings]) -> Result<Vec<TimeHistory>, SimError> {
        self.run_all_with_progress(settings, &|_| {})
    }

    /// As [`Simulator::run_all`], calling `progress(done)` after each finished run (from the
    /// worker threads; for a progress bar).
    pub fn run_all_with_progress(
        &self,
        settings: &[SimSettings],
        progress: &(dyn Fn(usize) + Sync),
    ) -> Result<Vec<TimeHistory>, SimError> {
        parallel_map(settings, |s| self.run(s), progress)
            .into_iter()
            .collect()
    }
}

/// Runs `f` on every item on up to [`THREADS`] scoped threads, calling `progress(done)` after
/// each item; results in input order.
pub(crate) fn parallel_map<T: Sync, R: Send>(
    items: &[T],
    f: impl Fn(&T) -> R + Sync,
    progress: &(dyn Fn(usize) + Sync),
) -> Vec<R> {
    use std::sync::atomic::{AtomicUsize, Ordering};
    let done = AtomicUsize::new(0);
    let step = |x: &T| {
        let r = f(x);
        progress(done.fetch_add(1, Ordering::Relaxed) + 1);
        r
    };
    let threads = THREADS.min(items.len()).max(1);
    if threads == 1 {
        return items.iter().map(step).collect();
    }
    let step = &step;
    let mut out: Vec<Option<R>> = (0..items.len()).map(|_| None).collect();
    std::thread::scope(|scope| {
        let handles: Vec<_> = (0..threads)
            .map(|k| {
                scope.spawn(move || {
                    items
                        .iter()
                        .enumerate()
                        .skip(k)
                        .step_by(threads)
                        .map(|(i, x)| (i, step(x)))
                        .collect::<Vec<(usize, R)>>()
                })
            })
            .collect();
        for h in handles {
            // A panicking worker re-panics here (there is no panic in the simulation code).
            let part = match h.join() {
                Ok(part) => part,
                Err(e) => std::panic::resume_unwind(e),
            };
            for (i, r) in part {
                out[i] = Some(r);
            }
        }
    });
    out.into_iter().flatten().collect()
}

/// Worker threads for families and sweeps (the target machine has two cores).
pub const THREADS: usize = 2;

/// Runs one simulation (builds a [`Simulator`] for it; use a simulator directly for many runs).
pub fn simulate(aircraft: &Aircraft, settings: &SimSettings) -> Result<TimeHistory, SimError> {
    Simulator::new(aircraft, settings.delta_e)?.run(settings)
}

fn validate(s: &SimSettings) -> Result<(), SimError> {
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

/// The control inputs as functions of time.
struct Inputs<'a> {
    sim: &'a Simulator,
    aileron: Aileron,
    rudder: Rudder,
    /// The rudder when it is constant for t > 0 (fixed, or scheduled with a step aileron).
    rudder_after_step: Option<f64>,
}

impl<'a> Inputs<'a> {
    fn new(sim: &'a Simulator, aileron: Aileron, rudder: Rudder) -> Result<Inputs<'a>, SimError> {
        // Check the schedule covers the final deflection (a ramp stays between 0 and it).
        let last = sim.rudder_at(rudder, aileron.final_value())?;
        let rudder_after_step = match (rudder, aileron) {
            (Rudder::Fixed(v), _) => Some(v),
            (Rudder::ZeroSideslip, Aileron::Step { .. }) => Some(last),
            (Rudder::ZeroSideslip, Aileron::Ramp { .. }) => None,
        };
        Ok(Inputs {
            sim,
            aileron,
            rudder,
            rudder_after_step,
        })
    }

    fn controls(&self, t: f64) -> Controls {
        let delta_a = self.aileron.at(t);
        // Inside a ramp the schedule is defined (checked in `new`); NaN would fail the
        // integration loudly rather than silently.
        let delta_r = match self.rudder_after_step {
            Some(v) => v,
            None => self.sim.rudder_at(self.rudder, delta_a).unwrap_or(f64::NAN),
        };
        Controls {
            delta_a,
            delta_e: self.sim.trims.delta_e(),
            delta_r,
        }
    }
}

/// The PSS model (Appendix A.2), state [alpha, beta, p, q, r].
struct PssSystem<'a> {
    model: &'a PssModel,
    inputs: &'a Inputs<'a>,
}

impl System<f64, SVector<f64, 5>> for PssSystem<'_> {
    fn system(&self, t: f64, y: &SVector<f64, 5>, dy: &mut SVector<f64, 5>) {
        let x = [y[0], y[1], y[2], y[3], y[4]];
        let f = self.model.rhs(&x, &self.inputs.controls(t));
        dy.copy_from_slice(&f);
    }
}

/// The 7th-order model (Appendix A.1), state [alpha, beta, p, q, r, gamma_x, gamma_y, gamma_z]
/// with gamma the direction of gravity in body axes.
struct FullSystem<'a> {
    model: &'a PssModel,
    inputs: &'a Inputs<'a>,
    speed: f64,
}

impl System<f64, SVector<f64, 8>> for FullSystem<'_> {
    fn system(&self, t: f64, y: &SVector<f64, 8>, dy: &mut SVector<f64, 8>) {
        let x = [y[0], y[1], y[2], y[3], y[4]];
        let f = self.model.rhs(&x, &self.inputs.controls(t));
        let gamma = [y[5], y[6], y[7]];
        let (phi, theta) = euler(&gamma);
        let (d_alpha, d_beta, _, _) =
            gravity_and_attitude(self.speed, x[2], x[3], x[4], phi, theta);
        dy[0] = f[0] + d_alpha;
        dy[1] = f[1] + d_beta;
        dy[2] = f[2];
        dy[3] = f[3];
        dy[4] = f[4];
        let g = gravity_rate(&gamma, x[2], x[3], x[4]);
        dy[5] = g[0];
        dy[6] = g[1];
        dy[7] = g[2];
    }
}

/// The samples as columns, one vector per state component.
fn columns<const N: usize>(y: &[SVector<f64, N>]) -> Vec<Vec<f64>> {
    (0..N).map(|i| y.iter().map(|v| v[i]).collect()).collect()
}

/// d gamma / dt = gamma x omega for the body-axis direction of a fixed inertial vector.
fn gravity_rate(g: &[f64; 3], p: f64, q: f64, r: f64) -> [f64; 3] {
    [
        g[1] * r - g[2] * q,
        g[2] * p - g[0] * r,
        g[0] * q - g[1] * p,
    ]
}

/// (phi, theta) from the body-axis gravity direction (normalised first).
fn euler(g: &[f64; 3]) -> (f64, f64) {
    let n = (g[0] * g[0] + g[1] * g[1] + g[2] * g[2]).sqrt();
    let theta = (-g[0] / n).clamp(-1.0, 1.0).asin();
    let phi = g[1].atan2(g[2]);
    (phi, theta)
}

/// The representative of `angle` (mod 2 pi) nearest to `prev`.
fn unwrap_angle(prev: f64, angle: f64) -> f64 {
    let tau = std::f64::consts::TAU;
    angle + tau * ((prev - angle) / tau).round()
}

/// Integrates over the segments `breaks[0]..breaks[1]..` and samples the continuous output at
/// the times `t`.
fn integrate<const N: usize, S>(
    make: impl Fn() -> S,
    y0: SVector<f64, N>,
    breaks: &[f64],
    t: &[f64],
    tol: &Tolerances,
    model: Model,
) -> Result<(Vec<SVector<f64, N>>, RunStats), SimError>
where
    S: System<f64, SVector<f64, N>>,
{
    let mut out = Vec::with_capacity(t.len());
    let mut stats = RunStats::default();
    let mut y = y0;
    let mut k = 0;
    for w in breaks.windows(2) {
        let (a, b) = (w[0], w[1]);
        let mut solver = Dopri5::new(make(), a, b, b - a, y, tol.rtol, tol.atol);
        let mut dense = ContinuousOutputModel::new();
        let fail = |t: f64, message: String| SimError::Integration {
            model: model.name(),
            t,
            message,
        };
        let st = solver
            .integrate_with_continuous_output_model(&mut dense)
            .map_err(|e| {
                // The time the integrator stopped at, not the start of the segment.
                use ode_solvers::dop_shared::IntegrationError as E;
                let at = match e {
                    E::MaxNumStepReached { x, .. }
                    | E::StepSizeUnderflow { x }
                    | E::StiffnessDetected { x } => x,
                };
                fail(at, e.to_string())
            })?;
        stats.evaluations += st.num_eval;
        stats.accepted += st.accepted_steps;
        stats.rejected += st.rejected_steps;
        let last = b == breaks[breaks.len() - 1];
        while k < t.len() && (t[k] < b || (last && t[k] <= b)) {
            let v = dense
                .evaluate(t[k].max(a))
                .ok_or_else(|| fail(t[k], "no dense output".into()))?;
            if v.iter().any(|x| !x.is_finite()) {
                return Err(fail(t[k], "the state is no longer finite".into()));
            }
            out.push(v);
            k += 1;
        }
        y = solver
            .y_out()
            .last()
            .copied()
            .ok_or_else(|| fail(b, "no final state".into()))?;
    }
    Ok((out, stats))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gravity_direction_kinematics_equal_the_euler_equations_of_a1() {
        // gamma = (-sin theta, cos theta sin phi, cos theta cos phi); its chain-rule derivative
        // with phi_dot, theta_dot of gravity_and_attitude must equal gamma x omega.
        for (phi, theta, p, q, r) in [
            (0.3, -0.4, 2.0, -0.3, 0.5),
            (-2.5, 1.2, -1.0, 0.7, -0.2),
            (4.0, 0.05, 0.1, 0.2, 0.3),
        ] {
            let (_, _, phi_dot, theta_dot) = gravity_and_attitude(150.0, p, q, r, phi, theta);
            let (sp, cp) = f64::sin_cos(phi);
            let (st, ct) = f64::sin_cos(theta);
            let chain = [
                -ct * theta_dot,
                -st * sp * theta_dot + ct * cp * phi_dot,
                -st * cp * theta_dot - ct * sp * phi_dot,
            ];
            let g = gravity_rate(&[-st, ct * sp, ct * cp], p, q, r);
            for i in 0..3 {
                assert!((chain[i] - g[i]).abs() < 1e-13, "{i}: {chain:?} vs {g:?}");
            }
            let (ph, th) = euler(&[-st, ct * sp, ct * cp]);
            assert!((th - theta).abs() < 1e-14);
            assert!((unwrap_angle(phi, ph) - phi).abs() < 1e-14);
        }
    }
}
