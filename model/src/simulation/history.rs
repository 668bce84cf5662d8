//! A simulated time history, its CSV form, and its end-of-run (steady) values.

use super::SimSettings;
use serde::Serialize;
use std::fmt::Write as _;

/// Integrator statistics of one run.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
pub struct RunStats {
    /// Right-hand-side evaluations.
    pub evaluations: u32,
    /// Accepted steps.
    pub accepted: u32,
    /// Rejected steps.
    pub rejected: u32,
}

/// A simulated time history, sampled every `dt` from t = 0 (angles in rad, rates in rad/s).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct TimeHistory {
    /// The settings of the run.
    pub settings: SimSettings,
    /// The trim the run starts from.
    pub start: [f64; 5],
    /// Time, s.
    pub t: Vec<f64>,
    /// Angle of attack, rad.
    pub alpha: Vec<f64>,
    /// Sideslip, rad.
    pub beta: Vec<f64>,
    /// Roll rate, rad/s.
    pub p: Vec<f64>,
    /// Pitch rate, rad/s.
    pub q: Vec<f64>,
    /// Yaw rate, rad/s.
    pub r: Vec<f64>,
    /// Bank angle phi, rad, unwrapped (7th-order model only; empty for the PSS model, which has
    /// no attitude).
    pub phi: Vec<f64>,
    /// Pitch attitude theta, rad, in [-pi/2, pi/2] (7th-order model only; empty for PSS).
    pub theta: Vec<f64>,
    /// Aileron deflection, rad.
    pub delta_a: Vec<f64>,
    /// Rudder deflection, rad.
    pub delta_r: Vec<f64>,
    /// Integrator statistics.
    pub stats: RunStats,
}

/// End-of-run (steady) values of a time history over its last `window` seconds.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Steady {
    /// Mean roll rate, rad/s.
    pub p_mean: f64,
    /// Smallest roll rate in the window, rad/s.
    pub p_min: f64,
    /// Largest roll rate in the window, rad/s.
    pub p_max: f64,
    /// Mean sideslip, rad.
    pub beta_mean: f64,
    /// Largest |sideslip| in the window, rad.
    pub beta_max_abs: f64,
    /// Largest |sideslip| over the whole run, rad.
    pub beta_peak_abs: f64,
}

impl TimeHistory {
    /// The history as CSV: a header line, then one line per sample (shortest round-trip
    /// decimals). Columns `t_s, alpha_rad, beta_rad, p_rad_s, q_rad_s, r_rad_s, [phi_rad,
    /// theta_rad,] delta_a_rad, delta_r_rad`; phi and theta only for the 7th-order model.
    pub fn to_csv(&self) -> String {
        let attitude = !self.phi.is_empty();
        let mut s = String::from("t_s,alpha_rad,beta_rad,p_rad_s,q_rad_s,r_rad_s,");
        if attitude {
            s += "phi_rad,theta_rad,";
        }
        s += "delta_a_rad,delta_r_rad\n";
        for i in 0..self.t.len() {
            let _ = write!(
                s,
                "{},{},{},{},{},{},",
                self.t[i], self.alpha[i], self.beta[i], self.p[i], self.q[i], self.r[i]
            );
            if attitude {
                let _ = write!(s, "{},{},", self.phi[i], self.theta[i]);
            }
            let _ = writeln!(s, "{},{}", self.delta_a[i], self.delta_r[i]);
        }
        s
    }

    /// Steady values over the last `window` seconds (the whole run if it is shorter).
    pub fn steady(&self, window: f64) -> Steady {
        let t_end = self.t.last().copied().unwrap_or(0.0);
        let from = self
            .t
            .partition_point(|t| *t < t_end - window)
            .min(self.t.len().saturating_sub(1));
        let p = &self.p[from..];
        let b = &self.beta[from..];
        let n = p.len().max(1) as f64;
        Steady {
            p_mean: p.iter().sum::<f64>() / n,
            p_min: p.iter().copied().fold(f64::INFINITY, f64::min),
            p_max: p.iter().copied().fold(f64::NEG_INFINITY, f64::max),
            beta_mean: b.iter().sum::<f64>() / n,
            beta_max_abs: b.iter().fold(0.0, |m, v| m.max(v.abs())),
            beta_peak_abs: self.beta.iter().fold(0.0, |m, v| m.max(v.abs())),
        }
    }
}
