//! The pieces of the derivation's steps: the model with an aircraft's values, the substitution
//! of the trim, Eq. 5's biquadratic, the stiffness matrix of step 5 (Eqs 16, 27-31), the
//! zero-sideslip trim of step 6 (Eqs 32-35), and the small algebra they share (linear systems
//! solved by Cramer's rule, solving for one symbol, time derivatives).

use super::Ratio;
use crate::algebra::{Matrix, Poly, Sym, Q};
use crate::equations::{pss, Symbols};

/// The model with the aircraft's values, and the unconstrained model (the rudder also at its
/// value). The unconstrained roll holds the rudder at the given value. With n_delta_a != 0 the
/// aileron also enters the yaw equation: for a given P0 the four trim equations stay linear in
/// (alpha, beta, q, r), with a constant part affine in delta_a, and the roll equation becomes
/// quadratic in delta_a (the trim condition).
pub(super) fn models(s: &Symbols, values: &[(Sym, Q)]) -> ([Poly; 5], [Poly; 5]) {
    let base_values: Vec<(Sym, Q)> = values
        .iter()
        .filter(|(v, _)| *v != s.delta_r)
        .cloned()
        .collect();
    let model = pss().map(|f| f.subs_values(&base_values));
    let unc_values: Vec<(Sym, Q)> = values
        .iter()
        .filter(|(v, _)| *v == s.delta_r)
        .cloned()
        .collect();
    let unc = model.clone().map(|f| f.subs_values(&unc_values));
    (model, unc)
}

/// `f` with the states replaced by their trim symbols.
pub(super) fn at_trim(s: &Symbols, f: &Poly) -> Poly {
    f.subs_all(
        &s.states()
            .iter()
            .zip(s.trims())
            .map(|(x, t)| (*x, Poly::var(t)))
            .collect::<Vec<_>>(),
    )
}

/// Eq. 5: the coefficients of P0^0, P0^2 and P0^4 of det A. The P0^4 coefficient is C D, which a
/// user's aircraft may make zero (Ix = Iy or Ix = Iz): missing coefficients are zero, odd ones
/// vanish identically.
pub(super) fn biquadratic(s: &Symbols, det_a: &Poly) -> [Poly; 3] {
    let c = det_a.coeffs(s.p0);
    let at = |k: usize| c.get(k).cloned().unwrap_or_default();
    assert!(
        c.len() <= 5 && at(1).is_zero() && at(3).is_zero(),
        "Eq. 5: det A must be a biquadratic in P0"
    );
    [at(0), at(2), at(4)]
}

/// Step 5 (Eqs 16, 27-31): the stiffness matrix K = K0 - g h^T / d with p = p_s substituted.
pub(super) struct Stiffness {
    pub(super) k0: [[Poly; 2]; 2],
    pub(super) g: [Poly; 2],
    pub(super) k_times_d: [[Poly; 2]; 2],
    pub(super) d_det_k: Poly,
}

/// Step 5 from the second-order equations and the roll mode's static residual `d`, `h`.
pub(super) fn stiffness(
    s: &Symbols,
    second_order: &[Poly; 2],
    d: &Poly,
    h: &[Poly; 2],
) -> Stiffness {
    let y = [s.alpha, s.beta];
    let k0: [[Poly; 2]; 2] =
        std::array::from_fn(|i| std::array::from_fn(|j| coefficient_of(&second_order[i], y[j])));
    let g: [Poly; 2] = std::array::from_fn(|i| coefficient_of(&second_order[i], s.p));
    let k_times_d: [[Poly; 2]; 2] =
        std::array::from_fn(|i| std::array::from_fn(|j| &(d * &k0[i][j]) - &(&g[i] * &h[j])));
    let k0m = Matrix::from_rows(k0.iter().map(|r| r.to_vec()).collect());
    let adj = k0m.adjugate();
    let h_adj_g = (0..2).fold(Poly::zero(), |acc, i| {
        (0..2).fold(acc, |acc, j| &acc + &(&(&h[i] * adj.get(i, j)) * &g[j]))
    });
    let d_det_k = &(d * &k0m.det()) - &h_adj_g;
    Stiffness {
        k0,
        g,
        k_times_d,
        d_det_k,
    }
}

/// Step 6 (Eqs 32-35): the zero-sideslip trim, with the rudder freed and beta = 0.
pub(super) struct ZeroSideslip {
    pub(super) zs_a: Matrix,
    pub(super) zs_rhs: Vec<Poly>,
    pub(super) zs_det: Poly,
    pub(super) zs_trim: [Poly; 3],
    pub(super) zs_delta_r: Ratio,
    pub(super) zs_delta_a: Ratio,
}

/// Step 6 from the model with the aircraft's values.
pub(super) fn zero_sideslip(s: &Symbols, model: &[Poly; 5]) -> ZeroSideslip {
    let zs_eqs: Vec<Poly> = [0usize, 1, 3]
        .iter()
        .map(|&i| model[i].subs_all(&[(s.p, Poly::var(s.p0)), (s.beta, Poly::zero())]))
        .collect();
    assert!(
        zs_eqs.iter().all(|e| !e.contains(s.delta_r)),
        "Eq. 34: A1 is block-triangular, the rudder only enters the yaw equation"
    );
    let (zs_a, zs_rhs) = linear_system(&zs_eqs, &[s.alpha, s.q, s.r]);
    let (zs_trim_v, zs_det) = solve(&zs_a, &zs_rhs);
    let zs_trim: [Poly; 3] = [
        zs_trim_v[0].clone(),
        zs_trim_v[1].clone(),
        zs_trim_v[2].clone(),
    ];
    let zs_at_trim = |f: &Poly| at_trim(s, f).subs(s.beta0, &Poly::zero());
    // The roll and yaw equations hold the trim with the two lateral controls together.
    let (zs_controls, zs_controls_det) = {
        let eqs = [zs_at_trim(&model[2]), zs_at_trim(&model[4])];
        let (m, c) = linear_system(&eqs, &[s.delta_a, s.delta_r]);
        solve(&m, &c)
    };
    let zs_delta_a = Ratio {
        num: zs_controls[0].clone(),
        den: zs_controls_det.clone(),
    };
    let zs_delta_r = Ratio {
        num: zs_controls[1].clone(),
        den: zs_controls_det,
    };
    ZeroSideslip {
        zs_a,
        zs_rhs,
        zs_det,
        zs_trim,
        zs_delta_r,
        zs_delta_a,
    }
}

/// Splits equations that are linear in `unknowns` into `A x + c = 0`.
pub(super) fn linear_system(eqs: &[Poly], unknowns: &[Sym]) -> (Matrix, Vec<Poly>) {
    for e in eqs {
        assert!(
            e.degree_in(unknowns) <= 1,
            "trim equations must be linear in the unknowns"
        );
    }
    let rows = eqs
        .iter()
        .map(|e| unknowns.iter().map(|u| e.coeff(*u, 1)).collect())
        .collect();
    let zero: Vec<(Sym, Q)> = unknowns.iter().map(|u| (*u, Q::ZERO)).collect();
    (
        Matrix::from_rows(rows),
        eqs.iter().map(|e| e.subs_values(&zero)).collect(),
    )
}

/// Solves `A x + c = 0`: numerators `-adj(A) c` over the common denominator `det A`.
pub(super) fn solve(a: &Matrix, c: &[Poly]) -> (Vec<Poly>, Poly) {
    let (num, den) = a.solve(c);
    (num.iter().map(|n| -n).collect(), den)
}

/// Solves `f = 0` for `x`, where `f` is linear in `x`: `x = -f|_{x=0} / (df/dx)`.
/// The denominator is zero when `x` does not occur (e.g. `n_delta_r = 0` for the rudder of
/// Eq. 35): callers that divide by it check for that.
pub(super) fn solve_for(f: &Poly, x: Sym) -> Ratio {
    assert!(f.degree(x) <= 1, "equation must be linear in {x}");
    Ratio {
        num: -f.coeff(x, 0),
        den: f.coeff(x, 1),
    }
}

/// Divides `f` by its (constant) coefficient of `x`, making the equation monic in `x`.
pub(super) fn monic_in(f: &Poly, x: Sym) -> Poly {
    let c = f
        .coeff(x, 1)
        .as_constant()
        .expect("leading coefficient is a constant");
    f.scale(&Q::ONE.div(&c))
}

/// The coefficient of the perturbation `x` in an expression linear in the perturbations.
pub(super) fn coefficient_of(f: &Poly, x: Sym) -> Poly {
    f.coeff(x, 1)
}

/// d/dt of an expression linear in the perturbations (trims and parameters are constant).
pub(super) fn time_derivative(s: &Symbols, f: &Poly) -> Poly {
    let chain = [
        (s.alpha, s.alpha_dot),
        (s.alpha_dot, s.alpha_ddot),
        (s.beta, s.beta_dot),
        (s.beta_dot, s.beta_ddot),
        (s.p, s.p_dot),
    ];
    for x in [s.q, s.r, s.alpha_ddot, s.beta_ddot, s.p_dot] {
        assert!(
            !f.contains(x),
            "time derivative of {x} is not part of the derivation"
        );
    }
    chain.iter().fold(Poly::zero(), |acc, (x, xd)| {
        &acc + &(&f.diff(*x) * &Poly::var(*xd))
    })
}
