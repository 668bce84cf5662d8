//! The speed of det K, measured in one run: the generated parametric det K (trim
//! included), the prepared det K (`Prepared::det_k` per call, and the slice form
//! `Prepared::det_k_into`), CasADi's generated C for the same det K (tests/oracle/casadi_det_k.py,
//! compiled at -O2 by tests/build.rs; left out without a C compiler) and numeric routes in Rust
//! with nalgebra (LU trim + Schur-complement K, LU trim + 5x5 determinant, LU trim + eigenvalues
//! of J5), all for aircraft B over the same 1000 roll rates, so that nothing is constant-folded.
//!
//! Run with `cargo bench -p paper-tests --bench det_k`.

use nalgebra::{Matrix2, Matrix3, Matrix4, Matrix5, Vector4};
use roll_criterion as gen;

fn main() {
    divan::main();
}

const DE: f64 = 0.03490658503988659;
const N: usize = 1000;

fn p0s() -> Vec<f64> {
    (0..N).map(|i| 0.2 + 4.5 * i as f64 / N as f64).collect()
}

/// The trim by LU and the Jacobian at it, numerically (aircraft B's data).
fn numeric_jacobian(k: &gen::Derivatives, p0: f64) -> Matrix5<f64> {
    let a = Matrix4::new(
        k.z_alpha,
        -p0,
        1.0,
        0.0, //
        p0,
        k.y_beta,
        0.0,
        -1.0, //
        k.m_alpha,
        0.0,
        k.m_q,
        k.c * p0, //
        0.0,
        k.n_beta,
        -k.d * p0,
        k.n_r,
    );
    let rhs = Vector4::new(0.0, 0.0, -k.m_delta_e * DE, -k.n_p * p0);
    let y = a.lu().solve(&rhs).unwrap_or_else(Vector4::zeros);
    let (al, be, q, r) = (y[0], y[1], y[2], y[3]);
    Matrix5::new(
        k.z_alpha,
        -p0,
        -be,
        1.0,
        0.0, //
        p0,
        k.y_beta,
        al,
        0.0,
        -1.0, //
        0.0,
        k.l_beta,
        k.l_p,
        -k.e * r,
        k.l_r - k.e * q, //
        k.m_alpha,
        0.0,
        k.c * r,
        k.m_q,
        k.c * p0, //
        0.0,
        k.n_beta,
        k.n_p - k.d * q,
        -k.d * p0,
        k.n_r,
    )
}

/// Runs `route` over the 1000 roll rates of [`p0s`] with aircraft B's data, one divan item each.
fn run(b: divan::Bencher, route: impl Fn(&gen::Derivatives, f64) -> f64) {
    let k = gen::aircraft_b::DERIVATIVES;
    let ps = p0s();
    b.counter(divan::counter::ItemsCount::new(N))
        .bench_local(|| {
            ps.iter()
                .map(|p| route(divan::black_box(&k), divan::black_box(*p)))
                .sum::<f64>()
        });
}

#[divan::bench]
fn generated_det_k(b: divan::Bencher) {
    run(b, |k, p| gen::det_k(k, p, DE, 0.0));
}

#[divan::bench]
fn prepared_det_k(b: divan::Bencher) {
    let k = gen::aircraft_b::DERIVATIVES;
    let prepared = gen::Prepared::new(divan::black_box(&k), DE, 0.0);
    run(b, |_, p| prepared.det_k(p));
}

/// The slice form over the same 1000 roll rates, summed as the others are.
#[divan::bench]
fn prepared_det_k_into(b: divan::Bencher) {
    let k = gen::aircraft_b::DERIVATIVES;
    let prepared = gen::Prepared::new(divan::black_box(&k), DE, 0.0);
    let ps = p0s();
    let mut out = vec![0.0; N];
    b.counter(divan::counter::ItemsCount::new(N))
        .bench_local(|| {
            prepared.det_k_into(divan::black_box(&ps), &mut out);
            divan::black_box(&out).iter().sum::<f64>()
        });
}

#[divan::bench]
fn casadi_generated_c_det_k(b: divan::Bencher) {
    let k = model::aircraft::Aircraft::b().values_f64();
    if paper_tests::casadi_det_k(&k, 1.0, DE, 0.0).is_none() {
        eprintln!("SKIPPED casadi_generated_c_det_k: CasADi's C was not compiled (no C compiler)");
        return;
    }
    run(b, |_, p| {
        paper_tests::casadi_det_k(divan::black_box(&k), p, DE, 0.0).unwrap_or(f64::NAN)
    });
}

#[divan::bench]
fn numeric_lu_trim_and_schur_k(b: divan::Bencher) {
    run(b, |k, p| {
        let j = numeric_jacobian(k, p);
        // K is, up to row signs, the Schur complement onto [alpha, beta] of the static
        // system: rows (q_dot, r_dot) against columns (alpha, beta), eliminating [p, q, r]
        // with rows (alpha_dot, beta_dot, p_dot).
        let e1y = Matrix2::new(j[(3, 0)], j[(3, 1)], j[(4, 0)], j[(4, 1)]);
        let e1z = nalgebra::Matrix2x3::new(
            j[(3, 2)],
            j[(3, 3)],
            j[(3, 4)],
            j[(4, 2)],
            j[(4, 3)],
            j[(4, 4)],
        );
        let e2y = nalgebra::Matrix3x2::new(
            j[(0, 0)],
            j[(0, 1)],
            j[(1, 0)],
            j[(1, 1)],
            j[(2, 0)],
            j[(2, 1)],
        );
        let e2z = Matrix3::new(
            j[(0, 2)],
            j[(0, 3)],
            j[(0, 4)],
            j[(1, 2)],
            j[(1, 3)],
            j[(1, 4)],
            j[(2, 2)],
            j[(2, 3)],
            j[(2, 4)],
        );
        let z = e2z
            .lu()
            .solve(&e2y)
            .unwrap_or_else(nalgebra::Matrix3x2::zeros);
        (e1y - e1z * z).determinant()
    });
}

#[divan::bench]
fn numeric_lu_trim_and_det_j5(b: divan::Bencher) {
    run(b, |k, p| numeric_jacobian(k, p).determinant());
}

#[divan::bench]
fn numeric_lu_trim_and_eigenvalues_of_j5(b: divan::Bencher) {
    run(b, |k, p| numeric_jacobian(k, p).complex_eigenvalues()[0].re);
}
