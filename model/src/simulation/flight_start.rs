//! The 7th-order model's start for an aircraft whose file gives its trim: its own flight, not
//! the PSS trim.
//!
//! The PSS trim at P0 = 0 neglects gravity, so the trim lift `z_0` curves its path: it pulls up
//! at `Q_0 = n g / V`. The aircraft itself was trimmed with gravity: in 1-g level flight its
//! pitch rate is zero. So the 7th-order model (the PSS right-hand side plus gravity) starts on
//! its own steady flight path: wings level, the path horizontal, so the principal axis pitched
//! up by its angle of attack `alpha_t + alpha`, and alpha and q such that the alpha and pitch
//! equations are at rest with gravity included. At the trim's own elevator and load factor 1
//! that is the trim itself (alpha = q = 0, to within `1 - cos(alpha_t)`); at another load factor
//! it is the steady pull-up or push-over the trim's lift flies without the elevator moving
//! (n = 0: the unloaded, ballistic arc).

use crate::equations::gravity_and_attitude;
use crate::pss_model::{Controls, PssModel};

/// Newton steps: the equations are linear in (alpha, q) but for the cosine of the attitude.
const STEPS: usize = 8;

/// The start `([alpha, beta, p, q, r], theta)` of the 7th-order model: beta, p and r zero (wings
/// level, no aileron), alpha and q at rest with gravity, `theta = alpha_t + alpha`. `None` when
/// the 2x2 system is singular or the iteration does not settle to a finite state.
pub fn flight_start(
    model: &PssModel,
    controls: &Controls,
    speed: f64,
    alpha_t: f64,
) -> Option<([f64; 5], f64)> {
    let mut x = [0.0; 5];
    for _ in 0..STEPS {
        let theta = alpha_t + x[0];
        let f = model.rhs(&x, controls);
        let (d_alpha, ..) = gravity_and_attitude(speed, 0.0, x[3], 0.0, 0.0, theta);
        let j = model.jacobian(&x, controls);
        // d/d alpha of the gravity term (g/V) cos(theta): -(g/V) sin(theta).
        let g_slope = -d_alpha * theta.tan();
        let (a11, a12, a21, a22) = (j[0][0] + g_slope, j[0][3], j[3][0], j[3][3]);
        let det = a11 * a22 - a12 * a21;
        if det == 0.0 || !det.is_finite() {
            return None;
        }
        let (r1, r2) = (f[0] + d_alpha, f[3]);
        x[0] -= (a22 * r1 - a12 * r2) / det;
        x[3] -= (a11 * r2 - a21 * r1) / det;
    }
    let start = (x, alpha_t + x[0]);
    x.iter().all(|v| v.is_finite()).then_some(start)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::aircraft::{Aircraft, Param};
    use num_rational::BigRational;

    /// Aircraft A linearized about a 1-g trim at 150 m/s with its principal axis 0.05 rad above
    /// the flight path.
    fn trimmed_a(n: f64) -> Aircraft {
        let g_v = 9.80665 / 150.0;
        Aircraft::a()
            .with(
                Param::Z0,
                BigRational::from_float(-n * g_v).expect("finite"),
            )
            .with(
                Param::AlphaT,
                BigRational::from_float(0.05).expect("finite"),
            )
    }

    const TRIM: Controls = Controls {
        delta_a: 0.0,
        delta_e: 0.0,
        delta_r: 0.0,
    };

    /// The start of [`trimmed_a`] at load factor `n`, with its model.
    fn start(n: f64) -> (PssModel, [f64; 5], f64) {
        let model = PssModel::new(&trimmed_a(n));
        let (x, theta) = flight_start(&model, &TRIM, 150.0, 0.05).unwrap();
        (model, x, theta)
    }

    #[test]
    fn at_one_g_the_start_is_the_trim_itself() {
        let (model, x, theta) = start(1.0);
        let u = TRIM;
        // alpha_dot = q + z_alpha alpha - g/V + (g/V) cos(theta) = 0 and
        // q_dot = m_q q + m_alpha alpha = 0: alpha and q of order (g/V)(1 - cos 0.05) ~ 8e-5.
        assert!(x[0].abs() < 1e-4 && x[3].abs() < 1e-4, "{x:?}");
        assert!((theta - 0.05).abs() < 1e-4);
        let f = model.rhs(&x, &u);
        let (d_alpha, ..) = gravity_and_attitude(150.0, 0.0, x[3], 0.0, 0.0, theta);
        assert!(
            (f[0] + d_alpha).abs() < 1e-14 && f[3].abs() < 1e-14,
            "{f:?}"
        );
    }

    #[test]
    fn unloaded_the_start_is_the_ballistic_arc() {
        // n = 0: no lift, so the path curves down at g/V cos(theta): q = -(g/V) cos(theta) to
        // hold alpha, with the pitch equation at rest by a small alpha (m_q q + m_alpha alpha).
        let (_, x, theta) = start(0.0);
        let (mq, ma, za) = (-1.815, -13.52504, -3.0076);
        let g_v = 9.80665 / 150.0 * theta.cos();
        // q + z_alpha alpha + g_v = 0, m_q q + m_alpha alpha = 0:
        let alpha = g_v * mq / (ma - za * mq);
        let q = -ma * alpha / mq;
        assert!(
            (x[0] - alpha).abs() < 1e-12 && (x[3] - q).abs() < 1e-12,
            "{x:?} {alpha} {q}"
        );
        assert!(x[3] < -0.04, "{x:?}");
    }
}
