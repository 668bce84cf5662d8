//! The generated crate against an independent oracle: the SymPy values of
//! `tests/oracle/write_values.py` (committed in `oracle/mod.rs`), which share no code with the
//! Rust derivation that emitted the crate.
//!
//! Tolerances, from the error analysis of straight-line f64 evaluation: every folded constant is
//! rounded once (relative error u = 2^-53 = 1.1e-16) and a function of n operations on
//! well-conditioned data is then accurate to about n u times the condition of the sum it ends
//! in. det J5, d and det K at these roll rates are far from roots and poles (|det K| > 10) and
//! cost about 110 operations: 1e-13 relative (about 900 u) bounds them with room for the
//! cancellation of the sums. The jump polynomial's
//! coefficients are sums of up to 450 operations with cancellation between terms of opposite
//! sign: 1e-12 relative to the largest coefficient. The divergence roll rates pass through one
//! quadratic formula and two square roots: 1e-12. Measured: below 2e-15 for det K, det J5
//! and d, below 1e-15 for the jump coefficients (of the largest) and the divergence roll rates.

mod oracle;

use roll_criterion::{aircraft_a, aircraft_b, det_k};

fn close(got: f64, want: f64, rel: f64, what: &str) {
    let err = (got - want).abs() / want.abs();
    assert!(err <= rel, "{what}: got {got:e}, want {want:e}, relative error {err:e}");
}

type Point = fn(f64, f64, f64) -> f64;

fn check_det_k(
    name: &str,
    table: &[[f64; 4]],
    funcs: (Point, Point, Point),
    k: &roll_criterion::Derivatives,
) {
    for &[p0, dk, dj5, d] in table {
        let at = format!("{name} at P0 = {p0}");
        close(funcs.0(p0, oracle::DE, 0.0), dk, 1e-13, &format!("{at}: det K"));
        close(det_k(k, p0, oracle::DE, 0.0), dk, 1e-13, &format!("{at}: parametric det K"));
        close(funcs.1(p0, oracle::DE, 0.0), dj5, 1e-13, &format!("{at}: det J5"));
        close(funcs.2(p0, oracle::DE, 0.0), d, 1e-13, &format!("{at}: d"));
    }
}

fn check_jump_polynomial(name: &str, got: [f64; 13], want: &[f64; 13]) {
    let scale = want.iter().fold(0.0_f64, |m, c| m.max(c.abs()));
    for (i, (g, w)) in got.iter().zip(want).enumerate() {
        let err = (g - w).abs() / scale;
        assert!(err <= 1e-12, "{name}: P0^{i}: got {g:e}, want {w:e}, error {err:e} of the largest");
    }
}

#[test]
fn aircraft_a_det_k_det_j5_and_d_equal_the_sympy_values() {
    check_det_k(
        "A",
        &oracle::A_DET_K,
        (aircraft_a::det_k, aircraft_a::det_j5, aircraft_a::residual_denominator),
        &aircraft_a::DERIVATIVES,
    );
}

#[test]
fn aircraft_b_det_k_det_j5_and_d_equal_the_sympy_values() {
    check_det_k(
        "B",
        &oracle::B_DET_K,
        (aircraft_b::det_k, aircraft_b::det_j5, aircraft_b::residual_denominator),
        &aircraft_b::DERIVATIVES,
    );
}

#[test]
fn jump_polynomials_equal_the_sympy_coefficients() {
    check_jump_polynomial("A", aircraft_a::jump_polynomial(oracle::DE, 0.0), &oracle::A_JUMP_POLYNOMIAL);
    check_jump_polynomial("B", aircraft_b::jump_polynomial(oracle::DE, 0.0), &oracle::B_JUMP_POLYNOMIAL);
}

#[test]
fn table_1_divergence_roll_rates_equal_the_sympy_roots() {
    let [a1, a2] = aircraft_a::divergence_roll_rates();
    assert!(oracle::A_DIVERGENCE.is_empty() && a1.is_nan() && a2.is_nan());
    let got = aircraft_b::divergence_roll_rates();
    assert_eq!(oracle::B_DIVERGENCE.len(), 2);
    for (g, w) in got.iter().zip(oracle::B_DIVERGENCE) {
        close(*g, *w, 1e-12, "B: divergence roll rate");
    }
}
