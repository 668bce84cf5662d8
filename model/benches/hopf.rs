//! Benchmarks of issue 10: deriving the Hopf criterion parametrically (Orlando's Delta4 of the
//! characteristic coefficients of J5, in the trim symbols and every parameter), the Hopf part of
//! `analyze` per aircraft, and `analyze` with and without it, measured in the same run (the
//! ratio of the medians is the cost of the new answer). Run with
//! `cargo bench -p model --bench hopf`.

use model::aircraft::Aircraft;
use model::analysis::{
    analyze_with, parametric, parametric_characteristic, CriterionPolys, HopfPolys,
};
use model::derivation::hopf::{at_coefficients, orlando};

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

/// `analyze` as before issue 10 (jump analysis only), the baseline of the ratio.
#[divan::bench(args = ["A", "B"])]
fn analyze_without_hopf(name: &str) -> usize {
    let ac = Aircraft::builtin(name).unwrap();
    analyze_with(divan::black_box(&ac), 2f64.to_radians(), false)
        .unwrap()
        .jump
        .len()
}
