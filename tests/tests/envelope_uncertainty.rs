//! `model envelope --uncertainty` against aircraft sampled by hand: at grid points chosen by a
//! seeded generator, no exact analysis of an aircraft of the box (its corners and seeded random
//! points, each written into the file `import jsbsim ... --load-factor 0` gives there, and read
//! without any `[uncertainty]` table) has a critical jump below the certified lower bounds. Bad
//! specs are refused (exit 2) naming them before any work, and `--json` has the documented keys.
//! Skipped with a message when the JSBSim models are not installed.

use model::aircraft;
use model::clearance::critical;
use model::envelope::source::Source;
use model::envelope::uncertainty::Uncertainty;
use model::envelope::{Elevator, Point};
use model::jsbsim::condition::Speed;
use model::jsbsim::import::{import, Alpha, Request};
use model::present::envelope::command;
use model::present::failure::Failure;
use model::present::options::EnvelopeArgs;
use serde_json::Value;
use support::{jsbsim_installed as installed, size, Rng};

mod support;

/// The box of the soundness check: roll damping, yaw damping and aileron authority.
const BOX: [(&str, f64); 3] = [("Cl_p", 0.10), ("Cn_r", 0.10), ("Cl_delta_a", 0.05)];
/// Random samples of the box per point, besides its eight corners, and the grid points checked
/// (`ROLL_FULL_SIZE=1`: 1,000 samples at 8 points).
fn samples_and_points() -> (usize, usize) {
    (size(192, 1000), size(3, 8))
}

fn args(altitude_m: &str, mach: &str, uncertainty: &str) -> EnvelopeArgs {
    let [source, altitude_m, mach, uncertainty] =
        ["jsbsim:f104", altitude_m, mach, uncertainty].map(String::from);
    EnvelopeArgs {
        source,
        altitude_m,
        mach: Some(mach),
        speed: None,
        uncertainty: Some(uncertainty),
        json: true,
        load_factor: None,
        delta_e_deg: None,
        out: None,
        validate: false,
        validate_sample: 0.1,
    }
}

/// `text` with coefficient `key` of `[coefficients]` set to `value`, and its nominal value.
fn with_coefficient(text: &str, key: &str, value: Option<f64>) -> (String, f64) {
    let mut nominal = f64::NAN;
    let lines: Vec<String> = text
        .lines()
        .map(|line| match line.strip_prefix(&format!("{key} = ")) {
            Some(rest) => {
                nominal = rest.split('#').next().unwrap().trim().parse().unwrap();
                value.map_or(line.to_string(), |v| format!("{key} = {v:e}"))
            }
            None => line.to_string(),
        })
        .collect();
    assert!(nominal.is_finite(), "no {key} in the import");
    (lines.join("\n"), nominal)
}

/// The aircraft at `unit` (each in [-1, 1]: -1 and 1 the box's ends) of [`BOX`] about the
/// import `text`, kept 1e-9 of its width inside the box (the file's numbers are decimals).
fn sample(text: &str, unit: &[f64]) -> aircraft::Aircraft {
    let mut t = text.to_string();
    for ((key, width), u) in BOX.iter().zip(unit) {
        let (_, nominal) = with_coefficient(&t, key, None);
        let v = nominal + nominal.abs() * width * u * (1.0 - 1e-9);
        t = with_coefficient(&t, key, Some(v)).0;
    }
    aircraft::parse(&t, "sample").unwrap()
}

/// At three grid points of the F-104 chosen by a seeded generator, trimmed at 0 g, the eight corners of the box
/// and 192 seeded random aircraft of it (more in the full-size run), analysed by the exact path, have no critical jump
/// below the certified lower bounds of the roll rate and of |delta_a|.
#[test]
fn no_exact_sample_of_a_box_beats_its_certified_lower_bound() {
    if !installed() {
        return;
    }
    let loaded = Source::parse("jsbsim:f104").unwrap().load().unwrap();
    let spec: Vec<String> = BOX
        .iter()
        .map(|(k, w)| format!("{k}={}%", w * 100.0))
        .collect();
    let u = Uncertainty::parse(&spec.join(",")).unwrap();
    let (n_samples, n_points) = samples_and_points();
    let mut rng = Rng::new(38);
    let mut samples = 0;
    // The unloaded roll (0 g), where the F-104 has critical jumps to bound; at 1 g it has
    // none over most of these points.
    let unloaded = Elevator {
        load_factor: 0.0,
        increment: 0.0,
    };
    for _ in 0..n_points {
        let h = (rng.unit() * 4.0).floor() * 3000.0;
        let m = 0.45 + (rng.unit() * 4.0).floor() * 0.1;
        let p = Point::cleared_at(
            &loaded,
            "jsbsim:f104",
            (h, Speed::Mach(m)),
            unloaded,
            Some(&u),
        );
        let request = Request {
            model: "f104".to_string(),
            root: None,
            altitude_m: h,
            speed: Speed::Mach(m),
            alpha: Alpha::Trim(0.0),
            settings: Vec::new(),
        };
        let Ok(text) = import(&request) else {
            assert!(!p.trimmed && p.clearance.is_none(), "{p:?}");
            continue;
        };
        let c = p.clearance.as_ref().unwrap_or_else(|| panic!("{p:?}"));
        assert_eq!(c.uncertain, 3);
        let de = p.delta_e_deg.unwrap().to_radians();
        let corners = (0..8).map(|k: usize| (0..3).map(|i| [-1.0, 1.0][(k >> i) & 1]).collect());
        let random = (0..n_samples).map(|_| (0..3).map(|_| 2.0 * rng.unit() - 1.0).collect());
        let all: Vec<Vec<f64>> = corners.chain(random).collect();
        let mut lowest = f64::INFINITY;
        for unit in &all {
            let Some(j) = critical(&sample(&text, unit), de).unwrap() else {
                continue;
            };
            let (p0_lo, da_lo) = (c.p0_lo.unwrap(), c.delta_a_lo_deg.unwrap());
            assert!(
                j.p0 >= p0_lo,
                "{h} m, Mach {m}, {unit:?}: P0 {} < {p0_lo}",
                j.p0
            );
            let da = j.delta_a_deg.abs();
            assert!(da >= da_lo, "{h} m, Mach {m}, {unit:?}: {da} deg < {da_lo}");
            lowest = lowest.min(da);
            samples += 1;
        }
        println!(
            "{h} m, Mach {m}: |delta_a| lo {:.4}, lowest sample {lowest:.4}, hi {:?} deg ({:?})",
            c.delta_a_lo_deg.unwrap(),
            c.delta_a_hi_deg,
            c.verdict
        );
    }
    assert!(samples > 0, "no sample with a critical jump");
    println!("envelope --uncertainty: {samples} exact samples, none below the certified bounds");
}

/// A spec with an unknown key, a negative width, an unreadable file or a file without the
/// table is refused as input (exit 2) naming it and what is wrong, before any output.
#[test]
fn bad_specs_are_refused_naming_them() {
    if !installed() {
        return;
    }
    let no_table = std::path::Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("no-uncertainty-{}.toml", std::process::id()));
    std::fs::write(&no_table, "[coefficients]\nCl_p = 1\n").unwrap();
    let no_table = no_table.display().to_string();
    let bad = [
        ("Cl_pp=10%", "unknown key `uncertainty.Cl_pp`"),
        ("Cl_p=-10%", "negative width"),
        ("-5%", "negative width"),
        ("Cn_r=0.02,Cn_r=5%", "twice"),
        ("Cl_p=wide", "relative width"),
        ("/no/such/file.toml", "not a readable file"),
        (no_table.as_str(), "no `[uncertainty]` table"),
    ];
    for (spec, why) in bad {
        let mut out = Vec::new();
        match command(&args("0:12000:4000", "0.4:0.9:0.25", spec), &mut out) {
            Err(Failure::Input(msg)) => {
                assert!(msg.starts_with(&format!("--uncertainty {spec}: ")), "{msg}");
                assert!(msg.contains(why), "{spec}: {msg}");
            }
            _ => panic!("{spec}: not refused as input"),
        }
        assert!(out.is_empty());
    }
    let _ = std::fs::remove_file(&no_table);
}

/// `--json` names the spec and gives every trimmed point a `clearance` with the documented
/// keys: the proven lower bounds, the worst case found, the verdict against the aileron limit.
#[test]
fn json_gives_every_point_its_clearance_with_the_documented_keys() {
    if !installed() {
        return;
    }
    let mut out = Vec::new();
    let mut a = args("6000", "0.6", "Cl_p=5%");
    // Unloaded (0 g), where the point has a critical jump to clear.
    a.load_factor = Some(0.0);
    command(&a, &mut out).unwrap();
    let v: Value = serde_json::from_slice(&out).unwrap();
    assert_eq!(v["uncertainty"], "Cl_p=5%");
    let c = &v["points"][0]["clearance"];
    let keys = [
        "uncertain",
        "p0_lo",
        "p0_hi",
        "delta_a_lo_deg",
        "delta_a_hi_deg",
        "no_critical_jump",
        "verdict",
        "verdict_reason",
        "counterexample_delta_a_deg",
        "gap_to_limit",
        "note",
    ];
    for k in keys {
        assert!(c.get(k).is_some(), "{k} missing in {c}");
    }
    assert_eq!(c["uncertain"], 1);
    let verdicts = ["cleared", "not_cleared", "undecided_budget", "undecided"];
    assert!(verdicts.contains(&c["verdict"].as_str().unwrap()), "{c}");
    let (lo, hi) = (c["delta_a_lo_deg"].as_f64(), c["delta_a_hi_deg"].as_f64());
    assert!(lo.unwrap() <= hi.unwrap(), "{c}");
}

/// A file's `[uncertainty]` table is taken as written (other tables ignored): a relative width
/// reads as the list's, an interval passes through to the loader unchanged.
#[test]
fn a_file_spec_is_its_uncertainty_table_as_written() {
    let path = std::path::Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("uncertainty-{}.toml", std::process::id()));
    let text = "[flight]\nspeed = 1\n\n[uncertainty]\nCl_p = \"5%\"  # roll damping\n\
                Cn_r = [-0.8, -0.7]\n";
    std::fs::write(&path, text).unwrap();
    let from_file = Uncertainty::parse(&path.display().to_string()).unwrap();
    let _ = std::fs::remove_file(&path);
    let from_list = Uncertainty::parse("Cl_p=5%").unwrap();
    assert_eq!(
        from_file.table(),
        from_list.table() + "Cn_r = [-0.8, -0.7]\n"
    );
}

/// The F-104 at 6000 m, Mach 0.6, trimmed at 1 g, every coefficient +- 10 %: its primary
/// branch reaches 60 to 90 deg of aileron near P0 = 1.97 rad/s, where the enclosure of the
/// branch's root bounded |delta_a| only by 12 deg, so the verdict against the 20.05 deg limit
/// was undecided at the budget. Bounded by the trims' absence within the limit instead, the point
/// is cleared; seeded random aircraft of the box and its two extreme corners, analysed by the
/// exact path, have no critical jump within the limit (nor below the proven bound).
#[test]
fn the_f104_all_coefficients_point_is_cleared_and_no_exact_sample_contradicts_it() {
    if !installed() {
        return;
    }
    let loaded = Source::parse("jsbsim:f104").unwrap().load().unwrap();
    let u = Uncertainty::parse("10%").unwrap();
    let at = (6000.0, Speed::Mach(0.6));
    let level = Elevator {
        load_factor: 1.0,
        increment: 0.0,
    };
    let p = Point::cleared_at(&loaded, "jsbsim:f104", at, level, Some(&u));
    let c = p.clearance.as_ref().unwrap_or_else(|| panic!("{p:?}"));
    assert_eq!(c.uncertain, 15);
    let text = import(&Request {
        model: "f104".to_string(),
        root: None,
        altitude_m: 6000.0,
        speed: Speed::Mach(0.6),
        alpha: Alpha::Trim(1.0),
        settings: Vec::new(),
    })
    .unwrap();
    let limit = aircraft::parse(&text, "nominal")
        .unwrap()
        .limits
        .aileron_deg
        .unwrap();
    let da_lo = c.delta_a_lo_deg.unwrap();
    assert_eq!(c.verdict, Some(model::clearance::Verdict::Cleared), "{c:?}");
    assert!(da_lo > limit, "{da_lo} <= {limit}");
    let keys: Vec<&str> = model::aircraft::convert::Coefficient::ALL
        .iter()
        .map(|k| k.key())
        .collect();
    let mut rng = Rng::new(46);
    let mut units: Vec<Vec<f64>> = vec![vec![-1.0; keys.len()], vec![1.0; keys.len()]];
    units.extend((0..size(8, 64)).map(|_| keys.iter().map(|_| 2.0 * rng.unit() - 1.0).collect()));
    for unit in &units {
        let mut t = text.clone();
        for (key, x) in keys.iter().zip(unit) {
            let (_, nominal) = with_coefficient(&t, key, None);
            let v = nominal + nominal.abs() * 0.1 * x * (1.0 - 1e-9);
            t = with_coefficient(&t, key, Some(v)).0;
        }
        let a = aircraft::parse(&t, "sample").unwrap();
        if let Some(j) = critical(&a, p.delta_e_deg.unwrap().to_radians()).unwrap() {
            let da = j.delta_a_deg.abs();
            assert!(
                da > limit && da >= da_lo,
                "{unit:?}: a critical jump at {da} deg"
            );
        }
    }
}
