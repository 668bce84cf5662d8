//! `roll_criterion!`: the proc-macro front end of the roll-coupling criterion emitter.
//!
//! The macro expands, at compile time, the same closed-form functions that
//! `cargo run -p model -- emit` writes into the generated `roll-criterion` crate: the trims, the
//! 5x5 Jacobian, the stiffness matrix K and det K, det J5, the divergence roll rates and the
//! coefficients of the degree-12 jump polynomials of Mahale & Ananthkrishnan (AIAA 2006-6267).
//! Both front ends call one emitter, `model::emit::macro_items`, so they cannot drift apart;
//! this crate only parses its input and reports errors.
//!
//! # Syntax
//!
//! | input | expands to |
//! | --- | --- |
//! | `roll_criterion!(aircraft = "aircraft/a.toml")` | the functions with the file's data folded in |
//! | `roll_criterion!(aircraft = A)`, `aircraft = B` | the same for the built-in aircraft of Table A.1 |
//! | `roll_criterion!(parametric)` | the functions taking `k: &Derivatives`, and that struct |
//!
//! The path is relative to the directory of the crate that invokes the macro
//! (`CARGO_MANIFEST_DIR`), and the file has the format of `model::aircraft::load`. The expansion
//! includes the file with `include_bytes!`, so cargo recompiles the crate when the file changes.
//! A file's constants are folded exactly (rational arithmetic) and rounded once to f64.
//!
//! Every expansion defines the structs `Trim` and `ZeroSideslipTrim` (and, parametric,
//! `Derivatives`) and the functions `trim`, `zero_sideslip_trim`, `jacobian5`,
//! `residual_denominator`, `stiffness`, `det_k`, `det_j5`, `zero_sideslip_det_k`,
//! `divergence_biquadratic`, `divergence_roll_rates`, `jump_polynomial`,
//! `zero_sideslip_jump_polynomial`, `characteristic_coefficients`, `hurwitz_delta4` and
//! `hopf_omega_squared`, and for an aircraft `hopf_polynomial` (the exact Hopf polynomial of its
//! data; NaN with aileron yaw), and, parametric, the struct `Prepared` (det K prepared for many
//! roll rates) with its private module `prepared_lanes`; the doc comment of each gives its
//! formula and units. Since the names are fixed, put each invocation in a module of its own.
//!
//! The functions take square roots through `libm::sqrt`: add `libm = "0.2"` to the
//! `[dependencies]` of the invoking crate (which may be `#![no_std]`).
//!
//! # Example
//!
//! ```
//! mod aircraft_a {
//!     roll_criterion_derive::roll_criterion!(aircraft = A);
//! }
//! mod parametric {
//!     roll_criterion_derive::roll_criterion!(parametric);
//! }
//!
//! let delta_e = 2.0_f64.to_radians();
//! // det K changes sign at a jump roll rate of aircraft A near P0 = 1.706 rad/s (Fig. 7).
//! let below = aircraft_a::det_k(1.70, delta_e, 0.0);
//! let above = aircraft_a::det_k(1.71, delta_e, 0.0);
//! assert!(below * above < 0.0);
//!
//! // The parametric form takes the aircraft's data as its first argument.
//! fn det_k_at_2_deg(k: &parametric::Derivatives, p0: f64) -> f64 {
//!     parametric::det_k(k, p0, 2.0_f64.to_radians(), 0.0)
//! }
//! ```
//!
//! With the data in a file of the invoking crate:
//!
//! ```ignore
//! mod my_aircraft {
//!     roll_criterion_derive::roll_criterion!(aircraft = "aircraft/my_aircraft.toml");
//! }
//! ```
//!
//! # Errors
//!
//! Input errors are compile errors at the offending tokens, all of them at once: an unknown key,
//! a missing or wrongly typed value, duplicate keys, extra tokens. A file that cannot be read or
//! is not a valid aircraft file is reported at the path string, with the loader's message
//! (`path:line:column: ...`). The macro never panics.
//!
//! For tests under trybuild, which compiles in a crate of its own, the environment variable
//! `ROLL_CRITERION_MANIFEST_DIR`, when set, replaces `CARGO_MANIFEST_DIR` as the base of relative
//! paths.

#![warn(missing_docs)]

mod expand;
mod input;

use proc_macro::TokenStream;

/// Expands to the closed-form roll-coupling criterion functions; see the [crate] docs.
///
/// `roll_criterion!(aircraft = "path.toml")`, `roll_criterion!(aircraft = A)` (or `B`), or
/// `roll_criterion!(parametric)`.
#[proc_macro]
pub fn roll_criterion(input: TokenStream) -> TokenStream {
    let input = syn::parse_macro_input!(input as input::Input);
    expand::expand(input)
        .unwrap_or_else(syn::Error::into_compile_error)
        .into()
}
