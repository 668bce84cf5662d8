//! The flight condition of an import and the flight state about it: the standard atmosphere at
//! the altitude, the speed (true airspeed or Mach), and every `aero/`, `velocities/`,
//! `atmosphere/` and `position/` property a model reads, set from alpha, beta, the body rates
//! and the surfaces. For the import quasi-steady: alpha-dot and beta-dot are zero, the attitude
//! wings level ([`Motion::QUASI_STEADY`]); a moving aircraft (the 6-DOF) gives them ([`Motion`]).
//! Everything else the aerodynamics read that only a system computes (flaps, gear, speed brakes,
//! boundary-layer control, engine outputs) is zero, the clean power-off configuration, unless
//! the user sets it.

use super::atmosphere::{standard, Air};
use super::digits::every_digit;
use super::error::JsbsimError;
use super::evaluate::Env;
use super::model::Model;
use super::surfaces::Surface;
use super::units::{FT_PER_M, M_PER_FT};

/// Feet per second in a knot.
const FPS_PER_KT: f64 = 1.687_809_857_101_196;

/// The speed of a flight condition.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Speed {
    /// Mach number.
    Mach(f64),
    /// True airspeed, m/s.
    True(f64),
}

/// Altitude and speed with the standard atmosphere there.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Condition {
    /// Geometric altitude above mean sea level, m.
    pub altitude_m: f64,
    /// The standard day there.
    pub air: Air,
    /// True airspeed, m/s.
    pub speed: f64,
    /// Mach number.
    pub mach: f64,
}

impl Condition {
    /// The condition at `altitude_m` and `speed`; an error if outside the atmosphere model or
    /// the speed is not positive.
    pub fn new(altitude_m: f64, speed: Speed) -> Result<Condition, String> {
        let air = standard(altitude_m).ok_or_else(|| {
            format!(
                "altitude {} m is outside the standard atmosphere (expected 0 to 86,000 m)",
                every_digit(altitude_m)
            )
        })?;
        let (speed, mach) = match speed {
            Speed::Mach(m) => (m * air.sound_speed, m),
            Speed::True(v) => (v, v / air.sound_speed),
        };
        if !(speed.is_finite() && speed > 0.0) {
            return Err(format!(
                "speed {} m/s (expected a positive speed)",
                every_digit(speed)
            ));
        }
        Ok(Condition {
            altitude_m,
            air,
            speed,
            mach,
        })
    }

    /// Dynamic pressure, psf.
    pub fn qbar_psf(&self) -> f64 {
        0.5 * self.air.density * self.speed * self.speed * 0.020_885_434_233_150_13
    }
}

/// The state about the condition: angles (rad), body rates (rad/s) and each surface's
/// deflection (rad, or travel for a surface per unit travel).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct State {
    /// Angle of attack, rad.
    pub alpha: f64,
    /// Sideslip, rad.
    pub beta: f64,
    /// Body rates p, q, r, rad/s.
    pub rates: [f64; 3],
    /// Aileron, elevator, rudder (JSBSim's signs).
    pub surfaces: [f64; 3],
}

/// Sets every input of `env` for `state` at `condition`: the flight state, the surfaces, the
/// user's `settings`, and zero for the system outputs left (listed in the returned vector).
pub fn set_state(
    env: &mut Env,
    model: &Model,
    condition: &Condition,
    state: &State,
    surfaces: &[Surface],
    settings: &[(String, f64)],
) -> Result<Vec<String>, JsbsimError> {
    for (name, value) in state_values(model, condition, state) {
        env.set(name, value);
    }
    for (s, x) in surfaces.iter().zip(state.surfaces) {
        for (name, value) in s.values(x) {
            if let Some(v) = value {
                env.set(name, v);
            }
        }
    }
    for (name, value) in settings {
        env.set(name, *value);
    }
    let zeroed: Vec<String> = model
        .functions
        .inputs()
        .into_iter()
        .filter(|n| env.is_unset(n) && is_system_output(n))
        .map(str::to_string)
        .collect();
    for name in &zeroed {
        env.set(name, 0.0);
    }
    Ok(zeroed)
}

/// The names of the properties [`set_state`] sets from the flight state (alpha, beta, the
/// rates, the speed and the atmosphere): the import's own variables, which a `--set` must not
/// override, or the derivatives taken by moving them would be those of a constant.
pub fn state_properties(model: &Model) -> Vec<&'static str> {
    let condition = Condition {
        altitude_m: 0.0,
        air: Air {
            temperature: 288.15,
            pressure: 101_325.0,
            density: 1.225,
            sound_speed: 340.294,
        },
        speed: 100.0,
        mach: 0.294,
    };
    let state = State {
        alpha: 0.0,
        beta: 0.0,
        rates: [0.0; 3],
        surfaces: [0.0; 3],
    };
    state_values(model, &condition, &state)
        .into_iter()
        .map(|(name, _)| name)
        .collect()
}

/// What a moving aircraft adds to the quasi-steady state of an import: the rates of change of
/// the aerodynamic angles, the attitude and the flight path. [`Motion::QUASI_STEADY`] is the
/// import's: alpha-dot and beta-dot zero, wings level, the pitch attitude alpha on a level path.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Motion {
    /// Alpha-dot and beta-dot, rad/s.
    pub angle_rates: [f64; 2],
    /// Bank and pitch attitude, rad; `None` for wings level at pitch attitude alpha.
    pub attitude: Option<[f64; 2]>,
    /// Flight-path angle, rad.
    pub gamma: f64,
    /// Downward speed over the ground, ft/s.
    pub v_down_fps: f64,
}

impl Motion {
    /// The import's quasi-steady state.
    pub const QUASI_STEADY: Motion = Motion {
        angle_rates: [0.0; 2],
        attitude: None,
        gamma: 0.0,
        v_down_fps: 0.0,
    };
}

/// How many flight-state properties [`flight_values`] gives.
pub const FLIGHT_VALUES: usize = 45;

/// Every flight-state property a model may read, with its value for `state` at `condition`.
fn state_values(model: &Model, condition: &Condition, state: &State) -> Vec<(&'static str, f64)> {
    flight_values(model, condition, state, &Motion::QUASI_STEADY).to_vec()
}

/// Every flight-state property a model may read, with its value for `state` and `motion` at
/// `condition`, always in the same order (a caller may resolve the names once).
pub fn flight_values(
    model: &Model,
    condition: &Condition,
    state: &State,
    motion: &Motion,
) -> [(&'static str, f64); FLIGHT_VALUES] {
    let vt = condition.speed * FT_PER_M;
    let (a, b) = (state.alpha, state.beta);
    let [p, q, r] = state.rates;
    let [adot, bdot] = motion.angle_rates;
    let [phi, theta] = motion.attitude.unwrap_or([0.0, a]);
    let rho = condition.air.density * 0.001_940_320_331_979_716;
    let qbar = 0.5 * rho * vt * vt;
    let m = &model.metrics;
    let h_ft = condition.altitude_m / M_PER_FT;
    let (u, v, w) = (vt * a.cos() * b.cos(), vt * b.sin(), vt * a.sin() * b.cos());
    [
        ("aero/alpha-rad", a),
        ("aero/alpha-deg", a.to_degrees()),
        ("aero/beta-rad", b),
        ("aero/beta-deg", b.to_degrees()),
        ("aero/mag-beta-rad", b.abs()),
        ("aero/mag-beta-deg", b.abs().to_degrees()),
        ("aero/alpha-wing-rad", a + m.incidence),
        ("aero/alphadot-rad_sec", adot),
        ("aero/betadot-rad_sec", bdot),
        ("aero/alphadot-deg_sec", adot.to_degrees()),
        ("aero/betadot-deg_sec", bdot.to_degrees()),
        ("aero/qbar-psf", qbar),
        ("aero/qbarUW-psf", 0.5 * rho * (u * u + w * w)),
        ("aero/qbarUV-psf", 0.5 * rho * (u * u + v * v)),
        ("aero/qbar-area", qbar * m.wing_area),
        ("aero/bi2vel", m.span / (2.0 * vt)),
        ("aero/ci2vel", m.chord / (2.0 * vt)),
        ("aero/h_b-mac-ft", h_ft / m.span),
        ("aero/h_b-cg-ft", h_ft / m.span),
        ("velocities/mach", condition.mach),
        ("velocities/vt-fps", vt),
        ("velocities/u-aero-fps", u),
        ("velocities/v-aero-fps", v),
        ("velocities/w-aero-fps", w),
        ("velocities/u-fps", u),
        ("velocities/v-fps", v),
        ("velocities/w-fps", w),
        ("velocities/p-aero-rad_sec", p),
        ("velocities/q-aero-rad_sec", q),
        ("velocities/r-aero-rad_sec", r),
        ("velocities/p-rad_sec", p),
        ("velocities/q-rad_sec", q),
        ("velocities/r-rad_sec", r),
        (
            "velocities/ve-kts",
            (2.0 * qbar / 0.002_376_9).sqrt() / FPS_PER_KT,
        ),
        ("velocities/vc-kts", calibrated_kts(condition)),
        ("aero/Re", reynolds(condition, m.chord * M_PER_FT)),
        ("aero/stall-hyst-norm", 0.0),
        ("atmosphere/rho-slugs_ft3", rho),
        ("atmosphere/a-fps", condition.air.sound_speed * FT_PER_M),
        ("position/h-sl-ft", h_ft),
        ("attitude/roll-rad", phi),
        ("attitude/pitch-rad", theta),
        ("flight-path/gamma-rad", motion.gamma),
        ("velocities/v-down-fps", motion.v_down_fps),
        ("velocities/h-dot-fps", -motion.v_down_fps),
    ]
}

/// Calibrated airspeed, knots: the sea-level speed whose impact pressure equals the one at
/// the condition (isentropic, subsonic; Rayleigh pitot above Mach 1).
fn calibrated_kts(c: &Condition) -> f64 {
    static SEA_LEVEL: std::sync::LazyLock<Air> =
        std::sync::LazyLock::new(|| standard(0.0).expect("sea level is in the atmosphere"));
    let sl = *SEA_LEVEL;
    let m = c.mach;
    let qc = if m <= 1.0 {
        c.air.pressure * ((1.0 + 0.2 * m * m).powf(3.5) - 1.0)
    } else {
        c.air.pressure * (166.921_58 * m.powi(7) / (7.0 * m * m - 1.0).powf(2.5) - 1.0)
    };
    let vc = sl.sound_speed * (5.0 * ((qc / sl.pressure + 1.0).powf(2.0 / 7.0) - 1.0)).sqrt();
    vc / 0.514_444_444_444_444_5
}

/// Reynolds number on the chord `chord_m` m, with Sutherland's law for the viscosity.
fn reynolds(c: &Condition, chord_m: f64) -> f64 {
    let t = c.air.temperature;
    let mu = 1.458e-6 * t.powf(1.5) / (t + 110.4);
    c.air.density * c.speed * chord_m / mu
}

/// Whether `name` is an output of a system (flight controls, gear, other systems, engines):
/// zero in the clean power-off configuration.
fn is_system_output(name: &str) -> bool {
    ["fcs/", "gear/", "systems/", "propulsion/"]
        .iter()
        .any(|p| name.starts_with(p))
}
