//! What a 6-DOF run records at every step, and its CSV form with the units in the header.

use super::run::Settings;
use super::state::State;
use crate::jsbsim::atmosphere::standard;
use crate::jsbsim::units::M_PER_FT;
use std::fmt::Write as _;

/// The time history of a run (SI and rad).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct History {
    /// The run's settings.
    pub settings: Option<Settings>,
    /// The thrust held, lbs (0 with the thrust off).
    pub thrust_lbs: f64,
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
    /// True airspeed, m/s.
    pub speed: Vec<f64>,
    /// Altitude, m.
    pub altitude: Vec<f64>,
    /// Mach number.
    pub mach: Vec<f64>,
    /// Bank angle, rad, in (-pi, pi].
    pub phi: Vec<f64>,
    /// Pitch attitude, rad.
    pub theta: Vec<f64>,
    /// Heading, rad, in (-pi, pi].
    pub psi: Vec<f64>,
}

/// The columns of the CSV, with their units.
pub const COLUMNS: &str = "t_s,alpha_rad,beta_rad,p_rad_s,q_rad_s,r_rad_s,V_m_s,h_m,mach,\
phi_rad,theta_rad,psi_rad,jsbsim_aileron_rad";

impl History {
    /// An empty history of a run of `settings`, room for `n` samples.
    pub fn new(settings: Settings, n: usize) -> History {
        let v = || Vec::with_capacity(n);
        History {
            settings: Some(settings),
            thrust_lbs: 0.0,
            t: v(),
            alpha: v(),
            beta: v(),
            p: v(),
            q: v(),
            r: v(),
            speed: v(),
            altitude: v(),
            mach: v(),
            phi: v(),
            theta: v(),
            psi: v(),
        }
    }

    /// Records `s` at time `t`.
    pub fn record(&mut self, t: f64, s: &State) {
        let (alpha, beta) = s.alpha_beta();
        let [phi, theta, psi] = s.euler();
        let h = s.altitude_ft() * M_PER_FT;
        let v = s.airspeed() * M_PER_FT;
        let mach = standard(h).map_or(f64::NAN, |air| v / air.sound_speed);
        self.t.push(t);
        self.alpha.push(alpha);
        self.beta.push(beta);
        self.p.push(s.pqr[0]);
        self.q.push(s.pqr[1]);
        self.r.push(s.pqr[2]);
        self.speed.push(v);
        self.altitude.push(h);
        self.mach.push(mach);
        self.phi.push(phi);
        self.theta.push(theta);
        self.psi.push(psi);
    }

    /// The history as CSV: the header [`COLUMNS`], then one line per step (shortest
    /// round-trip decimals); the aileron surface in JSBSim's sign (the left aileron, positive
    /// rolls right: the paper's delta_a is its negative).
    pub fn to_csv(&self) -> String {
        let aileron = self.settings.map_or(0.0, |s| s.aileron);
        let mut s = format!("{COLUMNS}\n");
        for i in 0..self.t.len() {
            let row = [
                self.t[i],
                self.alpha[i],
                self.beta[i],
                self.p[i],
                self.q[i],
                self.r[i],
                self.speed[i],
                self.altitude[i],
                self.mach[i],
                self.phi[i],
                self.theta[i],
                self.psi[i],
                aileron,
            ];
            let line: Vec<String> = row.iter().map(|v| v.to_string()).collect();
            let _ = writeln!(s, "{}", line.join(","));
        }
        s
    }
}
