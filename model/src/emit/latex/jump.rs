//! The sections of the jump polynomial: det J5 with the trim substituted by step 8 of the
//! derivation, and with aileron yaw the trim condition and the jump polynomial with the aileron
//! eliminated by a resultant.

use super::typeset::{Term, Writer};
use crate::algebra::{Poly, Sym};
use crate::derivation::Derivation;
use std::fmt::Write;

impl Writer<'_> {
    pub(super) fn jump_section(&self, out: &mut String, d: &Derivation) {
        let s = self.s;
        let trims = self.trims4();
        let p0: &[Sym] = &[s.p0];
        out.push_str("\\section{The jump polynomial}\n\n");
        out.push_str(
            "Substituting the trim $x_0 = N/\\det A$ of Eq.~4 into $\\det J_5 = d \\det K$ and \
             clearing the denominator gives a polynomial in $P_0$ whose real roots are the jump \
             points (saddle-node bifurcations), except where they are cancelled by zeros of \
             $d$ or $\\det A$:\n\\begin{align*}\n\
             J(P_0) = (\\det A)^2 \\det J_5\\big|_{x = x_0} \
             = \\sum_m c_m\\, N^m (\\det A)^{2 - |m|}, \\qquad \
             \\det K = \\frac{J(P_0)}{(\\det A)^2\\, d|_{x=x_0}}\n\\end{align*}\n\
             where $m$ runs over the monomials of $\\det J_5$ in $(\\alpha_0, \\beta_0, Q_0, \
             R_0)$ (degree at most 2), $N^m$ is the same monomial in \
             $(N_\\alpha, N_\\beta, N_Q, N_R)$, and the coefficients $c_m$ are polynomials in \
             the parameters and $P_0$:\n\\begin{align*}\n",
        );
        let groups = self.split(&d.det_j5, &trims);
        let tr_names: Vec<(Sym, &str)> = vec![
            (s.alpha0, "N_\\alpha"),
            (s.beta0, "N_\\beta"),
            (s.q0, "N_Q"),
            (s.r0, "N_R"),
        ];
        let mut rows = Vec::new();
        let mut sum_terms = Vec::new();
        for (m, c) in &groups {
            let sub = if m.is_one() {
                "1".to_string()
            } else {
                self.mono(m)
            };
            let name = format!("c_{{{sub}}}");
            rows.push(self.rows(&name, &self.grouped(c, &[p0]), None));
            let deg = m.total_degree();
            let mut factors: Vec<String> = Vec::new();
            for (x, nm) in &tr_names {
                match m.exp(*x) {
                    0 => {}
                    1 => factors.push(nm.to_string()),
                    e => factors.push(format!("{nm}^{{{e}}}")),
                }
            }
            match 2 - deg {
                0 => {}
                1 => factors.push("\\det A".into()),
                k => factors.push(format!("(\\det A)^{{{k}}}")),
            }
            sum_terms.push(Term::Atom {
                neg: false,
                body: format!("{name} {}", factors.join(" ")),
            });
        }
        out.push_str(&rows.join(" \\\\\n"));
        out.push_str("\n\\end{align*}\n");
        out.push_str(
            "with $N_\\alpha, N_\\beta, N_Q, N_R$ and $\\det A$ from Section~2. Written out,\n\
             \\begin{align*}\n",
        );
        out.push_str(&self.rows("J(P_0)", &sum_terms, None));
        out.push_str("\n\\end{align*}\n");
        self.jump_expansion(out, d, &tr_names);
    }

    pub(super) fn aileron_yaw_section(&self, out: &mut String, d: &Derivation) {
        let s = self.s;
        let p0: &[Sym] = &[s.p0];
        out.push_str(
            "\\section{Aileron yaw: the trim condition and the eliminated jump polynomial}\n\n",
        );
        out.push_str(
            "With aileron yaw ($n_{\\delta a} \\ne 0$) the aileron enters the yaw equation, so \
             the trim of Eq.~4 is affine in $\\delta_a$, $N = N^0 + \\delta_a N^a$, with\n\
             \\begin{align*}\n",
        );
        let names = ["N^a_\\alpha", "N^a_\\beta", "N^a_Q", "N^a_R"];
        let rows: Vec<String> = d
            .trim
            .iter()
            .zip(names)
            .map(|(n, l)| self.rows(l, &self.grouped(&n.coeff(s.delta_a, 1), &[p0]), None))
            .collect();
        out.push_str(&rows.join(" \\\\\n"));
        out.push_str("\n\\end{align*}\n");
        out.push_str(
            "($N^0$ is $N$ of Section~2 at $\\delta_a = 0$). The roll equation at the trim, \
             cleared of $\\det A$, is the \\emph{trim condition}, a quadratic in $\\delta_a$ \
             (through $-E Q_0 R_0$) whose zero set is the equilibrium curve; a roll rate has \
             0, 1 or 2 trims:\n\\begin{align*}\n\
             G(P_0, \\delta_a) = (\\det A)^2\\, \\dot p\\big|_{x = x_0} = g_2 \\delta_a^2 + g_1 \\delta_a + g_0\n\
             \\end{align*}\nwith, from the roll equation $\\dot p = ",
        );
        out.push_str(&self.inline(&self.grouped(&d.roll_at_trim, &[])));
        out.push_str("$ in the trim symbols,\n\\begin{align*}\n");
        let rows = self.trim_condition_rows(d);
        out.push_str(&rows.join(" \\\\\n"));
        out.push_str("\n\\end{align*}\n");
        let nda = s.param(crate::aircraft::Param::NDeltaA);
        let g2_ok = d
            .trim_condition()
            .coeff(s.delta_a, 2)
            .div_var_pow(nda, 2)
            .is_some();
        let _ = writeln!(
            out,
            "so $g_2$ carries $n_{{\\delta a}}^2$ ({}) and without aileron yaw $G$ is linear \
             with $g_1 = l_{{\\delta a}} (\\det A)^2$: the trim of Section~2.\n",
            if g2_ok {
                "checked on the expansion"
            } else {
                "NOT confirmed by the expansion"
            }
        );
        out.push_str(
            "Jump points are the trims on the curve where $\\det J_5$ vanishes; on $G = 0$, \
             $\\det J_5 = (\\partial G / \\partial P_0) / \\det A$ (the Schur complement of \
             $A$ in $J_5$), so they are where the curve turns in $\\delta_a$. With $F(P_0, \\delta_a) = (\\det A)^2 \\det J_5|_{x = x_0} = f_2 \
             \\delta_a^2 + f_1 \\delta_a + f_0$ (the $J$ of Section~8 with $N = N^0 + \\delta_a \
             N^a$), the aileron is eliminated by the resultant\n\\begin{align*}\n\
             \\operatorname{Res}_{\\delta_a}(G, F) = (g_2 f_0 - g_0 f_2)^2 - (g_2 f_1 - g_1 f_2)\
             (g_1 f_0 - g_0 f_1),\n\\end{align*}\n\
             the determinant of the Sylvester matrix, which vanishes exactly where $G$ and $F$ \
             share a root $\\delta_a$ for the given $P_0$. As $g_2$ and $f_2$ carry \
             $n_{\\delta a}^2$ and $f_1$ carries $n_{\\delta a}$, the resultant carries \
             $n_{\\delta a}^2$; the jump polynomial is $J_{ya}(P_0) = \
             \\operatorname{Res}_{\\delta_a}(G, F) / n_{\\delta a}^2$, continuous in \
             $n_{\\delta a}$, and at $n_{\\delta a} = 0$\n\\begin{align*}\n\
             J_{ya}\\big|_{n_{\\delta a} = 0} = g_1^2\\, e\\, J(P_0), \\qquad \
             g_1 = l_{\\delta a} (\\det A)^2, \\quad e = \\lim f_2 / n_{\\delta a}^2,\n\
             \\end{align*}\n\
             where $e$ belongs to the second trim branch, which leaves to infinite aileron as \
             $n_{\\delta a} \\to 0$: so $J_{ya}$ has the paper's jump roots plus roots whose \
             trims are at infinity, never reported (\\texttt{tests/tests/aileron\\_yaw.rs} checks \
             this identity exactly). For an aircraft's data the Sylvester matrix is built on the \
             actual degrees in $\\delta_a$, which gives $J$ itself when $n_{\\delta a} = 0$. At \
             each root the common $\\delta_a$ gives the trim. The poles of $\\det K$ on the \
             curve follow in the same way from $(\\det A)^2 d|_{x = x_0}$ in place of $F$.\n\n",
        );
    }

    /// The jump polynomial expanded in P0 without aileron yaw, and the denominator
    /// `(det A)^2 d` on the trim with its compact form checked; `tr_names` names the trim
    /// numerators.
    fn jump_expansion(&self, out: &mut String, d: &Derivation, tr_names: &[(Sym, &str)]) {
        let s = self.s;
        let ctrl: &[Sym] = &[s.delta_e, s.delta_r];
        let inertia: &[Sym] = &self.inertia();
        // The paper's aircraft have no aileron yaw: the jump polynomial in P0 alone is det J5
        // det(A)^2 at n_delta_a = 0 (Section 9 gives the elimination of delta_a otherwise).
        let nda = s.param(crate::aircraft::Param::NDeltaA);
        let jump = d.jump_at().subs(nda, &Poly::zero());
        let d_det_a = d.d_at().subs(nda, &Poly::zero());
        let coeffs = jump.coeffs(s.p0);
        let _ = write!(
            out,
            "Expanded, $J(P_0) = \\sum_{{k=0}}^{{{}}} J_k P_0^k$ has {} terms. Its coefficients, \
             grouped by the controls and the inertia coefficients:\n\\begin{{align*}}\n",
            coeffs.len().saturating_sub(1),
            jump.len()
        );
        out.push_str(&self.coefficient_rows("J", &coeffs, &[ctrl, inertia]));
        out.push_str("\n\\end{align*}\n");
        let d_sub = |x: Sym| -> String {
            tr_names
                .iter()
                .find(|(t, _)| *t == x)
                .map(|(_, n)| n.to_string())
                .unwrap_or_default()
        };
        let _ = write!(
            out,
            "The denominator $(\\det A)^2 d|_{{x=x_0}} = l_p (\\det A)^2 + l_r ({} + \\alpha_t \\det A) \
             \\det A - E\\,{} ({} + \\alpha_t \\det A) - E\\,{} {}$ vanishes at the poles of \
             $\\det K$; expanded it has {} terms:\n\\begin{{align*}}\n",
            d_sub(s.alpha0),
            d_sub(s.q0),
            d_sub(s.alpha0),
            d_sub(s.beta0),
            d_sub(s.r0),
            d_det_a.len()
        );
        out.push_str(&self.coefficient_rows("D", &d_det_a.coeffs(s.p0), &[ctrl, inertia]));
        out.push_str("\n\\end{align*}\n");
        let check_d = {
            let n: Vec<Poly> = d.trim.iter().map(|t| t.subs(nda, &Poly::zero())).collect();
            use crate::aircraft::Param;
            let da = &d.det_a;
            let k = |p: Param| Poly::var(s.param(p));
            // The principal axis' angle of attack at the trim, over det A: alpha0 + alpha_t.
            let alpha = &n[0] + &(&k(Param::AlphaT) * da);
            let recon = &(&(&k(Param::Lp) * &(da * da)) + &(&(&k(Param::Lr) * &alpha) * da))
                - &(&k(Param::E) * &(&(&alpha * &n[2]) + &(&n[1] * &n[3])));
            recon == d_det_a
        };
        let _ = writeln!(
            out,
            "with $(\\det A)^2 d|_{{x=x_0}} = \\sum_k D_k P_0^k$ (the compact form above {}).\n",
            if check_d {
                "was checked against the expansion"
            } else {
                "does NOT match the expansion"
            }
        );
    }

    /// The rows `g_k = ...` of the trim condition `G = g2 delta_a^2 + g1 delta_a + g0`: each
    /// monomial `c_m t^m` of the roll equation (degree `|m| <= 2` in the trim symbols)
    /// contributes `c_m (N^0 + delta_a N^a)^m (det A)^(2 - |m|)`, collected by powers of delta_a.
    fn trim_condition_rows(&self, d: &Derivation) -> Vec<String> {
        let s = self.s;
        let trims = self.trims4();
        let groups = self.split(&d.roll_at_trim, &trims);
        let sym_name = |x: Sym| match x {
            x if x == s.alpha0 => "\\alpha",
            x if x == s.beta0 => "\\beta",
            x if x == s.q0 => "Q",
            _ => "R",
        };
        let mut by_power: [Vec<String>; 3] = Default::default();
        for (m, c) in &groups {
            let factors: Vec<Sym> = trims
                .iter()
                .flat_map(|x| std::iter::repeat_n(*x, m.exp(*x) as usize))
                .collect();
            let deg = factors.len();
            let den = match 2 - deg {
                0 => String::new(),
                1 => " \\det A".into(),
                k => format!(" (\\det A)^{{{k}}}"),
            };
            // delta_a explicit in c (l_delta_a delta_a) shifts the power by one.
            for (k_c, c_k) in c.coeffs(s.delta_a).iter().enumerate() {
                if c_k.is_zero() {
                    continue;
                }
                let coef = format!("\\bigl({}\\bigr)", self.inline(&self.grouped(c_k, &[])));
                // Choose for each factor N^0 or N^a: the count of N^a is the power of delta_a.
                for pick in 0..(1usize << deg) {
                    let k = k_c + pick.count_ones() as usize;
                    if k > 2 {
                        continue;
                    }
                    let ns: Vec<String> = factors
                        .iter()
                        .enumerate()
                        .map(|(i, x)| {
                            let sup = if pick >> i & 1 == 1 { "a" } else { "0" };
                            format!(" N^{sup}_{}", sym_name(*x))
                        })
                        .collect();
                    by_power[k].push(format!("{coef}{}{den}", ns.concat()));
                }
            }
        }
        by_power
            .iter()
            .enumerate()
            .map(|(k, terms)| {
                let body = if terms.is_empty() {
                    "0".to_string()
                } else {
                    terms.join(" + ")
                };
                format!("g_{k} &= {body}")
            })
            .collect()
    }
}
