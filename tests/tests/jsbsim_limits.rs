//! The control surfaces' limits of an import against the travel JSBSim itself gives them: for
//! every catalogue model the import reads whose aerodynamics read an aileron angle, JSBSim
//! (its Python package, through `tests/oracle/jsbsim_limits.py`, flight control system intact,
//! flight state frozen wings level with no rates or sideslip) settles each surface at the
//! pilot's command +1 and -1; the imported file's `[limits]` must hold the smaller end, or say
//! in a warning which component stops the chain and hold no limit. The same for the elevator
//! and the rudder. Skipped with a message when the `jsbsim` package is not installed.

use model::jsbsim::catalogue;
use model::jsbsim::condition::Speed;
use model::jsbsim::import::{evaluates, import, Alpha, Request, REFERENCE};
use model::jsbsim::surfaces::{Control, Form};
use model::jsbsim::Model;
use serde_json::{json, Value};
use std::path::Path;
use std::process::Command;

#[allow(dead_code)]
#[path = "support/oracle.rs"]
mod oracle;

/// Agreement required, deg. Both sides compute the settled position from the same decimal
/// constants of the model (a range times a gain, a clip, a sum) in double precision, mostly in
/// the same order, so they differ by a few ulps (about 1e-14 deg); the oracle runs until a
/// further second changes no position by more than 1e-14 rad, so a lag or a rate limit left
/// unsettled is far below this. A wrong reading of a chain is off by whole degrees (a range in
/// degrees read as radians by a factor of 57).
const TOLERANCE_DEG: f64 = 1e-9;

/// The fewest models whose aileron limit must be compared (the catalogue has 40 or more whose
/// aileron chain is a plain scale, sum, gain or actuator): the test cannot pass by warnings.
const FEWEST_COMPARED: usize = 30;

fn oracle(request: &Value) -> Value {
    oracle::run("jsbsim_limits.py", request)
}

/// The angle forms (rad or deg, JSBSim's sign) of a control, in the import's order.
fn angles(control: Control) -> Vec<(&'static str, Form)> {
    control
        .properties()
        .into_iter()
        .filter(|(_, f, sign)| matches!(f, Form::Rad | Form::Deg) && *sign > 0.0)
        .map(|(n, f, _)| (n, f))
        .collect()
}

/// The pilot's command of a control.
fn command(control: Control) -> &'static str {
    match control {
        Control::Aileron => "fcs/aileron-cmd-norm",
        Control::Elevator => "fcs/elevator-cmd-norm",
        Control::Rudder => "fcs/rudder-cmd-norm",
    }
}

/// The `[limits]` of an aircraft file, deg.
fn limits(toml: &str) -> Vec<(String, f64)> {
    toml.split("\n[limits]\n")
        .nth(1)
        .unwrap_or("")
        .lines()
        .take_while(|l| !l.starts_with('['))
        .filter(|l| !l.starts_with('#'))
        .filter_map(|l| {
            let (k, v) = l.split_once('=')?;
            Some((k.trim().to_string(), v.trim().parse().ok()?))
        })
        .collect()
}

/// JSBSim's settled position (rad) of `property` at command `end` ("+1" or "-1").
fn jsbsim_at(
    travel: &Value,
    control: Control,
    end: &str,
    property: &str,
    form: Form,
) -> Option<f64> {
    let v = travel[command(control)][end][property].as_f64()?;
    Some(if form == Form::Deg { v.to_radians() } else { v })
}

#[test]
fn limits_are_the_travel_jsbsim_gives_at_full_stick() {
    let Some(root) = catalogue::root(None) else {
        eprintln!("skipped: {}", catalogue::HOW_TO_GET);
        return;
    };
    if Command::new("python3")
        .args(["-c", "import jsbsim"])
        .output()
        .map_or(true, |o| !o.status.success())
    {
        eprintln!("skipped: the jsbsim Python package is not installed");
        return;
    }
    // The models that read and evaluate, with an aileron angle their aerodynamics read.
    let mut models = Vec::new();
    for name in catalogue::names(&root) {
        let path = root
            .join("aircraft")
            .join(&name)
            .join(format!("{name}.xml"));
        let Ok(model) = Model::load(&path) else {
            continue;
        };
        if evaluates(&model, &path).is_err() {
            continue;
        }
        let reads = |n: &str| model.functions.symbols.get(n).is_some();
        if angles(Control::Aileron).iter().any(|(n, _)| reads(n)) {
            models.push((name, model));
        }
    }
    let properties: Vec<&str> = Control::ALL
        .iter()
        .flat_map(|&c| angles(c).into_iter().map(|(n, _)| n))
        .collect();
    let names: Vec<&str> = models.iter().map(|(n, _)| n.as_str()).collect();
    let travel = oracle(&json!({"root": root, "models": names, "properties": properties}));
    let (h, mach, alpha) = REFERENCE;
    let mut compared = Vec::new();
    let mut failures = Vec::new();
    for (name, model) in &models {
        let file = import(&Request {
            model: name.clone(),
            root: Some(root.clone()),
            altitude_m: h,
            speed: Speed::Mach(mach),
            alpha: Alpha::Given(alpha.to_radians()),
            settings: Vec::new(),
        })
        .unwrap_or_else(|e| panic!("{name}: {e}"));
        let ours = limits(&file);
        let t = &travel[name.as_str()];
        assert!(t.get("error").is_none(), "{name}: JSBSim: {}", t["error"]);
        for control in Control::ALL {
            let reads = |n: &str| model.functions.symbols.get(n).is_some();
            // JSBSim's travel of the angle the aerodynamics read.
            let Some((property, form)) = angles(control).into_iter().find(|(n, _)| reads(n)) else {
                continue;
            };
            let plus = jsbsim_at(t, control, "+1", property, form).unwrap_or(0.0);
            let minus = jsbsim_at(t, control, "-1", property, form).unwrap_or(0.0);
            let theirs = (-plus.min(minus)).min(plus.max(minus)).to_degrees();
            let limit = ours
                .iter()
                .find(|(k, _)| k == control.name())
                .map(|(_, v)| *v);
            let warned = file.contains(&format!("# Warning: no {} limit", control.name()));
            let line = format!(
                "{name} {}: JSBSim {:.4} / {:.4} deg at +1 / -1 ({property}), limit {theirs:.4}; ours {}",
                control.name(),
                plus.to_degrees(),
                minus.to_degrees(),
                limit.map_or(if warned { "none (warned)".into() } else { "none".into() }, |v| format!("{v:.4}"))
            );
            eprintln!("{line}");
            match limit {
                Some(v) if (v - theirs).abs() <= TOLERANCE_DEG && theirs > 0.0 => {
                    if control == Control::Aileron {
                        compared.push(name.clone());
                    }
                }
                Some(_) => failures.push(line),
                // No limit: right only when JSBSim does not move the surface to both sides, or
                // when the file says which component stops the chain.
                None if theirs <= 0.0 || warned => {}
                None => failures.push(format!("{line}: no limit and no warning")),
            }
        }
    }
    assert!(
        failures.is_empty(),
        "limits that disagree with JSBSim:\n{}",
        failures.join("\n")
    );
    assert!(
        compared.len() >= FEWEST_COMPARED,
        "only {} aileron limits compared (expected at least {FEWEST_COMPARED}): {compared:?}",
        compared.len()
    );
    eprintln!(
        "{} aileron limits agree with JSBSim: {compared:?}",
        compared.len()
    );
}

/// Copies the directory `from` to `to`, files and subdirectories.
fn copy_dir(from: &Path, to: &Path) {
    std::fs::create_dir_all(to).unwrap();
    for e in std::fs::read_dir(from).unwrap().flatten() {
        let target = to.join(e.file_name());
        if e.file_type().unwrap().is_dir() {
            copy_dir(&e.path(), &target);
        } else {
            std::fs::copy(e.path(), target).unwrap();
        }
    }
}

/// The DHC-6 keeps its controls' chain in `Systems/Conventional Controls.xml`: a copy of its
/// folder imports with the limits JSBSim gives; without that file the import is an error
/// naming it (JSBSim itself refuses to load the model), not a file with no `[limits]`.
#[test]
fn a_missing_systems_file_is_an_error_naming_it() {
    let Some(root) = catalogue::root(None) else {
        eprintln!("skipped: {}", catalogue::HOW_TO_GET);
        return;
    };
    let copy = std::path::Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("limits-missing-{}", std::process::id()));
    let folder = copy.join("aircraft").join("DHC6");
    copy_dir(&root.join("aircraft").join("DHC6"), &folder);
    let (h, mach, alpha) = REFERENCE;
    let request = Request {
        model: folder.join("DHC6.xml").display().to_string(),
        root: None,
        altitude_m: h,
        speed: Speed::Mach(mach),
        alpha: Alpha::Given(alpha.to_radians()),
        settings: Vec::new(),
    };
    let whole = import(&request).unwrap();
    assert!(!limits(&whole).is_empty(), "{whole}");
    std::fs::remove_file(folder.join("Systems").join("Conventional Controls.xml")).unwrap();
    let err = import(&request).unwrap_err();
    std::fs::remove_dir_all(&copy).unwrap();
    assert!(
        err.contains("<system file=\"Conventional Controls.xml\">") && err.contains("no such file"),
        "{err}"
    );
}
