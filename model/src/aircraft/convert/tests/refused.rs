//! Body-axis files the loader refuses: each names the file, the line and the key, and no
//! conversion beyond f64 panics.

use super::*;

#[test]
fn bad_body_axis_files_name_file_line_and_key() {
    // missing tables
    for t in ["[geometry]\n", "[coefficients]\n"] {
        let other = if t.starts_with("[geometry]") {
            "coefficients"
        } else {
            "geometry"
        };
        let cut = BODY
            .split(t)
            .next()
            .map(|head| {
                let tail = BODY.split(t).nth(1).unwrap_or("");
                let rest = tail.find('[').map_or("", |i| &tail[i..]);
                format!("{head}{rest}")
            })
            .unwrap();
        let name = t.trim().trim_matches(['[', ']']);
        let e = err(&cut, 1, &[&format!("missing table `[{name}]`")]);
        assert!(matches!(e, AircraftError::MissingTable { .. }), "{other}");
    }
    let no_flight = body("[flight]\nspeed = 100\ndensity = 1.2\n", "");
    err(
        &no_flight,
        1,
        &["missing table `[flight]`", "`speed`, `density`, `altitude`"],
    );
    // missing keys
    for (line, key, header) in [
        ("speed = 100\n", "flight.speed", 2),
        ("mass = 10000\n", "geometry.mass", 5),
        ("ixz = 0\n", "inertia.ixz", 10),
        ("Cn_delta_r = -0.05\n", "coefficients.Cn_delta_r", 15),
        ("iy = 40000\n", "inertia.iy", 10),
    ] {
        let e = err(
            &body(line, ""),
            header,
            &[&format!("missing required key `{key}`")],
        );
        assert!(matches!(e, AircraftError::MissingKey { .. }));
    }
    err(
        &body("density = 1.2\n", ""),
        2,
        &["flight.density", "or `altitude = <number>` in m"],
    );
    // non-positive values
    for (from, to, line, key) in [
        ("mass = 10000", "mass = 0", 6, "geometry.mass"),
        ("wing_area = 20", "wing_area = -20", 7, "geometry.wing_area"),
        ("span = 10", "span = 0.0", 8, "geometry.span"),
        ("chord = 2", "chord = -2", 9, "geometry.chord"),
        ("speed = 100", "speed = 0", 3, "flight.speed"),
        ("density = 1.2", "density = -1.2", 4, "flight.density"),
        ("ix = 10000", "ix = 0", 11, "inertia.ix"),
    ] {
        let e = err(&body(from, to), line, &[key, "> 0"]);
        assert!(matches!(e, AircraftError::InvalidValue { .. }), "{e}");
    }
    // altitude outside the ISA troposphere, and both density and altitude
    for h in ["-1", "11000.5", "2e4"] {
        err(
            &body("density = 1.2", &format!("altitude = {h}")),
            4,
            &["flight.altitude", "ISA troposphere, 0 to 11000", h],
        );
    }
    err(
        &body("density = 1.2", "density = 1.2\naltitude = 100"),
        5,
        &[
            "flight.altitude",
            "either `flight.density` or `flight.altitude`",
        ],
    );
    // a principal moment <= 0: ix iz - ixz^2 <= 0
    let e = err(
        &body("ixz = 0", "ixz = 30000"),
        10,
        &[
            "principal moment ix' <= 0",
            "ix iz - ixz^2 <= 0",
            "singular",
        ],
    );
    assert!(matches!(e, AircraftError::UnphysicalInertia { .. }));
    // mixing the formats
    let e = err(
        &body("ixz = 0\n", "ixz = 0\nC = 0.5\n"),
        15,
        &["`inertia.C`", "not a mix"],
    );
    assert!(matches!(e, AircraftError::MixedFormats { .. }));
    err(
        &format!("{BODY}[derivatives]\nl_p = 1\n"),
        31,
        &[
            "`[derivatives]` given together with `[geometry]`",
            "not a mix",
        ],
    );
    // no roll authority
    err(
        &body("Cl_delta_a = -0.2", "Cl_delta_a = 0"),
        21,
        &["coefficients.Cl_delta_a", "nonzero aileron derivative"],
    );
    // wrong types and unknown keys
    err(
        &body("Cm_q = -10", "Cm_q = \"x\""),
        24,
        &["coefficients.Cm_q", "a number"],
    );
    err(
        &body("Cm_q = -10", "cm_q = -10"),
        24,
        &["unknown key `coefficients.cm_q`", "did you mean `Cm_q`?"],
    );
}

#[test]
fn conversions_beyond_f64_are_refused_and_nothing_panics() {
    err(
        &body("mass = 10000", "mass = 1e-310"), // z_alpha = -6000 / m = -6e313
        6,
        &["key `geometry.mass`", "rho V S / (2 m)", "overflows"],
    );
    // principal axes at 45 deg (ix = iz), and every prefix of two files: no panic
    let _ = parse(
        &body("iz = 50000", "iz = 10000").replacen("ixz = 0", "ixz = 5", 1),
        FILE,
    );
    for text in [BODY, fighter_text()] {
        for (i, _) in text.char_indices() {
            let _ = parse(&text[..i], FILE);
        }
    }
}

#[test]
fn a_flight_condition_that_makes_the_derivatives_underflow_names_its_key() {
    // g/V = 9.8e320 leaves f64 before any derivative is computed
    let e = err(
        &body("speed = 100", "speed = 1e-320"),
        3,
        &["key `flight.speed`", "`1e-320`"],
    );
    assert!(!e.to_string().contains("Cl_delta_a"), "{e}");
    // rho V^2 / 2 = 6e-321: every static lateral derivative underflows
    err(
        &body("speed = 100", "speed = 1e-160"),
        3,
        &[
            "key `flight.speed`",
            "rho V^2 S b / (2 ix')",
            "underflows",
            "`1e-160`",
        ],
    );
    err(
        &body("density = 1.2", "density = 1e-320"),
        4,
        &["key `flight.density`", "rho V S / (2 m)", "underflows"],
    );
}

#[test]
fn geometry_inertia_and_coefficients_that_take_a_derivative_beyond_f64_name_their_key() {
    // l_p per unit Cl_p = rho V S b^2 / (4 ix') = 1.2e601
    err(
        &body("span = 10", "span = 1e300"),
        8,
        &["key `geometry.span`", "rho V S b^2 / (4 ix')", "overflows"],
    );
    let tiny = body(
        "ix = 10000\niy = 40000\niz = 50000",
        "ix = 1e-316\niy = 4e-316\niz = 5e-316",
    );
    err(&tiny, 11, &["key `inertia.ix`", "overflows"]);
    // l_p = 6 Cl_p
    err(
        &body("Cl_p = -0.4", "Cl_p = 1e308"),
        19,
        &["key `coefficients.Cl_p`", "l_p", "range of f64"],
    );
}

#[test]
fn convert_refuses_a_dimensional_file() {
    let path = std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../aircraft/a.toml"));
    let e = crate::aircraft::convert_file(path).unwrap_err();
    assert!(matches!(e, AircraftError::AlreadyDimensional { .. }));
    assert!(e.to_string().contains("a.toml:1:1"), "{e}");
}
