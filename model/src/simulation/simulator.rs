//! A simulator for one aircraft and elevator: the trims and the rudder schedule built once, one
//! run from the trim at delta_a = 0, and families of runs on two threads.

use super::attitude::{euler, unwrap_angle};
use super::integrate::{columns, integrate, FullSystem, Inputs, PssSystem};
use super::{
    parallel_map, validate, Aileron, Model, Rudder, RudderSchedule, SimError, SimSettings,
    TimeHistory, Trims,
};
use crate::aircraft::Aircraft;
use ode_solvers::SVector;

/// A simulator for one aircraft and elevator setting: the compiled model, the closed-form trims
/// and the zero-sideslip rudder schedule, built once and shared by many runs.
#[derive(Clone, Debug)]
pub struct Simulator {
    pub(super) trims: Trims,
    schedule: Result<RudderSchedule, SimError>,
    pub(super) speed: f64,
    /// |delta_r| limit of the aircraft's `[limits]`, rad: the schedule saturates there.
    rudder_limit: Option<f64>,
    /// The principal axis' angle of attack at the trim of an aircraft whose file gives it: the
    /// 7th-order model then starts on its own flight path ([`super::flight_start`]).
    trim_alpha_t: Option<f64>,
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
            trim_alpha_t: aircraft
                .trimmed
                .then(|| aircraft.value(crate::aircraft::Param::AlphaT)),
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

    /// The 7th-order model's start and pitch attitude: the PSS trim `pss` at theta = 0 for the
    /// paper's aircraft, the aircraft's own steady flight for one whose file gives its trim.
    fn seventh_order_start(
        &self,
        pss: [f64; 5],
        delta_r: f64,
    ) -> Result<([f64; 5], f64), SimError> {
        let Some(alpha_t) = self.trim_alpha_t else {
            return Ok((pss, 0.0));
        };
        let controls = crate::pss_model::Controls {
            delta_a: 0.0,
            delta_e: self.trims.delta_e(),
            delta_r,
        };
        super::flight_start(self.trims.model(), &controls, self.speed, alpha_t)
            .ok_or(SimError::NoTrim { delta_r })
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
                let (x0, theta) = self.seventh_order_start(start.x, delta_r0)?;
                let mut y0 = SVector::<f64, 8>::zeros();
                y0.fixed_rows_mut::<5>(0).copy_from_slice(&x0);
                // Gravity in body axes, wings level: (-sin theta, 0, cos theta).
                (y0[5], y0[7]) = (-theta.sin(), theta.cos());
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

/// Runs one simulation (builds a [`Simulator`] for it; use a simulator directly for many runs).
pub fn simulate(aircraft: &Aircraft, settings: &SimSettings) -> Result<TimeHistory, SimError> {
    Simulator::new(aircraft, settings.delta_e)?.run(settings)
}
