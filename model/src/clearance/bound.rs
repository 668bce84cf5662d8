//! Sound enclosures of the criterion over a box of data and a slab of roll rates, for the
//! branch and bound that certifies how far the primary branch is free of jumps.
//!
//! A slab `[pa, pb] x X` (X the box of the uncertain parameters) is *certified* when, with every
//! enclosure outward-rounded ([`crate::interval`]):
//!
//! 1. det A has no zero on it (the trim exists and is finite);
//! 2. the discriminant `g1^2 - 4 g0 g2` of the trim condition
//!    `G = g0 + g1 delta_a + g2 delta_a^2` is positive and `g1 + s sqrt(disc)` has no zero, `s`
//!    the sign of `g1` at P0 = 0 over the box (the branch's side): the root
//!    `delta_a = -2 g0 / (g1 + s sqrt(disc))` (0 at P0 = 0; the root of smaller magnitude while
//!    `g1` keeps the sign `s`, the larger one after `g1` changes sign) is a continuous function
//!    on the slab with `dG/d delta_a = s sqrt(disc) != 0`, so it *is* the primary branch there
//!    (implicit function theorem, continued from P0 = 0 through certified slabs);
//! 3. `J = det J5 det(A)^2`, evaluated on that root, has no zero: no fold (saddle-node,
//!    det J5 = 0) of the primary branch in the slab.
//!
//! With aileron yaw a branch that turns in P0 beyond the certified slabs comes back on the
//! other root of `G`; [`BoxPolys::other_trim`] checks that it meets no jump there, and
//! [`BoxPolys::turn_back`] proves, where it can, that every branch of the box turns back within
//! a zone above the slabs that holds no jump (docs/clearance.md, step 6).
//!
//! Each quantity is computed by the certified route's one construction
//! ([`crate::certified::at_roll_rate`]) in [`Dual`] numbers: an enclosure over the whole slab
//! and box together with enclosures of its partial derivatives in every uncertain parameter and
//! in P0. The mean-value form `f(c) + sum_i df/dx_i (X) (x_i - c_i)`, with `f(c)` evaluated at
//! the centre, then encloses `f` far more tightly than the value alone, and each enclosure is
//! intersected into the next step of the chain. For J, whose zero is what the proof is about, a
//! coordinate in which J is monotone over the box is fixed at the face where J comes closest to
//! zero before the mean-value form is taken there.
//!
//! ```
//! use model::aircraft::{Aircraft, Param};
//! use model::clearance::bound::{BoxPolys, Failure};
//! use model::interval::I;
//!
//! // Aircraft A with l_p free in [-21.8, -21.7] 1/s (A's is -21.7529).
//! let b = BoxPolys::new(&Aircraft::a(), &[Param::Lp], 2f64.to_radians());
//! let l_p = b.lift(&[I::new(-21.8, -21.7)]);
//! // No jump for P0 in [1.0, 1.01]: certified, with negative aileron on the primary branch.
//! let da = b.certify(&l_p, I::new(1.0, 1.01)).unwrap();
//! assert!(da.hi < 0.0);
//! // The slab [1.6, 1.8] holds A's first jump (1.706 rad/s, Fig. 7): it cannot be certified.
//! assert_eq!(b.certify(&l_p, I::new(1.6, 1.8)), Err(Failure::Jump));
//! ```

use super::Coordinate;
use crate::aircraft::{Aircraft, Param, Uncertain};
use crate::analysis::primary::TURN_STEP;
use crate::certified::dense::horner;
use crate::certified::num::{Dual, Num, GRADIENT};
use crate::certified::{at_roll_rate, at_roll_rate_with, AtRollRate, Values};
use crate::equations::symbols;
use crate::interval::{next_down, next_up, I};
use crate::specialise::parametric;

mod faces;
use faces::Faces;

/// Why a slab could not be certified.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Failure {
    /// det A may vanish: the trim may diverge (Eq. 5) in the slab.
    Divergence,
    /// `dG/d delta_a` may vanish (the primary branch may turn in P0: two trims merge), or the
    /// branch's root cannot be told from the other's.
    Turn,
    /// J may vanish: a jump may lie in the slab.
    Jump,
}

/// What a branch coming back on its other trim meets in a slab ([`BoxPolys::other_trim`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OtherTrim {
    /// No jump: J has no zero on the other root (or there is no other trim).
    NoJump,
    /// The end of the aileron range: the other root lies beyond it, so `analyze`'s walk ends
    /// there (and below the slab it cannot come back up).
    BeyondRange,
    /// Possibly a jump within the aileron range.
    MayJump,
}

impl OtherTrim {
    /// Whether a branch coming back meets no jump in the slab.
    pub fn is_clear(self) -> bool {
        self != OtherTrim::MayJump
    }
}

/// The criterion of a box of aircraft, ready for enclosures over slabs of roll rates.
#[derive(Clone, Debug)]
pub struct BoxPolys {
    /// The coordinates of the box, in order.
    coordinates: Vec<Coordinate>,
    /// Enclosures of every parameter's fixed value (the uncertain ones are replaced by the box).
    fixed: [I; Param::COUNT],
    delta_e_rad: f64,
    /// Whether the trim at P0 = 0 is delta_a = 0 for every aircraft of the box (exactly).
    pub symmetric: bool,
    /// Whether some aircraft of the box may have aileron yaw (n_delta_a != 0): then the trim
    /// condition is quadratic in delta_a, the primary branch may turn in P0, and each slab's
    /// other trim is checked too ([`BoxPolys::other_trim`]).
    pub aileron_yaw: bool,
}

/// A box of uncertain data lifted for the chain (see [`BoxPolys::lift`]).
#[derive(Clone, Debug)]
pub struct LiftedBox {
    theta: Vec<I>,
    centre: Vec<f64>,
    over: Values<Dual>,
    at_centre: Values<I>,
    /// The side of the primary branch, the sign of `g1` at P0 = 0 over the box (`None` when
    /// it is not certain): the branch is the root `-2 g0 / (g1 + side sqrt(disc))` of the trim
    /// condition on every certified slab ([`BoxPolys::trim`]).
    side: Option<f64>,
    /// Its faces lifted so far ([`BoxPolys::face`]).
    faces: Faces,
}

impl LiftedBox {
    /// The box.
    pub fn theta(&self) -> &[I] {
        &self.theta
    }

    /// The side of the primary branch (see [`BoxPolys::lift_on_side`]).
    pub fn side(&self) -> Option<f64> {
        self.side
    }
}

/// The quantities of the chain over the box.
struct Chain<T> {
    det_a: T,
    da: T,
    jump: T,
}

/// The trim condition's part of the chain ([`BoxPolys::trim`]): each quantity over the box and
/// at its centre.
struct Trim {
    /// The criterion's quantities over the box and at the centre.
    at: (AtRollRate<Dual>, AtRollRate<I>),
    /// The box with P0 last, and its centre.
    x: Vec<I>,
    c: Vec<f64>,
    det_a: Dual,
    /// `g0` and `g2`, over the box and at the centre.
    g: (Dual, Dual),
    g_c: (I, I),
    /// `g1 + s sqrt(disc)`, `s` the branch's side ([`LiftedBox`]), over the box and at the
    /// centre.
    den: (Dual, I),
}

/// det A and the trim condition's coefficients over a slab and the box ([`BoxPolys::coefficients`]).
/// What an evaluation over a slab needs of the criterion: the trim condition alone (the
/// branch's aileron, the roots in delta_a) or J on the trim too, which costs about as much again.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Need {
    Trim,
    Jump,
}

struct Coefficients {
    /// The criterion's quantities over the box and at the centre.
    at: (AtRollRate<Dual>, AtRollRate<I>),
    /// The box with P0 last, and its centre.
    x: Vec<I>,
    c: Vec<f64>,
    det_a: Dual,
    /// `g0, g1, g2` over the box (`g1` tightened) and at the centre.
    g: [Dual; 3],
    g_c: [I; 3],
}

impl BoxPolys {
    /// The box of `aircraft` in the uncertain `params` at `delta_e_rad` (delta_r = 0).
    pub fn new(aircraft: &Aircraft, params: &[Param], delta_e_rad: f64) -> BoxPolys {
        BoxPolys::with(
            aircraft,
            params.iter().map(|p| Coordinate::Param(*p)).collect(),
            delta_e_rad,
        )
    }

    /// The box of `aircraft` whose coordinates are `params` (each a parameter, or a coefficient
    /// of a nondimensional file moving several), with every coordinate's value in `aircraft`
    /// its nominal one.
    ///
    /// A parameter a coefficient moves is its loaded nominal value (the conversion rounded once
    /// to f64) plus exact increments, while a file written with the same coefficients holds
    /// the conversion rounded at those coefficients: the two differ by at most one ulp of the
    /// parameter's largest magnitude over the box. Its fixed part is widened by four of those,
    /// so that the proof covers both.
    pub fn of_box(aircraft: &Aircraft, params: &[Uncertain], delta_e_rad: f64) -> BoxPolys {
        let coordinates: Vec<Coordinate> = params.iter().map(Coordinate::of).collect();
        let mut b = BoxPolys::with(aircraft, coordinates, delta_e_rad);
        let mut largest = [0.0f64; Param::COUNT];
        for (u, c) in params.iter().zip(&b.coordinates) {
            let Coordinate::Coefficient { nominal, moves } = c else {
                continue;
            };
            let reach = (I::from_q(&u.lo) - *nominal)
                .mag()
                .max((I::from_q(&u.hi) - *nominal).mag());
            for (p, a) in moves {
                largest[p.index()] += a.mag() * reach;
            }
        }
        for (i, extra) in largest.iter().enumerate() {
            if *extra > 0.0 {
                let f = b.fixed[i];
                let w = 4.0 * f64::EPSILON * (f.mag() + extra);
                b.fixed[i] = I::new(next_down(f.lo - w), next_up(f.hi + w));
            }
        }
        b
    }

    fn with(aircraft: &Aircraft, coordinates: Vec<Coordinate>, delta_e_rad: f64) -> BoxPolys {
        assert!(
            coordinates.len() < GRADIENT,
            "at most {} uncertain parameters (and P0)",
            GRADIENT - 1
        );
        // A parameter's own coordinate sets it: no coefficient may move it too (the loader
        // makes every coefficient that moves more than its own derivative a coordinate).
        debug_assert!(coordinates.iter().all(|c| match c {
            Coordinate::Param(p) => coordinates.iter().all(|o| match o {
                Coordinate::Coefficient { moves, .. } => moves.iter().all(|(q, _)| q != p),
                Coordinate::Param(_) => true,
            }),
            Coordinate::Coefficient { .. } => true,
        }));
        let moved: Vec<Param> = coordinates.iter().flat_map(Coordinate::params).collect();
        let fixed = Values::data(aircraft);
        BoxPolys {
            aileron_yaw: moved.contains(&Param::NDeltaA)
                || !fixed[Param::NDeltaA.index()].is_exact_zero(),
            fixed,
            delta_e_rad,
            symmetric: trim_at_rest_is_level(aircraft, &moved, delta_e_rad),
            coordinates,
        }
    }

    /// The box `theta` lifted once for every slab of roll rates: over the box (a gradient seed in
    /// each uncertain coordinate, P0 the last) and at its centre.
    pub fn lift(&self, theta: &[I]) -> LiftedBox {
        self.lift_on_side(theta, None)
    }

    /// [`BoxPolys::lift`] of a part `theta` of the lifted box `whole`: the branch's side is the
    /// whole's where that is certain (the same sign of `g1` at P0 = 0 holds on every part).
    pub fn lift_part(&self, theta: &[I], whole: &LiftedBox) -> LiftedBox {
        debug_assert!(
            theta.len() == whole.theta.len()
                && theta
                    .iter()
                    .zip(&whole.theta)
                    .all(|(t, w)| w.lo <= t.lo && t.hi <= w.hi),
            "a part of the box"
        );
        self.lift_on_side(theta, whole.side)
    }

    /// [`BoxPolys::lift`] of a box on the branch's side `side` (that of the lifted box it was
    /// a part of, [`LiftedBox::side`]), computed from the box when `None`: a sub-box lifted
    /// again, as [`BoxPolys::lift_part`] lifted it first.
    pub fn lift_on_side(&self, theta: &[I], side: Option<f64>) -> LiftedBox {
        let n = self.coordinates.len() + 1;
        let mut over: [Dual; Param::COUNT] = std::array::from_fn(|i| Dual::constant(self.fixed[i]));
        let mut at = self.fixed;
        let centre: Vec<f64> = theta.iter().map(|t| t.mid()).collect();
        for (k, (coordinate, x)) in self.coordinates.iter().zip(theta).enumerate() {
            match coordinate {
                Coordinate::Param(param) => {
                    over[param.index()] = Dual::variable(*x, k, n);
                    at[param.index()] = I::point(centre[k]);
                }
                Coordinate::Coefficient { nominal, moves } => {
                    let dx = Dual::variable(*x, k, n) - Dual::constant(*nominal);
                    let dc = I::point(centre[k]) - *nominal;
                    for (p, a) in moves {
                        let i = p.index();
                        over[i] = over[i] + Dual::constant(*a) * dx;
                        at[i] = at[i] + *a * dc;
                    }
                }
            }
        }
        let mut bx = LiftedBox {
            theta: theta.to_vec(),
            centre,
            over: Values::new(over, self.delta_e_rad, 0.0),
            at_centre: Values::new(at, self.delta_e_rad, 0.0),
            side,
            faces: Faces::default(),
        };
        if side.is_none() {
            bx.side = self
                .coefficients(&bx, I::point(0.0), Need::Trim)
                .ok()
                .and_then(|k| k.g[1].v.sign());
        }
        bx
    }

    /// det A and the coefficients of the trim condition over `p x` the box, det A and `g1`
    /// tightened by their mean-value forms around the centre and det A proven nonzero, or the
    /// first link that fails; with J's polynomial in delta_a on the trim when `need` says so
    /// (else that is left empty).
    fn coefficients(&self, bx: &LiftedBox, p: I, need: Need) -> Result<Coefficients, Failure> {
        let n = self.coordinates.len() + 1;
        let x: Vec<I> = bx.theta.iter().copied().chain([p]).collect();
        let c: Vec<f64> = bx.centre.iter().copied().chain([p.mid()]).collect();
        let (vb, pb) = (&bx.over, Dual::variable(p, n - 1, n));
        let (vc, pc) = (&bx.at_centre, I::point(c[n - 1]));
        let jump = need == Need::Jump;
        let b = at_roll_rate_with(vb, pb, jump).map_err(|_| Failure::Divergence)?;
        let m = at_roll_rate_with(vc, pc, jump).map_err(|_| Failure::Divergence)?;
        let det_a = tight(b.det_a, m.det_a, &x, &c)?;
        if det_a.v.contains_zero() {
            return Err(Failure::Divergence);
        }
        let coef = |a: &AtRollRate<Dual>, i: usize| {
            a.g.get(i)
                .copied()
                .unwrap_or_else(|| Dual::constant(I::point(0.0)))
        };
        let coef_c = |a: &AtRollRate<I>, i: usize| a.g.get(i).copied().unwrap_or(I::point(0.0));
        let g1 = tight(coef(&b, 1), coef_c(&m, 1), &x, &c)?;
        Ok(Coefficients {
            g: [coef(&b, 0), g1, coef(&b, 2)],
            g_c: [coef_c(&m, 0), coef_c(&m, 1), coef_c(&m, 2)],
            at: (b, m),
            x,
            c,
            det_a,
        })
    }

    /// The discriminant `g1^2 - 4 g0 g2` of the trim condition, tightened by its mean-value
    /// form, and its enclosure at the centre.
    fn discriminant(k: &Coefficients) -> Result<(Dual, I), Failure> {
        let four = I::point(4.0);
        let ([g0, g1, g2], [g0c, g1c, g2c]) = (k.g, k.g_c);
        let centre = g1c * g1c - four * g0c * g2c;
        let disc = tight(g1 * g1 - Dual::constant(four) * g0 * g2, centre, &k.x, &k.c)?;
        Ok((disc, centre))
    }

    /// The trim condition's part of the chain over `p x` the box (det A, the coefficients of
    /// `G` in delta_a and its discriminant), every value tightened by its mean-value form around
    /// the centre, or the first link that fails; with J's polynomial for the rest of the chain.
    fn trim(&self, bx: &LiftedBox, p: I) -> Result<Trim, Failure> {
        self.trim_for(bx, p, Need::Jump)
    }

    /// [`BoxPolys::trim`], with J's polynomial only if `need` says so.
    fn trim_for(&self, bx: &LiftedBox, p: I, need: Need) -> Result<Trim, Failure> {
        let k = self.coefficients(bx, p, need)?;
        let ([g0, g1, g2], [g0c, g1c, g2c]) = (k.g, k.g_c);
        let Some(s) = bx.side else {
            return Err(Failure::Turn);
        };
        let (disc, disc_c) = BoxPolys::discriminant(&k)?;
        if disc.v.lo <= 0.0 {
            return Err(Failure::Turn);
        }
        let root = Num::sqrt(disc).ok_or(Failure::Turn)?;
        let root_c = I::sqrt(disc_c).ok_or(Failure::Turn)?;
        // g1 + side sqrt(disc): without cancellation while g1 keeps the side's sign (the root
        // of smaller magnitude); past a change of g1's sign the same root, now the larger one,
        // as long as the sum keeps clear of zero (g0 g2 != 0).
        let den = g1 + Dual::constant(I::point(s)) * root;
        let den_c = g1c + I::point(s) * root_c;
        if den.v.contains_zero() {
            return Err(Failure::Turn);
        }
        Ok(Trim {
            at: k.at,
            x: k.x,
            c: k.c,
            det_a: k.det_a,
            g: (g0, g2),
            g_c: (g0c, g2c),
            den: (den, den_c),
        })
    }

    /// The chain over `p x` the box, every value tightened by its mean-value form around the
    /// centre, or the first link that fails.
    fn chain(&self, bx: &LiftedBox, p: I) -> Result<Chain<Dual>, Failure> {
        self.chain_on(&self.trim(bx, p)?)
    }

    /// The chain on the trim condition's part `t` of it.
    fn chain_on(&self, t: &Trim) -> Result<Chain<Dual>, Failure> {
        let ((b, m), (x, c)) = (&t.at, (&t.x, &t.c));
        let (da, da_c) = BoxPolys::aileron_on(t)?;
        let jump = tight(horner(&b.jump_at, da), horner(&m.jump_at, da_c), x, c)?;
        Ok(Chain {
            det_a: t.det_a,
            da,
            jump,
        })
    }

    /// The primary branch's aileron over the box and at the centre, on the trim condition's
    /// part `t` of the chain: the root `-2 g0 / (g1 + s sqrt(disc))`, tightened by its
    /// mean-value form.
    fn aileron_on(t: &Trim) -> Result<(Dual, I), Failure> {
        let ((g0, _), (g0c, _), (den, den_c)) = (t.g, t.g_c, t.den);
        let minus_two = I::point(-2.0);
        let da_box = (Dual::constant(minus_two) * g0)
            .div(den)
            .ok_or(Failure::Turn)?;
        let da_c = (minus_two * g0c).checked_div(den_c).ok_or(Failure::Turn)?;
        Ok((tight(da_box, da_c, &t.x, &t.c)?, da_c))
    }

    /// The primary branch's aileron over `p x` the box ([`BoxPolys::aileron_on`]), from the
    /// trim condition alone.
    fn aileron(&self, bx: &LiftedBox, p: I) -> Result<Dual, Failure> {
        Ok(BoxPolys::aileron_on(&self.trim_for(bx, p, Need::Trim)?)?.0)
    }

    /// What a primary branch that comes back into the slab `p x` the box on its *other* trim
    /// (after turning in P0 beyond it, aileron yaw) meets there: no jump, as J has no zero on
    /// the other root `delta_a = -(g1 + s sqrt(disc)) / (2 g2)`, `s` the branch's side
    /// ([`OtherTrim::NoJump`]);
    /// or the end of the aileron range, as that root lies beyond the `range` (1e-9 relative
    /// margin, as for `finished`) on the slab and two steps of `analyze`'s walk above it
    /// ([`OtherTrim::BeyondRange`]); or possibly a jump ([`OtherTrim::MayJump`]). The walk on
    /// the other trim checks the range at steps at most `analysis::primary::TURN_STEP` apart;
    /// the extension, certified free of turns and divergences, keeps any turn of the branch two
    /// such steps above the slab, so every step that could reach a jump in the slab starts from
    /// a point checked against the range where the root is proven beyond it. Without aileron
    /// yaw (g2 = 0 for every aircraft) there is no other trim.
    pub fn other_trim(&self, bx: &LiftedBox, p: I, range: f64) -> OtherTrim {
        self.other_trim_with(bx, p, range, None)
    }

    /// [`BoxPolys::other_trim`], from the trim condition's part `t` of the chain on the slab
    /// when it is at hand (else evaluated here, if it comes to that).
    fn other_trim_with(&self, bx: &LiftedBox, p: I, range: f64, t: Option<&Trim>) -> OtherTrim {
        if !self.aileron_yaw {
            return OtherTrim::NoJump;
        }
        // The range first: a run of such slabs also shields the slabs below it.
        if self.other_beyond_range(bx, p, range) {
            return OtherTrim::BeyondRange;
        }
        match t {
            Some(t) => BoxPolys::other_on(t),
            None => match self.trim(bx, p) {
                Ok(t) => BoxPolys::other_on(&t),
                Err(_) => OtherTrim::MayJump,
            },
        }
    }

    /// Whether J has no zero on the other root over the slab of the trim condition's part `t`
    /// of the chain ([`OtherTrim::NoJump`], else [`OtherTrim::MayJump`]).
    fn other_on(t: &Trim) -> OtherTrim {
        let ((b, m), (g2, g2c), (den, den_c)) = (&t.at, (t.g.1, t.g_c.1), t.den);
        let two = I::point(2.0);
        if !g2.v.contains_zero() {
            let other = (-den).div(Dual::constant(two) * g2);
            let other_c = (-den_c).checked_div(two * g2c);
            if let (Some(o), Some(oc)) = (other, other_c) {
                let j = tight(horner(&b.jump_at, o), horner(&m.jump_at, oc), &t.x, &t.c);
                if j.is_ok_and(|j| !j.v.contains_zero()) {
                    return OtherTrim::NoJump;
                }
            }
        }
        OtherTrim::MayJump
    }

    /// Whether the other root of `G` lies beyond the aileron `range` (1e-9 relative margin) on
    /// the slab `p x` the box and two walk steps above it, with the trim certified there
    /// ([`OtherTrim::BeyondRange`] of [`BoxPolys::other_trim`]). Where g2 = 0 exactly there is
    /// no other root at all (it has gone to infinity), which counts as beyond.
    pub fn other_beyond_range(&self, bx: &LiftedBox, p: I, range: f64) -> bool {
        let above = I::new(p.lo, next_up(p.hi + 2.0 * TURN_STEP));
        let Ok(t) = self.trim_for(bx, above, Need::Trim) else {
            return false;
        };
        let (g2, den) = (t.g.1.v, t.den.0.v);
        // |other root| >= min |g1 + s sqrt(disc)| / (2 max |g2|), rounded down.
        g2.is_exact_zero()
            || I::point(den.mig())
                .checked_div(I::point(2.0) * I::point(g2.mag()))
                .is_some_and(|least| least.lo > range * (1.0 + 1e-9))
    }

    /// Where every aircraft's primary branch, certified from P0 = 0 up to `from`, turns back in
    /// P0 without a jump: the smallest `top = from + w` (`w = min_width, 2 min_width, ...` up
    /// to `max_width`) such that the trim condition has no real root for any aircraft of the box
    /// on `[top, top + 2 TURN_STEP]` (its discriminant is negative, `g2` nonzero), provided the
    /// *turn zone* `[from, top]` clears ([`BoxPolys::turn_zone_clear`]); `None` otherwise, or
    /// without aileron yaw (no turn). Then every branch comes back down through `from` on its
    /// other trim, and the other trims checked below `from` ([`BoxPolys::other_trim`]) are all it
    /// can meet a jump on (docs/clearance.md, step 6). The band without trims is two steps of
    /// `analyze`'s walk wide (it steps at most `TURN_STEP` where the branch may turn), so that
    /// the walk cannot step over it onto trims beyond, where the exact curve never goes.
    pub fn turn_back(
        &self,
        bx: &LiftedBox,
        from: f64,
        min_width: f64,
        max_width: f64,
    ) -> Option<f64> {
        if !self.aileron_yaw || min_width.is_nan() || min_width <= 0.0 {
            return None;
        }
        let mut w = min_width;
        while w <= max_width {
            let top = from + w;
            if self.no_trim_on(bx, I::new(top, next_up(top + 2.0 * TURN_STEP))) {
                return self.turn_zone_clear(bx, I::new(from, top)).then_some(top);
            }
            w *= 2.0;
        }
        None
    }

    /// Whether the trim condition has no real root in delta_a at any roll rate of `p` for any
    /// aircraft of the box: `g2` of one sign and the discriminant negative.
    fn no_trim_on(&self, bx: &LiftedBox, p: I) -> bool {
        self.quadratic(bx, p, Need::Trim)
            .is_some_and(|(_, _, disc)| disc.v.hi < 0.0)
    }

    /// The trim condition over `p x` the box as a quadratic in delta_a: its coefficients, `g2`
    /// and the discriminant, both tightened by their mean-value forms; `None` when a link
    /// fails or `g2` may vanish.
    fn quadratic(&self, bx: &LiftedBox, p: I, need: Need) -> Option<(Coefficients, Dual, Dual)> {
        let k = self.coefficients(bx, p, need).ok()?;
        let g2 = tight(k.g[2], k.g_c[2], &k.x, &k.c).ok()?;
        let (disc, _) = BoxPolys::discriminant(&k).ok()?;
        g2.v.sign()?;
        Some((k, g2, disc))
    }

    /// Whether the turn zone `u x` the box holds no jump on any trim: det A and `g2` have no
    /// zero on it, and J has no zero for delta_a anywhere between the two roots of the trim
    /// condition, `(-g1 +- sqrt(max(disc, 0))) / (2 g2)`, which holds every real root (both
    /// trims, wherever they exist). Then `G_P0 = J / det A` (step 5 of docs/clearance.md) has no
    /// zero on the equilibrium curve in the zone: the curve is a graph over delta_a there, so a
    /// branch entering the zone at its bottom on one trim, unable to leave it at the top (no
    /// root there, as `turn_back` checks) or to run off in delta_a (`g2 != 0` bounds the
    /// roots), leaves it at the bottom again, on the other trim, and meets no jump (`J = 0`) on
    /// the way. J is enclosed over the box, the zone and that whole range of delta_a (the range
    /// as one interval, J's mean-value form in the box and P0 around the centre, where it is
    /// evaluated over the same range of delta_a).
    pub fn turn_zone_clear(&self, bx: &LiftedBox, u: I) -> bool {
        let Some((k, g2, disc)) = self.quadratic(bx, u, Need::Jump) else {
            return false;
        };
        // Every real root: between the two roots where disc >= 0 (none where disc < 0).
        let Some(root) = I::new(0.0, disc.v.hi.max(0.0)).sqrt() else {
            return false;
        };
        let spread = I::new(-root.hi, root.hi);
        let Some(da) = (-k.g[1].v + spread).checked_div(I::point(2.0) * g2.v) else {
            return false;
        };
        let (b, m) = &k.at;
        let j = tight(
            horner(&b.jump_at, Dual::constant(da)),
            horner(&m.jump_at, da),
            &k.x,
            &k.c,
        );
        j.is_ok_and(|j| !j.v.contains_zero())
    }

    /// A lower bound of |delta_a| on the primary branch at roll rate `p` over the box (`None`
    /// when the chain fails there): the smallest magnitude of its enclosure over the box, or on
    /// the face of the box towards which |delta_a| decreases in every coordinate where it is
    /// monotone (the mean-value form there), whichever is larger.
    pub fn aileron_lower(&self, bx: &LiftedBox, p: f64) -> Option<f64> {
        let branch = self.aileron(bx, I::point(p)).ok()?;
        let da = branch.v;
        let Some(sign) = da.sign() else {
            return Some(0.0);
        };
        let face: Vec<I> = bx
            .theta
            .iter()
            .enumerate()
            .map(|(i, t)| match branch.g[i].sign() {
                // Towards smaller |delta_a|: against the gradient when delta_a > 0.
                Some(g) if g * sign > 0.0 => I::point(t.lo),
                Some(_) => I::point(t.hi),
                None => *t,
            })
            .collect();
        let on_face = self
            .aileron(&self.face(&face, bx), I::point(p))
            .map_or(0.0, |d| {
                if d.v.sign() == Some(sign) {
                    d.v.mig()
                } else {
                    0.0
                }
            });
        Some(on_face.max(da.mig()))
    }

    /// Whether no aircraft of the box has a trim with |delta_a| <= `l` at roll rate `p`: det A
    /// has no zero there and the trim condition `G = g0 + g1 delta_a + g2 delta_a^2` no zero
    /// for delta_a in [-l, l]. The primary branch at `p` is such a root, so then its |delta_a|
    /// exceeds `l` for every aircraft, whichever root it is: a bound that needs no enclosure of
    /// the root itself, which near a steep stretch of the branch (delta_a changing fast with
    /// P0, the discriminant small) is far wider than the data's spread. [-l, l] is cut into
    /// pieces, checked from 0 outwards (a root near 0 fails first); on each, G is enclosed with
    /// delta_a as an interval, in its mean-value form in the parameters around the centre.
    ///
    /// ```
    /// use model::aircraft::{Aircraft, Param};
    /// use model::clearance::bound::BoxPolys;
    /// use model::interval::I;
    ///
    /// // Aircraft A with l_p free in [-21.8, -21.7] 1/s, its primary branch at P0 = 1 rad/s.
    /// let b = BoxPolys::new(&Aircraft::a(), &[Param::Lp], 2f64.to_radians());
    /// let l_p = b.lift(&[I::new(-21.8, -21.7)]);
    /// let da = b.certify(&l_p, I::point(1.0)).unwrap();
    /// // No trim within 0.99 of the branch's smallest |delta_a|; one within 1.01 of its largest.
    /// assert!(b.no_trim_within(&l_p, 1.0, 0.99 * da.mig()));
    /// assert!(!b.no_trim_within(&l_p, 1.0, 1.01 * da.mag()));
    /// ```
    pub fn no_trim_within(&self, bx: &LiftedBox, p: f64, l: f64) -> bool {
        const PIECES: usize = 16;
        // Ends of the pieces; neighbours share an end, so the pieces cover [-l, l] whatever
        // the rounding.
        let end = |i: usize| -l + 2.0 * l * (i as f64) / (PIECES as f64);
        let half = PIECES / 2;
        let order: Vec<usize> = (0..half).flat_map(|j| [half - 1 - j, half + j]).collect();
        let piece = |i: usize| I::new(end(i), if i + 1 == PIECES { l } else { end(i + 1) });
        // The centre's aircraft first, in plain intervals: where it has a trim within l, so
        // has the box (the common case below the target, and a tenth of the cost).
        let Ok(m) = at_roll_rate_with(&bx.at_centre, I::point(p), false) else {
            return false;
        };
        let coef_c = |i: usize| m.g.get(i).copied().unwrap_or(I::point(0.0));
        let at_centre = |d: I| coef_c(0) + coef_c(1) * d + coef_c(2) * d.sqr();
        if order.iter().any(|i| at_centre(piece(*i)).contains_zero()) {
            return false;
        }
        let Ok(k) = self.coefficients(bx, I::point(p), Need::Trim) else {
            return false;
        };
        order.into_iter().all(|i| {
            let d = piece(i);
            let ([g0, g1, g2], [g0c, g1c, g2c]) = (k.g, k.g_c);
            let (dd, d2) = (Dual::constant(d), Dual::constant(d.sqr()));
            let over = g0 + g1 * dd + g2 * d2;
            let centre = g0c + g1c * d + g2c * d.sqr();
            tight(over, centre, &k.x, &k.c).is_ok_and(|g| !g.v.contains_zero())
        })
    }

    /// Certifies the slab `p x theta` (see the module documentation); on success returns the
    /// enclosure of the primary branch's aileron on it.
    pub fn certify(&self, bx: &LiftedBox, p: I) -> Result<I, Failure> {
        let chain = self.chain(bx, p)?;
        self.certified(bx, p, chain)
    }

    /// [`BoxPolys::certify`] and, on success, [`BoxPolys::other_trim`] of the same slab, from
    /// one evaluation of the trim condition's part of the chain on it.
    pub fn certify_with_other(
        &self,
        bx: &LiftedBox,
        p: I,
        range: f64,
    ) -> Result<(I, OtherTrim), Failure> {
        let t = self.trim(bx, p)?;
        let da = self.certified(bx, p, self.chain_on(&t)?)?;
        Ok((da, self.other_trim_with(bx, p, range, Some(&t))))
    }

    /// The last link of [`BoxPolys::certify`]: J of the `chain` over the slab `p` free of zeros
    /// (tried again on a face of the box where J is monotone).
    fn certified(&self, bx: &LiftedBox, p: I, chain: Chain<Dual>) -> Result<I, Failure> {
        debug_assert!(!chain.det_a.v.contains_zero());
        if !chain.jump.v.contains_zero() {
            return Ok(chain.da.v);
        }
        // J is monotone in some coordinates: on the face where it comes closest to zero (on the
        // side of its sign at the centre) the mean-value form is tighter.
        let x: Vec<I> = bx.theta.iter().copied().chain([p]).collect();
        let centre_sign = if chain.jump.v.mid() >= 0.0 { 1.0 } else { -1.0 };
        let mut moved = false;
        let face: Vec<I> = x
            .iter()
            .enumerate()
            .map(|(i, xi)| match chain.jump.g[i].sign() {
                // Towards J's zero: against the gradient when J > 0, along it when J < 0.
                Some(g) => {
                    moved = true;
                    if g * centre_sign > 0.0 {
                        I::point(xi.lo)
                    } else {
                        I::point(xi.hi)
                    }
                }
                None => *xi,
            })
            .collect();
        if !moved {
            return Err(Failure::Jump);
        }
        let face_box = self.face(&face[..face.len() - 1], bx);
        let on_face = self.chain(&face_box, face[face.len() - 1])?;
        match on_face.jump.v.sign() {
            Some(s) if s == centre_sign => Ok(chain.da.v),
            _ => Err(Failure::Jump),
        }
    }
}

impl BoxPolys {
    /// The coordinate of `theta` to split when the slab `p x theta` fails with `why`: the one
    /// with the largest smear (|partial derivative| times width) of the quantity that failed
    /// (J for a jump, the aileron otherwise), `None` when the chain cannot be evaluated.
    pub fn split_coordinate(&self, bx: &LiftedBox, p: I, why: Failure) -> Option<usize> {
        let theta = &bx.theta;
        let chain = self.chain(bx, p).ok();
        let q = match (why, chain) {
            (Failure::Jump, Some(c)) => c.jump,
            (_, Some(c)) => c.da,
            (_, None) => {
                // The chain fails before the aileron (det A or the discriminant): smear det A.
                let n = self.coordinates.len() + 1;
                at_roll_rate(&bx.over, Dual::variable(p, n - 1, n))
                    .ok()?
                    .det_a
            }
        };
        (0..theta.len())
            .filter(|i| theta[*i].lo < theta[*i].hi)
            .max_by(|a, b| {
                let smear = |i: usize| q.g[i].mag() * theta[i].width();
                smear(*a).total_cmp(&smear(*b))
            })
    }
}

/// `q` (over the box `x`) tightened by its mean-value form around the centre `c`, where its
/// value is enclosed by `centre`: both enclose it.
fn tight(q: Dual, centre: I, x: &[I], c: &[f64]) -> Result<Dual, Failure> {
    let mut q = q;
    let mv = mean_value(&q, centre, x, c);
    q.v = q.v.intersect(mv).ok_or(Failure::Divergence)?;
    Ok(q)
}

/// The mean-value form of `q` (value and gradient over the box `x`) around the centre `c`,
/// where its value is enclosed by `centre`.
fn mean_value(q: &Dual, centre: I, x: &[I], c: &[f64]) -> I {
    (0..q.n).fold(centre, |acc, i| {
        if x[i].lo == x[i].hi {
            acc
        } else {
            acc + q.g[i] * (x[i] - I::point(c[i]))
        }
    })
}

/// Whether the trim condition at P0 = 0 is satisfied by delta_a = 0 for every aircraft of the
/// box, decided exactly: its delta_a^0 coefficient at P0 = 0, with the fixed data substituted,
/// is the zero polynomial in the uncertain parameters.
fn trim_at_rest_is_level(aircraft: &Aircraft, params: &[Param], delta_e_rad: f64) -> bool {
    let s = symbols();
    let free: Vec<_> = params.iter().map(|p| s.param(*p)).collect();
    let values: Vec<_> = crate::specialise::specialisation(aircraft, delta_e_rad)
        .into_iter()
        .filter(|(sym, _)| !free.contains(sym))
        .collect();
    parametric()
        .trim_condition()
        .coeff(s.delta_a, 0)
        .subs(s.p0, &crate::algebra::Poly::zero())
        .subs_values(&values)
        .is_zero()
}
