//! Tests of the conversion: by hand and exactly, against an independent f64 computation, and
//! the output of `model convert` loading as the same aircraft; refused files in `tests/refused.rs`.

use super::dimensional_toml::toml_string;
use super::*;
use crate::aircraft::{decimal_to_rational, parse, AircraftError, Limits};
use nalgebra::{Matrix2, SymmetricEigen, Vector2};

/// A made-up aircraft in the body-axis format; round numbers so that the conversion can be
/// done by hand (see `conversion_by_hand_exact`).
const BODY: &str = r#"name = "Made up"
[flight]
speed = 100
density = 1.2
[geometry]
mass = 10000
wing_area = 20
span = 10
chord = 2
[inertia]
ix = 10000
iy = 40000
iz = 50000
ixz = 0
[coefficients]
CL_alpha = 5
CY_beta = -1
Cl_beta = -0.1
Cl_p = -0.4
Cl_r = 0.1
Cl_delta_a = -0.2
Cl_delta_r = 0.01
Cm_alpha = -0.5
Cm_q = -10
Cm_delta_e = -1
Cn_beta = 0.1
Cn_p = -0.05
Cn_r = -0.3
Cn_delta_a = 0.01
Cn_delta_r = -0.05
"#;

const FILE: &str = "body.toml";

fn fighter_text() -> &'static str {
    include_str!(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../aircraft/fighter.toml"
    ))
}

fn body(from: &str, to: &str) -> String {
    assert!(BODY.contains(from), "{from}");
    BODY.replacen(from, to, 1)
}

fn err(text: &str, line: usize, needles: &[&str]) -> AircraftError {
    let e = match parse(text, FILE) {
        Ok(a) => panic!("expected an error, got {a:?}"),
        Err(e) => e,
    };
    let msg = e.to_string();
    assert!(
        msg.contains(&format!("{FILE}:{line}:")),
        "no line {line} in: {msg}"
    );
    for n in needles {
        assert!(msg.contains(n), "no `{n}` in: {msg}");
    }
    e
}

/// `model convert` on a text: written to a temporary file, converted by `convert_file`.
fn convert_text(text: &str) -> String {
    use std::sync::atomic::{AtomicUsize, Ordering};
    static N: AtomicUsize = AtomicUsize::new(0);
    let n = N.fetch_add(1, Ordering::Relaxed);
    let path = std::env::temp_dir().join(format!("convert-{}-{n}.toml", std::process::id()));
    std::fs::write(&path, text).unwrap();
    let out = crate::aircraft::convert_file(&path);
    let _ = std::fs::remove_file(&path);
    out.unwrap_or_else(|e| panic!("{e}"))
}
mod refused;

#[test]
fn conversion_by_hand_exact() {
    // qbar = 1.2 * 100^2 / 2 = 6000 Pa, qbar S = 120000 N; qbar S b = 1.2e6 N m,
    // qbar S b (b/2V) = 60000 N m s; qbar S c = 240000 N m, qbar S c (c/2V) = 2400 N m s.
    // ixz = 0: the body axes are principal, so the principal axis meets the flight path at the
    // trim's body-axis alpha.
    let a = parse(
        &body("[flight]\n", "[flight]\nalpha = 0.05\nload_factor = 2\n"),
        FILE,
    )
    .unwrap();
    let q = |s: &str| decimal_to_rational(s).unwrap();
    let want = [
        (Param::C, "1"),          // (50000 - 10000) / 40000
        (Param::D, "0.6"),        // (40000 - 10000) / 50000
        (Param::E, "1"),          // (50000 - 40000) / 10000
        (Param::ZAlpha, "-0.6"),  // -120000 * 5 / (10000 * 100)
        (Param::YBeta, "-0.12"),  // 120000 * -1 / (10000 * 100)
        (Param::Lp, "-2.4"),      // 60000 * -0.4 / 10000
        (Param::Lr, "0.6"),       // 60000 * 0.1 / 10000
        (Param::LBeta, "-12"),    // 1.2e6 * -0.1 / 10000
        (Param::LDeltaA, "-24"),  // 1.2e6 * -0.2 / 10000
        (Param::LDeltaR, "1.2"),  // 1.2e6 * 0.01 / 10000
        (Param::Mq, "-0.6"),      // 2400 * -10 / 40000
        (Param::MAlpha, "-3"),    // 240000 * -0.5 / 40000
        (Param::MDeltaE, "-6"),   // 240000 * -1 / 40000
        (Param::Np, "-0.06"),     // 60000 * -0.05 / 50000
        (Param::Nr, "-0.36"),     // 60000 * -0.3 / 50000
        (Param::NBeta, "2.4"),    // 1.2e6 * 0.1 / 50000
        (Param::NDeltaA, "0.24"), // 1.2e6 * 0.01 / 50000
        (Param::NDeltaR, "-1.2"), // 1.2e6 * -0.05 / 50000
        (Param::Z0, "-0.196133"), // -2 * 9.80665 / 100
        (Param::AlphaT, "0.05"),  // 0.05 - 0
    ];
    assert_eq!(want.len(), Param::ALL.len());
    for (p, v) in want {
        assert_eq!(*a.exact(p), q(v), "{p:?}");
    }
    assert_eq!(a.speed, 100.0);
    assert_eq!(a.name, "Made up");
}

/// The conversion by straightforward f64 code of its own: ISA by the formula with the
/// constants typed here, principal axes by nalgebra's symmetric eigensolver.
fn independent_f64(
    v: f64,
    rho: f64,
    geom: [f64; 4],
    inertia: [f64; 4],
    c: &[f64; 15],
    trim: (Option<f64>, f64),
) -> ([f64; Param::COUNT], f64) {
    let [m, s, b, ch] = geom;
    let [ix, iy, iz, ixz] = inertia;
    let qbar = 0.5 * rho * v * v;
    let [cla, cyb, clb, clp, clr, clda, cldr, cma, cmq, cmde, cnb, cnp, cnr, cnda, cndr] = *c;
    let lat = qbar * s * b;
    let rate = lat * b / (2.0 * v);
    let eig = SymmetricEigen::new(Matrix2::new(ix, -ixz, -ixz, iz));
    let cols: Vec<Vector2<f64>> = (0..2).map(|i| eig.eigenvectors.column(i).into()).collect();
    let k = if cols[0].x.abs() >= cols[1].x.abs() {
        0
    } else {
        1
    };
    let mut xp = cols[k];
    if xp.x < 0.0 {
        xp = -xp;
    }
    let mut zp = cols[1 - k];
    if zp.y < 0.0 {
        zp = -zp;
    }
    let r = Matrix2::from_columns(&[xp, zp]);
    let ixp = (r.transpose() * Matrix2::new(ix, -ixz, -ixz, iz) * r)[(0, 0)];
    let izp = (r.transpose() * Matrix2::new(ix, -ixz, -ixz, iz) * r)[(1, 1)];
    let a = r.transpose() * Matrix2::new(rate * clp, rate * clr, rate * cnp, rate * cnr) * r;
    let vec = |l: f64, n: f64| r.transpose() * Vector2::new(lat * l, lat * n);
    let (beta, da, dr) = (vec(clb, cnb), vec(clda, cnda), vec(cldr, cndr));
    let lon = qbar * s * ch;
    let out = [
        (izp - ixp) / iy,
        (iy - ixp) / izp,
        (izp - iy) / ixp,
        -qbar * s * cla / (m * v),
        qbar * s * cyb / (m * v),
        a[(0, 0)] / ixp,
        a[(0, 1)] / ixp,
        beta.x / ixp,
        da.x / ixp,
        lon * ch / (2.0 * v) * cmq / iy,
        lon * cma / iy,
        lon * cmde / iy,
        a[(1, 0)] / izp,
        a[(1, 1)] / izp,
        beta.y / izp,
        da.y / izp,
        dr.y / izp,
        dr.x / ixp,
        // z_0 = -n g / V; the flight path lies alpha below body x, the principal x axis `tilt`
        // below it.
        -trim.1 * 9.80665 / v,
        trim.0.map_or(0.0, |alpha| alpha - xp.y.atan2(xp.x)),
    ];
    (out, xp.y.atan2(xp.x).to_degrees())
}

#[test]
fn conversion_with_tilt_and_isa_matches_an_independent_f64_computation() {
    // The numbers of aircraft/fighter.toml, typed again here.
    let h = 4000.0;
    let t = 288.15 - 0.0065 * h;
    let rho = 101325.0 * (t / 288.15_f64).powf(9.80665 / (0.0065 * 287.05287)) / (287.05287 * t);
    // ISA table at 4000 m: T = 262.15 K, p = 61640 Pa, so rho = p / (R T) = 0.81913 kg/m^3
    assert!((rho - 0.81913).abs() < 1e-4, "{rho}");
    let coeffs = [
        4.6, -1.07, -0.092, -0.38, 0.10, -0.10, 0.021, -0.35, -5.0, -0.55, 0.12, -0.03, -0.35,
        0.008, -0.045,
    ];
    let (want, tilt) = independent_f64(
        180.0,
        rho,
        [9300.0, 27.87, 9.144, 3.45],
        [12875.0, 75674.0, 85552.0, 1331.0],
        &coeffs,
        (None, 0.0),
    );
    let a = parse(fighter_text(), "fighter.toml").unwrap();
    for p in Param::ALL {
        let (got, w) = (a.value(p), want[p.index()]);
        assert!(
            (got - w).abs() <= 1e-12 * w.abs().max(1e-3),
            "{p:?}: {got} vs {w}"
        );
    }
    assert!(tilt > 0.5 && tilt < 1.5, "{tilt}");
    let out = convert_text(fighter_text());
    let printed: f64 = out
        .lines()
        .find_map(|l| l.strip_prefix("# Principal x axis tilt: "))
        .and_then(|l| l.split(' ').next())
        .and_then(|t| t.parse().ok())
        .unwrap();
    assert!((printed - tilt).abs() < 1e-6, "{printed} vs {tilt}");
    assert!(out.contains("rounded once"), "{out}");
    // aileron yaw and roll due to rudder both present in principal axes
    assert!(a.value(Param::NDeltaA) != 0.0 && a.value(Param::LDeltaR) != 0.0);
    assert_eq!(a.limits.aileron_deg, Some(21.5));
    assert_eq!(a.validity.beta_max_deg, 20.0);
}

#[test]
fn a_trim_gives_the_lift_term_and_the_principal_axis_angle_of_attack() {
    // The fighter at 1.5 g with the body axis 0.1 rad above the flight path: the principal axis,
    // tilted below body x by the product of inertia, sits at 0.1 rad less that tilt.
    let text = fighter_text().replacen(
        "[flight]\n",
        "[flight]\nalpha = 0.1\nload_factor = 1.5\n",
        1,
    );
    let a = parse(&text, "fighter.toml").unwrap();
    let plain = parse(fighter_text(), "fighter.toml").unwrap();
    let (_, tilt_deg) = independent_f64(
        180.0,
        0.8,
        [9300.0, 27.87, 9.144, 3.45],
        [12875.0, 75674.0, 85552.0, 1331.0],
        &[0.0; 15],
        (None, 0.0),
    );
    assert_eq!(a.value(Param::Z0), -1.5 * 9.80665 / 180.0);
    let want = 0.1 - tilt_deg.to_radians();
    assert!(
        (a.value(Param::AlphaT) - want).abs() < 1e-15,
        "{}",
        a.value(Param::AlphaT)
    );
    assert!(want < 0.1 && want > 0.07, "{want}");
    // Nothing else moves; without a trim both are 0, the paper's convention.
    for p in Param::ALL
        .into_iter()
        .filter(|p| !matches!(p, Param::Z0 | Param::AlphaT))
    {
        assert_eq!(a.value(p), plain.value(p), "{p:?}");
    }
    assert_eq!(
        (plain.value(Param::Z0), plain.value(Param::AlphaT)),
        (0.0, 0.0)
    );
}

#[test]
fn a_trim_alpha_beyond_a_right_angle_and_a_dimensional_trim_in_flight_are_refused() {
    let text = fighter_text().replacen("[flight]\n", "[flight]\nalpha = 1.6\n", 1);
    let e = parse(&text, "fighter.toml").unwrap_err().to_string();
    assert!(
        e.contains("flight.alpha") && e.contains("pi/2") && e.contains("1.6"),
        "{e}"
    );
    let dimensional = include_str!(concat!(env!("CARGO_MANIFEST_DIR"), "/../aircraft/a.toml"))
        .replacen("[flight]\n", "[flight]\nload_factor = 1\n", 1);
    let e = parse(&dimensional, "a.toml").unwrap_err().to_string();
    assert!(
        e.contains("flight.load_factor") && e.contains("derivatives.z_0"),
        "{e}"
    );
}

#[test]
fn convert_output_loads_as_the_same_aircraft() {
    // ix = 7000 kg m^2: l_p = 60000 * -0.4 / 7000 = -24/7, not a terminating decimal
    let sevenths = body("ix = 10000", "ix = 7000").replacen("iz = 50000", "iz = 45000", 1);
    let limited = format!("{BODY}[limits]\naileron = 20\n[validity]\nalpha_max = 15\n");
    for text in [BODY, &sevenths, &limited, fighter_text()] {
        let a = parse(text, FILE).unwrap();
        let out = convert_text(text);
        let back = parse(&out, "out.toml").unwrap_or_else(|e| panic!("{e}\n{out}"));
        assert_eq!(back, a, "{out}");
        assert!(out.contains("# Principal x axis tilt: "), "{out}");
    }
    let out = convert_text(&sevenths);
    assert!(out.contains("l_p = \"-24/7\""), "{out}");
    let limited = parse(&limited, FILE).unwrap();
    assert_eq!(
        limited.limits,
        Limits {
            aileron_deg: Some(20.0),
            ..Limits::default()
        }
    );
    assert_eq!(limited.validity.alpha_max_deg, 15.0);
}

#[test]
#[cfg(feature = "analysis")]
fn analyze_agrees_on_body_axis_and_converted_files() {
    // The fighter as it is (aileron yaw, roll due to rudder from the tilt, ixz != 0), and
    // without aileron yaw and product of inertia.
    let plain = fighter_text().replacen("Cn_delta_a = 0.008", "Cn_delta_a = 0.0", 1);
    let plain = plain.replacen("ixz = 1331.0", "ixz = 0.0", 1);
    for text in [fighter_text().to_string(), plain] {
        let a = parse(&text, FILE).unwrap();
        let b = parse(&convert_text(&text), "out.toml").unwrap();
        let (ra, rb) = (
            crate::analysis::analyze(&a, 0.0349),
            crate::analysis::analyze(&b, 0.0349),
        );
        assert!(ra.as_ref().is_ok_and(|r| r.critical.is_some()), "{ra:?}");
        assert_eq!(ra, rb);
    }
}

#[test]
fn principal_moments_that_break_a_triangle_inequality_give_a_warning() {
    // ix' + iy < iz': 10000 + 40000 < 60000, analysed with E = 2.
    let a = parse(&body("iz = 50000", "iz = 60000"), FILE).unwrap();
    assert_eq!(*a.exact(Param::E), decimal_to_rational("2").unwrap());
    let [w] = a.warnings.as_slice() else {
        panic!("one warning expected: {:?}", a.warnings);
    };
    for needle in [&format!("{FILE}:"), "table `[inertia]`", "ix' + iy < iz'"] {
        assert!(w.contains(needle), "no `{needle}` in: {w}");
    }
    assert!(parse(BODY, FILE).unwrap().warnings.is_empty());
}

#[test]
fn terminating_decimals_are_written_in_full() {
    let q = |s: &str| decimal_to_rational(s).unwrap();
    assert_eq!(toml_number(&q("-12")), "-12.0");
    assert_eq!(toml_number(&q("0.0625")), "0.0625");
    assert_eq!(toml_number(&q("-0.003")), "-0.003");
    assert_eq!(toml_number(&q("123.45e10")), "1234500000000.0");
    let third = BigRational::new(1.into(), 3.into());
    assert!(toml_number(&third).starts_with("\"1/3\""));
    assert_eq!(toml_string("a\"b\\c\u{1}"), "\"a\\\"b\\\\c\\u0001\"");
}

#[test]
fn isa_density_at_the_ends_of_the_troposphere() {
    // ISA tables: 1.2250 kg/m^3 at sea level, 0.36392 kg/m^3 at 11 km.
    assert!((isa_density(0.0) - 1.2250).abs() < 1e-4);
    assert!((isa_density(11000.0) - 0.36392).abs() < 1e-4);
}
