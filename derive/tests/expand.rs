//! The expansion of `roll_criterion!` works: for a built-in aircraft, for a TOML file and
//! parametric, it agrees with an independently computed jump root, with itself across the
//! parametric and specialised forms, and with the committed generated crate.

#[allow(dead_code)]
#[path = "../../model/tests/support/reference.rs"]
mod reference;

/// Aircraft A, built in.
mod a {
    roll_criterion_derive::roll_criterion!(aircraft = A);
}

/// Aircraft B, from its file (relative to this crate's `CARGO_MANIFEST_DIR`, i.e. `derive/`).
mod b {
    roll_criterion_derive::roll_criterion!(aircraft = "../aircraft/b.toml");
}

/// The fighter of `aircraft/fighter.toml`: nondimensional body-axis data with aileron yaw and
/// a product of inertia (converted to principal axes when the macro loads it).
mod fighter {
    roll_criterion_derive::roll_criterion!(aircraft = "../aircraft/fighter.toml");
}

/// The parametric form.
mod parametric {
    roll_criterion_derive::roll_criterion!(parametric);
}

/// Elevator deflection of the paper's Figs 7-8: 2 deg in rad.
const DE: f64 = 0.03490658503988659;

/// Aircraft B of Table A.1 (AIAA 2006-6267), typed in here from the paper, not from `model`.
const B: parametric::Derivatives = parametric::Derivatives {
    c: 0.949,
    d: 0.716,
    e: 0.727,
    z_alpha: -1.329,
    y_beta: -0.196,
    l_p: -3.933,
    l_r: 0.126,
    l_beta: -9.99,
    l_delta_a: -45.83,
    m_q: -0.814,
    m_alpha: -23.18,
    m_delta_e: -28.37,
    n_p: 0.0,
    n_r: -0.235,
    n_beta: 5.67,
    n_delta_a: 0.0,
    n_delta_r: -1.0,
    l_delta_r: 0.0,
    z_0: 0.0,
    alpha_t: 0.0,
};

fn assert_close(got: f64, want: f64, rel: f64, what: &str) {
    assert!(
        (got - want).abs() <= rel * want.abs(),
        "{what}: got {got:e}, want {want:e} (relative tolerance {rel:e})"
    );
}

/// det K of aircraft A changes sign at its jump roll rates, Fig. 7 of the paper (1.70 and
/// 3.03 rad/s at delta_e = 2 deg, delta_r = 0), as an independent numeric computation
/// (continuation and eigenvalues) gives them (`reference`, also pinned in tests/tests/paper.rs).
#[test]
fn fig_7_det_k_aircraft_a_changes_sign_at_the_jump_roll_rates() {
    for p in reference::A_JUMP_P0 {
        let below = a::det_k(p - 1e-5, DE, 0.0);
        let above = a::det_k(p + 1e-5, DE, 0.0);
        assert!(
            below * above < 0.0,
            "det K({p} -/+ 1e-5) = {below:e}, {above:e}"
        );
    }
}

/// The parametric det K with B's data equals the specialised B, away from roots and poles,
/// where straight-line f64 evaluation of either form loses at most a few hundred ulps.
#[test]
fn parametric_det_k_with_b_data_equals_specialised_aircraft_b() {
    for p0 in [0.3, 0.8, 1.5, 2.5, 4.0] {
        let want = b::det_k(p0, DE, 0.0);
        assert!(
            want.abs() > 1e-3,
            "P0 = {p0} is too close to a root: {want:e}"
        );
        assert_close(parametric::det_k(&B, p0, DE, 0.0), want, 1e-9, "det_k");
        assert_close(
            parametric::det_j5(&B, p0, DE, 0.0),
            b::det_j5(p0, DE, 0.0),
            1e-9,
            "det_j5",
        );
    }
    // Table 1 of the paper: B's pitch-yaw divergence roll rates, 2.98 and 4.78 rad/s, as
    // independently computed.
    let got = parametric::divergence_roll_rates(&B);
    let want = b::divergence_roll_rates();
    for ((g, w), table_1) in got.iter().zip(want).zip(reference::B_DIVERGENCE_P0) {
        assert_close(*g, w, 1e-12, "divergence_roll_rates");
        assert_close(w, table_1, 2e-7, "Table 1 (independent)");
    }
}

/// The file front end and the built-in data agree with the generated crate for B too.
#[test]
fn file_aircraft_b_equals_generated_aircraft_b() {
    for p0 in [0.3, 1.5, 4.0] {
        assert_eq!(
            b::det_k(p0, DE, 0.0).to_bits(),
            roll_criterion::aircraft_b::det_k(p0, DE, 0.0).to_bits(),
            "det_k({p0})"
        );
    }
    assert_eq!(
        bits(&b::jump_polynomial(DE, 0.0)),
        bits(&roll_criterion::aircraft_b::jump_polynomial(DE, 0.0))
    );
}

/// The bit patterns of f64 values, so that equal NaNs (no real divergence roll rate) compare equal.
fn bits(xs: &[f64]) -> Vec<u64> {
    xs.iter().map(|x| x.to_bits()).collect()
}

/// One emitter serves the macro and `model -- emit`: the expansion for A computes bit for bit
/// what the committed `generated/src/aircraft_a.rs` computes.
#[test]
fn macro_equals_committed_generated_aircraft_a() {
    use roll_criterion::aircraft_a as g;
    for (p0, de, dr) in [
        (0.5, DE, 0.0),
        (1.0, DE, 0.01),
        (2.5, -DE, 0.0),
        (6.0, 0.1, -0.02),
    ] {
        let at = format!("at ({p0}, {de}, {dr})");
        for (m, c) in a::trim(p0, de, dr).iter().zip(g::trim(p0, de, dr)) {
            assert_eq!(
                bits(&[m.alpha, m.beta, m.q, m.r, m.delta_a]),
                bits(&[c.alpha, c.beta, c.q, c.r, c.delta_a]),
                "trim {at}"
            );
        }
        let (m, c) = (a::zero_sideslip_trim(p0, de), g::zero_sideslip_trim(p0, de));
        assert_eq!(
            bits(&[m.alpha, m.q, m.r, m.delta_a, m.delta_r]),
            bits(&[c.alpha, c.q, c.r, c.delta_a, c.delta_r]),
            "zero_sideslip_trim {at}"
        );
        let scalars = [
            ("det_k", a::det_k(p0, de, dr), g::det_k(p0, de, dr)),
            ("det_j5", a::det_j5(p0, de, dr), g::det_j5(p0, de, dr)),
            (
                "residual_denominator",
                a::residual_denominator(p0, de, dr),
                g::residual_denominator(p0, de, dr),
            ),
            (
                "zero_sideslip_det_k",
                a::zero_sideslip_det_k(p0, de),
                g::zero_sideslip_det_k(p0, de),
            ),
            (
                "hopf_polynomial",
                a::hopf_polynomial(p0, de, dr),
                g::hopf_polynomial(p0, de, dr),
            ),
        ];
        for (name, m, c) in scalars {
            assert_eq!(m.to_bits(), c.to_bits(), "{name} {at}: {m:e} vs {c:e}");
        }
        assert_eq!(
            bits(a::stiffness(p0, de, dr).as_flattened()),
            bits(g::stiffness(p0, de, dr).as_flattened()),
            "stiffness {at}"
        );
        assert_eq!(
            bits(a::jacobian5(0.1, -0.02, p0, 0.3, -0.05).as_flattened()),
            bits(g::jacobian5(0.1, -0.02, p0, 0.3, -0.05).as_flattened()),
            "jacobian5 {at}"
        );
        assert_eq!(
            bits(&a::jump_polynomial(de, dr)),
            bits(&g::jump_polynomial(de, dr)),
            "jump_polynomial {at}"
        );
        assert_eq!(
            bits(&a::zero_sideslip_jump_polynomial(de)),
            bits(&g::zero_sideslip_jump_polynomial(de)),
            "zero_sideslip_jump_polynomial {at}"
        );
    }
    assert_eq!(
        bits(&a::divergence_biquadratic()),
        bits(&g::divergence_biquadratic())
    );
    assert_eq!(
        bits(&a::divergence_roll_rates()),
        bits(&g::divergence_roll_rates())
    );
}

#[test]
fn fighter_with_aileron_yaw_expands_and_its_trims_hold_the_roll_equation() {
    // The expansion folds the converted data; the parametric form takes the same converted
    // values from the loader. Both trims (when real) must zero the PSS equations, which are
    // written out here from Appendix A.2 with the aileron-yaw term.
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../aircraft/fighter.toml");
    let v = model::aircraft::load(&path).unwrap().values_f64();
    let k = parametric::Derivatives {
        c: v[0],
        d: v[1],
        e: v[2],
        z_alpha: v[3],
        y_beta: v[4],
        l_p: v[5],
        l_r: v[6],
        l_beta: v[7],
        l_delta_a: v[8],
        m_q: v[9],
        m_alpha: v[10],
        m_delta_e: v[11],
        n_p: v[12],
        n_r: v[13],
        n_beta: v[14],
        n_delta_a: v[15],
        n_delta_r: v[16],
        l_delta_r: v[17],
        z_0: v[18],
        alpha_t: v[19],
    };
    assert!(k.n_delta_a != 0.0 && k.l_delta_r != 0.0, "{k:?}");
    let mut real = 0;
    for p0 in [0.5, 1.5, 2.5] {
        let folded = fighter::trim(p0, DE, 0.0);
        let param = parametric::trim(&k, p0, DE, 0.0);
        for (t, u) in folded.iter().zip(&param) {
            if !t.delta_a.is_finite() {
                continue;
            }
            let (a, b, q, r, da) = (t.alpha, t.beta, t.q, t.r, t.delta_a);
            let f = [
                q - p0 * b + k.z_alpha * a + k.z_0,
                p0 * (k.alpha_t + a) - r + k.y_beta * b,
                k.l_p * p0 + k.l_beta * b + k.l_r * r - k.e * q * r + k.l_delta_a * da,
                k.m_q * q + k.m_alpha * a + k.c * p0 * r + k.m_delta_e * DE,
                k.n_r * r + k.n_beta * b + k.n_p * p0 - k.d * p0 * q + k.n_delta_a * da,
            ];
            assert!(f.iter().all(|v| v.abs() < 1e-9), "{p0}: {f:?}");
            assert_close(u.delta_a, da, 1e-9, "parametric and folded trims");
            real += 1;
        }
    }
    assert!(real >= 3, "{real} real trims");
    // With aileron yaw no Hopf polynomial in P0 and the controls alone exists: NaN.
    assert!(fighter::hopf_polynomial(1.5, DE, 0.0).is_nan());
}
