//! Presentation: the commands of `model` (their options, and one function per command that
//! computes, prints and writes), the report folder, the clearance's text, Markdown, CSV and
//! figures, the text tables of `analyze`, and how numbers print. The computing modules
//! (`analysis`, `clearance`, `continuation`, `simulation`) return results and never import this
//! module; `main.rs` parses the arguments and calls one function of [`commands`] per command.

pub mod catalogue;
pub mod clearance;
pub mod commands;
pub mod envelope;
pub mod envelope_clearance;
pub mod envelope_clearance_map;
pub mod envelope_folder;
pub mod envelope_maps;
pub mod envelope_validation;
pub mod envelope_validation_map;
pub mod failure;
pub mod numbers;
pub mod options;
pub mod outputs;
pub mod progress;
pub mod report;
pub mod six_dof;
pub mod tables;
pub mod validate;
