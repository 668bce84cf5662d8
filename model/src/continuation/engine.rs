//! The pseudo-arclength engine: predictor, Newton corrector on the bordered system, adaptive
//! step, test functions and their location, branch switching (what AUTO2000 does for section
//! II.B and Figs 1-4, 9 of the paper).
//!
//! A point of a branch is `z = (y, mu)` in R^6: five unknowns `y` (the PSS states, or for the
//! constrained zero-sideslip system the states with beta replaced by the rudder) and the
//! continuation parameter `mu`. Everything runs on nalgebra's fixed-size types, so the inner loop
//! (corrector, tangent, eigenvalues) does not allocate.
//!
//! Test functions, each evaluated at every accepted point and located by Illinois regula falsi
//! along the branch (each trial point corrected back onto the branch on the hyperplane
//! `t_a . z = t_a . z_a + sigma`):
//! * fold (saddle-node): `t_mu`, the parameter component of the unit tangent;
//! * branch point: `det [[J, f_mu], [t^T]]`, the determinant of the bordered matrix with the
//!   consistently oriented tangent (it changes sign exactly where the rank of `[J, f_mu]` drops);
//! * Hopf: the bialternate-product test function `prod_{i<j} (lambda_i + lambda_j)` (Orlando's
//!   formula: it is `det(2 J (.) I)` up to sign), computed from the eigenvalues of J5; a located
//!   zero is reported as a Hopf point only when a complex pair sits on the imaginary axis (a real
//!   pair `lambda, -lambda`, a neutral saddle, also zeroes it and is skipped).

use nalgebra::{Complex, Matrix5, Matrix6, RowVector6, Vector5, Vector6};

/// A point `(y, mu)` of the continuation space.
pub(crate) type V6 = Vector6<f64>;

/// The residual, Jacobian and parameter derivative of a system at one point.
pub(crate) struct Eval {
    /// `f(y, mu)`.
    pub f: Vector5<f64>,
    /// `d f / d y`.
    pub jy: Matrix5<f64>,
    /// `d f / d mu`.
    pub fmu: Vector5<f64>,
}

/// A system of five equations in five unknowns and one parameter.
pub(crate) trait System {
    /// Residual and derivatives; `None` if anything is not finite.
    fn eval(&self, z: &V6) -> Option<Eval>;
    /// The physical state [alpha, beta, p, q, r] and the reported parameter value at `z`.
    fn physical(&self, z: &V6) -> ([f64; 5], f64);
    /// Position in `z` of physical state `i`, if it is an unknown.
    fn z_index(&self, i: usize) -> Option<usize>;
    /// Whether `jy` is the Jacobian of the dynamics (so stability and Hopf points mean something).
    fn dynamic(&self) -> bool;
}

/// Numerical limits of one continuation.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Limits {
    pub mu_lo: f64,
    pub mu_hi: f64,
    pub max_state: f64,
    pub ds_init: f64,
    pub ds_min: f64,
    pub ds_max: f64,
    pub tol: f64,
    pub max_iter: usize,
    pub max_angle: f64,
    pub locate_tol: f64,
    pub max_points: usize,
    /// End a branch at its first fold (the zero-sideslip schedule of EBA step 1).
    pub stop_at_fold: bool,
}

/// An accepted point with everything the test functions need.
#[derive(Clone, Debug)]
pub(crate) struct Node {
    pub z: V6,
    /// Unit tangent, oriented along the direction of travel.
    pub t: V6,
    /// Branch-point test function (bordered determinant with the oriented tangent).
    pub det_b: f64,
    /// Eigenvalues of J5 (zeros when the system is not dynamic).
    pub eig: [Complex<f64>; 5],
    /// All eigenvalues in the open left half-plane.
    pub stable: bool,
    /// Hopf test function.
    pub hopf: f64,
}

impl Node {
    /// The same point travelled the other way.
    pub fn reversed(&self) -> Node {
        Node {
            t: -self.t,
            det_b: -self.det_b,
            ..self.clone()
        }
    }
}

/// Kinds of located special points.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) enum Kind {
    Fold,
    Hopf,
    Branch,
}

/// A located special point.
#[derive(Clone, Debug)]
pub(crate) struct Found {
    pub kind: Kind,
    pub node: Node,
    pub frequency: Option<f64>,
}

/// Why a half-branch ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum End {
    /// The parameter reached the end of its range (the last point is on the bound).
    Range,
    /// A state reached `max_state` (the last point is on the bound).
    State,
    /// The branch closed on itself.
    Loop,
    /// The branch ran onto a part already traced from another start.
    Known,
    /// The step size fell below `ds_min`.
    StepFailed,
    /// `max_points` reached.
    MaxPoints,
    /// A fold, with `stop_at_fold`.
    Fold,
}

/// What a watcher says about a segment.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Verdict {
    Continue,
    Known,
}

/// One direction of a branch, from (excluding) its start.
pub(crate) struct Half {
    pub nodes: Vec<Node>,
    pub found: Vec<Found>,
    pub end: End,
}

/// The engine: a system and its limits.
pub(crate) struct Engine<'a, S: System> {
    pub sys: &'a S,
    pub lim: Limits,
}

fn bordered(e: &Eval, n: &V6) -> Matrix6<f64> {
    let mut b = Matrix6::zeros();
    b.fixed_view_mut::<5, 5>(0, 0).copy_from(&e.jy);
    b.fixed_view_mut::<5, 1>(0, 5).copy_from(&e.fmu);
    b.set_row(5, &RowVector6::from_iterator(n.iter().copied()));
    b
}

/// The Hopf test function `prod_{i<j} (lambda_i + lambda_j)` (real for a real matrix).
fn bialternate(eig: &[Complex<f64>; 5]) -> f64 {
    let mut prod = Complex::new(1.0, 0.0);
    for i in 0..5 {
        for j in i + 1..5 {
            prod *= eig[i] + eig[j];
        }
    }
    prod.re
}

/// A unit vector spanning the kernel of the 5x6 matrix `[jy, fmu]` when it has rank 5 (the
/// generalized cross product of its rows: signed 5x5 minors).
pub(crate) fn kernel(e: &Eval) -> Option<V6> {
    let mut n = V6::zeros();
    for j in 0..6 {
        let m = Matrix5::from_fn(|r, c| {
            let c = if c < j { c } else { c + 1 };
            if c < 5 {
                e.jy[(r, c)]
            } else {
                e.fmu[r]
            }
        });
        let sign = if j % 2 == 0 { 1.0 } else { -1.0 };
        n[j] = sign * m.determinant();
    }
    let norm = n.norm();
    (norm > 0.0 && norm.is_finite()).then(|| n / norm)
}

impl<S: System> Engine<'_, S> {
    /// Newton on `f(z) = 0, n . z = c` (the bordered system). Returns the point and the number
    /// of iterations.
    pub fn correct(&self, mut z: V6, n: &V6, c: f64) -> Option<(V6, usize)> {
        let mut last = f64::INFINITY;
        for it in 1..=self.lim.max_iter {
            let e = self.sys.eval(&z)?;
            let b = bordered(&e, n);
            let mut r = V6::zeros();
            r.fixed_rows_mut::<5>(0).copy_from(&e.f);
            r[5] = n.dot(&z) - c;
            let dz = b.lu().solve(&(-r))?;
            z += dz;
            if !z.iter().all(|v| v.is_finite()) {
                return None;
            }
            let step = dz.norm();
            let size = 1.0 + z.norm();
            // Converged, or stalled at the rounding level (near a singular point).
            if step <= self.lim.tol * size || (step <= 1e-9 * size && step >= 0.5 * last) {
                return Some((z, it));
            }
            last = step;
        }
        None
    }

    /// The node at a point on the branch, its tangent oriented by `t_ref` (`t . t_ref > 0`).
    pub fn node(&self, z: V6, t_ref: &V6) -> Option<Node> {
        let e = self.sys.eval(&z)?;
        let lu = bordered(&e, t_ref).lu();
        let det_b = lu.determinant();
        let v = lu.solve(&V6::from_fn(|i, _| if i == 5 { 1.0 } else { 0.0 }))?;
        let norm = v.norm();
        if !(norm > 0.0 && norm.is_finite()) {
            return None;
        }
        let (eig, stable, hopf) = if self.sys.dynamic() {
            let eig = crate::spectrum::eigenvalues(&e.jy)?;
            (eig, eig.iter().all(|l| l.re < 0.0), bialternate(&eig))
        } else {
            ([Complex::new(0.0, 0.0); 5], false, 0.0)
        };
        Some(Node {
            z,
            t: v / norm,
            det_b,
            eig,
            stable,
            hopf,
        })
    }

    /// A start node at a (nearly) converged point: polished on the hyperplane `n . z = n . z0`,
    /// tangent from the kernel, oriented so that `orient(t) > 0`.
    pub fn start(&self, z0: V6, n: &V6, orient: impl Fn(&V6) -> f64) -> Option<Node> {
        let (z, _) = self.correct(z0, n, n.dot(&z0))?;
        let k = kernel(&self.sys.eval(&z)?)?;
        let k = if orient(&k) < 0.0 { -k } else { k };
        self.node(z, &k)
    }

    fn physical_bound_hit(&self, z: &V6) -> bool {
        (0..5).any(|i| {
            self.sys
                .z_index(i)
                .is_some_and(|k| z[k].abs() > self.lim.max_state)
        })
    }

    /// Follows the branch from `start` in the direction of its tangent.
    pub fn trace(&self, start: &Node, watch: &mut dyn FnMut(&V6, &V6) -> Verdict) -> Half {
        let lim = &self.lim;
        let cos_max = lim.max_angle.cos();
        let mut nodes: Vec<Node> = Vec::new();
        let mut found = Vec::new();
        let mut cur = start.clone();
        let mut ds = lim.ds_init;
        let mut travelled = 0.0;
        let end = loop {
            if nodes.len() >= lim.max_points {
                break End::MaxPoints;
            }
            let pred = cur.z + cur.t * ds;
            let accepted = self
                .correct(pred, &cur.t, cur.t.dot(&pred))
                .filter(|(z, _)| (z - pred).norm() <= ds)
                .and_then(|(z, it)| Some((self.node(z, &cur.t)?, it)))
                .filter(|(n, _)| n.t.dot(&cur.t) >= cos_max);
            let Some((next, iters)) = accepted else {
                ds *= 0.5;
                if ds < lim.ds_min {
                    break End::StepFailed;
                }
                continue;
            };
            // The parameter range and the state bound: end exactly on the bound.
            let (next, bound) = match self.clip(&cur, &next) {
                Some((clipped, why)) => (clipped, Some(why)),
                None => (next, None),
            };
            if lim.stop_at_fold && cur.t[5] * next.t[5] < 0.0 {
                if let Some(f) = self.locate(&cur, &next, |n| n.t[5], false) {
                    nodes.push(f);
                    break End::Fold;
                }
            }
            self.detect(&cur, &next, &mut found);
            let verdict = watch(&cur.z, &next.z);
            if let Some(why) = bound {
                nodes.push(next);
                break why;
            }
            let seg = (next.z - cur.z).norm();
            travelled += seg;
            // Closing on the start (an isola traced all round).
            if travelled > 4.0 * seg && next.t.dot(&start.t) > 0.0 {
                let d = dist_to_segment(&start.z, &cur.z, &next.z);
                if d <= 0.1 * seg + 1e-9 {
                    nodes.push(next);
                    break End::Loop;
                }
            }
            if verdict == Verdict::Known {
                nodes.push(next);
                break End::Known;
            }
            nodes.push(next.clone());
            cur = next;
            ds = if iters <= 2 {
                (ds * 1.6).min(lim.ds_max)
            } else if iters >= 5 {
                ds * 0.6
            } else {
                ds
            }
            .max(lim.ds_min);
        };
        Half { nodes, found, end }
    }

    /// If `b` lies beyond the parameter range or the state bound, the point where the branch
    /// leaves them (corrected onto the bound), and why.
    fn clip(&self, a: &Node, b: &Node) -> Option<(Node, End)> {
        let lim = &self.lim;
        let mut best: Option<(f64, usize, f64, End)> = None;
        let mut consider = |k: usize, bound: f64, why: End| {
            let (va, vb) = (a.z[k], b.z[k]);
            let theta = if vb != va {
                (bound - va) / (vb - va)
            } else {
                0.0
            };
            if best.is_none_or(|(t, ..)| theta < t) {
                best = Some((theta.clamp(0.0, 1.0), k, bound, why));
            }
        };
        if b.z[5] > lim.mu_hi {
            consider(5, lim.mu_hi, End::Range);
        }
        if b.z[5] < lim.mu_lo {
            consider(5, lim.mu_lo, End::Range);
        }
        if self.physical_bound_hit(&b.z) {
            for i in 0..5 {
                if let Some(k) = self.sys.z_index(i) {
                    if b.z[k].abs() > lim.max_state {
                        consider(k, lim.max_state.copysign(b.z[k]), End::State);
                    }
                }
            }
        }
        let (theta, k, bound, why) = best?;
        let z0 = a.z + (b.z - a.z) * theta;
        let e = V6::from_fn(|i, _| if i == k { 1.0 } else { 0.0 });
        let clipped = self
            .correct(z0, &e, bound)
            .and_then(|(z, _)| self.node(z, &a.t))
            .unwrap_or_else(|| a.clone());
        Some((clipped, why))
    }

    /// Test functions changing sign between `a` and `b`, located.
    fn detect(&self, a: &Node, b: &Node, found: &mut Vec<Found>) {
        if a.t[5] * b.t[5] < 0.0 {
            if let Some(n) = self.locate(a, b, |n| n.t[5], false) {
                found.push(Found {
                    kind: Kind::Fold,
                    node: n,
                    frequency: None,
                });
            }
        }
        if a.det_b * b.det_b < 0.0 {
            if let Some(n) = self.locate(a, b, |n| n.det_b, true) {
                found.push(Found {
                    kind: Kind::Branch,
                    node: n,
                    frequency: None,
                });
            }
        }
        if self.sys.dynamic() && a.hopf * b.hopf < 0.0 {
            if let Some(n) = self.locate(a, b, |n| n.hopf, false) {
                if let Some(w) = hopf_frequency(&n.eig) {
                    found.push(Found {
                        kind: Kind::Hopf,
                        node: n,
                        frequency: Some(w),
                    });
                }
            }
        }
    }

    /// The zero of `g` between `a` and `b` (opposite signs), by Illinois regula falsi in the
    /// pseudo-arclength `sigma` along `a`'s tangent, each trial point corrected onto the branch
    /// (initial guess: the chord between the current bracket's points).
    ///
    /// At a branch point (`singular`) the corrector itself is singular, so the bracket is only
    /// narrowed to 1e-6 and the zero is then found from a cubic through four well-conditioned
    /// points at +-h, +-2h (h = 1e-4) around it: ψ and z are both interpolated.
    pub fn locate(
        &self,
        a: &Node,
        b: &Node,
        g: impl Fn(&Node) -> f64,
        singular: bool,
    ) -> Option<Node> {
        let s_end = a.t.dot(&(b.z - a.z));
        if s_end.is_nan() || s_end <= 0.0 {
            return None;
        }
        let bracket = self.bracket(a, b, &g, s_end, singular);
        if !singular {
            return bracket.best.map(|(_, n)| n);
        }
        self.branch_point_by_cubic(a, &g, s_end, bracket)
    }

    /// The point at pseudo-arclength `s` along `a`'s tangent, corrected onto the branch from `z0`.
    fn along(&self, a: &Node, s: f64, z0: V6) -> Option<Node> {
        let base = a.t.dot(&a.z);
        self.correct(z0, &a.t, base + s)
            .and_then(|(z, _)| self.node(z, &a.t))
    }

    /// Illinois regula falsi on `g` in `[0, s_end]` along `a`'s tangent (see [`Engine::locate`]),
    /// to `locate_tol`, or to 1e-6 at a branch point (`singular`).
    fn bracket(
        &self,
        a: &Node,
        b: &Node,
        g: &impl Fn(&Node) -> f64,
        s_end: f64,
        singular: bool,
    ) -> Bracket {
        let (mut lo, mut glo, mut hi, mut ghi) = (0.0, g(a), s_end, g(b));
        let (mut zlo, mut zhi) = (a.z, b.z);
        let mut best: Option<(f64, Node)> = None;
        let mut side = 0i8;
        let stop = if singular {
            1e-6_f64.max(self.lim.locate_tol)
        } else {
            self.lim.locate_tol
        };
        for _ in 0..100 {
            if hi - lo <= stop {
                break;
            }
            let mut s = (lo * ghi - hi * glo) / (ghi - glo);
            if !(s > lo && s < hi) {
                s = 0.5 * (lo + hi);
            }
            let z0 = zlo + (zhi - zlo) * ((s - lo) / (hi - lo));
            let Some(n) = self.along(a, s, z0) else {
                break;
            };
            let gs = g(&n);
            let z = n.z;
            best = Some((s, n));
            if gs == 0.0 {
                break;
            }
            if gs * ghi < 0.0 {
                (lo, glo, zlo) = (s, gs, z);
                if side == -1 {
                    ghi *= 0.5;
                }
                side = -1;
            } else {
                (hi, ghi, zhi) = (s, gs, z);
                if side == 1 {
                    glo *= 0.5;
                }
                side = 1;
            }
        }
        Bracket {
            lo,
            hi,
            zlo,
            zhi,
            best,
        }
    }

    /// The branch point near the narrowed `bracket`: the zero of a cubic through four points
    /// around the estimate, away from the singular point, with z and the tangent interpolated.
    fn branch_point_by_cubic(
        &self,
        a: &Node,
        g: &impl Fn(&Node) -> f64,
        s_end: f64,
        bracket: Bracket,
    ) -> Option<Node> {
        let Bracket {
            lo,
            hi,
            zlo,
            zhi,
            best,
        } = bracket;
        // Cubic through four points around the estimate, away from the singular point.
        let (s0, z_near, t_near) = match &best {
            Some((s, n)) => (*s, n.z, n.t),
            None => (0.5 * (lo + hi), zlo + (zhi - zlo) * 0.5, a.t),
        };
        let h = 1e-3_f64.min(0.25 * s_end);
        let mut pts: Vec<(f64, Node)> = Vec::with_capacity(4);
        for o in [-2.0, -1.0, 1.0, 2.0] {
            let s = s0 + o * h;
            // Tangent predictor from the point nearest the branch point, on this branch.
            let z0 = z_near + t_near * ((s - s0) / t_near.dot(&a.t));
            pts.push((s, self.along(a, s, z0)?));
        }
        let vals: Vec<f64> = pts.iter().map(|(_, n)| g(n)).collect();
        let xs: Vec<f64> = pts.iter().map(|(s, _)| *s).collect();
        let lagrange = |x: f64, j: usize| -> f64 {
            (0..4)
                .filter(|&m| m != j)
                .map(|m| (x - xs[m]) / (xs[j] - xs[m]))
                .product()
        };
        let interp = |x: f64| (0..4).map(|j| vals[j] * lagrange(x, j)).sum::<f64>();
        // Secant on the cubic, from the two inner points.
        let (mut x0, mut x1) = (xs[1], xs[2]);
        let (mut f0, mut f1) = (interp(x0), interp(x1));
        for _ in 0..60 {
            if f1 == f0 {
                break;
            }
            let x2 = x1 - f1 * (x1 - x0) / (f1 - f0);
            (x0, f0) = (x1, f1);
            x1 = x2;
            f1 = interp(x1);
            if (x1 - x0).abs() <= 1e-15 * (1.0 + x1.abs()) {
                break;
            }
        }
        if !(x1 >= xs[0] && x1 <= xs[3]) {
            return best.map(|(_, n)| n);
        }
        let z = (0..4).fold(V6::zeros(), |acc, j| acc + pts[j].1.z * lagrange(x1, j));
        let t = (0..4)
            .fold(V6::zeros(), |acc, j| acc + pts[j].1.t * lagrange(x1, j))
            .normalize();
        let e = self.sys.eval(&z)?;
        let eig = if self.sys.dynamic() {
            crate::spectrum::eigenvalues(&e.jy)?
        } else {
            [Complex::new(0.0, 0.0); 5]
        };
        Some(Node {
            z,
            t,
            det_b: 0.0,
            eig,
            stable: self.sys.dynamic() && eig.iter().all(|l| l.re < 0.0),
            hopf: if self.sys.dynamic() {
                bialternate(&eig)
            } else {
                0.0
            },
        })
    }

    /// Branch switching at a located branch point: the second direction of the two-dimensional
    /// kernel of `[J, f_mu]`, orthogonal to the branch's tangent, corrected onto the crossing
    /// branch. Returns a start node on the other branch, oriented away from the branch point.
    pub fn switch(&self, bp: &Node) -> Option<Node> {
        let e = self.sys.eval(&bp.z)?;
        let c = bordered(&e, &bp.t);
        let svd = c.svd(false, true);
        let v_t = svd.v_t?;
        let (imin, _) = svd.singular_values.argmin();
        let phi: V6 = v_t.row(imin).transpose();
        for h in [
            self.lim.ds_init,
            4.0 * self.lim.ds_init,
            0.25 * self.lim.ds_init,
        ] {
            let pred = bp.z + phi * h;
            let Some((z, _)) = self.correct(pred, &phi, phi.dot(&pred)) else {
                continue;
            };
            let d = z - bp.z;
            let off = d - bp.t * d.dot(&bp.t);
            if off.norm() > 0.5 * h {
                let k = kernel(&self.sys.eval(&z)?)?;
                let k = if k.dot(&d) < 0.0 { -k } else { k };
                return self.node(z, &k);
            }
        }
        None
    }
}

/// The frequency of the complex pair closest to the imaginary axis, if it is on it.
fn hopf_frequency(eig: &[Complex<f64>; 5]) -> Option<f64> {
    let scale = eig.iter().map(|l| l.norm()).fold(1.0, f64::max);
    eig.iter()
        .filter(|l| l.im > 1e-7 * scale)
        .min_by(|a, b| a.re.abs().total_cmp(&b.re.abs()))
        .filter(|l| l.re.abs() <= 1e-6 * scale)
        .map(|l| l.im)
}

/// Distance from `p` to the segment `[a, b]`.
pub(crate) fn dist_to_segment(p: &V6, a: &V6, b: &V6) -> f64 {
    let d = b - a;
    let l2 = d.norm_squared();
    let theta = if l2 > 0.0 {
        ((p - a).dot(&d) / l2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (a + d * theta - p).norm()
}

/// The bracket of a zero that [`Engine::locate`] narrows: its ends in pseudo-arclength and their
/// points, and the last point corrected inside it.
struct Bracket {
    lo: f64,
    hi: f64,
    zlo: V6,
    zhi: V6,
    best: Option<(f64, Node)>,
}
