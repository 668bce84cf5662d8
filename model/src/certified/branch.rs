//! The first Hopf point on the primary branch of an aircraft whose aileron yaws, certified by
//! interval evaluation along the branch ([`first_hopf_on_branch`]) instead of through the Hopf
//! resultant in delta_a.
//!
//! With aileron yaw the exact path eliminates delta_a from `det(A)^6 Delta4` by a resultant with
//! the trim condition, a polynomial of degree 52 in P0 whose enclosure dividing out `det(A)^12`
//! destroys. The envelope and the clearance need only the first departure on the primary branch,
//! so here the branch itself is enclosed piece by piece in P0 (interval Newton on the trim
//! condition in delta_a: a unique trim of each roll rate of the piece lies in the enclosure),
//! and `det(A)^6 Delta4` is evaluated over each piece with the trim in that enclosure. Its
//! values there are well conditioned away from det A's roots.

use super::characteristic::hopf_in;
use super::compiled::Characteristic;
use super::isolate::{Bracket, Uncertified};
use super::mode::{AtP0, Da, Mode};
use super::rolls::Unconstrained;
use super::values::Values;
use crate::interval::I;

/// How many pieces [`first_hopf_on_branch`] evaluates before it gives up.
pub const PIECE_BUDGET: usize = 4000;

/// The first root on the primary branch (from `P0 = 0, delta_a = 0`) of the Hopf determinant
/// `det(A)^6 Delta4` of the data `v`, with P0 at most `p_end`: its certified bracket (relative
/// width at most `width`) and an enclosure of the branch's aileron there, or `None` when the
/// determinant keeps its sign over `[0, p_end]`, proven; with `at_end` the aileron the caller
/// expects the branch to have at `p_end`, which must lie in the branch's enclosure there (the
/// caller's point is on this branch).
///
/// Each piece `[a, b]` of roll rates is decided by interval evaluation: the branch's aileron over
/// it is enclosed by interval Newton on the trim condition (the Newton image strictly inside the
/// candidate interval proves exactly one trim there for every roll rate of the piece, so the
/// enclosures of consecutive pieces, each containing the previous end's, follow one continuous
/// branch), and the determinant's enclosure over the piece with the aileron in that enclosure
/// either excludes zero (no root in the piece) or it does not, when the piece is split. A root
/// is bracketed by a sign-definite cover of `[0, lo]` and a point `hi` of the opposite sign.
/// Where the branch turns in P0 (the trim condition's slope in delta_a vanishes) or a piece
/// cannot be decided within `PIECE_BUDGET` pieces, the answer is an [`Uncertified`] reason.
pub fn first_hopf_on_branch(
    v: &Values,
    p_end: f64,
    at_end: Option<f64>,
    width: f64,
) -> Result<Option<(Bracket, I)>, Uncertified> {
    let start = newton(v, I::point(0.0), I::new(-1e-9, 1e-9)).ok_or(Uncertified::Degenerate)?;
    let s0 = hopf_over(v, I::point(0.0), start)
        .sign()
        .ok_or(Uncertified::Sign)?;
    let (mut lo, mut e_lo) = (0.0_f64, start);
    let mut hi: Option<(f64, I)> = None;
    let mut h = p_end / 64.0;
    for _ in 0..PIECE_BUDGET {
        if let Some((b, e_b)) = hi {
            if b - lo <= width * b.abs() {
                return Ok(Some((bracket(lo, b), e_b)));
            }
            h = h.min((b - lo) / 2.0);
        } else if lo >= p_end {
            return match at_end {
                Some(da) if (da - e_lo.mid()).abs() > 1e-6 * (1.0 + da.abs()) => {
                    Err(Uncertified::Uncovered)
                }
                _ => Ok(None),
            };
        }
        let b = match hi {
            Some((b, _)) => (lo + h).min(b),
            None => (lo + h).min(p_end),
        };
        if h <= 4.0 * f64::EPSILON * lo.max(1e-3) {
            return Err(Uncertified::Budget);
        }
        let Some(piece) = piece(v, lo, b, e_lo) else {
            h /= 2.0;
            continue;
        };
        if hopf_over(v, I::new(lo, b), piece.over).sign() == Some(s0) {
            (lo, e_lo) = (b, piece.at_end);
            h *= 2.0;
            continue;
        }
        match hopf_over(v, I::point(b), piece.at_end).sign() {
            Some(s) if s != s0 => hi = Some((b, piece.at_end)),
            _ => {
                // The root may lie just beyond b: a point of the opposite sign there bounds it.
                if hi.is_none() {
                    hi = beyond(v, b, b + h, piece.at_end, s0);
                }
                h /= 2.0;
            }
        }
    }
    Err(Uncertified::Budget)
}

/// The point `c` (beyond `b`, where the branch's trim is `e_b`) and the branch's trim there,
/// when the determinant's sign at `c` is proven opposite to `s0`.
fn beyond(v: &Values, b: f64, c: f64, e_b: I, s0: f64) -> Option<(f64, I)> {
    let p = piece(v, b, c, e_b)?;
    let s = hopf_over(v, I::point(c), p.at_end).sign()?;
    (s != s0).then_some((c, p.at_end))
}

/// The bracket `[lo, hi]` with its midpoint as the value.
fn bracket(lo: f64, hi: f64) -> Bracket {
    Bracket {
        lo,
        hi,
        value: lo + (hi - lo) / 2.0,
    }
}

/// The branch over one piece of roll rates: its aileron's enclosure over the piece and at its
/// end.
struct Piece {
    over: I,
    at_end: I,
}

/// [`Piece`] over `[a, b]` from the branch's enclosure `e_a` at `a`, or `None` when interval
/// Newton does not prove a unique trim (the piece is too wide, or the branch turns in P0).
fn piece(v: &Values, a: f64, b: f64, e_a: I) -> Option<Piece> {
    // The f64 trim at b, from the branch's aileron at a.
    let guess = trim_near(v, b, e_a.mid())?;
    let (lo, hi) = (e_a.lo.min(guess), e_a.hi.max(guess));
    let pad = 4.0 * (hi - lo) + 1e-12 * (1.0 + lo.abs().max(hi.abs()));
    let candidate = I::new(lo - pad, hi + pad);
    let over = newton(v, I::new(a, b), candidate)?;
    let at_end = tighten(v, b, newton(v, I::point(b), over)?);
    Some(Piece { over, at_end })
}

/// The enclosure `e` of the trim at the roll rate `p` contracted by further interval Newton
/// steps while they prove it (each image holds the one trim in `e`).
fn tighten(v: &Values, p: f64, mut e: I) -> I {
    for _ in 0..4 {
        match newton(v, I::point(p), e) {
            Some(n) => e = n,
            None => break,
        }
    }
    e
}

/// The trim condition's coefficients in delta_a at the roll rates `x`.
fn trim_condition(v: &Values, x: I) -> Option<Vec<I>> {
    let mut m = AtP0(x);
    let u = Unconstrained::new(&mut m, &v.lifted).ok()?;
    let g = &u.trim_condition;
    Some(g.c[..g.len].to_vec())
}

/// The f64 trim (aileron) at the roll rate `p` nearest `da`: a few Newton steps on the trim
/// condition's midpoints, a guess for [`newton`] to prove.
fn trim_near(v: &Values, p: f64, da: f64) -> Option<f64> {
    let c: Vec<f64> = trim_condition(v, I::point(p))?
        .iter()
        .map(|k| k.mid())
        .collect();
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

/// One interval Newton step on the trim condition in delta_a over the roll rates `x` from the
/// candidate `d`: the image, when it lies strictly inside `d` (then every roll rate of `x` has
/// exactly one trim in `d`, and it lies in the image), else `None`.
fn newton(v: &Values, x: I, d: I) -> Option<I> {
    let c = trim_condition(v, x)?;
    let mid = I::point(d.mid());
    let value = c.iter().rev().fold(I::point(0.0), |acc, k| acc * mid + *k);
    let slope = c
        .iter()
        .enumerate()
        .skip(1)
        .rev()
        .fold(I::point(0.0), |acc, (k, ck)| {
            acc * d + *ck * I::point(k as f64)
        });
    let image = mid - value.checked_div(slope)?;
    (image.lo > d.lo && image.hi < d.hi).then_some(image)
}

/// An enclosure of `det(A)^6 Delta4` (the Hopf polynomial of the exact path before the aileron
/// is eliminated) over the roll rates `x` with the aileron anywhere in `da`.
fn hopf_over(v: &Values, x: I, da: I) -> I {
    let mut m = AtP0(x);
    let t = &v.lifted;
    let den = m.lifted(&t.det_a);
    let num: [Da<I>; 4] = std::array::from_fn(|i| {
        let n = m.lifted(&t.trim[i]);
        let at = n.c[..n.len]
            .iter()
            .rev()
            .fold(I::point(0.0), |acc, k| acc * da + *k);
        Da::new([at, I::point(0.0), I::point(0.0), I::point(0.0)])
    });
    hopf_in(&mut m, &Characteristic::get().c, &t.hopf().c, &num, &den)
        .map_or_else(|_| I::entire(), |r| r.delta4().0)
}
