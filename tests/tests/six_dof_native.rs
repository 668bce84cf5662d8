//! The native 6-DOF (`model::six_dof`) against JSBSim's own 6-DOF of the same airframe
//! (`tests/oracle/jsbsim_six_dof.py`: the catalogue model with its flight control system and
//! engines cut, fuel frozen, on a flat, non-rotating planet with standard gravity, which is the
//! native 6-DOF's Earth), from the same n-g trim, the same aileron step, over 10 s.
//!
//! The tolerance is the integrators' own: each side is run at its step and at half of it. For a
//! method of order k, the error of the run at step h is the difference of the two runs times
//! 2^k / (2^k - 1); JSBSim's rotational rates and attitude integrate by rectangular Euler
//! (order 1: twice the difference) and ours by the classical Runge-Kutta method (order 4; taken
//! as order 1 here too, the larger bound). Two simulations of one ODE then differ by at most the
//! sum of their errors, channel by channel, over the run: `2 |J(h) - J(h/2)| + 2 |N(h) - N(h/2)|`
//! (maximum over time), with a floor of 1e-6 of the channel's scale for rounding. Anything
//! beyond that is a difference of the models, not of the integration. The table printed
//! (`--nocapture`) also gives how far ours lies from JSBSim's Richardson extrapolation to step
//! zero, `2 J(h/2) - J(h)`: a measure of the models' own difference. Skipped with a message
//! when the `jsbsim` package is not installed.

use model::jsbsim::condition::{Condition, Speed};
use model::jsbsim::import::Loaded;
use model::jsbsim::trim::trim;
use model::six_dof::{simulate, History, Settings};
use serde_json::Value;

#[path = "support/mod.rs"]
mod support;

/// One comparison: a model at a flight condition, the aileron surface stepped (JSBSim's sign).
struct Case {
    model: &'static str,
    altitude_m: f64,
    mach: f64,
    load_factor: f64,
    aileron_deg: f64,
}

/// The length of the runs, s.
const RUN_S: f64 = 10.0;

/// JSBSim's run of `c` at `dt` on the flat planet.
fn jsbsim(c: &Case, dt: f64) -> Value {
    support::oracle::six_dof(
        c.model,
        (c.altitude_m, c.mach, c.load_factor),
        &[
            "--flat-earth".into(),
            "--aileron-deg".into(),
            c.aileron_deg.to_string(),
            "--time".into(),
            RUN_S.to_string(),
            "--dt".into(),
            dt.to_string(),
        ],
    )
}

/// Our run of `c` at `dt`.
fn native(c: &Case, dt: f64) -> History {
    let loaded = Loaded::new(c.model, None, &[]).unwrap_or_else(|e| panic!("{e}"));
    let condition = Condition::new(c.altitude_m, Speed::Mach(c.mach)).expect("condition");
    let setup = loaded.setup(condition);
    let t = trim(&setup, c.load_factor).unwrap_or_else(|e| panic!("{}: {e}", c.model));
    let settings = Settings {
        dt,
        ..Settings::step(c.aileron_deg.to_radians(), RUN_S)
    };
    simulate(&setup, &t, &settings).unwrap_or_else(|e| panic!("{}: {e}", c.model))
}

/// The channels compared: name, whether an angle that wraps, and the scale of its rounding floor.
const CHANNELS: [(&str, bool, f64); 9] = [
    ("alpha", false, 1.0),
    ("beta", false, 1.0),
    ("p", false, 1.0),
    ("q", false, 1.0),
    ("r", false, 1.0),
    ("V", false, 300.0),
    ("phi", true, 1.0),
    ("theta", false, 1.0),
    ("psi", true, 1.0),
];

/// Our channel `name` at sample `i`.
fn ours(h: &History, name: &str, i: usize) -> f64 {
    match name {
        "alpha" => h.alpha[i],
        "beta" => h.beta[i],
        "p" => h.p[i],
        "q" => h.q[i],
        "r" => h.r[i],
        "V" => h.speed[i],
        "phi" => h.phi[i],
        "theta" => h.theta[i],
        _ => h.psi[i],
    }
}

/// JSBSim's channel `name` at every `every`-th sample.
fn theirs(run: &Value, name: &str, every: usize) -> Vec<f64> {
    run["history"][name]
        .as_array()
        .expect("history")
        .iter()
        .step_by(every)
        .map(|v| v.as_f64().expect("number"))
        .collect()
}

/// `a - b`, wrapped into (-pi, pi] for an angle that wraps.
fn difference(a: f64, b: f64, wraps: bool) -> f64 {
    let d = a - b;
    if wraps {
        let tau = std::f64::consts::TAU;
        (d + std::f64::consts::PI).rem_euclid(tau) - std::f64::consts::PI
    } else {
        d
    }
}

/// Largest |x - y| over the samples.
fn worst(x: impl Iterator<Item = f64>, y: impl Iterator<Item = f64>, wraps: bool) -> f64 {
    x.zip(y)
        .map(|(a, b)| difference(a, b, wraps).abs())
        .fold(0.0, f64::max)
}

fn compare(c: &Case) -> Vec<String> {
    let h = 1.0 / 120.0;
    let (j1, j2) = (jsbsim(c, h), jsbsim(c, h / 2.0));
    let (n1, n2) = (native(c, h), native(c, h / 2.0));
    let samples = n1.t.len();
    assert_eq!(theirs(&j1, "t", 1).len(), samples, "{}: samples", c.model);
    let mut failures = Vec::new();
    for (name, wraps, scale) in CHANNELS {
        let jh = theirs(&j1, name, 1);
        let jh2 = theirs(&j2, name, 2);
        let ours_h = (0..samples).map(|i| ours(&n1, name, i));
        let ours_h2 = (0..samples).map(|i| ours(&n2, name, 2 * i));
        let jsbsim_error = 2.0 * worst(jh.iter().copied(), jh2.iter().copied(), wraps);
        let native_error = 2.0 * worst(ours_h.clone(), ours_h2, wraps);
        let tolerance = jsbsim_error + native_error + 1e-6 * scale;
        let apart = worst(ours_h.clone(), jh.iter().copied(), wraps);
        // JSBSim's Richardson extrapolation to step zero, 2 J(h/2) - J(h) (first order): what
        // is left apart from it is the models' difference plus the extrapolation's own error.
        let extrapolated = jh
            .iter()
            .zip(&jh2)
            .map(|(a, b)| b + difference(*b, *a, wraps));
        let apart_extrapolated = worst(ours_h, extrapolated, wraps);
        eprintln!(
            "{:<5} {:>5} {:>5.2} {:>3} {:>5} {:<6} apart {:>10.3e}  tolerance {:>10.3e} (JSBSim {:>9.2e}, native {:>9.2e})  from JSBSim extrapolated {:>9.2e}  {}",
            c.model,
            c.altitude_m,
            c.mach,
            c.load_factor,
            c.aileron_deg,
            name,
            apart,
            tolerance,
            jsbsim_error,
            native_error,
            apart_extrapolated,
            if apart <= tolerance { "ok" } else { "FAILS" }
        );
        if apart > tolerance {
            failures.push(format!(
                "{} {} m Mach {} n {} aileron {} deg: {name} apart by {apart:.3e}, beyond \
                 {tolerance:.3e}",
                c.model, c.altitude_m, c.mach, c.load_factor, c.aileron_deg
            ));
        }
    }
    failures
}

#[test]
fn the_native_6_dof_flies_as_jsbsim_within_the_integrators_own_error() {
    if !support::jsbsim_installed() {
        return;
    }
    let cases = [
        Case {
            model: "f104",
            altitude_m: 7300.0,
            mach: 0.75,
            load_factor: 1.0,
            aileron_deg: 10.0,
        },
        Case {
            model: "f15",
            altitude_m: 6000.0,
            mach: 0.7,
            load_factor: 1.0,
            aileron_deg: 10.0,
        },
        Case {
            model: "f16",
            altitude_m: 9000.0,
            mach: 1.2,
            load_factor: 1.0,
            aileron_deg: 5.0,
        },
    ];
    let failures: Vec<String> = cases.iter().flat_map(compare).collect();
    assert!(failures.is_empty(), "{failures:#?}");
}
