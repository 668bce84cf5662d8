//! The attitude of the 7th-order model as the direction of gravity in body axes: its
//! kinematics `d gamma/dt = gamma x omega` (no singularity at theta = +-90 deg), and phi and theta
//! recovered from it (Appendix A.1).

/// d gamma / dt = gamma x omega for the body-axis direction of a fixed inertial vector.
pub(super) fn gravity_rate(g: &[f64; 3], p: f64, q: f64, r: f64) -> [f64; 3] {
    [
        g[1] * r - g[2] * q,
        g[2] * p - g[0] * r,
        g[0] * q - g[1] * p,
    ]
}

/// (phi, theta) from the body-axis gravity direction (normalised first).
pub(super) fn euler(g: &[f64; 3]) -> (f64, f64) {
    let n = (g[0] * g[0] + g[1] * g[1] + g[2] * g[2]).sqrt();
    let theta = (-g[0] / n).clamp(-1.0, 1.0).asin();
    let phi = g[1].atan2(g[2]);
    (phi, theta)
}

/// The representative of `angle` (mod 2 pi) nearest to `prev`.
pub(super) fn unwrap_angle(prev: f64, angle: f64) -> f64 {
    let tau = std::f64::consts::TAU;
    angle + tau * ((prev - angle) / tau).round()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::equations::gravity_and_attitude;

    #[test]
    fn gravity_direction_kinematics_equal_the_euler_equations_of_a1() {
        // gamma = (-sin theta, cos theta sin phi, cos theta cos phi); its chain-rule derivative
        // with phi_dot, theta_dot of gravity_and_attitude must equal gamma x omega.
        for (phi, theta, p, q, r) in [
            (0.3, -0.4, 2.0, -0.3, 0.5),
            (-2.5, 1.2, -1.0, 0.7, -0.2),
            (4.0, 0.05, 0.1, 0.2, 0.3),
        ] {
            let (_, _, phi_dot, theta_dot) = gravity_and_attitude(150.0, p, q, r, phi, theta);
            let (sp, cp) = f64::sin_cos(phi);
            let (st, ct) = f64::sin_cos(theta);
            let chain = [
                -ct * theta_dot,
                -st * sp * theta_dot + ct * cp * phi_dot,
                -st * cp * theta_dot - ct * sp * phi_dot,
            ];
            let g = gravity_rate(&[-st, ct * sp, ct * cp], p, q, r);
            for i in 0..3 {
                assert!((chain[i] - g[i]).abs() < 1e-13, "{i}: {chain:?} vs {g:?}");
            }
            let (ph, th) = euler(&[-st, ct * sp, ct * cp]);
            assert!((th - theta).abs() < 1e-14);
            assert!((unwrap_angle(phi, ph) - phi).abs() < 1e-14);
        }
    }
}
