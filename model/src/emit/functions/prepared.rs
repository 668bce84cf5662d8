//! `Prepared`: det K at the trim of a roll rate, on the trim branch of `det_k`
//! (branch 0, with aileron yaw too), with everything that depends only on the aircraft and the
//! controls computed once by `Prepared::new` and only the roll-rate-dependent rest per call.
//!
//! The program is built so that the split is large: every polynomial is a Horner scheme in the
//! late symbols (P0, the trim, delta_a) whose coefficients, polynomials in the data and the
//! controls, are single nodes ([`Dag::poly_over`]); then [`crate::program::stage`] makes each early
//! operand of a late operation a field. Per call: the trim numerators N_a + delta_a N_b and det A
//! as polynomials in P0, the trim condition `G2 delta_a^2 + G1 delta_a + G0` (step 8 on the roll
//! equation, in delta_a), its root on branch 0 by the cancellation-free quadratic formula
//! `delta_a = -2 G0 / (G1 + copysign(sqrt(G1^2 - 4 G0 G2), G1))` (the root of `det_k`'s trim,
//! which writes the same formula with a second division) kept as a fraction whose denominator
//! joins det A's, and det K by the matrix determinant lemma with det A cleared (as `det_k`):
//! one square root and one division per call.

use super::{finish, lines, Function, Ret};
use crate::algebra::Q;
use crate::derivation::{clear_trim, Derivation, TRIM_DEGREE};
use crate::equations::symbols;
use crate::program::builder::{Arg, Ctx, InVar, DE, DR, P0};
use crate::program::expr::Id;
use crate::program::stage::stage;

/// The prepared det K: the whole program and its two stages.
#[derive(Clone, Debug)]
pub struct Prepared {
    /// det K from the data, the controls and P0 in one program (the self-test's reference).
    pub full: Function,
    /// `Prepared::new(k, delta_e, delta_r)`: the fields.
    pub new: Function,
    /// `Prepared::det_k(&self, p0)`.
    pub det_k: Function,
}

/// The name of the generated type.
pub const TYPE: &str = "Prepared";

/// det K of [`Prepared`] in one program: the trim numerators and the trim condition as
/// Horner schemes in the late symbols, the aileron's root kept as a fraction, and det K by the
/// matrix determinant lemma with det A cleared.
fn full_program(d: &Derivation) -> Function {
    let s = symbols();
    let args = vec![P0, DE, DR];
    let mut c = Ctx::new(true, &args);
    c.outer = vec![s.p0, s.alpha0, s.beta0, s.q0, s.r0, s.delta_a];
    let t = [s.alpha0, s.beta0, s.q0, s.r0];
    // Trim numerators over det A, affine in delta_a: N = N_a + delta_a N_b.
    let num: Vec<Vec<Id>> = d
        .trim
        .iter()
        .map(|n| {
            vec![
                c.poly(&n.coeff(s.delta_a, 0)),
                c.poly(&n.coeff(s.delta_a, 1)),
            ]
        })
        .collect();
    let det = c.poly(&d.det_a);
    // The trim condition det(A)^2 p_dot as a polynomial in delta_a (step 8).
    let g = clear_trim(
        &mut InVar(&mut c, s.delta_a),
        &d.roll_at_trim,
        &t,
        &num,
        &vec![det],
        TRIM_DEGREE,
    );
    let zero = c.dag.constant(Q::ZERO);
    let coef = |i: usize| g.get(i).copied().unwrap_or(zero);
    let (g0, g1, g2) = (coef(0), coef(1), coef(2));
    // The aileron is delta_a = -2 G0 / D with D = G1 + copysign(sqrt(G1^2 - 4 G0 G2), G1), and
    // it is not divided out: det K is homogeneous of degree 0 in the trim's numerators and their
    // denominator (g and h are cleared with det A, d with det(A)^2), so the numerators
    // D N_a - 2 G0 N_b over D det A give the same det K with one division fewer.
    let (two_g0, den) = {
        let dag = &mut c.dag;
        let den = dag.stable_quadratic_sum(g1, g0, g2);
        let two = dag.constant(Q::int(2));
        (dag.mul(two, g0), den)
    };
    let x: Vec<Id> = num
        .iter()
        .map(|n| {
            let a = c.dag.mul(den, n[0]);
            let b = c.dag.mul(two_g0, n[1]);
            c.dag.sub(a, b)
        })
        .collect();
    let det_scaled = c.dag.mul(den, det);
    // det K0 is det A up to sign (the derivation's Eq. 16 is the 2x2 system of A with the q and
    // r rows eliminated): checked exactly here, then det A's node serves for both.
    let k0 = &d.k0;
    let det_k0 = &(&k0[0][0] * &k0[1][1]) - &(&k0[0][1] * &k0[1][0]);
    let det_k0 = if det_k0 == d.det_a {
        Some(det)
    } else if det_k0 == -&d.det_a {
        Some(c.dag.neg(det))
    } else {
        None
    };
    let det_k = c.det_k_cleared(d, &t, &x, det_scaled, det_k0);
    finish(
        c,
        "det_k",
        lines(&["det K of [`Prepared`] in one program (for the self-test)."]),
        true,
        args,
        vec![(String::new(), det_k)],
        Ret::Scalar,
    )
}

/// The prepared det K of the parametric derivation `d`.
pub fn prepared(d: &Derivation) -> Prepared {
    let full = full_program(d);
    let ids: Vec<Id> = full.outputs.iter().map(|(_, id)| *id).collect();
    let st = stage(&full.dag, &ids, &["p0"]);
    let fields: Vec<(String, Id)> = st
        .fields
        .iter()
        .enumerate()
        .map(|(n, id)| (format!("f{n}"), *id))
        .collect();
    let new = Function {
        name: "new",
        doc: lines(&[
            "Prepares det K for an aircraft `k` and the controls: computes once everything of",
            "[`det_k`](Self::det_k) that does not depend on the roll rate (the coefficients of the",
            "polynomials in P0 of the trim numerators, det A, the trim condition and K0, g, h, d).",
        ]),
        takes_derivatives: true,
        args: vec![DE, DR],
        dag: st.early,
        outputs: fields,
        ret: Ret::Struct(TYPE),
        owner: Some(TYPE),
    };
    let det_k = Function {
        name: "det_k",
        doc: lines(&[
            "The jump criterion det K (Eq. 27) at the trim of `p0`, 1/s^4: the value of the free",
            "function `det_k(k, p0, delta_e, delta_r)` on the same trim branch (element 0 of",
            "`trim`, with aileron yaw too), computed from the prepared fields. Not bit-identical to",
            "`det_k` (other operations), equal to it within rounding away from roots and poles.",
        ]),
        takes_derivatives: false,
        args: vec![Arg {
            name: "p0",
            doc: "trim roll rate P0, rad/s",
        }],
        dag: st.late,
        outputs: vec![(String::new(), st.outputs[0])],
        ret: Ret::Scalar,
        owner: Some(TYPE),
    };
    Prepared { full, new, det_k }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::emit::op_count;

    /// The split is worth it: the per-call program is at most three quarters of the free
    /// `det_k`, and the two stages hold every operation of the whole.
    #[test]
    fn per_call_work_is_a_fraction_of_the_whole() {
        let d = crate::specialise::parametric();
        let p = prepared(d);
        let free = super::super::functions(d, true)
            .into_iter()
            .find(|f| f.name == "det_k")
            .expect("the free det_k");
        let (full, new, late) = (op_count(&p.full), op_count(&p.new), op_count(&p.det_k));
        assert_eq!(full.total(), new.total() + late.total());
        let whole = op_count(&free).total();
        assert!(4 * late.total() <= 3 * whole, "{late:?} of {whole}");
        assert!(late.div <= 1 && late.libm <= 2, "{late:?}");
    }
}
