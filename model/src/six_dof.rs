//! A native nonlinear 6-DOF simulation of a JSBSim airframe: the rigid body with the full
//! inertia tensor as loaded, over a flat, non-rotating Earth with constant gravity, in the
//! standard atmosphere of the import, the model's aerodynamic functions evaluated at every
//! integration step by the import's own evaluator ([`crate::jsbsim`]).
//!
//! Data flow: [`state`] (the body's state and its attitude), [`airframe`] (the forces and
//! moments of the model at a state, the import's evaluation with the property names resolved
//! once), [`motion`] (the equations of motion), [`run`] (the start from the import's n-g trim,
//! the surfaces held, the integration), [`history`] (what a run records, as CSV), [`jump`] (the rule that calls
//! a jump in a sweep of aileron steps) and [`mod@sweep`] (a sweep's runs and verdict).

pub mod airframe;
pub mod history;
pub mod jump;
pub mod motion;
pub mod run;
pub mod state;
pub mod sweep;

pub use history::History;
pub use run::{simulate, Settings, Thrust};
pub use sweep::{sweep, Sweep};
