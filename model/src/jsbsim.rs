//! Real aircraft from JSBSim: reading a JSBSim aircraft model (XML), evaluating its aerodynamic
//! functions natively at a flight condition, and from them the nondimensional body-axis
//! derivatives of an aircraft file that `analyze` reads.
//!
//! Data flow: [`xml`] and [`units`] read values; [`table`], [`function`] and [`evaluate`] are
//! JSBSim's function language, [`readers`] which functions read each property (what an
//! evaluation computes again when a few inputs change), [`finite`] refuses its non-finite values
//! and [`clamp`] names its lookups beyond a table's range, [`digits`] writes their numbers;
//! [`metrics`], [`mass`] and [`aerodynamics`] the model's sections, put together in [`model`];
//! [`systems`] and [`fcs`] read the flight control system, and [`surfaces`] the controls' travel
//! through it. JSBSim itself (its Python package) is the independent check of the evaluation,
//! in the integration tests.

pub mod aerodynamics;
pub mod atmosphere;
pub mod catalogue;
pub mod clamp;
pub mod cli;
pub mod coefficients;
pub mod condition;
pub mod derivatives;
pub mod digits;
pub mod error;
pub mod evaluate;
pub mod fcs;
pub mod finite;
pub mod fixed;
pub mod function;
pub mod import;
pub mod mass;
pub mod metrics;
pub mod model;
pub mod readers;
pub mod surfaces;
pub mod systems;
pub mod table;
pub mod table_xml;
pub mod trim;
pub mod units;
pub mod write;
pub mod xml;

pub use error::JsbsimError;
pub use model::Model;
#[cfg(test)]
mod fcs_tests;
#[cfg(test)]
mod readers_tests;
#[cfg(test)]
mod tests;
