//! The flight envelope: the analysis of `model analyze` at every point of a grid of altitude
//! and Mach, each point linearised about its own n-g trim (alpha and elevator) from a JSBSim
//! model read once.
//!
//! Data flow: [`grid`] (the ranges, checked before any work) and [`source`] (the model and its
//! settings) give the points; [`elevator`] says the load factor of the trim and the elevator
//! increment from it (the paper's `delta_e`); [`point`] trims, imports and analyses one
//! point; [`map`] runs every point in parallel. With `--uncertainty`, [`uncertainty`] gives each
//! point's aircraft its `[uncertainty]` box and [`clearance`] clears it. With `--validate`,
//! [`validation`] adds the native 6-DOF's verdict at the points that predict a jump and a
//! seeded sample of the others.

pub mod clearance;
pub mod elevator;
pub mod grid;
pub mod map;
pub mod point;
pub mod source;
pub mod uncertainty;
pub mod validation;

pub use elevator::Elevator;
pub use grid::{Grid, Range};
pub use map::{cleared_envelope, envelope, Envelope};
pub use point::{Critical, Point};
