//! A 6-DOF run: from the import's n-g trim (alpha, elevator, the pull-up's pitch rate, wings
//! level on a level flight path), the aileron stepped at t = 0 and every surface held (the
//! flight control system cut, as the import cuts it), thrust off or held at the trim's drag
//! balance, fuel frozen, integrated by the classical fourth-order Runge-Kutta method at a fixed
//! step.
//!
//! Alpha-dot and beta-dot, which some models' aerodynamics read, depend on the accelerations
//! those aerodynamics make: each evaluation reads the values of the evaluation before it (a
//! quarter step earlier at most), as JSBSim reads those of its previous step; so does
//! `aero/cl-squared`.

use super::airframe::{lift_coefficient, Airframe};
use super::history::History;
use super::motion::{angle_rates, Rigid};
use super::state::State;
use crate::jsbsim::aerodynamics::Loads;
use crate::jsbsim::coefficients::Setup;
use crate::jsbsim::condition::{Condition, Motion, Speed, State as Flight};
use crate::jsbsim::trim::Trim;
use crate::jsbsim::units::{FT_PER_M, M_PER_FT};

/// The thrust of a run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Thrust {
    /// No thrust: the airframe glides, and its speed is free to change.
    Off,
    /// A force along the body x axis through the CG, held at the value that balances the drag
    /// along the flight path at the trim (the speed's rate of change zero at the start).
    Trim,
}

/// What to run.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Settings {
    /// The aileron surface from t = 0, rad, JSBSim's sign (the left aileron, positive rolls
    /// right), or normalised travel for a model that reads only that.
    pub aileron: f64,
    /// Length of the run, s.
    pub t_end: f64,
    /// Integration step, s.
    pub dt: f64,
    /// Thrust.
    pub thrust: Thrust,
}

/// JSBSim's default integration rate, Hz: the step of [`Settings::step`].
pub const RATE_HZ: f64 = 120.0;

impl Settings {
    /// An aileron step of `aileron` (rad, JSBSim's sign) for `t_end` s at 120 Hz, thrust off.
    pub fn step(aileron: f64, t_end: f64) -> Settings {
        Settings {
            aileron,
            t_end,
            dt: 1.0 / RATE_HZ,
            thrust: Thrust::Off,
        }
    }
}

/// What an evaluation leaves for the next: alpha-dot, beta-dot and CL^2.
#[derive(Clone, Copy, Debug)]
struct Lagged {
    angle_rates: [f64; 2],
    cl2: f64,
}

/// The airframe, the body and the run's fixed inputs.
struct Dynamics<'m> {
    airframe: Airframe<'m>,
    rigid: Rigid,
    surfaces: [f64; 3],
    thrust: f64,
    lagged: Lagged,
}

impl Dynamics<'_> {
    /// The flight condition of `s`: the standard atmosphere at its altitude, its airspeed.
    fn condition(s: &State, t: f64) -> Result<Condition, String> {
        Condition::new(
            s.altitude_ft() * M_PER_FT,
            Speed::True(s.airspeed() * M_PER_FT),
        )
        .map_err(|e| format!("at t = {t:.3} s the aircraft left the simulated flight: {e}"))
    }

    /// Forces and moments at `s` (body axes, lbs and lbs ft), the thrust included, and the
    /// flight state the model read.
    fn loads(&mut self, s: &State, t: f64) -> Result<(Loads, Condition, Flight), String> {
        let condition = Self::condition(s, t)?;
        let (alpha, beta) = s.alpha_beta();
        let flight = Flight {
            alpha,
            beta,
            rates: s.pqr,
            surfaces: self.surfaces,
        };
        let [phi, theta, _] = s.euler();
        let v_down = s.ned_velocity()[2];
        let motion = Motion {
            angle_rates: self.lagged.angle_rates,
            attitude: Some([phi, theta]),
            gamma: (-v_down / s.airspeed()).clamp(-1.0, 1.0).asin(),
            v_down_fps: v_down,
        };
        let mut loads = self
            .airframe
            .loads(&condition, &flight, &motion, self.lagged.cl2)
            .map_err(|e| format!("at t = {t:.3} s: {e}"))?;
        loads.force[0] += self.thrust;
        Ok((loads, condition, flight))
    }

    /// The rate of change of `s` at time `t`.
    fn rate(&mut self, s: &State, t: f64) -> Result<State, String> {
        let (loads, condition, flight) = self.loads(s, t)?;
        let rate = self.rigid.rate(s, loads.force, loads.moment);
        let qbar_area = condition.qbar_psf() * self.airframe.model().metrics.wing_area;
        let mut aero = loads;
        aero.force[0] -= self.thrust;
        let cl = lift_coefficient(&aero, flight.alpha, qbar_area);
        self.lagged = Lagged {
            angle_rates: angle_rates(s.uvw, rate.uvw),
            cl2: cl * cl,
        };
        Ok(rate)
    }

    /// One step of the classical Runge-Kutta method from `s` at `t`.
    fn rk4(&mut self, s: &State, t: f64, h: f64) -> Result<State, String> {
        let k1 = self.rate(s, t)?;
        let k2 = self.rate(&s.step(h / 2.0, &k1), t + h / 2.0)?;
        let k3 = self.rate(&s.step(h / 2.0, &k2), t + h / 2.0)?;
        let k4 = self.rate(&s.step(h, &k3), t + h)?;
        let mut sum = k1;
        for (k, w) in [(k2, 2.0), (k3, 2.0), (k4, 1.0)] {
            sum = sum.step(w, &k);
        }
        Ok(s.step(h / 6.0, &sum).normalised())
    }
}

/// The body state of `trim` at `setup`'s condition: wings level, heading north, on a level
/// flight path at the trim's alpha and pitch rate.
pub fn trim_state(setup: &Setup, trim: &Trim) -> State {
    let v = setup.condition.speed * FT_PER_M;
    let a = trim.alpha;
    State::new(
        [v * a.cos(), 0.0, v * a.sin()],
        [0.0, trim.q, 0.0],
        [0.0, a, 0.0],
        setup.condition.altitude_m * FT_PER_M,
    )
}

/// The 6-DOF run of `settings` from `trim` at `setup`'s condition.
pub fn simulate(setup: &Setup, trim: &Trim, settings: &Settings) -> Result<History, String> {
    let Settings { t_end, dt, .. } = *settings;
    if !(t_end.is_finite() && t_end > 0.0 && dt.is_finite() && dt > 0.0 && dt <= t_end) {
        return Err(format!(
            "a run of {t_end} s at a step of {dt} s (expected 0 < step <= length, finite)"
        ));
    }
    let model = setup.model;
    let mut surfaces = trim.state().surfaces;
    surfaces[0] = settings.aileron;
    let start = Flight {
        surfaces,
        ..trim.state()
    };
    let airframe = Airframe::new(
        model,
        (&setup.condition, &start),
        &setup.surfaces,
        &setup.settings,
    )
    .map_err(|e| e.to_string())?;
    let mut dynamics = Dynamics {
        airframe,
        rigid: Rigid::new(&model.totals())?,
        surfaces,
        thrust: 0.0,
        lagged: Lagged {
            angle_rates: [0.0; 2],
            cl2: 0.0,
        },
    };
    let mut s = trim_state(setup, trim);
    // The lagged values and the thrust of the trim, the aileron still neutral.
    dynamics.surfaces[0] = 0.0;
    for _ in 0..2 {
        dynamics.rate(&s, 0.0)?;
    }
    if settings.thrust == Thrust::Trim {
        let (loads, _, flight) = dynamics.loads(&s, 0.0)?;
        let (a, f) = (flight.alpha, loads.force);
        let drag = -(a.cos() * f[0] + a.sin() * f[2]);
        dynamics.thrust = drag / a.cos();
    }
    dynamics.surfaces[0] = settings.aileron;
    let steps = (t_end / dt).round() as usize;
    let mut history = History::new(*settings, steps + 1);
    history.record(0.0, &s);
    for k in 0..steps {
        let t = k as f64 * dt;
        s = dynamics.rk4(&s, t, dt)?;
        history.record(t + dt, &s);
    }
    history.thrust_lbs = dynamics.thrust;
    Ok(history)
}
