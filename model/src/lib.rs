//! Roll-coupling jump criterion of Mahale & Ananthkrishnan (AIAA 2006-6267), derived exactly.
//!
//! Data flow is one way: [`equations`] (Appendix A written once) -> [`derivation`] (the paper's
//! steps, Eqs 1-35, as named symbolic results) -> [`analysis`] (what `model analyze` prints).
//! [`algebra`] and [`aircraft`] depend on nothing of ours; [`roots`] isolates real roots of the
//! univariate polynomials exactly.
#![warn(missing_docs)]

pub mod aircraft;
pub mod algebra;
#[cfg(feature = "analysis")]
pub mod analysis;
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
pub mod jsbsim;
// The tests' reference numbers (one file, shared with the other crates' tests): for the unit
// tests and for the generator of `generated/tests/values.rs` in `emit`.
#[cfg(feature = "cli")]
pub mod plot;
#[cfg(feature = "cli")]
pub mod present;
pub mod pss_model;
pub mod random;
#[allow(dead_code)]
#[path = "../tests/support/reference.rs"]
mod reference;
pub mod roots;
#[cfg(feature = "cli")]
pub mod simulation;
pub mod specialise;
#[cfg(any(feature = "analysis", feature = "continuation"))]
pub mod spectrum;
