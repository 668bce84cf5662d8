//! Start points for every branch: the equilibria on a grid of roll rates P0 (section II.A).
//!
//! At a fixed roll rate p = P0 the PSS equations of Appendix A.2 are linear in
//! `(alpha, beta, q, r)` and in every control, except for the single product `-E q r` of the
//! roll equation (the other couplings `p beta`, `p alpha`, `C p r`, `D p q` are linear once p is
//! fixed). Writing `w = q r`, the five equations are five linear equations in the six unknowns
//! `(alpha, beta, q, r, mu, w)`: a line `z0 + t n`, and `w = q r` on it is a quadratic in `t`.
//! So the equilibria with roll rate P0 are found in closed form, for any continued control and
//! any aircraft: with n_delta_a = 0 and mu = delta_a the quadratic degenerates to the linear
//! trim of Eqs 1-4 with delta_a from the roll equation, as in the paper; with n_delta_a != 0,
//! or for delta_e and delta_r, it is a genuine quadratic (two equilibria or none per P0).
//!
//! A P0 at which the whole line solves the equations (the quadratic vanishes identically, e.g.
//! the symmetric branch p = 0 of a delta_e continuation) gives a branch along which p is
//! constant: it is seeded from one point of that line. Such a branch is found only if its P0 is
//! on the grid (the grid contains P0 = 0, where symmetry puts it). A section whose linear system
//! has a kernel of dimension two or more is skipped.
//!
//! The linear structure is read off the compiled model (its Jacobian at q = r = 0 and its
//! control derivatives) at P0 = 0 and 1, and checked against the model at a generic point.

use super::engine::V6;
use super::systems::with_control;
use super::ContinuationError;
use crate::pss_model::{Controls, PssModel};
use nalgebra::{Matrix5, SMatrix, Vector5, Vector6};

type M56 = SMatrix<f64, 5, 6>;

/// The equations at fixed P0: `(L0 + P0 L1) (alpha, beta, q, r, mu, w) + c0 + P0 c1 = 0`.
pub(crate) struct Sections {
    l0: M56,
    l1: M56,
    c0: Vector5<f64>,
    c1: Vector5<f64>,
}

/// The equilibria in one section.
pub(crate) enum Section {
    /// Isolated equilibria (at most two), `z = (alpha, beta, p, q, r, mu)`.
    Points(Vec<V6>),
    /// A whole line of equilibria at this P0: a point of it and its direction.
    Line(V6, V6),
}

impl Sections {
    /// Reads the linear structure off the model. Errors if the model is not of the form above.
    pub fn new(
        model: &PssModel,
        base: Controls,
        control: usize,
    ) -> Result<Sections, ContinuationError> {
        let at = |p0: f64| -> (M56, Vector5<f64>) {
            let x = [0.0, 0.0, p0, 0.0, 0.0];
            let u = with_control(base, control, 0.0);
            let j = model.jacobian(&x, &u);
            let cj = model.control_jacobian(&x, &u);
            let f = model.rhs(&x, &u);
            const COLS: [usize; 4] = [0, 1, 3, 4];
            // d f_roll / d(q r) = -E: read off d f_roll / d q at r = 1.
            let e = model.jacobian(&[0.0, 0.0, p0, 0.0, 1.0], &u)[2][3] - j[2][3];
            let m = M56::from_fn(|i, k| match k {
                0..=3 => j[i][COLS[k]],
                4 => cj[i][control],
                _ => {
                    if i == 2 {
                        e
                    } else {
                        0.0
                    }
                }
            });
            (m, Vector5::from(f))
        };
        let (l0, c0) = at(0.0);
        let (m1, f1) = at(1.0);
        let s = Sections {
            l0,
            l1: m1 - l0,
            c0,
            c1: f1 - c0,
        };
        // Check the structure at a generic point.
        let (x, mu) = ([0.31, -0.27, 1.73, 0.41, -0.59], 0.13);
        let f = model.rhs(&x, &with_control(base, control, mu));
        let y = Vector6::new(x[0], x[1], x[3], x[4], mu, x[3] * x[4]);
        let lin = (s.l0 + s.l1 * x[2]) * y + s.c0 + s.c1 * x[2];
        let scale = 1.0 + s.l0.amax() + s.l1.amax() + s.c0.amax() + s.c1.amax();
        if (0..5).any(|i| (lin[i] - f[i]).abs() > 1e-9 * scale) {
            return Err(ContinuationError::Model(
                "the PSS equations at fixed roll rate are not linear but for q r".into(),
            ));
        }
        Ok(s)
    }

    /// The equilibria with roll rate `p0`.
    pub fn at(&self, p0: f64) -> Section {
        let m = self.l0 + self.l1 * p0;
        let c = self.c0 + self.c1 * p0;
        let Some((z0, n)) = line_by_lu(&m, &c).or_else(|| line_by_minors(&m, &c)) else {
            return Section::Points(Vec::new());
        };
        // w = q r on the line (indices: q 2, r 3, w 5).
        let a = n[2] * n[3];
        let b = z0[2] * n[3] + z0[3] * n[2] - n[5];
        let cc = z0[2] * z0[3] - z0[5];
        let to_z = |y: Vector6<f64>| V6::new(y[0], y[1], p0, y[2], y[3], y[4]);
        let size = 1.0 + z0.norm_squared();
        if a.abs() <= 1e-12 * size && b.abs() <= 1e-12 * size && cc.abs() <= 1e-12 * size {
            let dir = V6::new(n[0], n[1], 0.0, n[2], n[3], n[4]);
            if dir.norm() > 1e-9 {
                return Section::Line(to_z(z0), dir / dir.norm());
            }
            return Section::Points(vec![to_z(z0)]);
        }
        Section::Points(
            crate::specialise::quadratic_roots(a, b, cc)
                .into_iter()
                .filter(|t| t.is_finite())
                .map(|t| to_z(z0 + n * t))
                .collect(),
        )
    }
}

/// The solution line `z0 + t n` (unit `n`) of `m z + c = 0` when the 5x5 part of `m` (all but
/// the `w` column) is well conditioned: `y = y0 + w y1`, one LU and two solves. The usual case.
fn line_by_lu(m: &M56, c: &Vector5<f64>) -> Option<(Vector6<f64>, Vector6<f64>)> {
    let l: Matrix5<f64> = m.fixed_columns::<5>(0).into_owned();
    let lu = l.lu();
    let u = lu.u();
    let d = u.diagonal().map(f64::abs);
    let conditioned = d.min() > 1e-10 * d.max();
    if !conditioned {
        return None;
    }
    let y0 = lu.solve(&(-c))?;
    let y1 = lu.solve(&(-m.column(5).into_owned()))?;
    let z0 = Vector6::new(y0[0], y0[1], y0[2], y0[3], y0[4], 0.0);
    let n = Vector6::new(y1[0], y1[1], y1[2], y1[3], y1[4], 1.0);
    Some((z0, n / n.norm()))
}

/// The solution line from the generalized cross product of the rows of `m` (signed 5x5
/// minors), for sections where the 5x5 part is singular (e.g. a line of equilibria).
fn line_by_minors(m: &M56, c: &Vector5<f64>) -> Option<(Vector6<f64>, Vector6<f64>)> {
    let mut n = Vector6::zeros();
    let minor = |j: usize| Matrix5::from_fn(|r, k| m[(r, if k < j { k } else { k + 1 })]);
    for j in 0..6 {
        let sign = if j % 2 == 0 { 1.0 } else { -1.0 };
        n[j] = sign * minor(j).determinant();
    }
    let scale = m.amax().max(1e-300);
    let jstar = n.iamax();
    let rank_five = n[jstar].abs() > 1e-13 * scale.powi(5);
    if !rank_five {
        return None;
    }
    let sol = minor(jstar).lu().solve(&(-c))?;
    let z0 = Vector6::from_fn(|i, _| match i.cmp(&jstar) {
        std::cmp::Ordering::Less => sol[i],
        std::cmp::Ordering::Equal => 0.0,
        std::cmp::Ordering::Greater => sol[i - 1],
    });
    Some((z0, n / n.norm()))
}

/// One start point.
pub(crate) struct Seed {
    pub z: V6,
    /// The branch that passes through it, once traced.
    pub owner: Option<usize>,
    /// Start of a line of equilibria at constant p (never crossed by a P0 grid line).
    pub line: bool,
}

/// The seeds on the P0 grid, and which branch owns each.
pub(crate) struct SeedBook {
    /// Grid P0_k = (k - half) h.
    pub h: f64,
    pub half: usize,
    pub seeds: Vec<Vec<Seed>>,
}

impl SeedBook {
    /// Seeds with the parameter in `[mu_lo, mu_hi]` and every state within `max_state`.
    pub fn build(sections: &Sections, h: f64, max_state: f64, mu_lo: f64, mu_hi: f64) -> SeedBook {
        let half = (max_state / h).floor() as usize;
        let inside = |z: &V6| {
            z.iter().take(5).all(|v| v.abs() <= max_state) && z[5] >= mu_lo && z[5] <= mu_hi
        };
        let seeds = (0..=2 * half)
            .map(|k| {
                let p0 = (k as f64 - half as f64) * h;
                match sections.at(p0) {
                    Section::Points(pts) => pts
                        .into_iter()
                        .filter(|z| inside(z))
                        .map(|z| Seed {
                            z,
                            owner: None,
                            line: false,
                        })
                        .collect(),
                    Section::Line(z0, dir) => {
                        // The point of the line at mid-range, or the one nearest the origin.
                        let t = if dir[5].abs() > 1e-9 {
                            (0.5 * (mu_lo + mu_hi) - z0[5]) / dir[5]
                        } else {
                            -z0.dot(&dir)
                        };
                        let z = z0 + dir * t;
                        if inside(&z) {
                            vec![Seed {
                                z,
                                owner: None,
                                line: true,
                            }]
                        } else {
                            Vec::new()
                        }
                    }
                }
            })
            .collect();
        SeedBook { h, half, seeds }
    }

    /// The grid roll rate of index `k`.
    pub fn p0(&self, k: usize) -> f64 {
        (k as f64 - self.half as f64) * self.h
    }

    /// Marks the seeds that the segment `a -> b` of branch `branch` passes through. Returns
    /// `Known` if it passes a seed of another branch (it is retracing that branch). `exact`
    /// corrects a point onto the branch at a given roll rate; it settles ambiguous matches.
    pub fn crossed(
        &mut self,
        a: &V6,
        b: &V6,
        branch: usize,
        exact: &dyn Fn(&V6, f64) -> Option<V6>,
    ) -> super::engine::Verdict {
        use super::engine::Verdict;
        let (pa, pb) = (a[2], b[2]);
        if (pb - pa).abs() <= 1e-12 {
            return Verdict::Continue;
        }
        let len = (b - a).norm();
        let tol = 0.25 * len + 1e-9;
        let n = self.seeds.len() as i64;
        // Grid indices with P0_k in the half-open interval from pa (excluded) to pb (included).
        let ka = pa / self.h + self.half as f64;
        let kb = pb / self.h + self.half as f64;
        let (first, last, step) = if pb > pa {
            (ka.floor() as i64 + 1, kb.floor() as i64, 1)
        } else {
            (ka.ceil() as i64 - 1, kb.ceil() as i64, -1)
        };
        let mut k = first;
        while (step > 0 && k <= last) || (step < 0 && k >= last) {
            let kk = k;
            k += step;
            if kk < 0 || kk >= n {
                continue;
            }
            let kk = kk as usize;
            let p0 = self.p0(kk);
            let theta = (p0 - pa) / (pb - pa);
            let mut zi = a + (b - a) * theta;
            let z_lin = zi;
            let near = |s: &Seed| !s.line && (s.z - z_lin).norm() <= tol;
            let n_near = self.seeds[kk].iter().filter(|s| near(s)).count();
            let other = |s: &Seed| s.owner.is_some_and(|o| o != branch);
            let ambiguous = n_near > 1 || self.seeds[kk].iter().any(|s| near(s) && other(s));
            let mut match_tol = tol;
            if ambiguous {
                match exact(&zi, p0) {
                    Some(z) => {
                        zi = z;
                        match_tol = 1e-7 * (1.0 + z.norm());
                    }
                    None => continue,
                }
            }
            let nearest = (self.seeds[kk].iter().enumerate())
                .filter(|(_, s)| near(s))
                .map(|(i, s)| ((s.z - zi).norm(), i))
                .min_by(|x, y| x.0.total_cmp(&y.0));
            if let Some((d, i)) = nearest {
                if d <= match_tol {
                    let seed = &mut self.seeds[kk][i];
                    match seed.owner {
                        None => seed.owner = Some(branch),
                        Some(o) if o == branch => {}
                        Some(_) => return Verdict::Known,
                    }
                }
            }
        }
        Verdict::Continue
    }
}
