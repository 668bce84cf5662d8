//! Benchmarks of `model envelope --uncertainty`: the certified clearance of one grid point of
//! the F-104 (6,000 m, Mach 0.6, 1 g) against the number of uncertain coefficients (2, 6 and all
//! 15) and their relative width (5, 10 and 20 %), with the settings of an envelope's point
//! ([`model::envelope::clearance::settings`]). One sample each: a point can take tens of seconds.
//! The point of `model envelope jsbsim:f104 --altitude-m 6000 --mach 0.6 --uncertainty 10%`
//! (all 15 coefficients +- 10 %) has its own case, sampled for a median, beside a same-run
//! baseline: the exact analysis of its nominal aircraft (`analyze`'s jump part), one of the
//! analyses the clearance's worst-case search makes. Run with `cargo bench -p model --bench
//! envelope_uncertainty` (`-- point` for those two alone); nothing runs when the JSBSim models
//! are not installed. Under the command-line tool's allocator (mimalloc), as `model` runs.

use model::aircraft::convert::Coefficient;
use model::envelope::clearance::clear_point;
use model::envelope::source::Source;
use model::envelope::uncertainty::Uncertainty;
use model::jsbsim::condition::{Condition, Speed};
use model::jsbsim::import::trimmed_file;
use model::jsbsim::trim::trim;
use std::sync::OnceLock;

/// The command-line tool's allocator (model/src/main.rs).
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

fn main() {
    divan::main();
}

/// The F-104's file at 6,000 m, Mach 0.6 at its 1-g trim, imported once; `None` without the
/// JSBSim models.
fn f104() -> Option<&'static str> {
    static TEXT: OnceLock<Option<String>> = OnceLock::new();
    TEXT.get_or_init(|| {
        let loaded = Source::parse("jsbsim:f104").ok()?.load().ok()?;
        let setup = loaded.setup(Condition::new(6000.0, Speed::Mach(0.6)).ok()?);
        trimmed_file(&setup, &trim(&setup, 1.0).ok()?).ok()
    })
    .as_deref()
}

/// The first `n` coefficients of the box, the lateral damping and stiffness first.
fn spec(n: usize, percent: u32) -> String {
    let first = [
        "Cl_p",
        "Cn_r",
        "Cl_beta",
        "Cn_beta",
        "Cl_delta_a",
        "Cn_delta_a",
    ];
    let rest = Coefficient::ALL.iter().map(|c| c.key());
    let keys: Vec<&str> = first
        .into_iter()
        .chain(rest.filter(|k| !first.contains(k)))
        .take(n)
        .collect();
    let widths: Vec<String> = keys.iter().map(|k| format!("{k}={percent}%")).collect();
    widths.join(",")
}

/// One point's clearance with `N` coefficients uncertain by `percent` %.
#[divan::bench(consts = [2, 6, 15], args = [5, 10, 20], sample_count = 1, sample_size = 1)]
fn clearance_f104_6000_m_mach_0_6<const N: usize>(percent: u32) -> bool {
    f104().is_some_and(|text| {
        let u = Uncertainty::parse(&spec(N, percent)).unwrap();
        let a = u.aircraft(text, "jsbsim:f104").unwrap();
        clear_point(&a, 0.0).is_ok()
    })
}

/// The envelope's point with `--uncertainty 10%`: every coefficient +- 10 %, as `model envelope`
/// clears it.
#[divan::bench(sample_count = 7, sample_size = 1)]
fn point_clearance_15_coefficients_10_percent() -> bool {
    f104().is_some_and(|text| {
        let u = Uncertainty::parse("10%").unwrap();
        let a = u.aircraft(text, "jsbsim:f104").unwrap();
        clear_point(&a, 0.0).is_ok()
    })
}

/// Baseline of the same run: the exact path's critical jump of the point's nominal aircraft.
#[divan::bench(sample_count = 7, sample_size = 1)]
fn point_baseline_exact_analysis_nominal() -> bool {
    f104().is_some_and(|text| {
        let a = model::aircraft::parse(text, "jsbsim:f104").unwrap();
        model::clearance::critical(&a, 0.0).is_ok()
    })
}
