//! Certified clearance: the critical jump over a box of uncertain data (`model clear`).
//!
//! For an aircraft whose file has an `[uncertainty]` table, [`clear`] bounds the minimum over the
//! box of the critical jump roll rate (the first fold of the primary branch, as
//! [`crate::analysis::analyze`] defines it) and of |delta_a| at it: `lo` is proven by the branch
//! and bound of [`bound`] (no aircraft of the box has a primary-branch jump below it), `hi` is
//! attained by a reported aircraft of the box, computed by the exact `analyze`. What exactly is
//! proven is in `docs/clearance.md`.
//!
//! ```
//! use model::aircraft::{Aircraft, Param, Uncertain};
//! use model::clearance::{sample, split_box, Rng};
//! use num_rational::BigRational;
//!
//! // Aircraft A with l_p uncertain in [-22, -21.5] 1/s, and n_r given as a zero-width interval.
//! let q = |n: i64, d: i64| BigRational::new(n.into(), d.into());
//! let mut a = Aircraft::a();
//! let n_r = a.exact(Param::Nr).clone();
//! a.uncertainty = vec![
//!     Uncertain::param(Param::Lp, q(-22, 1), q(-43, 2)),
//!     Uncertain::param(Param::Nr, n_r.clone(), n_r),
//! ];
//! // The box has one dimension; every sample of it is an aircraft inside it.
//! let (base, wide) = split_box(&a);
//! assert_eq!(wide.len(), 1);
//! let mut rng = Rng::new(7);
//! for _ in 0..10 {
//!     let l_p = sample(&base, &wide, &mut rng).value(Param::Lp);
//!     assert!((-22.0..=-21.5).contains(&l_p), "{l_p}");
//! }
//! ```
//!
//! The parts: [`Settings`] and the results ([`Clearance`]); the box's coordinates
//! ([`split_box`], [`at`], [`sample`]); the worst case found by the exact path (which sets `hi`);
//! the branch-and-bound tree and its certificates ([`bound`], which prove `lo`); [`clear`], which
//! runs them, tightening the bounds past the tolerance while the aileron limit lies between
//! them, to a [`Verdict`]; the Monte Carlo comparison ([`monte_carlo`]) and [`run::clear_each`]
//! over elevator settings.

pub mod bound;
mod clear;
mod coordinates;
mod data_map;
pub mod monte_carlo;
mod on_pool;
mod result;
pub mod run;
mod settings;
mod tree;
mod verdict;
mod worst_case;

pub use clear::clear;
pub(crate) use coordinates::Coordinate;
pub use coordinates::{
    at, clamp_exact, exact_coordinates, sample, sample_coordinates, split_box, Rng,
};
pub use result::{Bounds, CaseAircraft, ClearError, Clearance};
pub use settings::Settings;
pub use tree::MAX_ROLL_RATE;
pub use verdict::{LimitGap, Verdict};

use crate::aircraft::Aircraft;
use crate::analysis::{analyze_with, AnalysisError, JumpPoint};

/// The critical jump of one exact aircraft by the exact path: the jump part of `analyze`
/// alone, whose critical jump is the same point; the departure part (Hopf points, landings)
/// would cost up to seconds per aircraft with aileron yaw and decide nothing here.
pub fn critical(aircraft: &Aircraft, delta_e_rad: f64) -> Result<Option<JumpPoint>, AnalysisError> {
    Ok(analyze_with(aircraft, delta_e_rad, false)?.critical)
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;

    /// The committed `aircraft/a_uncertain.toml` (four uncertain derivatives).
    pub(crate) fn a_uncertain() -> Aircraft {
        let path =
            std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../aircraft/a_uncertain.toml");
        crate::aircraft::load(&path).expect("the committed uncertain aircraft")
    }
}
