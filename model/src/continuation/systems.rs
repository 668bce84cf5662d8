//! The three systems continued: the unconstrained PSS model of Appendix A.2 in one control
//! (section II.B, Figs 1-4), and the two steps of the extended bifurcation analysis of the
//! zero-sideslip roll (section V.B, Eqs 36-37, Fig. 9).
//!
//! All derivatives come from [`PssModel`]: its symbolic Jacobian and control derivatives,
//! compiled. The zero-sideslip rudder schedule is the closed-form trim of Eqs 32-35 (beta = 0:
//! alpha, q, r from a 3x3 linear system at given P0, then delta_a from the roll equation and
//! delta_r from the yaw equation), differentiated in P0 exactly through the same linear system.

use super::engine::{Eval, System, V6};
use crate::pss_model::{Controls, PssModel};
use nalgebra::{Matrix3, Matrix5, Vector3, Vector5};

fn mat5(a: &[[f64; 5]; 5]) -> Matrix5<f64> {
    Matrix5::from_fn(|i, j| a[i][j])
}

fn finite(e: Eval) -> Option<Eval> {
    let ok =
        e.f.iter()
            .chain(e.jy.iter())
            .chain(e.fmu.iter())
            .all(|v| v.is_finite());
    ok.then_some(e)
}

/// The unconstrained model in one control: `z = (alpha, beta, p, q, r, mu)`.
pub(crate) struct Unconstrained<'a> {
    pub model: &'a PssModel,
    /// Values of the controls that are held fixed (the continued one is overwritten).
    pub base: Controls,
    /// Which control is continued: 0 delta_a, 1 delta_e, 2 delta_r.
    pub control: usize,
}

pub(crate) fn with_control(base: Controls, control: usize, value: f64) -> Controls {
    let mut u = base;
    match control {
        0 => u.delta_a = value,
        1 => u.delta_e = value,
        _ => u.delta_r = value,
    }
    u
}

impl System for Unconstrained<'_> {
    fn eval(&self, z: &V6) -> Option<Eval> {
        let x = [z[0], z[1], z[2], z[3], z[4]];
        let u = with_control(self.base, self.control, z[5]);
        let cj = self.model.control_jacobian(&x, &u);
        finite(Eval {
            f: Vector5::from(self.model.rhs(&x, &u)),
            jy: mat5(&self.model.jacobian(&x, &u)),
            fmu: Vector5::from_fn(|i, _| cj[i][self.control]),
        })
    }

    fn physical(&self, z: &V6) -> ([f64; 5], f64) {
        ([z[0], z[1], z[2], z[3], z[4]], z[5])
    }

    fn z_index(&self, i: usize) -> Option<usize> {
        Some(i)
    }

    fn dynamic(&self) -> bool {
        true
    }
}

/// The zero-sideslip trim at one roll rate and its derivative in the roll rate.
#[derive(Clone, Copy, Debug)]
pub(crate) struct ZsTrim {
    /// [alpha, 0, P0, q, r].
    pub x: [f64; 5],
    pub delta_a: f64,
    pub delta_r: f64,
    pub d_delta_a: f64,
    pub d_delta_r: f64,
}

/// The closed-form zero-sideslip trim (Eqs 32-35) as a function of P0.
pub(crate) struct Schedule<'a> {
    pub model: &'a PssModel,
    pub delta_e: f64,
    /// d f_roll / d delta_a, d f_yaw / d delta_a, d f_yaw / d delta_r (constants).
    l_da: f64,
    n_da: f64,
    n_dr: f64,
}

impl<'a> Schedule<'a> {
    /// `None` when l_delta_a or n_delta_r vanishes (no schedule exists).
    pub fn new(model: &'a PssModel, delta_e: f64) -> Option<Schedule<'a>> {
        let cj = model.control_jacobian(&[0.0; 5], &Controls::default());
        let (l_da, n_da, n_dr) = (cj[2][0], cj[4][0], cj[4][2]);
        (l_da != 0.0 && n_dr != 0.0).then_some(Schedule {
            model,
            delta_e,
            l_da,
            n_da,
            n_dr,
        })
    }

    /// The trim at roll rate `p0`; `None` where the 3x3 system is singular (Eq. 35's det = 0).
    pub fn at(&self, p0: f64) -> Option<ZsTrim> {
        const ROWS: [usize; 3] = [0, 1, 3];
        const COLS: [usize; 3] = [0, 3, 4];
        let u0 = Controls {
            delta_a: 0.0,
            delta_e: self.delta_e,
            delta_r: 0.0,
        };
        let x0 = [0.0, 0.0, p0, 0.0, 0.0];
        // Rows alpha, beta, q are linear in (alpha, q, r) at fixed p with beta = 0.
        let j0 = self.model.jacobian(&x0, &u0);
        let f0 = self.model.rhs(&x0, &u0);
        let a = Matrix3::from_fn(|i, j| j0[ROWS[i]][COLS[j]]);
        let y = a.lu().solve(&Vector3::from_fn(|i, _| -f0[ROWS[i]]))?;
        let x = [y[0], 0.0, p0, y[1], y[2]];
        let delta_a = -self.model.rhs(&x, &u0)[2] / self.l_da;
        let u1 = Controls { delta_a, ..u0 };
        let delta_r = -self.model.rhs(&x, &u1)[4] / self.n_dr;
        // d/dP0: A(P0) y' = -(d f / d p) on the same rows, at the trim.
        let j = self.model.jacobian(&x, &u1);
        let aj = Matrix3::from_fn(|i, k| j[ROWS[i]][COLS[k]]);
        let yp = aj.lu().solve(&Vector3::from_fn(|i, _| -j[ROWS[i]][2]))?;
        let dx = [yp[0], 0.0, 1.0, yp[1], yp[2]];
        let dot = |row: usize| (0..5).map(|k| j[row][k] * dx[k]).sum::<f64>();
        let d_delta_a = -dot(2) / self.l_da;
        let d_delta_r = -(dot(4) + self.n_da * d_delta_a) / self.n_dr;
        let out = ZsTrim {
            x,
            delta_a,
            delta_r,
            d_delta_a,
            d_delta_r,
        };
        let scalars = [delta_a, delta_r, d_delta_a, d_delta_r];
        x.iter()
            .chain(&dx)
            .chain(&scalars)
            .all(|v| v.is_finite())
            .then_some(out)
    }
}

/// EBA step 1 (Eq. 36): f = 0 with beta = 0 imposed and the rudder freed,
/// `z = (alpha, p, q, r, delta_r, delta_a)`.
pub(crate) struct ZsConstrained<'a> {
    pub model: &'a PssModel,
    pub delta_e: f64,
}

impl System for ZsConstrained<'_> {
    fn eval(&self, z: &V6) -> Option<Eval> {
        let x = [z[0], 0.0, z[1], z[2], z[3]];
        let u = Controls {
            delta_a: z[5],
            delta_e: self.delta_e,
            delta_r: z[4],
        };
        let j = self.model.jacobian(&x, &u);
        let cj = self.model.control_jacobian(&x, &u);
        const COLS: [usize; 4] = [0, 2, 3, 4];
        finite(Eval {
            f: Vector5::from(self.model.rhs(&x, &u)),
            jy: Matrix5::from_fn(|i, k| if k < 4 { j[i][COLS[k]] } else { cj[i][2] }),
            fmu: Vector5::from_fn(|i, _| cj[i][0]),
        })
    }

    fn physical(&self, z: &V6) -> ([f64; 5], f64) {
        ([z[0], 0.0, z[1], z[2], z[3]], z[5])
    }

    fn z_index(&self, i: usize) -> Option<usize> {
        [Some(0), None, Some(1), Some(2), Some(3)][i]
    }

    fn dynamic(&self) -> bool {
        false
    }
}

/// EBA step 2 (Eq. 37): the unconstrained model with the rudder schedule substituted,
/// `z = (alpha, beta, p, q, r, s)` where `s` is the schedule's own roll rate, so that
/// `delta_a = delta_a(s)` and `delta_r = delta_r(s)` are exact. On the interval used,
/// `delta_a(s)` is monotone (EBA step 1 ends it at the schedule's first fold), so continuing in
/// `s` is continuing in delta_a with delta_r(delta_a) substituted.
pub(crate) struct ZsScheduled<'a> {
    pub schedule: Schedule<'a>,
}

impl System for ZsScheduled<'_> {
    fn eval(&self, z: &V6) -> Option<Eval> {
        let m = self.schedule.model;
        let s = self.schedule.at(z[5])?;
        let x = [z[0], z[1], z[2], z[3], z[4]];
        let u = Controls {
            delta_a: s.delta_a,
            delta_e: self.schedule.delta_e,
            delta_r: s.delta_r,
        };
        let cj = m.control_jacobian(&x, &u);
        finite(Eval {
            f: Vector5::from(m.rhs(&x, &u)),
            jy: mat5(&m.jacobian(&x, &u)),
            fmu: Vector5::from_fn(|i, _| cj[i][0] * s.d_delta_a + cj[i][2] * s.d_delta_r),
        })
    }

    fn physical(&self, z: &V6) -> ([f64; 5], f64) {
        let da = self.schedule.at(z[5]).map_or(f64::NAN, |s| s.delta_a);
        ([z[0], z[1], z[2], z[3], z[4]], da)
    }

    fn z_index(&self, i: usize) -> Option<usize> {
        Some(i)
    }

    fn dynamic(&self) -> bool {
        true
    }
}
