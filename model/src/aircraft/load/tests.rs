//! Tests of reading aircraft files: the files accepted, what unusual text and literals become,
//! and a table of refused files with the line, key and expectation each error names.

use super::*;

const GOOD: &str = r#"name = "T"
[inertia]
C = 0.959
D = 0.786
E = 0.705
[derivatives]
z_alpha = -3.0076
y_beta = -0.0558
l_p = -21.7529
l_r = 1.5207
l_beta = -110.45
l_delta_a = -327.28
m_q = -1.815
m_alpha = -13.52504
m_delta_e = -33.268
n_p = 0
n_r = -0.2608
n_beta = 3.716
n_delta_a = 0.0
[flight]
speed = 150.0
"#;

const FILE: &str = "test_plane.toml";

/// Parses `text`, expects an error, and checks the message holds the file, the line, and
/// every one of `needles`.
fn err(text: &str, line: usize, needles: &[&str]) -> AircraftError {
    let e = match parse(text, FILE) {
        Ok(a) => panic!("expected an error, got {a:?}"),
        Err(e) => e,
    };
    let msg = e.to_string();
    assert!(msg.contains(FILE), "no file name in: {msg}");
    assert!(
        msg.contains(&format!("{FILE}:{line}:")),
        "no line {line} in: {msg}"
    );
    for n in needles {
        assert!(msg.contains(n), "no `{n}` in: {msg}");
    }
    assert_eq!(e.location().map(|l| l.line), Some(line), "{msg}");
    e
}

fn replace(from: &str, to: &str) -> String {
    assert!(GOOD.contains(from), "{from}");
    GOOD.replacen(from, to, 1)
}

mod accepted;
mod literals;
mod refused;
