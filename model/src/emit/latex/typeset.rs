//! The polynomial typesetter of `docs/formulas.tex`: polynomials grouped (by perturbation
//! variable, by powers of `P_0`, by trim symbols, by controls) with common monomial factors and a
//! leading minus sign pulled out of each group, then broken greedily into `align*` lines by an
//! estimate of their printed width; matrices, columns, fractions, and the sentence that states
//! whether a derived formula agrees with the paper's printed one. Every order is fixed here.

use crate::algebra::{Matrix, Mono, Poly, Sym, Q};
use crate::derivation::Ratio;
use crate::emit::paper::{display_order, perturbation_order};
use crate::equations::Symbols;
use std::collections::BTreeMap;
use std::fmt::Write;

/// One summand of a typeset sum: a signed atom, or a signed group `prefix (inner) suffix`.
#[derive(Clone, Debug)]
pub(super) enum Term {
    Atom {
        neg: bool,
        body: String,
    },
    Group {
        neg: bool,
        prefix: String,
        inner: Vec<Term>,
        suffix: String,
    },
}

impl Term {
    pub(super) fn nested(&self) -> bool {
        matches!(self, Term::Group { .. })
    }
}

/// Estimated printed width of a LaTeX math string, in units of about one italic letter.
pub(super) fn width(s: &str) -> f32 {
    let cs: Vec<char> = s.chars().collect();
    let mut w = 0.0;
    let mut i = 0;
    let mut script = 0usize; // brace depth at which a sub/superscript group ends
    let mut depth = 0usize;
    let mut single_script = false;
    while i < cs.len() {
        let c = cs[i];
        let scale = if script > 0 || single_script {
            0.7
        } else {
            1.0
        };
        match c {
            '\\' => {
                let start = i + 1;
                i += 1;
                while i < cs.len() && cs[i].is_ascii_alphabetic() {
                    i += 1;
                }
                let name: String = cs[start..i].iter().collect();
                if name.is_empty() {
                    i += 1; // \, \; \\ etc.
                    w += 0.3;
                } else {
                    w += match name.as_str() {
                        "dot" | "ddot" | "left" | "right" | "frac" | "tfrac" | "mathrm"
                        | "text" | "operatorname" => 0.0,
                        "quad" => 2.0,
                        "qquad" => 4.0,
                        "cdot" => 1.5,
                        _ => scale,
                    };
                    if single_script && name != "dot" && name != "ddot" {
                        single_script = false;
                    }
                }
                continue;
            }
            '{' => depth += 1,
            '}' => {
                if script == depth {
                    script = 0;
                }
                depth = depth.saturating_sub(1);
            }
            '^' | '_' => {
                if cs.get(i + 1) == Some(&'{') {
                    script = depth + 1;
                } else {
                    single_script = true;
                }
            }
            ' ' => {}
            '+' | '-' | '=' => w += 2.0 * scale,
            _ => {
                w += scale;
                single_script = false;
            }
        }
        i += 1;
    }
    w
}

/// The left-hand sides of the five state equations (Eqs 6-10), in state order.
pub(super) const STATE_RATES: [&str; 5] = [
    "\\dot\\alpha",
    "\\dot\\beta",
    "\\dot p",
    "\\dot q",
    "\\dot r",
];

/// Line width budget for a display, in the units of [`width`].
pub(super) const LINE: f32 = 78.0;

/// Sort key of a group's monomial: total degree, then exponents in display order, larger
/// exponents of earlier symbols first.
pub(super) type Key = (u32, Vec<std::cmp::Reverse<u32>>);

pub(super) struct Writer<'a> {
    pub(super) s: &'a Symbols,
    pub(super) order: Vec<Sym>,
}

impl<'a> Writer<'a> {
    pub(super) fn new(s: &'a Symbols) -> Writer<'a> {
        Writer {
            s,
            order: display_order(s),
        }
    }

    pub(super) fn l(&self, x: Sym) -> String {
        self.s.latex(x)
    }

    // ---- monomials and terms -------------------------------------------------------------

    /// Exponent vector of a monomial in display order (the sort key of terms and groups).
    pub(super) fn key(&self, m: &Mono) -> Key {
        (
            m.total_degree(),
            self.order
                .iter()
                .map(|x| std::cmp::Reverse(m.exp(*x)))
                .collect(),
        )
    }

    pub(super) fn mono(&self, m: &Mono) -> String {
        let mut parts = Vec::new();
        for x in &self.order {
            let e = m.exp(*x);
            if e == 1 {
                parts.push(self.l(*x));
            } else if e > 1 {
                parts.push(format!("{}^{{{e}}}", self.l(*x)));
            }
        }
        parts.join(" ")
    }

    /// `|c| m` without sign: coefficient 1 omitted, rationals as fractions.
    pub(super) fn body(&self, c: &Q, m: &Mono) -> String {
        let a = c.abs();
        let ms = self.mono(m);
        let cs = if a.is_integer() {
            a.to_string()
        } else {
            let b = a.to_big();
            format!("\\frac{{{}}}{{{}}}", b.numer(), b.denom())
        };
        match (a.is_one(), ms.is_empty()) {
            (true, true) => "1".into(),
            (true, false) => ms,
            (false, true) => cs,
            (false, false) => format!("{cs} {ms}"),
        }
    }

    /// The terms of `p` in display order: by total degree, then monomials with fewer of the
    /// early symbols (inertia coefficients first in Table A.1 order) first.
    pub(super) fn sorted(&self, p: &Poly) -> Vec<(Mono, Q)> {
        let mut t: Vec<(Mono, Q)> = p.terms().to_vec();
        t.sort_by_cached_key(|(m, _)| {
            (
                m.total_degree(),
                self.order.iter().map(|x| m.exp(*x)).collect::<Vec<_>>(),
            )
        });
        t
    }

    /// True when a group's monomial is written after the parentheses (perturbations, trim
    /// symbols, P0: `(...) P_0^2`), false when before (parameters, controls: `m_{\delta e}
    /// \delta_e (...)`).
    pub(super) fn trailing(&self, m: &Mono) -> bool {
        let s = self.s;
        m.factors()
            .iter()
            .any(|(x, _)| !s.params.contains(x) && ![s.delta_a, s.delta_e, s.delta_r].contains(x))
    }

    /// The plain terms of `p` times the monomial `times`.
    pub(super) fn plain(&self, p: &Poly, times: &Mono) -> Vec<Term> {
        self.sorted(p)
            .into_iter()
            .map(|(m, c)| Term::Atom {
                neg: c.is_negative(),
                body: self.body(&c, &m.mul(times)),
            })
            .collect()
    }

    /// Splits `p` by its monomials in `syms`: `(monomial in syms, coefficient)`, sorted.
    pub(super) fn split(&self, p: &Poly, syms: &[Sym]) -> Vec<(Mono, Poly)> {
        let mut groups: BTreeMap<Key, (Mono, Vec<(Mono, Q)>)> = BTreeMap::new();
        for (m, c) in p.terms() {
            let mut g = Mono::ONE;
            let mut rest = *m;
            for x in syms {
                let e = m.exp(*x);
                if e > 0 {
                    g.set(*x, e);
                    rest.set(*x, 0);
                }
            }
            groups
                .entry(self.key(&g))
                .or_insert((g, Vec::new()))
                .1
                .push((rest, c.clone()));
        }
        groups
            .into_values()
            .map(|(g, ts)| (g, Poly::from_terms(ts)))
            .collect()
    }

    /// `p` grouped level by level: by its monomials in `levels[0]`, each coefficient grouped by
    /// `levels[1]`, and so on; a group's common monomial and leading minus sign are pulled out.
    pub(super) fn grouped(&self, p: &Poly, levels: &[&[Sym]]) -> Vec<Term> {
        self.grouped_times(p, levels, &Mono::ONE)
    }

    pub(super) fn grouped_times(&self, p: &Poly, levels: &[&[Sym]], times: &Mono) -> Vec<Term> {
        let Some((first, rest)) = levels.split_first() else {
            return self.plain(p, times);
        };
        let mut out = Vec::new();
        for (g, coef) in self.split(p, first) {
            let outer = g.mul(times);
            if coef.len() == 1 {
                out.extend(self.plain(&coef, &outer));
            } else if outer.is_one() {
                // No factor outside: parentheses would be redundant.
                out.extend(self.grouped(&coef, rest));
            } else {
                out.push(self.group(&coef, rest, &outer));
            }
        }
        out
    }

    /// `coef * outer` as one group, `coef` of several terms.
    pub(super) fn group(&self, coef: &Poly, levels: &[&[Sym]], outer: &Mono) -> Term {
        // Common monomial factor.
        let ts = coef.terms();
        let mut gcd = ts[0].0;
        for (m, _) in &ts[1..] {
            for (x, e) in gcd.factors() {
                gcd.set(x, e.min(m.exp(x)));
            }
        }
        // Common integer factor (when every coefficient is an integer).
        let content = if ts.iter().all(|(_, c)| c.is_integer()) {
            ts.iter().fold(num_bigint::BigInt::from(0), |g, (_, c)| {
                num_integer::Integer::gcd(&g, c.to_big().numer())
            })
        } else {
            num_bigint::BigInt::from(1)
        };
        let content = Q::from_big(num_rational::BigRational::from_integer(content));
        let mut inner = Poly::from_terms(ts.iter().map(|(m, c)| {
            let mut r = *m;
            for (x, e) in gcd.factors() {
                r.set(x, m.exp(x) - e);
            }
            (r, c.div(&content))
        }));
        // Leading minus sign (of the first term as displayed).
        let lead_neg = self.sorted(&inner)[0].1.is_negative();
        if lead_neg {
            inner = -inner;
        }
        let (front, back) = if self.trailing(outer) {
            (gcd, *outer)
        } else {
            (gcd.mul(outer), Mono::ONE)
        };
        let prefix = if front.is_one() && content.is_one() {
            String::new()
        } else {
            self.body(&content, &front)
        };
        Term::Group {
            neg: lead_neg,
            prefix,
            inner: self.grouped(&inner, levels),
            suffix: self.mono(&back),
        }
    }

    // ---- rendering -----------------------------------------------------------------------

    /// Tokens (unbreakable pieces, breaks allowed between them) of a sum.
    pub(super) fn tokens(&self, terms: &[Term]) -> Vec<String> {
        if terms.is_empty() {
            return vec!["0".into()];
        }
        let mut out = Vec::new();
        for (i, t) in terms.iter().enumerate() {
            push_term(t, i == 0, &mut out);
        }
        out
    }

    /// A sum on one line.
    pub(super) fn inline(&self, terms: &[Term]) -> String {
        self.tokens(terms).join(" ")
    }

    /// One equation `lhs = rhs` (or, with `lhs` empty, `rhs = 0`) as `align*` rows, broken
    /// greedily; `tag` goes on the last row.
    pub(super) fn rows(&self, lhs: &str, terms: &[Term], tag: Option<&str>) -> String {
        let toks = self.tokens(terms);
        let lead = if lhs.is_empty() {
            2.0
        } else {
            width(lhs) + 3.0
        };
        let mut lines: Vec<Vec<String>> = vec![Vec::new()];
        let mut used = lead;
        for t in toks {
            let tw = width(&t) + 1.0;
            let cur = lines.last_mut().expect("non-empty");
            if !cur.is_empty() && used + tw > LINE {
                lines.push(vec![t]);
                used = lead + 2.0 + tw;
            } else {
                cur.push(t);
                used += tw;
            }
        }
        let mut out = String::new();
        let n = lines.len();
        for (i, line) in lines.iter().enumerate() {
            let body = line.join(" ");
            if i == 0 {
                if lhs.is_empty() {
                    let _ = write!(out, "& {body}");
                } else {
                    let _ = write!(out, "{lhs} &= {body}");
                }
            } else {
                let _ = write!(out, "&\\quad {{}}{body}");
            }
            if i + 1 == n {
                if lhs.is_empty() {
                    out.push_str(" = 0");
                }
                if let Some(t) = tag {
                    let _ = write!(out, " \\tag{{{t}}}");
                }
            } else {
                out.push_str(" \\\\\n");
            }
        }
        out
    }

    /// The coefficients `name_k` of a polynomial in P0 as `align*` rows, in order of `k`,
    /// each grouped by `levels`.
    pub(super) fn coefficient_rows(
        &self,
        name: &str,
        coeffs: &[Poly],
        levels: &[&[Sym]],
    ) -> String {
        let rows: Vec<String> = coeffs
            .iter()
            .enumerate()
            .map(|(k, c)| self.rows(&format!("{name}_{{{k}}}"), &self.grouped(c, levels), None))
            .collect();
        rows.join(" \\\\[1ex]\n")
    }

    pub(super) fn matrix(&self, m: &Matrix) -> String {
        let rows: Vec<String> = (0..m.rows())
            .map(|i| {
                (0..m.cols())
                    .map(|j| self.inline(&self.grouped(m.get(i, j), &[])))
                    .collect::<Vec<_>>()
                    .join(" & ")
            })
            .collect();
        format!(
            "\\begin{{pmatrix}} {} \\end{{pmatrix}}",
            rows.join(" \\\\ ")
        )
    }

    pub(super) fn column(&self, v: &[Poly]) -> String {
        let rows: Vec<String> = v
            .iter()
            .map(|p| self.inline(&self.grouped(p, &[])))
            .collect();
        format!(
            "\\begin{{pmatrix}} {} \\end{{pmatrix}}",
            rows.join(" \\\\ ")
        )
    }

    /// `num / den` inline as a fraction.
    pub(super) fn frac(&self, r: &Ratio, levels: &[&[Sym]]) -> String {
        format!(
            "\\frac{{{}}}{{{}}}",
            self.inline(&self.grouped(&r.num, levels)),
            self.inline(&self.grouped(&r.den, levels))
        )
    }

    /// `p` in the paper's case: the trim terms `z_0` and `alpha_t` zero (angles measured from
    /// zero lift, the principal axis on the flight path), the only case the paper prints.
    pub(super) fn paper_case(&self, p: &Poly) -> Poly {
        use crate::aircraft::Param;
        p.subs(self.s.param(Param::Z0), &Poly::zero())
            .subs(self.s.param(Param::AlphaT), &Poly::zero())
    }

    /// A comparison with the paper's print, in the paper's case ([`Self::paper_case`]):
    /// agreement, or the difference typeset.
    pub(super) fn check(
        &self,
        what: &str,
        derived: &Poly,
        printed: &Poly,
        levels: &[&[Sym]],
    ) -> String {
        let diff = &self.paper_case(derived) - printed;
        if diff.is_zero() {
            format!("{what}: agrees with the paper's print.")
        } else {
            format!(
                "{what}: differs from the paper's print; derived minus printed is \
                 ${}$.",
                self.inline(&self.grouped(&diff, levels))
            )
        }
    }

    pub(super) fn states_syms(&self) -> Vec<Sym> {
        perturbation_order(self.s).to_vec()
    }

    pub(super) fn inertia(&self) -> [Sym; 3] {
        use crate::aircraft::Param;
        [
            self.s.param(Param::C),
            self.s.param(Param::D),
            self.s.param(Param::E),
        ]
    }

    pub(super) fn trims4(&self) -> [Sym; 4] {
        [self.s.alpha0, self.s.beta0, self.s.q0, self.s.r0]
    }
}

fn push_term(t: &Term, first: bool, out: &mut Vec<String>) {
    let sign = |neg: bool| match (first, neg) {
        (true, false) => "",
        (true, true) => "-",
        (false, false) => "+ ",
        (false, true) => "- ",
    };
    match t {
        Term::Atom { neg, body } => out.push(format!("{}{body}", sign(*neg))),
        Term::Group {
            neg,
            prefix,
            inner,
            suffix,
        } => {
            let (open, close) = if inner.iter().any(Term::nested) {
                ("\\Bigl(", "\\Bigr)")
            } else {
                ("\\bigl(", "\\bigr)")
            };
            let mut toks = Vec::new();
            for (i, x) in inner.iter().enumerate() {
                push_term(x, i == 0, &mut toks);
            }
            let pre = if prefix.is_empty() {
                String::new()
            } else {
                format!("{prefix} ")
            };
            toks[0] = format!("{}{pre}{open}{}", sign(*neg), toks[0]);
            let last = toks.len() - 1;
            let suf = if suffix.is_empty() {
                String::new()
            } else {
                format!(" {suffix}")
            };
            toks[last] = format!("{}{close}{suf}", toks[last]);
            out.extend(toks);
        }
    }
}
