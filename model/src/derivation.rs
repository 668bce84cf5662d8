//! The paper's derivation (sections II, IV, V), carried out by the algebra layer.
//!
//! Every result is derived from [`crate::equations::pss`]; nothing is transcribed from the
//! paper, whose printed signs disagree with each other in places (compare the p-terms of Eq. 13
//! with Eq. 28). The identity of step 7, `det J5 = d det K`, checks the whole chain.
//!
//! A derivation is either *parametric* (every parameter a symbol: what the emitter turns into
//! code and LaTeX) or *specialised* to an aircraft and elevator setting (parameters replaced by
//! their exact rational values before the first step: what `model analyze` uses, because the
//! resulting polynomials are univariate in P0 and tiny). Both run the same code.
//!
//! Rational functions are never normalized: trims are numerators over the common denominator
//! `det A`, and the stiffness matrix is kept as `K = K0 - g h^T / d`, whose determinant times
//! `d` is a polynomial (matrix determinant lemma).
//!
//! ```
//! use model::algebra::{Poly, Sym};
//! use model::derivation::homogenize;
//!
//! // Step 8 on f = t^2 + t with t = n / d: (n^2 + n d) has no denominator left
//! let (t, n, d) = (Sym::new("t"), Sym::new("n"), Sym::new("d"));
//! let f = &Poly::var(t).pow(2) + &Poly::var(t);
//! let cleared = homogenize(&f, &[t], &[Poly::var(n)], &Poly::var(d), 2);
//! assert_eq!(cleared, &Poly::var(n).pow(2) + &(&Poly::var(n) * &Poly::var(d)));
//! ```

use crate::aircraft::Param;
use crate::algebra::{Matrix, Poly, Sym, Q};
use crate::equations::symbols;
use std::sync::OnceLock;

pub mod hopf;
mod steps;

use steps::{
    at_trim, biquadratic, linear_system, models, monic_in, solve, solve_for, stiffness,
    time_derivative, zero_sideslip, Stiffness, ZeroSideslip,
};

/// A quotient `num / den` of two polynomials, not normalized.
#[derive(Clone, Debug, PartialEq)]
pub struct Ratio {
    /// Numerator.
    pub num: Poly,
    /// Denominator.
    pub den: Poly,
}

/// The results of the derivation, each named after the paper's equation.
#[derive(Clone, Debug)]
pub struct Derivation {
    /// The PSS model (Appendix A.2) with the fixed values substituted, `d/dt [alpha, beta, p, q, r]`.
    pub model: [Poly; 5],
    /// The PSS model used for unconstrained rolls: as `model` with delta_r substituted when a
    /// value was given. See [`Derivation::derive`].
    pub unconstrained_model: [Poly; 5],
    /// Eq. 2: the 4x4 matrix A of the trim system in x = [alpha, beta, q, r] at p = P0.
    pub a: Matrix,
    /// Eqs 1-2: the constant part `b u + b1 P0` of the trim system `A x + b u + b1 P0 = 0`; with
    /// aileron yaw `u` includes delta_a (the `n_delta_a delta_a` term of the yaw equation), so the
    /// trim is affine in delta_a for a given P0.
    pub a_rhs: Vec<Poly>,
    /// Eq. 4: det A, the common denominator of the trim states.
    pub det_a: Poly,
    /// Eqs 3-4: numerators of [alpha0, beta0, Q0, R0] over `det_a`: `-adj(A) (b u + b1 P0)`,
    /// affine in delta_a (which enters through `n_delta_a` only).
    pub trim: [Poly; 4],
    /// Eq. 5: coefficients of P0^0, P0^2, P0^4 of det A (odd powers vanish identically).
    pub biquadratic: [Poly; 3],
    /// The aileron deflection that holds a trim, from the roll equation, in trim symbols.
    pub delta_a: Ratio,
    /// The roll equation (Appendix A.2) in the trim symbols, with delta_a: `p_dot` at a trim.
    pub roll_at_trim: Poly,
    /// The 5x5 Jacobian of the PSS model at the trim (alpha0, beta0, P0, Q0, R0).
    pub jacobian: Matrix,
    /// Eqs 6-10: the linearized equations, right-hand sides in the perturbations.
    pub linearized: [Poly; 5],
    /// Eq. 11: q in terms of alpha, alpha_dot, beta, p.
    pub q_elim: Poly,
    /// Eq. 12: r in terms of alpha, beta, beta_dot, p.
    pub r_elim: Poly,
    /// Eqs 13-14: the coupled second-order equations (= 0), leading coefficients 1.
    pub second_order: [Poly; 2],
    /// Eq. 21: the roll-mode equation, d p / dt in terms of alpha, alpha_dot, beta, beta_dot, p.
    pub roll_mode: Poly,
    /// Eq. 22: the static-residual denominator d = l_p + l_r alpha0 - E Q0 alpha0 - E R0 beta0.
    pub d: Poly,
    /// Eq. 22: `h = [h_alpha, h_beta]` with the static residual `p_s = -(h . y) / d`.
    pub h: [Poly; 2],
    /// Eqs 24-25: d p_s / d alpha and d p_s / d beta.
    pub dps: [Ratio; 2],
    /// Eq. 16: the stiffness matrix without the roll residual (coefficients of y in Eqs 13-14).
    pub k0: [[Poly; 2]; 2],
    /// Coefficients of p in Eqs 13-14 (g); the residual terms are `f_ij = -g_i h_j / d`.
    pub g: [Poly; 2],
    /// Eqs 16, 27-31: `d K` entry by entry, `d K0_ij - g_i h_j`.
    pub k_times_d: [[Poly; 2]; 2],
    /// Eq. 27: `d det K = d det K0 - h^T adj(K0) g`, a polynomial.
    pub d_det_k: Poly,
    /// det J5 at the trim, in trim symbols.
    pub det_j5: Poly,
    /// Step 7: `det J5 - d det K`; identically zero.
    pub identity_residual: Poly,
    /// Step 8, computed on first use (see [`Derivation::jump_at`]).
    step8: OnceLock<Step8>,
    /// The aileron elimination after step 8, computed on first use (see [`Derivation::jump`]).
    elimination: OnceLock<Elimination>,
    /// Eqs 32-34: the zero-sideslip trim system in [alpha, q, r] (beta = 0, delta_r freed).
    pub zs_a: Matrix,
    /// Eqs 32-33: the constant part of the zero-sideslip trim system `zs_a x + zs_rhs = 0`.
    pub zs_rhs: Vec<Poly>,
    /// Eq. 35: det of the zero-sideslip system, common denominator of `zs_trim`.
    pub zs_det: Poly,
    /// Eq. 35: numerators of [alpha0, Q0, R0] of the zero-sideslip trim.
    pub zs_trim: [Poly; 3],
    /// Eq. 35: the rudder deflection holding beta = 0, in trim symbols: with the roll equation it
    /// solves the 2x2 system in (delta_a, delta_r) of the roll and yaw equations, whose
    /// determinant `l_delta_a n_delta_r - l_delta_r n_delta_a` is the denominator.
    pub zs_delta_r: Ratio,
    /// The aileron deflection of the zero-sideslip trim, in trim symbols (same denominator).
    pub zs_delta_a: Ratio,
}

/// Step 8 results, cleared of the trim's denominators.
#[derive(Clone, Debug)]
struct Step8 {
    trim_condition: Poly,
    jump_at: Poly,
    d_at: Poly,
    zs_jump: Poly,
    zs_d_det: Poly,
}

/// The aileron eliminated along the equilibrium curve: the jump and pole polynomials in P0.
#[derive(Clone, Debug)]
struct Elimination {
    jump: Poly,
    poles: Poly,
}

impl Derivation {
    /// The derivation with every parameter and control a symbol.
    pub fn parametric() -> Derivation {
        Derivation::derive(&[])
    }

    /// The derivation specialised to exact parameter and control values.
    ///
    /// `values` may fix any symbol of the model (parameters, delta_e, delta_r). A value for
    /// delta_r applies to the unconstrained roll only: the zero-sideslip trim frees the rudder.
    pub fn derive(values: &[(Sym, Q)]) -> Derivation {
        let s = symbols();
        let (model, unc) = models(s, values);
        let at_trim = |f: &Poly| at_trim(s, f);

        // Step 1, Eqs 1-5: the trim system with p = P0 is linear in [alpha, beta, q, r].
        let unknowns = [s.alpha, s.beta, s.q, s.r];
        let at_p0: Vec<Poly> = [0usize, 1, 3, 4]
            .iter()
            .map(|&i| unc[i].subs(s.p, &Poly::var(s.p0)))
            .collect();
        let (a, a_rhs) = linear_system(&at_p0, &unknowns);
        let (trim, det_a) = solve(&a, &a_rhs);
        let biquadratic = biquadratic(s, &det_a);
        let roll_at_trim = at_trim(&unc[2]);
        let delta_a = solve_for(&roll_at_trim, s.delta_a);

        // Step 2, Eqs 6-10: linearize by symbolic differentiation at the trim.
        let jacobian = Matrix::from_rows(
            unc.iter()
                .map(|f| s.states().iter().map(|x| at_trim(&f.diff(*x))).collect())
                .collect(),
        );
        let linearized: [Poly; 5] = std::array::from_fn(|i| {
            s.states()
                .iter()
                .enumerate()
                .fold(Poly::zero(), |acc, (j, x)| {
                    &acc + &(jacobian.get(i, j) * &Poly::var(*x))
                })
        });

        // Step 3, Eqs 11-15: q from the alpha equation, r from the beta equation.
        let q_elim = solve_for(&(&linearized[0] - &Poly::var(s.alpha_dot)), s.q).as_poly();
        let r_elim = solve_for(&(&linearized[1] - &Poly::var(s.beta_dot)), s.r).as_poly();
        let elim = |f: &Poly| f.subs_all(&[(s.q, q_elim.clone()), (s.r, r_elim.clone())]);
        let eq13 = &time_derivative(s, &q_elim) - &elim(&linearized[3]);
        let eq14 = &time_derivative(s, &r_elim) - &elim(&linearized[4]);
        let second_order = [monic_in(&eq13, s.alpha_ddot), monic_in(&eq14, s.beta_ddot)];

        // Step 4, Eqs 21-26: roll mode and its static residual (alpha_dot = beta_dot = 0).
        let roll_mode = elim(&linearized[2]);
        let statics = roll_mode.subs_values(&[(s.alpha_dot, Q::ZERO), (s.beta_dot, Q::ZERO)]);
        let d = statics.coeff(s.p, 1).coeff(s.alpha, 0).coeff(s.beta, 0);
        let h = [
            statics.coeff(s.alpha, 1).coeff(s.p, 0),
            statics.coeff(s.beta, 1).coeff(s.p, 0),
        ];
        let dps = h.clone().map(|hj| Ratio {
            num: -hj,
            den: d.clone(),
        });

        // Step 5, Eqs 16, 27-31: stiffness matrix with p = p_s substituted.
        let Stiffness {
            k0,
            g,
            k_times_d,
            d_det_k,
        } = stiffness(s, &second_order, &d, &h);

        // Step 7: det J5 = d det K, identically in the trim symbols.
        let det_j5 = jacobian.det();
        let identity_residual = &det_j5 - &d_det_k;

        // Step 6, Eqs 32-35: zero sideslip; the rudder is freed and beta = 0.
        let ZeroSideslip {
            zs_a,
            zs_rhs,
            zs_det,
            zs_trim,
            zs_delta_r,
            zs_delta_a,
        } = zero_sideslip(s, &model);

        Derivation {
            model,
            unconstrained_model: unc,
            a,
            a_rhs,
            det_a,
            trim: [
                trim[0].clone(),
                trim[1].clone(),
                trim[2].clone(),
                trim[3].clone(),
            ],
            biquadratic,
            delta_a,
            roll_at_trim,
            jacobian,
            linearized,
            q_elim,
            r_elim,
            second_order,
            roll_mode,
            d,
            h,
            dps,
            k0,
            g,
            k_times_d,
            d_det_k,
            det_j5,
            identity_residual,
            step8: OnceLock::new(),
            elimination: OnceLock::new(),
            zs_a,
            zs_rhs,
            zs_det,
            zs_trim,
            zs_delta_r,
            zs_delta_a,
        }
    }
}

impl Derivation {
    fn step8(&self) -> &Step8 {
        self.step8.get_or_init(|| {
            // Step 8: substitute the trim and clear denominators; then eliminate the aileron
            // along the equilibrium curve (trim condition = 0).
            let s = symbols();
            let trims4 = [s.alpha0, s.beta0, s.q0, s.r0];
            let jump_at = homogenize(&self.det_j5, &trims4, &self.trim, &self.det_a, TRIM_DEGREE);
            let d_at = homogenize(&self.d, &trims4, &self.trim, &self.det_a, TRIM_DEGREE);
            let trim_condition = homogenize(
                &self.roll_at_trim,
                &trims4,
                &self.trim,
                &self.det_a,
                TRIM_DEGREE,
            );
            Step8 {
                trim_condition,
                jump_at,
                d_at,
                zs_jump: zero_sideslip_step8(&self.det_j5, &self.zs_trim, &self.zs_det),
                zs_d_det: zero_sideslip_step8(&self.d, &self.zs_trim, &self.zs_det),
            }
        })
    }

    /// The trim condition: the roll equation at the trim of Eqs 3-4, cleared of det A,
    /// `G(P0, delta_a) = det(A)^2 p_dot(x0(P0, delta_a), P0, delta_a)` (step 8). Quadratic in
    /// delta_a through `-E Q0 R0` when `n_delta_a != 0` (so a roll rate has 0, 1 or 2 trims),
    /// linear with slope `l_delta_a det(A)^2` when `n_delta_a = 0`. Its zero set is the
    /// equilibrium curve.
    pub fn trim_condition(&self) -> &Poly {
        &self.step8().trim_condition
    }

    /// `det J5 * det(A)^2` at the trim of Eqs 3-4, a polynomial in P0 and delta_a (step 8).
    /// With `n_delta_a = 0` it does not contain delta_a and is the paper's jump polynomial.
    pub fn jump_at(&self) -> &Poly {
        &self.step8().jump_at
    }

    /// `d * det(A)^2` at the trim of Eqs 3-4, in P0 and delta_a: `det K = jump_at / d_at`.
    pub fn d_at(&self) -> &Poly {
        &self.step8().d_at
    }

    /// The jump polynomial in P0: `det J5 = 0` on the equilibrium curve, the aileron eliminated
    /// by the resultant of [`Derivation::jump_at`] and the trim condition in delta_a (see
    /// [`eliminate_aileron`]). With `n_delta_a = 0` it is `jump_at` itself. Computed on first
    /// use.
    pub fn jump(&self) -> &Poly {
        &self.elimination().jump
    }

    fn elimination(&self) -> &Elimination {
        self.elimination.get_or_init(|| {
            let g = self.trim_condition();
            Elimination {
                jump: eliminate_aileron(g, self.jump_at()),
                poles: eliminate_aileron(g, self.d_at()),
            }
        })
    }

    /// The pole polynomial in P0: `d = 0` on the equilibrium curve (delta_a eliminated as for
    /// [`Derivation::jump`]); its roots not shared with det A are the poles of det K.
    pub fn poles(&self) -> &Poly {
        &self.elimination().poles
    }

    /// det J5 at the zero-sideslip trim times `zs_det^2`, in P0.
    pub fn zs_jump(&self) -> &Poly {
        &self.step8().zs_jump
    }

    /// `d * zs_det^2` at the zero-sideslip trim, in P0: `det K = zs_jump / zs_d_det` there.
    pub fn zs_d_det(&self) -> &Poly {
        &self.step8().zs_d_det
    }
}

/// Eliminates the aileron between the trim condition `g` and a trim quantity `f` (both
/// polynomials in P0 and delta_a, cleared of det A): the resultant in delta_a, which vanishes at
/// the P0 where some trim on the equilibrium curve has `f = 0`.
///
/// With a symbolic `n_delta_a` both are quadratic in delta_a, but their delta_a^2 coefficients
/// carry `n_delta_a^2` (and f's delta_a coefficient `n_delta_a`), so the Sylvester resultant
/// carries `n_delta_a^2`, which is divided out: the result is continuous in `n_delta_a`, and at
/// `n_delta_a = 0` it equals `g1^2 e f0`, where `g1 = l_delta_a det(A)^2` marks the trim poles,
/// `f0` is the `n_delta_a = 0` polynomial and `e = lim f2 / n_delta_a^2` the trim of the second
/// branch, which escapes to infinite aileron as `n_delta_a -> 0` (a trim at infinity, never
/// reported: its aileron is not finite). With numeric data the Sylvester matrix is built on the
/// actual degrees, so an aircraft with `n_delta_a = 0` gets `f` itself (no spurious factor).
pub fn eliminate_aileron(g: &Poly, f: &Poly) -> Poly {
    let s = symbols();
    let res = g.resultant(f, s.delta_a);
    let nda = s.param(Param::NDeltaA);
    if g.degree(s.delta_a) == 2 && g.coeff(s.delta_a, 2).contains(nda) {
        res.div_var_pow(nda, 2)
            .expect("the resultant carries n_delta_a^2 (the delta_a^2 terms carry it)")
    } else {
        res
    }
}

impl Ratio {
    /// The quotient as a polynomial when the denominator is a constant.
    ///
    /// Panics when it is not: used only where the derivation has shown it (e.g. Eq. 11 divides
    /// by the coefficient 1 of q).
    pub fn as_poly(&self) -> Poly {
        let c = self
            .den
            .as_constant()
            .expect("denominator is a constant by construction");
        self.num.scale(&Q::ONE.div(&c))
    }
}

/// The power of the trim's denominator that step 8 clears from det J5 and from d.
///
/// Both are at most quadratic in the trim states (the entries of J5 are linear in them; d has
/// the `E Q0 alpha0` term). Clearing both with the same power keeps `det K = jump / d_det_a`
/// for every aircraft, also when E = 0 lowers the degree of d.
pub const TRIM_DEGREE: u32 = 2;

/// The ring step 8 builds its result in: exact polynomials ([`homogenize`]) or the emitter's
/// expression DAG (one node, or the coefficient nodes of a polynomial in P0), so that the
/// clearing of the trim's denominator is written once ([`clear_trim`]).
pub trait Clearing {
    /// A value of the ring.
    type Value: Clone;
    /// A polynomial free of the trim symbols as a value.
    fn lift(&mut self, p: &Poly) -> Self::Value;
    /// `a + b`.
    fn add(&mut self, a: &Self::Value, b: &Self::Value) -> Self::Value;
    /// `a * b`.
    fn mul(&mut self, a: &Self::Value, b: &Self::Value) -> Self::Value;
    /// `acc + a * b` in place of `acc` (by default a product and a sum).
    fn add_product(&mut self, acc: &mut Self::Value, a: &Self::Value, b: &Self::Value) {
        let term = self.mul(a, b);
        *acc = self.add(acc, &term);
    }
    /// `a^n` (by default `n` products starting from 1).
    fn pow(&mut self, a: &Self::Value, n: u32) -> Self::Value {
        let mut acc = self.lift(&Poly::int(1));
        for _ in 0..n {
            acc = self.mul(&acc, a);
        }
        acc
    }
}

/// Exact polynomials as the ring of [`Clearing`].
struct Exact;

impl Clearing for Exact {
    type Value = Poly;
    fn lift(&mut self, p: &Poly) -> Poly {
        p.clone()
    }
    fn add(&mut self, a: &Poly, b: &Poly) -> Poly {
        a + b
    }
    fn mul(&mut self, a: &Poly, b: &Poly) -> Poly {
        a * b
    }
    fn pow(&mut self, a: &Poly, n: u32) -> Poly {
        a.pow(n)
    }
}

/// Step 8 in any [`Clearing`] ring: `f` (of degree at most `k` in the trim symbols `t`) with
/// `t_i = num_i / den` substituted, times `den^k`, built without division. `f` is grouped by its
/// monomial `t^m` in the trim symbols, `f = sum_m c_m t^m`; each group becomes
/// `c_m num^m den^(k - |m|)`.
pub fn clear_trim<C: Clearing>(
    ring: &mut C,
    f: &Poly,
    t: &[Sym],
    num: &[C::Value],
    den: &C::Value,
    k: u32,
) -> C::Value {
    TrimGroups::new(f, t, k).clear(ring, num, den)
}

/// The grouping of step 8, `f = sum_m c_m t^m` by monomials `t^m` in the trim symbols, made
/// once so that a caller clearing the same `f` for many aircraft ([`crate::certified`]) groups
/// it once and lifts each coefficient `c_m` its own (precompiled) way.
#[derive(Clone, Debug)]
pub struct TrimGroups {
    k: u32,
    groups: Vec<(Vec<u32>, Poly)>,
}

impl TrimGroups {
    /// Groups `f` (of degree at most `k` in the trim symbols `t`) by its monomials in `t`.
    pub fn new(f: &Poly, t: &[Sym], k: u32) -> TrimGroups {
        assert!(f.degree_in(t) <= k, "degree in the trim states above {k}");
        let mut groups: std::collections::BTreeMap<Vec<u32>, Poly> = Default::default();
        for (m, c) in f.terms() {
            let e: Vec<u32> = t.iter().map(|s| m.exp(*s)).collect();
            let mut rest = *m;
            for s in t {
                rest.set(*s, 0);
            }
            let g = groups.entry(e).or_insert_with(Poly::zero);
            *g = &*g + &Poly::term(rest, c.clone());
        }
        TrimGroups {
            k,
            groups: groups.into_iter().collect(),
        }
    }

    /// The coefficients `c_m` (free of the trim symbols), in the order [`TrimGroups::clear_by`]
    /// asks for them.
    pub fn coefficients(&self) -> impl Iterator<Item = &Poly> {
        self.groups.iter().map(|(_, c)| c)
    }

    /// Step 8 with every coefficient lifted by [`Clearing::lift`].
    pub fn clear<C: Clearing>(&self, ring: &mut C, num: &[C::Value], den: &C::Value) -> C::Value {
        self.clear_by(ring, num, den, |ring, i| ring.lift(&self.groups[i].1))
    }

    /// Step 8 with coefficient `i` (of [`TrimGroups::coefficients`]) lifted by `lift`.
    pub fn clear_by<C: Clearing, L: std::borrow::Borrow<C::Value>>(
        &self,
        ring: &mut C,
        num: &[C::Value],
        den: &C::Value,
        lift: impl FnMut(&mut C, usize) -> L,
    ) -> C::Value {
        let mut products = TrimProducts::new(ring, den, self.k);
        self.clear_with(ring, num, den, &mut products, lift)
    }

    /// Step 8 on the trim `num / den` with the products of that trim kept in `products`
    /// (extended and reused; always the same trim for the same `products`), coefficient `i`
    /// lifted by `lift` (as a value of the ring, or a reference to one that is kept elsewhere).
    pub fn clear_with<C: Clearing, L: std::borrow::Borrow<C::Value>>(
        &self,
        ring: &mut C,
        num: &[C::Value],
        den: &C::Value,
        products: &mut TrimProducts<C::Value>,
        mut lift: impl FnMut(&mut C, usize) -> L,
    ) -> C::Value {
        assert!(num.len() <= 8, "at most eight trim quantities");
        let mut acc = ring.lift(&Poly::zero());
        for (i, (e, _)) in self.groups.iter().enumerate() {
            debug_assert_eq!(e.len(), num.len(), "one exponent per trim quantity");
            let at = products.index(ring, num, den, self.k - e.iter().sum::<u32>(), e);
            let c = lift(ring, i);
            ring.add_product(&mut acc, c.borrow(), products.get(at));
        }
        acc
    }
}

/// The products `den^j num^m` of step 8 on one trim (`t_i = num_i / den`), each built once, on
/// demand, and kept: `den^j` by the ring's power, every other one from the product with its
/// last factor removed. The groups of one quantity share their prefixes, and the quantities
/// cleared on the same trim (the trim condition, det J5, d) share the products themselves.
/// The products and their order are those of multiplying `den^j` by the factors of `num^m`
/// one by one, so a ring that records expressions (the emitter's DAG) sees the same
/// expressions, fewer times.
#[derive(Clone, Debug)]
pub struct TrimProducts<V> {
    /// `((j, m), den^j num^m)`, the exponents `m` packed a byte each ([`TrimProducts::key`]).
    memo: Vec<((u32, u64), V)>,
}

impl<V: Clone> TrimProducts<V> {
    /// The products of a trim with denominator `den` (at most eight trim quantities),
    /// starting with `den^0 .. den^k`.
    pub fn new<C: Clearing<Value = V>>(ring: &mut C, den: &V, k: u32) -> Self {
        // Room for the products of the trim quantities (k = 2, four trim states: 21), and no
        // more: for polynomial values a request of 1 KiB or above sends glibc's malloc down
        // its slow path (it consolidates its fast bins), measurably on every Monte Carlo sample.
        let mut memo = Vec::with_capacity(24);
        memo.extend((0..=k).map(|j| ((j, 0), ring.pow(den, j))));
        TrimProducts { memo }
    }

    /// The packed exponents `m` with one more factor `num_v` (each exponent at most the
    /// clearing power, far below 256).
    fn key(m: u64, v: usize) -> u64 {
        m + (1 << (8 * v))
    }

    /// The index of the product under `key`, built by `make` (from the products so far) if
    /// new.
    fn find_or(&mut self, key: (u32, u64), make: impl FnOnce(&[((u32, u64), V)]) -> V) -> usize {
        if let Some(found) = self.memo.iter().position(|(k, _)| *k == key) {
            return found;
        }
        let value = make(&self.memo);
        self.memo.push((key, value));
        self.memo.len() - 1
    }

    /// The index of `den^j num^m`, built if new.
    fn index<C: Clearing<Value = V>>(
        &mut self,
        ring: &mut C,
        num: &[V],
        den: &V,
        j: u32,
        m: &[u32],
    ) -> usize {
        let mut key = (j, 0);
        let mut at = self.find_or(key, |_| ring.pow(den, j));
        for (v, e) in m.iter().enumerate() {
            for _ in 0..*e {
                key.1 = Self::key(key.1, v);
                let prefix = at;
                at = self.find_or(key, |memo| ring.mul(&memo[prefix].1, &num[v]));
            }
        }
        at
    }

    fn get(&self, at: usize) -> &V {
        &self.memo[at].1
    }
}

/// Step 8 on the zero-sideslip trim (section V): `f` with beta0 = 0, then `alpha0, Q0, R0 =
/// num_i / den` substituted and `den^TRIM_DEGREE` cleared.
pub fn zero_sideslip_step8(f: &Poly, num: &[Poly], den: &Poly) -> Poly {
    let s = symbols();
    let f = f.subs_values(&[(s.beta0, Q::ZERO)]);
    homogenize(&f, &[s.alpha0, s.q0, s.r0], num, den, TRIM_DEGREE)
}

/// Substitutes `t_i = num_i / den` into `f` (of degree at most k in the `t_i`) and multiplies
/// by `den^k` (step 8), giving a polynomial: each term of degree j in the `t_i` gets
/// `den^(k-j)`.
pub fn homogenize(f: &Poly, t: &[Sym], num: &[Poly], den: &Poly, k: u32) -> Poly {
    clear_trim(&mut Exact, f, t, num, den, k)
}
