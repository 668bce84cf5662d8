//! `model import jsbsim` of a small model (tests/fixtures/jsbsim_jet.xml) and its variants: a
//! function that is not finite at the condition and mass properties no aircraft has are refused
//! with exit 2, naming the function, the property and the condition; a table read beyond its
//! breakpoints is a warning in the aircraft file, in `analyze`'s text and JSON and in the
//! envelope's JSON.

use super::{model, scratch, stderr};
use std::path::PathBuf;

/// The fixture model's text.
fn jet() -> String {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/jsbsim_jet.xml");
    std::fs::read_to_string(path).unwrap()
}

/// The fixture with `from` replaced by `to`, written as `name`.xml into a fresh folder.
fn variant(name: &str, from: &str, to: &str) -> String {
    let text = jet();
    assert!(text.contains(from), "{from}");
    let path = scratch(&format!("jsbsim-{name}")).join(format!("{name}.xml"));
    std::fs::write(&path, text.replace(from, to)).unwrap();
    path.to_string_lossy().into_owned()
}

/// The roll-damping function with a factor `1 / PROPERTY`.
fn divided_by(property: &str) -> (&'static str, String) {
    (
        "<value>-0.4</value></product>",
        format!(
            "<value>-0.4</value><quotient><value>1</value><property>{property}</property>\
             </quotient></product>"
        ),
    )
}

fn import(path: &str, condition: &[&str]) -> std::process::Output {
    let mut args = vec!["import", "jsbsim", path, "--altitude-m"];
    args.extend(condition);
    model(&args)
}

#[test]
fn a_function_dividing_by_a_zero_property_is_refused_naming_both() {
    // JSBSim 1.3.3 evaluates this model's aero/coefficient/Clp to nan at p = 0 and -inf at
    // p = 0.1 rad/s (speed brake 0): the quotient by zero is HUGE_VAL, times the zero rate NaN.
    let (from, to) = divided_by("fcs/speedbrake-pos-norm");
    let path = variant("divided", from, &to);
    let out = import(&path, &["6096", "--mach", "0.6", "--alpha-deg", "3"]);
    let err = stderr(&out);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(out.stdout.is_empty(), "nothing written on a refusal");
    for part in [
        "`aero/coefficient/Clp` is NaN",
        "altitude 6096 m, Mach 0.6, alpha 3 deg",
        "<quotient> divides 1 by `fcs/speedbrake-pos-norm` = 0",
        "give it with --set",
    ] {
        assert!(err.contains(part), "{part} not in: {err}");
    }
    // Set to a value that is not zero, the same model imports.
    let set = import(
        &path,
        &[
            "6096",
            "--mach",
            "0.6",
            "--alpha-deg",
            "3",
            "--set",
            "fcs/speedbrake-pos-norm=0.5",
        ],
    );
    assert!(set.status.success(), "{}", stderr(&set));
    let text = String::from_utf8_lossy(&set.stdout);
    assert!(text.contains("Cl_p = -0.8"), "{text}");
}

#[test]
fn a_model_without_mass_is_refused_naming_it() {
    let path = variant(
        "massless",
        r#"<emptywt unit="LBS">20000</emptywt>"#,
        r#"<emptywt unit="LBS">0</emptywt>"#,
    );
    let out = import(&path, &["6096", "--mach", "0.6", "--alpha-deg", "3"]);
    let err = stderr(&out);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("<mass_balance>: the total weight is 0 lbs (empty 0 lbs"),
        "{err}"
    );
    let path = variant(
        "flat",
        r#"<ixx unit="SLUG*FT2">10000</ixx>"#,
        r#"<ixx unit="SLUG*FT2">0</ixx>"#,
    );
    let out = import(&path, &["6096", "--mach", "0.6", "--alpha-deg", "3"]);
    let err = stderr(&out);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("the moment of inertia ixx about the CG is 0 slug ft^2"),
        "{err}"
    );
}

/// What the imported file, `analyze` and its JSON say at Mach 1.2, beyond the lift table's
/// breakpoints (0.2 to 0.9); JSBSim 1.3.3 reads that table at Mach 1.5 as 3.6, its value at
/// Mach 0.9 (held, not extrapolated). The flaps' table (0.65 to 0.95) is left too, at Mach 1.2
/// and 0.6, but its function is zero with the flaps up: no number of the file depends on it, so
/// it is not named.
#[test]
fn a_table_read_beyond_its_breakpoints_is_a_warning_in_the_file_and_analyze() {
    let dir = scratch("jsbsim-beyond");
    let xml = dir.join("jet.xml");
    std::fs::write(&xml, jet()).unwrap();
    let xml = xml.to_string_lossy().into_owned();
    let file = dir.join("jet.toml").to_string_lossy().into_owned();
    let out = import(
        &xml,
        &["6096", "--mach", "1.2", "--level-flight", "--out", &file],
    );
    assert!(out.status.success(), "{}", stderr(&out));
    let text = std::fs::read_to_string(&file).unwrap();
    let warning = "reads `velocities/mach` = 1.2 beyond the breakpoints of 1 table, where JSBSim \
                   holds the end value (no extrapolation): 0.2 to 0.9 in aero/coefficient/CLalpha";
    assert!(
        text.contains(
            "[import]\n# Warning: the imported flight state (altitude 6096 m, Mach 1.2, alpha"
        ),
        "{text}"
    );
    assert_eq!(text.matches(warning).count(), 2, "comment and data: {text}");

    let analysis = model(&["analyze", &file]);
    let shown = String::from_utf8_lossy(&analysis.stdout);
    assert!(analysis.status.success(), "{}", stderr(&analysis));
    let line = shown
        .lines()
        .find(|l| l.contains(warning))
        .expect("a warning line");
    assert!(
        line.starts_with("Warning: the imported flight state"),
        "{line}"
    );
    assert!(shown.find(warning) < shown.find("Critical jump"), "{shown}");

    let json = super::json(&model(&["analyze", &file, "--json"]));
    let warnings = json["warnings"].as_array().expect("a warnings array");
    assert_eq!(warnings.len(), 1, "{warnings:?}");
    assert!(warnings[0].as_str().unwrap().contains(warning));

    // Within the lift table's breakpoints (the flaps' table left, but no matter): no warning.
    let out = import(&xml, &["6096", "--mach", "0.6", "--level-flight"]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success() && !text.contains("[import]") && !text.contains("Warning"));
}

/// An envelope over sea level and 3000 m of a model that divides by the altitude: the sea-level
/// points are refused with the reason, the others analysed, and the point beyond the lift
/// table's breakpoints carries its warning.
#[test]
fn an_envelope_reports_a_non_finite_point_and_the_warnings_of_each_point() {
    let (from, to) = divided_by("position/h-sl-ft");
    let path = variant("altitude", from, &to);
    let source = format!("jsbsim:{path}");
    let out = model(&[
        "envelope",
        &source,
        "--altitude-m",
        "0:3000:3000",
        "--mach",
        "0.6:1.2:0.6",
        "--json",
    ]);
    let json = super::json(&out);
    let points = json["points"].as_array().unwrap();
    assert_eq!(points.len(), 4);
    for p in points {
        let at_sea_level = p["altitude_m"].as_f64() == Some(0.0);
        let why = [&p["reason"], &p["error"]]
            .iter()
            .find_map(|v| v.as_str())
            .unwrap_or("");
        if at_sea_level {
            assert!(p["critical"].is_null(), "{p}");
            assert!(
                why.contains("`aero/coefficient/Clp` is NaN at altitude 0 m")
                    && why.contains("`position/h-sl-ft` = 0"),
                "{p}"
            );
        } else {
            assert!(why.is_empty(), "{p}");
        }
        let warned = p["warnings"].as_array().map_or(0, Vec::len);
        let beyond = !at_sea_level && p["mach"].as_f64() == Some(1.2);
        assert_eq!(warned, usize::from(beyond), "{p}");
    }
}

/// `--out` says what it wrote and where the aircraft was linearised: the trim's load factor,
/// alpha and elevator, which the file's `[flight]` gives too.
#[test]
fn an_import_into_a_file_says_the_trim_it_wrote() {
    let dir = scratch("jsbsim-said");
    let xml = dir.join("jet.xml");
    std::fs::write(&xml, jet()).unwrap();
    let xml = xml.to_string_lossy().into_owned();
    let file = dir.join("jet.toml").to_string_lossy().into_owned();
    let out = import(&xml, &["6096", "--mach", "0.6", "--out", &file]);
    assert!(out.status.success(), "{}", stderr(&out));
    let said = String::from_utf8(out.stdout).unwrap();
    let text = std::fs::read_to_string(&file).unwrap();
    let alpha: f64 = text
        .lines()
        .find_map(|l| l.strip_prefix("alpha = "))
        .and_then(|l| l.split_whitespace().next()?.parse().ok())
        .expect("the trim's alpha in [flight]");
    assert!(
        said.starts_with(&format!(
            "wrote {file}: {xml} at 6096 m, Mach 0.6, trimmed at n = 1 (alpha "
        )),
        "{said}"
    );
    assert!(
        said.contains(&format!("alpha {:.4} deg", alpha.to_degrees())),
        "{said}"
    );
    assert!(said.contains("deg, JSBSim's sign)"), "{said}");
}
