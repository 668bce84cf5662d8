//! `model simulate jsbsim:... --six-dof` of the small fixture model (tests/fixtures/
//! jsbsim_jet.xml): the CSV and the figure written; the run starts in the equilibrium of the
//! 1-g trim; bad input is refused with exit 2.

use super::{model, scratch, stderr};
use std::path::PathBuf;

/// The fixture as a `jsbsim:` source.
fn source() -> String {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/jsbsim_jet.xml");
    format!("jsbsim:{}", path.display())
}

/// `simulate` of the fixture at 5,000 m, Mach 0.6 with `extra` options.
fn six_dof(extra: &[&str]) -> std::process::Output {
    let source = source();
    let mut args = vec![
        "simulate",
        &source,
        "--six-dof",
        "--altitude-m",
        "5000",
        "--mach",
        "0.6",
    ];
    args.extend(extra);
    model(&args)
}

/// The columns of a CSV file as numbers, by header name.
fn column(csv: &str, name: &str) -> Vec<f64> {
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let k = header.iter().position(|h| *h == name).unwrap();
    lines
        .map(|l| l.split(',').nth(k).unwrap().parse().unwrap())
        .collect()
}

#[test]
fn the_six_dof_writes_its_time_history_and_figure() {
    let dir = scratch("six-dof-run");
    let csv = dir.join("run.csv");
    let figures = dir.join("figures");
    let out = six_dof(&[
        "--delta-a-deg",
        "-5",
        "--t-end",
        "2",
        "--csv",
        csv.to_str().unwrap(),
        "--out",
        figures.to_str().unwrap(),
    ]);
    assert!(out.status.success(), "{}", stderr(&out));
    let text = std::fs::read_to_string(&csv).unwrap();
    assert!(text.starts_with(
        "t_s,alpha_rad,beta_rad,p_rad_s,q_rad_s,r_rad_s,V_m_s,h_m,mach,phi_rad,theta_rad,psi_rad"
    ));
    // 2 s at 120 Hz and the start; the aileron rolls right (JSBSim's sign: p > 0).
    let p = column(&text, "p_rad_s");
    assert_eq!(p.len(), 241);
    assert!(p[240] > 0.1, "{}", p[240]);
    for f in ["six_dof.svg", "six_dof.png", "six_dof.csv"] {
        assert!(figures.join(f).is_file(), "{f}");
    }
    let said = String::from_utf8_lossy(&out.stdout);
    assert!(
        said.contains("trim alpha") && said.contains("settled roll rate"),
        "{said}"
    );
}

/// The run starts at the trim: in level flight (n = 1) the lift carries the weight and the
/// pitching moment is zero, so over the first step (1/120 s) alpha and q move only by what the
/// changing speed (thrust off: the drag decelerates) does to second order. A lift or a moment
/// off by 1 % of the weight's would move alpha by about 4e-6 rad in a step (0.01 g / V dt).
#[test]
fn the_run_starts_in_the_trims_equilibrium() {
    let dir = scratch("six-dof-trim");
    let csv = dir.join("run.csv");
    let out = six_dof(&[
        "--delta-a-deg",
        "0",
        "--t-end",
        "0.1",
        "--csv",
        csv.to_str().unwrap(),
    ]);
    assert!(out.status.success(), "{}", stderr(&out));
    let text = std::fs::read_to_string(&csv).unwrap();
    let alpha = column(&text, "alpha_rad");
    let q = column(&text, "q_rad_s");
    assert!(
        (alpha[1] - alpha[0]).abs() < 1e-7,
        "{}",
        alpha[1] - alpha[0]
    );
    assert!(q[0] == 0.0 && q[1].abs() < 1e-7, "{}", q[1]);
    // Wings level and no sideslip stay exactly so without an aileron.
    assert!(column(&text, "p_rad_s").iter().all(|p| *p == 0.0));
    assert!(column(&text, "beta_rad").iter().all(|b| *b == 0.0));
}

#[test]
fn bad_six_dof_input_is_refused_with_exit_2() {
    let out = model(&["simulate", "A", "--six-dof", "--delta-a-deg", "5"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(stderr(&out).contains("the 6-DOF simulates a JSBSim airframe"));
    for (args, said) in [
        (
            ["--delta-a-deg", "5", "--thrust", "full"],
            "--thrust full: expected off or trim",
        ),
        (
            ["--delta-a-deg", "5", "--dt", "0"],
            "--dt = 0: expected an integration step",
        ),
        (
            ["--delta-a-deg", "5", "--t-end", "-1"],
            "--t-end = -1: expected the length of the run",
        ),
        (
            ["--delta-a-deg", "nan", "--t-end", "1"],
            "--delta-a-deg = NaN: expected a finite",
        ),
    ] {
        let out = six_dof(&args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        assert!(stderr(&out).contains(said), "{}", stderr(&out));
    }
    // The 6-DOF's options need --six-dof: the 7th-order simulate is unchanged.
    let out = model(&["simulate", "A", "--delta-a-deg", "5", "--mach", "0.5"]);
    assert_eq!(out.status.code(), Some(2));
}

#[test]
fn validate_writes_the_plateau_and_a_verdict_per_model() {
    let dir = scratch("validate");
    let source = source();
    let args = [
        "validate",
        &source,
        "--altitude-m",
        "5000",
        "--mach",
        "0.6",
        "--delta-a-deg",
        "2:6:2",
        "--t-end",
        "4",
        "--out",
        dir.to_str().unwrap(),
    ];
    let out = model(&args);
    assert!(out.status.success(), "{}", stderr(&out));
    let said = String::from_utf8_lossy(&out.stdout);
    assert!(
        said.contains("7th-order model: ") && said.contains("6-DOF: "),
        "{said}"
    );
    assert!(said.contains("largest change: V"), "{said}");
    assert!(dir.join("plateau.png").is_file() && dir.join("plateau.csv").is_file());
    let out = model(&["validate", "A"]);
    assert_eq!(out.status.code(), Some(2));
    let mut bad = args;
    bad[7] = "6:2:1";
    let out = model(&bad);
    assert_eq!(out.status.code(), Some(2));
    assert!(
        stderr(&out).contains("expected A:B:STEP"),
        "{}",
        stderr(&out)
    );
}
