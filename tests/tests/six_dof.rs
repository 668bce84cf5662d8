//! How far the criterion holds on a real aircraft: the import, the criterion and the 7th-order
//! model against JSBSim's own nonlinear 6-DOF flight (`tests/oracle/jsbsim_six_dof.py`: the
//! catalogue model with its flight control system cut, so the surfaces stay where set, engines
//! cut and fuel frozen, trimmed by the script's own Newton iteration on JSBSim's accelerations).
//!
//! At seeded points of the envelope, in 1-g level flight and in an unloaded (0-g) roll, both
//! sides start from the same trim and step the aileron over the same deflections; the settled
//! roll rate is the mean of p over the last 2 s of 15 s. Three claims are checked:
//!
//! - (a) before any jump and within the aileron's travel, the 7th-order model's settled roll
//!   rate agrees with JSBSim's within [`ROLL_RATE_AGREEMENT`] relative;
//! - (b) "a jump within the aileron limit" is the same answer from the criterion and from JSBSim
//!   (whose jump is found by its aileron sweep, with its travel as JSBSim moves the surface);
//! - (c) where JSBSim jumps, the criterion's critical aileron lies below JSBSim's jump by at most
//!   [`JUMP_LAG_DEG`]: the criterion is the fold of the pseudo-steady equilibria, which a step
//!   must pass by the transient's overshoot before the roll rate jumps.
//!
//! The test prints its agreement table (`--nocapture`) and is skipped with a message when the
//! `jsbsim` package is not installed (`.ci/run` installs it).

mod support;

use model::aircraft::{parse, Aircraft};
use model::analysis::analyze;
use model::jsbsim::catalogue;
use model::jsbsim::condition::Speed;
use model::jsbsim::import::{import, Alpha, Request};
use model::simulation::{simulate, Model, SimSettings};
use rayon::prelude::*;
use serde_json::Value;
use support::oracle::{seeded_cases, Case};

/// Relative agreement of the settled roll rates before a jump. Both sides integrate accurately
/// (JSBSim's Euler rates converge to 5e-4 rad/s in the settled roll rate, measured at half its
/// step; Dopri5 to 1e-8): what remains is the model, linear aerodynamics about the trim at
/// constant speed against JSBSim's tables at the falling speed and the moving Mach of a rolling,
/// unpowered airframe.
const ROLL_RATE_AGREEMENT: f64 = 0.25;

/// The criterion's critical aileron may lie below JSBSim's jump by at most this, deg (the
/// issue's bound: the step's transient carries the roll past the fold before it jumps).
const JUMP_LAG_DEG: f64 = 2.5;

/// The aileron steps of both sweeps, deg (JSBSim's left aileron; the project's delta_a is its
/// negative): every half degree from 4 to 30.
const SWEEP: (f64, f64, f64) = (4.0, 30.0, 0.5);

/// The length of each run after the step, s: near a fold the roll settles slowly (the
/// eigenvalue that crosses zero there is small), so a short run finds the jump late (at 10 s
/// JSBSim's F-104 jumped up to 3.3 deg above the fold, at 15 s within 0.8 deg), while a long
/// one lets the unpowered, rolling airframe drift from the flight state of the trim (Mach by
/// up to 0.14 in 15 s).
const RUN_S: f64 = 15.0;

/// Six F-104 and three F-15 points drawn over their envelopes (seeded), each in 1-g level
/// flight and in an unloaded roll.
fn cases() -> Vec<Case> {
    seeded_cases(43, &[("f104", 6), ("f15", 3)], (0.0, 10_000.0), (0.5, 0.9))
}

/// The imported aircraft at the case's n-g trim.
fn imported(c: &Case) -> Aircraft {
    let request = Request {
        model: c.model.to_string(),
        root: None,
        altitude_m: c.altitude_m,
        speed: Speed::Mach(c.mach),
        alpha: Alpha::Trim(c.load_factor),
        settings: Vec::new(),
    };
    let text = import(&request).unwrap_or_else(|e| panic!("{}: {e}", c.model));
    parse(&text, c.model).unwrap_or_else(|e| panic!("{}: {e}", c.model))
}

/// JSBSim's sweep of the case.
fn jsbsim_sweep(c: &Case) -> Value {
    let (a, b, s) = SWEEP;
    support::oracle::six_dof(
        c.model,
        (c.altitude_m, c.mach, c.load_factor),
        &[
            "--sweep".into(),
            format!("{a}:{b}:{s}"),
            "--time".into(),
            RUN_S.to_string(),
        ],
    )
}

/// The 7th-order model's settled roll rate after an aileron step of JSBSim's `deg` (the mean of
/// p over the last 2 s of the run, as the oracle's).
fn model_settled_p(ac: &Aircraft, deg: f64) -> f64 {
    let settings = SimSettings {
        t_end: RUN_S,
        ..SimSettings::step(Model::SeventhOrder, 0.0, -deg.to_radians())
    };
    let run = simulate(ac, &settings).unwrap_or_else(|e| panic!("{}: {e}", ac.name));
    run.steady(2.0).p_mean
}

/// JSBSim's jump: the first step on the upper branch of its steepest rise, deg.
fn jsbsim_jump(sweep: &Value) -> Option<f64> {
    let jump = &sweep["jump"];
    if jump["jump"] != Value::Bool(true) {
        return None;
    }
    jump["between_deg"][1].as_f64()
}

/// The largest Mach drift over the runs, and whether the two steps around JSBSim's jump
/// settled: a jump between two roll rates that still drift (the unloaded roll dives, and its
/// speed builds) is a change of the flight state as much as a fold of the roll.
fn jump_is_steady(sweep: &Value, c: &Case) -> (f64, bool) {
    let steps = sweep["sweep"].as_array().expect("steps");
    let drift = steps
        .iter()
        .filter_map(|s| s["mach_end"].as_f64())
        .map(|m| (m - c.mach).abs())
        .fold(0.0, f64::max);
    let [lo, hi] = [0, 1].map(|i| sweep["jump"]["between_deg"][i].as_f64());
    let settled = |deg: Option<f64>| {
        steps
            .iter()
            .any(|s| s["aileron_deg"].as_f64() == deg && s["settled"] == Value::Bool(true))
    };
    (drift, settled(lo) && settled(hi))
}

#[test]
fn the_criterion_and_the_7th_order_model_agree_with_jsbsims_6_dof() {
    if catalogue::root(None).is_none() {
        eprintln!("skipped: {}", catalogue::HOW_TO_GET);
        return;
    }
    eprintln!(
        "model  alt_m  Mach  n  crit_deg  limit_deg  jsbsim_jump_deg  travel_deg  worst_p_rel  verdict"
    );
    let mut failures = Vec::new();
    let (mut compared, mut judged) = (0, 0);
    // JSBSim's sweeps are independent processes: run them on every core at once.
    let cases = cases();
    let sweeps: Vec<Value> = cases.par_iter().map(jsbsim_sweep).collect();
    for (c, sweep) in cases.into_iter().zip(sweeps) {
        let ac = imported(&c);
        let analysis = analyze(&ac, 0.0).expect("analysis");
        let critical = analysis.critical.as_ref().map(|j| j.delta_a_deg.abs());
        let limit = ac.limits.aileron_deg.expect("an aileron limit");
        let travel = sweep["trim"]["aileron_travel_deg"][1]
            .as_f64()
            .expect("travel");
        let jump = jsbsim_jump(&sweep);
        let (drift, steady) = jump_is_steady(&sweep, &c);
        // (a) settled roll rates before either side jumps.
        let before =
            |deg: f64| jump.is_none_or(|j| deg < j - 1.0) && critical.is_none_or(|k| deg < k - 1.0);
        let mut worst: f64 = 0.0;
        for step in sweep["sweep"].as_array().expect("steps") {
            let deg = step["aileron_deg"].as_f64().expect("deg");
            // Within the travel: beyond it the model's tables are read past their end.
            let reach = deg <= travel;
            if !reach || !before(deg) || step["settled"] != Value::Bool(true) || deg % 2.0 != 0.0 {
                continue;
            }
            let theirs = step["p_mean_last2s"].as_f64().expect("p");
            let ours = model_settled_p(&ac, deg);
            worst = worst.max((ours - theirs).abs() / theirs.abs());
            compared += 1;
        }
        // (b) a jump within the aileron limit, both ways.
        let ours_within = critical.is_some_and(|k| k <= limit);
        let theirs_within = jump.is_some_and(|j| j <= travel + 1e-9);
        // (c) the lag of JSBSim's jump behind the criterion.
        let lag = jump.zip(critical).map(|(j, k)| j - k);
        let mut verdict = Vec::new();
        if worst > ROLL_RATE_AGREEMENT {
            verdict.push(format!("(a) roll rate off by {worst:.3}"));
        }
        if ours_within != theirs_within {
            verdict.push(format!(
                "(b) within limit: criterion {ours_within}, JSBSim {theirs_within}"
            ));
        }
        // Judged where a pilot can meet the jump: beyond the surface's travel JSBSim reads its
        // tables past their end, and no such flight exists.
        if jump.is_some_and(|j| j <= travel + JUMP_LAG_DEG) {
            judged += 1;
            if !lag.is_some_and(|l| (0.0..=JUMP_LAG_DEG).contains(&l)) {
                verdict.push(format!("(c) lag {lag:?} deg"));
            }
        }
        let show = |x: Option<f64>| x.map_or("none".to_string(), |v| format!("{v:.2}"));
        eprintln!(
            "{:<5} {:>6} {:>5} {:>2} {:>9} {:>10} {:>16} {:>11.2} {:>12.3} {:.3} {}  {}",
            c.model,
            c.altitude_m,
            c.mach,
            c.load_factor,
            show(critical),
            format!("{limit:.2}"),
            show(jump),
            travel,
            worst,
            drift,
            steady,
            if verdict.is_empty() {
                "agrees".to_string()
            } else {
                verdict.join("; ")
            }
        );
        if !verdict.is_empty() {
            failures.push(format!(
                "{} {} m Mach {} n {}: {}",
                c.model,
                c.altitude_m,
                c.mach,
                c.load_factor,
                verdict.join("; ")
            ));
        }
    }
    eprintln!("{compared} settled roll rates compared, {judged} jumps within reach judged");
    assert!(failures.is_empty(), "{failures:#?}");
    // The comparison is not empty: both claims were put to the test.
    assert!(
        compared >= 20 && judged >= 3,
        "{compared} roll rates, {judged} jumps"
    );
}
