//! The elevator of an envelope: every point is trimmed at one load factor (a wings-level pull-up
//! at `n` g: lift `n` times the weight, pitching moment zero, [`crate::jsbsim::trim`]) and
//! linearised there, its elevator at the trim position; the paper's `delta_e` is an increment
//! from that trim elevator (its alpha and q are increments too), the same at every point.

/// The elevator of every point of an envelope.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Elevator {
    /// The load factor each point is trimmed at (lift over weight).
    pub load_factor: f64,
    /// The elevator increment from each point's trim, rad (the paper's `delta_e`).
    pub increment: f64,
}

impl Default for Elevator {
    /// Level flight (1 g), no increment.
    fn default() -> Elevator {
        Elevator {
            load_factor: 1.0,
            increment: 0.0,
        }
    }
}

impl std::fmt::Display for Elevator {
    /// `"trim at 1 g, increment 0 deg"`.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "trim at {} g, increment {} deg",
            self.load_factor,
            self.increment.to_degrees()
        )
    }
}
