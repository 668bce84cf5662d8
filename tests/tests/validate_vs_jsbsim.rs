//! The verdicts of `model validate` (the library's [`model::six_dof::sweep`], the 6-DOF's side
//! of the command) against the same judgement made on JSBSim's own runs: at seeded F-104 and
//! F-15 conditions, in 1-g level flight and in an unloaded (0-g) roll, both sides start from
//! the same n-g trim and step the aileron over the same deflections for 10 s each; JSBSim's
//! sweep is `tests/oracle/jsbsim_six_dof.py --sweep --flat-earth` (the catalogue model with its
//! flight control system and engines cut, fuel frozen, on the flat, non-rotating planet of the
//! native 6-DOF), which judges its settled roll rates by the rule of `model::six_dof::jump`
//! written independently in Python. The 6-DOF's verdict must be JSBSim's: a jump on both sides
//! or on neither, and where both jump, the step past the jump the same within one step of the
//! sweep. Skipped with a message when the `jsbsim` package is not installed.

mod support;

use model::jsbsim::catalogue;
use model::jsbsim::condition::{Condition, Speed};
use model::jsbsim::import::Loaded;
use model::jsbsim::trim::trim;
use model::six_dof::sweep;
use serde_json::Value;
use support::oracle::{seeded_cases, Case};

/// The aileron steps of both sweeps, deg (JSBSim's left aileron, a roll to the right): every
/// degree over the F-104's travel (20 deg) and a little past it, where its unloaded rolls jump.
const STEPS: (f64, f64, f64) = (8.0, 22.0, 1.0);

/// The length of each run, s (`model validate`'s default).
const RUN_S: f64 = 10.0;

/// Two F-104 points and one F-15 point drawn over their envelopes (seeded), each in 1-g level
/// flight and in an unloaded roll.
fn cases() -> Vec<Case> {
    seeded_cases(
        45,
        &[("f104", 2), ("f15", 1)],
        (2_000.0, 10_000.0),
        (0.6, 0.9),
    )
}

/// The aileron steps, deg.
fn steps() -> Vec<f64> {
    let (a, b, s) = STEPS;
    let n = ((b - a) / s).round() as usize;
    (0..=n).map(|k| a + k as f64 * s).collect()
}

/// JSBSim's sweep of `c`: its verdict (the step past the jump, if any) and its settled roll
/// rates.
fn jsbsim_sweep(c: &Case) -> (Option<f64>, Vec<f64>) {
    let (a, b, s) = STEPS;
    let v = support::oracle::six_dof(
        c.model,
        (c.altitude_m, c.mach, c.load_factor),
        &[
            "--flat-earth".into(),
            "--sweep".into(),
            format!("{a}:{b}:{s}"),
            "--time".into(),
            RUN_S.to_string(),
        ],
    );
    let jump = (v["jump"]["jump"] == Value::Bool(true))
        .then(|| v["jump"]["between_deg"][1].as_f64().expect("between_deg"));
    let p = v["sweep"]
        .as_array()
        .expect("steps")
        .iter()
        .map(|s| s["p_mean_last2s"].as_f64().expect("p").abs())
        .collect();
    (jump, p)
}

/// The 6-DOF's sweep of `c`: its verdict and settled roll rates.
fn native_sweep(c: &Case) -> (Option<f64>, Vec<f64>) {
    let loaded = Loaded::new(c.model, None, &[]).unwrap_or_else(|e| panic!("{e}"));
    let condition = Condition::new(c.altitude_m, Speed::Mach(c.mach)).expect("condition");
    let setup = loaded.setup(condition);
    let t = trim(&setup, c.load_factor).unwrap_or_else(|e| panic!("{c:?}: {e}"));
    let s = sweep(&setup, &t, &steps(), RUN_S).unwrap_or_else(|e| panic!("{c:?}: {e}"));
    (s.jump.map(|j| j.between_deg.1), s.settled)
}

#[test]
fn validates_verdicts_are_jsbsims_at_seeded_conditions() {
    if catalogue::root(None).is_none() {
        eprintln!("skipped: {}", catalogue::HOW_TO_GET);
        return;
    }
    let show = |x: Option<f64>| x.map_or("none".to_string(), |v| format!("{v:.0}"));
    eprintln!("model  alt_m  Mach  n  6-DOF_jump_to_deg  JSBSim_jump_to_deg  worst_p_diff_rad_s");
    let (mut failures, mut jumps, mut smooth) = (Vec::new(), 0, 0);
    for c in cases() {
        let (theirs, p_theirs) = jsbsim_sweep(&c);
        let (ours, p_ours) = native_sweep(&c);
        let worst = p_ours
            .iter()
            .zip(&p_theirs)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        eprintln!(
            "{:<5} {:>6} {:>5} {:>2} {:>18} {:>19} {:>19.4}",
            c.model,
            c.altitude_m,
            c.mach,
            c.load_factor,
            show(ours),
            show(theirs),
            worst
        );
        let agree = match (ours, theirs) {
            (None, None) => {
                smooth += 1;
                true
            }
            (Some(a), Some(b)) => {
                jumps += 1;
                (a - b).abs() <= STEPS.2 + 1e-9
            }
            _ => false,
        };
        if !agree {
            failures.push(format!(
                "{c:?}: 6-DOF {ours:?}, JSBSim {theirs:?}\n  ours   {p_ours:.3?}\n  theirs {p_theirs:.3?}"
            ));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    // Both verdicts were put to the test.
    assert!(jumps >= 1 && smooth >= 1, "{jumps} jumps, {smooth} smooth");
}
