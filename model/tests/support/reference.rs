//! Reference numbers the tests check, each written once, at delta_e = 2 deg and delta_r = 0.
//!
//! Sources: the paper (AIAA 2006-6267: Table 1, Figs 1-11, given there to two or three digits)
//! and computations that share no code with `model`: the independent numeric oracle of
//! `paper_tests` (hand-written PSS model, LU trims, scan and bisection of det J5 on its
//! finite-difference Jacobian; `tests/tests/paper.rs` recomputes its numbers) and an independent
//! AUTO-07p continuation (the Hopf points of B), to the digits printed.
//!
//! One file, included by path wherever the numbers are needed, so that no crate under test
//! depends on another for them: `paper_tests::reference` (tests/src/lib.rs), the unit tests and
//! the test generator of `model` (model/src/lib.rs), `model`'s integration tests (as
//! `support::reference`) and `derive/tests/expand.rs`. Nothing here is computed.

/// Aircraft A: the jump roll rates, rad/s (roots of det K, Fig. 7; the folds of Fig. 1).
pub const A_JUMP_P0: [f64; 2] = [1.706288, 3.033180];
/// Aircraft A: the aileron of the first jump (the critical point), deg (Figs 1, 5).
pub const A_FOLD_DELTA_A_DEG: f64 = -3.8467;
/// Aircraft B: the jump roll rates, rad/s (roots of det K, Fig. 8).
pub const B_JUMP_P0: [f64; 4] = [2.595015, 3.006127, 3.351058, 4.627182];
/// Aircraft B: the aileron of the first jump, deg (Figs 2, 6).
pub const B_FOLD_DELTA_A_DEG: f64 = -11.2068;
/// Aircraft A: the zero-sideslip departure roll rates, rad/s (Fig. 11).
pub const A_ZERO_SIDESLIP_P0: [f64; 2] = [2.130625, 4.457684];
/// Aircraft A: the aileron of the first zero-sideslip departure, deg (Fig. 9; the paper reads
/// about -0.15 rad).
pub const A_ZERO_SIDESLIP_DELTA_A_DEG: f64 = -8.1639;
/// Aircraft B: the pitch-yaw divergence roll rates of Eq. 5, rad/s (independent computation).
pub const B_DIVERGENCE_P0: [f64; 2] = [2.986460, 4.783697];
/// Aircraft B: the divergence roll rates as Table 1 of the paper prints them, rad/s.
pub const TABLE_1_B: [f64; 2] = [2.98, 4.78];
/// Aircraft B: the Hopf points by an independent AUTO-07p continuation: trim roll rate P0
/// (rad/s), aileron (deg) and the frequency omega of the imaginary pair (rad/s).
pub const B_HOPF: [(f64, f64, f64); 2] = [(3.129030, -20.70, 0.8796), (4.731306, -12.71, 5.1854)];
