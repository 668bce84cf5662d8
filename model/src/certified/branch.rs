//! The first Hopf point and the first jump on the primary branch of an aircraft whose aileron
//! yaws, certified by mean-value forms along the branch ([`first_root_on_branch`]) instead of
//! through the resultants in delta_a.
//!
//! With aileron yaw the exact path eliminates delta_a from `det(A)^6 Delta4` by a resultant with
//! the trim condition, a polynomial of degree 52 in P0 whose enclosure dividing out `det(A)^12`
//! destroys. The envelope and the clearance need only the first departure on the primary branch,
//! so here the branch itself is enclosed piece by piece in P0 (interval Newton on the trim
//! condition in delta_a: a unique trim of each roll rate of the piece lies in the enclosure),
//! and `det(A)^6 Delta4` (or, where det A is proven nonzero over the piece, `Delta4` of the trim
//! states themselves: the same sign, without the cancellation that forms the factor `det(A)^6`)
//! is enclosed over each piece along the branch by its value and
//! derivative at the piece's centre and its second derivative over the piece ([`Taylor2`]):
//! plain interval evaluation over a piece overestimates the range by orders of magnitude, the
//! mean-value form ([`Slope`]) by the derivative's overestimate times the piece's width (itself
//! of the order of the width: the form's error grows as the width squared), the Taylor form by
//! the second derivative's times the width squared (the error grows as its cube), so its
//! pieces are several times wider for the same decision. The jump determinant `det J5 det(A)^2` on
//! the trim (or `det J5` of the trim states, where det A is proven nonzero) is walked the same
//! way ([`Det::Jump`]): its first sign change on the branch is the critical jump, without
//! isolating the roots of the jump resultant on every other branch.

use super::characteristic::hopf_in;
use super::compiled::{Characteristic, Cleared, Parametric};
use super::dense::{horner, Dense2};
use super::elimination::Scalar;
use super::isolate::{Bracket, Uncertified};
use super::mode::{AtP0, Da, Mode, OverPiece};
use super::num::Num;
use super::rolls::Unconstrained;
use super::slope::{Slope, Taylor2};
use super::turn::round_turn;
use super::values::Values;
use crate::derivation::{TrimProducts, TRIM_DEGREE};
use crate::interval::I;

/// How many pieces [`first_hopf_on_branch`] evaluates before it gives up: a long walk (the
/// T-38's branch at 3,500 m, Mach 0.55 runs past 3.4 rad/s, in pieces of a few thousandths of a
/// rad/s) needs more than a thousand; a walk that cannot be decided ends sooner, its pieces
/// shrinking to nothing.
pub const PIECE_BUDGET: usize = 4000;

/// The half-width, relative to the value's magnitude, that [`Form::fit`] aims the next
/// piece's Taylor form at. The cube law it extrapolates by is optimistic where the branch
/// steepens (the F-104's Hopf walk at 0 m, Mach 0.7 towards 3.9 rad/s: a piece 1.4 times as
/// wide had a form about ten times as wide, not three), so at 0.5 about a third of the pieces
/// failed there and were decided again by halves (31 pieces and 10 halves); at 0.3 the next
/// piece is 0.84 times as wide and 25 pieces, none failing, reach the same end.
const FIT_MARGIN: f64 = 0.3;

/// Which determinant [`first_root_on_branch`] follows along the branch.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Det {
    /// The Hopf determinant `det(A)^6 Delta4` (its roots on the branch are Hopf points).
    Hopf,
    /// The jump determinant `det J5 det(A)^2` on the trim (its roots on the branch are folds
    /// in the aileron: jump points).
    Jump,
}

/// Where the walk along the primary branch ends.
#[derive(Clone, Copy, Debug)]
pub enum BranchEnd {
    /// At the fold of the critical jump, roll rate `p0` and aileron `delta_a` (rad), which must
    /// lie on the walked branch.
    Fold {
        /// The fold's roll rate, rad/s.
        p0: f64,
        /// The fold's aileron, rad.
        delta_a: f64,
    },
    /// Where the branch's aileron leaves `[-bound, bound]` (rad): proven outside at the end.
    Bound(f64),
    /// At the roll rate `p0` (rad/s; e.g. the lower end of the first divergence roll rate's
    /// bracket) or where the branch's aileron leaves `[-bound, bound]` (rad), whichever comes
    /// first.
    Before {
        /// The roll rate the walk stops at, rad/s.
        p0: f64,
        /// The aileron bound, rad.
        bound: f64,
    },
}

/// [`first_root_on_branch`] of the Hopf determinant.
pub fn first_hopf_on_branch(
    v: &Values,
    end: BranchEnd,
    width: f64,
) -> Result<Option<(Bracket, I)>, Uncertified> {
    first_root_on_branch(v, Det::Hopf, end, width)
}

/// The first root on the primary branch (from `P0 = 0, delta_a = 0`) of the determinant `det`
/// of the data `v` before the branch's `end`: its certified bracket (relative
/// width at most `width`) and an enclosure of the branch's aileron there, or `None` when the
/// determinant keeps its sign up to the end, proven. A [`BranchEnd::Fold`] must lie in the
/// branch's enclosure at its roll rate (the caller's fold is on this branch); past a
/// [`BranchEnd::Bound`] the walk may find a root beyond the bound, which the caller places
/// (so may it before a [`BranchEnd::Before`]'s bound, not beyond its roll rate).
///
/// Each piece `[a, b]` of roll rates is decided by Taylor forms in P0 (numbers carrying their
/// first and second derivatives in P0, enclosed over the piece): the branch's aileron over it
/// is enclosed by parametric interval Newton on the trim condition in delta_a (the Newton image
/// strictly inside the candidate interval proves exactly one trim there for every roll rate of
/// the piece, so the enclosures of consecutive pieces, each containing the previous end's,
/// follow one continuous branch), its first and second derivatives in P0 by the implicit
/// function theorem over the piece, and the determinant over the piece by its value and
/// derivative along the branch at the piece's centre plus its enclosed second derivative over
/// the piece times half the squared offsets from the centre: either that excludes zero (no
/// root in the piece) or the next piece is smaller. A root is bracketed by a
/// sign-definite cover of `[0, lo]` and a point `hi` of the opposite sign, and the bracket is
/// narrowed by interval Newton on the determinant along the branch (every root in the bracket
/// stays in its Newton image). Where the branch turns in P0 (the trim condition's slope in
/// delta_a vanishes: pieces in P0 shrink to nothing) the walk goes on in delta_a
/// (`certified/turn.rs`); where a piece cannot be decided within `PIECE_BUDGET` pieces, the answer
/// is an [`Uncertified`] reason.
pub fn first_root_on_branch(
    v: &Values,
    det: Det,
    end: BranchEnd,
    width: f64,
) -> Result<Option<(Bracket, I)>, Uncertified> {
    let p_end = match end {
        BranchEnd::Fold { p0, .. } | BranchEnd::Before { p0, .. } => p0,
        BranchEnd::Bound(_) => f64::INFINITY,
    };
    let g0 = trim_condition(v, 0.0).ok_or(Uncertified::Degenerate)?;
    let start = newton(&g0, I::new(-1e-9, 1e-9)).ok_or(Uncertified::Degenerate)?;
    let s0 = det_at(det, v, 0.0, start).sign().ok_or(Uncertified::Sign)?;
    let (mut lo, mut e_lo) = (0.0_f64, start);
    let mut hi: Option<(f64, I)> = None;
    let mut h = p_end.min(1.0) / 16.0;
    // Below a width at which a piece failed (the branch's enclosure or the determinant's sign),
    // a bound on the next pieces' that grows again with each piece decided: the forms' growth
    // with the width steepens where the branch does, beyond what `Form::fit` foresees.
    let mut cap = f64::INFINITY;
    for _ in 0..PIECE_BUDGET {
        if let Some((b, e_b)) = hi {
            if b - lo <= width * b.abs() {
                return Ok(Some((bracket(lo, b), e_b)));
            }
            if let Some((l, u, over)) = newton_det(det, v, lo, b, e_lo) {
                if u - l < 0.5 * (b - lo) {
                    let g = trim_condition(v, l).ok_or(Uncertified::Degenerate)?;
                    (lo, e_lo, hi) = (l, contract(&g, over), Some((u, over)));
                    continue;
                }
            }
            h = h.min((b - lo) / 2.0);
        } else if let Some(answer) = ended(end, lo, e_lo) {
            return answer;
        }
        let b = match hi {
            Some((b, _)) => (lo + h).min(b),
            None => (lo + h).min(p_end),
        };
        if h <= 4.0 * f64::EPSILON * lo.max(1e-3) {
            // Pieces in P0 cannot pass here (the branch turns in P0): on in delta_a.
            return match hi {
                None => round_turn(v, det, end, width, lo, e_lo, s0),
                Some(_) => Err(Uncertified::Budget),
            };
        }
        let Some(piece) = Piece::over(v, lo, b, e_lo) else {
            (h, cap) = (h / 2.0, 0.75 * (b - lo));
            continue;
        };
        let form = piece.det(det, v);
        let fit = form.fit();
        let fit = if fit.is_finite() && fit > 0.0 { fit } else { h };
        if form.range.sign() == Some(s0) {
            (lo, e_lo) = (b, piece.at_end);
            h = fit.clamp(h / 2.0, 2.0 * h).min(1.0).min(cap);
            cap *= 1.25;
            continue;
        }
        if hi.is_none() {
            if let Some((half, fit)) = first_half(det, v, &piece, &form, s0) {
                (lo, e_lo, cap) = (half.x.hi, half.at_end, 0.75 * (b - lo));
                h = fit.clamp(h / 4.0, h / 2.0);
                continue;
            }
        }
        match det_at(det, v, b, piece.at_end).sign() {
            Some(s) if s != s0 => hi = Some((b, piece.at_end)),
            _ => {
                // The root may lie just beyond b: a point of the opposite sign there bounds it.
                if hi.is_none() && b < p_end {
                    hi = beyond(det, v, b, (b + h).min(p_end), piece.at_end, s0);
                }
                (h, cap) = (fit.clamp(h / 16.0, h / 2.0), 0.75 * (b - lo));
            }
        }
    }
    Err(Uncertified::Budget)
}

/// The first half of `piece` and the width its form fits, when the determinant `det`'s sign
/// over it is proven `s0` by the second derivative of the whole piece's `form` (a quarter of
/// its second-order term, for the new value at the half's centre alone): a piece the walk
/// could not decide, because its width outgrew the forms, costs a third of a new piece's
/// evaluation more instead of a whole one.
fn first_half(det: Det, v: &Values, piece: &Piece, form: &Form, s0: f64) -> Option<(Piece, f64)> {
    let half = piece.first_half(v)?;
    let f = half.form(det, v, form.over, form.per_trim);
    let fit = f.fit();
    (f.range.sign() == Some(s0) && fit.is_finite() && fit > 0.0).then_some((half, fit))
}

/// Whether the walk at `lo`, the branch's aileron there in `e_lo`, is at its `end`: then no
/// root (the fold's aileron in `e_lo`) or [`Uncertified::Uncovered`] (the fold is on another
/// branch).
fn ended(end: BranchEnd, lo: f64, e_lo: I) -> Option<Result<Option<(Bracket, I)>, Uncertified>> {
    match end {
        BranchEnd::Fold { p0, delta_a } if lo >= p0 => Some(
            if (delta_a - e_lo.mid()).abs() > 1e-6 * (1.0 + delta_a.abs()) {
                Err(Uncertified::Uncovered)
            } else {
                Ok(None)
            },
        ),
        BranchEnd::Bound(bound) if e_lo.lo > bound || e_lo.hi < -bound => Some(Ok(None)),
        BranchEnd::Before { p0, bound } if lo >= p0 || e_lo.lo > bound || e_lo.hi < -bound => {
            Some(Ok(None))
        }
        _ => None,
    }
}

/// The point `c` (beyond `b`, where the branch's trim is `e_b`) and the branch's trim there,
/// when the determinant's sign at `c` is proven opposite to `s0`.
fn beyond(det: Det, v: &Values, b: f64, c: f64, e_b: I, s0: f64) -> Option<(f64, I)> {
    let p = Piece::over(v, b, c, e_b)?;
    let s = det_at(det, v, c, p.at_end).sign()?;
    (s != s0).then_some((c, p.at_end))
}

/// One interval Newton step on the determinant along the branch over `[lo, hi]` (the branch's
/// trim at `lo` in `e_lo`): the bracket that holds every root of `[lo, hi]`, and the branch's
/// aileron over `[lo, hi]`; `None` when the derivative's enclosure may vanish.
fn newton_det(det: Det, v: &Values, lo: f64, hi: f64, e_lo: I) -> Option<(f64, f64, I)> {
    let p = Piece::over(v, lo, hi, e_lo)?;
    let per_trim = per_trim_over(v, p.x);
    let slope = det_with(
        det,
        OverPiece::<Slope>::over(p.x),
        v,
        p.over.slope(),
        per_trim,
    )?;
    let at_c = det_with(det, AtP0(I::point(p.c)), v, p.at_c.v, per_trim)?;
    let image = I::point(p.c) - at_c.checked_div(slope.d)?;
    let x = image.intersect(p.x)?;
    Some((x.lo, x.hi, p.over.v))
}

/// The bracket `[lo, hi]` with its midpoint as the value.
pub(super) fn bracket(lo: f64, hi: f64) -> Bracket {
    Bracket {
        lo,
        hi,
        value: lo + (hi - lo) / 2.0,
    }
}

/// The branch over one piece `x` of roll rates: its aileron over the piece with its first and
/// second derivatives in P0, the aileron's enclosure at the piece's centre `c` with its slope
/// there, and its enclosure at the piece's end.
struct Piece {
    x: I,
    c: f64,
    over: Taylor2,
    at_c: Slope,
    at_end: I,
}

/// The determinant over a piece along the branch: its Taylor form over the piece of width
/// `width`, its value and derivative at the piece's centre, and its enclosure over the piece
/// (`over`, evaluated per trim state or not as `per_trim`) that the form takes its second
/// derivative from.
pub(super) struct Form {
    pub(super) range: I,
    pub(super) width: f64,
    pub(super) at_c: Slope,
    pub(super) over: Option<Taylor2>,
    pub(super) per_trim: bool,
}

impl Form {
    /// The width of the piece the Taylor form would decide here with a margin (its half-width
    /// at [`FIT_MARGIN`] times the value's magnitude), taking the half-width to grow as the
    /// cube of the piece's width (the second derivative's overestimate grows with the piece).
    pub(super) fn fit(&self) -> f64 {
        let half = (self.range.hi - self.at_c.v.mid()).max(self.at_c.v.mid() - self.range.lo);
        self.width * (FIT_MARGIN * self.at_c.v.mig() / half).cbrt()
    }
}

impl Piece {
    /// The branch over `[a, b]` from its enclosure `e_a` at `a`, or `None` when interval Newton
    /// does not prove a unique trim (the piece is too wide, or the branch turns in P0).
    fn over(v: &Values, a: f64, b: f64, e_a: I) -> Option<Piece> {
        let (x, c) = (I::new(a, b), a + (b - a) / 2.0);
        let g_c_slope = trim_condition_in(OverPiece::<Slope>::over(I::point(c)), v)?;
        let g_c: Vec<I> = g_c_slope.iter().map(|s| s.v).collect();
        let g_b = trim_condition(v, b)?;
        let g_x = trim_condition_in(OverPiece::<Taylor2>::over(x), v)?;
        // The f64 trims at c and b, from the branch's aileron at a, for the candidate.
        let (mut lo, mut hi) = (e_a.lo, e_a.hi);
        for g in [&g_c, &g_b] {
            let guess = root_near(g, e_a.mid())?;
            (lo, hi) = (lo.min(guess), hi.max(guess));
        }
        let pad = 2.0 * (hi - lo) + 1e-12 * (1.0 + lo.abs().max(hi.abs()));
        let image = branch_image(&g_c_slope, &g_x, (x, c), I::new(lo - pad, hi + pad))?;
        let at_c = contract(&g_c, image);
        Some(Piece {
            x,
            c,
            over: implicit(&g_x, image)?,
            at_c: Slope {
                v: at_c,
                d: implicit_slope(&g_c_slope, at_c)?,
            },
            at_end: contract(&g_b, image),
        })
    }

    /// The determinant `det` over the piece along the branch (its Taylor form) and at the
    /// piece's centre.
    fn det(&self, det: Det, v: &Values) -> Form {
        let per_trim = per_trim_over(v, self.x);
        let over = det_with(
            det,
            OverPiece::<Taylor2>::over(self.x),
            v,
            self.over,
            per_trim,
        );
        self.form(det, v, over, per_trim)
    }

    /// The Taylor form of the determinant `det` over the piece from its enclosure `over` over
    /// the piece or one holding it (evaluated per trim state or not as `per_trim`), and its
    /// value and derivative at the piece's centre.
    fn form(&self, det: Det, v: &Values, over: Option<Taylor2>, per_trim: bool) -> Form {
        let point = OverPiece::<Slope>::over(I::point(self.c));
        let entire = Slope {
            v: I::entire(),
            d: I::entire(),
        };
        let at_c = det_with(det, point, v, self.at_c, per_trim).unwrap_or(entire);
        let range = over.map_or_else(I::entire, |t| t.taylor(self.x, self.c, at_c.v, at_c.d));
        Form {
            range,
            width: self.x.width(),
            at_c,
            over,
            per_trim,
        }
    }

    /// The piece's first half, its branch taken from the piece's own enclosure (interval
    /// Newton's image over the piece holds the one trim of each roll rate of the half too):
    /// only the trims at the half's centre and end are new.
    fn first_half(&self, v: &Values) -> Option<Piece> {
        let (a, b) = (self.x.lo, self.c);
        let c = a + (b - a) / 2.0;
        let g_c_slope = trim_condition_in(OverPiece::<Slope>::over(I::point(c)), v)?;
        let g_c: Vec<I> = g_c_slope.iter().map(|s| s.v).collect();
        let at_c = contract(&g_c, self.over.v);
        Some(Piece {
            x: I::new(a, b),
            c,
            over: self.over,
            at_c: Slope {
                v: at_c,
                d: implicit_slope(&g_c_slope, at_c)?,
            },
            at_end: contract(&trim_condition(v, b)?, self.over.v),
        })
    }
}

/// The enclosure of the branch's aileron over the piece `x` (centre `c`) by parametric
/// interval Newton from `candidate`: the trim condition at the candidate's midpoint over the
/// piece by its Taylor form in P0 (`g_c` at the centre, `g_x` over the piece), its image
/// strictly inside the candidate. An image that leaves the candidate gives a wider one, its
/// hull with the image inflated by a tenth (epsilon-inflation), twice at most: the
/// polynomials are evaluated once, so a retry costs a few Horner steps, where a smaller piece
/// would cost new ones.
fn branch_image(g_c: &[Slope], g_x: &[Taylor2], (x, c): (I, f64), candidate: I) -> Option<I> {
    let values: Vec<I> = g_x.iter().map(|s| s.v).collect();
    let mut candidate = candidate;
    for _ in 0..3 {
        let m = I::point(candidate.mid());
        let at_m = horner(g_c, Slope::constant(m));
        let value = horner(g_x, Taylor2::constant(m)).taylor(x, c, at_m.v, at_m.d);
        let image = m - value.checked_div(in_aileron_slope(&values, candidate))?;
        if image.lo > candidate.lo && image.hi < candidate.hi {
            return Some(image);
        }
        let hull = candidate.hull(image);
        let pad = 0.1 * hull.width();
        candidate = I::new(hull.lo - pad, hull.hi + pad);
    }
    None
}

/// The branch's aileron over a piece as a function of P0 to second order, from the trim
/// condition `g` over the piece (coefficients in delta_a) and the aileron's enclosure `da`
/// over it (holding one trim of each roll rate): `g(P0, a(P0)) = 0` gives
/// `a' = -g_P / g_a` and `a'' = -(g_PP + 2 g_Pa a' + g_aa a'^2) / g_a`, every partial
/// derivative enclosed over the piece and `da`.
fn implicit(g: &[Taylor2], da: I) -> Option<Taylor2> {
    let values: Vec<I> = g.iter().map(|s| s.v).collect();
    let g_a = in_aileron_slope(&values, da);
    let at = horner(g, Taylor2::constant(da));
    let d = (-at.d).checked_div(g_a)?;
    let in_a: Vec<Taylor2> = derivative(g);
    let g_pa = horner(&in_a, Taylor2::constant(da)).d;
    let g_aa = in_aileron_slope(&derivative(&values), da);
    let two = I::point(2.0);
    let dd = (-(at.dd + two * g_pa * d + g_aa * d.sqr())).checked_div(g_a)?;
    Some(Taylor2 { v: da, d, dd })
}

/// The branch's slope in P0 at one roll rate, `-g_P / g_a`, from the trim condition `g` there
/// with its derivative in P0 and the aileron's enclosure `da`.
fn implicit_slope(g: &[Slope], da: I) -> Option<I> {
    let values: Vec<I> = g.iter().map(|s| s.v).collect();
    let at = horner(g, Slope::constant(da));
    (-at.d).checked_div(in_aileron_slope(&values, da))
}

/// The derivative in delta_a of the polynomial `c`, as coefficients.
pub(super) fn derivative<T: Num>(c: &[T]) -> Vec<T> {
    c.iter()
        .enumerate()
        .skip(1)
        .map(|(k, ck)| T::constant(I::point(k as f64)) * *ck)
        .collect()
}

/// The trim condition's coefficients in delta_a in the ring `m`.
pub(super) fn trim_condition_in<M, T>(mut m: M, v: &Values) -> Option<Vec<T>>
where
    M: Mode<Num = I, Value = Da<T>, Coef = Scalar<T>>,
    T: Num,
{
    let u = Unconstrained::new(&mut m, &v.lifted).ok()?;
    let g = &u.trim_condition;
    Some(g.c[..g.len].to_vec())
}

/// The trim condition's coefficients in delta_a at the roll rate `p`.
fn trim_condition(v: &Values, p: f64) -> Option<Vec<I>> {
    trim_condition_in(AtP0(I::point(p)), v)
}

/// The f64 root nearest `da` of the trim condition `c` (at one roll rate): a few Newton steps
/// on its midpoints, a guess for interval Newton to prove.
fn root_near(c: &[I], da: f64) -> Option<f64> {
    let c: Vec<f64> = c.iter().map(|k| k.mid()).collect();
    let mut x = da;
    for _ in 0..6 {
        let value = c.iter().rev().fold(0.0, |acc, k| acc * x + k);
        let slope = c
            .iter()
            .enumerate()
            .skip(1)
            .rev()
            .fold(0.0, |acc, (k, ck)| acc * x + ck * k as f64);
        x -= value / slope;
    }
    x.is_finite().then_some(x)
}

/// The derivative in delta_a of the polynomial `c` over the ailerons `d`.
fn in_aileron_slope(c: &[I], d: I) -> I {
    c.iter()
        .enumerate()
        .skip(1)
        .rev()
        .fold(I::point(0.0), |acc, (k, ck)| {
            acc * d + *ck * I::point(k as f64)
        })
}

/// The interval Newton image of `d` for the trim condition `c` at one roll rate, or `None`
/// when the slope may vanish.
fn newton_image(c: &[I], d: I) -> Option<I> {
    let mid = I::point(d.mid());
    Some(mid - horner(c, mid).checked_div(in_aileron_slope(c, d))?)
}

/// One interval Newton step on the trim condition `c` (at one roll rate) from the candidate
/// `d`: the image, when it lies strictly inside `d` (then exactly one trim lies in `d`, and in
/// the image), else `None`.
fn newton(c: &[I], d: I) -> Option<I> {
    let image = newton_image(c, d)?;
    (image.lo > d.lo && image.hi < d.hi).then_some(image)
}

/// The enclosure `d` of a trim of the trim condition `c` (at one roll rate) contracted by
/// interval Newton steps (each image holds every root in `d`).
fn contract(c: &[I], mut d: I) -> I {
    for _ in 0..4 {
        match newton_image(c, d).and_then(|n| n.intersect(d)) {
            Some(n) if n.width() < d.width() => d = n,
            _ => break,
        }
    }
    d
}

/// An enclosure of `det(A)^6 Delta4` (the Hopf polynomial of the exact path before the aileron
/// is eliminated) in the ring `m` with the aileron `da`, or with `per_trim` of `Delta4` itself
/// (the same sign and roots where det A does not vanish), or `None` where it cannot be formed.
///
/// On the branch `det(A)^6 Delta4` holds the factor `det(A)^6` only through cancellation among
/// its cleared terms (products of the trim's numerators), so an enclosure over a piece is
/// overestimated relative to its value by about `det(A)^-6`: towards the F-104's jump at
/// 2.05 rad/s, where det A is a quarter of its value at `P0 = 0`, its Taylor form decides only
/// pieces a few thousandths of a rad/s wide. `Delta4` of the trim states themselves
/// (`num / det A`, divided over the piece: den `= 1`) has no such cancellation.
fn hopf_with<M, T>(mut m: M, v: &Values, da: T, per_trim: bool) -> Option<T>
where
    M: Mode<Num = I, Value = Da<T>, Coef = Scalar<T>>,
    T: Num,
{
    let (num, den) = trim_states(&mut m, v, da, per_trim)?;
    let r = hopf_in(
        &mut m,
        &Characteristic::get().c,
        &v.lifted.hopf().c,
        &num,
        &den,
    )
    .ok()?;
    Some(r.delta4().0)
}

/// The trim at the aileron `da` as numerators (constants in delta_a) over their denominator
/// det A, or with `per_trim` the trim states themselves (the numerators divided by det A, the
/// denominator 1); `None` where det A may vanish.
fn trim_states<M, T>(m: &mut M, v: &Values, da: T, per_trim: bool) -> Option<([Da<T>; 4], Da<T>)>
where
    M: Mode<Num = I, Value = Da<T>, Coef = Scalar<T>>,
    T: Num,
{
    let t = &v.lifted;
    let zero = T::constant(I::point(0.0));
    let mut den = m.lifted(&t.det_a);
    let mut trims: [T; 4] = std::array::from_fn(|i| m.lifted(&t.trim[i]).at(da));
    if per_trim {
        let d = M::univariate(&den).ok()?.0;
        for x in &mut trims {
            *x = x.div(d)?;
        }
        den = Da::new([T::constant(I::point(1.0)), zero, zero, zero]);
    }
    Some((trims.map(|x| Da::new([x, zero, zero, zero])), den))
}

/// Whether the determinants are evaluated per trim state over the roll rates `x`
/// ([`hopf_with`], [`jump_with`]): where det A, the trims' denominator, is proven nonzero over `x`.
fn per_trim_over(v: &Values, x: I) -> bool {
    let det_a = v.lifted.det_a.0.first().map_or(&[][..], |c| &c.0[..]);
    !horner(det_a, x).contains_zero()
}

/// An enclosure of `det J5 det(A)^2` on the trim in the ring `m` with the aileron `da`, or with
/// `per_trim` of `det J5` of the trim states themselves (the same sign and roots where det A
/// does not vanish: the power is even), or `None` where it cannot be formed.
///
/// As the Hopf determinant's ([`hopf_with`]), the cleared form holds `det(A)^2` only through
/// cancellation among products of the trim's numerators: next to a divergence roll rate its
/// enclosure over a bracket is too wide for interval Newton to contract it.
fn jump_with<M, T>(mut m: M, v: &Values, da: T, per_trim: bool) -> Option<T>
where
    M: Mode<Num = I, Value = Da<T>, Coef = Scalar<T>>,
    T: Num,
{
    if !per_trim {
        let u = Unconstrained::new(&mut m, &v.lifted).ok()?;
        return Some(u.on_trim(&mut m, &v.lifted, true).at(da));
    }
    let c = &Parametric::get().det_j5;
    Some(of_trim_states(&mut m, v, da, c, &v.lifted.det_j5)?.at(da))
}

/// The grouped result `c` (its group coefficients lifted as `lifted`) of the trim states
/// themselves at the aileron `da` (the numerators divided by det A, [`trim_states`]), in the
/// ring `m`; `None` where det A may vanish.
pub(super) fn of_trim_states<M, T>(
    m: &mut M,
    v: &Values,
    da: T,
    c: &Cleared,
    lifted: &[Dense2<I>],
) -> Option<Da<T>>
where
    M: Mode<Num = I, Value = Da<T>, Coef = Scalar<T>>,
    T: Num,
{
    let (num, den) = trim_states(m, v, da, true)?;
    let mut products = TrimProducts::new(m, &den, TRIM_DEGREE);
    Some(m.clear_with(c, lifted, &num, &den, &mut products))
}

/// An enclosure of the determinant `det` in the ring `m` with the aileron `da` (per trim state
/// or not as `per_trim`, [`hopf_with`], [`jump_with`]: the same choice over a piece and at its
/// centre, so that a form of the two encloses one function).
pub(super) fn det_with<M, T>(det: Det, m: M, v: &Values, da: T, per_trim: bool) -> Option<T>
where
    M: Mode<Num = I, Value = Da<T>, Coef = Scalar<T>>,
    T: Num,
{
    match det {
        Det::Hopf => hopf_with(m, v, da, per_trim),
        Det::Jump => jump_with(m, v, da, per_trim),
    }
}

/// An enclosure of the determinant `det` at the roll rate `p` with the aileron anywhere in
/// `da`.
fn det_at(det: Det, v: &Values, p: f64, da: I) -> I {
    let per_trim = per_trim_over(v, I::point(p));
    det_with(det, AtP0(I::point(p)), v, da, per_trim).unwrap_or_else(I::entire)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::aircraft::{Aircraft, Param};
    use num_rational::BigRational;

    /// The Hopf determinant per trim state is the cleared one divided by `det(A)^6` (the
    /// trims' denominator to the power the exact path's `det(A)^6 Delta4` names): the same
    /// sign and roots wherever det A does not vanish.
    #[test]
    fn the_hopf_determinant_per_trim_is_the_cleared_one_over_det_a_to_the_sixth() {
        per_trim_is_cleared_over_a_power_of_det_a(Det::Hopf, 6);
    }

    /// The jump determinant per trim state is the cleared one divided by `det(A)^2`: the same
    /// sign and roots wherever det A does not vanish.
    #[test]
    fn the_jump_determinant_per_trim_is_the_cleared_one_over_det_a_squared() {
        per_trim_is_cleared_over_a_power_of_det_a(Det::Jump, 2);
    }

    /// The determinant `det` per trim state times `det(A)^power` is the cleared one (nonzero),
    /// on aircraft B with aileron yaw (n_delta_a = -1.5) at delta_e = 2 deg, on its branch
    /// below its first divergence roll rate, det A evaluated from its own lifted polynomial.
    fn per_trim_is_cleared_over_a_power_of_det_a(det: Det, power: i32) {
        let ac = Aircraft::b().with(Param::NDeltaA, BigRational::new((-3).into(), 2.into()));
        let v = Values::of(&ac, 2f64.to_radians(), 0.0);
        let det_a = &v.lifted.det_a.0[0].0;
        for p in [0.3, 0.9, 1.4] {
            let g = trim_condition(&v, p).unwrap();
            let guess = root_near(&g, 0.0).unwrap();
            let da = contract(&g, I::new(guess - 1e-9, guess + 1e-9));
            let cleared = det_with(det, AtP0(I::point(p)), &v, da, false).unwrap();
            let per_trim = det_with(det, AtP0(I::point(p)), &v, da, true).unwrap();
            let scale = horner(det_a, I::point(p)).mid().powi(power);
            let (x, y) = (cleared.mid(), per_trim.mid() * scale);
            assert!(per_trim_over(&v, I::point(p)), "{det:?}, P0 = {p}");
            assert!(
                x != 0.0 && (x - y).abs() <= 1e-8 * x.abs(),
                "{det:?}, P0 = {p}: {x} vs {y}"
            );
        }
    }
}
