//! Benchmarks of the whole parametric derivation (steps 1-8, including the degree-12
//! jump polynomial) and `analyze` on one aircraft, against a numeric baseline measured in the
//! same run (one LU trim plus the eigenvalues of the 5x5 Jacobian: the route the criterion
//! replaces, at a single P0).
//!
//! Also `emit` end to end. Run with `cargo bench -p model --bench derivation`.

use model::aircraft::Aircraft;
use model::analysis::analyze;
use model::derivation::Derivation;
use nalgebra::{Matrix4, Matrix5, Vector4};

fn main() {
    divan::main();
}

/// Steps 1-8 for symbolic parameters (trims, Eq. 5, Eqs 6-35, identity, the trim condition and
/// det J5 and d on the trim, and the zero-sideslip jump polynomials, which are computed on first
/// use and so forced here; the aileron elimination is benchmarked per aircraft in `analyze`).
#[divan::bench]
fn parametric_derivation() -> usize {
    let d = Derivation::parametric();
    d.trim_condition().len()
        + d.jump_at().len()
        + d.d_at().len()
        + d.zs_jump().len()
        + d.zs_d_det().len()
}

/// Everything `model analyze A` computes (specialised derivation, gcds, roots, trims).
#[divan::bench(args = ["A", "B"])]
fn analyze_aircraft(name: &str) -> usize {
    let ac = Aircraft::builtin(name).unwrap();
    let a = analyze(divan::black_box(&ac), 2f64.to_radians()).unwrap();
    a.jump.len()
}

/// Baseline: one numeric trim (LU) and the eigenvalues of J5 at one P0, aircraft A.
#[divan::bench]
fn baseline_numeric_trim_and_eigenvalues_one_p0() -> f64 {
    let k = Aircraft::a().values_f64();
    let [c, d, e, za, yb, lp, lr, lb, _lda, mq, ma, mde, np, nr, nb, _nda, _ndr, _ldr, z0, at] = k;
    let (p0, de) = (divan::black_box(1.7), 2f64.to_radians());
    let a = Matrix4::new(
        za,
        -p0,
        1.0,
        0.0,
        p0,
        yb,
        0.0,
        -1.0,
        ma,
        0.0,
        mq,
        c * p0,
        0.0,
        nb,
        -d * p0,
        nr,
    );
    let rhs = Vector4::new(-z0, -at * p0, -mde * de, -np * p0);
    let y = a.lu().solve(&rhs).unwrap();
    let (al, be, q, r) = (y[0], y[1], y[2], y[3]);
    let j = Matrix5::new(
        za,
        -p0,
        -be,
        1.0,
        0.0, //
        p0,
        yb,
        al + at,
        0.0,
        -1.0, //
        0.0,
        lb,
        lp,
        -e * r,
        lr - e * q, //
        ma,
        0.0,
        c * r,
        mq,
        c * p0, //
        0.0,
        nb,
        np - d * q,
        -d * p0,
        nr,
    );
    j.complex_eigenvalues()
        .iter()
        .map(|z| z.re)
        .fold(f64::MIN, f64::max)
}

/// `emit` end to end (derive, CSE, print, format, write to a scratch directory).
#[divan::bench]
fn emit_end_to_end() -> usize {
    let dir = std::env::temp_dir().join(format!("emit-bench-{}", std::process::id()));
    let outputs = model::emit::generate().unwrap();
    // Remove the previous run's files so that every iteration really writes.
    let _ = std::fs::remove_dir_all(&dir);
    model::emit::write(&dir, &outputs).unwrap().len()
}
