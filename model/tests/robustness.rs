//! Property-based robustness: thousands of random and mutated aircraft files and settings fed
//! to the library entry points (`aircraft::parse`, `analysis::analyze`, the simulation and
//! continuation settings). Never a panic; every `Ok` result finite; every `Err` names a key or a
//! value. Each test prints how many cases it tried.
//!
//! Integers past i64, floats past f64 such as 1e309, 400-digit numbers and NUL bytes have
//! unit tests of their own in `aircraft::load`.

use model::aircraft::{parse, Aircraft, Param};
use model::analysis::{analyze, Analysis};
use proptest::prelude::*;
use proptest::test_runner::{Config, TestCaseError, TestRunner};
use std::path::PathBuf;

fn shipped(name: &str) -> String {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../aircraft")
        .join(name);
    std::fs::read_to_string(path).unwrap()
}

fn bases() -> Vec<String> {
    ["a.toml", "b.toml", "c.toml"]
        .iter()
        .map(|f| shipped(f))
        .collect()
}

/// A value as it may appear in a file: numbers of every size and sign, and things that are not
/// numbers.
fn value() -> impl Strategy<Value = String> {
    prop_oneof![
        any::<f64>()
            .prop_filter("finite", |v| v.is_finite())
            .prop_map(|v| format!("{v:?}")),
        (-1000.0..1000.0f64).prop_map(|v| format!("{v}")),
        any::<i32>().prop_map(|v| v.to_string()),
        prop::sample::select(vec![
            "0",
            "-0.0",
            "0.0",
            "1e308",
            "-1e308",
            "1e-308",
            "5e-324",
            "-5e-324",
            "nan",
            "inf",
            "-inf",
            "+inf",
            "\"12\"",
            "\"x\"",
            "true",
            "[1, 2]",
            "{ a = 1 }",
            "",
            "1979-05-27",
            "0x10",
            "1_000",
            "9223372036854775807",
            "-9223372036854775808",
        ])
        .prop_map(str::to_string),
    ]
}

/// One edit of a file's text.
#[derive(Clone, Debug)]
enum Edit {
    SetKey(usize, String),
    DeleteLine(usize),
    DuplicateLine(usize),
    InsertLine(usize, String),
    Truncate(usize),
    ReplaceChar(usize, char),
}

fn edit() -> impl Strategy<Value = Edit> {
    let line = prop::sample::select(vec![
        "foo = 1",
        "[extra]",
        "name = 3",
        "[inertia]",
        "ix = 1.0",
        "C = 0.5",
        "[flight]\nspeed = -1",
        "speed = 0",
        "[limits]",
        "l_p = \"fast\"",
        "= 3",
        "[derivatives",
        "name = \"\\u001b[2J\"",
    ])
    .prop_map(str::to_string);
    prop_oneof![
        3 => (any::<usize>(), value()).prop_map(|(i, v)| Edit::SetKey(i, v)),
        1 => any::<usize>().prop_map(Edit::DeleteLine),
        1 => any::<usize>().prop_map(Edit::DuplicateLine),
        1 => (any::<usize>(), line).prop_map(|(i, l)| Edit::InsertLine(i, l)),
        1 => any::<usize>().prop_map(Edit::Truncate),
        1 => (any::<usize>(), prop::char::range(' ', '~')).prop_map(|(i, c)| Edit::ReplaceChar(i, c)),
    ]
}

fn apply(text: &str, e: &Edit) -> String {
    let mut lines: Vec<String> = text.lines().map(str::to_string).collect();
    let n = lines.len().max(1);
    match e {
        Edit::SetKey(i, v) => {
            let keyed: Vec<usize> = (0..lines.len())
                .filter(|k| lines[*k].contains(" = "))
                .collect();
            if let Some(&k) = keyed.get(i % keyed.len().max(1)) {
                let key = lines[k].split(" = ").next().unwrap().to_string();
                lines[k] = format!("{key} = {v}");
            }
        }
        Edit::DeleteLine(i) => {
            if !lines.is_empty() {
                lines.remove(i % n);
            }
        }
        Edit::DuplicateLine(i) => {
            if !lines.is_empty() {
                let l = lines[i % n].clone();
                lines.insert(i % n, l);
            }
        }
        Edit::InsertLine(i, l) => lines.insert(i % (lines.len() + 1), l.clone()),
        Edit::Truncate(i) => {
            let t: String = text.chars().take(i % (text.chars().count() + 1)).collect();
            return t;
        }
        Edit::ReplaceChar(i, c) => {
            let mut chars: Vec<char> = text.chars().collect();
            if !chars.is_empty() {
                let k = i % chars.len();
                chars[k] = *c;
            }
            return chars.into_iter().collect();
        }
    }
    lines.join("\n") + "\n"
}

fn mutated() -> impl Strategy<Value = String> {
    (
        prop::sample::select(bases()),
        prop::collection::vec(edit(), 1..5),
    )
        .prop_map(|(base, edits)| edits.iter().fold(base, |t, e| apply(&t, e)))
}

/// Whether an error message names a key (in backticks or before `=`) or a value.
fn names_a_key_or_value(msg: &str) -> bool {
    let keys = Param::ALL.iter().map(|p| p.key());
    msg.contains('`')
        || msg.contains(" = ")
        || keys
            .chain(["name", "inertia", "derivatives", "flight", "speed"])
            .any(|k| msg.contains(k))
}

fn finite_aircraft(ac: &Aircraft) -> bool {
    Param::ALL.iter().all(|p| ac.value(*p).is_finite())
}

/// Every number of an analysis, through its JSON form (a non-finite f64 becomes null).
fn finite_analysis(a: &Analysis) -> bool {
    // Null is a number that did not make it (NaN or inf in serde_json), except where it means
    // "none": no critical jump (and then no note's absence), no limit given (and then no
    // margin), no loss of stability on the primary branch, a zero-sideslip section not withheld.
    const MAY_BE_NULL: [&str; 7] = [
        "critical",
        "critical_note",
        "within_limits",
        "aileron_limit_deg",
        "margin_deg",
        "first_departure",
        "withheld",
    ];
    fn walk(v: &serde_json::Value) -> bool {
        match v {
            serde_json::Value::Null => false,
            serde_json::Value::Number(n) => n.as_f64().is_some_and(f64::is_finite),
            serde_json::Value::Array(a) => a.iter().all(walk),
            serde_json::Value::Object(o) => o
                .iter()
                .all(|(k, v)| (v.is_null() && MAY_BE_NULL.contains(&k.as_str())) || walk(v)),
            _ => true,
        }
    }
    walk(&serde_json::to_value(a).unwrap())
}

/// A runner with a fixed seed: the same cases on every machine and run, so that a failure
/// seen once is seen again.
fn runner(cases: u32) -> TestRunner {
    use proptest::test_runner::{RngAlgorithm, TestRng};
    let config = Config {
        cases,
        failure_persistence: None,
        ..Config::default()
    };
    TestRunner::new_with_rng(config, TestRng::deterministic_rng(RngAlgorithm::ChaCha))
}

/// A TOML syntax error: `Some(true)` when it names the file, line and column of the text at
/// fault and says what is wrong there; `Some(false)` when it has the position but no text
/// after it; `None` for any other error.
fn syntax_error(msg: &str) -> Option<bool> {
    let (at, rest) = msg.split_once(": TOML syntax error:")?;
    let positioned = at.split(':').count() == 3;
    Some(positioned && !rest.trim().is_empty())
}

#[test]
fn mutated_aircraft_files_parse_or_fail_naming_a_key_or_value() {
    let cases = 4000;
    let counts = std::cell::Cell::new((0usize, 0usize));
    runner(cases)
        .run(&mutated(), |text| {
            let (mut ok, mut err) = counts.get();
            match parse(&text, "mutant.toml") {
                Ok(ac) => {
                    ok += 1;
                    // Every value, also C, D, E computed from ix, iy, iz, is finite.
                    prop_assert!(finite_aircraft(&ac), "{text}");
                }
                Err(e) => {
                    err += 1;
                    let msg = e.to_string();
                    prop_assert!(msg.starts_with("mutant.toml:"), "{msg}");
                    match syntax_error(&msg) {
                        Some(true) => {}
                        Some(false) => prop_assert!(false, "syntax error without a message: {msg}"),
                        None => prop_assert!(names_a_key_or_value(&msg), "{msg}\n{text}"),
                    }
                }
            }
            counts.set((ok, err));
            Ok(())
        })
        .unwrap();
    let (ok, err) = counts.get();
    println!("parse: {cases} mutated files ({ok} parsed, {err} refused)");
    assert!(
        ok > 100 && err > 100,
        "both outcomes exercised: {ok} ok, {err} err"
    );
}

#[test]
fn random_bytes_never_panic_the_loader() {
    let cases = 2000;
    runner(cases)
        .run(&prop::collection::vec(1u8..=255, 0..300), |bytes| {
            let text = String::from_utf8_lossy(&bytes).into_owned();
            if let Err(e) = parse(&text, "noise.toml") {
                prop_assert!(e.to_string().starts_with("noise.toml"));
            }
            Ok(())
        })
        .unwrap();
    println!("parse: {cases} random byte strings");
}

/// A shipped aircraft with its derivatives scaled by random factors (zero and sign flips
/// included), at a random elevator.
fn scaled_aircraft() -> impl Strategy<Value = (String, f64)> {
    let factor = prop_oneof![
        Just(0.0),
        Just(-1.0),
        Just(1.0),
        Just(1e-3),
        Just(1e3),
        -10.0..10.0f64
    ];
    (
        prop::sample::select(bases()),
        prop::collection::vec((any::<usize>(), factor), 1..4),
        prop_oneof![
            -95.0..95.0f64,
            Just(0.0),
            Just(1e-300),
            Just(90.0),
            Just(-90.0)
        ],
    )
        .prop_map(|(base, scales, de)| {
            let mut lines: Vec<String> = base.lines().map(str::to_string).collect();
            let numeric: Vec<usize> = (0..lines.len())
                .filter(|k| {
                    let l = &lines[*k];
                    l.contains(" = ")
                        && !l.starts_with("name")
                        && !l.starts_with("n_delta_a")
                        && !l.starts_with('#')
                })
                .collect();
            for (i, f) in scales {
                let k = numeric[i % numeric.len()];
                let (key, rest) = lines[k].split_once(" = ").unwrap();
                let v: f64 = rest.split('#').next().unwrap().trim().parse().unwrap();
                lines[k] = format!("{key} = {:?}", v * f);
            }
            (lines.join("\n") + "\n", de)
        })
}

#[test]
fn analyze_on_random_aircraft_is_finite_or_names_the_reason() {
    let cases = 120;
    let counts = std::cell::Cell::new((0usize, 0usize, 0usize));
    runner(cases)
        .run(&scaled_aircraft(), |(text, de_deg)| {
            let (mut ok, mut refused, mut bad_file) = counts.get();
            match parse(&text, "scaled.toml") {
                Err(e) => {
                    bad_file += 1;
                    prop_assert!(names_a_key_or_value(&e.to_string()), "{e}");
                }
                Ok(ac) => match analyze(&ac, de_deg.to_radians()) {
                    Ok(a) => {
                        ok += 1;
                        prop_assert!(finite_analysis(&a), "{text}\ndelta_e {de_deg} deg: {a:?}");
                    }
                    Err(e) => {
                        refused += 1;
                        let msg = e.to_string();
                        prop_assert!(
                            names_a_key_or_value(&msg)
                                || msg.contains("P0")
                                || msg.contains("det "),
                            "{msg}"
                        );
                    }
                },
            }
            counts.set((ok, refused, bad_file));
            Ok(())
        })
        .unwrap();
    let (ok, refused, bad_file) = counts.get();
    println!(
        "analyze: {cases} random aircraft ({ok} analysed, {refused} refused, {bad_file} bad files)"
    );
}

#[test]
fn simulation_and_continuation_settings_are_checked_not_trusted() {
    use model::continuation::{continue_equilibria, Settings};
    use model::simulation::{simulate, Model, SimSettings};
    let num = prop_oneof![
        Just(f64::NAN),
        Just(f64::INFINITY),
        Just(f64::NEG_INFINITY),
        Just(0.0),
        Just(-1.0),
        Just(-1e-300),
        Just(1e300),
        -2.0..2.0f64
    ];
    let cases = 300;
    let a = Aircraft::a();
    runner(cases)
        .run(
            &(num.clone(), num.clone(), num.clone(), num),
            |(t_end, dt, da, de)| {
                // Short runs only: t_end is capped so that a valid case stays quick.
                let s = SimSettings {
                    t_end: if t_end.is_finite() {
                        t_end.min(0.5)
                    } else {
                        t_end
                    },
                    dt,
                    ..SimSettings::step(Model::Pss, de.clamp(-0.5, 0.5), da)
                };
                match simulate(&a, &s) {
                    Ok(h) => prop_assert!(h.p.iter().chain(&h.beta).all(|v| v.is_finite())),
                    Err(e) => prop_assert!(
                        names_a_key_or_value(&e.to_string()) || e.to_string().contains("delta_")
                    ),
                }
                // Continuation settings that cannot be valid are refused before any work.
                let c = Settings {
                    min: t_end,
                    max: dt,
                    delta_e: de,
                    ds_initial: da,
                    ..Settings::default()
                };
                let valid = t_end.is_finite()
                    && dt.is_finite()
                    && t_end < dt
                    && da > 0.0
                    && da.is_finite()
                    && de.is_finite();
                if !valid {
                    match continue_equilibria(&a, &c, &mut |_| {}) {
                        Ok(d) => prop_assert!(d
                            .branches
                            .iter()
                            .flat_map(|b| &b.points)
                            .all(|p| p.p.is_finite())),
                        Err(e) => prop_assert!(!e.to_string().is_empty()),
                    }
                }
                Ok(())
            },
        )
        .unwrap();
    println!("settings: {cases} random simulation and continuation settings");
}

/// A shipped aircraft made degenerate: one to six derivatives set to exactly zero (yaw
/// stiffness, damping and side force among them), possibly equal inertias (C = D = E = 0) and
/// data scaled by huge ratios, at a random elevator.
fn degenerate_aircraft() -> impl Strategy<Value = (String, f64)> {
    const ZEROABLE: [&str; 10] = [
        "n_beta", "n_r", "y_beta", "l_r", "l_beta", "m_q", "z_alpha", "l_p", "m_alpha", "n_p",
    ];
    (
        prop::sample::select(vec!["a.toml", "b.toml"]),
        prop::sample::subsequence(ZEROABLE.to_vec(), 1..=6),
        any::<bool>(),
        prop::option::of((
            prop::sample::select(ZEROABLE.to_vec()),
            prop_oneof![Just(1e6), Just(1e-6)],
        )),
        prop_oneof![Just(0.0), -5.0..5.0f64],
    )
        .prop_map(|(base, zeros, equal_inertias, scaled, de)| {
            let set = |text: String, key: &str, value: &dyn Fn(f64) -> f64| -> String {
                text.lines()
                    .map(|l| match l.split_once(" = ") {
                        Some((k, rest)) if k.trim() == key => {
                            let v: f64 = rest.split('#').next().unwrap().trim().parse().unwrap();
                            format!("{k} = {:?}", value(v))
                        }
                        _ => l.to_string(),
                    })
                    .collect::<Vec<_>>()
                    .join("\n")
                    + "\n"
            };
            let mut text = shipped(base);
            for key in zeros {
                text = set(text, key, &|_| 0.0);
            }
            if equal_inertias {
                for key in ["C", "D", "E"] {
                    text = set(text, key, &|_| 0.0);
                }
            }
            if let Some((key, factor)) = scaled {
                text = set(text, key, &|v| v * factor);
            }
            (text, de)
        })
}

/// No aircraft makes `analyze` hang: 2000 degenerate aircraft, each analysed in a worker
/// thread the test waits for at most 60 s (a hang fails the test and names the file). Every
/// answer is finite or a refusal that names its reason.
#[test]
fn analyze_ends_on_degenerate_aircraft() {
    let cases = 2000;
    let (to_worker, jobs) = std::sync::mpsc::channel::<(Aircraft, f64)>();
    let (to_test, answers) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        for (ac, de) in jobs {
            let answer = analyze(&ac, de).map_err(|e| e.to_string());
            if to_test.send(answer).is_err() {
                return;
            }
        }
    });
    let counts = std::cell::Cell::new((0usize, 0usize));
    // No shrinking: after a hang the worker is stuck, and every further case would wait too.
    let mut runner = runner(cases);
    let config = Config {
        max_shrink_iters: 0,
        ..runner.config().clone()
    };
    let mut runner = TestRunner::new_with_rng(config, runner.new_rng());
    runner
        .run(&degenerate_aircraft(), |(text, de_deg)| {
            let Ok(ac) = parse(&text, "degenerate.toml") else {
                return Ok(());
            };
            to_worker.send((ac, de_deg.to_radians())).unwrap();
            let Ok(answer) = answers.recv_timeout(std::time::Duration::from_secs(60)) else {
                return Err(TestCaseError::fail(format!(
                    "analyze hangs (60 s) on\n{text}\ndelta_e {de_deg} deg"
                )));
            };
            let (mut ok, mut refused) = counts.get();
            match answer {
                Ok(a) => {
                    ok += 1;
                    prop_assert!(finite_analysis(&a), "{text}\ndelta_e {de_deg} deg: {a:?}");
                }
                Err(msg) => {
                    refused += 1;
                    prop_assert!(
                        names_a_key_or_value(&msg) || msg.contains("P0") || msg.contains("det "),
                        "{msg}"
                    );
                }
            }
            counts.set((ok, refused));
            Ok(())
        })
        .unwrap();
    let (ok, refused) = counts.get();
    assert_eq!(ok + refused, cases as usize, "every degenerate file parses");
    println!("analyze: {cases} degenerate aircraft ({ok} analysed, {refused} refused)");
}

/// The inertia coefficients of random rigid bodies (principal moments that satisfy the
/// triangle inequalities), rounded to three decimals as in the paper's Table A.1, always load:
/// rounding never takes them beyond the loader's tolerance for C, D, E of one body.
#[test]
fn rounded_inertia_coefficients_of_rigid_bodies_load() {
    let cases = 1000;
    let a = shipped("a.toml");
    let body = (0.01..10.0f64, 0.01..10.0f64, 0.0..=1.0f64).prop_map(|(ix, iy, t)| {
        let iz = (ix - iy).abs() + t * (ix + iy - (ix - iy).abs());
        (ix, iy, iz)
    });
    runner(cases)
        .run(&body, |(ix, iy, iz)| {
            let (c, d, e) = ((iz - ix) / iy, (iy - ix) / iz, (iz - iy) / ix);
            let text = a
                .replacen("C = 0.959", &format!("C = {c:.3}"), 1)
                .replacen("D = 0.786", &format!("D = {d:.3}"), 1)
                .replacen("E = 0.705", &format!("E = {e:.3}"), 1);
            if let Err(err) = parse(&text, "rounded.toml") {
                prop_assert!(false, "ix {ix}, iy {iy}, iz {iz}: {err}");
            }
            Ok(())
        })
        .unwrap();
    println!("inertia: {cases} rounded rigid bodies");
}
