//! What the reader makes of unusual text: garbage never panics, numbers enter as the literals
//! written, integers beyond i64, percentages, and the helpers that place a message.

use super::super::suggest::edit_distance;
use super::*;
use crate::aircraft::{decimal_to_rational, Param};
use num_rational::BigRational;

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
