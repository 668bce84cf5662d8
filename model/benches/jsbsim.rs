//! Benchmarks of a JSBSim model from its XML to the answer of `analyze`: the F-104 of JSBSim's
//! catalogue at 20,000 ft (6096 m), Mach 0.53, level flight. Run with
//! `cargo bench -p model --bench jsbsim`; the models are found as `model import jsbsim` finds
//! them (`JSBSIM_ROOT`, else the `jsbsim` Python package), and without them nothing is measured.
//!
//! - `import_f104`: read the XML, trim at 1 g (alpha and elevator), differentiate, write the aircraft file;
//! - `analyze_f104`: load that file and analyse it as `model analyze` does (the certified route
//!   with departures, the exact path where it cannot certify: the F-104 has aileron yaw);
//! - `import_and_analyze_f104`: both, the figure of "import plus analyze of one model";
//! - `analyze_f104_jump_part`: the analysis without the departures (Hopf points, landings),
//!   which the certified route answers.
//!
//! Where `analyze` spends its time on a real jet, and the certified route against the exact
//! path in the same run, on the F-104 imported at 6,000 m, Mach 0.6, trimmed at 1 g and
//! analysed at the trim's elevator (`delta_e = 0`), as
//! `model import jsbsim f104 --altitude-m 6000 --mach 0.6` and `model analyze` give it:
//!
//! - `routes::analyze_exact`: the exact path (`model analyze --exact`), the baseline;
//! - `routes::analyze_routed`: what `model analyze` runs (the certified route with departures,
//!   the exact path where it cannot certify: the F-104's aileron yaws, so its Hopf points fall
//!   back);
//! - `routes::analyze_first_departure`: the jump part and the first departure (what the
//!   envelope reports), certified along the primary branch;
//! - `routes::analyze_routed_jump_part`: the same without departures, which the certified route
//!   answers;
//! - `routes::criterion_polys_exact`, `routes::hopf_polys_exact`: the exact path's stages, the
//!   criterion polynomials (det A, trim, det J5, d specialised) and the Hopf polynomial (the
//!   resultant in delta_a, in big rationals);
//! - `routes::analyze_exact_jump_part`: the exact path without departures (its jump part).
//!
//! And at 0 m, Mach 0.7, 1 g, a point where the enclosures of the jump polynomial cannot certify
//! its roots (the certified jump part falls back; the walks along the primary branch answer):
//!
//! - `routes::fallback_analyze_exact`: the exact path there, the baseline;
//! - `routes::fallback_first_departure`: what the envelope runs there (the critical jump and
//!   the first departure certified along the primary branch).

use model::analysis::fast::analyze_routed_with;
use model::jsbsim::condition::Speed;
use model::jsbsim::import::{import, Alpha, Request};

/// The command-line tool's allocator (model/src/main.rs), so that the benchmarks measure what
/// `model` runs.
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

fn main() {
    let Some(root) = model::jsbsim::catalogue::root(None) else {
        eprintln!("{}", model::jsbsim::catalogue::HOW_TO_GET);
        return;
    };
    let path = root.join("aircraft/f104/f104.xml");
    std::env::set_var("F104_XML", &path);
    // The parametric derivation is made once per process; keep it out of every measurement.
    let _ = analyze_routed_with(&model::aircraft::Aircraft::a(), 0.0, true);
    divan::main();
}

fn request() -> Request {
    Request {
        model: std::env::var("F104_XML").expect("set by main"),
        root: None,
        altitude_m: 6096.0,
        speed: Speed::Mach(0.53),
        alpha: Alpha::Trim(1.0),
        settings: Vec::new(),
    }
}

fn analyze(text: &str, departures: bool) {
    let ac = model::aircraft::parse(text, "f104.toml").expect("the import loads");
    analyze_routed_with(&ac, 2f64.to_radians(), departures).expect("the F-104 is analysed");
}

#[divan::bench(sample_count = 10)]
fn import_f104() -> String {
    import(&request()).expect("the F-104 imports")
}

#[divan::bench(sample_count = 10)]
fn analyze_f104(bencher: divan::Bencher) {
    let text = import(&request()).expect("the F-104 imports");
    bencher.bench(|| analyze(&text, true));
}

#[divan::bench(sample_count = 10)]
fn import_and_analyze_f104() {
    analyze(&import(&request()).expect("the F-104 imports"), true);
}

#[divan::bench(sample_count = 10)]
fn analyze_f104_jump_part(bencher: divan::Bencher) {
    let text = import(&request()).expect("the F-104 imports");
    bencher.bench(|| analyze(&text, false));
}

/// The F-104 at 6,000 m, Mach 0.6, 1 g, by route and by stage of the exact path.
mod routes {
    use super::*;
    use model::aircraft::Aircraft;
    use model::analysis::{analyze, analyze_with, parametric, CriterionPolys, HopfPolys};

    /// The imported F-104 at 6,000 m, Mach 0.6, 1 g.
    fn f104() -> Aircraft {
        f104_at(6000.0, 0.6)
    }

    /// The imported F-104 at `altitude_m` and Mach `mach`, 1 g.
    fn f104_at(altitude_m: f64, mach: f64) -> Aircraft {
        let request = Request {
            model: std::env::var("F104_XML").expect("set by main"),
            root: None,
            altitude_m,
            speed: Speed::Mach(mach),
            alpha: Alpha::Trim(1.0),
            settings: Vec::new(),
        };
        let text = import(&request).expect("the F-104 imports");
        model::aircraft::parse(&text, "f104.toml").expect("the import loads")
    }

    #[divan::bench(sample_count = 10)]
    fn analyze_exact(bencher: divan::Bencher) {
        let ac = f104();
        bencher.bench(|| analyze(divan::black_box(&ac), 0.0).expect("analysed"));
    }

    #[divan::bench(sample_count = 10)]
    fn analyze_routed(bencher: divan::Bencher) {
        let ac = f104();
        bencher.bench(|| analyze_routed_with(divan::black_box(&ac), 0.0, true).expect("analysed"));
    }

    #[divan::bench(sample_count = 10)]
    fn analyze_first_departure(bencher: divan::Bencher) {
        let ac = f104();
        bencher.bench(|| {
            model::analysis::fast::analyze_first_departure(divan::black_box(&ac), 0.0)
                .expect("analysed")
        });
    }

    #[divan::bench(sample_count = 10)]
    fn analyze_routed_jump_part(bencher: divan::Bencher) {
        let ac = f104();
        bencher.bench(|| analyze_routed_with(divan::black_box(&ac), 0.0, false).expect("analysed"));
    }

    #[divan::bench(sample_count = 10)]
    fn criterion_polys_exact(bencher: divan::Bencher) {
        let ac = f104();
        bencher.bench(|| CriterionPolys::new(parametric(), divan::black_box(&ac), 0.0));
    }

    #[divan::bench(sample_count = 10)]
    fn hopf_polys_exact(bencher: divan::Bencher) {
        let ac = f104();
        let cp = CriterionPolys::new(parametric(), &ac, 0.0);
        bencher.bench(|| HopfPolys::new(divan::black_box(&cp), &ac, 0.0));
    }

    #[divan::bench(sample_count = 10)]
    fn analyze_exact_jump_part(bencher: divan::Bencher) {
        let ac = f104();
        bencher.bench(|| analyze_with(divan::black_box(&ac), 0.0, false).expect("analysed"));
    }

    #[divan::bench(sample_count = 10)]
    fn fallback_analyze_exact(bencher: divan::Bencher) {
        let ac = f104_at(0.0, 0.7);
        bencher.bench(|| analyze(divan::black_box(&ac), 0.0).expect("analysed"));
    }

    #[divan::bench(sample_count = 10)]
    fn fallback_first_departure(bencher: divan::Bencher) {
        let ac = f104_at(0.0, 0.7);
        bencher.bench(|| {
            model::analysis::fast::analyze_first_departure(divan::black_box(&ac), 0.0)
                .expect("analysed")
        });
    }
}
