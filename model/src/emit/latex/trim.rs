//! The document's first sections: the PSS model of Appendix A.2 as the derivation has it, and
//! its pseudo-steady states (Eqs 1-5): the trim by Cramer's rule, det A and the divergence
//! biquadratic of Eq. 5, each compared with the paper's printed form.

use super::typeset::{Writer, STATE_RATES};
use crate::algebra::{Matrix, Poly, Sym};
use crate::derivation::Derivation;
use crate::emit::paper::{self as printed, parse};
use std::fmt::Write;

impl Writer<'_> {
    pub(super) fn model_section(&self, out: &mut String, d: &Derivation) {
        let s = self.s;
        out.push_str("\\section{The PSS model (Appendix A.2)}\n\n");
        out.push_str(
            "The right-hand sides of $\\frac{d}{dt}(\\alpha, \\beta, p, q, r)$. The inertia \
             couplings follow from Euler's equations in principal axes, $C = (I_z - I_x)/I_y$, \
             $D = (I_y - I_x)/I_z$, $E = (I_z - I_y)/I_x$; the paper's stray parenthesis after \
             $l_{\\delta a}$ is dropped. For the unconstrained roll (Sections 2--8) the derivation \
             sets $n_{\\delta a} = 0$, as for both aircraft of Table A.1: otherwise the trim is \
             not linear in $(\\alpha, \\beta, q, r)$ for given $P_0$.\n\n\
             Beyond Appendix A.2 the model is linearized about the aircraft's trimmed flight at \
             a load factor $n$: $\\alpha$, $\\beta$ and the controls are increments from that \
             trim, $z_0 = Z_0/(mV) = -n g/V$ is its lift, which keeps acting in body axes while \
             the aircraft rolls, and $\\alpha_t$ is the angle of attack of the principal axis \
             there, which the roll about that axis turns into sideslip ($\\dot\\beta = p \
             \\sin(\\alpha_t + \\alpha) - r \\cos(\\alpha_t + \\alpha)$ linearized as the \
             paper does). The paper's aircraft have $z_0 = \\alpha_t = 0$ (angles measured from \
             zero lift, the principal axis on the flight path), and every comparison with the \
             paper's print below is made in that case. For an imported aircraft (\\texttt{model \
             import jsbsim}) $z_0$ and $\\alpha_t$ come from its trim, the principal axis lying \
             the product-of-inertia tilt below the body axis.\n",
        );
        let lhs = STATE_RATES;
        let mut vars = vec![s.alpha, s.beta, s.p, s.q, s.r];
        vars.extend([s.delta_a, s.delta_e, s.delta_r]);
        out.push_str("\\begin{align*}\n");
        let rows: Vec<String> = d
            .model
            .iter()
            .zip(lhs)
            .map(|(f, l)| self.rows(l, &self.grouped(f, &[&vars]), None))
            .collect();
        out.push_str(&rows.join(" \\\\\n"));
        out.push_str(" \\tag{A.2}\n\\end{align*}\n\n");
    }

    pub(super) fn trim_section(&self, out: &mut String, d: &Derivation) {
        let s = self.s;
        out.push_str("\\section{Pseudo-steady states (Eqs.~1--5)}\n\n");
        out.push_str(
            "Leaving aside the roll equation, the PSS equations at $p = P_0$ are linear in \
             $x = [\\alpha, \\beta, q, r]^T$, with $u = [\\delta_e, \\delta_r, \\delta_a]^T$ \
             (the paper has $u = [\\delta_e, \\delta_r]^T$: its aircraft have no aileron yaw, \
             $n_{\\delta a} = 0$, and the aileron then enters the roll equation only):\n\
             \\begin{align*}\n\\dot x &= A x + b u + b_1 P_0 \\tag{1}\n\\end{align*}\n",
        );
        let split = |v: &[Poly], x: Sym| -> Vec<Poly> { v.iter().map(|p| p.coeff(x, 1)).collect() };
        let b = Matrix::from_rows(
            split(&d.a_rhs, s.delta_e)
                .into_iter()
                .zip(split(&d.a_rhs, s.delta_r))
                .zip(split(&d.a_rhs, s.delta_a))
                .map(|((e, r), a)| vec![e, r, a])
                .collect(),
        );
        let b1 = split(&d.a_rhs, s.p0);
        let _ = write!(
            out,
            "\\begin{{align*}}\nA &= {}, \\qquad b = {}, \\qquad b_1 = {} \\tag{{2}}\n\\end{{align*}}\n",
            self.matrix(&d.a),
            self.matrix(&b),
            self.column(&b1)
        );
        let printed_a = Matrix::from_rows(
            printed::EQ2_A
                .iter()
                .map(|r| r.iter().map(|e| parse(e)).collect())
                .collect(),
        );
        let a_ok = printed_a == d.a;
        // The paper's print is the n_delta_a = 0 case.
        let nda = s.param(crate::aircraft::Param::NDeltaA);
        let rhs_ok = printed::EQ2_RHS
            .iter()
            .zip(&d.a_rhs)
            .all(|(p, q)| parse(p) == self.paper_case(&q.subs(nda, &Poly::zero())));
        let _ = writeln!(
            out,
            "Eq.~2: $A$ {}; $b$ and $b_1$ (that is, $b u + b_1 P_0$) at $n_{{\\delta a}} = 0$ {}.\n",
            if a_ok {
                "agrees with the paper's print"
            } else {
                "differs from the paper's print"
            },
            if rhs_ok {
                "agrees with it"
            } else {
                "differs from it"
            },
        );
        self.trim_solution(out, d);
    }

    /// The trim by Cramer's rule (Eqs 3-4) with its numerators grouped by the controls, det A
    /// and its biquadratic coefficients (Eq. 5), and the aileron that holds the trim.
    fn trim_solution(&self, out: &mut String, d: &Derivation) {
        let s = self.s;
        let p0: &[Sym] = &[s.p0];
        let ctrl: &[Sym] = &[s.delta_e, s.delta_r];
        out.push_str(
            "Setting $\\dot x = 0$ gives the trim $x_0 = [\\alpha_0, \\beta_0, Q_0, R_0]^T$:\n\
             \\begin{align*}\nx_0 &= -A^{-1}\\bigl[b u + b_1 P_0\\bigr] \\tag{3} \\\\\n\
             &= -\\frac{\\operatorname{adj}[A]}{\\det[A]}\\bigl[b u + b_1 P_0\\bigr] \
             = \\frac{1}{\\det A}\\begin{pmatrix} N_\\alpha \\\\ N_\\beta \\\\ N_Q \\\\ N_R \
             \\end{pmatrix} \\tag{4}\n\\end{align*}\n\
             with the trim numerators $N = -\\operatorname{adj}(A)(b u + b_1 P_0)$, grouped by \
             the controls:\n\\begin{align*}\n",
        );
        let names = ["N_\\alpha", "N_\\beta", "N_Q", "N_R"];
        let rows: Vec<String> = d
            .trim
            .iter()
            .zip(names)
            .map(|(n, l)| self.rows(l, &self.grouped(n, &[ctrl, p0]), None))
            .collect();
        out.push_str(&rows.join(" \\\\\n"));
        out.push_str("\n\\end{align*}\n");
        out.push_str(
            "The common denominator is a biquadratic in $P_0$ (odd powers vanish identically); \
             its roots are the critical roll rates of pitch-yaw divergence:\n\\begin{align*}\n",
        );
        let det_terms = self.grouped(&d.det_a, &[p0]);
        out.push_str(&self.rows("\\det A", &det_terms, Some("5")));
        out.push_str(" \\\\\n");
        let coef_names = ["a_0", "a_2", "a_4"];
        let rows: Vec<String> = d
            .biquadratic
            .iter()
            .zip(coef_names)
            .map(|(c, l)| self.rows(l, &self.grouped(c, &[]), None))
            .collect();
        out.push_str(&rows.join(" \\\\\n"));
        out.push_str("\n\\end{align*}\n");
        let _ = writeln!(
            out,
            "with $\\det A = a_4 P_0^{{4}} + a_2 P_0^{{2}} + a_0$. {}\n",
            self.eq5_check(&d.det_a)
        );
        let _ = write!(
            out,
            "The aileron deflection that holds a trim follows from the roll equation:\n\
             \\begin{{align*}}\n\\delta_a &= {}\n\\end{{align*}}\n\n",
            self.frac(&d.delta_a, &[])
        );
    }

    pub(super) fn eq5_check(&self, det_a: &Poly) -> String {
        let cd = parse(printed::EQ5_TIMES_CD);
        if *det_a == cd {
            "Dividing by $a_4 = C D$ and writing $m'_\\alpha = m_\\alpha/C$, $m'_q = m_q/C$, \
             $n'_\\beta = n_\\beta/(-D)$, $n'_r = n_r/(-D)$ gives the paper's monic Eq.~5 \
             exactly (checked)."
                .into()
        } else if *det_a == -&cd {
            "Dividing by $-a_4$ and writing the paper's primed quantities gives its monic \
             Eq.~5 exactly (checked)."
                .into()
        } else {
            format!(
                "The paper's Eq.~5 times $CD$ differs: derived minus printed is ${}$.",
                self.inline(&self.grouped(&(det_a - &cd), &[&[self.s.p0]]))
            )
        }
    }
}
