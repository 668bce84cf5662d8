//! Sound enclosures of the criterion polynomials over a box of data and a slab of roll rates,
//! and the branch and bound that certifies how far the primary branch is free of jumps.
//!
//! For a box X of the uncertain parameters the derivation is specialised to the fixed data only,
//! leaving polynomials in P0, delta_a and the uncertain parameters: det A, the trim condition
//! `G = g0 + g1 delta_a + g2 delta_a^2` and `J = det J5 det(A)^2`. A slab `[pa, pb] x X` is
//! *certified* when, with every enclosure outward-rounded ([`super::interval`]):
//!
//! 1. det A has no zero on it (the trim exists and is finite);
//! 2. `g1` has no zero and the discriminant `g1^2 - 4 g0 g2` is positive: the root
//!    `delta_a = -2 g0 / (g1 + sign(g1) sqrt(disc))` (the root of smaller magnitude, 0 at P0 = 0)
//!    is a continuous function on the slab with `dG/d delta_a != 0`, so it *is* the primary
//!    branch there (implicit function theorem, continued from P0 = 0 through certified slabs);
//! 3. J, evaluated with delta_a in the enclosure of that root, has no zero: no fold (saddle-node,
//!    det J5 = 0) of the primary branch in the slab.
//!
//! Each polynomial is enclosed by the mean-value form at the box centre, after a monotonicity
//! test on its gradient enclosure: a coordinate in which it is monotone over the box is fixed at
//! the face where the bound is attained.
//!
//! ```
//! use model::aircraft::{Aircraft, Param};
//! use model::clearance::bound::{BoxPolys, Failure};
//! use model::clearance::interval::I;
//!
//! // Aircraft A with l_p free in [-21.8, -21.7] 1/s (A's is -21.7529).
//! let b = BoxPolys::new(&Aircraft::a(), &[Param::Lp], 2f64.to_radians());
//! let l_p = [I::new(-21.8, -21.7)];
//! // No jump for P0 in [1.0, 1.01]: certified, with negative aileron on the primary branch.
//! let da = b.certify(I::new(1.0, 1.01), &l_p).unwrap();
//! assert!(da.hi < 0.0);
//! // The slab [1.6, 1.8] holds A's first jump (1.706 rad/s, Fig. 7): it cannot be certified.
//! assert_eq!(b.certify(I::new(1.6, 1.8), &l_p), Err(Failure::Jump));
//! ```

use super::interval::I;
use crate::aircraft::{Aircraft, Param};
use crate::algebra::{Poly, Sym};
use crate::analysis::{parametric, specialisation};
use crate::equations::symbols;
use crate::specialise::{on_trim, OnTrim};

/// A polynomial compiled for interval evaluation over the variables `[P0, theta_1, ...]`.
#[derive(Clone, Debug)]
struct Compiled {
    terms: Vec<(Vec<u32>, I)>,
    degree: Vec<u32>,
}

impl Compiled {
    fn new(p: &Poly, vars: &[Sym]) -> Compiled {
        let mut degree = vec![0; vars.len()];
        let terms = p
            .terms()
            .iter()
            .map(|(m, c)| {
                let e: Vec<u32> = vars.iter().map(|v| m.exp(*v)).collect();
                for (d, k) in degree.iter_mut().zip(&e) {
                    *d = (*d).max(*k);
                }
                (e, I::from_q(&c.to_big()))
            })
            .collect();
        Compiled { terms, degree }
    }

    fn eval(&self, x: &[I]) -> I {
        let powers: Vec<Vec<I>> = x
            .iter()
            .zip(&self.degree)
            .map(|(xi, d)| (0..=*d).map(|k| xi.powi(k)).collect())
            .collect();
        let mut sum = I::point(0.0);
        for (e, c) in &self.terms {
            let mut t = *c;
            for (i, k) in e.iter().enumerate() {
                if *k > 0 {
                    t = t * powers[i][*k as usize];
                }
            }
            sum = sum + t;
        }
        sum
    }
}

/// A polynomial with its gradient, for mean-value enclosures with monotonicity tests.
#[derive(Clone, Debug)]
struct Enclosed {
    f: Compiled,
    grad: Vec<Option<Compiled>>,
}

impl Enclosed {
    fn new(p: &Poly, vars: &[Sym]) -> Enclosed {
        let grad = vars
            .iter()
            .map(|v| {
                let d = p.diff(*v);
                (!d.is_zero()).then(|| Compiled::new(&d, vars))
            })
            .collect();
        Enclosed {
            f: Compiled::new(p, vars),
            grad,
        }
    }

    fn mean_value(&self, x: &[I], g: &[I]) -> I {
        let c: Vec<I> = x.iter().map(|xi| I::point(xi.mid())).collect();
        let mut r = self.f.eval(&c);
        for (i, gi) in g.iter().enumerate() {
            if x[i].lo != x[i].hi {
                r = r + *gi * (x[i] - c[i]);
            }
        }
        r
    }

    fn grads(&self, x: &[I]) -> Vec<I> {
        self.grad
            .iter()
            .map(|g| g.as_ref().map_or(I::point(0.0), |g| g.eval(x)))
            .collect()
    }

    /// An enclosure of the range over the box `x`.
    fn enclose(&self, x: &[I]) -> I {
        let g = self.grads(x);
        let face = |lower: bool| -> Vec<I> {
            x.iter()
                .zip(&g)
                .map(|(xi, gi)| match gi.sign() {
                    Some(s) if (s > 0.0) == lower => I::point(xi.lo),
                    Some(_) => I::point(xi.hi),
                    None => *xi,
                })
                .collect()
        };
        let (xl, xh) = (face(true), face(false));
        let lo = self.mean_value(&xl, &self.grads(&xl)).lo;
        let hi = self.mean_value(&xh, &self.grads(&xh)).hi;
        let naive = self.mean_value(x, &g);
        I::new(lo.max(naive.lo), hi.min(naive.hi))
    }
}

/// Why a slab could not be certified.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Failure {
    /// det A may vanish: the trim may diverge (Eq. 5) in the slab.
    Divergence,
    /// `dG/d delta_a` may vanish: the primary branch may turn in P0 (two trims merge).
    Turn,
    /// J may vanish: a jump may lie in the slab.
    Jump,
}

/// The criterion polynomials of one box, ready for enclosures.
#[derive(Clone, Debug)]
pub struct BoxPolys {
    /// The uncertain parameters, in the order of the box coordinates.
    pub params: Vec<Param>,
    det_a: Enclosed,
    g: [Enclosed; 3],
    j: Vec<Enclosed>,
    /// The trim condition in `[P0, delta_a, theta...]`.
    g_full: Enclosed,
    /// Whether the trim at P0 = 0 is delta_a = 0 for every aircraft of the box (exactly).
    pub symmetric: bool,
}

impl BoxPolys {
    /// Specialises the derivation to `aircraft` at `delta_e_rad` except for `params`.
    pub fn new(aircraft: &Aircraft, params: &[Param], delta_e_rad: f64) -> BoxPolys {
        let s = symbols();
        let par = parametric();
        let free: Vec<Sym> = params.iter().map(|p| s.param(*p)).collect();
        let values: Vec<_> = specialisation(aircraft, delta_e_rad)
            .into_iter()
            .filter(|(sym, _)| !free.contains(sym))
            .collect();
        let OnTrim {
            det_a,
            trim_condition: g,
            jump_at: j,
            ..
        } = on_trim(par, &values);
        let mut vars = vec![s.p0];
        vars.extend(&free);
        let gc = g.coeffs(s.delta_a);
        let get = |k: usize| gc.get(k).cloned().unwrap_or_else(Poly::zero);
        let symmetric = get(0).subs(s.p0, &Poly::zero()).is_zero();
        let mut vars_da = vec![s.p0, s.delta_a];
        vars_da.extend(&free);
        BoxPolys {
            g_full: Enclosed::new(&g, &vars_da),
            params: params.to_vec(),
            det_a: Enclosed::new(&det_a, &vars),
            g: [0, 1, 2].map(|k| Enclosed::new(&get(k), &vars)),
            j: j.coeffs(s.delta_a)
                .iter()
                .map(|c| Enclosed::new(c, &vars))
                .collect(),
            symmetric,
        }
    }

    /// An enclosure of the primary branch's aileron over `p x theta`, or why there is none.
    pub fn aileron(&self, p: I, theta: &[I]) -> Result<I, Failure> {
        let mut x = vec![p];
        x.extend_from_slice(theta);
        if self.det_a.enclose(&x).contains_zero() {
            return Err(Failure::Divergence);
        }
        let [g0, g1, g2] = [0, 1, 2].map(|k| self.g[k].enclose(&x));
        let Some(s) = g1.sign() else {
            return Err(Failure::Turn);
        };
        let disc = g1.sqr() - I::point(4.0) * g0 * g2;
        if disc.lo <= 0.0 {
            return Err(Failure::Turn);
        }
        let root = disc.sqrt().ok_or(Failure::Turn)?;
        let den = g1 + I::point(s) * root;
        (I::point(-2.0) * g0).checked_div(den).ok_or(Failure::Turn)
    }

    /// A lower bound of |delta_a| on the primary branch at roll rate `p` over `theta`, given
    /// the enclosure `da` of it there (which must exclude 0): the largest |delta| (of the sign
    /// of `da`) such that the trim condition has no zero for delta_a between 0 and delta, found
    /// by bisection. Since the primary root is the first root met from delta_a = 0 in its
    /// direction, it lies beyond delta.
    pub fn aileron_lower(&self, p: f64, theta: &[I], da: I) -> f64 {
        let Some(sign) = da.sign() else {
            return 0.0;
        };
        let free_of_roots = |delta: f64| {
            let seg = if sign > 0.0 {
                I::new(0.0, delta)
            } else {
                I::new(-delta, 0.0)
            };
            let mut x = vec![I::point(p), seg];
            x.extend_from_slice(theta);
            !self.g_full.enclose(&x).contains_zero()
        };
        let (mut ok, mut bad) = (da.lo.abs().min(da.hi.abs()), da.mag());
        if !free_of_roots(ok) {
            return 0.0;
        }
        for _ in 0..24 {
            let m = 0.5 * (ok + bad);
            if free_of_roots(m) {
                ok = m;
            } else {
                bad = m;
            }
        }
        ok
    }

    /// Certifies the slab `p x theta` (see the module documentation); on success returns the
    /// enclosure of the primary branch's aileron on it.
    pub fn certify(&self, p: I, theta: &[I]) -> Result<I, Failure> {
        let da = self.aileron(p, theta)?;
        let mut x = vec![p];
        x.extend_from_slice(theta);
        let mut j = I::point(0.0);
        for c in self.j.iter().rev() {
            j = j * da + c.enclose(&x);
        }
        if j.contains_zero() {
            return Err(Failure::Jump);
        }
        Ok(da)
    }
}
