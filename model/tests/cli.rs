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
    assert!(
        out.status.success(),
        "stderr: {}",
        String::from_utf8_lossy(&out.stderr)
    );
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
    for key in [
        "p0",
        "delta_a_rad",
        "delta_a_deg",
        "alpha",
        "beta",
        "q",
        "r",
    ] {
        assert!(jump[0][key].is_f64(), "jump[0].{key}");
    }
    assert!(v["det_k_poles"].is_array());
    let dep = v["zero_sideslip"]["departure"].as_array().unwrap();
    for key in ["p0", "delta_a_rad", "delta_a_deg", "alpha", "q", "r"] {
        assert!(dep[0][key].is_f64(), "departure[0].{key}");
    }
    assert!(
        dep[0].get("beta").is_none(),
        "beta is zero by construction and not reported"
    );
}

#[test]
fn analyze_prints_a_table_for_b_and_a_users_file() {
    let out = model(&["analyze", "B"]);
    assert!(out.status.success());
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("Aircraft B") && text.contains("2.986460") && text.contains("4.627182"));
    let c = json(&model(&[
        "analyze",
        &repo("aircraft/c.toml"),
        "--json",
        "--delta-e-deg",
        "-1.5",
    ]));
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
    assert!(
        err.contains("bad.toml") && err.contains("l_delta_a"),
        "{err}"
    );
    assert!(!err.contains("panicked"), "{err}");

    let out = model(&["analyze", dir.join("missing.toml").to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("missing.toml"));

    let out = model(&["analyze", "A", "--delta-e-deg", "nan"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("delta_e"));
}

#[test]
fn continue_reports_the_folds_of_fig_1_as_json_and_csv() {
    let dir = std::env::temp_dir().join(format!("model-cli-cont-{}", std::process::id()));
    let csv = dir.join("a.csv");
    let v = json(&model(&[
        "continue",
        "A",
        "--json",
        "--csv",
        csv.to_str().unwrap(),
    ]));
    assert_eq!(v["parameter"], "delta_a");
    let point = &v["branches"][0]["points"][0];
    for key in ["delta_a", "alpha", "beta", "p", "q", "r"] {
        assert!(point[key].is_f64(), "point.{key}");
    }
    assert!(point["stable"].is_boolean());
    let folds: Vec<f64> = v["special_points"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|s| s["kind"] == "fold")
        .map(|s| s["p"].as_f64().unwrap())
        .filter(|p| *p > 0.0)
        .collect();
    // The jump roots of `analyze` (Fig. 7): 1.706288 and 3.033180.
    assert_eq!(folds.len(), 2, "{folds:?}");
    assert!(folds.iter().any(|p| (p - 1.706288).abs() < 1e-6));
    let text = std::fs::read_to_string(&csv).unwrap();
    assert!(
        text.starts_with("branch,delta_a_rad,alpha_rad,beta_rad,p_rad_s,q_rad_s,r_rad_s,stable"),
        "{}",
        &text[..60]
    );
    assert!(text.lines().count() > 100);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn continue_zero_sideslip_finds_the_branch_point_of_fig_9() {
    let v = json(&model(&["continue", "A", "--zero-sideslip", "--json"]));
    let bp: Vec<&serde_json::Value> = v["special_points"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|s| s["kind"] == "branch")
        .collect();
    // analyze: departure at P0 = 2.130625, delta_a = -0.14249 rad (paper: about -0.15 rad).
    assert!(
        bp.iter()
            .any(|s| (s["p"].as_f64().unwrap() - 2.130625).abs() < 1e-6
                && (s["delta_a"].as_f64().unwrap() + 0.14249).abs() < 1e-5),
        "{bp:?}"
    );
    let out = model(&["continue", "A", "--param", "delta_x"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("delta_x"));
}

#[test]
fn report_writes_every_figure_and_a_summary() {
    let dir = std::env::temp_dir().join(format!("model-cli-report-{}", std::process::id()));
    let out = model(&["report", "B", "--out", dir.to_str().unwrap()]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    for stem in [
        "fig01_bifurcation",
        "fig03_trim_states",
        "fig05_roll_response",
        "fig07_det_k",
        "fig09_zero_sideslip",
        "fig10_zero_sideslip_response",
        "fig11_zero_sideslip_det_k",
    ] {
        let png = std::fs::read(dir.join(format!("{stem}.png"))).unwrap();
        assert!(
            png.starts_with(b"\x89PNG") && png.len() > 10_000,
            "{stem}.png"
        );
        let svg = std::fs::read_to_string(dir.join(format!("{stem}.svg"))).unwrap();
        assert!(svg.contains("<svg"), "{stem}.svg");
    }
    let md = std::fs::read_to_string(dir.join("summary.md")).unwrap();
    // B's first jump (Fig. 8) and its Hopf points (Fig. 2) are in the report.
    assert!(md.contains("2.595015") && md.contains("hopf"), "{md}");
    assert!(md.contains("![Figs 1, 2](fig01_bifurcation.png)"));
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("summary.json")).unwrap()).unwrap();
    assert_eq!(summary["analysis"]["aircraft"], "Aircraft B");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn simulate_writes_a_time_history() {
    let dir = std::env::temp_dir().join(format!("model-cli-sim-{}", std::process::id()));
    let csv = dir.join("run.csv");
    let out = model(&[
        "simulate",
        "A",
        "--delta-a-deg",
        "-5",
        "--csv",
        csv.to_str().unwrap(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("steady roll rate"), "{text}");
    let rows = std::fs::read_to_string(&csv).unwrap();
    assert!(rows.lines().count() > 900, "20 s at 0.02 s");
    let bad = model(&["simulate", "A", "--delta-a-deg", "inf"]);
    assert_eq!(bad.status.code(), Some(2));
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Aircraft A's file with some values replaced, written to a temporary folder.
fn variant(tag: &str, replace: &[(&str, &str)]) -> (PathBuf, PathBuf) {
    let dir = std::env::temp_dir().join(format!("model-cli-{tag}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let mut text = std::fs::read_to_string(repo("aircraft/a.toml")).unwrap();
    for (from, to) in replace {
        assert!(text.contains(from), "{from}");
        text = text.replace(from, to);
    }
    let path = dir.join(format!("{tag}.toml"));
    std::fs::write(&path, text).unwrap();
    (dir, path)
}

#[test]
fn degenerate_aircraft_give_errors_or_partial_reports_never_panics() {
    // C D = 0 (the P0^4 coefficient of det A): det A is only quadratic in P0.
    let (dir, cd0) = variant("cd0", &[("D = 0.786", "D = 0.0")]);
    let out = model(&["analyze", cd0.to_str().unwrap(), "--json"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let rep = model(&[
        "report",
        cd0.to_str().unwrap(),
        "--out",
        dir.join("r").to_str().unwrap(),
    ]);
    assert!(
        rep.status.success(),
        "{}",
        String::from_utf8_lossy(&rep.stderr)
    );

    // No rudder authority: no zero-sideslip schedule; the rest of the report still appears.
    let (dir2, ndr0) = variant("ndr0", &[("n_delta_r = -1.0", "n_delta_r = 0.0")]);
    let sim = model(&[
        "simulate",
        ndr0.to_str().unwrap(),
        "--delta-a-deg",
        "-5",
        "--zero-sideslip",
    ]);
    assert_eq!(sim.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&sim.stderr).contains("n_delta_r"));
    let rep = model(&[
        "report",
        ndr0.to_str().unwrap(),
        "--out",
        dir2.join("r").to_str().unwrap(),
    ]);
    assert!(
        rep.status.success(),
        "{}",
        String::from_utf8_lossy(&rep.stderr)
    );
    let md = std::fs::read_to_string(dir2.join("r/summary.md")).unwrap();
    assert!(
        md.contains("Not computed for this aircraft") && md.contains("Fig. 9"),
        "{md}"
    );
    assert!(md.contains("fig01_bifurcation.png"));

    // No roll damping, stiffness or coupling: det J5 vanishes along the whole trim curve.
    let (dir3, flat) = variant(
        "flat",
        &[
            ("E = 0.705", "E = 0.0"),
            ("l_p = -21.7529", "l_p = 0.0"),
            ("l_r = 1.5207", "l_r = 0.0"),
            ("l_beta = -110.45", "l_beta = 0.0"),
        ],
    );
    let out = model(&["analyze", flat.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("vanishes identically"));

    let out = model(&["analyze", "A", "--delta-e-deg", "1e308"]);
    assert_eq!(out.status.code(), Some(2));
    for d in [dir, dir2, dir3] {
        std::fs::remove_dir_all(d).unwrap();
    }
}
