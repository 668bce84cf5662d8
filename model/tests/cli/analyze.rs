//! `model analyze` as a user runs it: its table and JSON, bad input and answers that must be
//! refused rather than printed.

use super::*;

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
    // Every row (B's fourth jump root lies beyond the validity range).
    let out = model(&["analyze", "B", "--all"]);
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
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("model-cli-{}", std::process::id()));
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
    assert!(String::from_utf8_lossy(&help.stdout)
        .contains("the path of an aircraft TOML file, or a JSBSim model"));
    std::fs::remove_dir_all(&dir).unwrap();
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

/// The unstable mode `analyze --json` reports for the file `path` at delta_e = 0, after checking
/// that it is the only one and the first departure is the unstable trim at P0 = 0.
fn unstable_mode(path: &std::path::Path) -> serde_json::Value {
    let v = json(&model(&[
        "analyze",
        path.to_str().unwrap(),
        "--json",
        "--delta-e-deg",
        "0",
    ]));
    let f = &v["first_departure"];
    assert_eq!(f["kind"], "unstable_trim", "{f}");
    assert_eq!(
        (f["p0"].as_f64(), f["delta_a_deg"].as_f64()),
        (Some(0.0), Some(0.0))
    );
    let modes = f["unstable_trim"]["modes"].as_array().unwrap();
    assert_eq!(modes.len(), 1, "{f}");
    modes[0].clone()
}

/// Aircraft A with m_alpha > 0: at delta_e = 0 the trim at P0 = 0 is the origin, where J5 splits
/// into the pitch block [[z_alpha, 1], [m_alpha, m_q]] and A's lateral block. With z_alpha =
/// m_q = -1 and m_alpha = 5 the pitch block's characteristic polynomial is s^2 + 2 s - 4
/// (determinant z_alpha m_q - m_alpha = -4 < 0), roots -1 +- sqrt(5): one real root sqrt(5) - 1
/// = 1.2361 > 0, a static pitch divergence. A's lateral block is stable there (a1 = 22.07,
/// a2 = 10.62, a3 = 81.1: a1 a2 > a3), so that is the only unstable mode.
#[test]
fn an_aircraft_with_m_alpha_above_z_alpha_m_q_departs_at_its_trim_in_pitch() {
    let (dir, path) = variant(
        "pitch-unstable",
        &[
            ("z_alpha = -3.0076", "z_alpha = -1.0"),
            ("m_q = -1.815", "m_q = -1.0"),
            ("m_alpha = -13.52504", "m_alpha = 5.0"),
        ],
    );
    let m = unstable_mode(&path);
    let want = 5f64.sqrt() - 1.0;
    assert!(
        (m["eigenvalue_re"].as_f64().unwrap() - want).abs() < 1e-12,
        "{m}"
    );
    assert_eq!(m["eigenvalue_im"].as_f64(), Some(0.0));
    assert_eq!(
        (&m["motion"], &m["subsystem"]),
        (&"divergence".into(), &"pitch".into())
    );
    let cause = m["cause"].as_str().unwrap();
    assert!(
        cause.starts_with("static pitch instability: m_alpha = 5.000"),
        "{cause}"
    );
    assert!(cause.contains("z_alpha m_q - m_alpha = -4.000"), "{cause}");

    let out = model(&["analyze", path.to_str().unwrap(), "--delta-e-deg", "0"]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.contains("First loss of stability on the primary branch: UNSTABLE TRIM")
            && text.contains("needs its stability augmentation")
            && text.contains("pitch divergence: eigenvalue 1.236 1/s"),
        "{text}"
    );
    // The jump and Hopf sections stay: they describe the airframe once it is held at its trim.
    assert!(
        text.contains("Jump points") && text.contains("Hopf points"),
        "{text}"
    );
    let _ = std::fs::remove_dir_all(dir);
}

/// Aircraft A with n_beta < 0: at the origin n_p = 0 and alpha0 = 0, so neither beta nor r
/// depends on p and the lateral block's roots are l_p and those of the directional subsystem
/// [[y_beta, -1], [n_beta, n_r]]: s^2 - (y_beta + n_r) s + (y_beta n_r + n_beta), determinant
/// 0.01455 - 3.716 < 0, one real root > 0: a directional divergence.
#[test]
fn an_aircraft_with_negative_n_beta_departs_at_its_trim_laterally() {
    let (dir, path) = variant("directional", &[("n_beta = 3.716", "n_beta = -3.716")]);
    let m = unstable_mode(&path);
    let (y_beta, n_r, n_beta): (f64, f64, f64) = (-0.0558, -0.2608, -3.716);
    let (trace, det) = (y_beta + n_r, y_beta * n_r + n_beta);
    let want = (trace + (trace * trace - 4.0 * det).sqrt()) / 2.0;
    assert!(
        (m["eigenvalue_re"].as_f64().unwrap() - want).abs() < 1e-9,
        "{m} vs {want}"
    );
    assert_eq!(
        (&m["motion"], &m["subsystem"]),
        (&"divergence".into(), &"lateral-directional".into())
    );
    let cause = m["cause"].as_str().unwrap();
    assert!(
        cause.starts_with("lateral-directional divergence")
            && cause.contains("roll damping times the directional subsystem"),
        "{cause}"
    );
    let _ = std::fs::remove_dir_all(dir);
}

/// The paper's aircraft start from a stable trim: their first departure is the critical jump
/// of the paper (Fig. 7 for A, Fig. 8 for B), as before.
#[test]
fn the_paper_aircraft_first_depart_by_their_critical_jump() {
    for (name, p0, delta_a) in [
        ("A", reference::A_JUMP_P0[0], reference::A_FOLD_DELTA_A_DEG),
        ("B", reference::B_JUMP_P0[0], reference::B_FOLD_DELTA_A_DEG),
    ] {
        let f = json(&model(&["analyze", name, "--json"]))["first_departure"].clone();
        assert_eq!(f["kind"], "jump", "{name}: {f}");
        assert!(f.get("unstable_trim").is_none(), "{name}: {f}");
        assert!((f["p0"].as_f64().unwrap() - p0).abs() < 1e-6, "{name}: {f}");
        assert!(
            (f["delta_a_deg"].as_f64().unwrap() - delta_a).abs() < 1e-4,
            "{name}: {f}"
        );
    }
}

/// A file that gives its trim: the analysis says the flight state (load factor from
/// `z_0 = -n g / V`, the principal axis' angle of attack) and its elevator defaults to the trim
/// itself, where the paper's aircraft default to 2 deg from zero lift.
#[test]
fn a_trimmed_aircraft_is_analysed_at_its_trim_and_says_it() {
    // A at V = 150 m/s linearised about 1.5 g with the principal axis 0.05 rad above the path.
    let z_0 = -1.5 * 9.80665 / 150.0;
    let (_, path) = variant(
        "trimmed",
        &[(
            "n_delta_r = -1.0",
            &format!("n_delta_r = -1.0\nz_0 = {z_0}\nalpha_t = 0.05"),
        )],
    );
    let path = path.to_str().unwrap();
    let v = json(&model(&["analyze", path, "--json"]));
    assert_eq!(v["delta_e_rad"], 0.0);
    assert!((v["trim"]["load_factor"].as_f64().unwrap() - 1.5).abs() < 1e-12);
    assert!((v["trim"]["alpha_t_deg"].as_f64().unwrap() - 0.05f64.to_degrees()).abs() < 1e-12);
    assert_eq!(v["trim"]["speed_m_s"], 150.0);
    let text = String::from_utf8(model(&["analyze", path]).stdout).unwrap();
    assert!(
        text.contains("(delta_e = 0.0000 deg from the trim"),
        "{text}"
    );
    assert!(
        text.contains(
            "At the trim: n = 1.500 g at V = 150.0 m/s, the principal axis at alpha_t = 2.865 deg"
        ),
        "{text}"
    );
    // The paper's aircraft: no trim, the elevator 2 deg from zero lift.
    let a = json(&model(&["analyze", "A", "--json"]));
    assert!(a.get("trim").is_none());
    assert_eq!(a["delta_e_rad"], 2f64.to_radians());
}

/// `--json --certified` says which route answered: aircraft A (no aileron yaw) is certified
/// whole; the fighter's aileron yaws, so its Hopf points, and with them the whole answer, come
/// from the exact path, with the reason. Plain `--json` is the exact path by request and has
/// no route field.
#[test]
fn certified_json_names_the_route_and_why_it_fell_back() {
    let a = json(&model(&["analyze", "A", "--json", "--certified"]));
    assert_eq!(a["route"], "certified");
    assert!(a.get("fallback").is_none());
    let fighter = json(&model(&[
        "analyze",
        &repo("aircraft/fighter.toml"),
        "--json",
        "--certified",
    ]));
    assert_eq!(fighter["route"], "exact");
    let why = fighter["fallback"].as_str().expect("a reason");
    assert!(why.contains("aileron yaws"), "{why}");
    let plain = json(&model(&["analyze", "A", "--json"]));
    assert!(plain.get("route").is_none());
}
