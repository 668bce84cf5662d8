//! The section of the zero-sideslip roll (Eqs 32-35): the trim with beta = 0 and the rudder
//! freed, its criterion and its jump polynomial.

use super::typeset::{Term, Writer};
use crate::algebra::{Matrix, Poly, Sym, Q};
use crate::derivation::Derivation;
use crate::emit::paper::{self as printed, parse};
use std::fmt::Write;

/// The names of the zero-sideslip trim numerators of [alpha0, Q0, R0].
const ZS_NUMERATORS: [&str; 3] = ["N^{zs}_\\alpha", "N^{zs}_Q", "N^{zs}_R"];

impl Writer<'_> {
    pub(super) fn zero_sideslip_section(&self, out: &mut String, d: &Derivation) {
        out.push_str("\\section{Zero-sideslip roll (Eqs.~32--35)}\n\n");
        let a1 = self.zero_sideslip_equations(out, d);
        self.zero_sideslip_trim(out, d, &a1);
        self.zero_sideslip_jump(out, d);
    }

    /// The equations other than roll at beta = 0 (Eq. 32) and their linear form at `p = P0`
    /// (Eqs 33-34), compared with the printed A1 and b1 u; returns A1.
    fn zero_sideslip_equations(&self, out: &mut String, d: &Derivation) -> Matrix {
        let s = self.s;
        out.push_str(
            "With $\\beta = 0$ held by the rudder ($\\delta_r$ freed), the PSS equations other \
             than roll are\n\\begin{align*}\n",
        );
        let lhs = [
            (0usize, "\\dot\\alpha"),
            (1, "\\dot\\beta"),
            (3, "\\dot q"),
            (4, "\\dot r"),
        ];
        let mut vars = vec![s.alpha, s.beta, s.p, s.q, s.r];
        vars.extend([s.delta_a, s.delta_e, s.delta_r]);
        let zs: Vec<Poly> = lhs
            .iter()
            .map(|(i, _)| d.model[*i].subs(s.beta, &Poly::zero()))
            .collect();
        let rows: Vec<String> = zs
            .iter()
            .zip(lhs)
            .map(|(f, (_, l))| self.rows(l, &self.grouped(f, &[&vars]), None))
            .collect();
        out.push_str(&rows.join(" \\\\\n"));
        out.push_str(" \\tag{32}\n\\end{align*}\n");
        // A1 in x = [alpha, q, r, delta_r]: rows from alpha, beta, q, r equations at p = P0.
        let unknowns = [s.alpha, s.q, s.r, s.delta_r];
        let at_p0: Vec<Poly> = zs.iter().map(|f| f.subs(s.p, &Poly::var(s.p0))).collect();
        let a1 = Matrix::from_rows(
            at_p0
                .iter()
                .map(|f| unknowns.iter().map(|u| f.coeff(*u, 1)).collect())
                .collect(),
        );
        let zero: Vec<(Sym, Q)> = unknowns.iter().map(|u| (*u, Q::ZERO)).collect();
        let rhs: Vec<Poly> = at_p0.iter().map(|f| f.subs_values(&zero)).collect();
        let _ = write!(
            out,
            "At $p = P_0$ they are linear in $x = [\\alpha, q, r, \\delta_r]^T$:\n\
             \\begin{{align*}}\nA_1 x + b_1 u &= 0 \\tag{{33}} \\\\\n\
             A_1 &= {}, \\qquad b_1 u = {} \\tag{{34}}\n\\end{{align*}}\n",
            self.matrix(&a1),
            self.column(&rhs)
        );
        let printed_a1 = Matrix::from_rows(
            printed::EQ34_A1
                .iter()
                .map(|r| r.iter().map(|e| parse(e)).collect())
                .collect(),
        );
        let rhs_diff: Vec<Poly> = printed::EQ34_RHS
            .iter()
            .zip(&rhs)
            .map(|(p, q)| &self.paper_case(q) - &parse(p))
            .collect();
        let _ = writeln!(
            out,
            "$A_1$ {} Eq.~34 as printed; $b_1 u$ {}.\n",
            if printed_a1 == a1 {
                "agrees with"
            } else {
                "differs from"
            },
            if rhs_diff.iter().all(Poly::is_zero) {
                "agrees with it".to_string()
            } else {
                let rows: Vec<String> = rhs_diff
                    .iter()
                    .enumerate()
                    .filter(|(_, p)| !p.is_zero())
                    .map(|(i, p)| {
                        format!(
                            "in row {}, by ${}$",
                            i + 1,
                            self.inline(&self.grouped(p, &[]))
                        )
                    })
                    .collect();
                format!(
                    "differs from it {} (derived minus printed; the paper omits terms in $n_p$ \
                     and $n_{{\\delta a}}$, both zero for its aircraft)",
                    rows.join(", ")
                )
            }
        );
        a1
    }

    /// det A1 and the trim (Eq. 35) with the rudder and the aileron holding it.
    fn zero_sideslip_trim(&self, out: &mut String, d: &Derivation, a1: &Matrix) {
        let s = self.s;
        let p0: &[Sym] = &[s.p0];
        let det_a1 = a1.det();
        let ndr = Poly::var(s.param(crate::aircraft::Param::NDeltaR));
        let block = det_a1 == &ndr * &d.zs_det;
        let _ = write!(
            out,
            "$A_1$ is block-triangular (the rudder enters only the yaw equation), so \
             $\\det A_1 = n_{{\\delta r}} \\Delta_1$ {} with\n\\begin{{align*}}\n{}\n\\end{{align*}}\n",
            if block { "(checked)" } else { "(NOT confirmed)" },
            self.rows("\\Delta_1", &self.grouped(&d.zs_det, &[p0]), None),
        );
        let names = ["\\alpha_0", "Q_0", "R_0"];
        let nn = ZS_NUMERATORS;
        let _ = write!(
            out,
            "The trim, $x_0 = -A_1^{{-1}} b_1 u = -\\frac{{\\operatorname{{adj}}[A_1]}}\
             {{\\det[A_1]}} b_1 u$:\n\\begin{{align*}}\n{} &= \\frac{{{}}}{{\\Delta_1}} \\\\\n\
             {} &= \\frac{{{}}}{{\\Delta_1}} \\\\\n{} &= \\frac{{{}}}{{\\Delta_1}} \\tag{{35}} \\\\\n\
             \\delta_r &= {} \\\\\n\\delta_a &= {}\n\\end{{align*}}\n",
            names[0],
            self.inline(&self.grouped(&d.zs_trim[0], &[])),
            names[1],
            self.inline(&self.grouped(&d.zs_trim[1], &[])),
            names[2],
            self.inline(&self.grouped(&d.zs_trim[2], &[])),
            self.frac(&d.zs_delta_r, &[]),
            self.frac(&d.zs_delta_a, &[]),
        );
        let _ = writeln!(
            out,
            "($\\delta_r$ and $\\delta_a$ in the trim symbols, $\\beta_0 = 0$); the numerators \
             are written ${}$, ${}$, ${}$ below.\n",
            nn[0], nn[1], nn[2]
        );
    }

    /// The jump polynomial of the zero-sideslip roll through the `c_m` of the jump section, its
    /// expansion in P0 and the pole polynomial.
    fn zero_sideslip_jump(&self, out: &mut String, d: &Derivation) {
        let s = self.s;
        let p0: &[Sym] = &[s.p0];
        let nn = ZS_NUMERATORS;
        let groups = self.split(
            &d.det_j5.subs(s.beta0, &Poly::zero()),
            &[s.alpha0, s.q0, s.r0],
        );
        let zs_names: Vec<(Sym, &str)> = vec![(s.alpha0, nn[0]), (s.q0, nn[1]), (s.r0, nn[2])];
        let mut sum_terms = Vec::new();
        for (m, _) in &groups {
            let sub = if m.is_one() {
                "1".to_string()
            } else {
                self.mono(m)
            };
            let mut factors = vec![format!("c_{{{sub}}}|_{{\\beta_0 = 0}}")];
            for (x, nm) in &zs_names {
                match m.exp(*x) {
                    0 => {}
                    1 => factors.push(nm.to_string()),
                    e => factors.push(format!("({nm})^{{{e}}}")),
                }
            }
            match 2 - m.total_degree() {
                0 => {}
                1 => factors.push("\\Delta_1".into()),
                k => factors.push(format!("\\Delta_1^{{{k}}}")),
            }
            sum_terms.push(Term::Atom {
                neg: false,
                body: factors.join(" "),
            });
        }
        out.push_str(
            "The jump polynomial of the zero-sideslip roll is $\\det J_5$ at this trim times \
             $\\Delta_1^2$, with the $c_m$ of Section~8 at $\\beta_0 = 0$:\n\\begin{align*}\n",
        );
        out.push_str(&self.rows("J^{zs}(P_0)", &sum_terms, None));
        out.push_str("\n\\end{align*}\n");
        let coeffs = d.zs_jump().coeffs(s.p0);
        let _ = write!(
            out,
            "Expanded ({} terms), $J^{{zs}}(P_0) = \\sum_k J^{{zs}}_k P_0^k$ with\n\\begin{{align*}}\n",
            d.zs_jump().len()
        );
        let ctrl: &[Sym] = &[s.delta_e];
        out.push_str(&self.coefficient_rows("J^{zs}", &coeffs, &[ctrl, &self.inertia()]));
        out.push_str("\n\\end{align*}\n");
        let _ = write!(
            out,
            "and the poles of $\\det K$ at the zeros of\n\\begin{{align*}}\n{}\n\\end{{align*}}\n\n",
            self.rows(
                "\\Delta_1^2\\, d|_{x = x_0}",
                &self.grouped(d.zs_d_det(), &[p0]),
                None
            )
        );
    }
}
