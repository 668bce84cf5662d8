//! The equations of motion of a rigid body over a flat, non-rotating Earth with constant
//! gravity: Newton's law in body axes, `m (d/dt uvw + pqr x uvw) = F + m g`, Euler's with the
//! full inertia tensor as loaded (products of inertia included), `I d/dt pqr + pqr x I pqr = M`,
//! the quaternion's kinematics and the position's. Fuel frozen: mass, CG and inertia constant.

use super::state::State;
use crate::jsbsim::mass::Totals;
use crate::jsbsim::units::SLUG_PER_LB;
use nalgebra::{Matrix3, Vector3};

/// Standard gravity, ft/s^2 (JSBSim's weight is the mass times it).
pub const G_FT: f64 = 32.174_049;

/// The rigid body.
#[derive(Clone, Copy, Debug)]
pub struct Rigid {
    /// Mass, slug.
    pub mass: f64,
    /// Inertia tensor about the CG, body axes, slug ft^2.
    pub inertia: Matrix3<f64>,
    /// Its inverse.
    pub inverse: Matrix3<f64>,
}

impl Rigid {
    /// The body of `totals` (weight in lbs, tensor in slug ft^2); an error when the tensor is
    /// singular.
    pub fn new(totals: &Totals) -> Result<Rigid, String> {
        let inertia = Matrix3::from_fn(|i, j| totals.tensor[i][j]);
        let inverse = inertia.try_inverse().ok_or_else(|| {
            format!(
                "the inertia tensor {:?} slug ft^2 is singular (expected a rigid body)",
                totals.tensor
            )
        })?;
        Ok(Rigid {
            mass: totals.weight * SLUG_PER_LB,
            inertia,
            inverse,
        })
    }

    /// The rate of change of `s` under `force` (lbs) and `moment` (lbs ft, about the CG), body
    /// axes.
    pub fn rate(&self, s: &State, force: [f64; 3], moment: [f64; 3]) -> State {
        let uvw = Vector3::from(s.uvw);
        let w = Vector3::from(s.pqr);
        let c = s.body_from_ned();
        let gravity = Vector3::new(c[0][2], c[1][2], c[2][2]) * G_FT;
        let accel = Vector3::from(force) / self.mass + gravity - w.cross(&uvw);
        let alpha = self.inverse * (Vector3::from(moment) - w.cross(&(self.inertia * w)));
        State {
            uvw: accel.into(),
            pqr: alpha.into(),
            quat: s.quat_rate(),
            ned: s.ned_velocity(),
        }
    }
}

/// Alpha-dot and beta-dot, rad/s, of the body velocity `uvw` changing at `rate` (ft/s^2): the
/// derivatives of atan2(w, u) and atan2(v, sqrt(u^2 + w^2)).
pub fn angle_rates(uvw: [f64; 3], rate: [f64; 3]) -> [f64; 2] {
    let [u, v, w] = uvw;
    let [ud, vd, wd] = rate;
    let uw2 = u * u + w * w;
    let v2 = uw2 + v * v;
    [
        (u * wd - w * ud) / uw2,
        (uw2 * vd - v * (u * ud + w * wd)) / (v2 * uw2.sqrt()),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Torque-free rotation conserves the kinetic energy and the angular momentum's magnitude
    /// (products of inertia included), checked on one rate evaluation: both time derivatives
    /// vanish.
    #[test]
    fn torque_free_rotation_conserves_energy_and_momentum() {
        let totals = Totals {
            weight: 20_000.0,
            cg: [0.0; 3],
            tensor: [
                [3000.0, 0.0, -500.0],
                [0.0, 50_000.0, 0.0],
                [-500.0, 0.0, 52_000.0],
            ],
        };
        let body = Rigid::new(&totals).unwrap();
        let s = State::new([500.0, 0.0, 20.0], [1.0, 0.2, -0.3], [0.0; 3], 0.0);
        let d = body.rate(&s, [0.0; 3], [0.0; 3]);
        let w = Vector3::from(s.pqr);
        let wd = Vector3::from(d.pqr);
        let h = body.inertia * w;
        assert!(w.dot(&(body.inertia * wd)).abs() < 1e-9 * h.norm());
        assert!(h.dot(&(body.inertia * wd)).abs() < 1e-9 * h.norm_squared());
    }

    /// The angle rates against central differences of the angles along a straight line.
    #[test]
    fn angle_rates_are_the_derivatives_of_alpha_and_beta() {
        let (uvw, rate) = ([700.0, 40.0, 60.0], [-3.0, 5.0, 11.0]);
        let at = |t: f64| {
            let s = State {
                uvw: std::array::from_fn(|i| uvw[i] + t * rate[i]),
                ..State::default()
            };
            s.alpha_beta()
        };
        let h = 1e-4;
        let ((a1, b1), (a0, b0)) = (at(h), at(-h));
        let [ad, bd] = angle_rates(uvw, rate);
        assert!((ad - (a1 - a0) / (2.0 * h)).abs() < 1e-10);
        assert!((bd - (b1 - b0) / (2.0 * h)).abs() < 1e-10);
    }
}
