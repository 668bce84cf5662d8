//! Benchmarks of the flight envelope: one grid point of the F-104 (the 1-g trim, the
//! import there and the analysis of `analyze`), and the parts it is made of (the trim, the
//! aircraft file written at the trim, the aircraft read from it, and the trim attempt of an
//! untrimmable point), so that points per second (one over the median of a point) can be
//! quoted per part. Run with
//! `cargo bench -p model --bench envelope`; nothing runs when the JSBSim models are not
//! installed. Under the command-line tool's allocator (mimalloc), as `model` runs.

use model::envelope::source::Source;
use model::envelope::{Elevator, Point};
use model::jsbsim::condition::{Condition, Speed};
use model::jsbsim::import::{trimmed_file, Loaded};
use model::jsbsim::trim::trim;
use std::sync::OnceLock;

/// The command-line tool's allocator (model/src/main.rs).
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

fn main() {
    divan::main();
}

/// The F-104, read once; `None` without the JSBSim models.
fn f104() -> Option<&'static Loaded> {
    static LOADED: OnceLock<Option<Loaded>> = OnceLock::new();
    LOADED
        .get_or_init(|| Source::parse("jsbsim:f104").ok()?.load().ok())
        .as_ref()
}

/// One grid point, 6,000 m and Mach 0.6: trim, import, analysis.
#[divan::bench(sample_count = 20)]
fn point_f104_6000_m_mach_0_6() -> bool {
    f104().is_some_and(|l| {
        Point::at(l, "jsbsim:f104", 6000.0, 0.6, Elevator::default())
            .critical
            .is_some()
    })
}

/// The 1-g trim (alpha and elevator) alone at the same point.
#[divan::bench(sample_count = 20)]
fn one_g_trim_f104_6000_m_mach_0_6() -> f64 {
    f104().map_or(0.0, |l| {
        let c = Condition::new(6000.0, Speed::Mach(0.6)).unwrap();
        trim(&l.setup(c), 1.0).unwrap().alpha
    })
}

/// The aircraft file at the 1-g trim of the same point (the derivatives there and the text),
/// the trim found once.
#[divan::bench(sample_count = 20)]
fn trimmed_file_f104_6000_m_mach_0_6(bencher: divan::Bencher) {
    let Some(l) = f104() else { return };
    let setup = l.setup(Condition::new(6000.0, Speed::Mach(0.6)).unwrap());
    let t = trim(&setup, 1.0).unwrap();
    bencher.bench_local(|| trimmed_file(&setup, &t).unwrap().len());
}

/// The aircraft read from that file: the TOML, its exact decimals and the exact conversion to
/// the principal-axis derivatives.
#[divan::bench(sample_count = 20)]
fn parse_trimmed_file_f104_6000_m_mach_0_6(bencher: divan::Bencher) {
    let Some(l) = f104() else { return };
    let setup = l.setup(Condition::new(6000.0, Speed::Mach(0.6)).unwrap());
    let text = trimmed_file(&setup, &trim(&setup, 1.0).unwrap()).unwrap();
    bencher.bench_local(|| model::aircraft::parse(&text, "jsbsim:f104").unwrap().speed);
}

/// The 1-g trim attempt at 14,000 m and Mach 0.3, where the F-104 has no lift solution: the
/// whole alpha search, for the message that names CLmax.
#[divan::bench(sample_count = 20)]
fn untrimmable_f104_14000_m_mach_0_3() -> bool {
    f104().is_some_and(|l| {
        let c = Condition::new(14000.0, Speed::Mach(0.3)).unwrap();
        trim(&l.setup(c), 1.0).is_err()
    })
}
