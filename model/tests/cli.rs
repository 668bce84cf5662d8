//! `model analyze` end to end, as a user runs it: built-in aircraft, a user's file, bad input.

use std::path::PathBuf;
use std::process::{Command, Output};

mod support;

use support::{json, model, reference};

fn repo(path: &str) -> String {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("..")
        .join(path)
        .to_string_lossy()
        .into_owned()
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
    assert!(text.contains("Aircraft B"));
    let (divergence, jump) = (reference::B_DIVERGENCE_P0[0], reference::B_JUMP_P0[3]);
    assert!(text.contains(&format!("{divergence:.6}")) && text.contains(&format!("{jump:.6}")));
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

/// A file with `text` in a temporary folder.
fn scratch_file(name: &str, text: &str) -> PathBuf {
    let path = scratch(&format!("convert-{name}")).join(name);
    std::fs::write(&path, text).unwrap();
    path
}

#[test]
fn convert_prints_a_dimensional_file_that_loads_as_the_same_aircraft() {
    let src = repo("aircraft/fighter.toml");
    let out = model(&["convert", &src]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.contains("# Principal x axis tilt: 1.04"), "{text}");
    assert!(
        text.contains("[derivatives]") && text.contains("[limits]"),
        "{text}"
    );
    let converted = scratch_file("fighter-dimensional.toml", &text);
    let a = model::aircraft::load(std::path::Path::new(&src)).unwrap();
    let b = model::aircraft::load(&converted).unwrap();
    assert_eq!(a, b);
}

#[test]
fn convert_refuses_dimensional_and_bad_files_with_exit_2() {
    let out = model(&["convert", &repo("aircraft/a.toml")]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("a.toml:1:1") && err.contains("already"),
        "{err}"
    );

    let text = std::fs::read_to_string(repo("aircraft/fighter.toml")).unwrap();
    let bad = scratch_file(
        "bad-mass.toml",
        &text.replacen("mass = 9300.0", "mass = -9300.0", 1),
    );
    for cmd in ["convert", "analyze"] {
        let out = model(&[cmd, bad.to_str().unwrap()]);
        assert_eq!(out.status.code(), Some(2), "{cmd}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(
            err.contains("bad-mass.toml:") && err.contains("geometry.mass") && err.contains("> 0"),
            "{cmd}: {err}"
        );
    }
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
    // The jump roots of `analyze` (Fig. 7).
    assert_eq!(folds.len(), 2, "{folds:?}");
    assert!(folds
        .iter()
        .any(|p| (p - reference::A_JUMP_P0[0]).abs() < 1e-6));
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
    // analyze's zero-sideslip departure (Fig. 11; the paper: about -0.15 rad of aileron).
    let (p0, delta_a) = (
        reference::A_ZERO_SIDESLIP_P0[0],
        reference::A_ZERO_SIDESLIP_DELTA_A_DEG.to_radians(),
    );
    assert!(
        bp.iter()
            .any(|s| (s["p"].as_f64().unwrap() - p0).abs() < 1e-6
                && (s["delta_a"].as_f64().unwrap() - delta_a).abs() < 1e-5),
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
        let doc = roxmltree::Document::parse(&svg).unwrap_or_else(|e| panic!("{stem}.svg: {e}"));
        assert_eq!(doc.root_element().tag_name().name(), "svg", "{stem}.svg");
    }
    let md = std::fs::read_to_string(dir.join("summary.md")).unwrap();
    // B's first jump (Fig. 8) and its Hopf points (Fig. 2) are in the report.
    let jump = format!("{:.6}", reference::B_JUMP_P0[0]);
    assert!(md.contains(&jump) && md.contains("hopf"), "{md}");
    assert!(md.contains("![Figs 1, 2](fig01_bifurcation.png)"));
    // Which instability comes first on the primary branch: B's first fold, before its Hopf
    // points.
    let first = format!(
        "First loss of stability on the primary branch: JUMP at P0 = {jump} rad/s, delta_a = {:.4} deg",
        reference::B_FOLD_DELTA_A_DEG
    );
    assert!(md.contains(&first), "{md}");
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("summary.json")).unwrap()).unwrap();
    assert_eq!(summary["analysis"]["aircraft"], "Aircraft B");
    let departure = &summary["analysis"]["first_departure"];
    assert_eq!(departure["kind"], "jump", "{departure}");
    let p0 = departure["p0"].as_f64().unwrap();
    assert!((p0 - reference::B_JUMP_P0[0]).abs() < 1e-6, "{departure}");
    // Fig. 1 marks the closed-form Hopf points at AUTO-07p's roll rates (and their mirror
    // images at -P0), apart from the continuation's; the CSV names each. (B's third Hopf point,
    // at +75.7 deg of aileron, lies beyond the figure's +-0.8 rad.)
    let csv = std::fs::read_to_string(dir.join("fig01_bifurcation.csv")).unwrap();
    let hopf: Vec<f64> = csv
        .lines()
        .filter(|row| row.contains(",marker,closed-form Hopf point"))
        .map(|row| row.rsplit(',').next().unwrap().parse().unwrap())
        .collect();
    assert_eq!(hopf.len(), 4, "{hopf:?}");
    for (p0, _, _) in reference::B_HOPF {
        assert!(hopf.iter().any(|p| (p - p0).abs() < 1e-6), "{p0}: {hopf:?}");
    }
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
    // D = 0 makes E = C for a rigid body.
    let (dir, cd0) = variant(
        "cd0",
        &[("D = 0.786", "D = 0.0"), ("E = 0.705", "E = 0.959")],
    );
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

    // No roll damping, stiffness or coupling: det J5 vanishes along the whole trim curve. (E = 0
    // needs C = D for a rigid body.)
    let (dir3, flat) = variant(
        "flat",
        &[
            ("E = 0.705", "E = 0.0"),
            ("C = 0.959", "C = 0.786"),
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

/// A fresh temporary folder for one test.
fn scratch(tag: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("model-cli-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn stderr(out: &Output) -> String {
    String::from_utf8_lossy(&out.stderr).into_owned()
}

#[cfg(unix)]
#[test]
fn stdout_write_errors_end_quietly_on_a_closed_pipe_and_loudly_otherwise() {
    use std::process::Stdio;
    // /dev/full: one line naming stdout and the OS error, exit 1, no panic.
    let full = std::fs::File::create("/dev/full").unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_model"))
        .args(["analyze", "A"])
        .stdout(full)
        .output()
        .unwrap();
    let err = stderr(&out);
    assert_eq!(out.status.code(), Some(1), "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.contains("stdout") && err.contains("os error 28"),
        "{err}"
    );
    assert!(!err.contains("panicked"), "{err}");
    // A reader that has gone (`| head -1` after its line): quiet, exit 0.
    let mut child = Command::new(env!("CARGO_BIN_EXE_model"))
        .args(["continue", "B", "--json"])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    drop(child.stdout.take());
    let out = child.wait_with_output().unwrap();
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    assert_eq!(stderr(&out), "");
}

#[cfg(unix)]
#[test]
fn csv_goes_into_devices_and_through_symlinks_and_failures_are_reported() {
    let dir = scratch("csv-targets");
    let sim = |csv: &str| {
        model(&[
            "simulate",
            "A",
            "--delta-a-deg",
            "-5",
            "--t-end",
            "2",
            "--csv",
            csv,
        ])
    };
    let out = sim("/dev/full");
    assert_eq!(out.status.code(), Some(1), "{}", stderr(&out));
    assert!(stderr(&out).contains("/dev/full"), "{}", stderr(&out));
    assert!(
        !std::fs::metadata("/dev/full").unwrap().is_file(),
        "device kept"
    );
    // /dev/stdout: the rows arrive on stdout, and /dev/stdout stays what it was.
    let out = sim("/dev/stdout");
    assert!(out.status.success(), "{}", stderr(&out));
    assert!(String::from_utf8_lossy(&out.stdout).starts_with("t_s,alpha_rad"));
    assert!(std::fs::symlink_metadata("/dev/stdout")
        .unwrap()
        .file_type()
        .is_symlink());
    // A symlink: its target gets the rows, the link stays a link.
    let target = dir.join("target.csv");
    let link = dir.join("link.csv");
    std::os::unix::fs::symlink(&target, &link).unwrap();
    let out = sim(link.to_str().unwrap());
    assert!(out.status.success(), "{}", stderr(&out));
    assert!(std::fs::symlink_metadata(&link)
        .unwrap()
        .file_type()
        .is_symlink());
    assert!(std::fs::read_to_string(&target)
        .unwrap()
        .starts_with("t_s,"));
    // A directory in the way: named, exit 1.
    let out = sim(dir.to_str().unwrap());
    assert_eq!(out.status.code(), Some(1));
    assert!(stderr(&out).contains("cannot write"), "{}", stderr(&out));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn plot_writes_what_it_can_names_each_failed_file_and_removes_stale_temporaries() {
    let dir = scratch("plot-fail");
    // A directory where a figure should go, and the temporary of a killed run (no such PID).
    std::fs::create_dir_all(dir.join("fig07_det_k.png")).unwrap();
    let stale = dir.join(".fig01_bifurcation.svg.tmp-4194305-0");
    std::fs::write(&stale, "half a figure").unwrap();
    // ... and of a file `plot` does not write (a killed `report`'s summary).
    let stale_summary = dir.join(".summary.md.tmp-4194305-1");
    std::fs::write(&stale_summary, "half a summary").unwrap();
    let out = model(&["plot", "B", "--out", dir.to_str().unwrap()]);
    let err = stderr(&out);
    assert_eq!(out.status.code(), Some(1), "{err}");
    assert!(err.contains("fig07_det_k.png"), "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        !stale.exists() && !stale_summary.exists(),
        "stale temporaries removed"
    );
    // The written files of the incomplete figure are announced like the others.
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.contains("fig07_det_k.svg") && text.contains("fig07_det_k.csv"),
        "{text}"
    );
    assert!(!text.contains("fig07_det_k.png"), "{text}");
    for f in [
        "fig01_bifurcation.svg",
        "fig07_det_k.svg",
        "fig07_det_k.csv",
        "fig11_zero_sideslip_det_k.png",
    ] {
        assert!(dir.join(f).is_file(), "{f}");
    }
    let leftovers: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.contains(".tmp"))
        .collect();
    assert!(leftovers.is_empty(), "{leftovers:?}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn report_with_no_yaw_stiffness_is_bounded_by_the_aileron_range_and_says_what_it_skipped() {
    // n_beta = 0 puts A's fold at delta_a = -110905 deg, far outside the aileron range.
    let (dir, path) = variant("nbeta0", &[("n_beta = 3.716", "n_beta = 0.0")]);
    let start = std::time::Instant::now();
    let out = model(&[
        "report",
        path.to_str().unwrap(),
        "--out",
        dir.join("r").to_str().unwrap(),
    ]);
    assert!(out.status.success(), "{}", stderr(&out));
    assert!(start.elapsed().as_secs() < 120, "{:?}", start.elapsed());
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.contains("skipped: simulated jump") && text.contains("aileron range"),
        "{text}"
    );
    let md = std::fs::read_to_string(dir.join("r/summary.md")).unwrap();
    assert!(
        md.contains("beyond the aileron range of +-30.0 deg"),
        "{md}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn answers_that_are_not_finite_or_cannot_be_told_apart_are_refused() {
    // An inertia coefficient beyond f64 (E = 0.6/1e-309) is refused, with no NaN printed; a
    // secondary section alone is withheld
    // (`a_tiny_elevator_withholds_the_zero_sideslip_section_only`).
    let dir = scratch("tiny-ix");
    let c = std::fs::read_to_string(repo("aircraft/c.toml")).unwrap();
    let ix = dir.join("ix.toml");
    std::fs::write(&ix, c.replace("ix = 1.0", "ix = 1e-309")).unwrap();
    let out = model(&["analyze", ix.to_str().unwrap()]);
    assert!(stderr(&out).contains("beyond f64"), "{}", stderr(&out));
    assert_eq!(
        out.status.code(),
        Some(2),
        "{}",
        String::from_utf8_lossy(&out.stdout)
    );
    assert!(!String::from_utf8_lossy(&out.stdout).contains("NaN"));
    // m_alpha = -1e308: distinct exact poles (and jump roots) that round to one f64.
    let (dir2, big) = variant("malpha", &[("m_alpha = -13.52504", "m_alpha = -1e308")]);
    let out = model(&["analyze", big.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    assert!(
        stderr(&out).contains("cannot be told apart in f64"),
        "{}",
        stderr(&out)
    );
    for d in [dir, dir2] {
        std::fs::remove_dir_all(d).unwrap();
    }
}

#[test]
fn negative_values_are_accepted_and_judged_in_the_unit_typed() {
    let out = model(&["simulate", "A", "--delta-a-deg", "-5", "--t-end", "-1"]);
    assert_eq!(out.status.code(), Some(2));
    let err = stderr(&out);
    assert!(
        err.contains("--t-end = -1") && err.contains("positive"),
        "{err}"
    );
    let out = model(&["analyze", "A", "--delta-e-deg", "-inf"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(
        stderr(&out).contains("--delta-e-deg = -inf"),
        "{}",
        stderr(&out)
    );
    let out = model(&["analyze", "A", "--delta-e-deg", "1e9"]);
    assert_eq!(out.status.code(), Some(2));
    let err = stderr(&out);
    assert!(
        err.contains("1000000000") && err.contains("90 deg") && !err.contains("rad"),
        "{err}"
    );
    // continue's range is in degrees, negative numbers welcome.
    let v = json(&model(&[
        "continue",
        "A",
        "--min-deg",
        "-1e-300",
        "--max-deg",
        "10",
        "--json",
    ]));
    let max = v["branches"]
        .as_array()
        .unwrap()
        .iter()
        .flat_map(|b| b["points"].as_array().unwrap())
        .map(|p| p["delta_a"].as_f64().unwrap())
        .fold(f64::MIN, f64::max);
    assert!(max <= 10f64.to_radians() + 1e-12, "{max}");
    let out = model(&["continue", "A", "--min-deg", "5", "--max-deg", "-5"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(stderr(&out).contains("--min-deg = 5"), "{}", stderr(&out));
}

#[test]
fn a_failed_integration_reports_the_time_it_failed() {
    let out = model(&["simulate", "A", "--delta-a-deg", "-5", "--t-end", "1e5"]);
    assert_eq!(out.status.code(), Some(2));
    let err = stderr(&out);
    let t: f64 = err
        .split("failed at t = ")
        .nth(1)
        .and_then(|r| r.split(' ').next())
        .and_then(|v| v.parse().ok())
        .unwrap_or_else(|| panic!("{err}"));
    assert!(t > 20.0, "{err}");
}

#[test]
fn names_are_escaped_and_unknown_names_get_the_built_ins() {
    let (dir, path) = variant(
        "ctrl",
        &[(
            "name = \"Aircraft A\"",
            "name = \"Evil\\u001b[31m red\\u0007\"",
        )],
    );
    // A name with control characters is refused, naming the key.
    let out = model(&["analyze", path.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2), "{}", stderr(&out));
    assert!(stderr(&out).contains("key `name`"), "{}", stderr(&out));
    // A file without a name is named by its file name, printed escaped.
    let text = std::fs::read_to_string(repo("aircraft/a.toml")).unwrap();
    let unnamed = dir.join("Evil\u{1b}[31m red\u{7}.toml");
    std::fs::write(&unnamed, text.replace("name = \"Aircraft A\"\n", "")).unwrap();
    let out = model(&["analyze", unnamed.to_str().unwrap()]);
    assert!(out.status.success(), "{}", stderr(&out));
    assert!(!out.stdout.contains(&0x1b) && !out.stdout.contains(&0x07));
    assert!(String::from_utf8_lossy(&out.stdout).contains("Evil\\u{1b}[31m red\\u{7}"));
    let out = model(&["analyze", "C"]);
    assert_eq!(out.status.code(), Some(2));
    let err = stderr(&out);
    assert!(
        err.contains("A and B") && err.contains("aircraft/c.toml"),
        "{err}"
    );
    let help = model(&["analyze", "--help"]);
    assert!(
        String::from_utf8_lossy(&help.stdout).contains("else the path of an aircraft TOML file")
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn no_colour_codes_when_not_on_a_terminal_even_in_ci() {
    let out = Command::new(env!("CARGO_BIN_EXE_model"))
        .args(["analyze", "A", "--no-such-option"])
        .env("CI", "true")
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(!out.stderr.contains(&0x1b), "{}", stderr(&out));
    let help = Command::new(env!("CARGO_BIN_EXE_model"))
        .args(["report", "--help"])
        .env("CI", "true")
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&help.stdout);
    assert!(!help.stdout.contains(&0x1b));
    assert!(
        text.contains("summary.json") && text.contains("--out <DIR>"),
        "{text}"
    );
}

/// Every file under `dir`, relative, with its contents.
fn tree(dir: &std::path::Path) -> std::collections::BTreeMap<PathBuf, Vec<u8>> {
    let mut files = std::collections::BTreeMap::new();
    let mut todo = vec![dir.to_path_buf()];
    while let Some(d) = todo.pop() {
        for e in std::fs::read_dir(&d).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                todo.push(p);
            } else {
                let rel = p.strip_prefix(dir).unwrap().to_path_buf();
                files.insert(rel, std::fs::read(&p).unwrap());
            }
        }
    }
    files
}

#[test]
fn emit_killed_at_random_points_leaves_all_old_or_all_new_and_the_next_run_cleans_up() {
    let root = scratch("emit-kill");
    let emit = |check: bool| {
        let mut c = Command::new(env!("CARGO_BIN_EXE_model"));
        c.args(["emit", "--root", root.to_str().unwrap()]);
        if check {
            c.arg("--check");
        }
        c
    };
    let start = std::time::Instant::now();
    assert!(emit(false).output().unwrap().status.success());
    let full_run = start.elapsed();
    let new = tree(&root);
    assert!(new.len() >= 5, "{:?}", new.keys());
    let old: std::collections::BTreeMap<PathBuf, Vec<u8>> = new
        .iter()
        .map(|(p, c)| (p.clone(), [c.as_slice(), b"\n// old\n"].concat()))
        .collect();
    // Pseudo-random delays (xorshift, seed printed): half over the whole run, half over its
    // last fifth, where the files are written.
    let mut seed = u64::from(std::process::id()).wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1;
    println!("seed {seed}, full run {full_run:?}");
    let mut next = move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed % 10_000) as f64 / 10_000.0
    };
    let (mut all_old, mut all_new) = (0, 0);
    let runs = 24;
    for i in 0..runs {
        for (p, c) in &old {
            std::fs::write(root.join(p), c).unwrap();
        }
        let u = next();
        let frac = if i % 2 == 0 { 1.2 * u } else { 0.8 + 0.3 * u };
        let mut child = emit(false)
            .stdout(std::process::Stdio::null())
            .spawn()
            .unwrap();
        std::thread::sleep(full_run.mul_f64(frac));
        let _ = child.kill();
        let _ = child.wait();
        // Right after the kill: old, new, or committed (journal present, finished next run).
        let now = tree(&root);
        let visible: std::collections::BTreeMap<_, _> = now
            .iter()
            .filter(|(p, _)| {
                !p.to_string_lossy().contains(".tmp-") && !p.ends_with(".emit-journal")
            })
            .map(|(p, c)| (p.clone(), c.clone()))
            .collect();
        let committed = now.keys().any(|p| p.ends_with(".emit-journal"));
        assert!(
            visible == old || visible == new || committed,
            "run {i}: a mix of old and new files without a journal"
        );
        // The next run (`emit --check`) finishes or discards what the killed one left.
        let _ = emit(true).output().unwrap();
        let after = tree(&root);
        assert!(
            after
                .keys()
                .all(|p| !p.to_string_lossy().contains(".tmp-") && !p.ends_with(".emit-journal")),
            "run {i}: leftovers {:?}",
            after.keys().collect::<Vec<_>>()
        );
        if after == old {
            all_old += 1;
        } else if after == new {
            all_new += 1;
        } else {
            panic!("run {i} (killed at {frac:.2} of a run): neither all old nor all new");
        }
    }
    println!("{runs} killed runs: {all_old} left every old file, {all_new} every new file");
    std::fs::remove_dir_all(&root).unwrap();
}

/// The fenced block of `lang` that follows `after` in the README.
fn readme_block(after: &str, lang: &str) -> String {
    let readme = std::fs::read_to_string(repo("README.md")).unwrap();
    let rest = &readme[readme.find(after).unwrap_or_else(|| panic!("{after}")) + after.len()..];
    let fence = format!("```{lang}\n");
    let start = rest.find(&fence).unwrap() + fence.len();
    let end = start + rest[start..].find("```").unwrap();
    rest[start..end].to_string()
}

#[test]
fn readme_shows_the_real_output_of_the_main_job() {
    let text = model(&["analyze", "A"]);
    assert_eq!(
        readme_block(
            "cargo run --release -p model -- analyze A\n```\n\nprints",
            "text"
        ),
        String::from_utf8_lossy(&text.stdout)
    );
    let json = model(&["analyze", "A", "--json"]);
    assert_eq!(
        readme_block("`analyze A --json` prints", "json"),
        String::from_utf8_lossy(&json.stdout)
    );
}

/// `model args` killed after `limit`: `Some(output)` when it ended in time, `None` on a hang.
fn model_within(args: &[&str], limit: std::time::Duration) -> Option<Output> {
    let mut child = Command::new(env!("CARGO_BIN_EXE_model"))
        .args(args)
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let start = std::time::Instant::now();
    while start.elapsed() < limit {
        if child.try_wait().unwrap().is_some() {
            return Some(child.wait_with_output().unwrap());
        }
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    child.kill().unwrap();
    child.wait().unwrap();
    None
}

/// Aircraft A without yaw stiffness, yaw damping and side force (all three, or two of them)
/// once made `analyze` and `report` loop forever in an eigenvalue decomposition. Every command
/// ends within 120 s with an answer or a refusal (exit 0 or 2), never a panic or a hang.
#[test]
fn aircraft_without_yaw_stiffness_damping_and_side_force_end_every_command() {
    let limit = std::time::Duration::from_secs(120);
    let zero = [
        ("n_beta = 3.716", "n_beta = 0.0"),
        ("n_r = -0.2608", "n_r = 0.0"),
        ("y_beta = -0.0558", "y_beta = 0.0"),
    ];
    for (tag, skip) in [("yaw-all", 3), ("yaw-no-nbeta", 0), ("yaw-no-nr", 1)] {
        let replace: Vec<_> = (0..3).filter(|i| *i != skip).map(|i| zero[i]).collect();
        let (dir, file) = variant(tag, &replace);
        let file = file.to_str().unwrap();
        let out_dir = dir.join("report");
        let out_dir = out_dir.to_str().unwrap();
        for args in [
            vec!["analyze", file],
            vec!["analyze", file, "--json"],
            vec!["analyze", file, "--exact"],
            vec!["continue", file],
            vec!["simulate", file, "--delta-a-deg", "-5"],
            vec!["report", file, "--out", out_dir],
        ] {
            let out = model_within(&args, limit).unwrap_or_else(|| {
                panic!("`model {}` still running after {limit:?}", args.join(" "))
            });
            let err = stderr(&out);
            assert!(matches!(out.status.code(), Some(0 | 2)), "{args:?}: {err}");
            assert!(!err.contains("panicked"), "{args:?}: {err}");
            assert!(
                !String::from_utf8_lossy(&out.stdout).contains("NaN"),
                "{args:?}"
            );
        }
        std::fs::remove_dir_all(&dir).unwrap();
    }
}

/// A tiny elevator deflection makes two zero-sideslip departure roots round to the same f64:
/// that section alone is withheld, with the reason, and the main answer is printed (text and
/// JSON, exit 0).
#[test]
fn a_tiny_elevator_withholds_the_zero_sideslip_section_only() {
    let out = model(&["analyze", "A", "--delta-e-deg", "1e-300"]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    // At delta_e = 0 aircraft A's primary branch has no fold: that is the main answer.
    assert!(
        text.contains("No critical jump: the primary branch reaches |delta_a| = 90.0 deg"),
        "{text}"
    );
    assert!(
        text.contains("  withheld: two zero-sideslip departure roots"),
        "{text}"
    );
    let v = json(&model(&[
        "analyze",
        "A",
        "--delta-e-deg",
        "1e-300",
        "--json",
    ]));
    assert!(v["critical"].is_null(), "{v}");
    assert!(
        v["critical_note"]
            .as_str()
            .unwrap()
            .contains("without a jump"),
        "{v}"
    );
    let zs = &v["zero_sideslip"];
    assert!(
        zs["withheld"]
            .as_str()
            .unwrap()
            .contains("cannot be told apart"),
        "{zs}"
    );
    assert_eq!(zs["departure"], serde_json::json!([]));
    // An ordinary elevator answers the section.
    let v = json(&model(&["analyze", "A", "--json"]));
    assert!(v["zero_sideslip"]["withheld"].is_null());
    assert!(!v["zero_sideslip"]["departure"]
        .as_array()
        .unwrap()
        .is_empty());
}

/// A clearance map over several elevator settings says on stderr, once the first is proven,
/// how long the others will take at that pace, and draws a histogram for each setting beside
/// the map; the result on stdout is the JSON array of the settings.
#[test]
fn a_clearance_map_says_how_long_it_will_take_and_draws_every_setting() {
    let file = repo("aircraft/a_uncertain.toml");
    let dir = scratch("clear-map");
    let out_dir = dir.join("out");
    let args = [
        "clear",
        &file,
        "--delta-e-range",
        "0:2:1",
        "--samples",
        "10",
        "--json",
        "--out",
        out_dir.to_str().unwrap(),
    ];
    let out = model(&args);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    let err = stderr(&out);
    assert!(
        err.starts_with("clear: 3 elevator settings; the first took ")
            && err.contains(" s, so the other 2 will take about "),
        "{err}"
    );
    let runs = json(&out);
    assert_eq!(runs.as_array().map(Vec::len), Some(3), "{runs}");
    for stem in [
        "clearance_histogram_1",
        "clearance_histogram_2",
        "clearance_histogram_3",
        "clearance_map",
    ] {
        let svg = std::fs::read_to_string(out_dir.join(format!("{stem}.svg"))).unwrap();
        let doc = roxmltree::Document::parse(&svg).unwrap_or_else(|e| panic!("{stem}: {e}"));
        assert_eq!(doc.root_element().tag_name().name(), "svg");
    }
    assert!(!out_dir.join("clearance_histogram.svg").exists());
    std::fs::remove_dir_all(&dir).unwrap();
}
