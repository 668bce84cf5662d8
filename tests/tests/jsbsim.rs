//! `model::jsbsim` against JSBSim itself: for catalogue models at seeded-random flight states
//! (altitude, Mach, alpha, beta, p, q, r and every flight-control input the aerodynamics read),
//! JSBSim (its Python package, through `tests/oracle/jsbsim_oracle.py`) gives the aerodynamic
//! forces and moments about the CG, the mass properties as loaded and each named function; the
//! native evaluation, fed the same inputs, must agree to 1e-9 relative. The test is skipped with
//! a message when the `jsbsim` package is not installed (`.ci/run` installs it). The derivatives
//! of the import are checked against central differences taken in JSBSim, and the imported file
//! against the aircraft loader and `analyze`.

use model::jsbsim::catalogue;
use model::jsbsim::condition::{Condition, Speed, State};
use model::jsbsim::derivatives::{derivatives, moved, DERIVATIVES};
use model::jsbsim::import::{import, Alpha, Loaded, Request};
use model::jsbsim::Model;
use model::random::Rng;
use serde_json::{json, Value};
use std::path::{Path, PathBuf};
use support::{f, jsbsim_coefficients, oracle_state};

mod support;

/// Relative agreement required: both sides sum the same products of the same table lookups in
/// double precision; what differs is the order of some operations (JSBSim interpolates a
/// two-variable table over rows first, this crate over columns first; the wind-to-body rotation
/// is written out here) and the rounding of the unit factors, each a few ulps, far below 1e-9.
const RELATIVE: f64 = 1e-9;

/// The catalogue models checked (the jets of the issue and others of each kind).
const MODELS: [&str; 8] = ["f104", "X15", "T38", "F4N", "f16", "A4", "c172p", "737"];

fn root() -> Option<PathBuf> {
    catalogue::root(None)
}

fn oracle(request: &Value) -> Vec<Value> {
    serde_json::from_value(support::oracle::run("jsbsim_oracle.py", request)).expect("oracle JSON")
}

/// Random states: altitude 5,000-40,000 ft, Mach 0.3-0.85, alpha -4..14 deg, beta -6..6 deg,
/// rates within 0.5 rad/s, each flight-control input within 0.3.
fn states(rng: &mut Rng, inputs: &[&str], n: usize) -> Vec<Value> {
    (0..n)
        .map(|_| {
            let set: serde_json::Map<String, Value> = inputs
                .iter()
                .filter(|i| i.starts_with("fcs/") && !i.contains("/mag-"))
                .map(|i| (i.to_string(), json!(rng.uniform(-0.3, 0.3))))
                .collect();
            json!({
                "h_ft": rng.uniform(5000.0, 40000.0),
                "mach": rng.uniform(0.3, 0.85),
                "alpha_deg": rng.uniform(-4.0, 14.0),
                "beta_deg": rng.uniform(-6.0, 6.0),
                "p": rng.uniform(-0.5, 0.5),
                "q": rng.uniform(-0.5, 0.5),
                "r": rng.uniform(-0.5, 0.5),
                "set": set,
            })
        })
        .collect()
}

/// The largest relative difference of `ours` from `theirs`, relative to `scale`.
fn worst(ours: &[f64], theirs: &[f64], scale: f64) -> f64 {
    ours.iter()
        .zip(theirs)
        .map(|(a, b)| (a - b).abs() / scale)
        .fold(0.0, f64::max)
}

fn norm(v: &[f64]) -> f64 {
    v.iter().map(|x| x * x).sum::<f64>().sqrt()
}

/// The standard atmosphere against JSBSim's at `h_ft`: density and speed of sound to 1e-6
/// relative (the same model; the constants are written in different units and digits).
fn check_atmosphere(atm: &Value, h_ft: f64) {
    let air = model::jsbsim::atmosphere::standard(h_ft * 0.3048).unwrap();
    let rho = air.density / 515.378_818_393_196_1;
    let a = air.sound_speed / 0.3048;
    let (rj, aj) = (f(&atm["rho"]), f(&atm["a"]));
    assert!(
        (rho - rj).abs() < 1e-6 * rj,
        "density at {h_ft} ft: ours {rho}, JSBSim {rj}"
    );
    assert!(
        (a - aj).abs() < 1e-6 * aj,
        "speed of sound at {h_ft} ft: ours {a}, JSBSim {aj}"
    );
}

/// Compares one model at `n` states; returns the worst relative differences (forces, moments,
/// mass).
fn check(root: &Path, name: &str, seed: u64, n: usize) -> [f64; 3] {
    let path = catalogue::model_path(Some(root), name).unwrap();
    let model = Model::load(&path).unwrap_or_else(|e| panic!("{name}: {e}"));
    let inputs = model.functions.inputs();
    let functions: Vec<&str> = model
        .functions
        .list
        .iter()
        .map(|f| f.name.as_str())
        .collect();
    let states = states(&mut Rng::new(seed), &inputs, n);
    let request = json!({"root": root, "model": name, "inputs": inputs,
                         "functions": functions, "states": states});
    let totals = model.totals();
    let mut worst_all = [0.0f64; 3];
    for out in oracle(&request) {
        let mut env = model.environment();
        for (k, v) in out["inputs"].as_object().unwrap() {
            if env.is_unset(k) {
                env.set(k, f(v));
            }
        }
        let atm = &out["atmosphere"];
        check_atmosphere(atm, f(&out["h_ft"]));
        let loads = model
            .loads(&mut env, f(&atm["alpha"]), f(&atm["beta"]))
            .unwrap();
        let force: Vec<f64> = out["forces"].as_array().unwrap().iter().map(f).collect();
        let moment: Vec<f64> = out["moments"].as_array().unwrap().iter().map(f).collect();
        let fs = norm(&force).max(1.0);
        let ms = norm(&moment).max(fs * model.metrics.chord);
        let m = &out["mass"];
        let cg: Vec<f64> = m["cg"].as_array().unwrap().iter().map(f).collect();
        let [ixx, iyy, izz, ixz] = totals.moments();
        let inertia = [ixx, iyy, izz, ixz];
        // JSBSim's inertia/ixz-slugs_ft2 is minus the integral of x z dm (body axes).
        let theirs = [f(&m["ixx"]), f(&m["iyy"]), f(&m["izz"]), -f(&m["ixz"])];
        let mass = worst(&inertia, &theirs, ixx.max(iyy).max(izz))
            .max(worst(&totals.cg, &cg, 100.0))
            .max(worst(&[totals.weight], &[f(&m["weight"])], totals.weight));
        let w = [
            worst(&loads.force, &force, fs),
            worst(&loads.moment, &moment, ms),
            mass,
        ];
        for (a, b) in worst_all.iter_mut().zip(w) {
            *a = a.max(b);
        }
        if w.iter().any(|&x| x > RELATIVE) {
            for (fname, v) in out["functions"].as_object().unwrap() {
                let ours = env.property(fname).unwrap();
                if (ours - f(v)).abs() > 1e-9 * f(v).abs().max(1.0) {
                    eprintln!("{name}: {fname}: ours {ours}, JSBSim {}", f(v));
                }
            }
            panic!(
                "{name}: forces {force:?} vs ours {:?}, moments {moment:?} vs ours {:?}, \
                 inertia {theirs:?} vs ours {inertia:?}, cg {cg:?} vs ours {:?}",
                loads.force, loads.moment, totals.cg
            );
        }
    }
    worst_all
}

/// Every model of the catalogue that the import reads, at three states each (run with
/// `--ignored`: about 20 s).
#[test]
#[ignore]
fn every_importable_catalogue_model_agrees_with_jsbsim() {
    let Some(root) = root() else {
        eprintln!("skipped: {}", catalogue::HOW_TO_GET);
        return;
    };
    let mut agreed = Vec::new();
    for (k, (name, model)) in catalogue::listing(&root).into_iter().enumerate() {
        let path = root
            .join("aircraft")
            .join(&name)
            .join(format!("{name}.xml"));
        let Ok(model) = model else { continue };
        if model::jsbsim::import::evaluates(&model, &path).is_err() {
            continue;
        }
        let w = check(&root, &name, 100 + k as u64, 3);
        eprintln!(
            "{name}: worst relative difference forces {:.1e}, moments {:.1e}, mass {:.1e}",
            w[0], w[1], w[2]
        );
        agreed.push(name);
    }
    eprintln!("{} models agree: {}", agreed.len(), agreed.join(", "));
}

#[test]
fn forces_moments_and_mass_agree_with_jsbsim() {
    let Some(root) = root() else {
        eprintln!("skipped: {}", catalogue::HOW_TO_GET);
        return;
    };
    for (k, name) in MODELS.iter().enumerate() {
        let w = check(&root, name, 36 + k as u64, 6);
        eprintln!(
            "{name}: worst relative difference forces {:.1e}, moments {:.1e}, mass {:.1e}",
            w[0], w[1], w[2]
        );
    }
}

/// The import's derivatives against central differences taken in JSBSim (step 1e-4 in each
/// variable, alpha-dot and beta-dot held at zero, the fed-back lift settled): the state
/// construction, the rate scaling, the body-to-wind conversion and the aileron sign are checked
/// by an independent computation. The two steps differ (1e-6 here), so the agreement is to the
/// curvature of the coefficients over 1e-4: 1e-3 relative, 1e-4 absolute.
#[test]
fn derivatives_agree_with_central_differences_in_jsbsim() {
    let Some(root) = root() else {
        eprintln!("skipped: {}", catalogue::HOW_TO_GET);
        return;
    };
    // An alpha given (elevator neutral, no pitch rate), or NaN for the 2-g trim (the trimmed
    // alpha, elevator and pull-up pitch rate: the state the import differentiates at, which the
    // file's derivatives must equal).
    for (name, altitude_m, mach, alpha_deg) in [
        ("f104", 6000.0, 0.5, 4.0f64),
        ("X15", 6096.0, 0.5, 3.0),
        ("T38", 3000.0, 0.6, 2.5),
        ("f104", 3048.0, 0.9, f64::NAN),
    ] {
        let loaded = Loaded::new(name, Some(&root), &[]).unwrap();
        let model = &loaded.model;
        let setup = loaded.setup(Condition::new(altitude_m, Speed::Mach(mach)).unwrap());
        let state = if alpha_deg.is_nan() {
            model::jsbsim::trim::trim(&setup, 2.0).unwrap().state()
        } else {
            State {
                alpha: alpha_deg.to_radians(),
                beta: 0.0,
                rates: [0.0; 3],
                surfaces: [0.0; 3],
            }
        };
        let (base, ours) = derivatives(&setup, &state).unwrap();
        if alpha_deg.is_nan() {
            let text = import(&Request {
                model: name.into(),
                root: Some(root.clone()),
                altitude_m,
                speed: Speed::Mach(mach),
                alpha: Alpha::Trim(2.0),
                settings: Vec::new(),
            })
            .unwrap();
            assert!(state.rates[1] > 0.0 && state.surfaces[1] < 0.0, "{state:?}");
            for d in &ours {
                let line = format!("\n{} = {:?}", d.key, d.value);
                assert!(text.contains(&line), "{line} not in the file:\n{text}");
            }
        }
        let h = 1e-4;
        let mut states = Vec::new();
        for (_, _, variable, _) in DERIVATIVES {
            for step in [h, -h] {
                states.push(oracle_state(
                    &setup,
                    &moved(&setup, &state, variable, step),
                    &base.zeroed,
                ));
            }
        }
        let inputs = model.functions.inputs();
        let request = json!({"root": root, "model": name, "inputs": inputs, "functions": [],
                             "states": states, "quasi_steady": true});
        let out = oracle(&request);
        for (k, ((key, c, _, sign), d)) in DERIVATIVES.iter().zip(&ours).enumerate() {
            let plus = jsbsim_coefficients(&out[2 * k], model)[*c];
            let minus = jsbsim_coefficients(&out[2 * k + 1], model)[*c];
            let theirs = sign * (plus - minus) / (2.0 * h);
            let tol = 1e-4 + 1e-3 * theirs.abs();
            eprintln!("{name} {key}: ours {:.6}, JSBSim {theirs:.6}", d.value);
            assert!(
                (d.value - theirs).abs() < tol,
                "{name} {key}: ours {}, JSBSim {theirs}",
                d.value
            );
        }
    }
}

/// The imported file loads with the aircraft loader and `analyze` runs on it; the `jsbsim:`
/// source gives the same aircraft.
#[test]
fn imported_files_load_and_analyze() {
    let Some(root) = root() else {
        eprintln!("skipped: {}", catalogue::HOW_TO_GET);
        return;
    };
    for name in ["f104", "X15", "T38", "F4N"] {
        let request = Request {
            model: name.into(),
            root: Some(root.clone()),
            altitude_m: 6000.0,
            speed: Speed::Mach(0.5),
            alpha: Alpha::Trim(1.0),
            settings: Vec::new(),
        };
        let text = import(&request).unwrap_or_else(|e| panic!("{name}: {e}"));
        let aircraft =
            model::aircraft::parse(&text, name).unwrap_or_else(|e| panic!("{name}: {e}\n{text}"));
        let analysis = model::analysis::analyze(&aircraft, 2f64.to_radians());
        assert!(analysis.is_ok(), "{name}: analyze failed");
        let spec = format!(
            "jsbsim:{name} --jsbsim-root {} --altitude-m 6000 --mach 0.5",
            root.display()
        );
        let source = model::jsbsim::cli::source(&spec).unwrap();
        assert_eq!(
            source.values_f64(),
            aircraft.values_f64(),
            "{name}: the jsbsim: source differs"
        );
    }
}

#[test]
fn inertias_no_rigid_body_has_are_analysed_with_a_warning() {
    let Some(root) = root() else {
        eprintln!("skipped: {}", catalogue::HOW_TO_GET);
        return;
    };
    // The eight catalogue models whose principal moments break a triangle inequality, each
    // where it flies level (the jets at 6096 m, Mach 0.6, the L410 and the c310 slower).
    for (name, mach) in [
        ("787-8", 0.6),
        ("A4", 0.6),
        ("Concorde", 0.6),
        ("f22", 0.6),
        ("global5000", 0.6),
        ("MD11", 0.6),
        ("L410", 0.4),
        ("c310", 0.3),
    ] {
        let spec = format!(
            "jsbsim:{name} --jsbsim-root {} --altitude-m 6096 --mach {mach} --level-flight",
            root.display()
        );
        let aircraft = model::jsbsim::cli::source(&spec).unwrap_or_else(|e| panic!("{e}"));
        let inertia: Vec<&String> = aircraft
            .warnings
            .iter()
            .filter(|w| !w.starts_with(model::jsbsim::clamp::WARNING_START))
            .collect();
        let [warning] = inertia.as_slice() else {
            panic!(
                "{name}: one warning of the inertia expected, got {:?}",
                aircraft.warnings
            );
        };
        assert!(
            warning.contains("break the triangle inequality"),
            "{warning}"
        );
        let analysis = model::analysis::fast::analyze_routed_with(&aircraft, 0.0349, false)
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_eq!(analysis.0.warnings, aircraft.warnings, "{name}");
    }
}

/// The number of `key = value` in an imported aircraft file (its keys are unique).
fn file_number(text: &str, key: &str) -> f64 {
    text.lines()
        .find_map(|l| {
            let (k, rest) = l.split_once('=')?;
            (k.trim() == key).then(|| rest.split_whitespace().next().unwrap().parse().unwrap())
        })
        .unwrap_or_else(|| panic!("no `{key}` in\n{text}"))
}

/// The F-16 at 12,000 m, Mach 0.5: its Cm_alpha is positive (the bare airframe, which flies
/// behind the stability augmentation of its flight control system), so the trim the primary
/// branch starts from is statically unstable in pitch. The first departure is that trim, a real
/// divergence in pitch whose eigenvalue is the positive root of the pitch subsystem at P0 = 0,
/// s^2 - (z_alpha + m_q) s + (z_alpha m_q - m_alpha), computed here from the file's
/// nondimensional coefficients by the textbook formulas (qbar = rho V^2 / 2; z_alpha = -qbar S
/// CL_alpha / (m V), m_alpha = qbar S c Cm_alpha / Iy, m_q = qbar S c^2 Cm_q / (2 V Iy): a
/// rotation to principal axes in the x-z plane leaves pitch alone).
#[test]
fn the_bare_f16_at_12000_m_mach_0_5_departs_at_its_unstable_trim() {
    let Some(root) = root() else {
        eprintln!("skipped: {}", catalogue::HOW_TO_GET);
        return;
    };
    let args = [
        "jsbsim",
        "f16",
        "--jsbsim-root",
        root.to_str().unwrap(),
        "--altitude-m",
        "12000",
        "--mach",
        "0.5",
        "--level-flight",
    ]
    .map(String::from);
    let mut out = Vec::new();
    assert_eq!(model::jsbsim::cli::run(&args, &mut out), 0, "the import");
    let text = String::from_utf8(out).unwrap();
    let k = |key: &str| file_number(&text, key);
    assert!(k("Cm_alpha") > 0.0, "the bare F-16 is statically unstable");
    let (v, rho) = (k("speed"), k("density"));
    let qs = 0.5 * rho * v * v * k("wing_area");
    let (c, iy) = (k("chord"), k("iy"));
    let z_alpha = -qs * k("CL_alpha") / (k("mass") * v);
    let m_alpha = qs * c * k("Cm_alpha") / iy;
    let m_q = qs * c * c * k("Cm_q") / (2.0 * v * iy);
    let (trace, det) = (z_alpha + m_q, z_alpha * m_q - m_alpha);
    assert!(det < 0.0, "z_alpha m_q - m_alpha = {det}");
    let want = (trace + (trace * trace - 4.0 * det).sqrt()) / 2.0;

    let aircraft = model::aircraft::parse(&text, "f16").unwrap();
    let (a, _) = model::analysis::fast::analyze_routed_with(&aircraft, 0.0, true).unwrap();
    let f = a.first_departure.as_ref().expect("a first departure");
    assert_eq!(
        (f.kind, f.p0, f.delta_a_rad),
        ("unstable_trim", 0.0, 0.0),
        "{f:?}"
    );
    let u = f.unstable_trim.as_ref().unwrap();
    let [m] = u.modes.as_slice() else {
        panic!("one unstable mode expected: {u:?}");
    };
    assert_eq!((m.motion, m.subsystem), ("divergence", "pitch"), "{m:?}");
    assert!(
        (m.eigenvalue_re - want).abs() < 1e-9 * want,
        "{} vs {want}",
        m.eigenvalue_re
    );
    assert!(
        m.cause
            .as_deref()
            .unwrap()
            .starts_with("static pitch instability"),
        "{m:?}"
    );
}

/// The F-104's tables end at Mach 2 (the roll damping's at Mach 1.8). JSBSim holds a table's
/// end value beyond its breakpoints: its roll-damping table reads the same at Mach 5 as at
/// Mach 1.8, the value written there (-0.2720). The import at Mach 5 names every table it reads
/// so in one warning, which reaches the file, the loader and `analyze`.
#[test]
fn the_f104_at_mach_5_names_the_tables_it_reads_beyond_their_breakpoints() {
    let Some(root) = root() else {
        eprintln!("skipped: {}", catalogue::HOW_TO_GET);
        return;
    };
    let path = catalogue::model_path(Some(&root), "f104").unwrap();
    let model = Model::load(&path).unwrap();
    let state = |mach: f64| {
        json!({"h_ft": 15000.0 / 0.3048, "mach": mach, "alpha_deg": 1.0, "beta_deg": 0.0,
               "p": 0.2, "q": 0.0, "r": 0.0, "set": {}})
    };
    let request = json!({"root": root, "model": "f104", "inputs": model.functions.inputs(),
                         "functions": ["aero/coefficient/Clp"], "states": [state(1.8), state(5.0)]});
    for out in oracle(&request) {
        let i = &out["inputs"];
        let factors: f64 = [
            "aero/qbar-psf",
            "metrics/Sw-sqft",
            "metrics/bw-ft",
            "aero/bi2vel",
        ]
        .iter()
        .chain(&["velocities/p-rad_sec"])
        .map(|n| f(&i[*n]))
        .product();
        let table = f(&out["functions"]["aero/coefficient/Clp"]) / factors;
        assert!(
            (table + 0.272).abs() < 1e-12,
            "JSBSim's roll-damping table at Mach {}: {table}",
            out["atmosphere"]["mach"]
        );
    }
    let request = Request {
        model: "f104".into(),
        root: Some(root.clone()),
        altitude_m: 15000.0,
        speed: Speed::Mach(5.0),
        alpha: Alpha::Given(0.03),
        settings: Vec::new(),
    };
    let text = import(&request).unwrap();
    let aircraft = model::aircraft::parse(&text, "f104").unwrap();
    let mach: Vec<&String> = aircraft
        .warnings
        .iter()
        .filter(|w| w.contains("reads `velocities/mach` = 5 beyond the breakpoints of"))
        .collect();
    let [warning] = mach.as_slice() else {
        panic!(
            "one warning of the Mach number expected: {:?}",
            aircraft.warnings
        );
    };
    for part in [
        "the imported flight state (altitude 15000 m, Mach 5, alpha",
        "where JSBSim holds the end value",
        "0.4 to 2 in aero/coefficient/CLo, aero/coefficient/CLalpha",
        "0.257 to 1.8 in aero/coefficient/CYb, aero/coefficient/Clb, aero/coefficient/Clp",
        "aero/coefficient/Clp",
    ] {
        assert!(warning.contains(part), "{part} not in {warning}");
    }
    assert!(text.contains(&format!("# Warning: {warning}.")), "{text}");
    let (analysis, _) = model::analysis::fast::analyze_routed_with(&aircraft, 0.0, true).unwrap();
    assert_eq!(analysis.warnings, aircraft.warnings);
}
