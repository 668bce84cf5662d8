//! Benchmarks of the continuation: the whole bifurcation diagram of aircraft B over delta_a in
//! [-0.8, 0.8] rad (Fig. 2 of AIAA 2006-6267: every branch, found automatically from the
//! roll-rate grid, with folds, Hopf points and branch points located), against a baseline
//! measured in the same run: one `analyze(B)` (the closed-form criterion of section IV, which
//! gives the same fold roll rates exactly). Also aircraft A (Fig. 1) and the zero-sideslip
//! extended bifurcation analysis of A (section V.B, Fig. 9).
//!
//! Run with `cargo bench -p model --bench continuation`; quote the medians.

use model::aircraft::Aircraft;
use model::analysis::analyze;
use model::continuation::{continue_equilibria, Settings};

fn main() {
    divan::main();
}

/// Every branch of the PSS equilibria over delta_a in [-0.8, 0.8] with special points located
/// (delta_e = 2 deg, delta_r = 0; default settings, including building the compiled model).
#[divan::bench(args = ["A", "B"])]
fn all_branches(name: &str) -> usize {
    let ac = Aircraft::builtin(name).unwrap();
    let d = continue_equilibria(divan::black_box(&ac), &Settings::default(), &mut |_| {}).unwrap();
    d.special_points.len()
}

/// The zero-sideslip roll of aircraft A: EBA steps 1 and 2 and branch switching at the
/// departure (Fig. 9).
#[divan::bench]
fn zero_sideslip_a() -> usize {
    let ac = Aircraft::a();
    let settings = Settings {
        zero_sideslip: true,
        ..Settings::default()
    };
    let d = continue_equilibria(divan::black_box(&ac), &settings, &mut |_| {}).unwrap();
    d.special_points.len()
}

/// Baseline: the analytical criterion for aircraft B (`model analyze B`).
#[divan::bench]
fn baseline_analyze_b() -> usize {
    let ac = Aircraft::b();
    analyze(divan::black_box(&ac), 2f64.to_radians())
        .unwrap()
        .jump
        .len()
}
