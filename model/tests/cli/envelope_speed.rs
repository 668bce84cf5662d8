//! `envelope --speed`: a grid of altitude by true airspeed. Its JSON names the axis and holds
//! the speeds as given, every point's Mach is that speed over the speed of sound of the
//! standard atmosphere there (computed here from the U.S. Standard Atmosphere 1976's own
//! constants), the table, the CSV and the maps say both, `--validate` and `--uncertainty` run
//! on it, and `--mach` and `--speed` are exclusive, one required, a speed not positive refused.

use super::{json, model, scratch, stderr};
use std::path::PathBuf;

/// The fixture model (tests/fixtures/jsbsim_jet.xml) as an envelope's source.
fn jet() -> String {
    let xml = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/jsbsim_jet.xml");
    format!("jsbsim:{}", xml.display())
}

/// The speed of sound, m/s, of the U.S. Standard Atmosphere 1976 at geometric altitude `h` m
/// in its first layer (below 11 km geopotential): T = 288.15 K - 6.5 K/km of geopotential
/// altitude, a = sqrt(1.4 R T) with R = 8.31432 J/(mol K) / 0.0289644 kg/mol.
fn isa_sound_speed(h: f64) -> f64 {
    let earth_radius = 6_356_766.0;
    let geopotential = h * earth_radius / (earth_radius + h);
    let t = 288.15 - 0.0065 * geopotential;
    (1.4 * 8.314_32 / 0.028_964_4 * t).sqrt()
}

/// The grid's points are altitude by true airspeed: the JSON names the axis (`speed_axis`),
/// every point's `speed_m_s` is the value given and its `mach` the ISA's V / a there; the
/// table's rows show both; the CSV has them in its columns and the maps' axis says "true
/// airspeed, m/s".
#[test]
fn an_envelope_over_true_airspeed_holds_the_speeds_and_their_mach() {
    let dir = scratch("envelope-speed");
    let out_dir = dir.join("env");
    let out = model(&[
        "envelope",
        &jet(),
        "--altitude-m",
        "0:3000:3000",
        "--speed",
        "150:250:50",
        "--json",
        "--out",
        out_dir.to_str().unwrap(),
    ]);
    let env = json(&out);
    assert_eq!(env["speed_axis"], "speed_m_s", "{env}");
    let points = env["points"].as_array().unwrap();
    let grid: Vec<(f64, f64)> = [0.0, 3000.0]
        .iter()
        .flat_map(|&h| [150.0, 200.0, 250.0].map(|v| (h, v)))
        .collect();
    assert_eq!(points.len(), grid.len());
    for (p, &(h, v)) in points.iter().zip(&grid) {
        assert_eq!(p["altitude_m"].as_f64(), Some(h), "{p}");
        assert_eq!(p["speed_m_s"].as_f64(), Some(v), "{p}");
        let mach = p["mach"].as_f64().unwrap();
        let want = v / isa_sound_speed(h);
        assert!((mach / want - 1.0).abs() < 1e-5, "{mach} against {want}");
        assert!(p["trimmed"].as_bool().unwrap(), "{p}");
    }

    let csv = std::fs::read_to_string(out_dir.join("envelope.csv")).unwrap();
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    assert_eq!(header[..3], ["altitude_m", "mach", "speed_m_s"]);
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').take(3).map(|x| x.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), grid.len());
    for (row, &(h, v)) in rows.iter().zip(&grid) {
        assert_eq!((row[0], row[2]), (h, v));
        assert!(
            (row[1] / (v / isa_sound_speed(h)) - 1.0).abs() < 1e-5,
            "{row:?}"
        );
    }
    for map in ["critical_aileron", "first_departure", "critical_roll_rate"] {
        let svg = std::fs::read_to_string(out_dir.join(format!("{map}.svg"))).unwrap();
        assert!(svg.contains("true airspeed, m/s"), "{map}");
    }
    let summary = std::fs::read_to_string(out_dir.join("summary.json")).unwrap();
    assert!(summary.contains("\"speed_axis\": \"speed_m_s\""));

    // The table: the axis in its first line, each row its altitude, Mach and speed.
    let table = model(&["envelope", &jet(), "--altitude-m", "3000", "--speed", "200"]);
    let text = String::from_utf8_lossy(&table.stdout);
    assert!(
        text.contains("envelope over altitude x true airspeed, m/s"),
        "{text}"
    );
    let mach = format!("{:.3}", 200.0 / isa_sound_speed(3000.0));
    let row = text
        .lines()
        .find(|l| l.trim_start().starts_with("3000 "))
        .unwrap_or_else(|| panic!("no row at 3000 m in {text}"));
    let cells: Vec<&str> = row.split_whitespace().collect();
    assert_eq!(cells[..3], ["3000", mach.as_str(), "200.0"], "{row}");
}

/// `--validate` and `--uncertainty` on a true-airspeed grid: every point gets its 6-DOF verdict
/// (or the 6-DOF's refusal) and its clearance, at the speed of the grid.
#[test]
fn validate_and_uncertainty_run_over_true_airspeed() {
    let out = model(&[
        "envelope",
        &jet(),
        "--altitude-m",
        "3000",
        "--speed",
        "250",
        "--validate",
        "--validate-sample",
        "1",
        "--uncertainty",
        "5%",
        "--json",
    ]);
    let env = json(&out);
    assert_eq!(env["speed_axis"], "speed_m_s");
    let p = &env["points"][0];
    assert_eq!(p["speed_m_s"].as_f64(), Some(250.0));
    assert!(p["validation"].is_object(), "{p}");
    assert!(p["validation"]["mach_change"].as_f64().is_some(), "{p}");
    assert_eq!(p["clearance"]["uncertain"].as_u64(), Some(12), "{p}");
}

/// `--mach` and `--speed` are exclusive, one required; a speed not positive, a range that is
/// not one and a source that gives its own speed are refused with exit 2 naming the option.
#[test]
fn the_speed_axis_is_refused_naming_the_option() {
    let source = jet();
    let run = |extra: &[&str]| {
        let mut args = vec!["envelope", source.as_str(), "--altitude-m", "3000"];
        args.extend(extra);
        let out = model(&args);
        assert_eq!(out.status.code(), Some(2), "{extra:?}: {}", stderr(&out));
        assert!(out.stdout.is_empty(), "{extra:?}");
        stderr(&out)
    };
    let both = run(&["--mach", "0.5", "--speed", "200"]);
    assert!(
        both.contains("cannot be used with")
            && both.contains("'--speed <START:STOP:STEP>'")
            && both.contains("'--mach <START:STOP:STEP>'"),
        "{both}"
    );
    let neither = run(&[]);
    assert!(
        neither.contains("required") && neither.contains("<--mach <START:STOP:STEP>|--speed"),
        "{neither}"
    );
    let zero = run(&["--speed", "0:300:100"]);
    assert!(
        zero.contains("--speed: 0 is not a positive true airspeed, m/s"),
        "{zero}"
    );
    let reversed = run(&["--speed", "300:100:50"]);
    assert!(
        reversed.contains("--speed 300:100:50: reversed") && reversed.contains("START:STOP:STEP"),
        "{reversed}"
    );
    let words = run(&["--speed", "fast"]);
    assert!(
        words.contains("--speed fast: not finite numbers"),
        "{words}"
    );
    let own = model(&[
        "envelope",
        &format!("{source} --speed 200"),
        "--altitude-m",
        "3000",
        "--speed",
        "200",
    ]);
    assert_eq!(own.status.code(), Some(2));
    assert!(
        stderr(&own).contains("--speed is the envelope's to give"),
        "{}",
        stderr(&own)
    );
    // The Mach grid's refusal is the same sentence for its option.
    let mach = run(&["--mach", "0:0.5:0.25"]);
    assert!(
        mach.contains("--mach: 0 is not a positive Mach number"),
        "{mach}"
    );
}
