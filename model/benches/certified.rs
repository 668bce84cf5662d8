//! Benchmarks of the certified floating-point route against the exact path, measured
//! in the same run (the ratio of the medians is the speed-up), and what clearance builds on it.
//! Run with `cargo bench -p model --bench certified`.
//!
//! - `analyze_exact` / `analyze_fast`: the jump part of `analyze` (divergence, jumps, poles,
//!   critical jump, zero-sideslip departure) by big rationals and by the certified route;
//! - `enclose_lifted` / `enclose_tape`: the criterion polynomials of the jump analysis,
//!   enclosed by lifting the data into the parametric results and by the criterion program's
//!   tape (`analyze_fast`'s route without aileron yaw);
//! - `critical_lean`: the Monte Carlo's per-sample route (critical jump only, on the tape);
//! - `monte_carlo_1000`: 1000 seeded samples of `aircraft/a_uncertain.toml` on every core
//!   (samples per second = 1000 / median);
//! - `clear_a_uncertain`: the proof of that file (bounds, worst case, verdict).
//!
//! Everything runs under the command-line tool's allocator (mimalloc), as `model` does.

use model::aircraft::Aircraft;
use model::analysis::{analyze_with, fast};
use model::certified::Values;
use std::path::Path;

/// The command-line tool's allocator (model/src/main.rs), so that the benchmarks measure what
/// `model analyze` and `model clear` run. Baseline and certified route alike.
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

fn main() {
    // The parametric derivation and its compiled form are made once per process; keep them out
    // of every measurement.
    let _ = fast::analyze_fast(&Aircraft::a(), 0.0);
    divan::main();
}

fn aircraft(name: &str) -> Aircraft {
    Aircraft::builtin(name).unwrap_or_else(|| {
        let path = Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../aircraft")
            .join(name);
        model::aircraft::load(&path).expect("a committed aircraft file")
    })
}

const DELTA_E: f64 = 0.034_906_585_039_886_59; // 2 deg

/// The exact path (the baseline).
#[divan::bench(args = ["A", "B", "fighter.toml"])]
fn analyze_exact(bencher: divan::Bencher, name: &str) {
    let a = aircraft(name);
    bencher.bench(|| analyze_with(divan::black_box(&a), DELTA_E, false).map(|r| r.jump.len()));
}

/// The certified route (exact fallback where a certificate fails: none for these three).
#[divan::bench(args = ["A", "B", "fighter.toml"])]
fn analyze_fast(bencher: divan::Bencher, name: &str) {
    let a = aircraft(name);
    bencher.bench(|| fast::analyze_fast(divan::black_box(&a), DELTA_E).map(|r| r.jump.len()));
}

/// One Monte Carlo sample: the lean critical-jump route on the data's tape (the whole data
/// lifted only where the tape does not answer).
#[divan::bench(args = ["A", "B"])]
fn critical_lean(bencher: divan::Bencher, name: &str) {
    let a = aircraft(name);
    let bound = a.aileron_range();
    bencher.bench(|| {
        let a = divan::black_box(&a);
        let lift = || Values::of(a, DELTA_E, 0.0);
        let data = Values::data(a);
        fast::critical_of(&data, DELTA_E, &lift, bound, fast::MAX_WIDTH)
            .ok()
            .flatten()
    });
}

/// 1000 seeded samples on every core.
#[divan::bench(sample_count = 20)]
fn monte_carlo_1000(bencher: divan::Bencher) {
    let a = aircraft("a_uncertain.toml");
    bencher.bench(|| model::clearance::monte_carlo::run(&a, DELTA_E, 1000, 1, 0).samples);
}

/// The whole proof of `aircraft/a_uncertain.toml` (4 uncertain parameters; bounds, worst case,
/// verdict; no Monte Carlo).
#[divan::bench(sample_count = 3)]
fn clear_a_uncertain(bencher: divan::Bencher) {
    let a = aircraft("a_uncertain.toml");
    let settings = model::clearance::Settings::default();
    bencher.bench(|| model::clearance::clear(&a, &settings, &mut |_| {}).map(|r| r.boxes));
}

/// The criterion polynomials of the jump analysis enclosed the general way: the whole data
/// lifted into the parametric results, cleared in interval polynomials (`EnclosedPolys::new`).
#[divan::bench(args = ["A", "B"])]
fn enclose_lifted(bencher: divan::Bencher, name: &str) {
    let a = aircraft(name);
    bencher.bench(|| {
        let v = Values::of(divan::black_box(&a), DELTA_E, 0.0);
        model::certified::EnclosedPolys::new(&v).map(|e| e.jump.0.len())
    });
}

/// The same polynomials from the criterion program's tape (`EnclosedPolys::by_tape`), the
/// route `analyze_fast` takes without aileron yaw.
#[divan::bench(args = ["A", "B"])]
fn enclose_tape(bencher: divan::Bencher, name: &str) {
    let a = aircraft(name);
    bencher.bench(|| {
        let data = Values::data(divan::black_box(&a));
        model::certified::EnclosedPolys::by_tape(&data, DELTA_E).map(|e| e.map(|e| e.jump.0.len()))
    });
}
