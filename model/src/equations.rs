//! The model equations of Appendix A, written once.
//!
//! [`pss`] is the fifth-order pseudo-steady-state (PSS) model of Appendix A.2 as symbolic
//! polynomials; every formula of the paper is derived from it by [`crate::derivation`]. The
//! seventh-order model of Appendix A.1 is the same right-hand side plus the gravity terms and
//! the two attitude equations, which are transcendental and used only numerically
//! ([`gravity_and_attitude`]).
//!
//! The paper prints `l_{\delta a})\delta a` in A.2 (a stray parenthesis) and writes the yaw
//! equation with `+ n_{\delta a}\delta a`; Euler's equations in principal axes give the signs
//! used here: `I_x \dot p = L + (I_y - I_z) q r` so the roll coupling term is `-E q r` with
//! `E = (I_z - I_y)/I_x`, `+C p r` in pitch and `-D p q` in yaw.
//!
//! Beyond Appendix A.2, the roll equation carries the roll-due-to-rudder derivative
//! `l_{\delta r} \delta r` (zero for the paper's aircraft): real data have it, and the rotation of
//! body-axis data into principal axes produces it even when the body-axis `Cl_delta_r` is zero.
//!
//! Beyond Appendix A.2, the model starts where a real aircraft is: in its trimmed flight at a load
//! factor n, not at zero lift. The paper's angles are measured from a state in which the principal
//! axis lies on the flight path and the wing carries no lift; a real aircraft in n-g flight
//! carries the lift `Z_0 = -n m g` and its principal axis is inclined by `alpha_t` to the flight
//! path. With alpha, beta and the controls the increments from that trim, Euler's kinematics of a
//! roll about the principal axis (`beta_dot = p sin(alpha_t + alpha) - r cos(alpha_t + alpha)`,
//! linearized in the small angles as the paper does) and the lift give two terms:
//!
//! - `+ z_0` in the alpha equation, `z_0 = Z_0 / (m V) = -n g / V`: the trim lift keeps acting in
//!   body axes while the aircraft rolls (the PSS model neglects gravity, as the paper does, so at
//!   P0 = 0 the model's trim pulls up at the pitch rate `Q_0 = n g / V`; the 7th-order model's
//!   gravity term balances it in level flight);
//! - `+ alpha_t p` in the sideslip equation: the roll about an inclined principal axis turns angle
//!   of attack into sideslip, the kinematic coupling that drives inertia coupling.
//!
//! Both are zero for the paper's aircraft A and B, whose equations are exactly those of A.2.
//!
//! ```
//! use model::algebra::Poly;
//! use model::equations::{pss, symbols};
//!
//! let s = symbols();
//! let [alpha_dot, ..] = pss();
//! // alpha_dot = q - p beta + z_alpha alpha: linear in q with coefficient 1
//! assert_eq!(alpha_dot.coeff(s.q, 1), Poly::int(1));
//! ```

use crate::aircraft::Param;
use crate::algebra::{Poly, Sym};
use std::sync::OnceLock;

/// Every symbol of the model, created once in a fixed order (which fixes every output order).
#[derive(Debug)]
pub struct Symbols {
    /// The parameters in [`Param::ALL`] order.
    pub params: [Sym; Param::COUNT],
    /// Aileron deflection, rad.
    pub delta_a: Sym,
    /// Elevator deflection, rad.
    pub delta_e: Sym,
    /// Rudder deflection, rad.
    pub delta_r: Sym,
    /// Trim (pseudo-steady) roll rate P0, rad/s.
    pub p0: Sym,
    /// Trim angle of attack alpha_0, rad.
    pub alpha0: Sym,
    /// Trim sideslip beta_0, rad.
    pub beta0: Sym,
    /// Trim pitch rate Q0, rad/s.
    pub q0: Sym,
    /// Trim yaw rate R0, rad/s.
    pub r0: Sym,
    /// State (or, in the linearized equations, perturbation) alpha.
    pub alpha: Sym,
    /// State/perturbation beta.
    pub beta: Sym,
    /// State/perturbation p.
    pub p: Sym,
    /// State/perturbation q.
    pub q: Sym,
    /// State/perturbation r.
    pub r: Sym,
    /// d alpha / dt (of the perturbation).
    pub alpha_dot: Sym,
    /// d beta / dt.
    pub beta_dot: Sym,
    /// d^2 alpha / dt^2.
    pub alpha_ddot: Sym,
    /// d^2 beta / dt^2.
    pub beta_ddot: Sym,
    /// d p / dt.
    pub p_dot: Sym,
}

impl Symbols {
    /// The symbol of a parameter.
    pub fn param(&self, p: Param) -> Sym {
        self.params[p.index()]
    }

    /// The state symbols in the order x = [alpha, beta, p, q, r].
    pub fn states(&self) -> [Sym; 5] {
        [self.alpha, self.beta, self.p, self.q, self.r]
    }

    /// The trim symbols in the order [alpha0, beta0, P0, Q0, R0].
    pub fn trims(&self) -> [Sym; 5] {
        [self.alpha0, self.beta0, self.p0, self.q0, self.r0]
    }

    /// LaTeX form of a symbol of the model (parameters in the paper's notation).
    pub fn latex(&self, s: Sym) -> String {
        if let Some(i) = self.params.iter().position(|p| *p == s) {
            return Param::ALL[i].latex().to_string();
        }
        let table = [
            (self.delta_a, "\\delta_a"),
            (self.delta_e, "\\delta_e"),
            (self.delta_r, "\\delta_r"),
            (self.p0, "P_0"),
            (self.alpha0, "\\alpha_0"),
            (self.beta0, "\\beta_0"),
            (self.q0, "Q_0"),
            (self.r0, "R_0"),
            (self.alpha, "\\alpha"),
            (self.beta, "\\beta"),
            (self.p, "p"),
            (self.q, "q"),
            (self.r, "r"),
            (self.alpha_dot, "\\dot\\alpha"),
            (self.beta_dot, "\\dot\\beta"),
            (self.alpha_ddot, "\\ddot\\alpha"),
            (self.beta_ddot, "\\ddot\\beta"),
            (self.p_dot, "\\dot p"),
        ];
        table
            .iter()
            .find(|(t, _)| *t == s)
            .map_or_else(|| s.name().to_string(), |(_, l)| l.to_string())
    }
}

/// The model's symbols (created on first use, always in the same order).
pub fn symbols() -> &'static Symbols {
    static S: OnceLock<Symbols> = OnceLock::new();
    S.get_or_init(|| {
        let params = Param::ALL.map(|p| Sym::new(p.key()));
        Symbols {
            params,
            delta_a: Sym::new("delta_a"),
            delta_e: Sym::new("delta_e"),
            delta_r: Sym::new("delta_r"),
            p0: Sym::new("P0"),
            alpha0: Sym::new("alpha0"),
            beta0: Sym::new("beta0"),
            q0: Sym::new("Q0"),
            r0: Sym::new("R0"),
            alpha: Sym::new("alpha"),
            beta: Sym::new("beta"),
            p: Sym::new("p"),
            q: Sym::new("q"),
            r: Sym::new("r"),
            alpha_dot: Sym::new("alpha_dot"),
            beta_dot: Sym::new("beta_dot"),
            alpha_ddot: Sym::new("alpha_ddot"),
            beta_ddot: Sym::new("beta_ddot"),
            p_dot: Sym::new("p_dot"),
        }
    })
}

/// The PSS equations of Appendix A.2: the right-hand sides of
/// d/dt [alpha, beta, p, q, r] in terms of the states, controls and parameters.
///
/// This is the single source of truth of the project.
pub fn pss() -> [Poly; 5] {
    let s = symbols();
    let v = Poly::var;
    let k = |p: Param| Poly::var(s.param(p));
    let (alpha, beta, p, q, r) = (v(s.alpha), v(s.beta), v(s.p), v(s.q), v(s.r));
    let (da, de, dr) = (v(s.delta_a), v(s.delta_e), v(s.delta_r));
    use Param::*;
    [
        // alpha_dot = q - p beta + z_alpha alpha + z_0
        sum(&[&q - &(&p * &beta), &k(ZAlpha) * &alpha, k(Z0)]),
        // beta_dot = p (alpha + alpha_t) - r + y_beta beta
        sum(&[&p * &(&alpha + &k(AlphaT)), -r.clone(), &k(YBeta) * &beta]),
        // p_dot = l_p p + l_beta beta + l_r r - E q r + l_da da + l_dr dr
        sum(&[
            &k(Lp) * &p,
            &k(LBeta) * &beta,
            &k(Lr) * &r,
            -(&(&k(E) * &q) * &r),
            &k(LDeltaA) * &da,
            &k(LDeltaR) * &dr,
        ]),
        // q_dot = m_q q + m_alpha alpha + C p r + m_de de
        sum(&[
            &k(Mq) * &q,
            &k(MAlpha) * &alpha,
            &(&k(C) * &p) * &r,
            &k(MDeltaE) * &de,
        ]),
        // r_dot = n_r r + n_beta beta + n_p p - D p q + n_dr dr + n_da da
        sum(&[
            &k(Nr) * &r,
            &k(NBeta) * &beta,
            &k(Np) * &p,
            -(&(&k(D) * &p) * &q),
            &k(NDeltaR) * &dr,
            &k(NDeltaA) * &da,
        ]),
    ]
}

fn sum(terms: &[Poly]) -> Poly {
    terms.iter().fold(Poly::zero(), |acc, t| &acc + t)
}

/// Acceleration due to gravity used by the 7th-order model, m/s^2 (the aircraft's constant).
pub use crate::aircraft::G;

/// The gravity terms and attitude equations that turn the PSS model into the 7th-order model of
/// Appendix A.1: returns `(d_alpha, d_beta, phi_dot, theta_dot)` where `d_alpha` and `d_beta` are
/// added to the PSS right-hand sides of alpha and beta.
///
/// `(g/V) cos(theta) cos(phi)` and `(g/V) cos(theta) sin(phi)`, `phi_dot = p + tan(theta)
/// (q sin(phi) + r cos(phi))`, `theta_dot = q cos(phi) - r sin(phi)`.
pub fn gravity_and_attitude(
    speed: f64,
    p: f64,
    q: f64,
    r: f64,
    phi: f64,
    theta: f64,
) -> (f64, f64, f64, f64) {
    let g_v = G / speed;
    let (sp, cp) = phi.sin_cos();
    let (st, ct) = theta.sin_cos();
    (
        g_v * ct * cp,
        g_v * ct * sp,
        p + st / ct * (q * sp + r * cp),
        q * cp - r * sp,
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pss_model_has_the_structure_of_appendix_a2() {
        let s = symbols();
        let f = pss();
        // Only the roll equation contains the aileron's l_delta_a; only pitch the elevator.
        assert!(f[2].contains(s.param(Param::LDeltaA)));
        // The trim lift is a constant of the alpha equation; alpha_t multiplies the roll rate
        // in the sideslip equation only.
        assert_eq!(f[0].coeff(s.param(Param::Z0), 1), Poly::int(1));
        assert_eq!(f[1].coeff(s.param(Param::AlphaT), 1), Poly::var(s.p));
        assert!((0..5).all(|i| i == 1 || !f[i].contains(s.param(Param::AlphaT))));
        assert!(f[3].contains(s.delta_e) && !f[2].contains(s.delta_e));
        // Gyroscopic couplings are bilinear in the rates.
        assert_eq!(f[2].degree_in(&[s.q, s.r]), 2);
        assert_eq!(f[3].degree_in(&[s.p, s.r]), 2);
        assert_eq!(f[4].degree_in(&[s.p, s.q]), 2);
    }
}
