//! The criterion at one roll rate: an enclosure of each criterion polynomial's value computed
//! through the trim ([`value_at`], much tighter near a root than the expanded polynomial), the
//! trim condition there ([`trim_condition_at`]), and the unconstrained roll's quantities as
//! polynomials in delta_a ([`at_roll_rate`], what clearance evaluates over a box).

use super::branch::of_trim_states;
use super::characteristic::hopf_in;
use super::compiled::{Characteristic, Parametric};
use super::isolate::Uncertified;
use super::mode::{AtP0, Da, Mode};
use super::num::Num;
use super::rolls::{zs_trim_in, Unconstrained, ZeroSideslip};
use super::values::Values;
use crate::interval::I;

/// Which criterion polynomial [`value_at`] encloses.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Criterion {
    /// det A.
    DetA,
    /// The jump polynomial.
    Jump,
    /// The pole polynomial.
    Poles,
    /// det A1 of the zero-sideslip trim.
    ZsDet,
    /// `det J5 det(A1)^2` at the zero-sideslip trim (`det J5` where that trim is the origin,
    /// as [`EnclosedPolys::zs_jump`](super::EnclosedPolys::zs_jump)).
    ZsJump,
    /// `d det(A1)^2` at the zero-sideslip trim (`d` at the origin).
    ZsDDet,
    /// The Hopf polynomial of [`EnclosedHopf`](super::EnclosedHopf).
    Hopf,
    /// The zero-sideslip Hopf polynomial of [`EnclosedHopf`](super::EnclosedHopf).
    ZsHopf,
}

/// An enclosure of the value at `P0 = x` of a criterion polynomial of [`EnclosedPolys`],
/// computed through the trim (the same construction at one roll rate): the trim-level factors
/// are small, so this is much tighter near a root than the expanded polynomial's Horner sum.
///
/// [`EnclosedPolys`]: super::EnclosedPolys
pub fn value_at(v: &Values, which: Criterion, x: f64) -> I {
    value_over(v, which, I::point(x))
}

/// An enclosure of the values over the roll rates `x` of a criterion polynomial, as
/// [`value_at`]: over a bracket of a root of another polynomial, what proves the two roots
/// apart without isolating this polynomial's roots.
pub fn value_over(v: &Values, which: Criterion, x: I) -> I {
    type M1 = AtP0<I>;
    let mut m = AtP0(x);
    let t = &v.lifted;
    let value = match which {
        Criterion::DetA | Criterion::Jump | Criterion::Poles => {
            if which == Criterion::DetA {
                M1::univariate(&m.lifted(&t.det_a))
            } else {
                Unconstrained::new(&mut m, t).and_then(|u| {
                    let f = u.on_trim(&mut m, t, which == Criterion::Jump);
                    u.eliminate(&f)
                })
            }
        }
        Criterion::Hopf => {
            let den = m.lifted(&t.det_a);
            let num: [Da<I>; 4] = std::array::from_fn(|i| m.lifted(&t.trim[i]));
            hopf_in(&mut m, &Characteristic::get().c, &t.hopf().c, &num, &den).map(|r| r.delta4())
        }
        Criterion::ZsHopf => {
            let (num, den) = zs_trim_in(&mut m, t);
            hopf_in(
                &mut m,
                &Characteristic::get().zs_c,
                &t.hopf().zs_c,
                &num,
                &den,
            )
            .map(|r| r.delta4())
        }
        _ => ZeroSideslip::new(&mut m, t).map(|z| match which {
            Criterion::ZsDet => z.zs_det,
            Criterion::ZsJump => z.zs_jump,
            _ => z.zs_d_det,
        }),
    };
    value.map_or_else(|_| I::entire(), |s| s.0)
}

/// An enclosure of the trim condition `det(A)^2 p_dot` at `P0 = x` and `delta_a = da`, through
/// the trim (as [`value_at`]): the tight value of [`EnclosedPolys::trim_condition`] there.
///
/// [`EnclosedPolys::trim_condition`]: super::EnclosedPolys::trim_condition
pub fn trim_condition_at(v: &Values, x: f64, da: f64) -> I {
    let mut m = AtP0(I::point(x));
    Unconstrained::new(&mut m, &v.lifted).map_or_else(
        |_| I::entire(),
        |u| {
            let g = &u.trim_condition;
            g.c[..g.len]
                .iter()
                .rev()
                .fold(I::point(0.0), |acc, c| acc * I::point(da) + *c)
        },
    )
}

/// [`trim_condition_at`] through the trim states themselves: the roll equation at the
/// numerators divided by det A, times `det(A)^2`, where det A is proven nonzero at `x`
/// (`None` where it may vanish).
///
/// The cleared form holds `det(A)^2` only through cancellation among products of the trim's
/// numerators, so its enclosure is about a hundred times wider than its rounding (the T-38 at
/// 2,400 m, Mach 0.48, 1 g: 9.6e-12 at the landing of its critical jump, where the midpoints of
/// neighbouring roll rates agree with a straight line to 1e-13); next to a fold, where the
/// trim condition's slope is small, that is too wide to bracket a landing within 1e-9.
pub fn trim_condition_of_states(v: &Values, x: f64, da: f64) -> Option<I> {
    let mut m = AtP0(I::point(x));
    let det_a = AtP0::univariate(&m.lifted(&v.lifted.det_a)).ok()?.0;
    if det_a.contains_zero() {
        return None;
    }
    let roll = &Parametric::get().roll;
    let p_dot = of_trim_states(&mut m, v, I::point(da), roll, &v.lifted.roll)?;
    Some(p_dot.at(I::point(da)) * det_a.sqr())
}

/// The unconstrained roll's criterion quantities at one roll rate, as polynomials in delta_a
/// (coefficients of `delta_a^0, delta_a^1, ...`), all cleared of det A as in
/// [`EnclosedPolys`], what clearance evaluates over a box of data and a slab of roll rates.
///
/// [`EnclosedPolys`]: super::EnclosedPolys
#[derive(Clone, Debug)]
pub struct AtRollRate<T> {
    /// det A.
    pub det_a: T,
    /// The trim condition `det(A)^2 p_dot`.
    pub g: Vec<T>,
    /// `det J5 det(A)^2` on the trim.
    pub jump_at: Vec<T>,
}

/// [`AtRollRate`] of the data `v` at the roll rate `p0` (both in the numbers `T`).
pub fn at_roll_rate<T: Num>(v: &Values<T>, p0: T) -> Result<AtRollRate<T>, Uncertified> {
    at_roll_rate_with(v, p0, true)
}

/// [`at_roll_rate`], or without `jump_at` (left empty) unless `jump`: det A and the trim
/// condition alone are the same values at about half the work, for what needs only the trim
/// (its roots in delta_a).
pub fn at_roll_rate_with<T: Num>(
    v: &Values<T>,
    p0: T,
    jump: bool,
) -> Result<AtRollRate<T>, Uncertified> {
    let m = &mut AtP0(p0);
    let l = &v.lifted;
    let u = Unconstrained::new(m, l)?;
    let coeffs = |d: &Da<T>| d.c[..d.len].to_vec();
    let jump_at = if jump {
        coeffs(&u.on_trim(m, l, true))
    } else {
        Vec::new()
    };
    Ok(AtRollRate {
        det_a: u.det_a.0,
        g: coeffs(&u.trim_condition),
        jump_at,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::aircraft::{Aircraft, Param};
    use num_rational::BigRational;

    /// Through the trim states the trim condition's enclosure meets the cleared one (both hold
    /// the exact value), on aircraft B with aileron yaw (n_delta_a = -1.5) at delta_e = 2 deg,
    /// at roll rates below and above its first divergence roll rate and at ailerons on and
    /// off its trims, and is narrower at those below 2 rad/s.
    #[test]
    fn the_trim_condition_of_the_trim_states_is_the_cleared_one_tighter() {
        let ac = Aircraft::b().with(Param::NDeltaA, BigRational::new((-3).into(), 2.into()));
        let v = Values::of(&ac, 2f64.to_radians(), 0.0);
        for p in [0.3, 0.9, 1.4, 2.5, 4.0] {
            for da in [-0.4, -0.05, 0.0, 0.3] {
                let cleared = trim_condition_at(&v, p, da);
                let states = trim_condition_of_states(&v, p, da).unwrap();
                assert!(
                    states.intersect(cleared).is_some(),
                    "P0 = {p}, delta_a = {da}: {states:?} vs {cleared:?}"
                );
                if p < 2.0 {
                    assert!(states.width() <= cleared.width(), "P0 = {p}, {da}");
                }
            }
        }
    }
}
