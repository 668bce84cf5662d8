//! The state of a rigid aircraft over a flat Earth: body-axis velocity and rates, the attitude
//! as a quaternion (no gimbal lock in a steep roll or dive), and the position north, east and
//! down, in JSBSim's units (ft, s, rad), with the quantities read from it (airspeed, alpha,
//! beta, the Euler angles).

/// The state (ft/s, rad/s, ft), also used for its rate of change.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct State {
    /// Body-axis velocity u, v, w, ft/s (no wind: also the air-relative velocity).
    pub uvw: [f64; 3],
    /// Body rates p, q, r, rad/s.
    pub pqr: [f64; 3],
    /// The attitude: the quaternion (scalar first) of the rotation from the local north-east-down
    /// axes to the body axes.
    pub quat: [f64; 4],
    /// Position north, east, down, ft.
    pub ned: [f64; 3],
}

/// `a + h b`, element by element.
fn axpy<const N: usize>(a: &[f64; N], h: f64, b: &[f64; N]) -> [f64; N] {
    std::array::from_fn(|i| a[i] + h * b[i])
}

impl State {
    /// The state at `phi`, `theta`, `psi` (rad, 3-2-1 Euler angles) with body velocity `uvw`,
    /// rates `pqr`, at height `altitude_ft` above the origin.
    pub fn new(uvw: [f64; 3], pqr: [f64; 3], euler: [f64; 3], altitude_ft: f64) -> State {
        let [c1, c2, c3] = euler.map(|a| (a / 2.0).cos());
        let [s1, s2, s3] = euler.map(|a| (a / 2.0).sin());
        State {
            uvw,
            pqr,
            quat: [
                c1 * c2 * c3 + s1 * s2 * s3,
                s1 * c2 * c3 - c1 * s2 * s3,
                c1 * s2 * c3 + s1 * c2 * s3,
                c1 * c2 * s3 - s1 * s2 * c3,
            ],
            ned: [0.0, 0.0, -altitude_ft],
        }
    }

    /// `self + h rate`: a step of the integrator.
    pub fn step(&self, h: f64, rate: &State) -> State {
        State {
            uvw: axpy(&self.uvw, h, &rate.uvw),
            pqr: axpy(&self.pqr, h, &rate.pqr),
            quat: axpy(&self.quat, h, &rate.quat),
            ned: axpy(&self.ned, h, &rate.ned),
        }
    }

    /// The same state with its quaternion of unit length (the integration lets it drift).
    pub fn normalised(mut self) -> State {
        let n = self.quat.iter().map(|q| q * q).sum::<f64>().sqrt();
        self.quat = self.quat.map(|q| q / n);
        self
    }

    /// True airspeed, ft/s.
    pub fn airspeed(&self) -> f64 {
        let [u, v, w] = self.uvw;
        (u * u + v * v + w * w).sqrt()
    }

    /// Angle of attack and sideslip, rad (JSBSim's: atan2(w, u) and atan2(v, sqrt(u^2 + w^2))).
    pub fn alpha_beta(&self) -> (f64, f64) {
        let [u, v, w] = self.uvw;
        (w.atan2(u), v.atan2(u.hypot(w)))
    }

    /// Height above the origin, ft.
    pub fn altitude_ft(&self) -> f64 {
        -self.ned[2]
    }

    /// The rotation matrix from north-east-down to body axes.
    pub fn body_from_ned(&self) -> [[f64; 3]; 3] {
        let [a, b, c, d] = self.quat;
        [
            [
                a * a + b * b - c * c - d * d,
                2.0 * (b * c + a * d),
                2.0 * (b * d - a * c),
            ],
            [
                2.0 * (b * c - a * d),
                a * a - b * b + c * c - d * d,
                2.0 * (c * d + a * b),
            ],
            [
                2.0 * (b * d + a * c),
                2.0 * (c * d - a * b),
                a * a - b * b - c * c + d * d,
            ],
        ]
    }

    /// The velocity over the ground, north, east, down, ft/s.
    pub fn ned_velocity(&self) -> [f64; 3] {
        let m = self.body_from_ned();
        std::array::from_fn(|i| (0..3).map(|k| m[k][i] * self.uvw[k]).sum())
    }

    /// Bank, pitch and heading (3-2-1 Euler angles), rad; heading in (-pi, pi].
    pub fn euler(&self) -> [f64; 3] {
        let m = self.body_from_ned();
        [
            m[1][2].atan2(m[2][2]),
            (-m[0][2]).clamp(-1.0, 1.0).asin(),
            m[0][1].atan2(m[0][0]),
        ]
    }

    /// The rate of change of the quaternion at body rates `pqr`.
    pub fn quat_rate(&self) -> [f64; 4] {
        let [a, b, c, d] = self.quat;
        let [p, q, r] = self.pqr;
        [
            0.5 * (-b * p - c * q - d * r),
            0.5 * (a * p + c * r - d * q),
            0.5 * (a * q + d * p - b * r),
            0.5 * (a * r + b * q - c * p),
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The Euler angles come back from the quaternion built of them, and the rotation matrix
    /// is the product of the three elementary rotations (written out independently here).
    #[test]
    fn euler_angles_round_trip_and_the_matrix_is_the_321_product() {
        let e = [0.3, -0.4, 1.2];
        let s = State::new([1.0, 0.0, 0.0], [0.0; 3], e, 0.0);
        let back = s.euler();
        for k in 0..3 {
            assert!((back[k] - e[k]).abs() < 1e-14, "{back:?}");
        }
        let (sf, cf, st, ct, sp, cp) = (
            e[0].sin(),
            e[0].cos(),
            e[1].sin(),
            e[1].cos(),
            e[2].sin(),
            e[2].cos(),
        );
        let m = s.body_from_ned();
        let want = [
            [ct * cp, ct * sp, -st],
            [sf * st * cp - cf * sp, sf * st * sp + cf * cp, sf * ct],
            [cf * st * cp + sf * sp, cf * st * sp - sf * cp, cf * ct],
        ];
        for i in 0..3 {
            for j in 0..3 {
                assert!((m[i][j] - want[i][j]).abs() < 1e-14);
            }
        }
    }
}
