//! The elevator of an envelope point. The paper's `delta_e` is an increment from the point
//! where the derivatives were linearised (its alpha and q are increments too), so the level
//! flight of each grid point is `delta_e = 0`. The pilot's elevator is given either as that
//! increment directly or as the load factor it holds before the roll: `N` g needs the pitch rate
//! `Q0 = (N - 1) g / V` of a steady pull-up (the flight path turns at `Q0` when alpha is
//! steady), and the elevator increment that holds it is read off the trim of the derivation
//! (Eqs 3-4: `Q0 = trim_Q / det A` at `P0 = 0`, linear in `delta_e`).

use crate::aircraft::{Aircraft, Param};
use crate::equations::{symbols, G};
use crate::specialise::parametric;

/// The elevator of every point of an envelope.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Elevator {
    /// The increment that holds this load factor (g) before the roll: 1 is `delta_e = 0`.
    LoadFactor(f64),
    /// The increment itself, rad.
    Increment(f64),
}

impl Default for Elevator {
    /// Level flight held (1 g): `delta_e = 0`.
    fn default() -> Elevator {
        Elevator::LoadFactor(1.0)
    }
}

impl Elevator {
    /// The increment (rad) when it does not depend on the aircraft (given, or 1 g).
    pub fn fixed(self) -> Option<f64> {
        match self {
            Elevator::Increment(d) => Some(d),
            Elevator::LoadFactor(1.0) => Some(0.0),
            Elevator::LoadFactor(_) => None,
        }
    }

    /// The elevator increment (rad) for `aircraft`, linearised in level flight at its speed.
    pub fn delta_e(self, aircraft: &Aircraft) -> Result<f64, String> {
        let n = match self {
            Elevator::LoadFactor(n) if n != 1.0 => n,
            _ => return Ok(self.fixed().unwrap_or_default()),
        };
        let per_rad = pitch_rate_per_elevator(aircraft);
        let delta_e = (n - 1.0) * G / (aircraft.speed * per_rad);
        if !(delta_e.is_finite() && delta_e.abs() <= std::f64::consts::FRAC_PI_2) {
            return Err(format!(
                "no elevator increment of at most 90 deg holds {n} g: the trim pitch rate is \
                 {per_rad:e} (rad/s) per rad of elevator at {:.1} m/s",
                aircraft.speed
            ));
        }
        Ok(delta_e)
    }
}

/// The trim pitch rate of the wings-level trim (`P0 = 0`, no aileron, no rudder) per radian of
/// elevator, rad/s: the derivation's `Q0` at `delta_e = 1`.
pub fn pitch_rate_per_elevator(aircraft: &Aircraft) -> f64 {
    let s = symbols();
    let value = |sym| {
        if sym == s.delta_e {
            return 1.0;
        }
        Param::ALL
            .into_iter()
            .find(|p| s.param(*p) == sym)
            .map_or(0.0, |p| aircraft.value(p))
    };
    let par = parametric();
    par.trim[2].eval_f64(&value) / par.det_a.eval_f64(&value)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The increment for N g against the pitch equilibrium at `p = 0` solved by hand (an
    /// independent oracle): `alpha_dot = q + z_alpha alpha = 0` and `q_dot = m_q q + m_alpha
    /// alpha + m_de de = 0` give `Q0 = z_alpha m_de de / (m_alpha - m_q z_alpha)`.
    #[test]
    fn one_g_is_no_increment_and_n_g_holds_the_pull_up_pitch_rate() {
        let a = Aircraft::a();
        assert_eq!(Elevator::default().delta_e(&a).unwrap(), 0.0);
        assert_eq!(Elevator::Increment(0.03).delta_e(&a).unwrap(), 0.03);
        let v = |p| a.value(p);
        let per_rad = v(Param::ZAlpha) * v(Param::MDeltaE)
            / (v(Param::MAlpha) - v(Param::Mq) * v(Param::ZAlpha));
        assert!((pitch_rate_per_elevator(&a) / per_rad - 1.0).abs() < 1e-12);
        let de = Elevator::LoadFactor(2.0).delta_e(&a).unwrap();
        assert!((per_rad * de * a.speed / G - 1.0).abs() < 1e-12, "{de}");
        let push = Elevator::LoadFactor(0.0).delta_e(&a).unwrap();
        assert!((push + de).abs() < 1e-12 * de.abs());
    }
}
