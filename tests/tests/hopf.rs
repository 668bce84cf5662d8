//! The closed-form Hopf criterion (beyond the paper: Delta4 = 0 with omega^2 > 0), its first
//! Lyapunov coefficient and where a jump lands, against independent numerics written here or in
//! `paper_tests`: finite-difference Jacobians and nalgebra eigenvalues, RK4 integration of the
//! hand-written PSS model, and the numeric continuation of `model::continuation` (which knows
//! nothing of the closed form). Expected numbers for aircraft B are an independent AUTO-07p
//! continuation's.

use model::aircraft::{f64_to_rational, Aircraft};
use model::analysis::{analyze, parametric, Analysis, CriterionPolys, HopfPolys};
use model::continuation::{continue_equilibria, Settings, SpecialKind};
use model::roots::positive_roots;
use nalgebra::Complex;
use paper_tests::{fd_jacobian, ix, pss_rhs, random_params, reference, trim_branches, Lcg, Params};

fn de() -> f64 {
    2f64.to_radians()
}

fn aircraft(k: &Params, name: &str) -> Aircraft {
    let values = k.iter().map(|v| f64_to_rational(*v).unwrap()).collect();
    Aircraft::new(name, values, 150.0)
}

fn eigenvalues(k: &Params, x: &[f64; 5], da: f64) -> Vec<Complex<f64>> {
    fd_jacobian(k, x, &[da, de(), 0.0])
        .complex_eigenvalues()
        .iter()
        .copied()
        .collect()
}

/// The eigenvalue pair with the smallest |l_i + l_j| (the factor of Orlando's product that
/// vanishes at a root of Delta4).
fn closest_pair(eig: &[Complex<f64>]) -> (Complex<f64>, Complex<f64>) {
    let mut best = (eig[0], eig[1]);
    for i in 0..eig.len() {
        for j in i + 1..eig.len() {
            if (eig[i] + eig[j]).norm() < (best.0 + best.1).norm() {
                best = (eig[i], eig[j]);
            }
        }
    }
    best
}

#[test]
fn hopf_points_of_b_are_autos_and_a_has_none_at_delta_e_2_deg() {
    let b = analyze(&Aircraft::b(), de()).unwrap();
    // An independent AUTO-07p continuation: P0, delta_a and omega of each Hopf point.
    for (p0, da_deg, omega) in reference::B_HOPF {
        let h = b
            .hopf
            .iter()
            .find(|h| (h.point.p0 - p0).abs() < 1e-6)
            .unwrap_or_else(|| panic!("no Hopf point at P0 = {p0}: {:?}", b.hopf));
        assert!((h.point.delta_a_deg - da_deg).abs() < 0.005, "{h:?}");
        assert!((h.omega - omega).abs() < 5e-5, "{h:?}");
        assert!((h.period - 2.0 * std::f64::consts::PI / omega).abs() < 1e-3);
    }
    assert!(b.hopf.windows(2).all(|w| w[0].point.p0 < w[1].point.p0));
    let a = analyze(&Aircraft::a(), de()).unwrap();
    assert!(a.hopf.is_empty(), "{:?}", a.hopf);
}

/// Every real-trim root of the Hopf polynomial, by nalgebra eigenvalues of the oracle's
/// Jacobian: reported roots have a pair `+-i omega` with the reported omega, unreported ones a
/// real pair `+-lambda` (a neutral saddle).
fn assert_roots_are_hopf_or_rejected_saddles(ac: &Aircraft, a: &Analysis) -> (usize, usize) {
    let k = ac.values_f64();
    let cp = CriterionPolys::new(parametric(), ac, de());
    let hp = HopfPolys::new(&cp, ac, de());
    let (mut hopf, mut saddles) = (0, 0);
    for root in positive_roots(&hp.hopf) {
        let p0 = root.value;
        for (x, da) in trim_branches(&k, p0, de(), 0.0) {
            let eig = eigenvalues(&k, &x, da);
            let (l1, l2) = closest_pair(&eig);
            let scale = eig.iter().map(|z| z.norm()).fold(1.0, f64::max);
            if (l1 + l2).norm() > 1e-5 * scale {
                continue; // the other trim of this roll rate
            }
            let reported = a.hopf.iter().find(|h| (h.point.p0 - p0).abs() < 1e-12);
            if l1.im.abs() > 1e-4 * scale {
                let h = reported.unwrap_or_else(|| panic!("{}: Hopf at {p0} missed", ac.name));
                assert!((l1.re).abs() < 1e-6 * scale, "{eig:?}");
                assert!(
                    (l1.im.abs() - h.omega).abs() < 1e-6 * scale,
                    "{eig:?} {h:?}"
                );
                assert!((da - h.point.delta_a_rad).abs() < 1e-7, "{da} {h:?}");
                hopf += 1;
            } else {
                assert!(reported.is_none(), "{}: saddle {p0} reported", ac.name);
                assert!(l1.re.abs() > 1e-6 && (l1.re + l2.re).abs() < 1e-5 * scale);
                saddles += 1;
            }
        }
    }
    (hopf, saddles)
}

#[test]
fn hopf_roots_have_an_imaginary_pair_and_neutral_saddles_are_rejected() {
    let mut rng = Lcg(1010);
    let mut aircraft_list = vec![Aircraft::b()];
    for i in 0..2 {
        aircraft_list.push(aircraft(&random_params(&mut rng), &format!("random {i}")));
        aircraft_list.push(aircraft(
            &with_aileron_yaw(&mut rng),
            &format!("yawing {i}"),
        ));
    }
    let (mut hopf, mut saddles) = (0, 0);
    for ac in &aircraft_list {
        let a = analyze(ac, de()).unwrap();
        let (h, s) = assert_roots_are_hopf_or_rejected_saddles(ac, &a);
        hopf += h;
        saddles += s;
    }
    assert!(hopf >= 3 && saddles >= 1, "{hopf} Hopf, {saddles} saddles");
}

fn with_aileron_yaw(rng: &mut Lcg) -> Params {
    let mut k = random_params(rng);
    let sign = if rng.next_f64() < 0.5 { -1.0 } else { 1.0 };
    k[ix::NDA] = sign * rng.range(0.01, 0.06) * k[ix::LDA].abs();
    k
}

#[test]
fn continuation_hopf_points_equal_the_closed_form_to_1e_8_with_and_without_aileron_yaw() {
    let mut rng = Lcg(77);
    let mut list: Vec<Aircraft> = vec![Aircraft::b()];
    for i in 0..2 {
        list.push(aircraft(&random_params(&mut rng), &format!("random {i}")));
        list.push(aircraft(
            &with_aileron_yaw(&mut rng),
            &format!("yawing {i}"),
        ));
    }
    let mut compared = 0;
    for ac in &list {
        let a = analyze(ac, de()).unwrap();
        let d = continue_equilibria(ac, &Settings::default(), &mut |_| {}).unwrap();
        for h in d.special(SpecialKind::Hopf) {
            let sign = h.p.signum();
            let c = a
                .hopf
                .iter()
                .find(|c| (c.point.p0 - h.p.abs()).abs() < 1e-8)
                .unwrap_or_else(|| panic!("{}: {h:?} not in {:?}", ac.name, a.hopf));
            assert!(
                (sign * c.point.delta_a_rad - h.param).abs() < 1e-8,
                "{h:?} {c:?}"
            );
            assert!((c.omega - h.frequency.unwrap()).abs() < 1e-8, "{h:?} {c:?}");
            compared += 1;
        }
    }
    assert!(compared >= 6, "{compared} Hopf points compared");
}

/// RK4 (step `dt`) of the hand-written PSS model at fixed controls; returns the (max - min) / 2
/// of p over the last `window` seconds and the final state.
fn settle(k: &Params, x0: [f64; 5], da: f64, t_end: f64, window: f64, dt: f64) -> (f64, [f64; 5]) {
    let u = [da, de(), 0.0];
    let f = |x: &[f64; 5]| pss_rhs(k, x, &u);
    let add = |x: &[f64; 5], d: &[f64; 5], h: f64| std::array::from_fn(|i| x[i] + h * d[i]);
    let mut x = x0;
    let (mut lo, mut hi) = (f64::MAX, f64::MIN);
    let n = (t_end / dt) as usize;
    for step in 0..n {
        let k1 = f(&x);
        let k2 = f(&add(&x, &k1, dt / 2.0));
        let k3 = f(&add(&x, &k2, dt / 2.0));
        let k4 = f(&add(&x, &k3, dt));
        x = std::array::from_fn(|i| x[i] + dt / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]));
        if (n - step) as f64 * dt <= window {
            lo = lo.min(x[2]);
            hi = hi.max(x[2]);
        }
        if x.iter().any(|v| !v.is_finite() || v.abs() > 1e3) {
            return (f64::INFINITY, x);
        }
    }
    (0.5 * (hi - lo), x)
}

#[test]
fn l1_sign_of_b_hopf_points_within_45_deg_checked_by_simulation() {
    let ac = Aircraft::b();
    let k = ac.values_f64();
    let a = analyze(&ac, de()).unwrap();
    let mut checked = 0;
    for h in a.hopf.iter().filter(|h| h.point.delta_a_deg.abs() <= 45.0) {
        // Along the branch in P0: the side where the pair has crossed into Re > 0.
        let trim_at = |p: f64| {
            trim_branches(&k, p, de(), 0.0)
                .into_iter()
                .min_by(|x, y| {
                    (x.1 - h.point.delta_a_rad)
                        .abs()
                        .total_cmp(&(y.1 - h.point.delta_a_rad).abs())
                })
                .unwrap()
        };
        // Real part of the critical pair (the oracle's eigenvalues) at P0 = p.
        let pair_re = |p: f64| {
            let (x, da) = trim_at(p);
            let eig = eigenvalues(&k, &x, da);
            eig.iter()
                .filter(|z| z.im > 0.0)
                .min_by(|a, b| (a.im - h.omega).abs().total_cmp(&(b.im - h.omega).abs()))
                .map(|z| z.re)
                .unwrap()
        };
        let eps = 2.5e-4;
        let side = if pair_re(h.point.p0 + eps) > 0.0 {
            1.0
        } else {
            assert!(pair_re(h.point.p0 - eps) > 0.0, "{h:?}: no crossing");
            -1.0
        };
        // Settle for many growth times 1 / Re(lambda) of the pair, from the trim nudged.
        let amplitude = |e: f64| {
            let p = h.point.p0 + side * e;
            let (x, da) = trim_at(p);
            let mut x0 = x;
            x0[0] += 1e-3;
            let t = 40.0 * h.period + 12.0 / pair_re(p);
            settle(&k, x0, da, t, 3.0 * h.period, h.period / 300.0).0
        };
        let (a1, a4) = (amplitude(eps), amplitude(4.0 * eps));
        // Supercritical: a small stable cycle whose amplitude grows like sqrt(distance), so
        // quadrupling the distance doubles it. Subcritical: no small cycle near the trim.
        let sqrt_law = a1.is_finite() && a4.is_finite() && (a4 / a1 - 2.0).abs() < 0.3;
        assert_eq!(sqrt_law, h.l1 < 0.0, "{h:?}: amplitudes {a1}, {a4}");
        checked += 1;
    }
    assert!(checked >= 2, "{checked} Hopf points of B checked");
}

#[test]
fn a_jump_lands_on_a_reported_stable_equilibrium_for_a_and_b() {
    for ac in [Aircraft::a(), Aircraft::b()] {
        let k = ac.values_f64();
        let a = analyze(&ac, de()).unwrap();
        let f = a.first_departure.as_ref().expect("a first departure");
        assert_eq!(f.kind, "jump", "{}", ac.name);
        let lands = f.lands_at.as_ref().unwrap();
        assert!(!lands.is_empty());
        // Start at the fold's trim, the aileron 0.1 % past the fold.
        let j = a.jump.iter().find(|j| j.p0 == f.p0).unwrap();
        let x0 = [j.alpha, j.beta, j.p0, j.q, j.r];
        let da = j.delta_a_rad * 1.001;
        let (amp, x) = settle(&k, x0, da, 400.0, 20.0, 2e-3);
        assert!(amp < 1e-6, "{}: settled {amp} {x:?}", ac.name);
        let hit = lands.iter().find(|l| (l.p0 - x[2]).abs() < 1e-2);
        let l = hit.unwrap_or_else(|| panic!("{}: settled at {x:?}, not in {lands:?}", ac.name));
        assert!((l.alpha - x[0]).abs() < 1e-2 && (l.beta - x[1]).abs() < 1e-2);
        // The oracle's eigenvalues say it is stable.
        assert!(eigenvalues(&k, &x, da).iter().all(|z| z.re < 0.0));
    }
}

#[test]
fn generated_characteristic_coefficients_delta4_and_omega_squared_match_nalgebra() {
    // At B's first Hopf point by AUTO-07p: the generated coefficients are those of
    // prod (s - l_i) over the oracle's eigenvalues, Delta4 changes sign across it, and omega^2
    // is the square of AUTO-07p's omega.
    let k = Aircraft::b().values_f64();
    let kd = paper_tests::generated_derivatives(&k);
    let (p0, _, omega) = reference::B_HOPF[0];
    let (x, da) = trim_branches(&k, p0, de(), 0.0).remove(0);
    let eig = eigenvalues(&k, &x, da);
    // Coefficients of prod (s - l_i), highest power first.
    let mut poly = vec![Complex::new(1.0, 0.0)];
    for l in &eig {
        let mut next = vec![Complex::new(0.0, 0.0); poly.len() + 1];
        for (i, c) in poly.iter().enumerate() {
            next[i] += c;
            next[i + 1] -= c * l;
        }
        poly = next;
    }
    let c = roll_criterion::characteristic_coefficients(&kd, p0, de(), 0.0);
    for i in 0..5 {
        let want = poly[i + 1].re;
        assert!(
            (c[i] - want).abs() < 1e-5 * (1.0 + want.abs()),
            "c{}: {} vs {want}",
            i + 1,
            c[i]
        );
    }
    let d4 = |p: f64| roll_criterion::hurwitz_delta4(&kd, p, de(), 0.0);
    assert!(d4(p0 - 1e-5) * d4(p0 + 1e-5) < 0.0);
    let w2 = roll_criterion::hopf_omega_squared(&kd, p0, de(), 0.0);
    assert!((w2.sqrt() - omega).abs() < 5e-5, "{w2}");
}

/// `det(A)^10 Delta4` at the trim of `p0`, computed here with nalgebra and the
/// hand-written model of `paper_tests`: the trim by LU, A of Eq. 2 and J5 by central differences
/// (exact up to rounding for the quadratic PSS model, so a large step keeps rounding small), the
/// characteristic coefficients from J5's eigenvalues, Delta4 as the 4x4 Hurwitz determinant.
/// Returns the value and `|det A|^10` times the sum of the magnitudes of Delta4's products (the
/// permanent of the Hurwitz matrix with absolute entries), the scale of its cancellation.
fn numeric_hopf(k: &Params, p0: f64, de: f64, dr: f64) -> (f64, f64) {
    let (x, da) = trim_branches(k, p0, de, dr).remove(0);
    let u = [da, de, dr];
    let h = 1e-2;
    let jac = |rows: &[usize], cols: &[usize]| {
        nalgebra::DMatrix::from_fn(rows.len(), cols.len(), |r, c| {
            let (mut xp, mut xm) = (x, x);
            xp[cols[c]] += h;
            xm[cols[c]] -= h;
            (pss_rhs(k, &xp, &u)[rows[r]] - pss_rhs(k, &xm, &u)[rows[r]]) / (2.0 * h)
        })
    };
    // A: the alpha, beta, q, r equations against alpha, beta, q, r at p = P0 (Eq. 2).
    let det_a = jac(&[0, 1, 3, 4], &[0, 1, 3, 4]).determinant();
    let j5 =
        nalgebra::Matrix5::from_iterator(jac(&[0, 1, 2, 3, 4], &[0, 1, 2, 3, 4]).iter().copied());
    let mut poly = vec![Complex::new(1.0, 0.0)];
    for l in j5.complex_eigenvalues().iter() {
        let mut next = vec![Complex::new(0.0, 0.0); poly.len() + 1];
        for (i, c) in poly.iter().enumerate() {
            next[i] += c;
            next[i + 1] -= c * l;
        }
        poly = next;
    }
    let c: Vec<f64> = poly[1..].iter().map(|z| z.re).collect();
    let hurwitz = |f: &dyn Fn(f64) -> f64| {
        nalgebra::Matrix4::new(
            f(c[0]),
            f(c[2]),
            f(c[4]),
            0.0, //
            1.0,
            f(c[1]),
            f(c[3]),
            0.0, //
            0.0,
            f(c[0]),
            f(c[2]),
            f(c[4]), //
            0.0,
            1.0,
            f(c[1]),
            f(c[3]),
        )
    };
    let delta4 = hurwitz(&|v| v).determinant();
    // The permanent of |H|: every product of the Leibniz expansion, in magnitude.
    let m = hurwitz(&f64::abs);
    let mut perm = 0.0;
    for p in permutations4() {
        perm += (0..4).map(|i| m[(i, p[i])]).product::<f64>();
    }
    let scale = det_a.abs().powi(10);
    (det_a.powi(10) * delta4, scale * perm)
}

fn permutations4() -> Vec<[usize; 4]> {
    let mut out = Vec::new();
    for a in 0..4 {
        for b in 0..4 {
            for c in 0..4 {
                for d in 0..4 {
                    let p = [a, b, c, d];
                    if (0..4).all(|i| (0..i).all(|j| p[i] != p[j])) {
                        out.push(p);
                    }
                }
            }
        }
    }
    out
}

/// The folded per-aircraft Hopf polynomial `det(A)^10 Delta4` of the generated crate
/// changes sign at B's Hopf points of AUTO-07p (P0 = 3.129030 and 4.731306 rad/s at delta_e = 2
/// deg), and at random roll rates, elevator and rudder settings, where the value is well away
/// from zero
/// (beyond 1e-6 of the scale of its cancellation, far above the ~1e-9 relative error of the
/// finite-difference coefficients), has the sign of `det(A)^10 Delta4` computed with nalgebra,
/// for A and B, in Rust and (through the same DAG) C. Everywhere the two agree to 1e-6 of that
/// scale (measured: 4.4e-8, the finite differences' and det A's rounding raised to the tenth
/// power near det A's roots).
#[test]
fn folded_hopf_polynomial_changes_sign_at_autos_hopf_points_and_has_the_sign_of_nalgebras() {
    use roll_criterion::{aircraft_a, aircraft_b};
    for (p0, _, _) in reference::B_HOPF {
        let (lo, hi) = (
            aircraft_b::hopf_polynomial(p0 - 1e-5, de(), 0.0),
            aircraft_b::hopf_polynomial(p0 + 1e-5, de(), 0.0),
        );
        assert!(lo * hi < 0.0, "no sign change at {p0}: {lo:e}, {hi:e}");
    }
    let mut rng = Lcg(0x40bf);
    let (mut checked, mut worst) = (0, 0.0f64);
    for (k, f) in [
        (
            Aircraft::a().values_f64(),
            aircraft_a::hopf_polynomial as fn(f64, f64, f64) -> f64,
        ),
        (Aircraft::b().values_f64(), aircraft_b::hopf_polynomial),
    ] {
        for _ in 0..400 {
            let p0 = rng.range(0.0, 6.0);
            let de = rng.range(-10.0, 10.0).to_radians();
            let dr = rng.range(-5.0, 5.0).to_radians();
            let got = f(p0, de, dr);
            let (want, scale) = numeric_hopf(&k, p0, de, dr);
            worst = worst.max((got - want).abs() / scale);
            assert!(
                (got - want).abs() <= 1e-6 * scale,
                "P0 {p0}, delta_e {de}, delta_r {dr}: {got:e} vs nalgebra {want:e} (scale {scale:e})"
            );
            if want.abs() > 1e-6 * scale {
                assert_eq!(
                    got.signum(),
                    want.signum(),
                    "P0 {p0}, delta_e {de}: {got:e} vs nalgebra {want:e} (scale {scale:e})"
                );
                checked += 1;
            }
        }
    }
    println!("{checked} signs checked; largest |generated - nalgebra| / scale {worst:e}");
    assert!(checked > 600, "only {checked} points away from zero");
}
