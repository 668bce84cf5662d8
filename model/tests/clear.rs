//! `model clear` end to end: bad `[uncertainty]` entries, zero-width boxes, the JSON shape.

use std::path::PathBuf;

mod support;

use support::{json, model};

fn aircraft_a_with(extra: &str, name: &str) -> PathBuf {
    let a = std::fs::read_to_string(
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../aircraft/a.toml"),
    )
    .unwrap();
    let dir = std::env::temp_dir().join(format!("model-clear-test-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, format!("{a}\n{extra}")).unwrap();
    path
}

#[test]
fn bad_uncertainty_entries_exit_2_naming_file_line_and_key() {
    // a.toml has 35 lines; the blank line and the table header follow, so the entry is line 38.
    let cases = [
        ("l_q = \"5%\"", "uncertainty.l_q"),
        ("l_p = -0.5", "negative width"),
        ("l_p = \"-5%\"", "negative width"),
        ("l_p = [-20.0, -22.0]", "non-empty interval"),
        ("l_delta_a = [-10.0, 10.0]", "keeps its sign"),
        ("E = [0.5, 1.2]", "unphysical"),
        ("l_p = [1.0]", "two numbers"),
        ("l_p = true", "half-width"),
    ];
    for (i, (entry, needle)) in cases.iter().enumerate() {
        let path = aircraft_a_with(
            &format!("[uncertainty]\n{entry}\n"),
            &format!("bad{i}.toml"),
        );
        let out = model(&["clear", path.to_str().unwrap(), "--samples", "1"]);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{entry}: {err}");
        let key = entry.split(' ').next().unwrap();
        assert!(err.contains(&format!("bad{i}.toml:")), "{entry}: {err}");
        assert!(
            err.contains(&format!("uncertainty.{key}")),
            "{entry}: {err}"
        );
        assert!(err.contains(needle), "{entry}: {err}");
        let lines = std::fs::read_to_string(&path).unwrap();
        let line = lines.lines().position(|l| l == *entry).unwrap() + 1;
        assert!(
            err.contains(&format!(":{line}:")),
            "{entry}: line {line}: {err}"
        );
    }
}

#[test]
fn zero_width_box_gives_lo_equal_hi_equal_analyze() {
    let path = aircraft_a_with("[uncertainty]\nl_p = 0.0\nn_beta = \"0%\"\n", "zero.toml");
    let c = json(&model(&[
        "clear",
        path.to_str().unwrap(),
        "--samples",
        "3",
        "--json",
    ]));
    let a = json(&model(&["analyze", "A", "--json"]));
    let p0 = a["critical"]["p0"].as_f64().unwrap();
    let da = a["critical"]["delta_a_deg"].as_f64().unwrap().abs();
    assert_eq!(c["critical_p0"]["lo"].as_f64(), Some(p0));
    assert_eq!(c["critical_p0"]["hi"].as_f64(), Some(p0));
    assert_eq!(c["critical_p0"]["converged"], true);
    assert_eq!(c["critical_delta_a_deg"]["lo"].as_f64(), Some(da));
    assert_eq!(c["critical_delta_a_deg"]["hi"].as_f64(), Some(da));
    for key in ["worst_case", "cleared", "counterexample", "monte_carlo"] {
        assert!(c.get(key).is_some(), "{key} missing");
    }
    assert_eq!(c["worst_case"]["l_p"].as_f64(), Some(-21.7529));
    assert_eq!(c["worst_case"]["p0"].as_f64(), Some(p0));
    assert_eq!(c["monte_carlo"]["samples"], 3);
    // The Monte Carlo runs the certified floating-point route: its roll rate lies in a
    // certified bracket of relative width 1e-9 around the exact root.
    let mc = c["monte_carlo"]["min_p0"].as_f64().unwrap();
    assert!((mc - p0).abs() <= 1e-9 * p0, "{mc} vs {p0}");
    assert!(c["cleared"].is_null());
}
