//! Files the reader accepts, and what it makes of them: Table A.1 exactly, inertia from moments,
//! defaults, dotted and inline tables, `[limits]` and `[validity]`.

use super::*;
use crate::aircraft::{decimal_to_rational, Param, DEFAULT_SPEED_M_S};
use num_rational::BigRational;
use num_traits::Zero;

#[test]
fn good_file_parses() {
    let a = parse(GOOD, FILE).unwrap();
    assert_eq!(a.name, "T");
    assert_eq!(a.speed, 150.0);
    for p in Param::ALL {
        assert_eq!(a.exact(p), Aircraft::a().exact(p), "{p:?}");
    }
}

#[test]
fn paper_files_are_table_a1_exactly() {
    for (text, builtin) in [
        (
            include_str!(concat!(env!("CARGO_MANIFEST_DIR"), "/../aircraft/a.toml")),
            Aircraft::a(),
        ),
        (
            include_str!(concat!(env!("CARGO_MANIFEST_DIR"), "/../aircraft/b.toml")),
            Aircraft::b(),
        ),
    ] {
        let a = parse(text, "x.toml").unwrap();
        assert_eq!(a.name, builtin.name);
        assert_eq!(a.speed, builtin.speed);
        for p in Param::ALL {
            assert!(a.exact(p) == builtin.exact(p), "{} {p:?}", builtin.name);
        }
    }
    let path = Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../aircraft/a.toml"));
    let a = load(path).unwrap();
    assert!(Param::ALL
        .iter()
        .all(|&p| a.exact(p) == Aircraft::a().exact(p)));
}

#[test]
fn aircraft_c_parses_with_computed_inertia() {
    let path = Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../aircraft/c.toml"));
    let c = load(path).unwrap();
    assert_eq!(c.name, "Aircraft C (non-paper test case)");
    assert_eq!(c.speed, 200.0);
    let q = |s: &str| decimal_to_rational(s).unwrap();
    // (6.1 - 1)/5.5, (5.5 - 1)/6.1, (6.1 - 5.5)/1
    assert_eq!(*c.exact(Param::C), q("5.1") / q("5.5"));
    assert_eq!(*c.exact(Param::D), q("4.5") / q("6.1"));
    assert_eq!(*c.exact(Param::E), q("0.6"));
    assert_eq!(*c.exact(Param::Np), q("-0.05"));
    assert_eq!(*c.exact(Param::Lr), q("0.3"));
    assert_eq!(*c.exact(Param::NDeltaR), q("-4"));
}

#[test]
fn moments_of_inertia_give_exact_coefficients() {
    let text = replace(
        "C = 0.959\nD = 0.786\nE = 0.705\n",
        "ix = 0.4\niy = 0.5\niz = 0.7\n",
    );
    let a = parse(&text, FILE).unwrap();
    let q = |s: &str| decimal_to_rational(s).unwrap();
    // C = (iz - ix)/iy = 0.3/0.5 = 3/5; D = (iy - ix)/iz = 0.1/0.7 = 1/7; E = (iz - iy)/ix = 1/2
    assert_eq!(*a.exact(Param::C), q("0.6"));
    assert_eq!(*a.exact(Param::D), BigRational::new(1.into(), 7.into()));
    assert_eq!(*a.exact(Param::E), q("0.5"));
    // 0.1 + 0.2 style binary rounding never enters
    assert_ne!(a.value(Param::D), 0.0);
}

#[test]
fn defaults_name_speed_and_rudder() {
    let text = GOOD
        .replacen("name = \"T\"\n", "", 1)
        .replacen("[flight]\nspeed = 150.0\n", "", 1);
    let a = parse(&text, "dir/my_jet.toml").unwrap();
    assert_eq!(a.name, "my_jet");
    assert_eq!(a.speed, DEFAULT_SPEED_M_S);
    assert_eq!(
        *a.exact(Param::NDeltaR),
        BigRational::from_integer((-1).into())
    );
    let a = parse(&GOOD.replacen("speed = 150.0", "speed = 210", 1), FILE).unwrap();
    assert_eq!(a.speed, 210.0);
    let a = parse(
        &replace("n_delta_a = 0.0\n", "n_delta_a = 0.0\nn_delta_r = -2.5\n"),
        FILE,
    )
    .unwrap();
    assert_eq!(a.value(Param::NDeltaR), -2.5);
}

#[test]
fn unreadable_file_names_the_path() {
    let e = load(Path::new("/nonexistent/dir/plane.toml")).unwrap_err();
    assert!(matches!(e, AircraftError::Io { .. }));
    let msg = e.to_string();
    assert!(msg.contains("/nonexistent/dir/plane.toml"), "{msg}");
    assert!(msg.contains("expected a readable"), "{msg}");
}

#[test]
fn inertia_coefficients_within_rounding_of_a_rigid_body_are_accepted() {
    // Table A.1's A: C and D imply E = 0.7026, E = 0.705 is within its three decimals.
    assert!(parse(GOOD, FILE).is_ok());
    // C = D = 0.5 imply E = 0; C, D within 0.001 reach E = 0.002/0.750001 = 0.00267, so E
    // within 0.001 of that passes and beyond it does not.
    let with_e = |e: &str| {
        replace(
            "C = 0.959\nD = 0.786\nE = 0.705",
            &format!("C = 0.5\nD = 0.5\nE = {e}"),
        )
    };
    assert!(parse(&with_e("0.0036"), FILE).is_ok());
    assert!(parse(&with_e("-0.0036"), FILE).is_ok());
    err(
        &with_e("0.0037"),
        5,
        &["C and D imply E = (C - D)/(1 - C D) = 0"],
    );
    // C = D = -1 is a lamina in the y-z plane (ix = iy + iz): every E in [-1, 1] is one.
    let lamina = replace("C = 0.959\nD = 0.786\nE = 0.705", "C = -1\nD = -1\nE = 0.3");
    assert!(parse(&lamina, FILE).is_ok());
}

#[test]
fn moments_that_break_a_triangle_inequality_are_analysed_with_a_warning() {
    // ix + iy < iz: E = (iz - iy)/ix = 2, outside [-1, 1], kept exactly.
    let broken = parse(
        &replace(
            "C = 0.959\nD = 0.786\nE = 0.705\n",
            "ix = 1\niy = 5\niz = 7\n",
        ),
        FILE,
    )
    .unwrap();
    assert_eq!(*broken.exact(Param::E), decimal_to_rational("2").unwrap());
    let [w] = broken.warnings.as_slice() else {
        panic!("one warning expected: {:?}", broken.warnings);
    };
    for needle in [
        &format!("{FILE}:2:"),
        "ix + iy < iz",
        "C, D, E = 1.2000, 0.5714, 2.0000",
    ] {
        assert!(w.contains(needle), "no `{needle}` in: {w}");
    }
    // A lamina (iz = ix + iy exactly) is a rigid body's: no warning.
    let lamina = parse(
        &replace(
            "C = 0.959\nD = 0.786\nE = 0.705\n",
            "ix = 2\niy = 5\niz = 7\n",
        ),
        FILE,
    )
    .unwrap();
    assert!(lamina.warnings.is_empty(), "{:?}", lamina.warnings);
    assert!(parse(GOOD, FILE).unwrap().warnings.is_empty());
}

#[test]
fn dotted_and_inline_tables_work_and_keep_lines() {
    let text = "inertia = { ix = 1, iy = 2, iz = 3 }\n\
                derivatives.z_alpha = -1\nderivatives.y_beta = -1\nderivatives.l_p = -1\n\
                derivatives.l_r = 0\nderivatives.l_beta = -1\nderivatives.l_delta_a = -1\n\
                derivatives.m_q = -1\nderivatives.m_alpha = -1\nderivatives.m_delta_e = -1\n\
                derivatives.n_p = 0\nderivatives.n_r = -1\nderivatives.n_beta = 1\n\
                derivatives.n_delta_a = 0\n";
    let a = parse(text, FILE).unwrap();
    assert_eq!(*a.exact(Param::E), BigRational::from_integer(1.into()));
    err(
        &text.replace("derivatives.m_q = -1", "derivatives.m_qq = -1"),
        8,
        &["`derivatives.m_qq`", "did you mean `m_q`?"],
    );
    err(
        &text.replace("derivatives.n_p = 0\n", ""),
        2,
        &["missing required key `derivatives.n_p`"],
    );
}

#[test]
fn roll_due_to_rudder_is_optional() {
    assert!(parse(GOOD, FILE).unwrap().exact(Param::LDeltaR).is_zero());
    let a = parse(
        &replace("n_delta_a = 0.0\n", "n_delta_a = 0.0\nl_delta_r = 2.25\n"),
        FILE,
    )
    .unwrap();
    assert_eq!(a.value(Param::LDeltaR), 2.25);
    err(
        &replace("n_delta_a = 0.0\n", "n_delta_a = 0.0\nl_delta_r = \"x\"\n"),
        20,
        &["derivatives.l_delta_r", "expected a number"],
    );
}

#[test]
fn limits_and_validity_tables() {
    let a = parse(GOOD, FILE).unwrap();
    assert_eq!(a.limits, Limits::default());
    assert_eq!(a.validity, Validity::default());
    assert_eq!(a.validity.alpha_max_deg, 30.0);
    let text =
        format!("{GOOD}[limits]\naileron = 21.5\nrudder = 30\n[validity]\nbeta_max = 12.5\n");
    let a = parse(&text, FILE).unwrap();
    assert_eq!(
        a.limits,
        Limits {
            aileron_deg: Some(21.5),
            elevator_deg: None,
            rudder_deg: Some(30.0),
        }
    );
    assert_eq!(a.validity.alpha_max_deg, 30.0);
    assert_eq!(a.validity.beta_max_deg, 12.5);
    for (bad, needle) in [
        ("0", "> 0"),
        ("-3", "> 0"),
        ("nan", "finite"),
        ("\"x\"", "number"),
    ] {
        err(
            &text.replacen("aileron = 21.5", &format!("aileron = {bad}"), 1),
            23,
            &["limits.aileron", needle],
        );
    }
    err(
        &text.replacen("rudder = 30", "rudder = 0.0", 1),
        24,
        &["limits.rudder", "a deflection limit in degrees > 0"],
    );
    err(
        &text.replacen("beta_max = 12.5", "beta_max = -1", 1),
        26,
        &["validity.beta_max", "an angle in degrees > 0"],
    );
    err(
        &text.replacen("rudder = 30", "flap = 30", 1),
        24,
        &[
            "unknown key `limits.flap`",
            "`aileron`, `elevator`, `rudder`",
        ],
    );
    err(
        &text.replacen("beta_max", "alpha_mx", 1),
        26,
        &[
            "unknown key `validity.alpha_mx`",
            "did you mean `alpha_max`?",
        ],
    );
    err(
        &format!("limits = 3\n{GOOD}"),
        1,
        &["key `limits`", "expected a table"],
    );
}
