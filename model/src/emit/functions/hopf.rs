//! The generated functions of the Hopf criterion (issue 10): the characteristic coefficients of
//! J5 at the trim, the fourth Hurwitz determinant and omega^2, all derived in
//! [`crate::derivation::hopf`] and emitted through the same DAG as the jump criterion.
//!
//! The Hopf polynomial in P0 is not emitted. Fully parametric it is far too large to be useful:
//! Delta4 of the parametric `c_k` has 61 600 terms in the trim symbols (`cargo bench -p model
//! --bench hopf`), and with the trim substituted the cleared `C_k = det(A)^k c_k` have 45, 782,
//! 6151, 18 330 and 14 778 terms, whose products in Delta4 exhaust memory (`cargo run --release
//! -p model --example hopf_parametric_size full` requests a 1.1 TB allocation). Per aircraft
//! `model analyze` builds it exactly (degree 32 in P0 for A and B); the functions here give
//! `Delta4` and `omega^2` at any trim instead, from which the Hopf points follow by a scalar root
//! search in P0.

use super::{with_formulas, Ctx, Formula, Function, Ret, DE, DR, P0};
use crate::derivation::hopf::{characteristic_coefficients, hopf_symbols, orlando};
use crate::derivation::Derivation;

/// The Hopf functions for a derivation (parametric when `t`).
pub(super) fn functions(d: &Derivation, t: bool) -> Vec<Function> {
    let args = vec![P0, DE, DR];
    let coeffs = characteristic_coefficients(&d.jacobian);
    let h = hopf_symbols();
    let o = orlando();
    // The documented c1, c2: the parametric derivation's.
    let par_coeffs = crate::specialise::parametric_characteristic();
    let at_trim = |c: &mut Ctx| {
        c.trim(d);
        let ids: Vec<_> = coeffs.iter().map(|p| c.poly(p)).collect();
        for (s, id) in h.c.iter().zip(&ids) {
            c.bind(*s, *id);
        }
        ids
    };
    let mut out = Vec::new();
    {
        let mut c = Ctx::new(t, &args);
        let ids = at_trim(&mut c);
        out.push(c.finish(
            "characteristic_coefficients",
            with_formulas(
                &[
                    "Coefficients [c1, c2, c3, c4, c5] of the characteristic polynomial of J5 at the trim",
                    "of `p0`, `det(s I - J5) = s^5 + c1 s^4 + c2 s^3 + c3 s^2 + c4 s + c5` (c_k in 1/s^k);",
                    "`c5 = -det J5`, the jump criterion. Beyond the paper (issue 10). c1 and c2 below (c3",
                    "to c5 follow from the same `det(s I - J5)`, with J5 as in [`jacobian5`]).",
                ],
                &[
                    ("c1", Formula::Poly(&par_coeffs[0])),
                    ("c2", Formula::Poly(&par_coeffs[1])),
                ],
            ),
            t,
            args.clone(),
            ids.into_iter().map(|id| (String::new(), id)).collect(),
            Ret::Array(5),
        ));
    }
    {
        let mut c = Ctx::new(t, &args);
        at_trim(&mut c);
        let delta4 = c.poly(&o.delta4);
        out.push(c.finish(
            "hurwitz_delta4",
            with_formulas(
                &[
                    "The fourth Hurwitz determinant of J5 at the trim of `p0`,",
                    "`Delta4 = det [[c1, c3, c5, 0], [1, c2, c4, 0], [0, c1, c3, c5], [0, 1, c2, c4]]`",
                    "(expanded below) in the coefficients of [`characteristic_coefficients`], 1/s^10. By",
                    "Orlando's formula it is, up to sign, the product of `l_i + l_j` over the ten",
                    "eigenvalue pairs: zero at a Hopf point (pair `+-i omega`) or a neutral saddle",
                    "(`+-lambda`).",
                ],
                &[("Delta4", Formula::Poly(&o.delta4))],
            ),
            t,
            args.clone(),
            vec![(String::new(), delta4)],
            Ret::Scalar,
        ));
    }
    {
        let mut c = Ctx::new(t, &args);
        at_trim(&mut c);
        let num = c.poly(&o.omega_sq.num);
        let den = c.poly(&o.omega_sq.den);
        let w = c.dag.div(num, den);
        out.push(c.finish(
            "hopf_omega_squared",
            with_formulas(
                &[
                    "`omega^2` at the trim of `p0`, rad^2/s^2, in the coefficients of",
                    "[`characteristic_coefficients`]: at a zero of [`hurwitz_delta4`] the square of the",
                    "frequency of the pair on the imaginary axis, positive at a Hopf point and negative",
                    "at a neutral saddle (from the even and odd parts of `p(i omega) = 0` with `w^2`",
                    "eliminated).",
                ],
                &[("omega^2", Formula::Ratio(&o.omega_sq))],
            ),
            t,
            args,
            vec![(String::new(), w)],
            Ret::Scalar,
        ));
    }
    out
}
