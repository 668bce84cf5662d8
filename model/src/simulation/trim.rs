//! Closed-form trims evaluated in f64: the starting point of every simulation, the equilibrium
//! curves of Figs 1-4 and 9, and the zero-sideslip rudder schedule (the aileron-rudder
//! interconnect of Fig. 9, top left).
//!
//! The trim numerators and denominators come from [`crate::derivation::Derivation`] specialised
//! to the aircraft (Eqs 3-4 for the unconstrained roll, Eq. 35 for zero sideslip), converted once
//! to f64 coefficients in P0. The controls that hold a trim (aileron from the roll equation,
//! rudder from the yaw equation) are evaluated with the compiled model [`PssModel`], so no
//! equation is typed twice.

use super::SimError;
use crate::aircraft::Aircraft;
use crate::algebra::Poly;
use crate::derivation::Derivation;
use crate::equations::symbols;
use crate::pss_model::{Controls, PssModel};
use crate::roots::F64Poly;
use crate::specialise::{exact_f64, specialisation, univariate};

/// A specialised polynomial in P0 alone, rounded to f64 for Horner evaluation.
fn horner(p: &Poly) -> F64Poly {
    univariate(p, symbols().p0).to_f64()
}

/// An equilibrium of the PSS model: state and the controls that hold it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Equilibrium {
    /// State [alpha, beta, p, q, r] (rad, rad/s).
    pub x: [f64; 5],
    /// Controls holding the state (rad).
    pub controls: Controls,
}

/// The closed-form trims of one aircraft at one elevator setting, in f64.
///
/// Unconstrained roll (section II.A): for a given P0, rudder and aileron deflection the trim is
/// `[alpha0, beta0, Q0, R0] = num(P0, delta_a, delta_r) / det A(P0)`, affine in both controls
/// (the aileron enters through the aileron yaw `n_delta_a`); the roll equation then fixes the
/// aileron, a quadratic in delta_a with aileron yaw. Zero-sideslip roll (section V.A):
/// `[alpha0, Q0, R0] = zs_num(P0) / zs_det(P0)` with beta0 = 0, the aileron and rudder from the
/// roll and yaw equations together.
#[derive(Clone, Debug)]
pub struct Trims {
    model: PssModel,
    delta_e: f64,
    det_a: F64Poly,
    /// Numerators of [alpha0, beta0, Q0, R0] at delta_a = delta_r = 0.
    num0: [F64Poly; 4],
    /// Their delta_a coefficients (zero without aileron yaw).
    num_a: [F64Poly; 4],
    /// Their delta_r coefficients.
    num_r: [F64Poly; 4],
    zs_det: F64Poly,
    zs_num: [F64Poly; 3],
    /// `[[l_delta_a, l_delta_r], [n_delta_a, n_delta_r]]`: the lateral controls in the roll and
    /// yaw equations (exact, from the compiled model's control Jacobian).
    lateral: [[f64; 2]; 2],
}

/// Relative size below which a trim denominator counts as zero (trims blow up: Eq. 5).
const SINGULAR: f64 = 1e-12;

impl Trims {
    /// Specialises the derivation to `aircraft` at elevator `delta_e` (rad).
    ///
    /// Fails when the elevator is not finite or the aircraft has no aileron authority
    /// (`l_delta_a = 0`, no trim can be held).
    pub fn new(aircraft: &Aircraft, delta_e: f64) -> Result<Trims, SimError> {
        if !delta_e.is_finite() {
            return Err(SimError::NotFinite {
                name: "delta_e",
                value: delta_e,
            });
        }
        let s = symbols();
        let model = PssModel::new(aircraft);
        let dc = model.control_jacobian(&[0.0; 5], &Controls::default());
        let l_delta_a = dc[2][0];
        if l_delta_a == 0.0 || !l_delta_a.is_finite() {
            return Err(SimError::NoAileronAuthority);
        }
        let mut values = specialisation(aircraft, delta_e);
        let d0 = Derivation::derive(&values);
        for (sym, v) in values.iter_mut() {
            if *sym == s.delta_r {
                *v = exact_f64(1.0);
            }
        }
        let d1 = Derivation::derive(&values);
        let no_aileron = |p: &Poly| p.coeff(s.delta_a, 0);
        Ok(Trims {
            model,
            delta_e,
            det_a: horner(&d0.det_a),
            num0: std::array::from_fn(|i| horner(&no_aileron(&d0.trim[i]))),
            num_a: std::array::from_fn(|i| horner(&d0.trim[i].coeff(s.delta_a, 1))),
            num_r: std::array::from_fn(|i| {
                horner(&(&no_aileron(&d1.trim[i]) - &no_aileron(&d0.trim[i])))
            }),
            zs_det: horner(&d0.zs_det),
            zs_num: std::array::from_fn(|i| horner(&d0.zs_trim[i])),
            lateral: [[dc[2][0], dc[2][2]], [dc[4][0], dc[4][2]]],
        })
    }

    /// The compiled PSS model of the aircraft.
    pub fn model(&self) -> &PssModel {
        &self.model
    }

    /// Elevator deflection, rad.
    pub fn delta_e(&self) -> f64 {
        self.delta_e
    }

    /// det A at P0 (Eq. 4; its roots are the divergence roll rates of Eq. 5).
    pub fn det_a(&self, p0: f64) -> f64 {
        self.det_a.eval(p0)
    }

    /// The unconstrained trim state at roll rate `p0` for given aileron and rudder (rad): the
    /// four non-roll equations hold, the roll equation need not. `None` where det A vanishes.
    fn state(&self, p0: f64, delta_a: f64, delta_r: f64) -> Option<[f64; 5]> {
        let den = nonsingular(&self.det_a, p0)?;
        let v: [f64; 4] = std::array::from_fn(|i| {
            (self.num0[i].eval(p0)
                + delta_a * self.num_a[i].eval(p0)
                + delta_r * self.num_r[i].eval(p0))
                / den
        });
        Some([v[0], v[1], p0, v[2], v[3]])
    }

    /// Every unconstrained trim at roll rate `p0` with rudder `delta_r` (rad), ascending in the
    /// aileron that holds it: one without aileron yaw, up to two with it (the roll equation along
    /// the trim is quadratic in delta_a; its coefficients follow from the compiled model at
    /// delta_a = -1, 0, 1, exactly up to rounding).
    pub fn unconstrained_all(&self, p0: f64, delta_r: f64) -> Vec<Equilibrium> {
        let controls = |delta_a: f64| Controls {
            delta_a,
            delta_e: self.delta_e,
            delta_r,
        };
        let roll = |da: f64| {
            self.state(p0, da, delta_r)
                .map(|x| self.model.rhs(&x, &controls(da))[2])
        };
        let (Some(fm), Some(f0), Some(fp)) = (roll(-1.0), roll(0.0), roll(1.0)) else {
            return vec![];
        };
        // Without aileron yaw the roll equation is exactly linear with slope l_delta_a.
        let (a, b) = if self.num_a.iter().all(|h| h.0.iter().all(|c| *c == 0.0)) {
            (0.0, self.lateral[0][0])
        } else {
            (0.5 * (fp + fm) - f0, 0.5 * (fp - fm))
        };
        crate::specialise::quadratic_roots(a, b, f0)
            .into_iter()
            .filter_map(|da| {
                let x = self.state(p0, da, delta_r)?;
                finite(Equilibrium {
                    x,
                    controls: controls(da),
                })
            })
            .collect()
    }

    /// The unconstrained trim at roll rate `p0` with rudder `delta_r` (rad), and the aileron that
    /// holds it, on the trim branch that continues the trim without aileron yaw (the trim of
    /// smallest |delta_a|). `None` where det A vanishes (the trim blows up), the roll rate has
    /// no trim, or the result is not finite.
    pub fn unconstrained(&self, p0: f64, delta_r: f64) -> Option<Equilibrium> {
        self.unconstrained_all(p0, delta_r)
            .into_iter()
            .min_by(|a, b| {
                a.controls
                    .delta_a
                    .abs()
                    .total_cmp(&b.controls.delta_a.abs())
            })
    }

    /// The rudder's yaw authority n_delta_r, 1/s^2.
    fn n_delta_r(&self) -> f64 {
        self.lateral[1][1]
    }

    /// The zero-sideslip trim at roll rate `p0` (Eq. 35) with the aileron and the rudder that
    /// hold it (the roll and yaw equations, linear in both, solved together). `None` where the
    /// zero-sideslip determinant vanishes or the lateral controls cannot hold the trim
    /// (`l_delta_a n_delta_r = l_delta_r n_delta_a`).
    pub fn zero_sideslip(&self, p0: f64) -> Option<Equilibrium> {
        if self.n_delta_r() == 0.0 {
            return None;
        }
        let den = nonsingular(&self.zs_det, p0)?;
        let v: [f64; 3] = std::array::from_fn(|i| self.zs_num[i].eval(p0) / den);
        let x = [v[0], 0.0, p0, v[1], v[2]];
        // The roll and yaw equations are linear in (delta_a, delta_r) with the matrix `lateral`:
        // their values without lateral controls, then Cramer.
        let free = Controls {
            delta_a: 0.0,
            delta_e: self.delta_e,
            delta_r: 0.0,
        };
        let rhs = self.model.rhs(&x, &free);
        let (r0, y0) = (rhs[2], rhs[4]);
        let [[m11, m12], [m21, m22]] = self.lateral;
        let det = m11 * m22 - m12 * m21;
        let controls = Controls {
            delta_a: (m12 * y0 - r0 * m22) / det,
            delta_e: self.delta_e,
            delta_r: (m21 * r0 - m11 * y0) / det,
        };
        finite(Equilibrium { x, controls })
    }

    /// The trim with delta_a = 0 nearest to P0 = 0 for rudder `delta_r` (the start of every
    /// simulation). With `n_p = 0` and `delta_r = 0` this is P0 = 0 exactly.
    pub fn trim_at_zero_aileron(&self, delta_r: f64) -> Result<Equilibrium, SimError> {
        let g = |p0: f64| self.unconstrained(p0, delta_r).map(|e| e.controls.delta_a);
        if let Some(e) = self.unconstrained(0.0, delta_r) {
            if e.controls.delta_a == 0.0 {
                return Ok(e);
            }
        }
        // March outwards from P0 = 0 in both directions; the first sign change is the nearest
        // root; refine by bisection.
        const STEP: f64 = 0.01;
        const P_MAX: f64 = 20.0;
        let mut k = 1;
        while f64::from(k) * STEP <= P_MAX {
            for dir in [1.0, -1.0] {
                let (a, b) = (dir * f64::from(k - 1) * STEP, dir * f64::from(k) * STEP);
                if let (Some(ga), Some(gb)) = (g(a), g(b)) {
                    if ga == 0.0 {
                        return self
                            .unconstrained(a, delta_r)
                            .ok_or(SimError::NoTrim { delta_r });
                    }
                    if ga * gb <= 0.0 {
                        let p0 = bisect(&|p| g(p).unwrap_or(f64::NAN), a, b, ga);
                        return self
                            .unconstrained(p0, delta_r)
                            .ok_or(SimError::NoTrim { delta_r });
                    }
                }
            }
            k += 1;
        }
        Err(SimError::NoTrim { delta_r })
    }
}

/// The value of a trim's denominator at `p0`, or `None` where it vanishes to within
/// [`SINGULAR`] of the size of its coefficients (the trim is singular there).
fn nonsingular(den: &F64Poly, p0: f64) -> Option<f64> {
    let value = den.eval(p0);
    let scale = den.0.iter().fold(0.0f64, |m, c| m.max(c.abs())).max(1.0);
    if value.abs() <= SINGULAR * scale * (1.0 + p0.abs()).powi(4) {
        None
    } else {
        Some(value)
    }
}

fn finite(e: Equilibrium) -> Option<Equilibrium> {
    let c = e.controls;
    (e.x.iter().all(|v| v.is_finite()) && c.delta_a.is_finite() && c.delta_r.is_finite())
        .then_some(e)
}

/// Bisection of `f` on `[a, b]` with `f(a) = fa` and a sign change, to machine precision.
pub(crate) fn bisect(f: &dyn Fn(f64) -> f64, mut a: f64, mut b: f64, mut fa: f64) -> f64 {
    for _ in 0..200 {
        let m = 0.5 * (a + b);
        if m == a || m == b {
            break;
        }
        let fm = f(m);
        if fm == 0.0 {
            return m;
        }
        if (fm < 0.0) == (fa < 0.0) {
            a = m;
            fa = fm;
        } else {
            b = m;
        }
    }
    0.5 * (a + b)
}

/// Regula falsi with the Illinois modification on a bracket `[a, b]` with a sign change:
/// superlinear on the nearly linear schedule, a few evaluations to machine precision.
fn illinois(f: &dyn Fn(f64) -> f64, mut a: f64, mut b: f64) -> f64 {
    let (mut fa, mut fb) = (f(a), f(b));
    if fa == 0.0 {
        return a;
    }
    // No sign change (or NaN): nothing to refine.
    if fb == 0.0 || fa * fb >= 0.0 || fa.is_nan() || fb.is_nan() {
        return b;
    }
    let mut side = 0;
    for _ in 0..100 {
        let c = (a * fb - b * fa) / (fb - fa);
        if !(c > a.min(b) && c < a.max(b)) {
            break;
        }
        let fc = f(c);
        if fc == 0.0 || (b - a).abs() <= 4.0 * f64::EPSILON * c.abs().max(1e-300) {
            return c;
        }
        if (fc < 0.0) == (fb < 0.0) {
            b = c;
            fb = fc;
            if side == -1 {
                fa *= 0.5;
            }
            side = -1;
        } else {
            a = c;
            fa = fc;
            if side == 1 {
                fb *= 0.5;
            }
            side = 1;
        }
    }
    if fa.abs() < fb.abs() {
        a
    } else {
        b
    }
}

/// The zero-sideslip rudder schedule delta_r(delta_a): the aileron-rudder interconnect of
/// Fig. 9 (section V.B, the first step of the extended bifurcation analysis).
///
/// For an aileron deflection, the zero-sideslip trim on the branch through P0 = 0 is found by
/// solving `delta_a(P0) = delta_a` (Eq. 35 and the roll equation); the schedule is the rudder of
/// that trim. The branch is tabulated once from P0 = 0 outwards while delta_a(P0) stays
/// monotonic, the trims stay finite and |delta_a| stays below [`RudderSchedule::MAX_DELTA_A`];
/// queries bracket from the table and refine by bisection on the exact closed form.
#[derive(Clone, Debug)]
pub struct RudderSchedule {
    trims: Trims,
    /// (delta_a, P0), ascending in delta_a.
    table: Vec<(f64, f64)>,
}

impl RudderSchedule {
    /// Largest aileron deflection tabulated, rad (90 deg: far beyond any small-angle model).
    pub const MAX_DELTA_A: f64 = std::f64::consts::FRAC_PI_2;
    /// Table spacing in P0, rad/s.
    const STEP: f64 = 0.005;
    /// Largest |P0| tabulated, rad/s.
    const P_MAX: f64 = 50.0;

    /// Tabulates the zero-sideslip branch through P0 = 0.
    pub fn new(trims: Trims) -> Result<RudderSchedule, SimError> {
        if trims.n_delta_r() == 0.0 {
            return Err(SimError::NoRudderAuthority);
        }
        let da = |p0: f64| trims.zero_sideslip(p0).map(|e| e.controls.delta_a);
        let d0 = da(0.0).ok_or(SimError::NoZeroSideslipTrim)?;
        let mut sides: [Vec<(f64, f64)>; 2] = [Vec::new(), Vec::new()];
        for (side, dir) in sides.iter_mut().zip([1.0, -1.0]) {
            let mut prev = d0;
            let mut trend = 0.0;
            let mut k = 1u32;
            while f64::from(k) * Self::STEP <= Self::P_MAX {
                let p0 = dir * f64::from(k) * Self::STEP;
                let Some(d) = da(p0) else { break };
                let step = d - prev;
                if trend == 0.0 {
                    trend = step.signum();
                }
                if step == 0.0 || step.signum() != trend || d.abs() > Self::MAX_DELTA_A {
                    break;
                }
                side.push((d, p0));
                prev = d;
                k += 1;
            }
        }
        let [pos, neg] = sides;
        let mut table: Vec<(f64, f64)> = neg.into_iter().rev().collect();
        table.push((d0, 0.0));
        table.extend(pos);
        // One side may run the other way round (both branches monotonic in the same sense
        // through 0 is the normal case); sort by delta_a and require strict monotonicity.
        table.sort_by(|a, b| a.0.total_cmp(&b.0));
        let sense = table[table.len() - 1].1 - table[0].1;
        let monotone = table
            .windows(2)
            .all(|w| w[0].0 < w[1].0 && (w[1].1 - w[0].1) * sense > 0.0);
        if !monotone || table.len() < 2 {
            return Err(SimError::NoZeroSideslipTrim);
        }
        Ok(RudderSchedule { trims, table })
    }

    /// The range of aileron deflections the schedule covers, rad.
    pub fn range(&self) -> (f64, f64) {
        (self.table[0].0, self.table[self.table.len() - 1].0)
    }

    /// The closed-form trims the schedule was built from.
    pub fn trims(&self) -> &Trims {
        &self.trims
    }

    /// The zero-sideslip trim (state and controls) held by aileron `delta_a` (rad).
    pub fn trim(&self, delta_a: f64) -> Result<Equilibrium, SimError> {
        let (lo, hi) = self.range();
        if !(lo..=hi).contains(&delta_a) {
            return Err(SimError::ScheduleRange { delta_a, lo, hi });
        }
        let i = self.table.partition_point(|(d, _)| *d < delta_a);
        let fail = || SimError::ScheduleRange { delta_a, lo, hi };
        if i < self.table.len() && self.table[i].0 == delta_a {
            return self.trims.zero_sideslip(self.table[i].1).ok_or_else(fail);
        }
        let (a, b) = (self.table[i - 1].1, self.table[i].1);
        let g = |p0: f64| {
            self.trims
                .zero_sideslip(p0)
                .map_or(f64::NAN, |e| e.controls.delta_a - delta_a)
        };
        let p0 = illinois(&g, a, b);
        self.trims.zero_sideslip(p0).ok_or_else(fail)
    }

    /// The rudder deflection (rad) that holds zero sideslip at aileron `delta_a` (rad).
    pub fn delta_r(&self, delta_a: f64) -> Result<f64, SimError> {
        self.trim(delta_a).map(|e| e.controls.delta_r)
    }

    /// The tabulated branch: (delta_a, P0) pairs ascending in delta_a.
    pub fn table(&self) -> &[(f64, f64)] {
        &self.table
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::reference::{
        A_FOLD_DELTA_A_DEG, A_JUMP_P0, A_ZERO_SIDESLIP_DELTA_A_DEG, A_ZERO_SIDESLIP_P0,
    };

    #[test]
    fn trims_are_equilibria_of_the_compiled_model() {
        let t = Trims::new(&Aircraft::a(), 2f64.to_radians()).unwrap();
        for p0 in [-2.0, 0.3, A_JUMP_P0[0], 3.5] {
            for dr in [0.0, 0.02] {
                let e = t.unconstrained(p0, dr).unwrap();
                let f = t.model().rhs(&e.x, &e.controls);
                assert!(f.iter().all(|v| v.abs() < 1e-11), "{p0} {dr}: {f:?}");
            }
            let z = t.zero_sideslip(p0).unwrap();
            assert_eq!(z.x[1], 0.0);
            let f = t.model().rhs(&z.x, &z.controls);
            assert!(f.iter().all(|v| v.abs() < 1e-11), "zs {p0}: {f:?}");
        }
        // The first fold of Fig. 1.
        let e = t.unconstrained(A_JUMP_P0[0], 0.0).unwrap();
        assert!((e.controls.delta_a.to_degrees() - A_FOLD_DELTA_A_DEG).abs() < 1e-3);
    }

    #[test]
    fn trim_at_zero_aileron_is_p0_zero_for_the_paper_aircraft() {
        let t = Trims::new(&Aircraft::b(), 2f64.to_radians()).unwrap();
        let e = t.trim_at_zero_aileron(0.0).unwrap();
        assert_eq!(e.x[2], 0.0);
        assert_eq!(e.controls.delta_a, 0.0);
        // With a rudder offset the trim moves off P0 = 0 but still holds delta_a = 0.
        let e = t.trim_at_zero_aileron(0.01).unwrap();
        assert!(e.controls.delta_a.abs() < 1e-12 && e.x[2] != 0.0, "{e:?}");
        let f = t.model().rhs(&e.x, &e.controls);
        assert!(f.iter().all(|v| v.abs() < 1e-11), "{f:?}");
    }

    #[test]
    fn schedule_holds_zero_sideslip_at_the_requested_aileron() {
        let t = Trims::new(&Aircraft::a(), 2f64.to_radians()).unwrap();
        let s = RudderSchedule::new(t).unwrap();
        let (lo, hi) = s.range();
        assert!(lo < -0.5 && hi > 0.5, "{lo} {hi}");
        for deg in [-12.0, A_ZERO_SIDESLIP_DELTA_A_DEG, -3.0, 0.0, 5.0] {
            let e = s.trim(f64::to_radians(deg)).unwrap();
            assert!((e.controls.delta_a - deg.to_radians()).abs() < 1e-14);
            let f = s.trims().model().rhs(&e.x, &e.controls);
            assert!(f.iter().all(|v| v.abs() < 1e-11), "{deg}: {f:?}");
        }
        // The departure point of Fig. 11 / section V.
        let e = s.trim(A_ZERO_SIDESLIP_DELTA_A_DEG.to_radians()).unwrap();
        assert!((e.x[2] - A_ZERO_SIDESLIP_P0[0]).abs() < 1e-4, "{e:?}");
        assert!(s.delta_r(2.0).is_err());
    }
}
