//! Positive roots of a polynomial of high degree refined in windows: each root bracketed
//! coarsely on the global polynomial, then refined on a Taylor expansion at the bracket (low
//! degree, accurate near its centre), and the same in `u = P0^2` for an even polynomial.

use super::bernstein::{isolate_unit_within, variations};
use super::bounds::positive_root_bound;
use super::*;

/// [`positive_roots_by`] for a polynomial whose expansion in powers of P0 is too cancellation-
/// prone to isolate roots from (the Hopf polynomial: degree 32, its terms up to 10^11 times its
/// value where its roots lie), given instead by `local(x0)`, an enclosure of its Taylor
/// expansion `p(x0 + y)` in `y` at a double `x0`, built from ingredients of low degree.
///
/// `(0, inf)` is covered by windows `[x0, x0 + h]` up to a bound on the positive roots of
/// `global` (the expansion in powers of P0, whose leading and constant coefficients must
/// exclude zero): `[0, 1/4]`, then one per octave `[2^j, 2^(j+1)]`, so that `h` is a power of
/// two and `y = h t` maps the window to `[0, 1]` exactly. In each, the local expansion is
/// isolated on `[0, 1]` as in [`positive_roots`] (its ends' signs certain, from the expansion
/// or from `value`) with a small bisection budget; a window that exhausts it is halved (new
/// expansions at the halves) up to [`MAX_WINDOW_SPLITS`] times. Each root is refined on its
/// window's expansion and on `value`.
pub fn positive_roots_windowed(
    global: &IPoly,
    local: &dyn Fn(f64) -> IPoly,
    value: &dyn Fn(f64) -> I,
    target: f64,
) -> Result<Vec<Bracket>, Uncertified> {
    let first = first_brackets_windowed(global, local, Some(value), MAX_WINDOWED_BOUND)?;
    final_brackets(first, local, value, target)
}

/// [`positive_roots_windowed`] for an even polynomial `p(x) = q(x^2)`, with the windows in
/// `u = x^2`: `global_u` is `q` expanded in powers of `u`, `local_u(u0)` an enclosure of
/// `q(u0 + w)` in `w`, `local(x0)` and `value` as in [`positive_roots_windowed`].
///
/// Why: every local expansion and every isolation then has half the degree (16 instead of 32
/// for the Hopf polynomial), which costs about a quarter per window. The roots are isolated and
/// bracketed to a relative width of 1e-6 in `u`, and each bracket is mapped to `x` by correctly
/// rounded square roots widened by one ulp, so it still holds its root, and no other: the
/// brackets in `u` hold every positive root of `q`, one each, and the mapped brackets must be
/// disjoint.
/// The final brackets are refined in `x` as in [`positive_roots_windowed`]. A window end whose
/// sign the expansion in `u` cannot decide is an [`Uncertified::Sign`] (there is no exact
/// double `x` to evaluate `value` at): the caller then isolates in `x`.
pub fn positive_roots_windowed_even(
    global_u: &IPoly,
    local_u: &dyn Fn(f64) -> IPoly,
    local: &dyn Fn(f64) -> IPoly,
    value: &dyn Fn(f64) -> I,
    target: f64,
) -> Result<Vec<Bracket>, Uncertified> {
    let in_u = first_brackets_windowed(
        global_u,
        local_u,
        None,
        MAX_WINDOWED_BOUND * MAX_WINDOWED_BOUND,
    )?;
    let first = in_u
        .iter()
        .map(|b| Bracket {
            lo: next_down(b.lo.sqrt()).max(0.0),
            hi: next_up(b.hi.sqrt()),
            value: b.value.sqrt(),
        })
        .collect();
    final_brackets(first, local, value, target)
}

/// The windowed isolation of [`positive_roots_windowed`] up to the first brackets (relative
/// width [`COARSE`], on each window's expansion), in whatever variable `global` and `local`
/// are polynomials of; `value`, when given, decides the window ends' signs the expansion
/// cannot, and `max_bound` is the largest root bound covered.
pub(super) fn first_brackets_windowed(
    global: &IPoly,
    local: &dyn Fn(f64) -> IPoly,
    value: Option<&dyn Fn(f64) -> I>,
    max_bound: f64,
) -> Result<Vec<Bracket>, Uncertified> {
    let c = global.coeffs();
    let n = c.len().checked_sub(1).ok_or(Uncertified::Degenerate)?;
    if c[0].contains_zero() || c[n].contains_zero() {
        return Err(Uncertified::Degenerate);
    }
    let Some(bound) = positive_root_bound(c) else {
        return Ok(Vec::new());
    };
    if bound.is_nan() || bound > max_bound {
        return Err(Uncertified::Degenerate);
    }
    let mut windows = vec![(0.0, 0.25, 0)];
    let mut x0 = 0.25;
    while x0 < bound {
        windows.push((x0, x0, 0));
        x0 *= 2.0;
    }
    windows.reverse();
    let mut out = Vec::new();
    // The windows are taken in ascending order of x0.
    while let Some((x0, h, splits)) = windows.pop() {
        let q = local(x0);
        // Descartes' rule on the Taylor coefficients at x0: no sign change, no root in
        // [x0, inf), nor in this window or any after it. Past the last real root this ends the
        // search long before the root bound, which is loose by a factor of two or more.
        if variations(q.coeffs()) == Some(0) {
            break;
        }
        let at = |y: I| q.eval(y);
        // The window's ends: x0 (y = 0) and x0 + h (y = h), each sign certain.
        let end_sign = |x: f64, y: I| {
            let c = at(y);
            c.sign().or_else(|| c.intersect(value?(x))?.sign())
        };
        if end_sign(x0, I::point(0.0)).is_none() || end_sign(x0 + h, I::point(h)).is_none() {
            return Err(Uncertified::Sign);
        }
        let k = h.log2() as i32;
        let scaled: Vec<I> = q
            .coeffs()
            .iter()
            .enumerate()
            .map(|(i, a)| a.scale2(k * i as i32))
            .collect();
        let isolated = match isolate_unit_within(&scaled, WINDOW_NODES) {
            Ok(t) => t,
            Err(Uncertified::Budget | Uncertified::Sign) if splits < MAX_WINDOW_SPLITS => {
                windows.push((x0 + h / 2.0, h / 2.0, splits + 1));
                windows.push((x0, h / 2.0, splits + 1));
                continue;
            }
            Err(e) => return Err(e),
        };
        for (tl, tr, t) in isolated {
            let lo = next_down(x0 + h * tl).max(x0);
            let hi = next_up(x0 + h * tr).min(x0 + h);
            out.push(refine_local(
                &Local::of(&q, x0),
                None,
                COARSE,
                (lo, hi, x0 + h * t),
            )?);
        }
    }
    Ok(out)
}

/// The final brackets of [`positive_roots_windowed`] from the first ones (disjoint, each
/// holding exactly one root): refined on an expansion at each first bracket's root, whose
/// enclosure is tightest there, and on `value`.
pub(super) fn final_brackets(
    first: Vec<Bracket>,
    local: &dyn Fn(f64) -> IPoly,
    value: &dyn Fn(f64) -> I,
    target: f64,
) -> Result<Vec<Bracket>, Uncertified> {
    // Each final bracket lies in its first one: the order and disjointness carry over.
    sorted_disjoint(first)?
        .iter()
        .map(|b| {
            let at_root = local(b.value);
            let at = Local::of(&at_root, b.value);
            refine_local(&at, Some(value), target, (b.lo, b.hi, b.value))
        })
        .collect()
}

/// The relative width of the first bracket of a root in [`positive_roots_windowed`], on the
/// window's expansion (the final one is refined on an expansion at that bracket's root).
pub(super) const COARSE: f64 = 1e-6;

/// The largest positive-root bound [`positive_roots_windowed`] covers with windows (a roll
/// rate far beyond any aircraft's).
pub(super) const MAX_WINDOWED_BOUND: f64 = 65536.0;

/// How often a window of [`positive_roots_windowed`] may be halved.
pub const MAX_WINDOW_SPLITS: u32 = 8;

/// The bisection budget of one window of [`positive_roots_windowed`].
pub(super) const WINDOW_NODES: usize = 16;
