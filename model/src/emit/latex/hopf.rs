//! The LaTeX section of the Hopf criterion (beyond the paper): the characteristic polynomial of J5,
//! Orlando's formula for the fourth Hurwitz determinant and the omega^2 expression, each typeset
//! from [`crate::derivation::hopf`].

use super::Writer;
use crate::derivation::hopf::{characteristic_coefficients, hopf_symbols, orlando};
use crate::derivation::Derivation;
use std::fmt::Write;

impl Writer<'_> {
    pub(super) fn hopf_section(&self, out: &mut String, d: &Derivation) {
        let h = hopf_symbols();
        let mut order = self.order.clone();
        order.extend(h.c);
        order.push(h.w);
        let w = Writer { s: self.s, order };
        let c = characteristic_coefficients(&d.jacobian);
        let o = orlando();
        out.push_str("\\section{Beyond the paper: the Hopf criterion}\n\n");
        let _ = write!(
            out,
            "A trim also loses stability when a complex pair of eigenvalues of $J_5$ crosses the \
             imaginary axis (a Hopf bifurcation: a growing oscillation). The characteristic \
             polynomial of $J_5$ at the trim was expanded symbolically,\n\
             \\begin{{equation*}}\n\\det(s I - J_5) = s^5 + c1\\, s^4 + c2\\, s^3 + c3\\, s^2 + \
             c4\\, s + c5,\n\\end{{equation*}}\n\
             with $c_k$ a polynomial of degree at most $k$ in the trim states ({}, {}, {}, {} and \
             {} terms); $c5 = -\\det J_5$ is the jump criterion, and\n\\begin{{align*}}\n{}\n\
             \\end{{align*}}\n",
            c[0].len(),
            c[1].len(),
            c[2].len(),
            c[3].len(),
            c[4].len(),
            w.rows("c1", &w.grouped(&c[0], &[]), None)
        );
        let _ = write!(
            out,
            "\\textbf{{Orlando's formula.}} The fourth Hurwitz determinant\n\
             \\begin{{equation*}}\n\\Delta_4 = \\det\\begin{{pmatrix}} c1 & c3 & c5 & 0 \\\\ 1 & \
             c2 & c4 & 0 \\\\ 0 & c1 & c3 & c5 \\\\ 0 & 1 & c2 & c4 \\end{{pmatrix}} = \
             \\pm\\prod_{{i<j}} (\\lambda_i + \\lambda_j)\n\\end{{equation*}}\n\
             vanishes exactly where two eigenvalues sum to zero: a pair $\\pm i\\omega$ (Hopf) or \
             $\\pm\\lambda$ (a neutral saddle). Expanded,\n\\begin{{align*}}\n{}\n\
             \\end{{align*}}\n\
             Every term has weight 10 ($c_k$ counting $k$), so with $C_k = \\det(A)^k\\, c_k$ at \
             the trim of Eqs.~3--4 the Hopf polynomial is $\\det(A)^{{10}} \\Delta_4 = \
             \\Delta_4(C_1, \\dots, C_5)$, a polynomial in $P_0$ (and $\\delta_a$ with aileron yaw, \
             which is eliminated against the trim condition by the same resultant as the jump \
             polynomial); for the zero-sideslip trims $\\det(A_1)$ takes the place of $\\det A$.\n\n",
            w.rows("\\Delta_4", &w.grouped(&o.delta4, &[]), None)
        );
        let verdict = if o.identity_residual.is_zero() {
            "The resultant in $w$ of the two parts equals $\\Delta_4$ identically (checked \
             symbolically)."
        } else {
            "WARNING: the resultant of the two parts differs from $\\Delta_4$."
        };
        let _ = write!(
            out,
            "\\textbf{{The frequency.}} With $s = i\\omega$ and $w = \\omega^2$, $p(i\\omega) = 0$ \
             splits into\n\\begin{{align*}}\n{} \\\\\n{}\n\\end{{align*}}\n{verdict} Eliminating \
             $w^2$ (the even part minus $c1$ times the odd part) leaves a linear equation:\n\
             \\begin{{equation*}}\n\\omega^2 = {}.\n\\end{{equation*}}\n\
             A root of the Hopf polynomial is a Hopf point when $\\omega^2 > 0$ and a neutral \
             saddle when $\\omega^2 < 0$.\n\n",
            w.rows("", &w.grouped(&o.even, &[]), None),
            w.rows("", &w.grouped(&o.odd, &[]), None),
            w.frac(&o.omega_sq, &[])
        );
    }
}
