//! What a clearance run is asked for: the elevator setting, the tolerances on the two gaps, the
//! budgets of work of the branch and bound, and the candidates for the worst case.

/// Settings of a clearance run.
#[derive(Clone, Debug)]
pub struct Settings {
    /// Elevator deflection, rad.
    pub delta_e_rad: f64,
    /// Tolerance on the roll-rate gap hi - lo, rad/s.
    pub tolerance_p0: f64,
    /// Tolerance on the aileron gap, deg.
    pub tolerance_deg: f64,
    /// An outer guard on the wall-clock time of the branch and bound, s: not a budget (the
    /// budgets are of work, so that the same input gives the same answer on any machine under
    /// any load); a run it stops says so in its note, as an answer that depends on the machine.
    pub wall_clock_guard_s: f64,
    /// Most boxes the branch and bound may hold.
    pub max_boxes: usize,
    /// Most slabs the branch and bound may certify.
    pub max_slabs: usize,
    /// Seed of the random candidates for the worst case.
    pub seed: u64,
    /// Random candidates tried for the worst case (exact analyses).
    pub candidates: usize,
    /// Further candidates for the worst case, as box coordinates (one per `[uncertainty]`
    /// entry, in its order; each clamped into the box): `model clear` passes the Monte Carlo's
    /// lowest samples ([`super::monte_carlo::MonteCarlo::lowest_at`]), so that hi is at most what
    /// they attain (to within the certified route's brackets, 1e-9 relative). One of another
    /// length, or that the exact path refuses, is skipped.
    pub candidates_at: Vec<Vec<f64>>,
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            delta_e_rad: 2f64.to_radians(),
            tolerance_p0: 1e-3,
            tolerance_deg: 0.01,
            wall_clock_guard_s: 600.0,
            max_boxes: 20_000,
            max_slabs: 500_000,
            seed: 1,
            candidates: 64,
            candidates_at: Vec::new(),
        }
    }
}
