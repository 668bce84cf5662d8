//! The formulas in the generated functions' doc comments, printed from the derivation's
//! polynomials (never typed): a fenced `text` block of `name = formula` lines in the notation
//! of [`super::paper::parse`], which `tests/tests/generated.rs` parses back and compares with
//! the derivation.
//!
//! Every function documents the polynomials it is built from, as the parametric derivation has
//! them (the modules of the built-in aircraft evaluate the same polynomials with the data folded
//! in); the prose around the block only says how the named quantities combine.

use super::paper::print;
use crate::algebra::{Matrix, Poly};
use crate::derivation::Ratio;

/// Lines longer than this are broken before a `+` or `-` between terms.
const WIDTH: usize = 96;

/// A formula of a doc comment.
pub enum Formula<'a> {
    /// A polynomial.
    Poly(&'a Poly),
    /// A quotient of two polynomials, `(num) / (den)`.
    Ratio(&'a Ratio),
    /// A column of polynomials, `[a, b, ...]`.
    Vector(Vec<&'a Poly>),
    /// A matrix, one row a line, `[[a, b], [c, d]]`.
    Matrix(Vec<Vec<&'a Poly>>),
}

impl<'a> Formula<'a> {
    /// The entries of a matrix of the algebra layer.
    pub fn matrix(m: &'a Matrix) -> Formula<'a> {
        Formula::Matrix(
            (0..m.rows())
                .map(|i| (0..m.cols()).map(|j| m.get(i, j)).collect())
                .collect(),
        )
    }
}

/// `text` broken before top-level ` + ` and ` - ` so that each line (after `indent`) fits
/// [`WIDTH`] where the terms allow; continuation lines are indented four more.
fn wrap(text: &str, indent: usize) -> Vec<String> {
    // Top-level terms, each with the sign that precedes it.
    let mut terms: Vec<String> = Vec::new();
    let mut current = String::new();
    let mut depth = 0i32;
    let chars: Vec<char> = text.chars().collect();
    for (i, c) in chars.iter().enumerate() {
        depth += match c {
            '(' | '[' => 1,
            ')' | ']' => -1,
            _ => 0,
        };
        let boundary = depth == 0
            && *c == ' '
            && matches!(chars.get(i + 1), Some('+' | '-'))
            && chars.get(i + 2) == Some(&' ');
        if boundary {
            terms.push(std::mem::take(&mut current));
        } else {
            current.push(*c);
        }
    }
    terms.push(current);
    let mut lines: Vec<String> = vec![String::new()];
    for t in terms {
        let room = WIDTH - indent - if lines.len() > 1 { 4 } else { 0 };
        let last = lines.last_mut().expect("one line");
        if last.is_empty() {
            last.push_str(&t);
        } else if last.len() + 1 + t.len() <= room {
            last.push(' ');
            last.push_str(&t);
        } else {
            lines.push(t);
        }
    }
    let pad = " ".repeat(indent + 4);
    lines
        .into_iter()
        .enumerate()
        .map(|(k, l)| if k == 0 { l } else { format!("{pad}{l}") })
        .collect()
}

/// The doc lines of one formula, `name = ...`.
fn formula(name: &str, f: &Formula) -> Vec<String> {
    let lead = format!("{name} = ");
    let pad = " ".repeat(lead.len());
    match f {
        Formula::Poly(p) => {
            let mut l = wrap(&print(p), lead.len());
            l[0] = format!("{lead}{}", l[0]);
            l
        }
        Formula::Ratio(r) => {
            // The numerator wrapped inside its parentheses, then the denominator.
            let mut l = wrap(&print(&r.num), lead.len() + 1);
            l[0] = format!("{lead}({}", l[0]);
            let den = format!(") / ({})", print(&r.den));
            let last = l.last_mut().expect("one line");
            if last.len() + den.len() <= WIDTH {
                last.push_str(&den);
            } else {
                l.push(format!("{pad}    {}", &den[2..]));
                let n = l.len();
                l[n - 2].push(')');
            }
            l
        }
        Formula::Vector(v) => {
            let entries: Vec<String> = v.iter().map(|p| print(p)).collect();
            let mut l = wrap(&format!("[{}]", entries.join(", ")), lead.len());
            l[0] = format!("{lead}{}", l[0]);
            l
        }
        Formula::Matrix(rows) => {
            let n = rows.len();
            rows.iter()
                .enumerate()
                .map(|(i, row)| {
                    let entries: Vec<String> = row.iter().map(|p| print(p)).collect();
                    let open = if i == 0 { "[[" } else { " [" };
                    let close = if i + 1 == n { "]]" } else { "]," };
                    let start = if i == 0 { lead.clone() } else { pad.clone() };
                    format!("{start}{open}{}{close}", entries.join(", "))
                })
                .collect()
        }
    }
}

/// The doc lines of a block of formulas, with its heading.
pub fn block(items: &[(&str, Formula)]) -> Vec<String> {
    let mut out = vec![
        String::new(),
        "Formulas, printed from the derivation (model/src/derivation.rs):".to_string(),
        "```text".to_string(),
    ];
    for (name, f) in items {
        out.extend(formula(name, f));
    }
    out.push("```".to_string());
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::emit::paper::parse;

    #[test]
    fn long_formulas_break_between_terms_only() {
        let p = parse(
            "C*D*P0^4 + (D*m_alpha - C*n_beta + C*D*y_beta*z_alpha + m_q*n_r)*P0^2 \
             - m_alpha*n_beta - m_alpha*n_r*y_beta + m_q*n_beta*z_alpha + m_q*n_r*y_beta*z_alpha",
        );
        let lines = formula("det_A", &Formula::Poly(&p));
        assert!(lines.len() > 1, "{lines:?}");
        for l in &lines {
            assert!(l.len() <= WIDTH, "{l}");
        }
        let joined = lines.join(" ");
        let rhs = joined.split_once(" = ").unwrap().1;
        assert_eq!(parse(rhs), p);
    }
}
