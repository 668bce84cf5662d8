//! The sections of the criterion itself: `det K = 0` (Eqs 27-31) and the identity
//! `det J5 = d det K` that ties it to the Jacobian.

use super::typeset::Writer;
use crate::algebra::Sym;
use crate::derivation::Derivation;
use crate::emit::paper::{self as printed, parse};
use std::fmt::Write;

impl Writer<'_> {
    pub(super) fn criterion_section(&self, out: &mut String, d: &Derivation) {
        let s = self.s;
        let trims: &[Sym] = &self.trims4();
        out.push_str("\\section{The criterion $\\det K = 0$ (Eqs.~27--31)}\n\n");
        out.push_str(
            "With $p = p_s$ the residual terms are $f_{ij} = g_i\\,\\partial p_s/\\partial y_j = \
             -g_i h_j / d$, so that\n\\begin{align*}\n\
             \\det K = \\begin{vmatrix} K_{0,11} + f_{11} & K_{0,12} + f_{12} \\\\ \
             K_{0,21} + f_{21} & K_{0,22} + f_{22} \\end{vmatrix} = 0, \\qquad \
             K_{ij} = K_{0,ij} - \\frac{g_i h_j}{d} \\tag{27}\n\\end{align*}\nwith\n\
             \\begin{align*}\n",
        );
        let mut rows = Vec::new();
        for (i, g) in d.g.iter().enumerate() {
            let minus_g = self.inline(&self.grouped(&-g, &[]));
            for (j, h) in ["h_\\alpha", "h_\\beta"].iter().enumerate() {
                let tag = 28 + 2 * i + j;
                rows.push(format!(
                    "f_{{{}{}}} &= -\\frac{{g_{} {h}}}{{d}} = \\frac{{\\bigl({minus_g}\\bigr)\\, \
                     {h}}}{{d}} \\tag{{{tag}}}",
                    i + 1,
                    j + 1,
                    i + 1,
                ));
            }
        }
        out.push_str(&rows.join(" \\\\\n"));
        out.push_str("\n\\end{align*}\n");
        let checks: Vec<String> = (0..2)
            .map(|i| {
                self.check(
                    &format!("The first factor of Eqs.~{}--{}", 28 + 2 * i, 29 + 2 * i),
                    &-&d.g[i],
                    &parse(printed::EQ28_31[i]),
                    &[],
                )
            })
            .collect();
        let _ = writeln!(out, "{}\n", checks.join(" "));
        out.push_str(
            "\\paragraph{Sign conventions.} The derivation's conventions are those of \
             Appendix A.2 with Euler's signs ($-E q r$, $+C p r$, $-D p q$), perturbations \
             $x = x_0 + \\delta x$, and Eqs.~13--14 normalised to leading coefficient $+1$ in \
             $\\ddot\\alpha$, $\\ddot\\beta$, so that $\\ddot y + \\mathsf{C}\\dot y + K y = 0$. \
             Then $g_1 = -(m_q \\beta_0 + C R_0 + C P_0 \\alpha_0)$ is the coefficient of $p$ in \
             Eq.~13: the paper's Eq.~13 prints $-(m_q \\beta_0 - C R_0 - C P_0 \\alpha_0)p$, \
             while its Eqs.~17 and 28 use the derived sign. The factor $g_2$ contains $n_p$, \
             omitted in the paper's Eqs.~14, 19--20 and 30--31.\n\n",
        );
        out.push_str(
            "Multiplied by $d$, each entry is a polynomial (matrix determinant lemma: \
             $d\\det K = d \\det K_0 - h^T \\operatorname{adj}(K_0)\\, g$):\n\\begin{align*}\n",
        );
        let p0: &[Sym] = &[s.p0];
        let mut rows = Vec::new();
        for i in 0..2 {
            for j in 0..2 {
                rows.push(self.rows(
                    &format!("d K_{{{}{}}}", i + 1, j + 1),
                    &self.grouped(&d.k_times_d[i][j], &[trims, p0]),
                    None,
                ));
            }
        }
        out.push_str(&rows.join(" \\\\\n"));
        out.push_str("\n\\end{align*}\n");
        out.push_str("and, grouped by the trim symbols and powers of $P_0$,\n\\begin{align*}\n");
        out.push_str(&self.rows(
            "d \\det K",
            &self.grouped(&d.d_det_k, &[trims, p0]),
            Some("27"),
        ));
        out.push_str("\n\\end{align*}\n\n");
    }

    pub(super) fn identity_section(&self, out: &mut String, d: &Derivation) {
        out.push_str("\\section{The identity $\\det J_5 = d \\det K$}\n\n");
        let verdict = if d.identity_residual.is_zero() {
            format!(
                "The determinant of the $5\\times 5$ Jacobian $J_5$ of the PSS model at the trim \
                 was expanded symbolically ({} terms in the trim symbols and parameters) and \
                 compared with $d \\det K$ of Eq.~27: the difference $\\det J_5 - d\\det K$ is \
                 identically zero (\\texttt{{identity\\_residual}} has no terms): the identity \
                 $\\det J_5 = d \\det K$ is verified symbolically, for all parameter values. \
                 Hence $\\det K$ vanishes exactly where $\\det J_5$ does (a real eigenvalue \
                 of $J_5$ crosses zero: a saddle-node of the PSS solutions), except at zeros of \
                 $d$, where $\\det K$ has poles.",
                d.det_j5.len()
            )
        } else {
            format!(
                "WARNING: $\\det J_5 - d\\det K$ is not zero ({} terms): the derivation is \
                 inconsistent.",
                d.identity_residual.len()
            )
        };
        let _ = writeln!(out, "{verdict}\n");
    }
}
