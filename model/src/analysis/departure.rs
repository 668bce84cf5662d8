//! Beyond the paper: Hopf points from the closed form, their first Lyapunov coefficient, where a
//! jump lands, and the first loss of stability along the primary branch.
//!
//! The Hopf polynomial is [`crate::derivation::hopf`]'s `det(A)^10 Delta4` specialised to the
//! aircraft (the cleared characteristic coefficients `C_k` are built from the same trim
//! numerators as the jump polynomial, and delta_a is eliminated by [`eliminate_aileron`]). Its
//! roots include neutral saddles; `omega^2 = (c1 c4 - c5) / (c1 c2 - c3)` (derived in
//! [`crate::derivation::hopf::orlando`]) tells them apart.

use super::primary::Walk;
use super::unstable_trim::{self, Start, UnstableTrim};
use super::{
    aileron_of_root, exact_f64, parametric_characteristic, specialisation, strip, univariate,
    CriterionPolys, InAileron, JumpPoint,
};
use crate::aircraft::Aircraft;
use crate::algebra::{Poly, PolyF64, Sym, Q};
use crate::derivation::eliminate_aileron;
use crate::derivation::hopf::{cleared_coefficients, hopf_at, orlando, Orlando};
use crate::equations::symbols;
use crate::roots::{real_roots, UPoly};
use crate::specialise::from_univariate;
use crate::specialise::hopf::{dense_hopf, weighted_integer};
use crate::specialise::hopf_in_aileron::{
    dense_in_aileron, from_in_aileron, stripped_hopf_in_aileron,
};
use nalgebra::{Complex, Matrix5, Vector5};
use serde::Serialize;

/// A Hopf point of the unconstrained roll: a trim where a complex pair of J5 crosses the
/// imaginary axis.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct HopfPoint {
    /// The trim (same keys as a jump entry).
    #[serde(flatten)]
    pub point: JumpPoint,
    /// The frequency of the pair `+-i omega`, rad/s.
    pub omega: f64,
    /// The period `2 pi / omega`, s.
    pub period: f64,
    /// First Lyapunov coefficient (Kuznetsov's formula, eigenvectors normalised `<q, q> = 1`,
    /// `<p, q> = 1`).
    pub l1: f64,
    /// `"supercritical"` (l1 < 0) or `"subcritical"` (l1 > 0).
    pub kind: &'static str,
}

/// A stable equilibrium a jump can land on (same aileron as the fold).
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct Landing {
    /// Roll rate after the jump, rad/s.
    pub p0: f64,
    /// Angle of attack, rad.
    pub alpha: f64,
    /// Sideslip, rad.
    pub beta: f64,
    /// Pitch rate, rad/s.
    pub q: f64,
    /// Yaw rate, rad/s.
    pub r: f64,
}

/// The first loss of stability met along the primary branch: its start itself when that trim is
/// unstable.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct FirstDeparture {
    /// `"jump"`, `"hopf"` or `"unstable_trim"` (the trim at P0 = 0, delta_a = 0, where the branch
    /// starts, is unstable: the bare airframe needs its stability augmentation there).
    pub kind: &'static str,
    /// Trim roll rate, rad/s.
    pub p0: f64,
    /// Aileron deflection, rad (the mirror point has the opposite sign and -P0).
    pub delta_a_rad: f64,
    /// The same in degrees.
    pub delta_a_deg: f64,
    /// For a jump or Hopf point: the trim's angle of attack there, rad (the increment from the
    /// analysed trim, as in the jump and Hopf tables).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub alpha: Option<f64>,
    /// For a jump or Hopf point: the trim's sideslip there, rad.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub beta: Option<f64>,
    /// For a jump or Hopf point: whether |alpha| and |beta| there lie within the `[validity]`
    /// range of the linear aerodynamics. Outside it the departure is the model's, which the
    /// aircraft's aerodynamics need not share.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub within_validity: Option<bool>,
    /// For a Hopf point: its frequency, rad/s.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub omega: Option<f64>,
    /// For a Hopf point: its first Lyapunov coefficient.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub l1: Option<f64>,
    /// For a Hopf point: supercritical or subcritical.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub hopf_kind: Option<&'static str>,
    /// For a jump: the stable equilibria it can land on (empty: divergence).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lands_at: Option<Vec<Landing>>,
    /// For an unstable trim: the trim and its unstable modes.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub unstable_trim: Option<UnstableTrim>,
}

impl FirstDeparture {
    /// Whether it is a jump or Hopf point whose trim lies outside the validity range.
    pub fn outside_validity(&self) -> bool {
        self.within_validity == Some(false)
    }

    /// The departure of `kind` at the jump or Hopf point `j`: its roll rate, aileron, trim
    /// angles and validity, the rest of its kind's fields to be filled in.
    fn at_point(kind: &'static str, j: &JumpPoint) -> FirstDeparture {
        FirstDeparture {
            kind,
            p0: j.p0,
            delta_a_rad: j.delta_a_rad,
            delta_a_deg: j.delta_a_deg,
            alpha: Some(j.alpha),
            beta: Some(j.beta),
            within_validity: Some(j.within_validity),
            omega: None,
            l1: None,
            hopf_kind: None,
            lands_at: None,
            unstable_trim: None,
        }
    }

    /// The departure at the branch's start, P0 = 0 and delta_a = 0, whose trim is `u`.
    fn at_start(u: UnstableTrim) -> FirstDeparture {
        FirstDeparture {
            kind: "unstable_trim",
            p0: 0.0,
            delta_a_rad: 0.0,
            delta_a_deg: 0.0,
            alpha: None,
            beta: None,
            within_validity: None,
            omega: None,
            l1: None,
            hopf_kind: None,
            lands_at: None,
            unstable_trim: Some(u),
        }
    }
}

/// The Hopf part of the closed form specialised to one aircraft.
#[derive(Clone, Debug)]
pub struct HopfPolys {
    /// `det(A)^10 Delta4` at the trim, in P0 and delta_a (with aileron yaw `det(A)^6 Delta4`,
    /// the factor taken out before the resultant: [`crate::specialise::hopf_in_aileron`]).
    pub hopf_at: Poly,
    /// The Hopf polynomial in P0 (delta_a eliminated, det A's roots removed).
    pub hopf: UPoly,
    /// The Hopf polynomial of the zero-sideslip trims in P0 (`det(A1)^10 Delta4`).
    pub zs_hopf: UPoly,
    /// J5, its characteristic coefficients and the model's derivatives, in trim symbols.
    pub local: LocalPolys,
}

/// What the departure part evaluates in f64 at a trim: the entries of J5, its characteristic
/// coefficients `c1..c5` and the second and third derivatives of the PSS right-hand side, as
/// polynomials in the trim symbols, specialised to an aircraft (exact path) or parametric (the
/// certified route, evaluated with the aircraft's values, see [`AtTrim`]).
#[derive(Clone, Debug)]
pub struct LocalPolys {
    /// `c1..c5`.
    pub c: [Poly; 5],
    /// Entries of J5 (row-major).
    pub jacobian: Vec<Poly>,
    /// Second derivatives `d2 f_i / dx_j dx_k` of the PSS right-hand side (constants for the
    /// quadratic PSS model), index `[i][j][k]`.
    pub second: Vec<Poly>,
    /// Third derivatives, index `[i][j][k][l]` (identically zero for the PSS model; kept so
    /// Kuznetsov's formula is complete).
    pub third: Vec<Poly>,
    /// The same prepared for f64 evaluation: `c`, `jacobian`, `second`, `third` in one list.
    f64s: Vec<PolyF64>,
}

impl LocalPolys {
    /// From the characteristic coefficients, J5's entries and the model's right-hand side
    /// (whose derivatives are taken here).
    fn new(c: [Poly; 5], jacobian: Vec<Poly>, model: &[Poly]) -> LocalPolys {
        let x = symbols().states();
        let mut second = Vec::with_capacity(125);
        let mut third = Vec::with_capacity(625);
        for f in model {
            for a in x {
                for b in x {
                    let fab = f.diff(a).diff(b);
                    for c in x {
                        third.push(fab.diff(c));
                    }
                    second.push(fab);
                }
            }
        }
        let f64s = c
            .iter()
            .chain(&jacobian)
            .chain(&second)
            .chain(&third)
            .map(Poly::to_f64_form)
            .collect();
        LocalPolys {
            c,
            jacobian,
            second,
            third,
            f64s,
        }
    }

    /// The parametric derivation's (every parameter a symbol), derived once per process.
    pub fn parametric() -> &'static LocalPolys {
        static L: std::sync::OnceLock<LocalPolys> = std::sync::OnceLock::new();
        L.get_or_init(|| LocalPolys::of(&|p: &Poly| p.clone()))
    }

    /// The parametric polynomials through `map` (e.g. a substitution of an aircraft's data).
    fn of(map: &dyn Fn(&Poly) -> Poly) -> LocalPolys {
        let par = super::parametric();
        let jacobian = (0..5)
            .flat_map(|i| (0..5).map(move |j| (i, j)))
            .map(|(i, j)| map(par.jacobian.get(i, j)))
            .collect();
        let model: Vec<Poly> = par.unconstrained_model.iter().map(map).collect();
        LocalPolys::new(
            parametric_characteristic().clone().map(|ck| map(&ck)),
            jacobian,
            &model,
        )
    }

    /// Evaluation at trims with `values` for the other symbols ([`AtTrim`]).
    pub fn at<'a>(&'a self, values: &[(Sym, f64)]) -> AtTrim<'a> {
        let mut v = vec![f64::NAN; crate::algebra::MAX_SYMS];
        for (s, x) in values {
            v[s.index()] = *x;
        }
        AtTrim {
            polys: self,
            values: v,
        }
    }
}

/// [`LocalPolys`] evaluated in f64 at trims `[alpha0, beta0, P0, Q0, R0]`, with fixed values of
/// the other symbols (none on the exact path; the aircraft's data and controls on the certified
/// route): one routine for both routes.
#[derive(Clone, Debug)]
pub struct AtTrim<'a> {
    polys: &'a LocalPolys,
    /// Values by symbol index (NaN: none).
    values: Vec<f64>,
}

impl HopfPolys {
    /// Specialises the Hopf criterion to an aircraft (delta_r = 0).
    pub fn new(cp: &CriterionPolys, aircraft: &Aircraft, delta_e_rad: f64) -> HopfPolys {
        let s = symbols();
        let values = specialisation(aircraft, delta_e_rad);
        let local = LocalPolys::of(&|p: &Poly| p.subs_values(&values));
        // Integer coefficients for the exact polynomials; `local.c` itself stays for f64
        // evaluation.
        let (ci, _) = weighted_integer(&local.c);
        let t4 = [s.alpha0, s.beta0, s.q0, s.r0];
        // Without aileron yaw everything is univariate in P0: dense arithmetic is much faster.
        let (hopf_at, hopf) = match dense_hopf(&ci, &t4, &cp.trim, &cp.det_a) {
            Some(u) => (from_univariate(&u), u),
            // With aileron yaw, det A's factor det(A)^4 is taken out before the resultant.
            None => {
                let g = dense_in_aileron(&cp.trim_condition);
                match stripped_hopf_in_aileron(&ci, &t4, &cp.trim, &cp.det_a) {
                    Some(h) if g.len() == 3 && h.len() >= 3 => {
                        (from_in_aileron(&h), resultant_dense(&g, &h))
                    }
                    _ => {
                        let cleared = cleared_coefficients(&ci, &t4, &cp.trim, &cp.det_a);
                        let hopf_at = hopf_at(&cleared);
                        let hopf = resultant_in_aileron(&cp.trim_condition, &hopf_at);
                        (hopf_at, hopf)
                    }
                }
            }
        };
        let hopf = strip(&hopf, &univariate(&cp.det_a, s.p0));
        let zero = [(s.beta0, Q::ZERO)];
        let t3 = [s.alpha0, s.q0, s.r0];
        let czs = ci.map(|ck| ck.subs_values(&zero));
        let zs_hopf = dense_hopf(&czs, &t3, &cp.zs_trim, &cp.zs_det)
            .unwrap_or_else(|| univariate(&hopf_at_zs(&czs, &t3, &cp.zs_trim, &cp.zs_det), s.p0));
        let zs_hopf = strip(&zs_hopf, &univariate(&cp.zs_det, s.p0));
        HopfPolys {
            hopf_at,
            hopf,
            zs_hopf,
            local,
        }
    }

    /// The f64 evaluation at trims (the polynomials hold no other symbol).
    pub fn at_trim(&self) -> AtTrim<'_> {
        self.local.at(&[])
    }
}

impl AtTrim<'_> {
    fn lookup(&self, trim: &[f64; 5]) -> impl Fn(Sym) -> f64 + '_ {
        let t = symbols().trims();
        let trim = *trim;
        move |x: Sym| {
            t.iter()
                .position(|y| *y == x)
                .map_or(self.values[x.index()], |i| trim[i])
        }
    }

    /// J5 at a trim `[alpha0, beta0, P0, Q0, R0]` in f64.
    pub fn j5(&self, trim: &[f64; 5]) -> Matrix5<f64> {
        let look = self.lookup(trim);
        let jacobian = &self.polys.f64s[5..30];
        Matrix5::from_fn(|i, j| jacobian[5 * i + j].eval(&look))
    }

    /// `c1..c5` at a trim in f64.
    pub fn coefficients(&self, trim: &[f64; 5]) -> [f64; 5] {
        let look = self.lookup(trim);
        std::array::from_fn(|k| self.polys.f64s[k].eval(&look))
    }

    /// The first Lyapunov coefficient at a Hopf trim with frequency `omega` (Kuznetsov,
    /// *Elements of Applied Bifurcation Theory*, Eq. 3.20 in its n-dimensional form):
    /// `l1 = Re[<p, C(q,q,qb)> - 2 <p, B(q, A^-1 B(q,qb))> + <p, B(qb, (2 i omega - A)^-1 B(q,q))>]
    /// / (2 omega)`, with `A q = i omega q`, `A^T p = -i omega p`, `<p, q> = 1`.
    pub fn lyapunov(&self, trim: &[f64; 5], omega: f64) -> Option<f64> {
        let look = self.lookup(trim);
        let sec: Vec<f64> = self.polys.f64s[30..155]
            .iter()
            .map(|p| p.eval(&look))
            .collect();
        let thi: Vec<f64> = self.polys.f64s[155..]
            .iter()
            .map(|p| p.eval(&look))
            .collect();
        let a = self.j5(trim).map(|v| Complex::new(v, 0.0));
        let iw = Complex::new(0.0, omega);
        let q = null_vector(&(a - Matrix5::from_diagonal_element(iw)))?;
        let q = q.unscale(q.norm());
        let p = null_vector(&(a.transpose() + Matrix5::from_diagonal_element(iw)))?;
        // <p, q> = p^H q = 1.
        let pq = p.dotc(&q);
        if pq.norm() == 0.0 {
            return None;
        }
        let p = p * pq.conj().inv();
        let b = |u: &Vector5<Complex<f64>>, v: &Vector5<Complex<f64>>| {
            Vector5::from_fn(|i, _| {
                let mut acc = Complex::new(0.0, 0.0);
                for j in 0..5 {
                    for k in 0..5 {
                        acc += sec[25 * i + 5 * j + k] * u[j] * v[k];
                    }
                }
                acc
            })
        };
        let cterm = Vector5::from_fn(|i, _| {
            let mut acc = Complex::new(0.0, 0.0);
            for j in 0..5 {
                for k in 0..5 {
                    for l in 0..5 {
                        acc += thi[125 * i + 25 * j + 5 * k + l] * q[j] * q[k] * q[l].conj();
                    }
                }
            }
            acc
        });
        let qb = q.map(|z| z.conj());
        let a_inv_b = a.lu().solve(&b(&q, &qb))?;
        let shifted = Matrix5::from_diagonal_element(iw * 2.0) - a;
        let s_inv_b = shifted.lu().solve(&b(&q, &q))?;
        let inner = p.dotc(&cterm) - p.dotc(&b(&q, &a_inv_b)) * 2.0 + p.dotc(&b(&qb, &s_inv_b));
        let l1 = inner.re / (2.0 * omega);
        l1.is_finite().then_some(l1)
    }

    /// Whether the trim is asymptotically stable (every eigenvalue of J5 in the left half-plane);
    /// `None` when J5's eigenvalues cannot be computed ([`crate::spectrum::eigenvalues`]).
    pub fn stable(&self, trim: &[f64; 5]) -> Option<bool> {
        crate::spectrum::stable(&self.j5(trim))
    }
}

/// The resultant in delta_a of the trim condition `g` and `f` (both in P0 and delta_a), as a
/// polynomial in P0: the same resultant as [`eliminate_aileron`] (numeric data, actual degrees),
/// computed in the dense univariate ring when `g` is quadratic, because the Hopf polynomial's
/// resultant exceeds the packed monomials' exponent range (P0 degree above 127).
///
/// With `g = g2 x^2 + g1 x + g0` and `f` of degree `n >= 2` in `x = delta_a`, the pseudo-remainder
/// `R = g2^(n-1) f mod g = R1 x + R0` gives `Res(g, f) = Res(g, R) / g2^(n-1)` and
/// `Res(g, R1 x + R0) = g2 R0^2 - g1 R0 R1 + g0 R1^2`; the division is exact.
pub fn resultant_in_aileron(g: &Poly, f: &Poly) -> UPoly {
    let s = symbols();
    if g.degree(s.delta_a) < 2 || f.degree(s.delta_a) < 2 {
        return univariate(&eliminate_aileron(g, f), s.p0);
    }
    resultant_dense(&dense_in_aileron(g), &dense_in_aileron(f))
}

/// [`resultant_in_aileron`] of `g` (quadratic in delta_a) and `f` (of degree at least 2 in it),
/// each given by its coefficients of `delta_a^0, delta_a^1, ...` as dense polynomials in P0.
pub fn resultant_dense(gc: &[UPoly], f: &[UPoly]) -> UPoly {
    assert_eq!(
        gc.len(),
        3,
        "the trim condition is at most quadratic in delta_a"
    );
    let (g0, g1, g2) = (&gc[0], &gc[1], &gc[2]);
    let mut h = f.to_vec();
    let n = h.len() - 1;
    for i in (2..=n).rev() {
        let c = h[i].clone();
        for hj in h.iter_mut().take(i) {
            *hj = hj.mul(g2);
        }
        h[i - 1] = h[i - 1].sub(&c.mul(g1));
        h[i - 2] = h[i - 2].sub(&c.mul(g0));
        h[i] = UPoly::zero();
    }
    let (r0, r1) = (&h[0], &h[1]);
    let mut res = g2
        .mul(&r0.mul(r0))
        .sub(&g1.mul(&r0.mul(r1)))
        .add(&g0.mul(&r1.mul(r1)));
    for _ in 0..n - 1 {
        res = res.div_exact(g2).expect("Res(g, R) carries g2^(n-1)");
    }
    res
}

/// `den^10 Delta4` at the zero-sideslip trim (beta0 = 0 already substituted into `c`).
fn hopf_at_zs(c: &[Poly; 5], t: &[Sym], num: &[Poly], den: &Poly) -> Poly {
    hopf_at(&cleared_coefficients(c, t, num, den))
}

/// A null vector of a (numerically) singular 5x5 complex matrix: the row with the smallest
/// pivot is replaced by the normalisation `x_k = 1`, choosing `k` for the smallest residual.
pub(super) fn null_vector(m: &Matrix5<Complex<f64>>) -> Option<Vector5<Complex<f64>>> {
    let mut best: Option<(f64, Vector5<Complex<f64>>)> = None;
    for row in 0..5 {
        for k in 0..5 {
            let mut a = *m;
            let mut rhs = Vector5::zeros();
            for j in 0..5 {
                a[(row, j)] = Complex::new(if j == k { 1.0 } else { 0.0 }, 0.0);
            }
            rhs[row] = Complex::new(1.0, 0.0);
            if let Some(x) = a.lu().solve(&rhs) {
                let res = (m * x).norm() / x.norm();
                if res.is_finite() && best.as_ref().is_none_or(|(r, _)| res < *r) {
                    best = Some((res, x));
                }
            }
        }
    }
    best.map(|(_, x)| x)
}

/// The Hopf points of the unconstrained roll at the positive roots `roots` (ascending) of the
/// Hopf polynomial, whose value in P0 and delta_a is `hopf_ia`: those with omega^2 > 0, with
/// their trim, omega, period and l1.
pub(crate) fn hopf_points(
    at: &AtTrim<'_>,
    roots: &[f64],
    hopf_ia: &InAileron,
    g: &InAileron,
    trims: &[InAileron],
    marks: (&Aircraft, f64),
) -> Vec<HopfPoint> {
    roots
        .iter()
        .filter_map(|&p0| {
            let da = hopf_aileron(at, g, hopf_ia, trims, p0)?;
            hopf_point(at, p0, da, trims, marks)
        })
        .collect()
}

/// The Hopf point at the root `p0` of the Hopf polynomial on the trim of aileron `da`, with its
/// omega, period and l1; `None` for a neutral saddle (omega^2 <= 0) or values that cannot be
/// computed.
pub(crate) fn hopf_point(
    at: &AtTrim<'_>,
    p0: f64,
    da: f64,
    trims: &[InAileron],
    marks: (&Aircraft, f64),
) -> Option<HopfPoint> {
    let point = trim_point(p0, da, trims, marks);
    let t = [point.alpha, point.beta, p0, point.q, point.r];
    let omega = omega_at(orlando(), &at.coefficients(&t))?;
    let l1 = at.lyapunov(&t, omega)?;
    Some(HopfPoint {
        point,
        omega,
        period: 2.0 * std::f64::consts::PI / omega,
        l1,
        kind: if l1 < 0.0 {
            "supercritical"
        } else {
            "subcritical"
        },
    })
}

/// The aileron of the trim at a root `p0` of the Hopf polynomial: of the trims of that roll rate
/// (roots of the trim condition), the one where Delta4, evaluated from the characteristic
/// coefficients at the trim, is smallest relative to the size of its terms. The high degree of
/// `hopf_at` in delta_a makes its own value a poor guide with aileron yaw. `None` when no trim is
/// real.
fn hopf_aileron(
    h: &AtTrim<'_>,
    g: &InAileron,
    hopf_ia: &InAileron,
    trims: &[InAileron],
    p0: f64,
) -> Option<f64> {
    let mut candidates = g.aileron_roots(p0).to_vec();
    if candidates.len() < 2 {
        let da = aileron_of_root(g, hopf_ia, p0);
        return da.is_finite().then_some(da);
    }
    let hs = crate::derivation::hopf::hopf_symbols();
    let delta4 = &orlando().delta4;
    let relative = |da: f64| {
        let dv = trims[0].eval(p0, 0.0);
        let [alpha, beta, q, r] = std::array::from_fn(|i| trims[i + 1].eval(p0, da) / dv);
        let c = h.coefficients(&[alpha, beta, p0, q, r]);
        let look = |x: Sym| hs.c.iter().position(|y| *y == x).map_or(f64::NAN, |i| c[i]);
        let (mut sum, mut size) = (0.0, 0.0);
        for (m, coef) in delta4.terms() {
            let t = Poly::term(*m, coef.clone()).eval_f64(&look);
            sum += t;
            size += t.abs();
        }
        (sum / size).abs()
    };
    candidates.sort_by(|a, b| relative(*a).total_cmp(&relative(*b)));
    candidates.first().copied()
}

/// `omega` from `omega^2 = (c1 c4 - c5) / (c1 c2 - c3)` when positive (a Hopf pair), `None` for
/// a neutral saddle (`omega^2 < 0`) or a degenerate root.
pub fn omega_at(o: &Orlando, c: &[f64; 5]) -> Option<f64> {
    let hs = crate::derivation::hopf::hopf_symbols();
    let look = |x: Sym| hs.c.iter().position(|y| *y == x).map_or(f64::NAN, |i| c[i]);
    let w = o.omega_sq.num.eval_f64(&look) / o.omega_sq.den.eval_f64(&look);
    (w.is_finite() && w > 0.0).then(|| w.sqrt())
}

/// The trim at `(p0, delta_a)` as a [`JumpPoint`] (no landing), marked with the aircraft's
/// limits and validity range at elevator `marks.1`.
pub(crate) fn trim_point(
    p0: f64,
    da: f64,
    trims: &[InAileron],
    marks: (&Aircraft, f64),
) -> JumpPoint {
    let dv = trims[0].eval(p0, 0.0);
    let [alpha, beta, q, r] = std::array::from_fn(|i| trims[i + 1].eval(p0, da) / dv);
    JumpPoint {
        p0,
        delta_a_rad: da,
        delta_a_deg: da.to_degrees(),
        alpha,
        beta,
        q,
        r,
        within_limits: marks.0.within_limits(da, marks.1, None),
        within_validity: marks.0.valid(alpha, beta),
        lands_at: None,
    }
}

/// The real roots in P0 of the trim condition at the (exact) aileron of the fold `fold`, det A's
/// roots removed: where the jump can land, before the stability check of [`landings`].
pub(super) fn landing_roots(cp: &CriterionPolys, fold: &JumpPoint) -> Vec<f64> {
    let s = symbols();
    let at = cp
        .trim_condition
        .subs_values(&[(s.delta_a, exact_f64(fold.delta_a_rad))]);
    let det_a = univariate(&cp.det_a, s.p0);
    let g = strip(&univariate(&at, s.p0), &det_a);
    if g.is_zero() {
        return Vec::new();
    }
    real_roots(&g).iter().map(|r| r.value).collect()
}

/// The roll rates within which a root of the trim condition at the fold's aileron is the fold
/// itself: the fold is a double root at its exact aileron, and the rounded aileron splits it.
pub(crate) fn fold_window(fold: &JumpPoint) -> (f64, f64) {
    let tol = 1e-6 * (1.0 + fold.p0.abs());
    (fold.p0 - tol, fold.p0 + tol)
}

/// Every stable equilibrium at the aileron of the fold `fold` other than the fold itself: of the
/// real roots `roots` of the trim condition at that aileron ([`landing_roots`]), those outside
/// [`fold_window`] with finite trims and all eigenvalues of J5 in the left half-plane (a trim
/// whose eigenvalues cannot be computed is not offered as a landing).
pub(crate) fn landings(
    at: &AtTrim<'_>,
    trims: &[InAileron],
    fold: &JumpPoint,
    roots: &[f64],
) -> Vec<Landing> {
    let (lo, hi) = fold_window(fold);
    roots
        .iter()
        .copied()
        .filter(|p| !(lo..=hi).contains(p))
        .filter_map(|p0| {
            let dv = trims[0].eval(p0, 0.0);
            let [alpha, beta, q, r] =
                std::array::from_fn(|i| trims[i + 1].eval(p0, fold.delta_a_rad) / dv);
            let t = [alpha, beta, p0, q, r];
            (t.iter().all(|v| v.is_finite()) && at.stable(&t) == Some(true)).then_some(Landing {
                p0,
                alpha,
                beta,
                q,
                r,
            })
        })
        .collect()
}

/// Whether the trim at `P0 = 0, delta_a = 0` (the primary branch's start) is stable: when it
/// is not, it is the first departure, whatever lies along the branch.
pub(crate) fn start(h: &AtTrim<'_>, trims: &[InAileron]) -> Start {
    let dv = trims[0].eval(0.0, 0.0);
    let origin: [f64; 5] = [
        trims[1].eval(0.0, 0.0) / dv,
        trims[2].eval(0.0, 0.0) / dv,
        0.0,
        trims[3].eval(0.0, 0.0) / dv,
        trims[4].eval(0.0, 0.0) / dv,
    ];
    unstable_trim::start(&h.j5(&origin), &origin)
}

/// The first loss of stability along the primary branch: the wings-level trim P0 = 0,
/// delta_a = 0 itself when an eigenvalue of J5 there lies in the right half-plane
/// ([`unstable_trim::start`]), else the first jump or Hopf point the branch meets when followed
/// from that trim towards P0 > 0. The trim is the one the analysis computes at P0 = 0 (the trim
/// numerators over det A), wherever the elevator puts it. With delta_r = 0 the model is
/// symmetric under `(P0, beta, r, delta_a) -> -(...)`, so the other aileron direction meets the
/// mirror point (-P0, -delta_a) with the same kind, omega and l1 (the symmetry maps J5 to a
/// similar matrix). `None` when the wings-level trim's stability is undecided (an eigenvalue on
/// the imaginary axis within rounding, or none computed), or the branch diverges or runs off the
/// aileron range first. `start` is that trim's stability ([`start`]), `walk` the branch's.
pub(crate) fn first_departure(
    start: Start,
    jump: &[JumpPoint],
    hopf: &[HopfPoint],
    walk: &Walk,
) -> Option<FirstDeparture> {
    match start {
        Start::Stable => {}
        Start::Unstable(u) => return Some(FirstDeparture::at_start(u)),
        Start::Undecided => return None,
    }
    let hits: Vec<(f64, f64)> = jump
        .iter()
        .map(|j| (j.p0, j.delta_a_rad))
        .chain(hopf.iter().map(|h| (h.point.p0, h.point.delta_a_rad)))
        .collect();
    let i = match walk.first(&hits).0 {
        super::Outcome::Jump(i) => i,
        _ => return None,
    };
    if let Some(j) = jump.get(i) {
        return Some(FirstDeparture {
            lands_at: j.lands_at.clone(),
            ..FirstDeparture::at_point("jump", j)
        });
    }
    let hp = hopf.get(i - jump.len())?;
    Some(FirstDeparture {
        omega: Some(hp.omega),
        l1: Some(hp.l1),
        hopf_kind: Some(hp.kind),
        ..FirstDeparture::at_point("hopf", &hp.point)
    })
}

/// The zero-sideslip Hopf roll rates: of the positive roots `roots` of the zero-sideslip Hopf
/// polynomial, those whose omega^2 at the beta = 0 trim is positive, with their omega.
pub(crate) fn zs_hopf_roll_rates(
    h: &AtTrim<'_>,
    roots: &[f64],
    zs_trims: &[InAileron],
) -> Vec<(f64, f64)> {
    let o = orlando();
    roots
        .iter()
        .filter_map(|&p0| {
            let dv = zs_trims[0].eval(p0, 0.0);
            let [alpha, q, r] = std::array::from_fn(|i| zs_trims[i + 1].eval(p0, 0.0) / dv);
            let c = h.coefficients(&[alpha, 0.0, p0, q, r]);
            omega_at(o, &c).map(|w| (p0, w))
        })
        .collect()
}

/// The departure part of the checks every answer passes: every Hopf point, landing and
/// zero-sideslip Hopf roll rate finite; `Err` names the value.
pub(super) fn check_finite(a: &super::Analysis) -> Result<(), String> {
    for h in &a.hopf {
        let j = &h.point;
        let finite = |v: &[f64]| v.iter().all(|x| x.is_finite());
        if !(finite(&j.numbers()) && finite(&[h.omega, h.period, h.l1])) {
            return Err(format!("the Hopf point at P0 = {:e} rad/s", j.p0));
        }
    }
    if let Some(u) = a
        .first_departure
        .as_ref()
        .and_then(|f| f.unstable_trim.as_ref())
    {
        let modes = u
            .modes
            .iter()
            .flat_map(|m| [m.eigenvalue_re, m.eigenvalue_im]);
        if !modes.chain([u.alpha, u.beta, u.q, u.r]).all(f64::is_finite) {
            return Err("the unstable trim at P0 = 0".into());
        }
    }
    for j in &a.jump {
        for l in j.lands_at.iter().flatten() {
            if ![l.p0, l.alpha, l.beta, l.q, l.r]
                .iter()
                .all(|x| x.is_finite())
            {
                return Err(format!("where the jump at P0 = {:e} rad/s lands", j.p0));
            }
        }
    }
    Ok(())
}
