//! Shared by the randomised tests (`certified.rs`, `hopf_fast.rs`, `clearance.rs`,
//! `envelope_uncertainty.rs`): their size, random aircraft around A and B, the comparison of an
//! exact and a certified analysis, whether the JSBSim models are installed, and the JSBSim
//! tests' Python oracles (`jsbsim.rs`, `jsbsim_trim.rs`).

#![allow(dead_code)]

pub mod oracle;

use model::aircraft::{Aircraft, Param};
use model::analysis::{Analysis, JumpPoint};
use num_rational::BigRational;

/// The path of a test's scratch file or folder `name` (tagged with the process) in Cargo's
/// scratch space for integration tests, under target/, so that no run leaves files in the
/// system's temporary folder.
pub fn scratch(name: &str) -> std::path::PathBuf {
    let tagged = format!("{name}-{}", std::process::id());
    std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join(tagged)
}

/// The environment variable that asks the randomised tests for their full size.
pub const FULL_SIZE: &str = "ROLL_FULL_SIZE";

/// `full` when `ROLL_FULL_SIZE=1` is set, else `default`: a randomised property is checked on a
/// sample sized for a check in the default run (seconds), and on a sample sized for a proof in
/// the full-size run (minutes; docs/contributing.md gives the command).
pub fn size(default: usize, full: usize) -> usize {
    if std::env::var(FULL_SIZE).is_ok_and(|v| v == "1") {
        full
    } else {
        default
    }
}

/// Whether the JSBSim models are installed (`pip install jsbsim`); says so when not, for the
/// tests that skip without them.
pub fn jsbsim_installed() -> bool {
    let found = model::jsbsim::catalogue::root(None).is_some();
    if !found {
        eprintln!("skipped: the JSBSim models are not installed (pip install jsbsim)");
    }
    found
}

/// The number `v` of an oracle's output.
pub fn f(v: &serde_json::Value) -> f64 {
    v.as_f64()
        .unwrap_or_else(|| panic!("number expected, got {v}"))
}

/// JSBSim's coefficients (CL, CD, CY, Cl, Cm, Cn) from its body forces and moments.
pub fn jsbsim_coefficients(out: &serde_json::Value, model: &model::jsbsim::Model) -> [f64; 6] {
    let atm = &out["atmosphere"];
    let (a, b) = (f(&atm["alpha"]), f(&atm["beta"]));
    let qs = f(&atm["qbar"]) * model.metrics.wing_area;
    let fb: Vec<f64> = out["forces"].as_array().unwrap().iter().map(f).collect();
    let m: Vec<f64> = out["moments"].as_array().unwrap().iter().map(f).collect();
    let wx = a.cos() * b.cos() * fb[0] + b.sin() * fb[1] + a.sin() * b.cos() * fb[2];
    let wz = -a.sin() * fb[0] + a.cos() * fb[2];
    let (s, c) = (model.metrics.span, model.metrics.chord);
    [
        -wz / qs,
        -wx / qs,
        fb[1] / qs,
        m[0] / (qs * s),
        m[1] / (qs * c),
        m[2] / (qs * s),
    ]
}

/// The oracle's description of `state` at `setup`'s condition: surfaces set as the import sets
/// them, the clean configuration's zeros (`zeroed`, gear up among them) given to JSBSim too.
pub fn oracle_state(
    setup: &model::jsbsim::coefficients::Setup,
    state: &model::jsbsim::condition::State,
    zeroed: &[String],
) -> serde_json::Value {
    use serde_json::{json, Value};
    let mut set: serde_json::Map<String, Value> =
        zeroed.iter().map(|n| (n.clone(), json!(0.0))).collect();
    set.extend(
        setup
            .surfaces
            .iter()
            .zip(state.surfaces)
            .flat_map(|(s, x)| s.values(x))
            .filter_map(|(n, v)| v.map(|v| (n.to_string(), json!(v)))),
    );
    json!({
        "h_ft": setup.condition.altitude_m / 0.3048,
        "mach": setup.condition.mach,
        "alpha_deg": state.alpha.to_degrees(),
        "beta_deg": state.beta.to_degrees(),
        "p": state.rates[0], "q": state.rates[1], "r": state.rates[2],
        "set": set,
    })
}

/// The project's seeded generator (SplitMix64), the same as the Monte Carlo's.
pub use model::random::Rng;

/// `x` with five significant decimal digits, exactly (the literal a data file would hold).
pub fn five_digits(x: f64) -> BigRational {
    model::aircraft::decimal_to_rational(&format!("{x:.4e}")).expect("a decimal literal")
}

pub fn random_aircraft(rng: &mut Rng, i: usize) -> Aircraft {
    let base = if i % 2 == 0 {
        Aircraft::a()
    } else {
        Aircraft::b()
    };
    let mut a = base.clone();
    for p in Param::ALL {
        let v = base.value(p);
        let moved = match p {
            // Physical inertia coefficients stay within (-1, 1).
            Param::C | Param::D | Param::E => (v * rng.uniform(0.7, 1.3)).clamp(-0.99, 0.99),
            Param::NDeltaA => {
                if rng.unit() < 0.5 {
                    0.0
                } else {
                    rng.uniform(-10.0, 10.0)
                }
            }
            Param::LDeltaR => {
                if rng.unit() < 0.3 {
                    rng.uniform(-5.0, 5.0)
                } else {
                    0.0
                }
            }
            Param::Np => {
                if rng.unit() < 0.3 {
                    rng.uniform(-0.5, 0.5)
                } else {
                    0.0
                }
            }
            _ => v * rng.uniform(0.7, 1.3),
        };
        let exact = if moved == 0.0 {
            BigRational::from_integer(0.into())
        } else {
            five_digits(moved)
        };
        a = a.with(p, exact);
    }
    a
}

/// Whether a certified roll rate `f` agrees with the exact one `e`: `e` is correctly rounded,
/// `f` lies in a bracket of relative width at most `width` around the exact root.
pub fn close_roots(e: f64, f: f64, width: f64) -> bool {
    (e - f).abs() <= (width + 2.0 * f64::EPSILON) * e.abs().max(f.abs())
}

/// Whether two values evaluated at a root agree: to 1e-6 relative, the precision `analyze`
/// prints. Both routes evaluate the trim in f64 at the root, and that evaluation is itself far
/// less accurate than the root in two places the random sample meets: next to a divergence roll
/// rate (the trim has a pole there) and where the two trims of a roll rate nearly merge (with
/// aileron yaw the aileron is a root of a quadratic whose discriminant nearly vanishes, and the
/// square root amplifies rounding: measured up to 5e-7 relative between the two routes, whose
/// polynomials' f64 coefficients differ by a few ulps).
pub fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-6 * a.abs().max(b.abs()) + 1e-9
}

pub fn same_point(e: &JumpPoint, f: &JumpPoint, w: f64) -> Result<(), String> {
    if !close_roots(e.p0, f.p0, w) {
        return Err(format!("P0 {} vs {}", e.p0, f.p0));
    }
    if e.within_limits != f.within_limits || e.within_validity != f.within_validity {
        return Err(format!("marks at P0 = {}", e.p0));
    }
    // Outside the validity range (trims of hundreds of degrees, where the linear model means
    // nothing) the trim is a badly conditioned f64 evaluation on both routes: only the roll
    // rate and the marks are compared there.
    if !e.within_validity {
        return Ok(());
    }
    for (name, x, y) in [
        ("delta_a", e.delta_a_rad, f.delta_a_rad),
        ("alpha", e.alpha, f.alpha),
        ("beta", e.beta, f.beta),
        ("q", e.q, f.q),
        ("r", e.r, f.r),
    ] {
        if !close(x, y) {
            return Err(format!("{name} at P0 = {}: {x} vs {y}", e.p0));
        }
    }
    Ok(())
}

pub fn same_analysis(e: &Analysis, f: &Analysis, w: f64) -> Result<(), String> {
    let lens = |a: &Analysis| {
        (
            a.divergence_roll_rates.len(),
            a.jump.len(),
            a.det_k_poles.len(),
            a.zero_sideslip.departure.len(),
        )
    };
    if lens(e) != lens(f) {
        return Err(format!("counts {:?} vs {:?}", lens(e), lens(f)));
    }
    for (x, y) in e.divergence_roll_rates.iter().zip(&f.divergence_roll_rates) {
        if !close_roots(*x, *y, w) {
            return Err(format!("divergence {x} vs {y}"));
        }
    }
    for (x, y) in e
        .jump
        .iter()
        .zip(&f.jump)
        .chain(e.det_k_poles.iter().zip(&f.det_k_poles))
    {
        same_point(x, y, w)?;
    }
    match (&e.critical, &f.critical) {
        (None, None) => {
            if e.critical_note.is_none() != f.critical_note.is_none() {
                return Err("critical note".into());
            }
        }
        (Some(x), Some(y)) => same_point(x, y, w)?,
        _ => return Err(format!("critical {:?} vs {:?}", e.critical, f.critical)),
    }
    for (x, y) in e
        .zero_sideslip
        .departure
        .iter()
        .zip(&f.zero_sideslip.departure)
    {
        let ok = close_roots(x.p0, y.p0, w)
            && x.within_limits == y.within_limits
            && x.within_validity == y.within_validity
            && (!x.within_validity
                || close(x.delta_a_rad, y.delta_a_rad)
                    && close(x.delta_r_rad, y.delta_r_rad)
                    && close(x.alpha, y.alpha));
        if !ok {
            return Err(format!("zero-sideslip departure {x:?} vs {y:?}"));
        }
    }
    Ok(())
}
