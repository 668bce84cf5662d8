//! The catalogue of generated functions: which derived results become which functions, each
//! built by the program builder ([`crate::program::builder`]) and documented with the formulas it
//! is built from. The documented formulas are the parametric derivation's (the same polynomials
//! as those of the derivation a function is built from, before the data are folded in).

use super::{finish, hopf, lines, stiffness_formulas, with_formulas, Function, Ret};
use crate::algebra::{Poly, Q};
use crate::derivation::Derivation;
use crate::emit::formulas::Formula;
use crate::equations::symbols;
use crate::program::builder::{Arg, Ctx, DE, DR, P0};
use crate::program::expr::Id;

/// All generated functions for a derivation (parametric when `takes_derivatives`).
pub fn functions(d: &Derivation, takes_derivatives: bool) -> Vec<Function> {
    let t = takes_derivatives;
    let mut out = vec![
        trim(d, t),
        zero_sideslip_trim(d, t),
        jacobian5(d, t),
        residual_denominator(d, t),
        stiffness(d, t),
        det_k(d, t),
        det_j5(d, t),
        zero_sideslip_det_k(d, t),
        divergence_biquadratic(d, t),
        divergence_roll_rates(d, t),
        jump_polynomial(d, t),
        zero_sideslip_jump_polynomial(d, t),
    ];
    out.extend(hopf::functions(d, t));
    out
}

/// `trim`: the pseudo-steady trims of a roll rate, both branches (Eqs 1-4).
fn trim(d: &Derivation, t: bool) -> Function {
    let par = crate::specialise::parametric();
    let trim_args = vec![P0, DE, DR];
    let mut c = Ctx::new(t, &trim_args);
    let mut outputs = Vec::new();
    for branch in 0..2 {
        let [a, b, q, r, da] = c.trim_branch(d, branch);
        for (name, id) in [
            ("alpha", a),
            ("beta", b),
            ("q", q),
            ("r", r),
            ("delta_a", da),
        ] {
            outputs.push((name.to_string(), id));
        }
    }
    finish(
        c,
        "trim",
        with_formulas(
            &[
                "Pseudo-steady trims at roll rate `p0` (Eqs 1-4): `x0 = [alpha0, beta0, Q0, R0]` solves",
                "`A x0 + b = 0` (Cramer's rule, one division by det A), affine in delta_a (aileron yaw",
                "`n_delta_a` enters b); the aileron then solves the roll equation `p_dot = 0` along it,",
                "a quadratic `g2 delta_a^2 + g1 delta_a + g0 = 0` (`g2 = 0` without aileron yaw). Element",
                "0 is the trim that continues the trim without aileron yaw (the root that tends to",
                "`-g0/g1`), element 1 the other root; both by the cancellation-free quadratic formula.",
                "NaN where the two trims of `p0` are complex; element 1 is infinite or NaN without",
                "aileron yaw (a single trim). Angles in rad, rates in rad/s. Non-finite where det A = 0",
                "(the divergence roll rates). The other functions of `p0` use element 0.",
            ],
            &[
                ("A", Formula::matrix(&par.a)),
                ("b", Formula::Vector(par.a_rhs.iter().collect())),
                ("p_dot", Formula::Poly(&par.roll_at_trim)),
            ],
        ),
        t,
        trim_args.clone(),
        outputs,
        Ret::Structs("Trim", 2),
    )
}

/// `zero_sideslip_trim`: the zero-sideslip trim of a roll rate (Eqs 32-35).
fn zero_sideslip_trim(d: &Derivation, t: bool) -> Function {
    let par = crate::specialise::parametric();
    let args = vec![P0, DE];
    let mut c = Ctx::new(t, &args);
    let [a, q, r] = c.zs_trim(d);
    // The roll and yaw equations hold the trim with both lateral controls (Cramer on the
    // 2x2 system, one reciprocal of its determinant l_delta_a n_delta_r - l_delta_r n_delta_a).
    let den = c.poly(&d.zs_delta_a.den);
    let one = c.dag.constant(Q::ONE);
    let inv = c.dag.div(one, den);
    let num_a = c.poly(&d.zs_delta_a.num);
    let da = c.dag.mul(num_a, inv);
    let num_r = c.poly(&d.zs_delta_r.num);
    let dr = c.dag.mul(num_r, inv);
    let outputs = vec![
        ("alpha".into(), a),
        ("q".into(), q),
        ("r".into(), r),
        ("delta_a".into(), da),
        ("delta_r".into(), dr),
    ];
    finish(
        c,
        "zero_sideslip_trim",
        with_formulas(
            &[
                "Trim of the zero-sideslip roll at roll rate `p0` (Eqs 32-35): beta = 0 with the",
                "rudder freed; `[alpha0, Q0, R0]` solves `A1 x + b1 = 0` (the alpha, beta and q",
                "equations), the aileron and the rudder the roll and yaw equations together (with",
                "aileron yaw and roll due to rudder both controls enter both; the rudder is the",
                "schedule of the aileron-rudder interconnect, Fig. 9). Angles in rad, rates in rad/s.",
            ],
            &[
                ("A1", Formula::matrix(&par.zs_a)),
                ("b1", Formula::Vector(par.zs_rhs.iter().collect())),
                ("delta_a", Formula::Ratio(&par.zs_delta_a)),
                ("delta_r", Formula::Ratio(&par.zs_delta_r)),
            ],
        ),
        t,
        args,
        outputs,
        Ret::Struct("ZeroSideslipTrim"),
    )
}

/// `jacobian5`: the 5x5 Jacobian of the PSS model at a state (Appendix A.2).
fn jacobian5(d: &Derivation, t: bool) -> Function {
    let par = crate::specialise::parametric();
    let args = vec![
        Arg {
            name: "alpha",
            doc: "angle of attack, rad",
        },
        Arg {
            name: "beta",
            doc: "sideslip, rad",
        },
        Arg {
            name: "p",
            doc: "roll rate, rad/s",
        },
        Arg {
            name: "q",
            doc: "pitch rate, rad/s",
        },
        Arg {
            name: "r",
            doc: "yaw rate, rad/s",
        },
    ];
    let mut c = Ctx::new(t, &args);
    let mut outputs = Vec::new();
    for i in 0..5 {
        for j in 0..5 {
            let id = c.poly(d.jacobian.get(i, j));
            outputs.push((String::new(), id));
        }
    }
    finish(
        c,
        "jacobian5",
        with_formulas(
            &[
                "The 5x5 Jacobian of the PSS model (Appendix A.2) at the state",
                "x = [alpha, beta, p, q, r]: the linearized Eqs 6-10, row i = d(x_i dot)/dx, 1/s;",
                "below with `(alpha0, beta0, P0, Q0, R0) = (alpha, beta, p, q, r)`.",
            ],
            &[("J5", Formula::matrix(&par.jacobian))],
        ),
        t,
        args,
        outputs,
        Ret::Matrix(5, 5),
    )
}

/// `residual_denominator`: the static-residual denominator d at the trim (Eq. 22).
fn residual_denominator(d: &Derivation, t: bool) -> Function {
    let par = crate::specialise::parametric();
    let trim_args = vec![P0, DE, DR];
    let mut c = Ctx::new(t, &trim_args);
    c.trim(d);
    let dd = c.poly(&d.d);
    finish(
        c,
        "residual_denominator",
        with_formulas(
            &[
                "The static-residual denominator d (Eq. 22) at the trim of `p0`, 1/s. det K has",
                "poles where d = 0 (Fig. 8).",
            ],
            &[("d", Formula::Poly(&par.d))],
        ),
        t,
        trim_args.clone(),
        vec![(String::new(), dd)],
        Ret::Scalar,
    )
}

/// `stiffness`: the stiffness matrix K at the trim (Eqs 15-16, 27-31).
fn stiffness(d: &Derivation, t: bool) -> Function {
    let par = crate::specialise::parametric();
    let trim_args = vec![P0, DE, DR];
    let mut c = Ctx::new(t, &trim_args);
    c.trim(d);
    let k = c.stiffness(d);
    let outputs = k.iter().flatten().map(|id| (String::new(), *id)).collect();
    finish(
        c,
        "stiffness",
        with_formulas(
            &[
                "The stiffness matrix K of the second-order form (Eqs 15-16, 27-31) at the trim of",
                "`p0`: `K = K0 - g h^T / d` where K0 holds the coefficients of [alpha, beta] in",
                "Eqs 13-14, g those of p and `p_s = -(h . [alpha, beta]) / d` is the static residual",
                "(Eqs 22-25). 1/s^2.",
            ],
            &stiffness_formulas(par),
        ),
        t,
        trim_args.clone(),
        outputs,
        Ret::Matrix(2, 2),
    )
}

/// `det_k`: det K at the trim (Eq. 27), with one division.
fn det_k(d: &Derivation, t: bool) -> Function {
    let s = symbols();
    let par = crate::specialise::parametric();
    let trim_args = vec![P0, DE, DR];
    let mut c = Ctx::new(t, &trim_args);
    let trims = [s.alpha0, s.beta0, s.q0, s.r0];
    // The trim's aileron first (it enters the trim through n_delta_a), then the cleared form.
    c.trim(d);
    let det = c.det_k_one_division(d, &d.a, &d.a_rhs, &trims);
    finish(
        c,
        "det_k",
        with_formulas(
            &[
                "The jump criterion det K (Eq. 27) at the trim of `p0`, 1/s^4. Its zeros are the",
                "saddle-node (jump) points of the PSS equilibria (Figs 7-8); `det J5 = d det K`.",
                "Evaluated as `det K0 - h^T adj(K0) g / d` (the matrix determinant lemma on",
                "`K = K0 - g h^T / d`) with the trim's denominator det A cleared from g, h and d, on",
                "the trim branch of [`trim`].",
            ],
            &stiffness_formulas(par),
        ),
        t,
        trim_args.clone(),
        vec![(String::new(), det)],
        Ret::Scalar,
    )
}

/// `det_j5`: det J5 at the trim.
fn det_j5(d: &Derivation, t: bool) -> Function {
    let trim_args = vec![P0, DE, DR];
    let mut c = Ctx::new(t, &trim_args);
    c.trim(d);
    let det = c.poly(&d.det_j5);
    finish(
        c,
        "det_j5",
        lines(&[
            "The determinant of the 5x5 Jacobian at the trim of `p0`, 1/s^5;",
            "equal to `residual_denominator * det_k` identically (step 7 of the derivation).",
        ]),
        t,
        trim_args.clone(),
        vec![(String::new(), det)],
        Ret::Scalar,
    )
}

/// `zero_sideslip_det_k`: det K at the zero-sideslip trim (Eq. 27, section V.D).
fn zero_sideslip_det_k(d: &Derivation, t: bool) -> Function {
    let s = symbols();
    let args = vec![P0, DE];
    let mut c = Ctx::new(t, &args);
    let zero = c.dag.constant(Q::ZERO);
    c.bind(s.beta0, zero);
    let det = c.det_k_one_division(d, &d.zs_a, &d.zs_rhs, &[s.alpha0, s.q0, s.r0]);
    finish(
        c,
        "zero_sideslip_det_k",
        lines(&[
            "det K (Eq. 27) at the zero-sideslip trim of `p0` (section V.D, Fig. 11), 1/s^4: its",
            "zeros mark the departure (transcritical point) of the zero-sideslip roll. K0, g, h",
            "and d are those of [`det_k`] with `beta0 = 0`.",
        ]),
        t,
        args,
        vec![(String::new(), det)],
        Ret::Scalar,
    )
}

/// `divergence_biquadratic`: the coefficients of the divergence biquadratic det A (Eq. 5).
fn divergence_biquadratic(d: &Derivation, t: bool) -> Function {
    let par = crate::specialise::parametric();
    let mut c = Ctx::new(t, &[]);
    let outs: Vec<(String, Id)> = d
        .biquadratic
        .iter()
        .map(|p| (String::new(), c.poly(p)))
        .collect();
    finish(
        c,
        "divergence_biquadratic",
        with_formulas(
            &[
                "Coefficients [c0, c2, c4] of `det A = c4 P0^4 + c2 P0^2 + c0` (Eq. 5); its",
                "positive roots are the pitch-yaw divergence roll rates of Table 1.",
            ],
            &[
                ("c0", Formula::Poly(&par.biquadratic[0])),
                ("c2", Formula::Poly(&par.biquadratic[1])),
                ("c4", Formula::Poly(&par.biquadratic[2])),
            ],
        ),
        t,
        vec![],
        outs,
        Ret::Array(3),
    )
}

/// `divergence_roll_rates`: the divergence roll rates, the roots of Eq. 5.
fn divergence_roll_rates(d: &Derivation, t: bool) -> Function {
    let mut c = Ctx::new(t, &[]);
    let [c0, c2, c4] = [0, 1, 2].map(|i| c.poly(&d.biquadratic[i]));
    let dag = &mut c.dag;
    // The cancellation-free quadratic formula in x = P0^2: q = -(c2 + sign(c2) sqrt(disc)) / 2
    // adds two numbers of the same sign, and the roots are c0 / q (the smaller in
    // magnitude) and q / c4 (the larger), each a single rounding of well-conditioned parts.
    let sum = dag.stable_quadratic_sum(c2, c4, c0);
    let half = dag.constant(Q::ratio(1, 2));
    let half_sum = dag.mul(sum, half);
    let q = dag.neg(half_sum);
    let small = dag.div(c0, q);
    let large = dag.div(q, c4);
    let p1 = dag.sqrt(small);
    let p2 = dag.sqrt(large);
    finish(
        c,
        "divergence_roll_rates",
        lines(&[
            "The divergence roll rates P1 <= P2 of Eq. 5 (Table 1), rad/s, the positive roots of",
            "`det A = c4 P0^4 + c2 P0^2 + c0` ([`divergence_biquadratic`]), by the cancellation-free",
            "quadratic formula in `P0^2`: `q = -(c2 + copysign(sqrt(c2^2 - 4 c4 c0), c2)) / 2`,",
            "`P1 = sqrt(c0 / q)` (the root of smaller magnitude), `P2 = sqrt(q / c4)`. Both are",
            "accurate to a few ulps of well-conditioned coefficients even when one root is tiny",
            "against the other (the textbook `(-c2 -+ sqrt(...)) / (2 c4)` loses the small one to",
            "cancellation); `c4 = 0` gives `P1 = sqrt(-c0 / c2)`. NaN for a root that does not",
            "exist (negative discriminant or `P0^2 < 0`), without a branch.",
        ]),
        t,
        vec![],
        vec![(String::new(), p1), (String::new(), p2)],
        Ret::Array(2),
    )
}

/// `jump_polynomial`: det J5 with the trim substituted, by convolutions in P0 (step 8).
fn jump_polynomial(d: &Derivation, t: bool) -> Function {
    let s = symbols();
    let args = vec![DE, DR];
    let mut c = Ctx::new(t, &args);
    // The trim without aileron yaw: its delta_a part is n_delta_a times N^a, so it is the
    // trim at delta_a = 0 whether n_delta_a is a symbol or an aircraft's folded value.
    let trim0: Vec<Poly> = d.trim.iter().map(|p| p.coeff(s.delta_a, 0)).collect();
    let coeffs = c.homogenize(
        &d.det_j5,
        &[s.alpha0, s.beta0, s.q0, s.r0],
        &trim0,
        &d.det_a,
    );
    // `1 + sqrt(-n_delta_a^2)` is 1 without aileron yaw and NaN with it, without a branch.
    let guard = {
        // n_delta_a as the model has it: a symbol, or the aircraft's folded value.
        let nda = c.poly(&d.model[4].coeff(s.delta_a, 1));
        let sq = c.dag.mul(nda, nda);
        let neg = c.dag.neg(sq);
        let root = c.dag.sqrt(neg);
        let one = c.dag.constant(Q::ONE);
        c.dag.add(one, root)
    };
    let outs: Vec<(String, Id)> = coeffs
        .iter()
        .map(|id| (String::new(), c.dag.mul(*id, guard)))
        .collect();
    let n = outs.len();
    finish(
        c,
        "jump_polynomial",
        lines(&[
            "Coefficients of P0^0 ..= P0^12 of the jump polynomial `det J5 * det(A)^2` (step 8).",
            "Its positive real roots that are not roots of det A or d are the jump roll rates.",
            "A polynomial in P0 alone exists only without aileron yaw: every coefficient is NaN",
            "when `n_delta_a != 0` (then `model analyze` eliminates delta_a by a resultant).",
        ]),
        t,
        args,
        outs,
        Ret::Array(n),
    )
}

/// `zero_sideslip_jump_polynomial`: the jump polynomial at the zero-sideslip trim.
fn zero_sideslip_jump_polynomial(d: &Derivation, t: bool) -> Function {
    let s = symbols();
    let args = vec![DE];
    let mut c = Ctx::new(t, &args);
    let det = d.det_j5.subs(s.beta0, &Poly::zero());
    let coeffs = c.homogenize(&det, &[s.alpha0, s.q0, s.r0], &d.zs_trim, &d.zs_det);
    let outs: Vec<(String, Id)> = coeffs.iter().map(|id| (String::new(), *id)).collect();
    let n = outs.len();
    finish(
        c,
        "zero_sideslip_jump_polynomial",
        lines(&[
            "Coefficients of P0^0 ..= P0^8 of `det J5 * det(A1)^2` at the zero-sideslip trim",
            "(Eqs 32-35); its positive roots (not roots of det A1 or d) are the departure roll rates.",
        ]),
        t,
        args,
        outs,
        Ret::Array(n),
    )
}
