//! The other commands end to end: convert, continue, report, simulate and clear's map, on good
//! aircraft and on aircraft that lack a stiffness, damping or side force.

use super::*;

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
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("model-cli-cont-{}", std::process::id()));
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
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("model-cli-report-{}", std::process::id()));
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
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("model-cli-sim-{}", std::process::id()));
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

/// `import --help` (anywhere among its arguments) prints what each option means and the usage,
/// and succeeds; it is not an unknown option.
#[test]
fn import_help_prints_the_options_and_succeeds() {
    for args in [
        &["import", "--help"][..],
        &["import", "jsbsim", "--help"],
        &["import", "jsbsim", "f104", "-h"],
        &["help", "import"],
    ] {
        let out = model(args);
        assert_eq!(out.status.code(), Some(0), "{args:?}");
        let text = String::from_utf8_lossy(&out.stdout);
        assert!(text.contains("--load-factor") && text.contains("Usage: model import jsbsim"));
        assert!(out.stderr.is_empty(), "{args:?}");
    }
}

/// `model import jsbsim f104` at an altitude (m), Mach number and load factor.
fn import_f104(altitude: &str, mach: &str, n: &str) -> std::process::Output {
    model(&[
        "import",
        "jsbsim",
        "f104",
        "--altitude-m",
        altitude,
        "--mach",
        mach,
        "--load-factor",
        n,
    ])
}

/// An untrimmable condition is bad input (exit 2) whose message names the limit: the F-104 at
/// 3,000 m, Mach 1.2 pulling 7 g needs more nose-up elevator than its stabilator's travel
/// (FCS-pitch.xml: -0.35 rad), and at 6,000 m, Mach 0.6 no alpha up to 30 deg gives 3 g of lift.
/// The same conditions at 5 g and 1 g trim and import (exit 0).
#[test]
fn an_untrimmable_condition_exits_2_naming_the_limit() {
    if model::jsbsim::catalogue::root(None).is_none() {
        eprintln!("skipped: the JSBSim models are not installed (pip install jsbsim)");
        return;
    }
    for (mach, altitude, n, limit) in [
        (
            "1.2",
            "3000",
            "7",
            "beyond its travel of -20.05 deg to 17.19 deg",
        ),
        (
            "0.6",
            "6000",
            "3",
            "no lift solution from -10 to 30 deg alpha",
        ),
    ] {
        let out = import_f104(altitude, mach, n);
        assert_eq!(
            out.status.code(),
            Some(2),
            "{altitude} m, Mach {mach}, n = {n}"
        );
        let err = stderr(&out);
        assert!(
            err.starts_with(&format!("error: untrimmable at n = {n}: ")) && err.contains(limit),
            "{err}"
        );
        assert!(out.stdout.is_empty());
    }
    for (mach, altitude, n) in [("1.2", "3000", "5"), ("0.6", "6000", "1")] {
        let out = import_f104(altitude, mach, n);
        assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
        let text = String::from_utf8_lossy(&out.stdout);
        assert!(text.contains(&format!("load_factor = {n}.0")), "{text}");
    }
}
