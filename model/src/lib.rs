//! Roll-coupling jump criterion of Mahale & Ananthkrishnan (AIAA 2006-6267), derived exactly.
//!
//! Data flow is one way: [`equations`] (Appendix A written once) -> [`derivation`] (the paper's
//! steps, Eqs 1-35, as named symbolic results) -> [`analysis`] (what `model analyze` prints).
//! Below them [`algebra`] (exact polynomials) and [`aircraft`] (its data); [`roots`] isolates
//! real roots of the univariate polynomials exactly. The program layer (the straight-line
//! programs of the criterion) serves both the emitter ([`emit`]) and the certified route
//! ([`certified`]), which never name each other; [`present`] at the top writes what the
//! commands print. The order of the whole tower is checked by `tests/tests/layers.rs`.
#![warn(missing_docs)]

pub mod aircraft;
pub mod algebra;
#[cfg(feature = "analysis")]
pub mod analysis;
#[cfg(feature = "analysis")]
pub mod certified;
#[cfg(feature = "cli")]
pub mod clearance;
#[cfg(feature = "continuation")]
pub mod continuation;
pub mod derivation;
pub mod emit;
#[cfg(feature = "cli")]
pub mod envelope;
pub mod equations;
pub mod files;
pub mod interval;
#[cfg(feature = "jsbsim")]
pub mod jsbsim;
#[cfg(feature = "cli")]
pub mod plot;
#[cfg(feature = "cli")]
pub mod present;
pub(crate) mod program;
pub mod pss_model;
pub mod random;
// The tests' reference numbers (one file, shared with the other crates' tests): for the unit
// tests and for the generator of `generated/tests/values.rs` in `emit`.
#[allow(dead_code)]
#[path = "../tests/support/reference.rs"]
mod reference;
pub mod roots;
#[cfg(feature = "cli")]
pub mod simulation;
#[cfg(feature = "cli")]
pub mod six_dof;
pub mod specialise;
#[cfg(any(feature = "analysis", feature = "continuation"))]
pub mod spectrum;
