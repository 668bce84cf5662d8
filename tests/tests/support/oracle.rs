//! Running a Python oracle script of `tests/oracle/`: the request as JSON on its standard
//! input, the answer as JSON on the last line of its standard output. Shared by `jsbsim.rs`,
//! `jsbsim_trim.rs` (through `support`) and `jsbsim_limits.rs`; and JSBSim's own 6-DOF, run
//! from its command line, by `six_dof.rs`, `six_dof_native.rs`, `validate_vs_jsbsim.rs` and
//! `envelope.rs`, the first and the third at seeded flight conditions drawn here.

use model::random::Rng;
use serde_json::Value;
use std::io::Write;
use std::path::Path;
use std::process::{Command, Stdio};

/// The answer of `tests/oracle/<script>` to `request`; panics with the script's standard error
/// when it fails.
pub fn run(script: &str, request: &Value) -> Value {
    let script = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("oracle")
        .join(script);
    let mut child = Command::new("python3")
        .arg(&script)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("python3 runs");
    child
        .stdin
        .take()
        .unwrap()
        .write_all(request.to_string().as_bytes())
        .unwrap();
    let out = child.wait_with_output().unwrap();
    assert!(
        out.status.success(),
        "oracle {} failed: {}",
        script.display(),
        String::from_utf8_lossy(&out.stderr)
    );
    let stdout = String::from_utf8_lossy(&out.stdout);
    let last = stdout.lines().last().expect("oracle output");
    serde_json::from_str(last).expect("oracle JSON")
}

/// The answer of `tests/oracle/jsbsim_six_dof.py` (JSBSim's own 6-DOF, its flight control
/// system cut) for `model` trimmed at `(altitude m, Mach, load factor)`, with the rest of its
/// command line `args` (a step or a sweep, the run's length, the planet); panics with the
/// script's standard error when it fails.
pub fn six_dof(
    model: &str,
    (altitude_m, mach, load_factor): (f64, f64, f64),
    args: &[String],
) -> Value {
    let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("oracle/jsbsim_six_dof.py");
    let out = Command::new("python3")
        .arg(&script)
        .args(["--model", model])
        .args(["--altitude-m", &altitude_m.to_string()])
        .args(["--mach", &mach.to_string()])
        .args(["--load-factor", &load_factor.to_string()])
        .args(args)
        .output()
        .expect("python3 runs");
    assert!(
        out.status.success(),
        "JSBSim's 6-DOF failed for {model} at {altitude_m} m, Mach {mach}, n = {load_factor}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).expect("the oracle's JSON")
}

/// One flight condition of a comparison with JSBSim's 6-DOF.
#[derive(Debug)]
pub struct Case {
    pub model: &'static str,
    pub altitude_m: f64,
    pub mach: f64,
    pub load_factor: f64,
}

/// `count` points of each model drawn (seeded) over `altitude_m` (rounded to 100 m) and `mach`
/// (rounded to 0.01), each in 1-g level flight and in an unloaded roll.
pub fn seeded_cases(
    seed: u64,
    models: &[(&'static str, usize)],
    altitude_m: (f64, f64),
    mach: (f64, f64),
) -> Vec<Case> {
    let mut rng = Rng::new(seed);
    let mut out = Vec::new();
    for &(model, count) in models {
        for _ in 0..count {
            let h = (rng.uniform(altitude_m.0, altitude_m.1) / 100.0).round() * 100.0;
            let m = (rng.uniform(mach.0, mach.1) * 100.0).round() / 100.0;
            for load_factor in [1.0, 0.0] {
                out.push(Case {
                    model,
                    altitude_m: h,
                    mach: m,
                    load_factor,
                });
            }
        }
    }
    out
}
