//! A first departure whose trim lies outside the aircraft's validity range is a departure of the
//! linear aerodynamics, which the aircraft's own need not share: `analyze`, `envelope` and the
//! catalogue table say so wherever they give it. The F-16's primary branch from 1-g flight at
//! 1,000 m meets a jump first at Mach 0.6 and a Hopf point first at Mach 0.7, the latter on a
//! trim whose angle of attack is 48 deg from the analysed one. Skipped with a message when the
//! JSBSim models are not installed.

use model::aircraft;
use model::jsbsim::catalogue;
use model::jsbsim::condition::Speed;
use model::jsbsim::import::{import, Alpha, Request};
use model::present::envelope::command;
use model::present::numbers::first_departure_text;
use model::present::options::EnvelopeArgs;
use serde_json::Value;

fn installed() -> bool {
    let found = catalogue::root(None).is_some();
    if !found {
        eprintln!("skipped: the JSBSim models are not installed (pip install jsbsim)");
    }
    found
}

/// `model envelope jsbsim:f16 --altitude-m 1000 --mach 0.6:0.7:0.1`, JSON or the table.
fn f16_at_1000_m(json: bool, out: Option<std::path::PathBuf>) -> String {
    let a = EnvelopeArgs {
        source: "jsbsim:f16".to_string(),
        altitude_m: "1000".to_string(),
        mach: Some("0.6:0.7:0.1".to_string()),
        speed: None,
        load_factor: None,
        delta_e_deg: None,
        json,
        out,
        uncertainty: None,
        validate: false,
        validate_sample: 0.1,
    };
    let mut printed = Vec::new();
    command(&a, &mut printed).unwrap();
    String::from_utf8(printed).unwrap()
}

/// The JSON's first departure carries its trim's alpha and beta and whether they lie within
/// the validity range, which is the range `analyze` checks its Hopf rows against (30 deg each
/// for an imported model).
#[test]
fn the_json_gives_the_first_departures_trim_and_its_validity() {
    if !installed() {
        return;
    }
    let v: Value = serde_json::from_str(&f16_at_1000_m(true, None)).unwrap();
    let departure = |i: usize| &v["points"][i]["first_departure"];
    let alpha_deg = |i: usize| departure(i)["alpha"].as_f64().unwrap().to_degrees();
    let beta_deg = |i: usize| departure(i)["beta"].as_f64().unwrap().to_degrees();
    assert_eq!(departure(0)["kind"], "jump", "{v}");
    assert_eq!(departure(0)["within_validity"], true, "{v}");
    assert!(
        alpha_deg(0).abs() <= 30.0 && beta_deg(0).abs() <= 30.0,
        "{v}"
    );
    assert_eq!(departure(1)["kind"], "hopf", "{v}");
    assert_eq!(departure(1)["within_validity"], false, "{v}");
    assert!(alpha_deg(1).abs() > 30.0, "{v}");
}

/// The table marks the row and counts it, the CSV has the column, the first-departure map
/// gives it a class of its own, the catalogue's row says so, `analyze` ends the first departure's line with the angle beyond
/// the range.
#[test]
fn the_table_the_csv_and_analyze_mark_a_departure_outside_the_validity_range() {
    if !installed() {
        return;
    }
    let table = f16_at_1000_m(false, None);
    let rows: Vec<&str> = table.lines().filter(|l| l.contains(" 1000 ")).collect();
    assert_eq!(rows.len(), 2, "{table}");
    assert!(!rows[0].contains("outside validity"), "{table}");
    assert!(
        rows[1].ends_with(
            "hopf (no jump: p0, delta_a, margin of the Hopf point)  [outside validity range]"
        ),
        "{table}"
    );
    assert!(
        table.contains("\n1 whose first departure lies outside the validity range"),
        "{table}"
    );
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("envelope-validity-{}", std::process::id()));
    f16_at_1000_m(true, Some(dir.clone()));
    let csv = std::fs::read_to_string(dir.join("envelope.csv")).unwrap();
    let map = std::fs::read_to_string(dir.join("first_departure.svg")).unwrap();
    let _ = std::fs::remove_dir_all(&dir);
    assert!(
        map.contains("jump or Hopf outside the validity range"),
        "the map's legend"
    );
    let column = |row: &str| -> String {
        let header: Vec<&str> = csv.lines().next().unwrap().split(',').collect();
        let i = header
            .iter()
            .position(|h| *h == "first_departure_within_validity")
            .unwrap();
        row.split(',').nth(i).unwrap().to_string()
    };
    let cells: Vec<String> = csv.lines().skip(1).map(column).collect();
    assert_eq!(cells, ["true", "false"], "{csv}");
    let request = Request {
        model: "f16".to_string(),
        root: None,
        altitude_m: 1000.0,
        speed: Speed::Mach(0.7),
        alpha: Alpha::Trim(1.0),
        settings: Vec::new(),
    };
    let ac = aircraft::parse(&import(&request).unwrap(), "jsbsim:f16").unwrap();
    let row = model::present::catalogue::row("f16", &Ok(ac.clone()));
    assert!(row.contains("| hopf (outside validity range) |"), "{row}");
    let a = model::analysis::analyze(&ac, 0.0).unwrap();
    let text = first_departure_text(&a);
    assert!(
        text.lines()
            .next()
            .unwrap()
            .ends_with("  [outside validity range: |alpha| = 48.0 deg > 30 deg]"),
        "{text}"
    );
}
