//! Tests of reading aircraft files: the files accepted, and a table of refused files with the
//! line, key and expectation each error names.

use super::suggest::edit_distance;
use super::*;

const GOOD: &str = r#"name = "T"
[inertia]
C = 0.959
D = 0.786
E = 0.705
[derivatives]
z_alpha = -3.0076
y_beta = -0.0558
l_p = -21.7529
l_r = 1.5207
l_beta = -110.45
l_delta_a = -327.28
m_q = -1.815
m_alpha = -13.52504
m_delta_e = -33.268
n_p = 0
n_r = -0.2608
n_beta = 3.716
n_delta_a = 0.0
[flight]
speed = 150.0
"#;

const FILE: &str = "test_plane.toml";

/// Parses `text`, expects an error, and checks the message holds the file, the line, and
/// every one of `needles`.
fn err(text: &str, line: usize, needles: &[&str]) -> AircraftError {
    let e = match parse(text, FILE) {
        Ok(a) => panic!("expected an error, got {a:?}"),
        Err(e) => e,
    };
    let msg = e.to_string();
    assert!(msg.contains(FILE), "no file name in: {msg}");
    assert!(
        msg.contains(&format!("{FILE}:{line}:")),
        "no line {line} in: {msg}"
    );
    for n in needles {
        assert!(msg.contains(n), "no `{n}` in: {msg}");
    }
    assert_eq!(e.location().map(|l| l.line), Some(line), "{msg}");
    e
}

fn replace(from: &str, to: &str) -> String {
    assert!(GOOD.contains(from), "{from}");
    GOOD.replacen(from, to, 1)
}

/// One refused file: what it shows, the file, the line its error names, and what the message
/// says; optionally also the error's kind, its column, what the message must not say, and a
/// bound on its length.
struct Refusal {
    case: &'static str,
    text: String,
    line: usize,
    says: &'static [&'static str],
    kind: Option<fn(&AircraftError) -> bool>,
    column: Option<usize>,
    never_says: &'static [&'static str],
    shorter_than: Option<usize>,
}

/// The test that an error is of one `AircraftError` variant.
macro_rules! is {
    ($variant:ident) => {
        |e: &AircraftError| matches!(e, AircraftError::$variant { .. })
    };
}

fn refused(
    case: &'static str,
    text: impl Into<String>,
    line: usize,
    says: &'static [&'static str],
) -> Refusal {
    Refusal {
        case,
        text: text.into(),
        line,
        says,
        kind: None,
        column: None,
        never_says: &[],
        shorter_than: None,
    }
}

impl Refusal {
    fn kind(self, kind: fn(&AircraftError) -> bool) -> Self {
        Refusal {
            kind: Some(kind),
            ..self
        }
    }

    fn column(self, column: usize) -> Self {
        Refusal {
            column: Some(column),
            ..self
        }
    }

    fn never_says(self, never_says: &'static [&'static str]) -> Self {
        Refusal { never_says, ..self }
    }

    fn shorter_than(self, bound: usize) -> Self {
        Refusal {
            shorter_than: Some(bound),
            ..self
        }
    }

    /// Parses the file and checks the error as `err` does, and the optional properties.
    fn check(&self) {
        let case = self.case;
        let e = match parse(&self.text, FILE) {
            Ok(a) => panic!("{case}: expected an error, got {a:?}"),
            Err(e) => e,
        };
        let msg = e.to_string();
        assert!(msg.contains(FILE), "{case}: no file name in: {msg}");
        let line = self.line;
        assert!(
            msg.contains(&format!("{FILE}:{line}:")),
            "{case}: no line {line} in: {msg}"
        );
        for n in self.says {
            assert!(msg.contains(n), "{case}: no `{n}` in: {msg}");
        }
        assert_eq!(e.location().map(|l| l.line), Some(line), "{case}: {msg}");
        if let Some(kind) = self.kind {
            assert!(kind(&e), "{case}: wrong kind: {e:?}");
        }
        if let Some(column) = self.column {
            assert_eq!(
                e.location().map(|l| l.column),
                Some(column),
                "{case}: {msg}"
            );
        }
        for n in self.never_says {
            assert!(!msg.contains(n), "{case}: `{n}` in: {msg}");
        }
        if let Some(bound) = self.shorter_than {
            assert!(msg.len() < bound, "{case}: {msg}");
        }
    }
}

/// The inertia coefficients of `GOOD`, one per line.
const CDE: &str = "C = 0.959\nD = 0.786\nE = 0.705\n";

#[test]
fn refused_files_name_their_line_key_and_expectation() {
    let tables = [
        syntax_refusals(),
        key_refusals(),
        type_refusals(),
        number_refusals(),
        inertia_refusals(),
    ];
    for refusal in tables.iter().flatten() {
        refusal.check();
    }
}

fn syntax_refusals() -> Vec<Refusal> {
    vec![
        // The parser stops there without a message of its own.
        refused(
            "a value cut off at the end of the file",
            "name = \"x\"\n[inertia]\nC = 0.9\nD = 0.7\nE = ",
            5,
            &["inertia.E", "expected a number"],
        )
        .kind(is!(Syntax)),
        // A cut-off header has the parser's own message.
        refused(
            "a table header cut off at the end of the file",
            "name = \"x\"\n[inertia]\nC = 0.9\nD = 0.7\n[deriv",
            5,
            &["table header"],
        )
        .kind(is!(Syntax)),
        refused(
            "a number with two decimal points",
            replace("l_p = -21.7529", "l_p = -21.75.29"),
            9,
            &["TOML syntax error"],
        )
        .kind(is!(Syntax)),
        refused(
            "an unclosed array, found where the next line starts",
            replace("l_r = 1.5207", "l_r = [1.5207"),
            11,
            &["syntax", "expected"],
        )
        .kind(is!(Syntax)),
        refused(
            "a duplicate key",
            replace("l_r = 1.5207", "l_p = 1.5207"),
            10,
            &["l_p"],
        )
        .kind(is!(Syntax)),
        refused(
            "a NUL inside a string",
            replace("name = \"T\"", "name = \"T\0\""),
            1,
            &["key `name`", "U+0000 (NUL)", "expected printable text"],
        )
        .kind(is!(ControlCharacter))
        .column(10),
        refused(
            "a NUL in a comment after a value",
            replace("l_p = -21.7529", "l_p = -21.7529 # \0"),
            9,
            &["key `derivatives.l_p`", "U+0000"],
        ),
        refused(
            "an ESC in a comment line of its own",
            replace("[derivatives]\n", "[derivatives]\n# \u{1b}[31m\n"),
            7,
            &["line 7", "U+001B (ESC)"],
        ),
    ]
}

fn key_refusals() -> Vec<Refusal> {
    vec![
        refused(
            "a missing key, named at its table's header",
            replace("m_alpha = -13.52504\n", ""),
            6,
            &[
                "derivatives.m_alpha",
                "missing required key",
                "expected `m_alpha = <number>`",
            ],
        )
        .kind(is!(MissingKey))
        .column(1),
        refused(
            "an unknown derivative, with the closest suggested",
            replace("l_p = -21.7529", "l_pp = -21.7529"),
            9,
            &[
                "unknown key `derivatives.l_pp`",
                "did you mean `l_p`?",
                "expected one of",
            ],
        )
        .kind(is!(UnknownKey)),
        refused(
            "an unknown top-level key",
            replace("name = \"T\"", "nmae = \"T\""),
            1,
            &["`nmae`", "did you mean `name`?"],
        )
        .kind(is!(UnknownKey)),
        refused(
            "a key in the wrong case",
            replace("C = 0.959", "c = 0.959"),
            3,
            &["`inertia.c`", "did you mean `C`?"],
        )
        .kind(is!(UnknownKey)),
        refused(
            "a key of another table",
            replace("n_delta_a = 0.0\n", "n_delta_a = 0.0\nspeed = 3\n"),
            20,
            &["`derivatives.speed`", "belongs in the `[flight]` table"],
        ),
        refused(
            "a misspelt flight key",
            replace("speed = 150.0", "sped = 150.0"),
            21,
            &["`flight.sped`", "did you mean `speed`?"],
        ),
        refused(
            "an unknown key close to none",
            replace("l_p = -21.7529", "roll_damping = -21.7529"),
            9,
            &["`derivatives.roll_damping`", "expected one of `z_alpha`"],
        )
        .never_says(&["did you mean"]),
        refused(
            "an unknown table",
            format!("{GOOD}[extra]\nx = 1\n"),
            22,
            &["unknown key `extra`"],
        ),
        refused(
            "a missing `[derivatives]`, named at line 1",
            GOOD.split("[derivatives]").next().unwrap(),
            1,
            &[
                "missing table `[derivatives]`",
                "expected `[derivatives]` with keys `z_alpha`",
            ],
        )
        .kind(is!(MissingTable)),
        refused(
            "a missing `[inertia]`, named at line 1",
            replace("[inertia]\nC = 0.959\nD = 0.786\nE = 0.705\n", ""),
            1,
            &["missing table `[inertia]`", "expected `[inertia]` with"],
        )
        .kind(is!(MissingTable)),
        refused(
            "a table given as a number",
            format!(
                "inertia = 3\n{}",
                GOOD.replacen("[inertia]\nC = 0.959\nD = 0.786\nE = 0.705\n", "", 1)
            ),
            1,
            &[
                "key `inertia`",
                "expected a table `[inertia]`",
                "found an integer",
            ],
        )
        .kind(is!(NotATable)),
        refused(
            "a table given as an array of tables",
            replace("[flight]\nspeed = 150.0\n", "[[flight]]\nspeed = 150.0\n"),
            20,
            &["key `flight`", "expected a table", "found an array"],
        )
        .kind(is!(NotATable)),
        refused(
            "a body-axis key in a dimensional `[inertia]`",
            replace("E = 0.705\n", "E = 0.705\nixz = 3\n"),
            6,
            &["`inertia.ixz`", "expected either the dimensional"],
        )
        .kind(is!(MixedFormats)),
        refused(
            "a body-axis key in a dimensional `[flight]`",
            replace("speed = 150.0", "speed = 150.0\naltitude = 3000"),
            22,
            &["`flight.altitude`", "not a mix"],
        ),
        refused(
            "a body-axis table in a dimensional file",
            format!("{GOOD}[geometry]\nmass = 1\n"),
            22,
            &[
                "table `[geometry]` given together with `[derivatives]`",
                "not a mix",
            ],
        ),
    ]
}

fn type_refusals() -> Vec<Refusal> {
    vec![
        refused(
            "a number written as a string",
            replace("l_beta = -110.45", "l_beta = \"-110.45\""),
            11,
            &["derivatives.l_beta", "expected a number, found a string"],
        )
        .kind(is!(WrongType)),
        refused(
            "a boolean for a number",
            replace("m_q = -1.815", "m_q = true"),
            13,
            &["derivatives.m_q", "expected a number", "boolean"],
        ),
        refused(
            "an array for a number",
            replace("m_q = -1.815", "m_q = [-1.815]"),
            13,
            &["derivatives.m_q", "found an array"],
        ),
        refused(
            "a date-time for a number",
            replace("m_q = -1.815", "m_q = 1979-05-27"),
            13,
            &["derivatives.m_q", "found a date-time"],
        ),
        refused(
            "an inline table for a number",
            replace("m_q = -1.815", "m_q = { v = 1 }"),
            13,
            &["derivatives.m_q", "found a table"],
        ),
        refused(
            "a string for an inertia coefficient",
            replace("D = 0.786", "D = \"x\""),
            4,
            &["inertia.D", "expected a number"],
        ),
        refused(
            "a string for the speed",
            replace("speed = 150.0", "speed = \"fast\""),
            21,
            &["flight.speed", "expected a number"],
        ),
        refused(
            "a number for the name",
            replace("name = \"T\"", "name = 3"),
            1,
            &["`name`", "expected a string, found an integer"],
        ),
        refused(
            "a name with an escaped BEL",
            replace("name = \"T\"", "name = \"Air\\u0007craft\""),
            1,
            &[
                "key `name`",
                "expected a name without control characters",
                "found `Air\\u{7}craft`",
            ],
        )
        .kind(is!(InvalidValue)),
        refused(
            "a name with an escaped ESC",
            replace("name = \"T\"", "name = \"Evil\\u001b[31m\""),
            1,
            &[
                "key `name`",
                "expected a name without control characters",
                "found `Evil\\u{1b}[31m`",
            ],
        )
        .kind(is!(InvalidValue)),
        refused(
            "a name with an escaped newline",
            replace("name = \"T\"", "name = \"two\\nlines\""),
            1,
            &[
                "key `name`",
                "expected a name without control characters",
                "found `two\\nlines`",
            ],
        )
        .kind(is!(InvalidValue)),
        refused(
            "a name with an escaped tab",
            replace("name = \"T\"", "name = \"tab\\there\""),
            1,
            &[
                "key `name`",
                "expected a name without control characters",
                "found `tab\\there`",
            ],
        )
        .kind(is!(InvalidValue)),
    ]
}

fn number_refusals() -> Vec<Refusal> {
    let digits = "7".repeat(400);
    vec![
        refused(
            "a NaN",
            replace("n_r = -0.2608", "n_r = nan"),
            17,
            &["derivatives.n_r", "expected a finite number", "`nan`"],
        )
        .kind(is!(NotFinite))
        .column(7),
        refused(
            "a negative infinity",
            replace("E = 0.705", "E = -inf"),
            5,
            &["inertia.E", "expected a finite number", "`-inf`"],
        )
        .kind(is!(NotFinite)),
        refused(
            "an infinite speed",
            replace("speed = 150.0", "speed = +inf"),
            21,
            &["flight.speed", "finite"],
        ),
        refused(
            "a zero aileron authority written 0",
            replace("l_delta_a = -327.28", "l_delta_a = 0"),
            12,
            &[
                "derivatives.l_delta_a",
                "expected a nonzero",
                "roll authority",
            ],
        )
        .kind(is!(ZeroAileronAuthority)),
        refused(
            "a zero aileron authority written 0.0",
            replace("l_delta_a = -327.28", "l_delta_a = 0.0"),
            12,
            &[
                "derivatives.l_delta_a",
                "expected a nonzero",
                "roll authority",
            ],
        )
        .kind(is!(ZeroAileronAuthority)),
        refused(
            "a zero aileron authority written -0.0",
            replace("l_delta_a = -327.28", "l_delta_a = -0.0"),
            12,
            &[
                "derivatives.l_delta_a",
                "expected a nonzero",
                "roll authority",
            ],
        )
        .kind(is!(ZeroAileronAuthority)),
        refused(
            "an integer beyond i64",
            replace("l_p = -21.7529", "l_p = 99999999999999999999"),
            9,
            &[
                "key `derivatives.l_p`",
                "expected an integer within the 64-bit range",
            ],
        )
        .kind(is!(InvalidValue))
        .column(7),
        refused(
            "a float beyond f64",
            replace("m_q = -1.815", "m_q = 1e309"),
            13,
            &["key `derivatives.m_q`", "range of f64", "`1e309`"],
        ),
        refused(
            "a 400-digit integer, shown shortened",
            replace("m_q = -1.815", &format!("m_q = {digits}")),
            13,
            &["key `derivatives.m_q`", "64-bit range", "(400 characters)"],
        )
        .shorter_than(400),
        refused(
            "a 400-digit float",
            replace("m_q = -1.815", &format!("m_q = {digits}.5")),
            13,
            &["key `derivatives.m_q`", "range of f64"],
        ),
        refused(
            "a speed beyond f64",
            replace("speed = 150.0", "speed = -1e400"),
            21,
            &["flight.speed", "finite"],
        ),
        // accepted by the parser as 0.0, but the literal is beyond exact reading
        refused(
            "an exponent beyond exact reading",
            replace("m_q = -1.815", "m_q = 1e-100000"),
            13,
            &["derivatives.m_q", "range of f64"],
        ),
        // inside an inline table the key is still found
        refused(
            "a float beyond f64 in an inline table",
            replace(CDE, "").replacen(
                "[inertia]\n",
                "inertia = { ix = 1, iy = 1e999, iz = 3 }\n",
                1,
            ),
            2,
            &["key `inertia.iy`", "range of f64"],
        ),
        refused(
            "a speed whose g/V leaves f64 (subnormal)",
            replace("speed = 150.0", "speed = 1e-320"),
            21,
            &["key `flight.speed`", "g/V", "1e-320"],
        ),
        refused(
            "a speed whose g/V leaves f64 (below f64)",
            replace("speed = 150.0", "speed = 1e-400"),
            21,
            &["key `flight.speed`", "g/V", "1e-400"],
        ),
        refused(
            "a zero speed",
            replace("speed = 150.0", "speed = 0"),
            21,
            &["flight.speed", "expected a speed in m/s > 0", "`0`"],
        )
        .kind(is!(InvalidSpeed)),
        refused(
            "a negative speed",
            replace("speed = 150.0", "speed = -3.5"),
            21,
            &["flight.speed", "> 0"],
        ),
    ]
}

fn inertia_refusals() -> Vec<Refusal> {
    vec![
        refused(
            "moments of inertia together with coefficients",
            replace("E = 0.705\n", "E = 0.705\nix = 1.0\niy = 2\niz = 3\n"),
            6,
            &[
                "`inertia.ix` given together with `inertia.C`",
                "expected either",
            ],
        )
        .kind(is!(InertiaSet)),
        refused(
            "no inertia at all",
            replace(CDE, ""),
            2,
            &["`inertia`", "no inertia given", "expected either"],
        )
        .kind(is!(InertiaSet)),
        refused(
            "two of the three coefficients",
            replace("E = 0.705\n", ""),
            2,
            &[
                "missing `inertia.E`",
                "`inertia.C`, `inertia.D`",
                "expected either",
            ],
        )
        .kind(is!(InertiaSet)),
        refused(
            "one of the three moments of inertia",
            replace(CDE, "iz = 2\n"),
            2,
            &["missing `inertia.ix`, `inertia.iy`", "expected either"],
        ),
        refused(
            "a zero moment of inertia",
            replace(CDE, "ix = 1\niy = 0\niz = 3\n"),
            4,
            &["inertia.iy", "expected a moment of inertia > 0", "0"],
        )
        .kind(is!(NonPositiveInertia)),
        refused(
            "a negative moment of inertia",
            replace(CDE, "ix = 1\niy = -1.5\niz = 3\n"),
            4,
            &["inertia.iy", "expected a moment of inertia > 0", "-1.5"],
        )
        .kind(is!(NonPositiveInertia)),
        refused(
            "a zero moment of inertia written 0.0",
            replace(CDE, "ix = 1\niy = 0.0\niz = 3\n"),
            4,
            &["inertia.iy", "expected a moment of inertia > 0", "0.0"],
        )
        .kind(is!(NonPositiveInertia)),
        // ix + iy < iz (and ratios beyond f64 without the check: E = 0.6 / 1e-309).
        refused(
            "moments of inertia no rigid body has",
            replace(CDE, "ix = 1e-309\niy = 5.5\niz = 6.1\n"),
            2,
            &["[inertia]", "ix + iy < iz", "triangle inequalities"],
        )
        .kind(is!(UnphysicalInertia)),
        refused(
            "a coefficient C above 1",
            replace("C = 0.959", "C = 1.5"),
            3,
            &["inertia.C", "within [-1, 1]", "unphysical"],
        ),
        refused(
            "a coefficient E below -1",
            replace("E = 0.705", "E = -1.01"),
            5,
            &["inertia.E", "within [-1, 1]", "unphysical"],
        ),
        // C = D = 0 is ix = iy = iz, so E = 0.
        refused(
            "coefficients C = D = 0 with E far from 0",
            replace("C = 0.959\nD = 0.786\nE = 0.705", "C = 0\nD = 0\nE = 0.9"),
            5,
            &[
                "`inertia.E` = 0.9",
                "C and D imply E = (C - D)/(1 - C D) = 0",
                "within 0.001 of those of one rigid body",
            ],
        )
        .kind(is!(InconsistentInertia)),
        // C = D = 1: iz = ix + iy and iy = ix + iz, so ix = 0 and E = (iz - iy)/ix is undefined.
        refused(
            "coefficients C = D = 1",
            replace("C = 0.959\nD = 0.786\nE = 0.705", "C = 1\nD = 1\nE = 0.5"),
            4,
            &[
                "`inertia.C` = 1 and `inertia.D` = 1",
                "ix = 0",
                "rigid body",
            ],
        )
        .kind(is!(InconsistentInertia)),
    ]
}

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
fn garbage_never_panics() {
    let inputs = [
        "",
        "\u{feff}",
        "[",
        "= 1",
        "a.b.c.d = 1",
        "[derivatives.l_p.x]\ny = 1",
        "inertia = []\n",
        "derivatives = {}\ninertia = {}",
        "name = \"\"",
        "\"$__serde_spanned_private_start\" = 1",
        "[inertia]\n\"$__toml_private_datetime\" = 1",
        "x = 9223372036854775807\ny = 1e308\nz = 5e-324",
        "[inertia]\nix = 1e308\niy = 5e-324\niz = 1e-300\n",
        "é = 1\nñ = \"ü\"",
    ];
    for text in inputs {
        let r = parse(text, "g.toml");
        if let Err(e) = r {
            assert!(e.to_string().contains("g.toml"), "{e}");
        }
    }
    for (i, _) in GOOD.char_indices() {
        let _ = parse(GOOD.get(..i).unwrap_or(""), "g.toml");
    }
}

#[test]
fn numbers_enter_as_the_literal_written_not_as_an_f64() {
    // 22 significant digits: an f64 cannot hold them, the literal text can.
    let a = parse(
        &replace("l_p = -21.7529", "l_p = -0.1000000000000000000001"),
        FILE,
    )
    .unwrap();
    let q = |s: &str| decimal_to_rational(s).unwrap();
    assert_eq!(*a.exact(Param::Lp), q("-0.1000000000000000000001"));
    assert_ne!(*a.exact(Param::Lp), q("-0.1"));
    // longer than any message shows: every digit counts
    let long = format!("-21.7529{}1", "0".repeat(100));
    let a = parse(&replace("l_p = -21.7529", &format!("l_p = {long}")), FILE).unwrap();
    assert_eq!(*a.exact(Param::Lp), q(&long));
    assert_ne!(*a.exact(Param::Lp), q("-21.7529"));
    // an empty quoted key is unknown, not a table
    err(&format!("\"\" = 1\n{GOOD}"), 1, &["unknown key ``"]);
    // underscores, a plus sign and an exponent
    let a = parse(&replace("l_r = 1.5207", "l_r = +1_5.207e-1"), FILE).unwrap();
    assert_eq!(*a.exact(Param::Lr), q("1.5207"));
    // an exact fraction as a string
    let a = parse(&replace("l_r = 1.5207", "l_r = \"-1/3\""), FILE).unwrap();
    assert_eq!(*a.exact(Param::Lr), BigRational::new((-1).into(), 3.into()));
    for bad in ["\"1/0\"", "\"1.5/2\"", "\"/3\""] {
        err(
            &replace("l_r = 1.5207", &format!("l_r = {bad}")),
            10,
            &["derivatives.l_r", "exact fraction"],
        );
    }
}

#[test]
fn an_integer_below_i64_names_its_key_and_range_as_one_above_does() {
    let below = err(
        &replace("l_beta = -110.45", "l_beta = -9223372036854775809"),
        11,
        &[
            "key `derivatives.l_beta`",
            "expected an integer within the 64-bit range (-9223372036854775808 to \
             9223372036854775807",
            "found `-9223372036854775809`",
        ],
    );
    let above = err(
        &replace("l_beta = -110.45", "l_beta = 9223372036854775808"),
        11,
        &["key `derivatives.l_beta`"],
    );
    let parts = |e: &AircraftError| match e {
        AircraftError::InvalidValue {
            at, key, expected, ..
        } => Some((at.clone(), key.clone(), expected.clone())),
        _ => None,
    };
    assert!(parts(&below).is_some(), "{below}");
    assert_eq!(parts(&below), parts(&above));
}

#[test]
fn a_percentage_is_one_number_and_one_percent_sign() {
    let with = |entry: &str| format!("{GOOD}[uncertainty]\nl_p = {entry}\n");
    let five = parse(&with("\"5%\""), FILE).unwrap().uncertainty;
    for same in ["\" 5 % \"", "\"5 %\"", "\"+5%\""] {
        assert_eq!(
            parse(&with(same), FILE).unwrap().uncertainty,
            five,
            "{same}"
        );
    }
    for bad in ["5%%", "5% junk", "%5", "5%5", "%", "5 % %"] {
        let e = err(
            &with(&format!("\"{bad}\"")),
            23,
            &[
                "key `uncertainty.l_p`",
                "one number followed by exactly one `%`",
                &format!("found `\"{bad}\"`"),
            ],
        );
        assert!(matches!(e, AircraftError::InvalidValue { .. }));
    }
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

#[test]
fn helpers() {
    assert_eq!(edit_distance("l_pp", "l_p"), 1);
    assert_eq!(edit_distance("", "abc"), 3);
    assert_eq!(edit_distance("kitten", "sitting"), 3);
    assert_eq!(line_col("ab\ncé\nx", 0), (1, 1));
    assert_eq!(line_col("ab\ncé\nx", 3), (2, 1));
    assert_eq!(line_col("ab\ncé\nx", 5), (2, 2));
    assert_eq!(line_col("ab\ncé\nx", 7), (3, 1));
    assert_eq!(line_col("ab", 99), (1, 3));
}
