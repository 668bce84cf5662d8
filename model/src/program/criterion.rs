//! The criterion polynomials of the certified route as one straight-line program of
//! the aircraft data: the coefficients in P0 of det A, the trim numerators, the trim condition,
//! the jump and pole polynomials and the zero-sideslip ones, built by step 8 in the ring of
//! polynomials in P0 with coefficient nodes (the ring `jump_polynomial` is built in), every
//! shared subexpression once.
//!
//! The program covers aircraft without aileron yaw (`n_delta_a = 0`, so that the trim does not
//! depend on delta_a and no resultant is needed) at `delta_r = 0` (as the certified analysis
//! runs): the certified route evaluates it in f64 with an a priori bound on its rounding,
//! a few thousand operations where lifting the parametric results term by term and clearing them
//! in interval polynomials takes a hundred thousand.

use super::builder::{Ctx, DE};
use crate::algebra::{Poly, Q};
use crate::derivation::Derivation;
use crate::equations::symbols;
use crate::program::expr::{Dag, Id};

/// The program and the coefficient nodes (ascending powers of P0) of each polynomial. Its
/// inputs are `delta_e` and then the parameters in [`crate::aircraft::Param::ALL`] order.
#[derive(Clone, Debug)]
pub struct CriterionProgram {
    /// The program.
    pub dag: Dag,
    /// det A (Eq. 4).
    pub det_a: Vec<Id>,
    /// The numerators of [alpha0, beta0, Q0, R0] over det A (Eqs 3-4).
    pub trim: [Vec<Id>; 4],
    /// The trim condition `det(A)^2 p_dot` on the trim, by powers of delta_a: `[G0, G1]`, the
    /// condition `G0 + G1 delta_a = 0` (linear in delta_a without aileron yaw).
    pub trim_condition: [Vec<Id>; 2],
    /// `det J5 det(A)^2` on the trim: the jump polynomial.
    pub jump: Vec<Id>,
    /// `d det(A)^2` on the trim: the pole polynomial.
    pub poles: Vec<Id>,
    /// det A1 of the zero-sideslip trim (Eq. 35).
    pub zs_det: Vec<Id>,
    /// The numerators of [alpha0, Q0, R0] of the zero-sideslip trim over det A1.
    pub zs_trim: [Vec<Id>; 3],
    /// `det J5 det(A1)^2` at the zero-sideslip trim.
    pub zs_jump: Vec<Id>,
    /// `d det(A1)^2` at the zero-sideslip trim.
    pub zs_d_det: Vec<Id>,
}

impl CriterionProgram {
    /// The polynomials in the order of the fields.
    pub fn polys(&self) -> Vec<&[Id]> {
        [&self.det_a]
            .into_iter()
            .chain(&self.trim)
            .chain(&self.trim_condition)
            .chain([&self.jump, &self.poles, &self.zs_det])
            .chain(&self.zs_trim)
            .chain([&self.zs_jump, &self.zs_d_det])
            .map(Vec::as_slice)
            .collect()
    }

    /// Every output node, polynomial after polynomial in the order of the fields.
    pub fn outputs(&self) -> Vec<Id> {
        self.polys().concat()
    }
}

/// The criterion program of the parametric derivation `d` (without aileron yaw, at
/// `delta_r = 0`).
pub fn criterion_program(d: &Derivation) -> CriterionProgram {
    let s = symbols();
    let mut c = Ctx::new(true, &[DE]);
    let zero = c.dag.constant(Q::ZERO);
    c.bind(s.delta_r, zero);
    let (p0, t4, t3) = (
        s.p0,
        [s.alpha0, s.beta0, s.q0, s.r0],
        [s.alpha0, s.q0, s.r0],
    );
    // The trim without aileron yaw: its delta_a part is n_delta_a times N^a (as in
    // `jump_polynomial`).
    let trim0: Vec<Poly> = d.trim.iter().map(|n| n.coeff(s.delta_a, 0)).collect();
    assert!(
        d.roll_at_trim.degree_in(&[s.delta_a]) <= 1,
        "the roll equation is affine in delta_a"
    );
    let roll = |j| d.roll_at_trim.coeff(s.delta_a, j);
    let at_beta0 = |p: &Poly| p.subs(s.beta0, &Poly::zero());
    CriterionProgram {
        det_a: c.in_var(&d.det_a, p0),
        trim: std::array::from_fn(|i| c.in_var(&trim0[i], p0)),
        trim_condition: [
            c.homogenize(&roll(0), &t4, &trim0, &d.det_a),
            c.homogenize(&roll(1), &t4, &trim0, &d.det_a),
        ],
        jump: c.homogenize(&d.det_j5, &t4, &trim0, &d.det_a),
        poles: c.homogenize(&d.d, &t4, &trim0, &d.det_a),
        zs_det: c.in_var(&d.zs_det, p0),
        zs_trim: std::array::from_fn(|i| c.in_var(&d.zs_trim[i], p0)),
        zs_jump: c.homogenize(&at_beta0(&d.det_j5), &t3, &d.zs_trim, &d.zs_det),
        zs_d_det: c.homogenize(&at_beta0(&d.d), &t3, &d.zs_trim, &d.zs_det),
        dag: c.dag,
    }
}
