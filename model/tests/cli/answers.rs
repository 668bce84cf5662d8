//! What `analyze` and `envelope` answer first: the critical jump with the aileron limit and the
//! margin, the first departure, the rows within the limits and the validity range (the others
//! counted, and printed with `--all`), states marked where they leave the validity range, one
//! number style, each warning once; the envelope's rows of a Hopf departure with its numbers.

use super::*;

fn stdout(out: &Output) -> String {
    String::from_utf8_lossy(&out.stdout).into_owned()
}

/// Aircraft A has no `[limits]`: the head says so. Its second jump root (beta -55 deg) and
/// second zero-sideslip root (alpha 919 deg) lie beyond the default 30 deg validity range:
/// counted, not printed, unless `--all`. The jump's landing at beta 46.8 deg is marked.
#[test]
fn analyze_answers_first_and_counts_the_rows_beyond_the_validity_range() {
    let text = stdout(&model(&["analyze", "A"]));
    let head: Vec<&str> = text.lines().skip(2).take(2).collect();
    assert!(head[0].starts_with("Critical jump (first fold of the primary branch): P0 = 1.706288"));
    assert_eq!(
        head[1],
        "  aileron limit: none in the aircraft file (no [limits] aileron), so no margin"
    );
    assert!(
        text.contains("beta = 46.7625 deg  [outside validity range: |beta| = 46.8 deg > 30 deg]\n"),
        "{text}"
    );
    assert!(!text.contains("3.033180"), "{text}");
    assert!(!text.contains("4.457684"), "{text}");
    for what in ["jump", "departure"] {
        let line = format!("  1 more {what} row beyond the limits or validity range: --all\n");
        assert!(text.contains(&line), "{line} in {text}");
    }
    let all = stdout(&model(&["analyze", "A", "--all"]));
    assert!(
        all.contains("3.033180") && all.contains("4.457684"),
        "{all}"
    );
    assert!(!all.contains("--all"), "{all}");
}

/// The fighter's file gives an aileron limit of 21.5 deg and a validity range of 25 deg of
/// alpha and 20 of beta: the head gives the limit and the margin (the limit minus the critical
/// |delta_a|), the JSON the same numbers and every row's flags, and the text prints exactly the
/// rows the JSON flags within both.
#[test]
fn the_critical_jump_comes_with_the_aileron_limit_and_the_margin() {
    let text = stdout(&model(&["analyze", &repo("aircraft/fighter.toml")]));
    let v = json(&model(&[
        "analyze",
        &repo("aircraft/fighter.toml"),
        "--json",
    ]));
    let critical = v["critical"]["delta_a_deg"].as_f64().unwrap();
    let margin = 21.5 - critical.abs();
    assert_eq!(v["aileron_limit_deg"].as_f64(), Some(21.5));
    assert!(
        (v["margin_deg"].as_f64().unwrap() - margin).abs() < 1e-12,
        "{v}"
    );
    assert_eq!(v["validity"]["alpha_max_deg"].as_f64(), Some(25.0));
    assert_eq!(v["validity"]["beta_max_deg"].as_f64(), Some(20.0));
    let line = format!(
        "  aileron limit 21.5000 deg, margin {margin:.4} deg (the limit minus |delta_a|): a \
         full-stick roll reaches the jump with {margin:.4} deg of travel to spare\n"
    );
    assert!(text.contains(&line), "{line} in {text}");
    let rows = |list: &serde_json::Value| -> Vec<(f64, bool)> {
        list.as_array()
            .unwrap()
            .iter()
            .map(|r| {
                let r = r.get("point").unwrap_or(r);
                let limits = r["within_limits"].as_bool().unwrap();
                let validity = r["within_validity"].as_bool().unwrap();
                (r["p0"].as_f64().unwrap(), limits && validity)
            })
            .collect()
    };
    let jump = rows(&v["jump"]);
    let hopf = rows(&v["hopf"]);
    let departure = rows(&v["zero_sideslip"]["departure"]);
    assert_eq!((jump.len(), hopf.len(), departure.len()), (4, 4, 2));
    for (p0, shown) in jump.iter().chain(&hopf).chain(&departure) {
        assert_eq!(
            text.contains(&format!("{p0:.6} ")),
            *shown,
            "P0 {p0} in {text}"
        );
    }
    assert!(text.contains("  2 more jump rows beyond the limits or validity range: --all\n"));
    assert!(text.contains("  4 Hopf rows beyond the limits or validity range: --all\n"));
}

/// Every number of the text is a plain decimal, `--all` included (the fighter's Hopf rows have
/// first Lyapunov coefficients of 3e-8 to 8e-4).
#[test]
fn analyze_prints_every_number_as_a_plain_decimal() {
    for ac in [
        "A",
        "B",
        &repo("aircraft/fighter.toml"),
        &repo("aircraft/c.toml"),
    ] {
        let text = stdout(&model(&["analyze", ac, "--all"]));
        let exponent = text
            .split(|c: char| c.is_whitespace() || c == ',')
            .find(|w| {
                let w = w.trim_end_matches([')', '.']);
                w.parse::<f64>().is_ok() && w.contains('e')
            });
        assert_eq!(exponent, None, "{ac}: {text}");
    }
    let text = stdout(&model(&[
        "analyze",
        &repo("aircraft/fighter.toml"),
        "--all",
    ]));
    assert!(text.contains(" 0.0001906  subcritical"), "{text}");
}

/// Aircraft C with iy above ix + iz, which no rigid body has: the warning is printed once by
/// `analyze` (in its text, not again on stderr), with the moments as plain decimals.
#[test]
fn the_inertia_warning_is_printed_once() {
    let text = std::fs::read_to_string(repo("aircraft/c.toml")).unwrap();
    let path = scratch_file("triangle.toml", &text.replace("iy = 5.5", "iy = 8.0"));
    let out = model(&["analyze", path.to_str().unwrap()]);
    assert!(out.status.success(), "{}", stderr(&out));
    let both = stdout(&out) + &stderr(&out);
    assert_eq!(both.matches("triangle inequality").count(), 1, "{both}");
    assert!(
        both.contains("ix = 1.000, iy = 8.000, iz = 6.100"),
        "{both}"
    );
}

/// An envelope of the A-4 (whose inertia breaks a triangle inequality) at 6000 m, Mach 0.5 and
/// 1 g: the first departure is a Hopf point and there is no jump on the primary branch, so the
/// row shows the Hopf point's roll rate, aileron and margin instead of `-`; the inertia warning
/// is printed once. Skipped without the JSBSim models.
#[test]
fn an_envelope_row_of_a_hopf_departure_shows_its_numbers_and_the_warning() {
    if model::jsbsim::catalogue::root(None).is_none() {
        eprintln!("skipped: the JSBSim models are not installed (pip install jsbsim)");
        return;
    }
    let out = model(&[
        "envelope",
        "jsbsim:A4",
        "--altitude-m",
        "6000",
        "--mach",
        "0.5",
    ]);
    assert!(out.status.success(), "{}", stderr(&out));
    let text = stdout(&out);
    let v = json(&model(&[
        "envelope",
        "jsbsim:A4",
        "--altitude-m",
        "6000",
        "--mach",
        "0.5",
        "--json",
    ]));
    let p = &v["points"][0];
    assert!(p["critical"].is_null(), "{p}");
    let d = &p["first_departure"];
    assert_eq!(d["kind"], "hopf");
    let (p0, delta_a) = (
        d["p0"].as_f64().unwrap(),
        d["delta_a_deg"].as_f64().unwrap(),
    );
    let limit = p["aileron_limit_deg"].as_f64().unwrap();
    let margin = limit - delta_a.abs();
    assert!((p["departure_margin_deg"].as_f64().unwrap() - margin).abs() < 1e-12);
    let row = text
        .lines()
        .find(|l| l.trim_start().starts_with("6000"))
        .unwrap();
    let cells: Vec<&str> = row.split_whitespace().collect();
    assert_eq!(
        cells[6..10],
        [
            format!("{p0:.4}").as_str(),
            &format!("{delta_a:.3}"),
            &format!("{margin:.3}"),
            "hopf"
        ],
        "{row}"
    );
    assert_eq!(text.matches("triangle inequality").count(), 1, "{text}");
}
