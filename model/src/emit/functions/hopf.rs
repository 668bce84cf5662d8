//! The generated functions of the Hopf criterion (beyond the paper): the characteristic
//! coefficients of J5 at the trim, the fourth Hurwitz determinant and omega^2, all derived in
//! [`crate::derivation::hopf`] and emitted through the same DAG as the jump criterion.
//!
//! The parametric Hopf polynomial in P0 is not emitted. Fully parametric it is far too large:
//! Delta4 of the parametric `c_k` has 61 600 terms in the trim symbols (`cargo bench -p model
//! --bench hopf`), and with the trim substituted the cleared `C_k = det(A)^k c_k` have 45, 782,
//! 6151, 18 330 and 14 778 terms, whose products in Delta4 exhaust memory (`cargo run --release
//! -p model --example hopf_parametric_size full` requests a 1.1 TB allocation). The functions
//! here give `Delta4` and `omega^2` at any trim instead, from which the Hopf points follow by a
//! scalar root search in P0; per aircraft, [`polynomial`] emits the exact Hopf polynomial
//! (degree 48 in P0 and 6 in delta_e for A and B) with the data folded in.

use super::{finish, lines, with_formulas, Formula, Function, Ret};
use crate::aircraft::Aircraft;
use crate::algebra::Poly;
use crate::algebra::Q;
use crate::derivation::hopf::{characteristic_coefficients, hopf_symbols, orlando};
use crate::derivation::Derivation;
use crate::equations::symbols;
use crate::program::builder::{Ctx, DE, DR, P0};
use crate::specialise::hopf::hopf_polynomial;

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
        out.push(finish(c,
            "characteristic_coefficients",
            with_formulas(
                &[
                    "Coefficients [c1, c2, c3, c4, c5] of the characteristic polynomial of J5 at the trim",
                    "of `p0`, `det(s I - J5) = s^5 + c1 s^4 + c2 s^3 + c3 s^2 + c4 s + c5` (c_k in 1/s^k);",
                    "`c5 = -det J5`, the jump criterion. Beyond the paper (the Hopf criterion). c1 and c2",
                    "below (c3 to c5 follow from the same `det(s I - J5)`, with J5 as in [`jacobian5`]).",
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
        out.push(finish(c,
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
        out.push(finish(c,
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

/// `hopf_polynomial(p0, delta_e, delta_r)` of one aircraft (data folded in): the exact Hopf
/// polynomial `det(A)^10 Delta4` at the trim, built as the derivation builds it
/// ([`crate::derivation::hopf`], step 3): the trim numerators N and det A by Cramer's rule
/// (Eqs 3-4), the cleared characteristic coefficients `C_k = det(A)^k c_k(N / det A)` as
/// polynomials in N and det A (no division), and Orlando's Delta4 of `C_1..C_5`. The expanded
/// polynomial in P0 is the same polynomial, but its monomial coefficients cancel so badly near
/// the Hopf points (the sum of `|a_i P0^i|` exceeds the value by 1e21 at B's first one) that
/// doubles cannot even represent it there; the cleared coefficients in P0 alone are no better
/// near det A's roots (1e11), the structured form has only Delta4's own cancellation. With
/// aileron yaw no polynomial in P0 and the controls alone exists: NaN, as `jump_polynomial`.
pub(crate) fn polynomial(aircraft: &Aircraft, d: &Derivation) -> Function {
    let s = symbols();
    let args = vec![P0, DE, DR];
    let mut c = Ctx::new(false, &args);
    let mut doc = lines(&[
        "The Hopf polynomial `det(A)^10 Delta4` (beyond the paper) of this aircraft at the trim of",
        "`p0` (1/s^10 times det A's units to the tenth): det A (Eq. 4) to the tenth times",
        "[`hurwitz_delta4`], so its sign is that of Delta4 wherever det A != 0. Its real roots",
        "are the Hopf points (where [`hopf_omega_squared`] > 0), the neutral saddles (omega^2 < 0)",
        "and the roots of det A (the divergence roll rates).",
        "",
    ]);
    let value = match hopf_polynomial(aircraft) {
        Some(h) => {
            let rhs0: Vec<Poly> = d.a_rhs.iter().map(|p| p.coeff(s.delta_a, 0)).collect();
            let (num, det) = c.cramer_numerators(&d.a, &rhs0);
            let t4 = [s.alpha0, s.beta0, s.q0, s.r0];
            let ck = characteristic_coefficients(&d.jacobian);
            let hs = hopf_symbols();
            for (k, ck) in ck.iter().enumerate() {
                let cleared = c.cleared(ck, &t4, &num, det, k as u32 + 1);
                c.bind(hs.c[k], cleared);
            }
            let (dp, de, terms) = (h.degree(s.p0), h.degree(s.delta_e), h.len());
            doc.extend([
                format!("At delta_r = 0 a polynomial of degree {dp} in P0 and {de} in delta_e ({terms} terms,"),
                "`model::specialise::hopf::hopf_polynomial`), evaluated here as the derivation builds".into(),
                "it: the trim numerators N and det A by Cramer's rule, the cleared characteristic".into(),
                "coefficients `C_k = det(A)^k c_k(N / det A)` as polynomials in N and det A (exact folded".into(),
                "constants, no division) and Orlando's `Delta4(C_1, ..., C_5)`. Its expanded form in P0".into(),
                "cancels far beyond double precision near the Hopf points; this form does not.".into(),
            ]);
            c.poly(&orlando().delta4)
        }
        None => {
            doc.extend(lines(&[
                "This aircraft has aileron yaw: the trim depends on delta_a and no polynomial in P0",
                "and the controls alone exists (`model analyze` eliminates delta_a by a resultant), so",
                "the function returns NaN, as `jump_polynomial` does.",
            ]));
            let minus_one = c.dag.constant(Q::int(-1));
            c.dag.sqrt(minus_one)
        }
    };
    finish(
        c,
        "hopf_polynomial",
        doc,
        false,
        args,
        vec![(String::new(), value)],
        Ret::Scalar,
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::emit::reference::{evaluate, Reference};
    use crate::emit::specialised_functions;
    use crate::specialise::exact_f64;

    /// The emitted structured form is exactly the expanded Hopf polynomial: its DAG evaluated in
    /// rational arithmetic (constants exact, no division) equals the interpolated polynomial.
    #[test]
    fn emitted_hopf_polynomial_is_the_exact_polynomial() {
        let s = symbols();
        let ac = Aircraft::b();
        let f = specialised_functions(&ac)
            .into_iter()
            .find(|f| f.name == "hopf_polynomial")
            .unwrap();
        let h = hopf_polynomial(&ac).unwrap();
        for (p0, de) in [(3.12903, 2f64.to_radians()), (0.7, -0.1), (5.5, 0.05)] {
            let input = |name: &str| match name {
                "p0" => p0,
                "delta_e" => de,
                _ => 0.0,
            };
            let got = evaluate(&f.dag, &[f.outputs[0].1], &input);
            let want = h
                .subs_values(&[(s.p0, exact_f64(p0)), (s.delta_e, exact_f64(de))])
                .as_constant()
                .unwrap();
            match &got[0] {
                Reference::Value(q, _) => assert_eq!(*q, want, "at {p0}, {de}"),
                other => panic!("{other:?}"),
            }
        }
    }
}
