//! Benchmarks of the flight envelope: one grid point of the F-104 (the 1-g trim, the
//! import there and the analysis of `analyze`), and the parts it is made of, so that points per
//! second (one over the median of a point) can be quoted per part. Run with
//! `cargo bench -p model --bench envelope`; nothing runs when the JSBSim models are not
//! installed. Under the command-line tool's allocator (mimalloc), as `model` runs.

use model::envelope::source::Source;
use model::envelope::{Elevator, Point};
use model::jsbsim::condition::{Condition, Speed};
use model::jsbsim::import::Loaded;
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
