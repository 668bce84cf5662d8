//! The walk along the primary branch in delta_a ([`round_turn`]), where the walk in P0 of
//! [`super::branch`] cannot go on: the branch turns in P0 (the trim condition's slope in
//! delta_a vanishes, `|d delta_a / d P0|` grows without bound, and the two trims of a roll rate
//! merge), which the F-16's branches do just before a divergence roll rate.
//!
//! Pieces are taken in delta_a instead: over a piece `S` of ailerons the branch's roll rate is
//! enclosed by parametric interval Newton on the trim condition in P0 (the image strictly inside
//! the candidate proves exactly one trim of each aileron of the piece there, and, the candidate
//! holding the previous end's enclosure, one continuous branch), with its first and second
//! derivatives in delta_a by the implicit function theorem. The determinant along the branch
//! is the same Taylor form as in P0, its ingredients evaluated at the roll rate as a number of
//! the walk's parameter ([`OnCurve`]). The turn itself is no obstacle in delta_a: there the
//! trim condition's slope in P0 is far from zero. The walk in delta_a fails where the branch
//! folds in delta_a (a jump point, where the slope in P0 vanishes), which the walk in P0 passes.

use super::branch::PIECE_BUDGET;
use super::branch::{bracket, derivative, det_with, trim_condition_in, BranchEnd, Det, Form};
use super::dense::{horner, Dense};
use super::isolate::{Bracket, Uncertified};
use super::mode::{AtP0, OverPiece};
use super::on_curve::OnCurve;
use super::slope::{Slope, Taylor2};
use super::values::Values;
use crate::interval::I;

/// What a walk along the branch answers: the first root's bracket in P0 and the branch's
/// aileron there, or none up to its end.
type Answer = Result<Option<(Bracket, I)>, Uncertified>;

/// The rest of [`super::first_root_on_branch`]'s walk from the roll rate `lo`, where the
/// branch's aileron lies in `e_lo` and the determinant `det` has kept the sign `s0` from
/// `P0 = 0`, walked in delta_a in the direction the branch takes there, up to `end`; its
/// answer. The first root's bracket in P0 is the branch's roll rates over a bracket of
/// ailerons narrowed by interval Newton on the determinant along the branch in delta_a, both of
/// relative width at most `width`.
///
/// Ends: the aileron bound of [`BranchEnd::Bound`] and [`BranchEnd::Before`] as in P0 (the
/// branch's aileron, here the walk's parameter, past it); a branch that comes back to the roll
/// rate of a [`BranchEnd::Before`] or [`BranchEnd::Fold`] is not covered
/// ([`Uncertified::Uncovered`]): the walk in P0 compares those roll rates with a branch
/// that has not turned.
pub(super) fn round_turn(
    v: &Values,
    det: Det,
    end: BranchEnd,
    width: f64,
    lo: f64,
    e_lo: I,
    s0: f64,
) -> Answer {
    let dir = direction(v, lo, e_lo).ok_or(Uncertified::Budget)?;
    // The link: one arc of the branch over all of e_lo through (lo, the branch's aileron), its
    // roll rates unique in the candidate, which holds lo. The walk starts at e_lo's end behind
    // the branch's aileron at lo (the part of the branch walked in P0 again, without a root).
    let (a, b) = if dir > 0.0 {
        (e_lo.lo, e_lo.hi)
    } else {
        (e_lo.hi, e_lo.lo)
    };
    let link = Piece::over(v, a, b, I::point(lo)).ok_or(Uncertified::Budget)?;
    let (mut s, mut p) = (a, contract(v, a, link.over.v));
    let mut hi: Option<(f64, I)> = None;
    let mut h = (1e-3_f64).max(2.0 * (b - a).abs());
    for _ in 0..PIECE_BUDGET {
        if let Some((t, _)) = hi {
            match narrowed(v, det, width, (s, p), t) {
                Narrowed::Answer(answer) => return Ok(Some(answer)),
                Narrowed::To(from, to) => {
                    ((s, p), hi) = (from, Some(to));
                    continue;
                }
                Narrowed::Not => h = h.min((t - s).abs() / 2.0),
            }
        } else if let Some(answer) = ended(end, s, p) {
            return answer;
        }
        let t = match hi {
            Some((t, _)) => s + dir * h.min((t - s).abs()),
            None => s + dir * h,
        };
        if h <= 4.0 * f64::EPSILON * s.abs().max(1e-3) {
            return Err(Uncertified::Budget);
        }
        let Some(piece) = Piece::over(v, s, t, p) else {
            h /= 2.0;
            continue;
        };
        let form = piece.det(det, v);
        let fit = form.fit();
        let fit = if fit.is_finite() && fit > 0.0 { fit } else { h };
        if form.range.sign() == Some(s0) {
            (s, p) = (t, piece.at_end);
            h = fit.clamp(h / 2.0, 2.0 * h);
            continue;
        }
        match det_at(det, v, t, piece.at_end).sign() {
            Some(sign) if sign != s0 => hi = Some((t, piece.at_end)),
            _ => h = fit.clamp(h / 16.0, h / 2.0),
        }
    }
    Err(Uncertified::Budget)
}

/// What one narrowing of a root's bracket of ailerons gives.
enum Narrowed {
    /// The root's bracket in P0 and its ailerons, both within the width asked.
    Answer((Bracket, I)),
    /// The narrowed bracket: its start and its end, each an aileron and the branch's roll
    /// rates there.
    To((f64, I), (f64, I)),
    /// No narrowing by half: the walk takes a smaller piece from the start.
    Not,
}

/// One narrowing of the bracket of ailerons from `(s, p)` (an aileron and the branch's roll
/// rates there) to `t` (where the determinant's sign is the opposite): the answer when
/// the branch's roll rates and the ailerons over the bracket are both within `width`
/// (relative), else the bracket narrowed by interval Newton on the determinant along the
/// branch (every root of the bracket stays in its Newton image) when that halves it at least.
fn narrowed(v: &Values, det: Det, width: f64, (s, p): (f64, I), t: f64) -> Narrowed {
    let Some(piece) = Piece::over(v, s, t, p) else {
        return Narrowed::Not;
    };
    let roll = piece.over.v;
    if roll.width() <= width * roll.mig() && piece.s.width() <= width * piece.s.mig().max(1e-3) {
        return Narrowed::Answer((bracket(roll.lo, roll.hi), piece.s));
    }
    let variable = Slope {
        v: piece.s,
        d: I::point(1.0),
    };
    let Some(slope) = det_with(det, OnCurve(piece.over.slope()), v, variable, false) else {
        return Narrowed::Not;
    };
    let at_c = det_at(det, v, piece.c, piece.at_c.v);
    let Some(x) = at_c
        .checked_div(slope.d)
        .and_then(|q| (I::point(piece.c) - q).intersect(piece.s))
    else {
        return Narrowed::Not;
    };
    if x.width() >= 0.5 * piece.s.width() {
        return Narrowed::Not;
    }
    let (from, to) = if t > s { (x.lo, x.hi) } else { (x.hi, x.lo) };
    Narrowed::To((from, contract(v, from, roll)), (to, contract(v, to, roll)))
}

/// The direction of the branch in delta_a as P0 grows at `lo` (the branch's aileron in
/// `e_lo`): the sign of `-g_P / g_delta_a`, or `None` where either may vanish.
fn direction(v: &Values, lo: f64, e_lo: I) -> Option<f64> {
    let g = trim_condition_in(OverPiece::<Slope>::over(I::point(lo)), v)?;
    let values: Vec<I> = g.iter().map(|c| c.v).collect();
    let in_p0: Vec<I> = g.iter().map(|c| c.d).collect();
    let slope = (-horner(&in_p0, e_lo)).checked_div(horner(&derivative(&values), e_lo))?;
    slope.sign()
}

/// The branch over one piece of ailerons from `a` to `b` (either order): the ailerons `s`,
/// their centre `c`, the branch's roll rate over the piece with its first and second
/// derivatives in delta_a, the roll rate at the centre with its derivative there, and the roll
/// rate at `b`.
struct Piece {
    s: I,
    c: f64,
    over: Taylor2,
    at_c: Slope,
    at_end: I,
}

impl Piece {
    /// The branch over the ailerons from `a` to `b`, its roll rate at `a` in `p_a`, or `None`
    /// when interval Newton in P0 does not prove a unique trim of each aileron of the piece
    /// in a candidate holding `p_a` (the piece is too wide, or the branch folds in delta_a).
    fn over(v: &Values, a: f64, b: f64, p_a: I) -> Option<Piece> {
        let (s, c) = (I::new(a.min(b), a.max(b)), a + (b - a) / 2.0);
        let (mut lo, mut hi) = (p_a.lo, p_a.hi);
        for at in [a, c, b] {
            let guess = roll_near(v, at, p_a.mid())?;
            (lo, hi) = (lo.min(guess), hi.max(guess));
        }
        let pad = 2.0 * (hi - lo) + 1e-12 * (1.0 + lo.abs().max(hi.abs()));
        let candidate = I::new(lo - pad, hi + pad);
        // Parametric interval Newton in P0: the trim condition at the candidate's midpoint
        // over the piece (a polynomial in delta_a shifted to the centre: tight over the piece),
        // over its slope in P0 over the candidate and the piece.
        let m = candidate.mid();
        let at_m = trim_condition_in(AtP0(I::point(m)), v)?;
        let g_x = trim_condition_in(OverPiece::<Slope>::over(candidate), v)?;
        let in_p0: Vec<I> = g_x.iter().map(|k| k.d).collect();
        let image = I::point(m) - centred(&at_m, s, c).checked_div(centred(&in_p0, s, c))?;
        if !(image.lo > candidate.lo && image.hi < candidate.hi) {
            return None;
        }
        let over = implicit(
            &trim_condition_in(OverPiece::<Taylor2>::over(image), v)?,
            s,
            image,
        )?;
        let at_c = contract(v, c, image);
        let g_c = trim_condition_in(OverPiece::<Slope>::over(at_c), v)?;
        let d = implicit_slope(&g_c, I::point(c))?;
        Some(Piece {
            s,
            c,
            over,
            at_c: Slope { v: at_c, d },
            at_end: contract(v, b, image),
        })
    }

    /// The determinant `det` over the piece along the branch (its Taylor form in delta_a) and
    /// at the piece's centre.
    fn det(&self, det: Det, v: &Values) -> Form {
        let entire = Slope {
            v: I::entire(),
            d: I::entire(),
        };
        let centre = Slope {
            v: I::point(self.c),
            d: I::point(1.0),
        };
        let at_c = det_with(det, OnCurve(self.at_c), v, centre, false).unwrap_or(entire);
        let variable = Taylor2 {
            v: self.s,
            d: I::point(1.0),
            dd: I::point(0.0),
        };
        let over = det_with(det, OnCurve(self.over), v, variable, false);
        let range = over.map_or_else(I::entire, |t| t.taylor(self.s, self.c, at_c.v, at_c.d));
        // No enclosure in P0 to split a piece by: the walk in delta_a halves its own pieces.
        Form {
            range,
            width: self.s.width(),
            at_c,
            over: None,
            per_trim: false,
        }
    }
}

/// The polynomial in delta_a with coefficients `k` over the ailerons `s`, shifted to `c`
/// first (its Taylor expansion there: tight over a piece around `c`).
fn centred(k: &[I], s: I, c: f64) -> I {
    let shifted = Dense::new(k.to_vec()).shift(I::point(c));
    horner(&shifted.0, s - I::point(c))
}

/// The branch's roll rate over a piece of ailerons `s` as a function of delta_a to second
/// order, from the trim condition `g` over its roll rates `p` (coefficients in delta_a with
/// their derivatives in P0; `p` holding one trim of each aileron of the piece):
/// `g(P(a), a) = 0` gives `P' = -g_a / g_P` and `P'' = -(g_aa + 2 g_aP P' + g_PP P'^2) / g_P`.
fn implicit(g: &[Taylor2], s: I, p: I) -> Option<Taylor2> {
    let part = |f: fn(&Taylor2) -> I| -> Vec<I> { g.iter().map(f).collect() };
    let (values, in_p0, in_p0_2) = (part(|k| k.v), part(|k| k.d), part(|k| k.dd));
    let g_p = horner(&in_p0, s);
    let g_a = horner(&derivative(&values), s);
    let d = (-g_a).checked_div(g_p)?;
    let g_aa = horner(&derivative(&derivative(&values)), s);
    let g_ap = horner(&derivative(&in_p0), s);
    let g_pp = horner(&in_p0_2, s);
    let two = I::point(2.0);
    let dd = (-(g_aa + two * g_ap * d + g_pp * d.sqr())).checked_div(g_p)?;
    Some(Taylor2 { v: p, d, dd })
}

/// The branch's slope in delta_a, `dP0/d delta_a = -g_a / g_P`, at the aileron `s` from the
/// trim condition `g` over the branch's roll rates there (with derivatives in P0).
fn implicit_slope(g: &[Slope], s: I) -> Option<I> {
    let values: Vec<I> = g.iter().map(|k| k.v).collect();
    let in_p0: Vec<I> = g.iter().map(|k| k.d).collect();
    (-horner(&derivative(&values), s)).checked_div(horner(&in_p0, s))
}

/// The f64 roll rate near `p` of the trim condition at the aileron `s`: a few Newton steps in
/// P0 on midpoints, a guess for interval Newton to prove.
fn roll_near(v: &Values, s: f64, mut p: f64) -> Option<f64> {
    for _ in 0..5 {
        let g = trim_condition_in(OverPiece::<Slope>::over(I::point(p)), v)?;
        let value: Vec<f64> = g.iter().map(|k| k.v.mid()).collect();
        let slope: Vec<f64> = g.iter().map(|k| k.d.mid()).collect();
        let at = |c: &[f64]| c.iter().rev().fold(0.0, |acc, k| acc * s + k);
        p -= at(&value) / at(&slope);
    }
    p.is_finite().then_some(p)
}

/// The enclosure `p` of the branch's roll rate at the aileron `s` contracted by interval
/// Newton steps in P0 (each image holds every trim of `p`).
fn contract(v: &Values, s: f64, mut p: I) -> I {
    for _ in 0..4 {
        let m = p.mid();
        let (Some(at_m), Some(g)) = (
            trim_condition_in(AtP0(I::point(m)), v),
            trim_condition_in(OverPiece::<Slope>::over(p), v),
        ) else {
            break;
        };
        let in_p0: Vec<I> = g.iter().map(|k| k.d).collect();
        let x = I::point(s);
        let image = horner(&at_m, x)
            .checked_div(horner(&in_p0, x))
            .map(|q| I::point(m) - q);
        match image.and_then(|n| n.intersect(p)) {
            Some(n) if n.width() < p.width() => p = n,
            _ => break,
        }
    }
    p
}

/// Whether the walk at the aileron `s`, the branch's roll rate there in `p`, is at its `end`.
fn ended(end: BranchEnd, s: f64, p: I) -> Option<Answer> {
    match end {
        BranchEnd::Bound(bound) | BranchEnd::Before { bound, .. } if s.abs() > bound => {
            Some(Ok(None))
        }
        BranchEnd::Before { p0, .. } | BranchEnd::Fold { p0, .. } if p.hi >= p0 => {
            Some(Err(Uncertified::Uncovered))
        }
        BranchEnd::Fold { delta_a, .. } if s.abs() > 2.0 * delta_a.abs() + 1.0 => {
            Some(Err(Uncertified::Uncovered))
        }
        _ => None,
    }
}

/// An enclosure of the determinant `det` at the aileron `s`, the branch's roll rate there in
/// `p`.
fn det_at(det: Det, v: &Values, s: f64, p: I) -> I {
    det_with(det, OnCurve(p), v, I::point(s), false).unwrap_or_else(I::entire)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::certified::num::Num;

    /// On the circle `g = P^2 + a^2 - 1` (coefficients in `a`: `P^2 - 1`, 0, 1, with their
    /// derivatives in P) the branch `P(a) = sqrt(1 - a^2)` has `P' = -a / P` and
    /// `P'' = -1 / P^3`, by hand; over `a` in [0.55, 0.65] and P in [0.75, 0.85] (which holds
    /// every `P(a)` there) both lie in the enclosures of the implicit function theorem, and
    /// `P'` at `a = 0.6` (P = 0.8) in the pointwise one.
    #[test]
    fn the_roll_rate_along_the_aileron_has_the_implicit_derivatives() {
        let (s, p) = (I::new(0.55, 0.65), I::new(0.75, 0.85));
        let k = |v: I, d: I, dd: f64| Taylor2 {
            v,
            d,
            dd: I::point(dd),
        };
        let zero = I::point(0.0);
        let g = [
            k(p.sqr() - I::point(1.0), I::point(2.0) * p, 2.0),
            k(zero, zero, 0.0),
            k(I::point(1.0), zero, 0.0),
        ];
        let t = implicit(&g, s, p).unwrap();
        for a in [0.55_f64, 0.6, 0.65] {
            let r = (1.0 - a * a).sqrt();
            let (d, dd) = (-a / r, -1.0 / r.powi(3));
            assert!(t.d.lo <= d && d <= t.d.hi, "{:?} vs {d}", t.d);
            assert!(t.dd.lo <= dd && dd <= t.dd.hi, "{:?} vs {dd}", t.dd);
        }
        let at = |v: I| Slope {
            v,
            d: I::point(2.0) * I::point(0.8),
        };
        let g_c = [
            at(I::point(0.8).sqr() - I::point(1.0)),
            Slope::constant(zero),
            Slope::constant(I::point(1.0)),
        ];
        let d = implicit_slope(&g_c, I::point(0.6)).unwrap();
        assert!(d.lo <= -0.75 && -0.75 <= d.hi && d.width() < 1e-12, "{d:?}");
    }
}
