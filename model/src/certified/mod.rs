//! Certified floating-point evaluation of the criterion: the same polynomials as the exact path,
//! enclosed in f64 intervals, and their positive roots with proven brackets.
//!
//! The exact path ([`crate::specialise`], [`crate::roots`]) substitutes an aircraft's exact
//! rational data into the parametric derivation and works in big rationals: every digit is
//! right, at milliseconds per aircraft (much more for data with long fractions). Clearance and
//! Monte Carlo analyse thousands to millions of aircraft, so they need the same answers in
//! floating point, without giving up the guarantee. Here every number is an interval
//! ([`crate::interval::I`], outward rounding) that encloses the exact value:
//!
//! 1. the parametric trim-level results of [`crate::derivation`] (det A, the trim numerators,
//!    the roll equation, det J5 and d in the trim symbols) are evaluated at the data's
//!    enclosures into dense polynomials in P0 and delta_a ([`dense`]);
//! 2. the trim's denominator is cleared by the one step-8 routine,
//!    [`crate::derivation::clear_trim`], in the ring of those interval polynomials, and the
//!    aileron is eliminated by the resultant with the trim condition ([`eliminate`]);
//! 3. [`isolate`] brackets the positive roots of every polynomial whose coefficients lie in
//!    the enclosures, or says it cannot (its inner loops keep f64 midpoints with radii that
//!    bound their rounding instead of intervals: the same guarantee, less work).
//!
//! So a certified answer is exactly the exact path's, up to the width of the brackets (an ulp or
//! two). Where a certificate fails (a root too close to another, a coefficient that may vanish)
//! callers fall back to the exact path: the answer is never a guess.
//!
//! ```
//! use model::aircraft::Aircraft;
//! use model::certified::{positive_roots_by, EnclosedPolys, Values};
//!
//! // Aircraft A at delta_e = 2 deg: its first jump root (Table 1: 1.706288 rad/s) lies in a
//! // certified bracket of relative width at most 1e-9.
//! let v = Values::of(&Aircraft::a(), 2f64.to_radians(), 0.0);
//! let e = EnclosedPolys::new(&v).unwrap();
//! let first = positive_roots_by(&e.jump, None, 1e-9).unwrap()[0];
//! assert!(first.lo < 1.7062880 && first.hi > 1.7062879);
//! ```

pub mod compiled;
pub mod dense;
pub mod isolate;
pub mod num;
pub(crate) mod tape;

mod at_roll_rate;
mod branch;
mod characteristic;
mod elimination;
mod enclosed;
mod fold;
mod hopf;
mod lifted;
mod mode;
mod on_curve;
mod rolls;
mod slope;
mod turn;
mod values;

pub use at_roll_rate::{
    at_roll_rate, at_roll_rate_with, trim_condition_at, trim_condition_of_states, value_at,
    value_over, AtRollRate, Criterion,
};
pub use branch::{first_hopf_on_branch, first_root_on_branch, BranchEnd, Det};
pub use elimination::{eliminate, Coeff, Scalar};
pub use enclosed::{EnclosedPolys, JumpPolys, TrimPolys};
pub use fold::{fold_aileron, fold_intervals, one_curvature};
pub use hopf::EnclosedHopf;
pub use isolate::{
    positive_roots, positive_roots_by, positive_roots_windowed, positive_roots_windowed_even,
    real_roots_outside, Bracket, Uncertified,
};
pub use values::{Sampler, Values};
