//! `model analyze` end to end, as a user runs it: built-in aircraft, a user's file, bad input.

use std::path::PathBuf;
use std::process::{Command, Output};

fn model(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_model"))
        .args(args)
        .output()
        .expect("run the model binary")
}

fn repo(path: &str) -> String {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("..")
        .join(path)
        .to_string_lossy()
        .into_owned()
}

fn json(out: &Output) -> serde_json::Value {
    assert!(out.status.success(), "stderr: {}", String::from_utf8_lossy(&out.stderr));
    serde_json::from_slice(&out.stdout).expect("valid JSON")
}

#[test]
fn analyze_json_has_the_documented_shape() {
    let v = json(&model(&["analyze", "A", "--json"]));
    assert_eq!(v["aircraft"], "Aircraft A");
    assert!((v["delta_e_rad"].as_f64().unwrap() - 0.0349066).abs() < 1e-7);
    assert_eq!(v["divergence_roll_rates"].as_array().unwrap().len(), 0);
    let jump = v["jump"].as_array().unwrap();
    assert_eq!(jump.len(), 2);
    for key in ["p0", "delta_a_rad", "delta_a_deg", "alpha", "beta", "q", "r"] {
        assert!(jump[0][key].is_f64(), "jump[0].{key}");
    }
    assert!(v["det_k_poles"].is_array());
    let dep = v["zero_sideslip"]["departure"].as_array().unwrap();
    for key in ["p0", "delta_a_rad", "delta_a_deg", "alpha", "q", "r"] {
        assert!(dep[0][key].is_f64(), "departure[0].{key}");
    }
    assert!(dep[0].get("beta").is_none(), "beta is zero by construction and not reported");
}

#[test]
fn analyze_prints_a_table_for_b_and_a_users_file() {
    let out = model(&["analyze", "B"]);
    assert!(out.status.success());
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("Aircraft B") && text.contains("2.986460") && text.contains("4.627182"));
    let c = json(&model(&["analyze", &repo("aircraft/c.toml"), "--json", "--delta-e-deg", "-1.5"]));
    assert!((c["delta_e_rad"].as_f64().unwrap() + 1.5f64.to_radians()).abs() < 1e-15);
    // The built-in A and the shipped a.toml are the same aircraft.
    let from_file = json(&model(&["analyze", &repo("aircraft/a.toml"), "--json"]));
    let builtin = json(&model(&["analyze", "A", "--json"]));
    assert_eq!(from_file["jump"], builtin["jump"]);
}

#[test]
fn bad_input_exits_2_with_a_message_naming_the_file_and_key() {
    let dir = std::env::temp_dir().join(format!("model-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let text = std::fs::read_to_string(repo("aircraft/a.toml")).unwrap();
    let bad = dir.join("bad.toml");
    std::fs::write(&bad, text.replace("l_delta_a = -327.28", "l_delta_a = 0.0")).unwrap();
    let out = model(&["analyze", bad.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("bad.toml") && err.contains("l_delta_a"), "{err}");
    assert!(!err.contains("panicked"), "{err}");

    let out = model(&["analyze", dir.join("missing.toml").to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("missing.toml"));

    let out = model(&["analyze", "A", "--delta-e-deg", "nan"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("delta_e"));
}
