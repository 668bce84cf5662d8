//! An independent numeric oracle for the integration tests.
//!
//! Nothing here uses the symbolic layer: the PSS model of Appendix A.2 is written again by hand
//! in f64, Jacobians are central differences, trims are solved with nalgebra's LU, and
//! eigenvalues come from nalgebra. Tests compare the derived formulas against this.

use nalgebra::{Matrix4, Matrix5, Vector4};

// One file of reference numbers, shared with the tests of `model` and `derive`.
#[path = "../../model/tests/support/reference.rs"]
pub mod reference;

/// Parameter values in the order C, D, E, z_alpha, y_beta, l_p, l_r, l_beta, l_delta_a, m_q,
/// m_alpha, m_delta_e, n_p, n_r, n_beta, n_delta_a, n_delta_r, l_delta_r, z_0, alpha_t (the
/// order of `model::aircraft::Param::ALL`).
pub type Params = [f64; 20];

/// Named access to [`Params`].
#[allow(missing_docs)]
pub mod ix {
    pub const C: usize = 0;
    pub const D: usize = 1;
    pub const E: usize = 2;
    pub const ZA: usize = 3;
    pub const YB: usize = 4;
    pub const LP: usize = 5;
    pub const LR: usize = 6;
    pub const LB: usize = 7;
    pub const LDA: usize = 8;
    pub const MQ: usize = 9;
    pub const MA: usize = 10;
    pub const MDE: usize = 11;
    pub const NP: usize = 12;
    pub const NR: usize = 13;
    pub const NB: usize = 14;
    pub const NDA: usize = 15;
    pub const NDR: usize = 16;
    pub const LDR: usize = 17;
    pub const Z0: usize = 18;
    pub const AT: usize = 19;
}

/// Appendix A.2 by hand: d/dt [alpha, beta, p, q, r] for controls u = [delta_a, delta_e, delta_r],
/// about a trim with lift `z_0` whose principal axis meets the flight path at `alpha_t` (the
/// kinematics `beta_dot = p sin(alpha_t + alpha) - r cos(alpha_t + alpha)` in small angles).
pub fn pss_rhs(k: &Params, x: &[f64; 5], u: &[f64; 3]) -> [f64; 5] {
    use ix::*;
    let [a, b, p, q, r] = *x;
    let [da, de, dr] = *u;
    [
        q - p * b + k[ZA] * a + k[Z0],
        p * (k[AT] + a) - r + k[YB] * b,
        k[LP] * p + k[LB] * b + k[LR] * r - k[E] * q * r + k[LDA] * da + k[LDR] * dr,
        k[MQ] * q + k[MA] * a + k[C] * p * r + k[MDE] * de,
        k[NR] * r + k[NB] * b + k[NP] * p - k[D] * p * q + k[NDR] * dr + k[NDA] * da,
    ]
}

/// The same parameters as the generated crate's [`roll_criterion::Derivatives`].
pub fn generated_derivatives(k: &Params) -> roll_criterion::Derivatives {
    roll_criterion::Derivatives {
        c: k[ix::C],
        d: k[ix::D],
        e: k[ix::E],
        z_alpha: k[ix::ZA],
        y_beta: k[ix::YB],
        l_p: k[ix::LP],
        l_r: k[ix::LR],
        l_beta: k[ix::LB],
        l_delta_a: k[ix::LDA],
        m_q: k[ix::MQ],
        m_alpha: k[ix::MA],
        m_delta_e: k[ix::MDE],
        n_p: k[ix::NP],
        n_r: k[ix::NR],
        n_beta: k[ix::NB],
        n_delta_a: k[ix::NDA],
        n_delta_r: k[ix::NDR],
        l_delta_r: k[ix::LDR],
        z_0: k[ix::Z0],
        alpha_t: k[ix::AT],
    }
}

/// Central-difference Jacobian of [`pss_rhs`] with respect to the states.
pub fn fd_jacobian(k: &Params, x: &[f64; 5], u: &[f64; 3]) -> Matrix5<f64> {
    let mut j = Matrix5::zeros();
    for c in 0..5 {
        let h = 1e-6 * (1.0 + x[c].abs());
        let (mut xp, mut xm) = (*x, *x);
        xp[c] += h;
        xm[c] -= h;
        let (fp, fm) = (pss_rhs(k, &xp, u), pss_rhs(k, &xm, u));
        for r in 0..5 {
            j[(r, c)] = (fp[r] - fm[r]) / (2.0 * h);
        }
    }
    j
}

/// [alpha, beta, q, r] from the four non-roll equations at roll rate `p0` and the given
/// controls, by LU (they are linear in these states at p = p0; columns from unit responses of
/// the model). `None` if singular.
fn non_roll_trim(k: &Params, p0: f64, u: &[f64; 3]) -> Option<Vector4<f64>> {
    let f = |y: [f64; 4]| {
        let v = pss_rhs(k, &[y[0], y[1], p0, y[2], y[3]], u);
        Vector4::new(v[0], v[1], v[3], v[4])
    };
    let c0 = f([0.0; 4]);
    let mut a = Matrix4::zeros();
    for i in 0..4 {
        let mut e = [0.0; 4];
        e[i] = 1.0;
        a.set_column(i, &(f(e) - c0));
    }
    a.lu().solve(&(-c0))
}

/// The pseudo-steady trim at roll rate `p0` (n_delta_a = 0): [alpha, beta, q, r] from the
/// four non-roll equations by LU, then delta_a from the roll equation. `None` if singular.
pub fn trim(k: &Params, p0: f64, de: f64, dr: f64) -> Option<([f64; 5], f64)> {
    let y = non_roll_trim(k, p0, &[0.0, de, dr])?;
    let x = [y[0], y[1], p0, y[2], y[3]];
    let roll = pss_rhs(k, &x, &[0.0, de, dr])[2];
    Some((x, -roll / k[ix::LDA]))
}

/// Every pseudo-steady trim at roll rate `p0` (aileron yaw allowed): the four non-roll
/// equations are linear in [alpha, beta, q, r] for a given aileron, so the trim is
/// `y(delta_a) = y0 + delta_a y1` (two LU solves); the roll equation along it is a quadratic in
/// delta_a, whose coefficients follow from its values at delta_a = -1, 0, 1. Returns each real
/// root with its state, ascending in delta_a.
pub fn trim_branches(k: &Params, p0: f64, de: f64, dr: f64) -> Vec<([f64; 5], f64)> {
    let solve = |da: f64| non_roll_trim(k, p0, &[da, de, dr]);
    let (Some(y0), Some(y1)) = (solve(0.0), solve(1.0)) else {
        return vec![];
    };
    let dy = y1 - y0;
    let state = |da: f64| {
        let y = y0 + dy * da;
        [y[0], y[1], p0, y[2], y[3]]
    };
    let roll = |da: f64| pss_rhs(k, &state(da), &[da, de, dr])[2];
    let (fm, f0, fp) = (roll(-1.0), roll(0.0), roll(1.0));
    let (a, b, c) = (0.5 * (fp + fm) - f0, 0.5 * (fp - fm), f0);
    let roots = if a.abs() <= 1e-13 * (b.abs() + c.abs()) {
        vec![-c / b]
    } else {
        let disc = b * b - 4.0 * a * c;
        if disc < 0.0 {
            vec![]
        } else {
            let q = -0.5 * (b + b.signum() * disc.sqrt());
            vec![q / a, c / q]
        }
    };
    let mut out: Vec<([f64; 5], f64)> = roots.into_iter().map(|da| (state(da), da)).collect();
    out.sort_by(|x, y| x.1.total_cmp(&y.1));
    out
}

/// Zero-sideslip trim at `p0`: [alpha, 0, p0, q, r], delta_a and delta_r, by LU on the
/// alpha, beta, q equations with beta = 0, then the roll and yaw equations.
pub fn zero_sideslip_trim(k: &Params, p0: f64, de: f64) -> Option<([f64; 5], f64, f64)> {
    let f = |y: [f64; 3]| {
        let v = pss_rhs(k, &[y[0], 0.0, p0, y[1], y[2]], &[0.0, de, 0.0]);
        nalgebra::Vector3::new(v[0], v[1], v[3])
    };
    let c0 = f([0.0; 3]);
    let mut a = nalgebra::Matrix3::zeros();
    for i in 0..3 {
        let mut e = [0.0; 3];
        e[i] = 1.0;
        a.set_column(i, &(f(e) - c0));
    }
    let y = a.lu().solve(&(-c0))?;
    let x = [y[0], 0.0, p0, y[1], y[2]];
    // The roll and yaw equations are linear in (delta_a, delta_r): unit responses, then Cramer.
    let f = |da: f64, dr: f64| {
        let v = pss_rhs(k, &x, &[da, de, dr]);
        (v[2], v[4])
    };
    let (r0, y0) = f(0.0, 0.0);
    let (ra, ya) = f(1.0, 0.0);
    let (rr, yr) = f(0.0, 1.0);
    let (m11, m12, m21, m22) = (ra - r0, rr - r0, ya - y0, yr - y0);
    let det = m11 * m22 - m12 * m21;
    let da = (-r0 * m22 + m12 * y0) / det;
    let dr = (-m11 * y0 + m21 * r0) / det;
    Some((x, da, dr))
}

/// The static-residual denominator d computed numerically: dp/dp of the roll equation after
/// eliminating q and r, i.e. l_p + (l_r - E Q0) alpha0 - E R0 beta0, from the Jacobian.
pub fn residual_denominator(j: &Matrix5<f64>) -> f64 {
    // Eqs 11-12 at alpha_dot = beta_dot = 0, alpha = beta = 0: q = -J[0][2] p / J[0][3],
    // r = -J[1][2] p / J[1][4]; then d = J[2][2] + J[2][3] q/p + J[2][4] r/p.
    let q_per_p = -j[(0, 2)] / j[(0, 3)];
    let r_per_p = -j[(1, 2)] / j[(1, 4)];
    j[(2, 2)] + j[(2, 3)] * q_per_p + j[(2, 4)] * r_per_p
}

/// Real eigenvalues of a 5x5 matrix (imaginary part below `1e-9` relative).
pub fn real_eigenvalues(j: &Matrix5<f64>) -> Vec<f64> {
    j.complex_eigenvalues()
        .iter()
        .filter(|z| z.im.abs() <= 1e-9 * (1.0 + z.re.abs()))
        .map(|z| z.re)
        .collect()
}

/// A random, plausible aircraft: signs as for a conventional airplane, magnitudes spread wide
/// (inertias from Ix = 1 and Iy, Iz in [2, 8] x [2, 9]; n_p != 0; n_delta_a = 0). Tests use
/// it so that nothing is tuned to the paper's aircraft A and B.
pub fn random_params(rng: &mut Lcg) -> Params {
    use ix::*;
    let mut k = [0.0; 20];
    let (ix_, iy, iz) = (1.0, rng.range(2.0, 8.0), rng.range(2.0, 9.0));
    k[C] = (iz - ix_) / iy;
    k[D] = (iy - ix_) / iz;
    k[E] = (iz - iy) / ix_;
    k[ZA] = rng.range(-4.0, -0.5);
    k[YB] = rng.range(-0.5, -0.02);
    k[LP] = rng.range(-25.0, -2.0);
    k[LR] = rng.range(-0.5, 2.0);
    k[LB] = rng.range(-120.0, -5.0);
    k[LDA] = rng.range(-300.0, -30.0);
    k[MQ] = rng.range(-2.0, -0.3);
    k[MA] = rng.range(-25.0, -5.0);
    k[MDE] = rng.range(-35.0, -10.0);
    k[NP] = rng.range(-0.3, 0.3);
    k[NR] = rng.range(-0.6, -0.1);
    k[NB] = rng.range(1.0, 8.0);
    k[NDA] = 0.0;
    k[NDR] = rng.range(-5.0, -0.5);
    k
}

/// [`random_params`] linearized about a random trim: lift of 0 to 2 g at 100 to 250 m/s
/// (`z_0 = -n g / V`) and the principal axis -0.05 to 0.15 rad above the flight path.
pub fn random_trimmed_params(rng: &mut Lcg) -> Params {
    let mut k = random_params(rng);
    k[ix::Z0] = -rng.range(0.0, 2.0) * 9.80665 / rng.range(100.0, 250.0);
    k[ix::AT] = rng.range(-0.05, 0.15);
    k
}

/// A small deterministic generator for random test data (no dependency, reproducible).
pub struct Lcg(pub u64);

impl Lcg {
    /// Uniform in [0, 1).
    pub fn next_f64(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Uniform in [lo, hi).
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.next_f64()
    }
}

/// det K by CasADi's generated C (`tests/oracle/casadi_det_k.c`, written by
/// `tests/oracle/casadi_det_k.py` from the model typed in there): `None` when the build had no C
/// compiler (`tests/build.rs`). CasADi's model is Appendix A.2 as printed, without the trim
/// terms: `None` too for data with `z_0` or `alpha_t`.
pub fn casadi_det_k(k: &Params, p0: f64, de: f64, dr: f64) -> Option<f64> {
    if k[ix::Z0] != 0.0 || k[ix::AT] != 0.0 {
        return None;
    }
    casadi::det_k(k, p0, de, dr)
}

#[cfg(casadi)]
mod casadi {
    use super::Params;

    extern "C" {
        /// CasADi's calling convention: input and output pointer arrays, integer and real work
        /// arrays (none needed here: `casadi_det_k_work` reports zero sizes), memory slot.
        fn casadi_det_k(
            arg: *const *const f64,
            res: *const *mut f64,
            iw: *mut i64,
            w: *mut f64,
            mem: std::os::raw::c_int,
        ) -> std::os::raw::c_int;
    }

    pub fn det_k(k: &Params, p0: f64, de: f64, dr: f64) -> Option<f64> {
        let mut out = f64::NAN;
        let args = [&p0 as *const f64, &de, &dr, k.as_ptr()];
        let res = [&mut out as *mut f64];
        // SAFETY: the four inputs point to 1, 1, 1 and (at least) 18 doubles as the generated function's
        // sparsity says, the output to one double; it needs no work arrays (sizes 0).
        let status = unsafe {
            casadi_det_k(
                args.as_ptr(),
                res.as_ptr(),
                std::ptr::null_mut(),
                std::ptr::null_mut(),
                0,
            )
        };
        (status == 0).then_some(out)
    }
}

#[cfg(not(casadi))]
mod casadi {
    use super::Params;

    pub fn det_k(_: &Params, _: f64, _: f64, _: f64) -> Option<f64> {
        None
    }
}
