//! Presentation: the report folder, the clearance's text, Markdown, CSV and figures, and the
//! text tables of `analyze`. The computing modules (`analysis`, `clearance`, `continuation`,
//! `simulation`) return results and never import this module; `main.rs` parses arguments and
//! calls one of them per command, then prints or writes through this one.

pub mod clearance;
pub mod numbers;
pub mod report;
pub mod tables;
