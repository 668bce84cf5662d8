//! Benchmarks of the native 6-DOF: the F-104 of JSBSim's catalogue at 7,300 m, Mach 0.75, in
//! 1-g level flight, the aileron stepped to 10 deg (JSBSim's sign). Run with
//! `cargo bench -p model --bench six_dof`; the models are found as `model import jsbsim` finds
//! them (`JSBSIM_ROOT`, else the `jsbsim` Python package), and without them nothing is measured.
//!
//! - `twenty_seconds_f104`: 20 s of flight at 120 Hz (2,400 steps of the classical Runge-Kutta
//!   method, 9,600 evaluations of the aerodynamics), from the trim found once;
//! - `one_evaluation_f104`: one evaluation of the forces and moments at the trim, as a step
//!   makes it (the flight-state properties set by their resolved indices, then every function);
//! - `one_evaluation_by_name_f104`: the import's own evaluation of the coefficients at the same
//!   state (a fresh evaluation, every property set by name), the baseline.

use model::jsbsim::coefficients::Setup;
use model::jsbsim::condition::{Condition, Motion, Speed};
use model::jsbsim::import::Loaded;
use model::jsbsim::trim::{trim, Trim};
use model::six_dof::airframe::Airframe;
use model::six_dof::{simulate, Settings};
use std::sync::OnceLock;

/// The command-line tool's allocator (model/src/main.rs), so that the benchmarks measure what
/// `model` runs.
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

/// The F-104, read once.
static LOADED: OnceLock<Loaded> = OnceLock::new();

fn main() {
    let Some(root) = model::jsbsim::catalogue::root(None) else {
        eprintln!("{}", model::jsbsim::catalogue::HOW_TO_GET);
        return;
    };
    let path = root.join("aircraft/f104/f104.xml");
    let loaded = Loaded::new(path.to_str().expect("a UTF-8 path"), None, &[]).expect("F-104");
    let _ = LOADED.set(loaded);
    divan::main();
}

/// The setup at the condition and its 1-g trim.
fn trimmed() -> (Setup<'static>, Trim) {
    let loaded = LOADED.get().expect("set by main");
    let setup = loaded.setup(Condition::new(7300.0, Speed::Mach(0.75)).expect("condition"));
    let t = trim(&setup, 1.0).expect("the F-104 trims");
    (setup, t)
}

#[divan::bench(sample_count = 20)]
fn twenty_seconds_f104(bencher: divan::Bencher) {
    let (setup, t) = trimmed();
    let settings = Settings::step(10f64.to_radians(), 20.0);
    bencher.bench_local(|| simulate(&setup, &t, &settings).expect("the run"));
}

#[divan::bench(sample_count = 100)]
fn one_evaluation_f104(bencher: divan::Bencher) {
    let (setup, t) = trimmed();
    let state = t.state();
    let mut airframe = Airframe::new(
        setup.model,
        (&setup.condition, &state),
        &setup.surfaces,
        &[],
    )
    .expect("airframe");
    bencher.bench_local(|| {
        airframe
            .loads(&setup.condition, &state, &Motion::QUASI_STEADY, 0.0)
            .expect("loads")
    });
}

#[divan::bench(sample_count = 100)]
fn one_evaluation_by_name_f104(bencher: divan::Bencher) {
    let (setup, t) = trimmed();
    let state = t.state();
    bencher.bench_local(|| setup.coefficients(&state).expect("coefficients"));
}
