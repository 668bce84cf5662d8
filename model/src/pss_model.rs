//! The PSS model and its symbolic Jacobian, specialised to an aircraft and compiled for fast
//! f64 evaluation.
//!
//! Continuation and simulation evaluate the right-hand side and the Jacobian millions of times;
//! they use the equations of [`crate::equations::pss`] with the aircraft's data substituted
//! exactly and the Jacobian differentiated symbolically (no finite differences), flattened into
//! term lists. One source of truth, evaluated at machine speed.
//!
//! ```
//! use model::aircraft::Aircraft;
//! use model::pss_model::{Controls, PssModel};
//!
//! let m = PssModel::new(&Aircraft::a());
//! let u = Controls { delta_a: 0.0, delta_e: 0.0, delta_r: 0.0 };
//! // the level, non-rolling state with centred controls is an equilibrium
//! assert_eq!(m.rhs(&[0.0; 5], &u), [0.0; 5]);
//! ```

use crate::aircraft::Aircraft;
use crate::algebra::{Poly, MAX_SYMS};
use crate::equations::{pss, symbols};

/// A polynomial flattened for f64 evaluation: coefficient and (symbol index, power) factors.
#[derive(Clone, Debug)]
pub struct Compiled {
    terms: Vec<(f64, Vec<(usize, i32)>)>,
}

impl Compiled {
    /// Flattens a polynomial (coefficients rounded once to f64).
    pub fn new(p: &Poly) -> Compiled {
        Compiled {
            terms: p
                .terms()
                .iter()
                .map(|(m, c)| {
                    let f = m
                        .factors()
                        .iter()
                        .map(|(s, e)| (s.index(), *e as i32))
                        .collect();
                    (c.to_f64(), f)
                })
                .collect(),
        }
    }

    /// Evaluates with `values[sym.index()]` for every symbol.
    #[inline]
    pub fn eval(&self, values: &[f64; MAX_SYMS]) -> f64 {
        let mut acc = 0.0;
        for (c, factors) in &self.terms {
            let mut t = *c;
            for (i, e) in factors {
                t *= if *e == 1 {
                    values[*i]
                } else {
                    values[*i].powi(*e)
                };
            }
            acc += t;
        }
        acc
    }
}

/// Controls of the model, rad.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Controls {
    /// Aileron deflection, rad.
    pub delta_a: f64,
    /// Elevator deflection, rad.
    pub delta_e: f64,
    /// Rudder deflection, rad.
    pub delta_r: f64,
}

/// The PSS model of an aircraft: right-hand side, state Jacobian and control derivatives.
#[derive(Clone, Debug)]
pub struct PssModel {
    rhs: [Compiled; 5],
    jac: [[Compiled; 5]; 5],
    /// d f / d [delta_a, delta_e, delta_r] (constant columns for the linear control terms).
    dcontrol: [[Compiled; 3]; 5],
}

impl PssModel {
    /// Builds the model for `aircraft` (its data substituted exactly).
    pub fn new(aircraft: &Aircraft) -> PssModel {
        let s = symbols();
        let values = crate::specialise::aircraft_values(aircraft);
        let f = pss().map(|e| e.subs_values(&values));
        let states = s.states();
        let controls = [s.delta_a, s.delta_e, s.delta_r];
        PssModel {
            rhs: std::array::from_fn(|i| Compiled::new(&f[i])),
            jac: std::array::from_fn(|i| {
                std::array::from_fn(|j| Compiled::new(&f[i].diff(states[j])))
            }),
            dcontrol: std::array::from_fn(|i| {
                std::array::from_fn(|j| Compiled::new(&f[i].diff(controls[j])))
            }),
        }
    }

    fn values(x: &[f64; 5], u: &Controls) -> [f64; MAX_SYMS] {
        let s = symbols();
        let mut v = [0.0; MAX_SYMS];
        for (sym, val) in s.states().iter().zip(x) {
            v[sym.index()] = *val;
        }
        v[s.delta_a.index()] = u.delta_a;
        v[s.delta_e.index()] = u.delta_e;
        v[s.delta_r.index()] = u.delta_r;
        v
    }

    /// d/dt [alpha, beta, p, q, r] (Appendix A.2).
    pub fn rhs(&self, x: &[f64; 5], u: &Controls) -> [f64; 5] {
        let v = Self::values(x, u);
        std::array::from_fn(|i| self.rhs[i].eval(&v))
    }

    /// The 5x5 Jacobian d f / d x, row-major.
    pub fn jacobian(&self, x: &[f64; 5], u: &Controls) -> [[f64; 5]; 5] {
        let v = Self::values(x, u);
        std::array::from_fn(|i| std::array::from_fn(|j| self.jac[i][j].eval(&v)))
    }

    /// d f / d [delta_a, delta_e, delta_r], row-major (5 x 3).
    pub fn control_jacobian(&self, x: &[f64; 5], u: &Controls) -> [[f64; 3]; 5] {
        let v = Self::values(x, u);
        std::array::from_fn(|i| std::array::from_fn(|j| self.dcontrol[i][j].eval(&v)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn compiled_model_matches_exact_evaluation() {
        let ac = Aircraft::a();
        let m = PssModel::new(&ac);
        let x = [0.1, -0.05, 2.0, 0.3, -0.2];
        let u = Controls {
            delta_a: -0.05,
            delta_e: 0.03,
            delta_r: 0.01,
        };
        let f = m.rhs(&x, &u);
        // alpha_dot = q - p beta + z_alpha alpha
        let want = 0.3 - 2.0 * -0.05 + -3.0076 * 0.1;
        assert!((f[0] - want).abs() < 1e-15);
        let j = m.jacobian(&x, &u);
        assert_eq!(j[0][1], -2.0, "d alpha_dot / d beta = -p");
    }
}
