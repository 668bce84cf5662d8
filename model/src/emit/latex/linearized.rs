//! The sections from the linearization to the roll mode: the linearized equations (Eqs 6-12),
//! the second-order form with its stiffness matrix (Eqs 13-20), and the roll mode with its
//! static residual (Eqs 21-26).

use super::typeset::{Writer, STATE_RATES};
use crate::algebra::{Matrix, Poly};
use crate::derivation::Derivation;
use crate::emit::paper::{self as printed, parse};
use std::fmt::Write;

impl Writer<'_> {
    pub(super) fn linearized_section(&self, out: &mut String, d: &Derivation) {
        let st = self.states_syms();
        out.push_str("\\section{Linearized equations (Eqs.~6--12)}\n\n");
        out.push_str(
            "The Jacobian of the PSS model at the trim, applied to the perturbations \
             $[\\alpha, \\beta, p, q, r]$:\n\\begin{align*}\n",
        );
        let lhs = STATE_RATES;
        let rows: Vec<String> = d
            .linearized
            .iter()
            .zip(lhs)
            .enumerate()
            .map(|(i, (f, l))| self.rows(l, &self.grouped(f, &[&st]), Some(&(6 + i).to_string())))
            .collect();
        out.push_str(&rows.join(" \\\\\n"));
        out.push_str("\n\\end{align*}\n");
        let checks: Vec<String> = d
            .linearized
            .iter()
            .zip(printed::EQ6_10)
            .enumerate()
            .map(|(i, (f, p))| self.check(&format!("Eq.~{}", 6 + i), f, &parse(p), &[&st]))
            .collect();
        let _ = writeln!(out, "{}\n", checks.join(" "));
        out.push_str("Solving Eqs.~6 and 7 for $q$ and $r$:\n\\begin{align*}\n");
        out.push_str(&self.rows("q", &self.grouped(&d.q_elim, &[&st]), Some("11")));
        out.push_str(" \\\\\n");
        out.push_str(&self.rows("r", &self.grouped(&d.r_elim, &[&st]), Some("12")));
        out.push_str("\n\\end{align*}\n");
        let _ = writeln!(
            out,
            "{} {}\n",
            self.check("Eq.~11", &d.q_elim, &parse(printed::EQ11), &[&st]),
            self.check("Eq.~12", &d.r_elim, &parse(printed::EQ12), &[&st])
        );
    }

    pub(super) fn second_order_section(&self, out: &mut String, d: &Derivation) {
        let s = self.s;
        let st = self.states_syms();
        out.push_str("\\section{Second-order form and stiffness matrix (Eqs.~13--20)}\n\n");
        out.push_str(
            "Substituting Eqs.~11--12 into Eqs.~9 and 10 (and the time derivatives of Eqs.~11--12 \
             for $\\dot q$, $\\dot r$):\n\\begin{align*}\n",
        );
        out.push_str(&self.rows("", &self.grouped(&d.second_order[0], &[&st]), Some("13")));
        out.push_str(" \\\\\n");
        out.push_str(&self.rows("", &self.grouped(&d.second_order[1], &[&st]), Some("14")));
        out.push_str("\n\\end{align*}\n");
        let _ = writeln!(
            out,
            "{} {}\n",
            self.check("Eq.~13", &d.second_order[0], &parse(printed::EQ13), &[&st]),
            self.check("Eq.~14", &d.second_order[1], &parse(printed::EQ14), &[&st])
        );
        out.push_str(
            "The sign of the $p$-terms of Eq.~13 as printed contradicts the paper's own \
             Eqs.~17 and 28; the derived signs agree with Eqs.~17 and 28. The derived Eq.~14 \
             carries the term $n_p p$ from the yaw equation, which the paper drops \
             ($n_p = 0$ for both aircraft).\n\n",
        );
        let yd = [s.alpha_dot, s.beta_dot];
        let damping: [[Poly; 2]; 2] =
            std::array::from_fn(|i| std::array::from_fn(|j| d.second_order[i].coeff(yd[j], 1)));
        let e: [Poly; 2] = std::array::from_fn(|i| d.second_order[i].coeff(s.p_dot, 1));
        let m2 = |m: &[[Poly; 2]; 2]| Matrix::from_rows(m.iter().map(|r| r.to_vec()).collect());
        let _ = write!(
            out,
            "With $y = [\\alpha, \\beta]^T$, Eqs.~13--14 read\n\\begin{{align*}}\n\
             \\ddot y + \\mathsf{{C}}_0 \\dot y + K_0 y + e\\,\\dot p + g\\,p &= 0, \\qquad \
             e = {}, \\quad g = {} \\tag{{15}}\n\\end{{align*}}\n\
             with the damping matrix ($\\mathsf{{C}}$, not the inertia coefficient $C$) and \
             the stiffness matrix without the roll residual\n\
             \\begin{{align*}}\n\\mathsf{{C}}_0 &= {}, \\qquad K_0 = {} \\tag{{16}}\n\\end{{align*}}\n",
            self.column(&e),
            self.column(&d.g),
            self.matrix(&m2(&damping)),
            self.matrix(&m2(&d.k0)),
        );
        let k0_ok = (0..2)
            .all(|i| (0..2).all(|j| parse(printed::EQ16_K0[i][j]) == self.paper_case(&d.k0[i][j])));
        let _ = writeln!(
            out,
            "$K_0$ {} Eq.~16 as printed.\n",
            if k0_ok { "agrees with" } else { "differs from" }
        );
        out.push_str(
            "The roll perturbation is replaced by its static residual $p_s$ (Eq.~22) and \
             $\\dot p$ by $\\dot p_s$ (Eq.~23). Since $\\partial \\dot p_s/\\partial y_j = 0$ \
             (Eq.~26), only $g$ enters the stiffness, $K = K_0 + F$ (the damping matrix \
             becomes $\\mathsf{C} = \\mathsf{C}_0 - e h^T/d$ and does not enter the criterion), \
             with\n\\begin{align*}\n",
        );
        let mut rows = Vec::new();
        for i in 1..=2 {
            for (j, y) in ["\\alpha", "\\beta"].iter().enumerate() {
                let tag = 15 + 2 * i + j;
                rows.push(format!(
                    "f_{{{i}{}}} &= g_{i} \\frac{{\\partial p_s}}{{\\partial {y}}} + e_{i} \
                     \\frac{{\\partial \\dot p_s}}{{\\partial {y}}} = g_{i} \\frac{{\\partial \
                     p_s}}{{\\partial {y}}} \\tag{{{tag}}}",
                    j + 1,
                ));
            }
        }
        out.push_str(&rows.join(" \\\\\n"));
        out.push_str("\n\\end{align*}\n");
        let g_checks: Vec<String> = (0..2)
            .map(|i| {
                self.check(
                    &format!(
                        "$g_{}$ (the factor in Eqs.~{}--{})",
                        i + 1,
                        17 + 2 * i,
                        18 + 2 * i
                    ),
                    &d.g[i],
                    &parse(printed::EQ17_20_G[i]),
                    &[],
                )
            })
            .collect();
        let _ = writeln!(out, "{}\n", g_checks.join(" "));
    }

    pub(super) fn roll_section(&self, out: &mut String, d: &Derivation) {
        let st = self.states_syms();
        out.push_str("\\section{Roll mode and its static residual (Eqs.~21--26)}\n\n");
        out.push_str("Eq.~8 with $q$, $r$ from Eqs.~11--12:\n\\begin{align*}\n");
        out.push_str(&self.rows("\\dot p", &self.grouped(&d.roll_mode, &[&st]), Some("21")));
        out.push_str("\n\\end{align*}\n");
        let _ = writeln!(
            out,
            "{}\n",
            self.check("Eq.~21", &d.roll_mode, &parse(printed::EQ21), &[&st])
        );
        let _ = write!(
            out,
            "With $\\dot\\alpha = \\dot\\beta = 0$ and $\\dot p = 0$ the roll perturbation \
             settles to its static residual\n\\begin{{align*}}\n\
             p_s &= -\\frac{{h_\\alpha \\alpha + h_\\beta \\beta}}{{d}} \\tag{{22}} \\\\\n\
             \\dot p_s &= -\\frac{{h_\\alpha \\dot\\alpha + h_\\beta \\dot\\beta}}{{d}} \\tag{{23}}\n\
             \\end{{align*}}\nwith\n\\begin{{align*}}\n{} \\\\\n{} \\\\\n{}\n\\end{{align*}}\n",
            self.rows("d", &self.grouped(&d.d, &[]), None),
            self.rows("h_\\alpha", &self.grouped(&d.h[0], &[]), None),
            self.rows("h_\\beta", &self.grouped(&d.h[1], &[]), None),
        );
        let _ = writeln!(
            out,
            "{} {} {}\n",
            self.check("$d$", &d.d, &parse(printed::EQ22_D), &[]),
            self.check("$h_\\alpha$", &d.h[0], &parse(printed::EQ22_H[0]), &[]),
            self.check("$h_\\beta$", &d.h[1], &parse(printed::EQ22_H[1]), &[]),
        );
        let _ = write!(
            out,
            "Its partial derivatives:\n\\begin{{align*}}\n\
             \\frac{{\\partial p_s}}{{\\partial \\alpha}} &= {} \\tag{{24}} \\\\\n\
             \\frac{{\\partial p_s}}{{\\partial \\beta}} &= {} \\tag{{25}} \\\\\n\
             \\frac{{\\partial \\dot p_s}}{{\\partial \\alpha}} &= \
             \\frac{{\\partial \\dot p_s}}{{\\partial \\beta}} = 0 \\tag{{26}}\n\\end{{align*}}\n\n",
            self.frac(&d.dps[0], &[]),
            self.frac(&d.dps[1], &[]),
        );
    }
}
