//! The paper's numbers, reproduced from the derived formulas (`model::analysis`).
//!
//! Expected values: the paper (Table 1, Figs 7, 8, 11; its data are rounded, so about 0.1 %) and an
//! independent numeric computation (AUTO-style continuation and eigenvalues, 6-7 digits). Each is
//! also re-checked here against the independent oracle in `paper_tests` (hand-written model, LU
//! trims, nalgebra eigenvalues).

use model::aircraft::Aircraft;
use model::analysis::{analyze, Analysis};
use paper_tests::{fd_jacobian, real_eigenvalues, reference, trim, Params};

fn params(ac: &Aircraft) -> Params {
    ac.values_f64()
}

fn at_2deg(ac: &Aircraft) -> Analysis {
    analyze(ac, 2f64.to_radians()).expect("paper aircraft analyse")
}

fn assert_close(got: &[f64], want: &[f64], rel: f64, what: &str) {
    assert_eq!(got.len(), want.len(), "{what}: got {got:?}, want {want:?}");
    for (g, w) in got.iter().zip(want) {
        assert!(
            ((g - w) / w).abs() <= rel,
            "{what}: got {g}, want {w} (rel tol {rel})"
        );
    }
}

#[test]
fn table_1_divergence_roll_rates_aircraft_a_none() {
    assert!(at_2deg(&Aircraft::a()).divergence_roll_rates.is_empty());
}

#[test]
fn table_1_divergence_roll_rates_aircraft_b() {
    let got = at_2deg(&Aircraft::b()).divergence_roll_rates;
    // The independent numeric computation and the paper.
    assert_close(
        &got,
        &reference::B_DIVERGENCE_P0,
        2e-7,
        "Table 1 (independent)",
    );
    assert_close(&got, &reference::TABLE_1_B, 3e-3, "Table 1 (paper)");
}

#[test]
fn fig_7_det_k_roots_aircraft_a_are_the_saddle_nodes_of_fig_1() {
    let a = at_2deg(&Aircraft::a());
    let p0: Vec<f64> = a.jump.iter().map(|j| j.p0).collect();
    assert_close(&p0, &reference::A_JUMP_P0, 1e-6, "Fig. 7 (independent)");
    assert_close(&p0, &[1.70, 3.03], 4e-3, "Fig. 7 (paper)");
    // Fig. 1: saddle-nodes near delta_a = -4 deg and +8 deg; the independent computation
    // gives the first.
    let fold = reference::A_FOLD_DELTA_A_DEG;
    assert!(
        (a.jump[0].delta_a_deg - fold).abs() < 1e-3,
        "{:?}",
        a.jump[0]
    );
    assert!((a.jump[0].delta_a_rad - fold.to_radians()).abs() < 1e-5);
    assert!((a.jump[1].delta_a_deg - 8.0).abs() < 1.0, "{:?}", a.jump[1]);
    assert!(
        a.det_k_poles.is_empty(),
        "A has no poles below the range: {:?}",
        a.det_k_poles
    );
}

#[test]
fn fig_8_det_k_roots_and_poles_aircraft_b() {
    let b = at_2deg(&Aircraft::b());
    let p0: Vec<f64> = b.jump.iter().map(|j| j.p0).collect();
    assert_close(&p0, &reference::B_JUMP_P0, 1e-6, "Fig. 8 roots");
    assert_close(
        &b.det_k_poles.iter().map(|j| j.p0).collect::<Vec<_>>(),
        &[2.95891, 3.01944, 4.68475, 4.88055],
        1e-5,
        "Fig. 8 poles",
    );
    // Fig. 2: the primary branch folds near delta_a = -12 deg.
    assert!(
        (b.jump[0].delta_a_deg - -12.0).abs() < 1.0,
        "{:?}",
        b.jump[0]
    );
}

#[test]
fn fig_11_zero_sideslip_departure_aircraft_a() {
    let a = at_2deg(&Aircraft::a());
    let p0: Vec<f64> = a.zero_sideslip.departure.iter().map(|j| j.p0).collect();
    assert_close(
        &p0,
        &reference::A_ZERO_SIDESLIP_P0,
        1e-6,
        "Fig. 11 (independent)",
    );
    assert_close(
        &p0,
        &[2.1293, 4.4546],
        1e-3,
        "Fig. 11 (paper, rounded data)",
    );
}

/// At every reported jump point a real eigenvalue of J5 (nalgebra, finite-difference Jacobian
/// at an LU trim) changes sign between P0 - h and P0 + h: a saddle-node, as the paper claims.
fn assert_real_eigenvalue_crosses_zero(ac: &Aircraft, a: &Analysis) {
    let k = params(ac);
    let de = a.delta_e_rad;
    for j in &a.jump {
        let h = 1e-4;
        let count_positive = |p0: f64| {
            let (x, da) = trim(&k, p0, de, 0.0).expect("regular trim");
            real_eigenvalues(&fd_jacobian(&k, &x, &[da, de, 0.0]))
                .iter()
                .filter(|l| **l > 0.0)
                .count()
        };
        let (below, above) = (count_positive(j.p0 - h), count_positive(j.p0 + h));
        assert_eq!(
            below.abs_diff(above),
            1,
            "{}: at P0 = {} the number of positive real eigenvalues goes {below} -> {above}",
            a.aircraft,
            j.p0
        );
    }
}

#[test]
fn det_k_roots_are_saddle_nodes_fig_7_and_8() {
    for ac in [Aircraft::a(), Aircraft::b()] {
        let a = at_2deg(&ac);
        assert_real_eigenvalue_crosses_zero(&ac, &a);
    }
}

#[test]
fn reported_trims_satisfy_the_pss_equations() {
    for ac in [Aircraft::a(), Aircraft::b()] {
        let a = at_2deg(&ac);
        let k = params(&ac);
        for j in &a.jump {
            let f = paper_tests::pss_rhs(
                &k,
                &[j.alpha, j.beta, j.p0, j.q, j.r],
                &[j.delta_a_rad, a.delta_e_rad, 0.0],
            );
            assert!(
                f.iter().all(|v| v.abs() < 1e-9),
                "{}: residual {f:?}",
                a.aircraft
            );
        }
        for z in &a.zero_sideslip.departure {
            let (x, da, _) = paper_tests::zero_sideslip_trim(&k, z.p0, a.delta_e_rad).unwrap();
            assert!((x[0] - z.alpha).abs() < 1e-9 && (x[3] - z.q).abs() < 1e-9);
            assert!((x[4] - z.r).abs() < 1e-9 && (da - z.delta_a_rad).abs() < 1e-9);
        }
    }
}
