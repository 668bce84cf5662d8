//! The straight-line programs the emitter prints and the certified route evaluates.
//!
//! A program is a hash-consed expression DAG ([`expr`]) built from the derivation's polynomials
//! by one builder ([`builder`]): the trim by Cramer's rule, step 8 of the derivation, det K by the
//! matrix determinant lemma. Like terms of its sums are merged exactly ([`linear`]), and a
//! program can be split into what depends only on the aircraft and the controls and what depends
//! on the roll rate ([`stage`]). The criterion program ([`criterion`]) holds the certified route's
//! polynomials. Two clients read these programs and neither owns them: `emit` prints them as
//! Rust, C and LaTeX, `certified` evaluates them in f64 with a bound on their rounding. This
//! module uses neither: it sits below both.

pub(crate) mod builder;
// The certified route's only: the proc-macro's build (no `analysis`) leaves it out.
#[cfg(feature = "analysis")]
pub(crate) mod criterion;
pub(crate) mod expr;
pub(crate) mod linear;
pub(crate) mod stage;
