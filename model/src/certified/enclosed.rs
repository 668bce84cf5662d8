//! The criterion polynomials of one aircraft, enclosed ([`EnclosedPolys`]): by the general
//! route (lifted results cleared in interval polynomials) or by the tape (one evaluation of the
//! criterion program in f64 with a bound on its rounding, [`super::tape`]); and the lean part the
//! critical jump needs ([`JumpPolys`]).

use super::dense::{IPoly, IPoly2};
use super::elimination::eliminate;
use super::isolate::Uncertified;
use super::mode::InP0;
use super::rolls::{without_origin_factor, Unconstrained, ZeroSideslip};
use super::tape;
use super::values::Values;
use crate::aircraft::Param;
use crate::interval::I;

/// The criterion polynomials of one aircraft, enclosed: the interval counterpart of
/// [`crate::analysis::CriterionPolys`] (same names, same construction, each proportional to
/// the exact one by a positive or negative constant).
#[derive(Clone, Debug)]
pub struct EnclosedPolys {
    /// det A (Eq. 4) in P0.
    pub det_a: IPoly,
    /// Numerators of [alpha0, beta0, Q0, R0] over `det_a`, in P0 and delta_a.
    pub trim: [IPoly2; 4],
    /// The trim condition `det(A)^2 p_dot` on the trim.
    pub trim_condition: IPoly2,
    /// `det J5 det(A)^2` on the trim.
    pub jump_at: IPoly2,
    /// `d det(A)^2` on the trim.
    pub d_at: IPoly2,
    /// The jump polynomial in P0 (delta_a eliminated; with aileron yaw divided by det(A)^4,
    /// a factor of every aircraft's resultant).
    pub jump: IPoly,
    /// The pole polynomial in P0 (as `jump`).
    pub poles: IPoly,
    /// det A1 of the zero-sideslip trim (Eq. 35) in P0.
    pub zs_det: IPoly,
    /// Numerators of [alpha0, Q0, R0] of the zero-sideslip trim over `zs_det`.
    pub zs_trim: [IPoly; 3],
    /// `det J5 det(A1)^2` at the zero-sideslip trim (`det J5` alone where that trim is the
    /// origin, at `delta_e = 0`: see `without_origin_factor`).
    pub zs_jump: IPoly,
    /// `d det(A1)^2` at the zero-sideslip trim (`d` alone at the origin, as `zs_jump`).
    pub zs_d_det: IPoly,
    /// The lateral control determinant `l_delta_a n_delta_r - l_delta_r n_delta_a`.
    pub lateral: I,
}

impl EnclosedPolys {
    /// Encloses the criterion polynomials of the data `v`.
    pub fn new(v: &Values) -> Result<EnclosedPolys, Uncertified> {
        let JumpPolys {
            det_a,
            trim_condition,
            jump_at,
            jump,
            unconstrained: u,
        } = JumpPolys::new(v)?;
        let (l, m) = (&v.lifted, &mut InP0::new());
        let d_at = u.on_trim(m, l, false);
        let z = ZeroSideslip::new(m, l)?;
        let lateral = l.lateral.coeff(0);
        // Every polynomial isolated below is even or odd in P0 (see `IPoly::symmetric`).
        Ok(EnclosedPolys {
            jump,
            poles: u.eliminate(&d_at)?.symmetric(),
            det_a,
            trim: u.trim,
            trim_condition,
            jump_at,
            d_at,
            zs_det: z.zs_det.symmetric(),
            zs_trim: z.zs_trim,
            zs_jump: z.zs_jump.symmetric(),
            zs_d_det: z.zs_d_det.symmetric(),
            lateral: lateral.coeffs().first().copied().unwrap_or(I::point(0.0)),
        })
    }
}

impl EnclosedPolys {
    /// The criterion polynomials of the data `params` (in [`Param::ALL`] order) at elevator
    /// `delta_e_rad` and `delta_r = 0`, from one evaluation of the criterion program (the
    /// straight-line program of their coefficients, `program::criterion`) in
    /// f64 with an a priori bound on its rounding (`certified::tape`): the same exact
    /// polynomials as [`EnclosedPolys::new`] on the same data, in enclosures of about the same
    /// width, at a small fraction of the cost. `None` where the tape does not apply: aileron
    /// yaw (`n_delta_a` not exactly zero), or data the tape's bound does not cover (an
    /// enclosure wider than an ulp, a magnitude outside its gate); [`EnclosedPolys::new`]
    /// answers those.
    pub fn by_tape(
        params: &[I; Param::COUNT],
        delta_e_rad: f64,
    ) -> Option<Result<EnclosedPolys, Uncertified>> {
        let yaw = Param::ALL.iter().position(|p| *p == Param::NDeltaA)?;
        if !params[yaw].is_exact_zero() {
            return None;
        }
        let t = CriterionTape::get();
        let inputs: Vec<I> = std::iter::once(I::point(delta_e_rad))
            .chain(params.iter().copied())
            .collect();
        let mut values = t.tape.eval(&inputs)?.into_iter();
        let mut next = |n: usize| IPoly::new(values.by_ref().take(n).collect());
        let mut lengths = t.lengths.iter().copied();
        let mut take = || next(lengths.next().unwrap_or(0));
        let det_a = take();
        let trim: [IPoly2; 4] = std::array::from_fn(|_| IPoly2::new(vec![take()]));
        let trim_condition = IPoly2::new(vec![take(), take()]);
        let jump_at = IPoly2::new(vec![take()]);
        let d_at = IPoly2::new(vec![take()]);
        let zs_det = take();
        let zs_trim: [IPoly; 3] = std::array::from_fn(|_| take());
        let (zs_jump, zs_d_det) = (take(), take());
        // At delta_e = 0 the zero-sideslip trim is the origin (see `without_origin_factor`);
        // the tape's numerators are then zero up to its rounding bound, so the elevator decides.
        let zs = if delta_e_rad == 0.0 {
            without_origin_factor(&zs_jump, &zs_d_det, &zs_det)
        } else {
            Ok((zs_jump, zs_d_det))
        };
        let at = |p: Param| params[Param::ALL.iter().position(|q| *q == p).unwrap_or(0)];
        let lateral =
            at(Param::LDeltaA) * at(Param::NDeltaR) - at(Param::LDeltaR) * at(Param::NDeltaA);
        // As the general route: delta_a eliminated from the trim condition (linear here).
        let eliminate =
            |f: &IPoly2| eliminate(&trim_condition.0, &f.0, &det_a).map(|p: IPoly| p.symmetric());
        Some((|| {
            let (zs_jump, zs_d_det) = zs?;
            Ok(EnclosedPolys {
                jump: eliminate(&jump_at)?,
                poles: eliminate(&d_at)?,
                det_a: det_a.symmetric(),
                trim,
                trim_condition: trim_condition.clone(),
                jump_at,
                d_at,
                zs_det: zs_det.symmetric(),
                zs_trim,
                zs_jump: zs_jump.symmetric(),
                zs_d_det: zs_d_det.symmetric(),
                lateral,
            })
        })())
    }
}

/// The criterion program ([`crate::program::criterion::criterion_program`]) of the process's
/// parametric derivation, compiled once, with the number of coefficients of each of its
/// polynomials (in the order of [`crate::program::criterion::CriterionProgram::polys`]).
pub(super) struct CriterionTape {
    pub(super) tape: tape::Tape,
    pub(super) lengths: Vec<usize>,
}

impl CriterionTape {
    pub(super) fn get() -> &'static CriterionTape {
        static T: std::sync::OnceLock<CriterionTape> = std::sync::OnceLock::new();
        T.get_or_init(|| {
            let p = crate::program::criterion::criterion_program(crate::specialise::parametric());
            // The inputs the data are given in: delta_e, then the parameters.
            let names: Vec<String> = std::iter::once("delta_e".to_string())
                .chain(
                    Param::ALL
                        .iter()
                        .map(|p| format!("k.{}", p.key().to_lowercase())),
                )
                .collect();
            assert_eq!(
                p.dag.inputs(),
                names.as_slice(),
                "the criterion program's inputs"
            );
            CriterionTape {
                lengths: p.polys().iter().map(|c| c.len()).collect(),
                tape: tape::Tape::new(&p.dag, &p.outputs()),
            }
        })
    }
}

/// The part of [`EnclosedPolys`] that needs no elimination of the aileron: det A, the trim and
/// the trim condition, and det J5 on the trim, in P0 and delta_a. What the walk along the
/// primary branch ([`super::first_root_on_branch`]) reports from (the trim at its roots, the
/// f64 branch, the landings), without the resultants of the jump and pole polynomials.
pub struct TrimPolys {
    /// det A (Eq. 4) in P0 (as in [`EnclosedPolys`]).
    pub det_a: IPoly,
    /// det A in P0 and delta_a (as the trim is evaluated).
    pub det_a_value: IPoly2,
    /// Numerators of [alpha0, beta0, Q0, R0] over `det_a`, in P0 and delta_a.
    pub trim: [IPoly2; 4],
    /// The trim condition `det(A)^2 p_dot` on the trim.
    pub trim_condition: IPoly2,
    /// `det J5 det(A)^2` on the trim.
    pub jump_at: IPoly2,
}

impl TrimPolys {
    /// Encloses the trim-level polynomials of the data `v` (the same construction as
    /// [`EnclosedPolys::new`]'s).
    pub fn new(v: &Values) -> Result<TrimPolys, Uncertified> {
        let (l, m) = (&v.lifted, &mut InP0::new());
        let u = Unconstrained::new(m, l)?;
        let jump_at = u.on_trim(m, l, true);
        Ok(TrimPolys {
            det_a: u.det_a.symmetric(),
            det_a_value: u.det_a_value,
            trim: u.trim,
            trim_condition: u.trim_condition,
            jump_at,
        })
    }
}

/// The part of [`EnclosedPolys`] the critical jump needs: det A, the trim condition, det J5 on
/// the trim and the jump polynomial (the Monte Carlo's lean route).
pub struct JumpPolys {
    /// det A (Eq. 4) in P0.
    pub det_a: IPoly,
    /// The trim condition `det(A)^2 p_dot` on the trim.
    pub trim_condition: IPoly2,
    /// `det J5 det(A)^2` on the trim.
    pub jump_at: IPoly2,
    /// The jump polynomial in P0.
    pub jump: IPoly,
    pub(super) unconstrained: Unconstrained<InP0<I>>,
}

impl JumpPolys {
    /// Encloses the jump part of the criterion polynomials of the data `v`.
    pub fn new(v: &Values) -> Result<JumpPolys, Uncertified> {
        let (l, m) = (&v.lifted, &mut InP0::new());
        let u = Unconstrained::new(m, l)?;
        let jump_at = u.on_trim(m, l, true);
        Ok(JumpPolys {
            jump: u.eliminate(&jump_at)?.symmetric(),
            det_a: u.det_a.symmetric(),
            trim_condition: u.trim_condition.clone(),
            jump_at,
            unconstrained: u,
        })
    }

    /// det A and the numerators of [alpha0, beta0, Q0, R0] in P0 and delta_a.
    pub fn trim(&self) -> (&IPoly2, &[IPoly2; 4]) {
        (&self.unconstrained.det_a_value, &self.unconstrained.trim)
    }

    /// The pole polynomial in P0 (as in [`EnclosedPolys`]) of the same data `v`.
    pub fn poles(&self, v: &Values) -> Result<IPoly, Uncertified> {
        let u = &self.unconstrained;
        let d_at = u.on_trim(&mut InP0::new(), &v.lifted, false);
        Ok(u.eliminate(&d_at)?.symmetric())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::aircraft::Aircraft;

    /// Every coefficient of two sets of criterion polynomials, as pairs (a missing one is an
    /// exact zero).
    fn polynomial_pairs(a: &EnclosedPolys, b: &EnclosedPolys) -> Vec<(I, I)> {
        let all = |e: &EnclosedPolys| -> Vec<IPoly> {
            let mut v = vec![e.det_a.clone(), e.jump.clone(), e.poles.clone()];
            v.extend([e.zs_det.clone(), e.zs_jump.clone(), e.zs_d_det.clone()]);
            v.extend(e.zs_trim.iter().cloned());
            for p in e
                .trim
                .iter()
                .chain([&e.trim_condition, &e.jump_at, &e.d_at])
            {
                v.extend((0..p.0.len().max(2)).map(|i| p.coeff(i)));
            }
            v
        };
        let zero = I::point(0.0);
        let (a, b) = (all(a), all(b));
        assert_eq!(a.len(), b.len());
        a.iter()
            .zip(&b)
            .flat_map(|(p, q)| {
                (0..p.0.len().max(q.0.len())).map(|i| {
                    let at = |d: &IPoly| d.0.get(i).copied().unwrap_or(zero);
                    (at(p), at(q))
                })
            })
            .collect()
    }

    /// The tape ([`EnclosedPolys::by_tape`]) and the general route ([`EnclosedPolys::new`])
    /// enclose the same exact coefficients of every criterion polynomial (every pair of
    /// enclosures overlaps), the tape's as tightly: on the paper's aircraft, none wider than
    /// 1e-12 relative to its magnitude, against which the general route's widest is given.
    #[test]
    fn the_tape_encloses_what_the_general_route_encloses() {
        for (name, ac) in [("A", Aircraft::a()), ("B", Aircraft::b())] {
            let de = 2f64.to_radians();
            let general = EnclosedPolys::new(&Values::of(&ac, de, 0.0)).unwrap();
            let tape = EnclosedPolys::by_tape(&Values::data(&ac), de)
                .expect("the tape covers the paper's aircraft")
                .unwrap();
            let relative = |c: I| c.width() / c.mag().max(f64::MIN_POSITIVE);
            let (mut widest_tape, mut widest_general) = (0.0f64, 0.0f64);
            for (t, g) in polynomial_pairs(&tape, &general) {
                assert!(
                    t.intersect(g).is_some(),
                    "{name}: tape {t:?} vs general {g:?}"
                );
                widest_tape = widest_tape.max(relative(t));
                widest_general = widest_general.max(relative(g));
            }
            println!(
                "{name}: widest relative width: tape {widest_tape:e}, general {widest_general:e}"
            );
            assert!(widest_tape <= 1e-12, "{name}: {widest_tape:e}");
        }
    }
}
