//! Benchmarks of the Hopf criterion (beyond the paper): deriving it parametrically (Orlando's
//! Delta4 of the characteristic coefficients of J5, in the trim symbols and every parameter),
//! the Hopf part of `analyze` per aircraft, and `analyze` with and without it, measured in the
//! same run (the ratio of the medians is the cost of the Hopf answer), and the full `analyze` on
//! the certified route against the exact one (target: under 2 ms per aircraft). Run with
//! `cargo bench -p model --bench hopf`. Everything runs under the command-line tool's allocator
//! (mimalloc), as `model` does.

use model::aircraft::Aircraft;
use model::analysis::fast::{analyze_routed_with, Route};
use model::analysis::{
    analyze_with, parametric, parametric_characteristic, CriterionPolys, HopfPolys,
};
use model::derivation::hopf::{at_coefficients, orlando};

/// The command-line tool's allocator (model/src/main.rs), so that the benchmarks measure what
/// `model analyze` runs. Baseline and certified route alike.
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

fn main() {
    divan::main();
}

/// Delta4 of the parametric characteristic coefficients: the Hopf criterion in the trim
/// symbols with every parameter a symbol (61 600 terms; the characteristic coefficients are
/// derived once per process and shared).
#[divan::bench(sample_count = 10)]
fn parametric_delta4_in_trim_symbols() -> usize {
    at_coefficients(&orlando().delta4, parametric_characteristic()).len()
}

/// The Hopf polynomial and the model's derivatives specialised to one aircraft.
#[divan::bench(args = ["A", "B"])]
fn hopf_polys(name: &str) -> usize {
    let ac = Aircraft::builtin(name).unwrap();
    let de = 2f64.to_radians();
    let cp = CriterionPolys::new(parametric(), &ac, de);
    HopfPolys::new(&cp, divan::black_box(&ac), de)
        .hopf
        .coeffs()
        .len()
}

/// `analyze` with the Hopf points, landings and first departure.
#[divan::bench(args = ["A", "B"])]
fn analyze_with_hopf(name: &str) -> usize {
    let ac = Aircraft::builtin(name).unwrap();
    analyze_with(divan::black_box(&ac), 2f64.to_radians(), true)
        .unwrap()
        .hopf
        .len()
}

/// `analyze` without the Hopf part (jump analysis only), the baseline of the ratio.
#[divan::bench(args = ["A", "B"])]
fn analyze_without_hopf(name: &str) -> usize {
    let ac = Aircraft::builtin(name).unwrap();
    analyze_with(divan::black_box(&ac), 2f64.to_radians(), false)
        .unwrap()
        .jump
        .len()
}

/// The full `analyze` (jumps, Hopf points with omega and l1, landings, first departure,
/// zero-sideslip part) on the certified route, as `model analyze` runs it by default; compare
/// with `analyze_with_hopf`, the exact path, in the same run. Panics if the route falls back, so
/// the figure is the certified route's.
#[divan::bench(args = ["A", "B"])]
fn analyze_full_certified(name: &str) -> usize {
    let ac = Aircraft::builtin(name).unwrap();
    let (a, route) = analyze_routed_with(divan::black_box(&ac), 2f64.to_radians(), true).unwrap();
    assert!(matches!(route, Route::Certified(_)), "{route:?}");
    a.hopf.len()
}
