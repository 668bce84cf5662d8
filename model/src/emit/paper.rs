//! The paper's printed formulas (Mahale & Ananthkrishnan, AIAA 2006-6267), transcribed once in
//! the symbol names of [`crate::equations`] (`alpha_dot`, `P0`, `m_q`, ...), and the parser that
//! reads them as polynomials.
//!
//! Nothing is derived from these strings: `docs/formulas.tex` ([`super::latex`]) compares them with
//! the derivation and states agreement or typesets the difference, and
//! `tests/tests/latex.rs` pins each difference exactly. [`print()`] is the parser's inverse: it
//! writes the derivation's polynomials in the same notation for the generated code's doc
//! comments, where `tests/tests/generated.rs` reads them back with [`parse`].
//!
//! ```
//! use model::emit::paper::parse;
//!
//! // the parser reads the paper's notation as exact polynomials
//! assert_eq!(parse("(m_q + C*y_beta)*P0"), parse("P0*m_q + C*P0*y_beta"));
//! ```

use crate::algebra::{Poly, Sym, Q};
use crate::derivation::hopf::hopf_symbols;
use crate::equations::{symbols, Symbols};

/// Eq. 5 multiplied by `C D` (with `m'_alpha = m_alpha/C`, `m'_q = m_q/C`,
/// `n'_beta = -n_beta/D`, `n'_r = -n_r/D`).
pub const EQ5_TIMES_CD: &str =
    "C*D*P0^4 + (D*m_alpha - C*n_beta + C*D*y_beta*z_alpha + m_q*n_r)*P0^2 \
    - m_alpha*n_beta - m_alpha*n_r*y_beta + m_q*n_beta*z_alpha + m_q*n_r*y_beta*z_alpha";
/// Eq. 2: the matrix A, row by row.
pub const EQ2_A: [[&str; 4]; 4] = [
    ["z_alpha", "-P0", "1", "0"],
    ["P0", "y_beta", "0", "-1"],
    ["m_alpha", "0", "m_q", "C*P0"],
    ["0", "n_beta", "-D*P0", "n_r"],
];
/// Eq. 2: `b u + b1 P0` with `b` and `b1` as printed.
pub const EQ2_RHS: [&str; 4] = ["0", "0", "m_delta_e*delta_e", "n_delta_r*delta_r + n_p*P0"];
/// Eqs 6-10: right-hand sides of the linearized equations.
pub const EQ6_10: [&str; 5] = [
    "q - P0*beta - p*beta0 + z_alpha*alpha",
    "P0*alpha + p*alpha0 - r + y_beta*beta",
    "l_p*p + l_beta*beta + l_r*r - E*Q0*r - E*q*R0",
    "m_q*q + m_alpha*alpha + C*P0*r + C*p*R0",
    "n_r*r + n_beta*beta + n_p*p - D*P0*q - D*p*Q0",
];
/// Eq. 11: q.
pub const EQ11: &str = "alpha_dot + P0*beta + p*beta0 - z_alpha*alpha";
/// Eq. 12: r.
pub const EQ12: &str = "P0*alpha + p*alpha0 - beta_dot + y_beta*beta";
/// Eq. 13 (left-hand side, `= 0`).
pub const EQ13: &str =
    "alpha_ddot - (z_alpha + m_q)*alpha_dot - (m_alpha - m_q*z_alpha + C*P0^2)*alpha \
    + P0*(C + 1)*beta_dot - P0*(m_q + C*y_beta)*beta + p_dot*beta0 \
    - (m_q*beta0 - C*R0 - C*P0*alpha0)*p";
/// Eq. 14 (left-hand side, `= 0`).
pub const EQ14: &str = "beta_ddot - (n_r + y_beta)*beta_dot + (n_beta + n_r*y_beta - D*P0^2)*beta \
    - P0*(D + 1)*alpha_dot + P0*(n_r + D*z_alpha)*alpha - p_dot*alpha0 \
    + (n_r*alpha0 - D*Q0 - D*P0*beta0)*p";
/// Eq. 16: the entries of K without the roll residual.
pub const EQ16_K0: [[&str; 2]; 2] = [
    ["-(m_alpha - m_q*z_alpha + C*P0^2)", "-P0*(m_q + C*y_beta)"],
    ["P0*(n_r + D*z_alpha)", "n_beta + n_r*y_beta - D*P0^2"],
];
/// Eqs 17-20: the factors multiplying the partials of p_s.
pub const EQ17_20_G: [&str; 2] = [
    "-m_q*beta0 - C*R0 - C*P0*alpha0",
    "n_r*alpha0 - D*Q0 - D*P0*beta0",
];
/// Eq. 21: the roll-mode right-hand side.
pub const EQ21: &str = "-E*R0*alpha_dot + (l_r*P0 - E*Q0*P0 + E*R0*z_alpha)*alpha \
    + (E*Q0 - l_r)*beta_dot + (l_beta + l_r*y_beta - E*Q0*y_beta - E*R0*P0)*beta \
    + (l_p + l_r*alpha0 - E*Q0*alpha0 - E*R0*beta0)*p";
/// Eq. 22: the denominator of p_s.
pub const EQ22_D: &str = "l_p + l_r*alpha0 - E*Q0*alpha0 - E*R0*beta0";
/// Eq. 22: the coefficients of alpha and beta in the numerator of p_s.
pub const EQ22_H: [&str; 2] = [
    "l_r*P0 - E*Q0*P0 + E*R0*z_alpha",
    "l_beta + l_r*y_beta - E*Q0*y_beta - E*R0*P0",
];
/// Eqs 28-31: the first factors of the numerators of f_ij (rows i = 1, 2).
pub const EQ28_31: [&str; 2] = [
    "m_q*beta0 + C*R0 + C*P0*alpha0",
    "D*Q0 + D*P0*beta0 - n_r*alpha0",
];
/// Eq. 34: the matrix A1, row by row, in x = [alpha, q, r, delta_r].
pub const EQ34_A1: [[&str; 4]; 4] = [
    ["z_alpha", "1", "0", "0"],
    ["P0", "0", "-1", "0"],
    ["m_alpha", "m_q", "C*P0", "0"],
    ["0", "-D*P0", "n_r", "n_delta_r"],
];
/// Eq. 34: `b1 u` as printed.
pub const EQ34_RHS: [&str; 4] = ["0", "0", "m_delta_e*delta_e", "0"];

/// Parses a printed formula written with `+ - * / ^ ( )`, integers and the model's symbol names
/// (and the Hopf symbols `c1..c5`, `s`, `w` of [`crate::derivation::hopf::hopf_symbols`]); `/`
/// divides by a constant only.
///
/// Panics on a malformed string or an unknown name: the strings are constants of this module,
/// so that is a bug here, caught by the tests.
pub fn parse(src: &str) -> Poly {
    let s = symbols();
    let toks = lex(src);
    let mut pos = 0;
    let p = parse_sum(s, &toks, &mut pos);
    assert!(pos == toks.len(), "trailing input in {src:?}");
    p
}

fn lex(src: &str) -> Vec<String> {
    let mut out = Vec::new();
    let cs: Vec<char> = src.chars().collect();
    let mut i = 0;
    while i < cs.len() {
        let c = cs[i];
        if c.is_whitespace() {
            i += 1;
        } else if c.is_ascii_alphanumeric() || c == '_' {
            let start = i;
            while i < cs.len() && (cs[i].is_ascii_alphanumeric() || cs[i] == '_') {
                i += 1;
            }
            out.push(cs[start..i].iter().collect());
        } else {
            assert!("+-*/^()".contains(c), "unexpected {c:?} in {src:?}");
            out.push(c.to_string());
            i += 1;
        }
    }
    out
}

fn parse_sum(s: &Symbols, t: &[String], pos: &mut usize) -> Poly {
    let mut acc = Poly::zero();
    let mut neg = false;
    if *pos < t.len() && (t[*pos] == "-" || t[*pos] == "+") {
        neg = t[*pos] == "-";
        *pos += 1;
    }
    loop {
        let term = parse_product(s, t, pos);
        acc = if neg { &acc - &term } else { &acc + &term };
        if *pos < t.len() && (t[*pos] == "+" || t[*pos] == "-") {
            neg = t[*pos] == "-";
            *pos += 1;
        } else {
            return acc;
        }
    }
}

fn parse_product(s: &Symbols, t: &[String], pos: &mut usize) -> Poly {
    let mut acc = parse_power(s, t, pos);
    while *pos < t.len() && (t[*pos] == "*" || t[*pos] == "/") {
        let divide = t[*pos] == "/";
        *pos += 1;
        let factor = parse_power(s, t, pos);
        acc = if divide {
            let c = factor.as_constant().expect("division by a constant");
            acc.scale(&Q::ONE.div(&c))
        } else {
            &acc * &factor
        };
    }
    acc
}

fn parse_power(s: &Symbols, t: &[String], pos: &mut usize) -> Poly {
    let tok = t.get(*pos).expect("unexpected end of formula").clone();
    *pos += 1;
    let base = if tok == "(" {
        let inner = parse_sum(s, t, pos);
        assert!(t.get(*pos).is_some_and(|c| c == ")"), "missing )");
        *pos += 1;
        inner
    } else if let Ok(n) = tok.parse::<i64>() {
        Poly::int(n)
    } else {
        Poly::var(lookup(s, &tok))
    };
    if t.get(*pos).is_some_and(|c| c == "^") {
        let e: u32 = t[*pos + 1].parse().expect("integer exponent");
        *pos += 2;
        base.pow(e)
    } else {
        base
    }
}

fn lookup(s: &Symbols, name: &str) -> Sym {
    let h = hopf_symbols();
    display_order(s)
        .into_iter()
        .chain(h.c)
        .chain([h.s, h.w])
        .find(|x| x.name() == name)
        .unwrap_or_else(|| panic!("unknown symbol {name:?}"))
}

/// Writes a polynomial in the notation [`parse`] reads: terms by total degree, then with more of
/// the earlier symbols of the display order (parameters in Table A.1 order, controls, P0, trims)
/// first; factors in display order; `*` between factors, `^` for powers, an integer
/// coefficient before the factors and a fractional one as `p/q*...`.
///
/// ```
/// use model::emit::paper::{parse, print};
///
/// let d = parse("l_p + l_r*alpha0 - E*Q0*alpha0 - E*R0*beta0");
/// assert_eq!(print(&d), "l_p + l_r*alpha0 - E*alpha0*Q0 - E*beta0*R0");
/// assert_eq!(parse(&print(&d)), d);
/// ```
pub fn print(p: &Poly) -> String {
    let s = symbols();
    let h = hopf_symbols();
    let order: Vec<Sym> = display_order(s)
        .into_iter()
        .chain(h.c)
        .chain([h.s, h.w])
        .collect();
    let mut terms = p.terms().to_vec();
    terms.sort_by_cached_key(|(m, _)| {
        (
            m.total_degree(),
            order
                .iter()
                .map(|x| std::cmp::Reverse(m.exp(*x)))
                .collect::<Vec<_>>(),
        )
    });
    if terms.is_empty() {
        return "0".into();
    }
    let mut out = String::new();
    for (i, (m, c)) in terms.iter().enumerate() {
        let sign = if c.is_negative() { "-" } else { "+" };
        if i == 0 {
            if c.is_negative() {
                out.push('-');
            }
        } else {
            out.push_str(&format!(" {sign} "));
        }
        let mut factors: Vec<String> = Vec::new();
        let a = c.abs();
        if !a.is_one() || m.total_degree() == 0 {
            let b = a.to_big();
            factors.push(if b.is_integer() {
                b.numer().to_string()
            } else {
                format!("{}/{}", b.numer(), b.denom())
            });
        }
        for x in &order {
            match m.exp(*x) {
                0 => {}
                1 => factors.push(x.name().to_string()),
                e => factors.push(format!("{}^{e}", x.name())),
            }
        }
        out.push_str(&factors.join("*"));
    }
    out
}

/// Every symbol of the model in display order: parameters (Table A.1 order), controls, P0,
/// trims, then the perturbations with their derivatives.
pub(super) fn display_order(s: &Symbols) -> Vec<Sym> {
    let mut v: Vec<Sym> = s.params.to_vec();
    v.extend([
        s.delta_a, s.delta_e, s.delta_r, s.p0, s.alpha0, s.beta0, s.q0, s.r0,
    ]);
    v.extend(perturbation_order(s));
    v
}

/// The perturbations with their derivatives, in display order (highest derivative first).
pub(super) fn perturbation_order(s: &Symbols) -> [Sym; 10] {
    [
        s.alpha_ddot,
        s.alpha_dot,
        s.alpha,
        s.beta_ddot,
        s.beta_dot,
        s.beta,
        s.p_dot,
        s.p,
        s.q,
        s.r,
    ]
}
