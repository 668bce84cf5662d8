//! The roots of the trim condition next to a fold of the branch that are the fold's own: an
//! interval of roll rates around a critical jump in which the trim condition at the fold's
//! exact aileron has no root but the fold itself, so that the jump's landings are sought
//! outside it ([`fold_intervals`]).
//!
//! At a fold `(P*, delta_a*)` of the branch the trim condition `G` vanishes with its slope in
//! P0 (on the trim, `det J5` is `G_P0 / det A` where `G` vanishes, and a jump is proven apart
//! from det A's roots), so `P*` is a double root of `G(., delta_a*)`. An aileron rounded
//! past the fold by 1e-13 rad splits that double root into two simple roots some 1e-6 rad/s
//! either side, which no isolation can tell from landings. If `G_P0P0` keeps one sign over
//! `X x D` (`X` a roll-rate interval holding `P*`, `D` an aileron interval holding
//! `delta_a*`), then for every aileron of `D` the trim condition is strictly convex (or
//! concave) in P0 over `X` and has at most two roots there, counted with multiplicity: at
//! `delta_a*`, the fold's double root alone. Every other root at the fold's aileron (every
//! landing) lies outside `X`, whatever the split at a rounded aileron.

use super::dense::{IPoly, IPoly2};
use super::isolate::Bracket;
use crate::interval::I;

/// Intervals of roll rates `[lo, hi]` around the fold of the bracket `fold` (which holds the
/// fold's roll rate `P*`), each proven to hold no root of the trim condition `g` at the fold's
/// exact aileron but `P*` itself ([`one_curvature`]), each at least `min_half` either side of
/// the bracket's value, widening; empty where no proof holds.
///
/// `near` encloses the branch's aileron at some roll rate of `fold` (the walk's enclosure
/// there), `da` is the aileron the caller evaluates the landings at. The fold's aileron is
/// enclosed from both ([`fold_aileron`]); the first interval is sized from the split of the
/// fold's double root at `da` (`G(P*, da) / G_P0P0` estimates its half-square) to hold the
/// split pair with room, so that its ends have certain signs.
pub fn fold_intervals(
    g: &IPoly2,
    value: &dyn Fn(f64, f64) -> I,
    fold: Bracket,
    near: I,
    da: f64,
    min_half: f64,
) -> Vec<(f64, f64)> {
    let p = I::new(fold.lo, fold.hi);
    let Some(d) = fold_aileron(g, value, p, near.hull(I::point(da))) else {
        return Vec::new();
    };
    // A root of G's slope at the fold: its enclosure must allow zero there.
    let at_d = g.at_aileron(d);
    if !at_d.derivative().eval(p).contains_zero() {
        return Vec::new();
    }
    let at_da = g.at_aileron(I::point(da));
    let c = I::point(fold.value);
    let curvature = at_da.derivative().derivative().eval(c).mid();
    let split = (2.0 * value(fold.value, da).mid() / curvature).abs().sqrt();
    let first = if split.is_finite() {
        min_half.max(4.0 * split)
    } else {
        min_half
    };
    let mut out = Vec::new();
    for k in 0..3 {
        let r = first * 4f64.powi(k);
        let x = (fold.value - r, fold.value + r);
        let holds = x.0 <= fold.lo && fold.hi <= x.1;
        if !(holds && one_curvature(&at_d, I::new(x.0, x.1))) {
            break;
        }
        out.push(x);
    }
    out
}

/// An enclosure of the aileron of every trim with a roll rate in `p` within a candidate around
/// `near` (one parametric interval Newton step on the trim condition `g` in delta_a, its image
/// strictly inside the candidate), or `None`. The trim condition over `p` at the candidate's
/// centre is its tight enclosure `value` at `p`'s centre plus its slope in P0 over `p` (from
/// `g`) times the offsets: `g`'s coefficients alone, evaluated over `p`, are too wide.
///
/// With `near` holding the branch's aileron at one roll rate of `p`, the branch's aileron at
/// every roll rate of `p` lies in the answer: each has exactly one trim in the candidate, in
/// the image, strictly inside, so the continuous branch cannot leave it over `p`.
pub fn fold_aileron(g: &IPoly2, value: &dyn Fn(f64, f64) -> I, p: I, near: I) -> Option<I> {
    let coeffs: Vec<I> = g.0.iter().map(|c| c.eval(p)).collect();
    let c = p.mid();
    let at = |m: f64| {
        let over = g.at_aileron(I::point(m));
        let centred = value(c, m) + over.derivative().eval(p) * (p - I::point(c));
        centred.intersect(over.eval(p))
    };
    let slope = |d: I| {
        coeffs
            .iter()
            .enumerate()
            .skip(1)
            .rev()
            .fold(I::point(0.0), |acc, (i, c)| {
                acc * d + *c * I::point(i as f64)
            })
    };
    let mut room = near.width().max(1e-15 * (1.0 + near.mag()));
    for _ in 0..3 {
        let candidate = I::new(near.lo - room, near.hi + room);
        let m = candidate.mid();
        let image = I::point(m) - at(m)?.checked_div(slope(candidate))?;
        if image.lo > candidate.lo && image.hi < candidate.hi {
            return Some(image);
        }
        room *= 16.0;
    }
    None
}

/// Whether the second derivative in P0 of every polynomial with coefficients in `q` (the trim
/// condition over an aileron interval) keeps one sign over the roll rates `x`: its value at
/// `x`'s centre plus its third derivative over `x` times the offsets, intersected with its plain
/// enclosure over `x`, excludes zero.
pub fn one_curvature(q: &IPoly, x: I) -> bool {
    let second = q.derivative().derivative();
    let c = I::point(x.mid());
    let centred = second.eval(c) + second.derivative().eval(x) * (x - c);
    centred
        .intersect(second.eval(x))
        .is_some_and(|v| v.sign().is_some())
}

#[cfg(test)]
mod tests {
    use super::super::dense::Dense;
    use super::super::isolate::real_roots_outside;
    use super::*;

    /// `G(P, delta_a) = (P - 1)^2 (P - 3) + delta_a`: at `delta_a = 0` the fold's double root
    /// at 1 and one landing at 3; `G_PP = 6 P - 10` vanishes at 5/3 alone.
    fn fold_at_one() -> IPoly2 {
        let p = |c: &[f64]| Dense::new(c.iter().map(|x| I::point(*x)).collect());
        IPoly2::new(vec![p(&[-3.0, 7.0, -5.0, 1.0]), p(&[1.0])])
    }

    /// The plain enclosure of `fold_at_one` at a point.
    fn value(p: f64, da: f64) -> I {
        fold_at_one().at_aileron(I::point(da)).eval(I::point(p))
    }

    fn fold() -> Bracket {
        Bracket {
            lo: 1.0 - 1e-12,
            hi: 1.0 + 1e-12,
            value: 1.0,
        }
    }

    #[test]
    fn one_curvature_holds_where_the_second_derivative_keeps_its_sign() {
        let q = fold_at_one().at_aileron(I::new(-1e-9, 1e-9));
        assert!(one_curvature(&q, I::new(0.5, 1.6)));
        // 5/3 inside: the curvature changes sign, at most two roots is not proven.
        assert!(!one_curvature(&q, I::new(0.5, 1.7)));
        // The landing at 3 can never lie in a proven interval around the fold.
        assert!(!one_curvature(&q, I::new(0.0, 3.5)));
    }

    #[test]
    fn the_folds_aileron_is_enclosed_from_a_nearby_one() {
        let g = fold_at_one();
        // At the fold G's slope in delta_a is 1: the trim of every roll rate near 1 is
        // -(P - 1)^2 (P - 3), within 1e-23 of zero over the bracket.
        let d = fold_aileron(
            &g,
            &value,
            I::new(fold().lo, fold().hi),
            I::new(-1e-15, 1e-14),
        )
        .unwrap();
        assert!(d.lo <= 0.0 && 0.0 <= d.hi && d.width() < 1e-13, "{d:?}");
    }

    /// At an aileron rounded past the fold by 1e-10 the double root splits into two roots
    /// about 7.1e-6 either side of 1 (`-2 (P - 1)^2 + 1e-10 = 0` there): a window of 1e-6
    /// would leave them to the landings. The proven intervals hold them, and outside the first
    /// only the landing at 3 (its root moved by -1e-10 / 4) is isolated.
    #[test]
    fn the_split_fold_is_left_inside_and_the_landing_found_outside() {
        let g = fold_at_one();
        let da = 1e-10;
        let at = g.at_aileron(I::point(da));
        let narrow = real_roots_outside(&at, (1.0 - 1e-6, 1.0 + 1e-6), None, 1e-9).unwrap();
        assert_eq!(narrow.len(), 3, "{narrow:?}");
        let x = fold_intervals(&g, &value, fold(), I::new(-1e-15, 1e-15), da, 1e-6);
        assert_eq!(x.len(), 3, "{x:?}");
        assert!(x[0].0 < 1.0 - 7.1e-6 && x[0].1 > 1.0 + 7.1e-6, "{x:?}");
        let roots = real_roots_outside(&at, x[0], None, 1e-9).unwrap();
        assert_eq!(roots.len(), 1, "{roots:?}");
        let landing = 3.0 - 1e-10 / 4.0;
        assert!(
            roots[0].lo <= landing && landing <= roots[0].hi,
            "{roots:?}"
        );
    }

    /// Away from a fold (a simple root of G in P0, whose slope there is far from zero) no
    /// interval is offered.
    #[test]
    fn no_interval_without_a_double_root() {
        let g = fold_at_one();
        let simple = Bracket {
            lo: 3.0 - 1e-12,
            hi: 3.0 + 1e-12,
            value: 3.0,
        };
        let near = I::new(-1e-11, 1e-11);
        assert!(fold_aileron(&g, &value, I::new(simple.lo, simple.hi), near).is_some());
        assert!(fold_intervals(&g, &value, simple, near, 0.0, 1e-6).is_empty());
    }
}
