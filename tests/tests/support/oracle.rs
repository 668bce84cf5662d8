//! Running a Python oracle script of `tests/oracle/`: the request as JSON on its standard
//! input, the answer as JSON on the last line of its standard output. Shared by `jsbsim.rs`,
//! `jsbsim_trim.rs` (through `support`) and `jsbsim_limits.rs`.

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
