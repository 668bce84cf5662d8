//! Certified isolation of the positive real roots of a polynomial with interval coefficients.
//!
//! The exact path ([`crate::roots`]) isolates roots of exact integer polynomials; here the
//! coefficients are only known to lie in intervals, and every claim is about *every* polynomial
//! with coefficients in them (hence about the exact one):
//!
//! 1. `(0, inf)` is split at a power of two `s` where the value has a certain sign: `(0, s]` is
//!    mapped to `t in (0, 1]` by `x = s t`, `(s, inf)` by `x = s / t` (the reversed polynomial).
//! 2. On `[0, 1]` the Bernstein coefficients are enclosed as f64 midpoints with radii that
//!    bound the conversion's rounding (`Node::bernstein`; in intervals above degree 56) and
//!    bisected by de Casteljau's algorithm, run on the midpoints with a bound on its rounding
//!    carried in the radii (`Node::split`). Descartes' rule for the Bernstein form: when
//!    every coefficient has a certain sign, 0 sign changes prove no root and 1 proves exactly
//!    one (simple) root in the open interval. Any coefficient whose sign is uncertain makes the
//!    node undecided; it is bisected, up to a depth and node budget.
//! 3. Each isolated root is refined on the original polynomial: Newton steps in f64 propose a
//!    point, and a bracket around it is certified by the signs of enclosures of the values at
//!    its ends ([`PointEnclosure`]: Horner in f64 with a running error bound; interval Horner
//!    for the windowed expansions at `x0 != 0` and below `|x| = 2^-20`), starting from
//!    the enclosure's half-width over the slope (the narrowest bracket the
//!    enclosure can possibly certify) and doubling. The result is a bracket `[lo, hi]` with
//!    certified opposite signs at its ends and exactly one root inside, within a factor two of
//!    that narrowest width: a few ulps for a well-conditioned root, wider by the root's
//!    condition number.
//!
//! Whatever cannot be decided (a leading or constant coefficient that may vanish, a root too
//! close to a split point, roots closer than the enclosures can tell apart) is an
//! [`Uncertified`] error: the caller then falls back to the exact path. Nothing is ever guessed.
//!
//! ```
//! use model::certified::dense::IPoly;
//! use model::certified::isolate::positive_roots_by;
//! use model::interval::I;
//!
//! // x^2 - 2: one positive root, sqrt(2), in a bracket of relative width at most 1e-12.
//! let p = IPoly::new(vec![I::point(-2.0), I::point(0.0), I::point(1.0)]);
//! let r = positive_roots_by(&p, None, 1e-12).unwrap();
//! assert_eq!(r.len(), 1);
//! assert!(r[0].lo <= 2f64.sqrt() && 2f64.sqrt() <= r[0].hi);
//! assert!(r[0].relative_width() <= 1e-12);
//! ```

use super::dense::{IPoly, PointEnclosure};
use crate::interval::{next_down, next_up, I};
use crate::roots::F64Poly;

/// A certified bracket of a simple real root: exactly one root lies in `[lo, hi]` (strictly
/// inside unless `lo == hi`), and `value` is a double in the bracket.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bracket {
    /// Lower end.
    pub lo: f64,
    /// Upper end.
    pub hi: f64,
    /// A double within `[lo, hi]`: when the bracket is one ulp wide, the end where the
    /// floating-point value of the polynomial is smaller in magnitude; otherwise the Newton
    /// root of the midpoint polynomial.
    pub value: f64,
}

impl Bracket {
    /// The width relative to the root's magnitude.
    pub fn relative_width(&self) -> f64 {
        (self.hi - self.lo) / self.lo.abs().max(self.hi.abs()).max(f64::MIN_POSITIVE)
    }
}

/// Why the roots could not be certified.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Uncertified {
    /// The polynomial may be zero, may have a root at 0 or may drop in degree.
    Degenerate,
    /// A sign that decides the isolation could not be certified (a root too close to a split
    /// point or a bracket end).
    Sign,
    /// The bisection budget ran out (roots closer than the enclosures resolve).
    Budget,
    /// A root is certified, but only within a bracket wider than the caller accepts (an
    /// ill-conditioned root: double precision cannot pin it down further).
    Wide,
    /// The certified route does not cover this case (the Hopf points with aileron yaw, whose
    /// polynomial is a resultant of high degree in delta_a): the exact path answers.
    Uncovered,
}

const MAX_DEPTH: u32 = 60;
const MAX_NODES: usize = 4000;

/// The positive real roots of every polynomial with coefficients in `p`'s intervals: one
/// certified bracket per root, ascending and disjoint, or why that could not be proven.
pub fn positive_roots(p: &IPoly) -> Result<Vec<Bracket>, Uncertified> {
    positive_roots_by(p, None, 0.0)
}

/// [`positive_roots`], with each bracket refined towards relative width `target`, on the
/// coefficients' enclosure and, where that is too coarse, on `value`: another enclosure of the
/// same polynomial's value at a double (e.g. through the trim), intersected with it.
pub fn positive_roots_by(
    p: &IPoly,
    value: Option<&dyn Fn(f64) -> I>,
    target: f64,
) -> Result<Vec<Bracket>, Uncertified> {
    // A factor x^k (exact zeros at the bottom) only adds the root 0, which is not positive.
    let first = p.coeffs().iter().take_while(|c| c.is_exact_zero()).count();
    let p = IPoly::new(p.coeffs()[first..].to_vec());
    let c = p.coeffs();
    // A polynomial in x^2 (every odd coefficient exactly zero) is isolated in y = x^2: half the
    // degree, and its roots are the squares of the positive ones.
    let even = c.len() > 2 && c.iter().skip(1).step_by(2).all(|c| c.is_exact_zero());
    let (isolating, in_square): (Vec<Isolating>, Option<IPoly>) = if even {
        let q = IPoly::new(c.iter().step_by(2).copied().collect());
        (isolate_positive(q.coeffs())?, Some(q))
    } else {
        (isolate_positive(c)?, None)
    };
    if isolating.is_empty() {
        return Ok(Vec::new());
    }
    // `value` encloses the value of `p` before the factor x^first was taken out: divided by
    // x^first, it encloses the value of the polynomial refined here.
    let stripped = value.map(|v| {
        move |x: f64| {
            v(x).checked_div(I::point(x).powi(first as u32))
                .unwrap_or(I::entire())
        }
    });
    let value: Option<&dyn Fn(f64) -> I> = match (&stripped, first) {
        (_, 0) => value,
        (Some(f), _) => Some(f),
        (None, _) => None,
    };
    // The polynomial in x, prepared on first use (in the square only for a root its expansion
    // in y cannot pin down).
    let in_x = std::cell::OnceCell::new();
    let local = || in_x.get_or_init(|| Local::of(&p, 0.0));
    let brackets = match &in_square {
        Some(q) => {
            // Refined in y = x^2 first, on q (half the degree: half the work per value): a
            // bracket [y0, y1] of q's root is one of p's, [sqrt(y0), sqrt(y1)] widened by an ulp
            // at each end (correctly rounded square roots), of about half the relative width.
            // Only a root that q's enclosures cannot pin down to `target` is refined in x as
            // well, where `value` can tighten them.
            let local_q = Local::of(q, 0.0);
            isolating
                .into_iter()
                .map(|(ylo, yhi, guess)| {
                    // A bracket [y0, y1] (with a value in it) as one in x.
                    let in_x = |(y0, y1, y): Isolating| {
                        let (lo, hi) = (next_down(y0.sqrt()), next_up(y1.sqrt()));
                        (lo, hi, y.sqrt().clamp(lo, hi))
                    };
                    let x = match refine_local(&local_q, None, target, (ylo, yhi, guess)) {
                        Ok(b) => in_x((b.lo, b.hi, b.value)),
                        // q's enclosures cannot decide an end: the isolating interval in x,
                        // where `value` can.
                        Err(_) => in_x((ylo, yhi, guess)),
                    };
                    let bracket = Bracket {
                        lo: x.0,
                        hi: x.1,
                        value: x.2,
                    };
                    if bracket.relative_width() <= target {
                        Ok(bracket)
                    } else {
                        refine_local(local(), value, target, x)
                    }
                })
                .collect::<Result<Vec<_>, _>>()?
        }
        None => isolating
            .into_iter()
            .map(|i| refine_local(local(), value, target, i))
            .collect::<Result<Vec<_>, _>>()?,
    };
    sorted_disjoint(brackets)
}

/// `brackets` in ascending order, proven pairwise disjoint (so each holds a different root), or
/// [`Uncertified::Sign`] when two meet.
fn sorted_disjoint(mut brackets: Vec<Bracket>) -> Result<Vec<Bracket>, Uncertified> {
    brackets.sort_by(|a, b| a.lo.total_cmp(&b.lo));
    if brackets.windows(2).any(|w| w[0].hi >= w[1].lo) {
        return Err(Uncertified::Sign);
    }
    Ok(brackets)
}

/// The real roots of every polynomial with coefficients in `p`'s intervals outside the window
/// `[lo, hi]` (`0 < lo < hi`), ascending, each refined towards relative width `target`: the
/// negative ones as positive roots of `p(-x)`, those in `(0, lo)` from `p(lo t)` on `(0, 1)`,
/// those beyond `hi` from `p(hi + y)` on `(0, inf)`. Whatever lies in the window is neither
/// counted nor isolated (e.g. a nearly double root there). `p(0)`, `p(lo)` and `p(hi)` must
/// have certain signs, from the coefficients or from `value` (another enclosure of the value at a
/// double, intersected with it; also used to refine).
pub fn real_roots_outside(
    p: &IPoly,
    (lo, hi): (f64, f64),
    value: Option<&dyn Fn(f64) -> I>,
    target: f64,
) -> Result<Vec<Bracket>, Uncertified> {
    if !(lo > 0.0 && hi > lo) {
        return Err(Uncertified::Degenerate);
    }
    let c = p.coeffs();
    if c.is_empty() || c[0].contains_zero() {
        return Err(Uncertified::Degenerate);
    }
    let at = |x: f64| {
        let c = p.eval(I::point(x));
        value.and_then(|v| c.intersect(v(x))).unwrap_or(c)
    };
    let (at_lo, at_hi) = (at(lo), at(hi));
    let local = Local::of(p, 0.0);
    let mut out: Vec<Bracket> = positive_roots_by(&p.mirror(), None, target)?
        .into_iter()
        .rev()
        .map(|b| Bracket {
            lo: -b.hi,
            hi: -b.lo,
            value: -b.value,
        })
        .collect();
    let scale = I::point(lo);
    let below: Vec<I> = c
        .iter()
        .enumerate()
        .map(|(i, a)| *a * scale.powi(i as u32))
        .collect();
    // The Bernstein end coefficients are the values at the window's ends: the tighter
    // enclosure of those decides their signs.
    for (tl, tr, t) in isolate_unit_ends(&below, MAX_NODES, (None, Some(at_lo)))? {
        let (a, b) = (next_down(lo * tl).max(0.0), next_up(lo * tr).min(lo));
        out.push(refine_local(&local, value, target, (a, b, lo * t))?);
    }
    let mut above = p.shift(I::point(hi)).0;
    if let Some(c0) = above.first_mut() {
        *c0 = c0.intersect(at_hi).ok_or(Uncertified::Sign)?;
    }
    for (yl, yr, y) in isolate_positive(&above)? {
        let (a, b) = (next_down(hi + yl).max(hi), next_up(hi + yr));
        out.push(refine_local(&local, value, target, (a, b, hi + y))?);
    }
    sorted_disjoint(out)
}

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
fn first_brackets_windowed(
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
fn final_brackets(
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
const COARSE: f64 = 1e-6;

/// The largest positive-root bound [`positive_roots_windowed`] covers with windows (a roll
/// rate far beyond any aircraft's).
const MAX_WINDOWED_BOUND: f64 = 65536.0;

/// How often a window of [`positive_roots_windowed`] may be halved.
pub const MAX_WINDOW_SPLITS: u32 = 8;

/// The bisection budget of one window of [`positive_roots_windowed`].
const WINDOW_NODES: usize = 16;

/// A bound on the positive roots (Kioustelidis: `2 max (|a_i| / a_n)^(1/(n-i))` over the
/// coefficients that may have the sign opposite to the leading one), rounded up to a power of
/// two; `None` when no coefficient can have that sign (no positive root at all). The leading
/// coefficient must exclude zero.
fn positive_root_bound(c: &[I]) -> Option<f64> {
    let n = c.len() - 1;
    let lead = c[n];
    let opposite = |a: &I| {
        if lead.lo > 0.0 {
            a.lo < 0.0
        } else {
            a.hi > 0.0
        }
    };
    let m = (0..n)
        .filter(|i| opposite(&c[*i]))
        .map(|i| (c[i].mag() / lead.mig()).powf(1.0 / (n - i) as f64))
        .fold(None, |acc: Option<f64>, r| {
            Some(acc.map_or(r, |a| a.max(r)))
        })?;
    let b = 2.0 * m * (1.0 + 1e-9);
    Some(if b.is_finite() && b > 0.0 {
        2f64.powi(b.log2().ceil() as i32)
    } else {
        f64::INFINITY
    })
}

/// Isolating intervals `[lo, hi]` (one root of every polynomial with coefficients in `c`
/// inside each, none elsewhere in `(0, inf)`) for the ascending coefficients `c`, whose
/// constant term must be certainly nonzero.
fn isolate_positive(c: &[I]) -> Result<Vec<Isolating>, Uncertified> {
    let Some(n) = c.len().checked_sub(1) else {
        return Err(Uncertified::Degenerate);
    };
    if c[0].contains_zero() || c[n].contains_zero() {
        return Err(Uncertified::Degenerate);
    }
    if n == 0 {
        return Ok(Vec::new());
    }
    let p = IPoly::new(c.to_vec());
    if let Some(found) = low_degree(&p) {
        return Ok(found);
    }
    let k = [0, 1, -1, 2, -2, 3, -3]
        .into_iter()
        .find(|k| !p.eval(I::point(2f64.powi(*k))).contains_zero())
        .ok_or(Uncertified::Sign)?;
    let s = 2f64.powi(k);
    // q(t) = p(s t) on (0, 1]; its reverse t^n q(1/t) = t^n p(s / t) on (0, 1).
    let forward: Vec<I> = c
        .iter()
        .enumerate()
        .map(|(i, a)| a.scale2(k * i as i32))
        .collect();
    let reverse: Vec<I> = forward.iter().rev().copied().collect();
    let mut out: Vec<Isolating> = isolate_unit(&forward)?
        .into_iter()
        .map(|(tl, tr, t)| (s * tl, s * tr, s * t))
        .collect();
    for (tl, tr, t) in isolate_unit(&reverse)? {
        let lo = next_down(s / tr);
        // The root bound (a root per coefficient: made only for the largest root's interval).
        let hi = if tl == 0.0 {
            root_bound(c)
        } else {
            next_up(s / tl)
        };
        // A root bound that overflows leaves the last root unbounded: no answer to refine.
        if !hi.is_finite() {
            return Err(Uncertified::Wide);
        }
        out.push((lo, hi, s / t));
    }
    Ok(out)
}

/// [`isolate_positive`] in closed form for degrees 1 and 2 (det A, the zero-sideslip
/// determinant and d, in `P0^2`), where interval arithmetic decides; `None` sends the
/// polynomial to the bisection.
///
/// Descartes' rule of signs counts the positive roots of every polynomial in the enclosures at
/// once when the coefficients' signs are certain: none for no sign change, exactly one for
/// one. For two sign changes there are two or none: none when the discriminant
/// `c1^2 - 4 c0 c2` is certainly negative, two (distinct, and positive) when it is certainly
/// positive. The roots are enclosed by the stable formulas `q / c2` and `c0 / q`,
/// `q = -(c1 + sign(c1) sqrt(D)) / 2` (`-c0 / c1` for degree 1, `sqrt(-c0 / c2)` for
/// `c1 = 0`), evaluated in intervals: they hold the roots of every polynomial in the box. Each
/// enclosure, widened by a relative `2^-30`, is an isolating interval if the polynomial's
/// value has certain, opposite signs at its ends (which refinement needs) and the intervals
/// are disjoint.
fn low_degree(p: &IPoly) -> Option<Vec<Isolating>> {
    let c = p.coeffs();
    let widen = 1.0 / (1u64 << 30) as f64;
    let bracket = |r: I| -> Option<Isolating> {
        let (lo, hi) = (next_down(r.lo - r.lo * widen), next_up(r.hi + r.hi * widen));
        let (a, b) = (p.eval(I::point(lo)).sign()?, p.eval(I::point(hi)).sign()?);
        (lo > 0.0 && hi.is_finite() && a != b).then_some((lo, hi, r.mid()))
    };
    let signs: Vec<Option<f64>> = c
        .iter()
        .filter(|x| !x.is_exact_zero())
        .map(|x| x.sign())
        .collect();
    let changes = sign_changes(signs.iter().copied())?;
    if changes == 0 {
        return Some(Vec::new());
    }
    let mut roots: Vec<I> = match c {
        [c0, c1] => vec![(-*c0).checked_div(*c1)?],
        [c0, c1, c2] if c1.is_exact_zero() => vec![I::sqrt((-*c0).checked_div(*c2)?)?],
        [c0, c1, c2] => {
            let d = c1.sqr() - I::point(4.0) * *c0 * *c2;
            if d.hi < 0.0 {
                return (changes == 2).then(Vec::new);
            }
            if d.lo.is_nan() || d.lo <= 0.0 {
                return None;
            }
            let root = d.sqrt()?;
            let q = -(*c1 + root * I::point(c1.sign()?)).scale2(-1);
            vec![q.checked_div(*c2)?, c0.checked_div(q)?]
        }
        _ => return None,
    };
    // The negative roots (two roots of opposite signs for one sign change) are not asked for.
    roots.retain(|r| r.hi >= 0.0);
    if roots.len() != changes {
        return None;
    }
    let mut out = roots
        .into_iter()
        .map(bracket)
        .collect::<Option<Vec<Isolating>>>()?;
    out.sort_by(|x, y| x.0.total_cmp(&y.0));
    if out.windows(2).any(|w| w[0].1 >= w[1].0) {
        return None;
    }
    Some(out)
}

/// Fujiwara's bound, `2 max |a_{n-i} / a_n|^(1/i)` (every root modulus is below it), rounded up
/// generously to a power of two.
fn root_bound(c: &[I]) -> f64 {
    let n = c.len() - 1;
    let lead = c[n].mig();
    let m = (1..=n)
        .map(|i| {
            let r = c[n - i].mag() / lead;
            let i = i as f64;
            if i == n as f64 {
                (r / 2.0).powf(1.0 / i)
            } else {
                r.powf(1.0 / i)
            }
        })
        .fold(0.0f64, f64::max);
    let b = 2.0 * m * (1.0 + 1e-9);
    if b.is_finite() && b > 0.0 {
        2f64.powi(b.log2().ceil() as i32 + 1)
    } else {
        f64::INFINITY
    }
}

/// An exact integer as an interval (a point below 2^53, else the two nearest doubles).
fn integer(v: u128) -> I {
    let x = v as f64;
    match (x as u128).cmp(&v) {
        std::cmp::Ordering::Equal => I::point(x),
        std::cmp::Ordering::Less => I::new(x, next_up(x)),
        std::cmp::Ordering::Greater => I::new(next_down(x), x),
    }
}

/// The rows of Pascal's triangle up to [`MAX_BERNSTEIN_DEGREE`], as intervals (exact below
/// 2^53; the entries are exact in u128), made once.
fn pascal() -> &'static [Vec<I>] {
    static P: std::sync::OnceLock<Vec<Vec<I>>> = std::sync::OnceLock::new();
    P.get_or_init(|| {
        let mut row: Vec<u128> = vec![1];
        let mut rows = vec![vec![I::point(1.0)]];
        for j in 1..=MAX_BERNSTEIN_DEGREE {
            let mut next = vec![1u128; j + 1];
            for i in 1..j {
                next[i] = row[i - 1] + row[i];
            }
            rows.push(next.iter().map(|v| integer(*v)).collect());
            row = next;
        }
        rows
    })
}

/// The highest degree [`bernstein`] converts (binomials stay exact in u128).
const MAX_BERNSTEIN_DEGREE: usize = 120;

/// The highest degree `Node::bernstein` converts in f64 (`C(56, 28) < 2^53`: every binomial of
/// these rows is an exact double).
const MAX_F64_BERNSTEIN_DEGREE: usize = 56;

/// The Bernstein coefficients on `[0, 1]` of the polynomial with (ascending) coefficients `a`:
/// `b_j = sum_{i <= j} C(j, i) / C(n, i) a_i`.
fn bernstein(a: &[I]) -> Option<Vec<I>> {
    let n = a.len() - 1;
    if n > MAX_BERNSTEIN_DEGREE {
        return None;
    }
    let rows = pascal();
    let scaled: Vec<I> = (0..=n)
        .map(|i| a[i].checked_div(rows[n][i]))
        .collect::<Option<_>>()?;
    Some(
        (0..=n)
            .map(|j| (0..=j).fold(I::point(0.0), |acc, i| acc + rows[j][i] * scaled[i]))
            .collect(),
    )
}

/// An isolating interval `(lo, hi, guess)`: exactly one root in `[lo, hi]` (strictly inside),
/// and a guess of where (a heuristic for the refinement's start only; NaN for none).
type Isolating = (f64, f64, f64);

/// Sign changes of a sequence whose signs are all certain; `None` if some sign is not.
fn variations(b: &[I]) -> Option<usize> {
    sign_changes(b.iter().map(|x| x.sign()))
}

/// Sign changes of a sequence of signs, all certain; `None` if some sign is not.
fn sign_changes(signs: impl Iterator<Item = Option<f64>>) -> Option<usize> {
    let mut last = None;
    let mut v = 0;
    for s in signs {
        let s = s?;
        if last.is_some_and(|l| l != s) {
            v += 1;
        }
        last = Some(s);
    }
    Some(v)
}

/// Bernstein coefficients of a node of the bisection as f64 midpoints `m_j` and radii `r_j`:
/// the exact coefficient lies in `[m_j - r_j, m_j + r_j]`. De Casteljau's subdivision runs on
/// the midpoints in f64 and carries a bound on its rounding error in the radii, a few times
/// less work than the same subdivision in outward-rounded intervals.
///
/// The bisection keeps its nodes in one buffer ([`isolate_unit_ends`]): a `Node` borrows its
/// coefficients (`C = &[..]` or `&mut [..]`) or owns them (`Vec`, the root and the tests).
#[derive(Clone, Debug)]
struct Node<C = Vec<(f64, f64)>> {
    /// `(m_j, r_j)`.
    c: C,
}

/// A coefficient `(m, r)` as a node holds it: as computed when both are finite, else `(0, inf)`,
/// which no sign is claimed for. A sum that overflowed to an infinity says nothing about the
/// sign of the exact value (later terms of the other sign cannot bring it back), so every
/// computed coefficient passes through here.
fn entry(m: f64, r: f64) -> (f64, f64) {
    if m.is_finite() && r.is_finite() {
        (m, r)
    } else {
        (0.0, f64::INFINITY)
    }
}

/// What each subdivision level adds to a radius for underflow, `2^-1072`: each of the five
/// products of a level (two for the midpoint, three for the radius) that underflows is off by
/// at most `2^-1075`, and sums of subnormals are exact, so a level loses at most `5 * 2^-1075`.
const NODE_FLOOR: f64 = f64::from_bits(4);

impl Node {
    /// The node of the enclosed coefficients `b` (a radius is infinite, so no sign is certain,
    /// where an enclosure is not finite).
    fn of(b: &[I]) -> Node {
        let c = b
            .iter()
            .map(|c| {
                let (m, r) = c.mid_rad();
                entry(m, r)
            })
            .collect();
        Node { c }
    }

    /// The node of the Bernstein coefficients on `[0, 1]` of the polynomial with enclosed
    /// ascending coefficients `a` (`None` beyond [`MAX_BERNSTEIN_DEGREE`]): [`bernstein`]'s
    /// `b_j = sum_(i <= j) C(j, i) s_i`, `s_i = a_i / C(n, i)`, computed in f64 on the
    /// midpoints up to degree [`MAX_F64_BERNSTEIN_DEGREE`] (every binomial exact), in intervals
    /// above.
    ///
    /// With midpoints `m_i`, radii `r_i` and `u = 2^-53`: `fl(m_i / C(n, i))` is off by at most
    /// `u |s_i|`, and the sum of `j + 1` exact-binomial products by at most
    /// `gamma_(j+1) sum C(j, i) |fl(s_i)|` (Higham, *Accuracy and Stability of Numerical
    /// Algorithms*, 2nd ed., eq. (3.5)), together at most `g = (n + 4) u` times that sum; the
    /// coefficients' radii add `sum C(j, i) r_i / C(n, i)`, and an underflowing quotient at
    /// most `2^-1075` per quotient or product. So `r_j = sum C(j, i) t_i` with
    /// `t_i = r_i / C(n, i) + g |fl(s_i)| + 2^-1073`, computed in f64 from nonnegative terms
    /// (at most `n + 7` roundings down) and multiplied by `1 + (2n + 16) u`, then rounded up.
    fn bernstein(a: &[I]) -> Option<Node> {
        let n = a.len() - 1;
        if n > MAX_F64_BERNSTEIN_DEGREE {
            return bernstein(a).map(|b| Node::of(&b));
        }
        let rows = pascal();
        let u = f64::EPSILON / 2.0;
        let g = (n + 4) as f64 * u;
        // 2^-1073: the underflow of two quotients and a product.
        let tiny = f64::from_bits(2);
        let (s, t): (Vec<f64>, Vec<f64>) = Node::of(a)
            .c
            .iter()
            .zip(&rows[n])
            .map(|((m, r), c)| {
                // Binomials up to this degree are below 2^53: exact points.
                let s = m / c.lo;
                (s, r / c.lo + g * s.abs() + tiny)
            })
            .unzip();
        let grow = 1.0 + (2 * n + 16) as f64 * u;
        let c = (0..=n)
            .map(|j| {
                let row = &rows[j];
                let (mut m, mut r) = (0.0, 0.0);
                for i in 0..=j {
                    m += row[i].lo * s[i];
                    r += row[i].lo * t[i];
                }
                entry(m, next_up(r * grow))
            })
            .collect();
        Some(Node { c })
    }
}

impl<C: AsMut<[(f64, f64)]>> Node<C> {
    /// Coefficient `j` replaced by its enclosure's intersection with `e` (`None` when they
    /// are disjoint).
    fn tighten(&mut self, j: usize, e: I) -> Option<()> {
        let c = self.c.as_mut();
        let (m, r) = c[j];
        let (cm, cr) = I::new(next_down(m - r), next_up(m + r))
            .intersect(e)?
            .mid_rad();
        c[j] = entry(cm, cr);
        Some(())
    }
}

impl<C: AsRef<[(f64, f64)]>> Node<C> {
    /// The coefficients.
    fn coefs(&self) -> &[(f64, f64)] {
        self.c.as_ref()
    }

    /// The certain sign of coefficient `j` (`None` if its enclosure holds zero).
    fn sign(&self, j: usize) -> Option<f64> {
        let (m, r) = self.coefs()[j];
        if !(m.is_finite() && r.is_finite()) {
            None
        } else if m > r {
            Some(1.0)
        } else if -m > r {
            Some(-1.0)
        } else {
            None
        }
    }

    /// A split weight in `(0, 1)` between the first two zero crossings of the control polygon
    /// (the points `(j / n, m_j)`), rounded to a multiple of 1/16, when there are two: the
    /// roots sit near the crossings, so splitting there tends to separate the first root
    /// from the others at once. A heuristic for speed only: any split is sound.
    fn guide(&self) -> Option<f64> {
        let c = self.coefs();
        let n = (c.len() - 1) as f64;
        let mut crossings = c.windows(2).enumerate().filter_map(|(j, w)| {
            let (m0, m1) = (w[0].0, w[1].0);
            ((m0 < 0.0) != (m1 < 0.0) && m0 != m1).then(|| (j as f64 + m0 / (m0 - m1)) / n)
        });
        let (x1, x2) = (crossings.next()?, crossings.next()?);
        let t = (8.0 * (x1 + x2)).round() / 16.0;
        (t > 0.0 && t < 1.0).then_some(t)
    }

    /// Where in `[0, 1]` the control polygon (the points `(j / n, m_j)`) first crosses zero, a
    /// guess of the root of a node with one sign change (the crossing is within the square of
    /// the node's width of it as the node shrinks); NaN without a crossing. A heuristic only.
    fn crossing(&self) -> f64 {
        let c = self.coefs();
        let n = (c.len() - 1) as f64;
        c.windows(2)
            .enumerate()
            .find_map(|(j, w)| {
                let (m0, m1) = (w[0].0, w[1].0);
                ((m0 < 0.0) != (m1 < 0.0) && m0 != m1).then(|| (j as f64 + m0 / (m0 - m1)) / n)
            })
            .unwrap_or(f64::NAN)
    }

    /// Sign changes of the coefficients, all of whose signs are certain; `None` if some sign
    /// is not.
    fn variations(&self) -> Option<usize> {
        sign_changes((0..self.coefs().len()).map(|j| self.sign(j)))
    }

    /// De Casteljau's subdivision at `t` (a dyadic weight: `t` and `1 - t` exact): (left,
    /// right); `w` is working space.
    ///
    /// Each level replaces `w_j` by `(1 - t) w_j + t w_(j+1)`, a convex combination: the exact
    /// values stay within the same combination of the radii, and the computed midpoint is off
    /// from the combination of the midpoints by at most the rounding of two products and a
    /// sum, `u (|(1 - t) w_j| + |t w_(j+1)|) + u |sum| <= 2u (1 + u) max(|w_j|, |w_(j+1)|)`,
    /// plus underflow. So each level's radius is that combination of the radii plus
    /// `2.01 u max(|w_j|, |w_(j+1)|)` plus [`NODE_FLOOR`], all computed in f64 and then times
    /// `1 + 8u`, which covers the (at most five) roundings down of those nonnegative terms.
    #[cfg(test)]
    fn split(&self, t: f64, w: &mut Vec<(f64, f64)>) -> (Node, Node) {
        let n = self.coefs().len();
        let (mut left, mut right) = (vec![(0.0, 0.0); n], vec![(0.0, 0.0); n]);
        self.split_into(t, w, &mut left, &mut right);
        (Node { c: left }, Node { c: right })
    }

    /// [`Node::split`] written into `left` and `right` (each as long as the node), without
    /// allocating: what the bisection runs.
    fn split_into(
        &self,
        t: f64,
        w: &mut Vec<(f64, f64)>,
        left: &mut [(f64, f64)],
        right: &mut [(f64, f64)],
    ) {
        let n = self.coefs().len() - 1;
        w.clear();
        w.extend_from_slice(self.coefs());
        left[0] = w[0];
        right[n] = w[n];
        let (a, b) = (1.0 - t, t);
        let u = 2.01 * f64::EPSILON / 2.0;
        let grow = 1.0 + 8.0 * f64::EPSILON / 2.0;
        // The halves' coefficients pass through `entry` as they are written; the levels in
        // between need not: an infinity or NaN never turns finite again in these convex
        // combinations (positive weights, nonnegative radii), so it reaches the coefficient it
        // feeds, which `entry` then makes sign-free, as a level-by-level `entry` would.
        for level in 1..=n {
            for j in 0..=n - level {
                let ((m0, r0), (m1, r1)) = (w[j], w[j + 1]);
                let mu = m0.abs().max(m1.abs());
                w[j] = (
                    a * m0 + b * m1,
                    (a * r0 + b * r1 + u * mu + NODE_FLOOR) * grow,
                );
            }
            left[level] = entry(w[0].0, w[0].1);
            right[n - level] = entry(w[n - level].0, w[n - level].1);
        }
    }
}

/// The open sub-intervals `(tl, tr)` of `(0, 1)` holding exactly one root each, for a
/// polynomial (ascending coefficients `a`) with certain, nonzero values at 0 and 1.
fn isolate_unit(a: &[I]) -> Result<Vec<Isolating>, Uncertified> {
    isolate_unit_within(a, MAX_NODES)
}

/// [`isolate_unit`] with a budget of `max_nodes` bisection nodes.
fn isolate_unit_within(a: &[I], max_nodes: usize) -> Result<Vec<Isolating>, Uncertified> {
    isolate_unit_ends(a, max_nodes, (None, None))
}

/// [`isolate_unit_within`] with tighter enclosures of the values at 0 and 1 (`ends`), which
/// are the first and last Bernstein coefficients of every node that reaches that end.
fn isolate_unit_ends(
    a: &[I],
    max_nodes: usize,
    ends: (Option<I>, Option<I>),
) -> Result<Vec<Isolating>, Uncertified> {
    let root = Node::bernstein(a).ok_or(Uncertified::Degenerate)?;
    let len = root.c.len();
    let n = len - 1;
    let tighten = |b: &mut Node<&mut [(f64, f64)]>, tl: f64, tr: f64| -> Result<(), Uncertified> {
        if let (0.0, Some(e)) = (tl, ends.0) {
            b.tighten(0, e).ok_or(Uncertified::Sign)?;
        }
        if let (1.0, Some(e)) = (tr, ends.1) {
            b.tighten(n, e).ok_or(Uncertified::Sign)?;
        }
        Ok(())
    };
    let mut out = Vec::new();
    // The nodes waiting, depth first: `stack[k]` holds the coefficients
    // `coefs[k * len..(k + 1) * len]` (every node has `len`), so a node is popped and its halves
    // pushed without allocating.
    let mut stack = vec![(0.0f64, 1.0f64, 0u32)];
    let mut coefs = root.c;
    tighten(&mut Node { c: &mut coefs[..] }, 0.0, 1.0)?;
    let mut nodes = 0usize;
    let (mut w, mut node) = (Vec::with_capacity(len), vec![(0.0, 0.0); len]);
    let (mut left, mut right) = (vec![(0.0, 0.0); len], vec![(0.0, 0.0); len]);
    while let Some((tl, tr, depth)) = stack.pop() {
        let top = coefs.len() - len;
        node.copy_from_slice(&coefs[top..]);
        coefs.truncate(top);
        tighten(&mut Node { c: &mut node[..] }, tl, tr)?;
        let b = Node { c: &node[..] };
        nodes += 1;
        if nodes > max_nodes || depth > MAX_DEPTH {
            return Err(Uncertified::Budget);
        }
        match b.variations() {
            Some(0) => continue,
            Some(1) => {
                out.push((tl, tr, tl + b.crossing() * (tr - tl)));
                continue;
            }
            _ => {}
        }
        // Split between the first two roots the control polygon suggests, else near the
        // middle; always where the value has a certain sign, so that no root sits on the split
        // point, and where the split point is exact.
        let at = |t: f64| split_point(tl, tr, t).map(|tm| (tm, t));
        let guided = b
            .guide()
            .and_then(at)
            .filter(|(tm, _)| keeps_bits(tl, *tm, tr));
        let mut split = None;
        for (tm, t) in guided.into_iter().chain(
            [0.5, 0.4375, 0.5625, 0.375, 0.625]
                .into_iter()
                .filter_map(at),
        ) {
            b.split_into(t, &mut w, &mut left, &mut right);
            if (Node { c: &left[..] }).sign(n).is_some() {
                split = Some(tm);
                break;
            }
        }
        let tm = split.ok_or(Uncertified::Sign)?;
        coefs.extend_from_slice(&right);
        stack.push((tm, tr, depth + 1));
        coefs.extend_from_slice(&left);
        stack.push((tl, tm, depth + 1));
    }
    out.sort_by(|x, y| x.0.total_cmp(&y.0));
    Ok(out)
}

/// A polynomial near its root as [`refine_local`] uses it: a cheap enclosure of its value and
/// floating-point values of it and its derivative, made once per polynomial (every root of it
/// is refined on the same one).
struct Local<'a> {
    /// The expansion in `y = x - x0`.
    q: &'a IPoly,
    x0: f64,
    /// `q` made ready for evaluation at doubles (`x0 = 0`: `y = x` exactly).
    at_point: Option<PointEnclosure<'a>>,
    /// The midpoint polynomial for Newton's method, in `y^2` where it is even or odd in `y`
    /// (the criterion polynomials are, about P0 = 0): half the steps of Horner's scheme.
    f: Midpoint,
}

/// A polynomial of doubles `f(y)`, given as `g(y^2)` (even), `y g(y^2)` (odd) or itself.
enum Midpoint {
    Even(F64Poly),
    Odd(F64Poly),
    General(F64Poly),
}

impl Midpoint {
    /// The midpoints of `q`'s coefficients, with the parity their exact zeros show.
    fn of(q: &IPoly) -> Midpoint {
        let m = q.mid();
        let zero_at =
            |parity: usize| m.0.len() > 2 && m.0.iter().skip(parity).step_by(2).all(|c| *c == 0.0);
        let half = |from: usize| F64Poly(m.0.iter().skip(from).step_by(2).copied().collect());
        if zero_at(1) {
            Midpoint::Even(half(0))
        } else if zero_at(0) {
            Midpoint::Odd(half(1))
        } else {
            Midpoint::General(m)
        }
    }

    /// The value and the derivative at `y`, by Horner's scheme for both at once.
    fn value_slope(&self, y: f64) -> (f64, f64) {
        let horner = |c: &[f64], t: f64| {
            c.iter()
                .rev()
                .fold((0.0, 0.0), |(v, d), c| (v * t + c, d * t + v))
        };
        match self {
            Midpoint::Even(g) => {
                let (v, d) = horner(&g.0, y * y);
                (v, 2.0 * y * d)
            }
            Midpoint::Odd(g) => {
                let u = y * y;
                let (v, d) = horner(&g.0, u);
                (y * v, v + 2.0 * u * d)
            }
            Midpoint::General(f) => horner(&f.0, y),
        }
    }
}

impl Local<'_> {
    /// The polynomial given by its expansion `q` in `y = x - x0`.
    fn of(q: &IPoly, x0: f64) -> Local<'_> {
        Local {
            q,
            x0,
            at_point: (x0 == 0.0).then(|| PointEnclosure::new(q)),
            f: Midpoint::of(q),
        }
    }

    /// An enclosure of the value at `x`.
    fn cheap(&self, x: f64) -> I {
        match &self.at_point {
            Some(e) => e.at(x),
            None => self.q.eval(I::point(x) - I::point(self.x0)),
        }
    }

    /// The floating-point value and derivative at `x` (nothing certified).
    fn f_df(&self, x: f64) -> (f64, f64) {
        self.f.value_slope(x - self.x0)
    }
}

/// Whether the split of `[tl, tr]` at `tm` leaves every end on the grid of `2^-20` of the
/// width (rounded down to a power of two), so that at least 20 bisections of the children stay
/// exact. A split at a sixteenth adds four bits to the ends but may shrink a node only to 15/16;
/// near a cluster of roots, a run of such splits would use up the 53 bits of the ends within
/// about 14 levels, after which no split point is exact and the node is refused. The guided
/// split yields to bisection before that. In integers, from each double's `m 2^e`
/// (`integer_decode`, as [`I::from_q`] reads doubles): the exponent of each end's lowest set
/// bit against that of the width's leading bit (a width that is not a normal double: no
/// guided split).
fn keeps_bits(tl: f64, tm: f64, tr: f64) -> bool {
    use num_traits::float::FloatCore;
    /// The exponent of the lowest set bit of `x` (`i32::MAX` for zero).
    fn lowest_bit(x: f64) -> i32 {
        match x.integer_decode() {
            (0, _, _) => i32::MAX,
            (m, e, _) => i32::from(e) + m.trailing_zeros() as i32,
        }
    }
    let w = tr - tl;
    if !w.is_normal() {
        return false;
    }
    // A normal double's mantissa holds 53 bits: its leading bit is 2^(e + 52).
    let grid = i32::from(w.integer_decode().1) + 52 - 20;
    [tl, tm, tr].iter().all(|x| lowest_bit(*x) >= grid)
}

/// `tl + t (tr - tl)` when it is exact in f64 and strictly inside `(tl, tr)`, else `None`. The
/// halves of a node hold the coefficients of the exact subdivision at this point, so the
/// intervals reported must be the halves' own domains. Sums and products of exact points stay
/// points exactly when they are exact.
fn split_point(tl: f64, tr: f64, t: f64) -> Option<f64> {
    let p = I::point(tl) + I::point(t) * (I::point(tr) - I::point(tl));
    (p.lo == p.hi && p.lo > tl && p.lo < tr).then_some(p.lo)
}

/// How many ulps a Newton step of [`refine_local`] may move and still count as converged.
const NEWTON_ULPS: f64 = 16.0;

/// Refines the bracket `[lo, hi]` of the single root of `p` in it, to relative width `target`
/// if the enclosures allow.
///
/// A guess first, by safeguarded Newton on the midpoint polynomial (nothing certified). Then a
/// bracket around the guess certified by the signs of the cheap enclosure ([`Local::cheap`]),
/// starting from the enclosure's half-width over the slope (the narrowest bracket it can
/// possibly certify) and doubling; only when that is wider than `target` is the same done with
/// `value` (a tighter, costlier enclosure), intersected with the cheap one.
fn refine_local(
    p: &Local<'_>,
    value: Option<&dyn Fn(f64) -> I>,
    target: f64,
    (lo, hi, guess): Isolating,
) -> Result<Bracket, Uncertified> {
    let cheap = |x: f64| p.cheap(x);
    let end_sign = |x: f64| {
        let c = cheap(x);
        c.sign()
            .or_else(|| value.and_then(|v| c.intersect(v(x))?.sign()))
    };
    let (Some(slo), Some(shi)) = (end_sign(lo), end_sign(hi)) else {
        return Err(Uncertified::Sign);
    };
    if slo == shi || lo >= hi || lo.is_nan() || hi.is_nan() {
        return Err(Uncertified::Sign);
    }
    let f = |x: f64| p.f_df(x).0;
    let inside = |x: f64, lo: f64, hi: f64| x > lo && x < hi;
    let (mut a, mut b) = (lo, hi);
    let fa_sign = f(a).signum();
    let mut x = if inside(guess, a, b) {
        guess
    } else {
        0.5 * a + 0.5 * b
    };
    for _ in 0..100 {
        let (fx, dfx) = p.f_df(x);
        if fx == 0.0 || b <= next_up(a) {
            break;
        }
        if fx.signum() == fa_sign {
            a = x;
        } else {
            b = x;
        }
        let newton = x - fx / dfx;
        // A Newton step within a few ulps: converged as far as doubles go (further steps only
        // wander in the rounding noise, far inside the narrowest bracket the enclosures can
        // certify). Also when the step leaves `(a, b)` by those few ulps: `x` is then the root
        // to the last bits, at the end just moved to it, where the sign of f is noise; the
        // bisection that a step outside asks for would only halve the bracket towards `x`, an
        // ulp of progress a step (a closed-form bracket 2^-30 wide took 18 steps so).
        let close = NEWTON_ULPS * (next_up(x.abs()) - x.abs());
        if (newton - x).abs() <= close {
            if inside(newton, a, b) {
                x = newton;
            }
            break;
        }
        let next = if inside(newton, a, b) {
            newton
        } else {
            0.5 * a + 0.5 * b
        };
        if (next - x).abs() <= close {
            x = next;
            break;
        }
        x = next;
    }
    if !inside(x, lo, hi) {
        x = 0.5 * lo + 0.5 * hi;
    }
    let slope = p.f_df(x).1.abs();
    let certify = |enclose: &dyn Fn(f64) -> I, x: f64| -> (f64, f64, f64) {
        certified_bracket(enclose, (lo, slo), (hi, shi), x, slope)
    };
    let (mut blo, mut bhi, mut bx) = certify(&cheap, x);
    let wide = |lo: f64, hi: f64| hi - lo > target * lo.abs().max(hi.abs());
    if let (true, Some(value)) = (wide(blo, bhi), value) {
        let tight = |x: f64| {
            let c = cheap(x);
            if c.sign().is_some() {
                c
            } else {
                c.intersect(value(x)).unwrap_or(c)
            }
        };
        // The cheap bracket holds the root: the tight one is searched inside it, from a guess
        // by regula falsi (Illinois) on the tight enclosure's midpoints, a much better guess
        // than the cheap polynomial's Newton root (nothing certified: only where to start).
        let guess = illinois(&|x| tight(x).mid(), blo, bhi, bx);
        let (l, h, bx2) = certified_bracket(&tight, (blo, slo), (bhi, shi), guess, slope);
        (blo, bhi, bx) = (l, h, bx2);
    }
    let value = if bhi <= next_up(blo) {
        if f(blo).abs() <= f(bhi).abs() {
            blo
        } else {
            bhi
        }
    } else if (blo..=bhi).contains(&bx) {
        bx
    } else {
        0.5 * blo + 0.5 * bhi
    };
    Ok(Bracket {
        lo: blo,
        hi: bhi,
        value,
    })
}

/// A few steps of the Illinois variant of regula falsi for a root of `f` in `[a, b]`; `x` when
/// `f` has no sign change there (or a step leaves the interval).
fn illinois(f: &dyn Fn(f64) -> f64, mut a: f64, mut b: f64, x: f64) -> f64 {
    let (mut fa, mut fb) = (f(a), f(b));
    if fa * fb >= 0.0 || (fa * fb).is_nan() {
        return x;
    }
    let mut side = 0;
    let mut c = x;
    for step in 0..ILLINOIS_STEPS {
        let next = (a * fb - b * fa) / (fb - fa);
        if !(next > a && next < b) {
            // Converged onto an end (or lost): the last point inside is the best guess.
            return if step == 0 { x } else { c };
        }
        // Converged to a few ulps, or the last step: no further value is needed.
        let converged = step > 0 && (next - c).abs() <= 4.0 * f64::EPSILON * next.abs();
        c = next;
        if converged || step + 1 == ILLINOIS_STEPS {
            break;
        }
        let fc = f(c);
        if fc == 0.0 {
            break;
        }
        if fc * fb < 0.0 {
            (a, fa) = (b, fb);
            if side == 1 {
                fa *= 0.5;
            }
            side = 1;
        } else {
            if side == -1 {
                fa *= 0.5;
            }
            side = -1;
        }
        (b, fb) = (c, fc);
    }
    c
}

/// How many steps [`illinois`] takes.
const ILLINOIS_STEPS: usize = 4;

/// The narrowest bracket around `x` within `(lo, hi)` (whose ends have the known signs `slo`,
/// `shi`) that `enclose` certifies: half-width from the enclosure's width over `slope`, doubled
/// until both ends have certain, opposite signs; a root found outside moves the search to its
/// side (first next to the end passed, then to the middle of what is left). Returns the
/// bracket and its centre.
fn certified_bracket(
    enclose: &dyn Fn(f64) -> I,
    (mut lo, slo): (f64, f64),
    (mut hi, shi): (f64, f64),
    mut x: f64,
    slope: f64,
) -> (f64, f64, f64) {
    if hi <= next_up(lo) {
        return (lo, hi, x);
    }
    let ulp = next_up(x.abs()) - x.abs();
    let start = {
        let v = enclose(x);
        let guess = 0.5 * (v.hi - v.lo) / slope;
        if guess.is_finite() {
            guess.max(2.0 * ulp)
        } else {
            2.0 * ulp
        }
    };
    let (mut delta, mut nudged) = (start, false);
    loop {
        let (a, b) = (x - delta, x + delta);
        if a <= lo && b >= hi {
            return (lo, hi, x);
        }
        let (a, b) = (a.max(lo), b.min(hi));
        let sign = |t: f64, end: f64, s: f64| if t == end { Some(s) } else { enclose(t).sign() };
        // The root outside [a, b] on one side: that end moves in, and the centre next to it.
        let next_to = match (sign(a, lo, slo), sign(b, hi, shi)) {
            (Some(sa), Some(sb)) if sa == slo && sb == shi => return (a, b, x),
            (Some(sa), _) if sa == shi => {
                hi = a;
                a - delta
            }
            (_, Some(sb)) if sb == slo => {
                lo = b;
                b + delta
            }
            _ => {
                delta *= 2.0;
                continue;
            }
        };
        // The first time, the bracket of the same width next to the end passed (a guess within
        // the enclosure's noise is off by about one half-width); after that, the middle of
        // what is left.
        if nudged {
            (x, delta) = (0.5 * lo + 0.5 * hi, start);
        } else {
            (x, nudged) = (next_to, true);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Enclosures of relative half-width `rel` around `m 10^e 10^scale` for each `(m, e)`.
    fn enclosures(coefficients: &[(f64, i32)], rel: f64, scale: i32) -> Vec<I> {
        coefficients
            .iter()
            .map(|(m, e)| {
                let m = m * 10f64.powi(*e) * 10f64.powi(scale);
                I::new(m - m.abs() * rel, m + m.abs() * rel)
            })
            .collect()
    }

    /// Coefficient vectors of the box `b` to check exactly: every lower end, every upper end
    /// (the extremes of any combination with nonnegative weights), the corner `corner` and an
    /// interior point.
    fn corners(b: &[I], corner: &[bool]) -> [Vec<f64>; 4] {
        [
            b.iter().map(|c| c.lo).collect(),
            b.iter().map(|c| c.hi).collect(),
            b.iter()
                .zip(corner)
                .map(|(c, k)| if *k { c.hi } else { c.lo })
                .collect(),
            b.iter().map(|c| c.lo + 0.75 * (c.hi - c.lo)).collect(),
        ]
    }

    /// The exact value `e` lies in the node's coefficient `(m, r)`, or the node claims nothing
    /// about it (an infinite radius, no sign).
    fn holds(node: &Node, j: usize, e: &num_rational::BigRational) -> bool {
        let (m, r) = node.c[j];
        if !r.is_finite() {
            return node.sign(j).is_none();
        }
        let q = |v: f64| num_rational::BigRational::from_float(v).expect("finite");
        q(m) - q(r) <= *e && *e <= q(m) + q(r)
    }

    /// De Casteljau's subdivision at `t` in exact rationals: (left, right).
    fn exact_split(
        mut w: Vec<num_rational::BigRational>,
        t: &num_rational::BigRational,
    ) -> (
        Vec<num_rational::BigRational>,
        Vec<num_rational::BigRational>,
    ) {
        let n = w.len() - 1;
        let a = num_rational::BigRational::from_integer(1.into()) - t;
        let mut l = vec![w[0].clone()];
        let mut r = vec![w[n].clone()];
        for level in 1..=n {
            for j in 0..=n - level {
                w[j] = &a * &w[j] + t * &w[j + 1];
            }
            l.push(w[0].clone());
            r.push(w[n - level].clone());
        }
        r.reverse();
        (l, r)
    }

    /// Magnitudes the property tests scale their coefficients by: ordinary, tiny (down to
    /// subnormal, where the underflow floors matter) and huge (sums overflow).
    const SCALES: [i32; 4] = [0, -300, -315, 296];

    proptest::proptest! {
        /// The Bernstein coefficients in f64 with their radii (`Node::bernstein`) enclose the
        /// exact ones, in rationals, of every polynomial with coefficients in the enclosures
        /// (all lower ends, all upper ends, a corner and an interior point), for magnitudes
        /// that differ by many orders, tiny and huge ones, and wide or point enclosures, up to
        /// the degree where the conversion is in f64 and beyond.
        #[test]
        fn bernstein_coefficients_in_f64_enclose_the_exact_ones(
            coefficients in proptest::collection::vec((-1.0f64..1.0, -12i32..12), 2..60),
            rel in proptest::sample::select(vec![0.0, 1e-15, 1e-9, 1e-3]),
            scale in proptest::sample::select(SCALES.to_vec()),
            corner in proptest::collection::vec(proptest::bool::ANY, 60),
        ) {
            use num_rational::BigRational;
            let q = |v: f64| BigRational::from_float(v).expect("finite");
            let a = enclosures(&coefficients, rel, scale);
            let n = a.len() - 1;
            let node = Node::bernstein(&a).expect("within the degree limit");
            let binomial = |n: usize, k: usize| -> BigRational {
                let mut c = num_bigint::BigInt::from(1);
                for i in 0..k {
                    c = c * (n - i) / (i + 1);
                }
                BigRational::from_integer(c)
            };
            for chosen in corners(&a, &corner) {
                for j in 0..=n {
                    let exact = (0..=j).fold(BigRational::from_integer(0.into()), |acc, i| {
                        acc + binomial(j, i) / binomial(n, i) * q(chosen[i])
                    });
                    proptest::prop_assert!(
                        holds(&node, j, &exact),
                        "b_{j} of degree {n}: {:?} misses {exact}",
                        node.c[j]
                    );
                }
            }
        }

        /// De Casteljau's subdivision in f64 with its radii (`Node::split`), applied twice,
        /// encloses the exact subdivision, in rationals, of every coefficient vector in the
        /// node's enclosures (all lower ends, all upper ends, a corner and an interior point),
        /// at every split point the isolation uses, for magnitudes that differ by many orders,
        /// tiny and huge ones, and wide or point enclosures.
        #[test]
        fn subdivision_in_f64_encloses_the_exact_subdivision(
            coefficients in proptest::collection::vec((-1.0f64..1.0, -12i32..12), 2..24),
            rel in proptest::sample::select(vec![0.0, 1e-15, 1e-9, 1e-3]),
            scale in proptest::sample::select(SCALES.to_vec()),
            corner in proptest::collection::vec(proptest::bool::ANY, 24),
            which in 0usize..15,
        ) {
            use num_rational::BigRational;
            let q = |v: f64| BigRational::from_float(v).expect("finite");
            let b = enclosures(&coefficients, rel, scale);
            // The guided splits' sixteenths (which include the fixed weights 0.4375 ... 0.625).
            let t = (which + 1) as f64 / 16.0;
            let (left, right) = Node::of(&b).split(t, &mut Vec::new());
            let (left_right, _) = right.split(t, &mut Vec::new());
            for chosen in corners(&b, &corner) {
                let w: Vec<BigRational> = chosen.iter().map(|v| q(*v)).collect();
                let (l, r) = exact_split(w, &q(t));
                let (rl, _) = exact_split(r.clone(), &q(t));
                for (node, exact) in [(&left, &l), (&right, &r), (&left_right, &rl)] {
                    for (j, e) in exact.iter().enumerate() {
                        proptest::prop_assert!(
                            holds(node, j, e),
                            "coefficient {j}: {:?} misses {e} for t = {t}",
                            node.c[j]
                        );
                    }
                }
            }
        }
    }

    proptest::proptest! {
        /// Degrees 1 and 2 in closed form: every answer counts the exact positive roots (in
        /// rationals: Descartes' count and the discriminant's sign) of the polynomial at the
        /// enclosures' lower ends, upper ends and midpoints, and each bracket holds a sign
        /// change of each; the brackets are finite, positive, sorted and disjoint. A refusal
        /// (`None`) is always allowed: the bisection takes the polynomial.
        #[test]
        fn closed_forms_isolate_the_exact_positive_roots(
            c in proptest::collection::vec((-1.0f64..1.0, -40i32..40, 0u8..4), 2..4),
            rel in proptest::sample::select(vec![0.0, 1e-15, 1e-6]),
        ) {
            use num_rational::BigRational;
            let q = |v: f64| BigRational::from_float(v).expect("finite");
            let zero = || BigRational::from_integer(0.into());
            let last = c.len() - 1;
            let box_: Vec<I> = c
                .iter()
                .enumerate()
                .map(|(i, (m, e, kind))| {
                    let m = m * 10f64.powi(*e);
                    // The middle coefficient of a quadratic may be an exact zero.
                    if *kind == 0 && i != 0 && i != last {
                        return I::point(0.0);
                    }
                    I::new(m - m.abs() * rel, m + m.abs() * rel)
                })
                .collect();
            proptest::prop_assume!(!box_[0].contains_zero() && !box_[last].contains_zero());
            let Some(found) = low_degree(&IPoly::new(box_.clone())) else {
                return Ok(());
            };
            for (k, (lo, hi, _)) in found.iter().enumerate() {
                proptest::prop_assert!(0.0 < *lo && lo < hi && hi.is_finite(), "{:?}", found);
                if k > 0 {
                    proptest::prop_assert!(found[k - 1].1 < *lo, "overlap in {:?}", found);
                }
            }
            for pick in 0..3 {
                let e: Vec<BigRational> = box_
                    .iter()
                    .map(|x| match pick {
                        0 => q(x.lo),
                        1 => q(x.hi),
                        _ => (q(x.lo) + q(x.hi)) / BigRational::from_integer(2.into()),
                    })
                    .collect();
                let value = |x: f64| e.iter().rev().fold(zero(), |acc, c| acc * q(x) + c);
                let positive = if e.len() == 2 {
                    usize::from(e[0].clone() * &e[1] < zero())
                } else {
                    let d = e[1].clone() * &e[1] - BigRational::from_integer(4.into()) * &e[0] * &e[2];
                    let changes = super::sign_changes(
                        e.iter().filter(|x| **x != zero()).map(|x| Some(if *x > zero() { 1.0 } else { -1.0 })),
                    )
                    .expect("exact signs");
                    if changes == 2 && d < zero() { 0 } else { changes }
                };
                proptest::prop_assert_eq!(found.len(), positive, "{:?} at {:?}", found, e);
                for (lo, hi, _) in &found {
                    proptest::prop_assert!(value(*lo) * value(*hi) < zero(), "no sign change on [{lo}, {hi}]");
                }
            }
        }
    }

    /// Guided splits keep 20 bits of the ends for bisection: a sixteenth of [0, 1] does; a
    /// node of width 2^-10 whose end has a bit at 2^-45 (finer than its grid 2^-30) does not;
    /// ends of every sign and zero are read by their lowest set bit.
    #[test]
    fn guided_splits_keep_bits_for_bisection() {
        assert!(keeps_bits(0.0, 0.4375, 1.0));
        assert!(keeps_bits(-1.0, -0.125, 1.0));
        let tl = 0.5 + 2f64.powi(-45);
        let tr = tl + 2f64.powi(-10);
        assert!(!keeps_bits(tl, tl + 7.0 * 2f64.powi(-14), tr));
        let tl = 0.5 + 2f64.powi(-30);
        assert!(keeps_bits(
            tl,
            tl + 7.0 * 2f64.powi(-14),
            tl + 2f64.powi(-10)
        ));
        // Width 2^-40: the grid is 2^-60, and ends that are multiples of 2^-60 pass.
        let a = 2f64.powi(-20) + 2f64.powi(-60);
        let b = a + 2f64.powi(-40);
        assert!(keeps_bits(a, a + 2f64.powi(-41), b));
        assert!(!keeps_bits(a, a + 2f64.powi(-61), b));
        // A subnormal width: no guided split.
        assert!(!keeps_bits(0.0, f64::from_bits(1), f64::from_bits(2)));
    }

    /// A split point is exact or there is no split: 7/16 of an interval whose width needs all
    /// 53 bits is not a double.
    #[test]
    fn split_points_are_exact_or_refused() {
        assert_eq!(split_point(0.0, 1.0, 0.4375), Some(0.4375));
        assert_eq!(split_point(0.25, 0.5, 0.5), Some(0.375));
        assert_eq!(split_point(0.0, 1.0 - f64::EPSILON, 0.4375), None);
        // The middle of an interval one ulp wide is not a double.
        assert_eq!(split_point(1.0, 1.0 + f64::EPSILON, 0.5), None);
    }

    /// A sum that overflows is no sign: the Bernstein coefficients of this
    /// polynomial of degree 10 with coefficients near `f64::MAX` overflow to +inf while two of
    /// the exact ones are negative, and a node that read +inf as positive proved "no roots". It
    /// has two positive roots, near 0.82 and 0.9 (exact values of opposite signs at 0.8, 0.85
    /// and 0.95; Descartes' rule on the signs + + - - + allows at most two): the isolation
    /// must find them or give up, never answer that there are none.
    #[test]
    fn an_overflowing_sum_is_no_sign() {
        let m = f64::MAX;
        let c = [
            0.6 * m,
            0.6 * m,
            -m,
            -0.99 * m,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            m,
        ];
        let q = |v: f64| num_rational::BigRational::from_float(v).expect("finite");
        let value = |x: f64| c.iter().rev().fold(q(0.0), |acc, a| acc * q(x) + q(*a));
        let zero = q(0.0);
        assert!(value(0.8) > zero && value(0.85) < zero && value(0.95) > zero);
        match positive_roots(&p(&c)) {
            Ok(r) => {
                assert_eq!(r.len(), 2, "{r:?}");
                assert!(r[0].lo < 0.85 && r[0].hi > 0.8 && r[1].lo > 0.85 && r[1].hi < 0.95);
            }
            // Giving up (the exact path then answers) is allowed; a wrong count is not.
            Err(Uncertified::Budget | Uncertified::Sign | Uncertified::Degenerate) => {}
            Err(why) => panic!("{why:?}"),
        }
    }

    fn p(c: &[f64]) -> IPoly {
        IPoly::new(c.iter().map(|x| I::point(*x)).collect())
    }

    #[test]
    fn well_conditioned_roots_are_bracketed_to_a_few_ulps() {
        // (x - 1/3)(x - 2)(x - 1000)(x + 5): positive roots 1/3, 2, 1000.
        let f = p(&[-1.0 / 3.0, 1.0]);
        let q = f
            .mul(&p(&[-2.0, 1.0]))
            .mul(&p(&[-1000.0, 1.0]))
            .mul(&p(&[5.0, 1.0]));
        let r = positive_roots(&q).expect("simple, well separated roots");
        assert_eq!(r.len(), 3);
        for (b, want) in r.iter().zip([1.0 / 3.0, 2.0, 1000.0]) {
            assert!(b.lo <= want && want <= b.hi, "{b:?} vs {want}");
            // The running error bound of Horner's scheme widens each step by an ulp or two of
            // the partial sum, and the bracket is within a factor two of what that enclosure
            // can certify.
            assert!(b.hi - b.lo <= 64.0 * f64::EPSILON * want, "{b:?}");
        }
    }

    #[test]
    fn even_polynomials_are_isolated_in_the_square_with_the_same_brackets() {
        // q(u) = (u - 1/10)(u - 3)(u - 9)(u + 1), p(x) = q(x^2): positive roots of p at
        // sqrt(1/10), sqrt(3) and 3, and p is given only through its local expansions.
        let q = p(&[-0.1, 1.0])
            .mul(&p(&[-3.0, 1.0]))
            .mul(&p(&[-9.0, 1.0]))
            .mul(&p(&[1.0, 1.0]));
        let px = IPoly::new(
            q.coeffs()
                .iter()
                .flat_map(|c| [*c, I::point(0.0)])
                .take(2 * q.coeffs().len() - 1)
                .collect(),
        );
        assert_eq!(px.in_square().as_ref(), Some(&q));
        let value = |x: f64| px.eval(I::point(x));
        let (local, local_u) = (
            |x0: f64| px.shift(I::point(x0)),
            |u0: f64| q.shift(I::point(u0)),
        );
        let even = positive_roots_windowed_even(&q, &local_u, &local, &value, 1e-12).unwrap();
        let direct = positive_roots_windowed(&px, &local, &value, 1e-12).unwrap();
        assert_eq!(even.len(), 3);
        for ((b, d), want) in even
            .iter()
            .zip(&direct)
            .zip([0.1f64.sqrt(), 3f64.sqrt(), 3.0])
        {
            assert!(b.lo <= want && want <= b.hi, "{b:?} vs {want}");
            assert!(b.relative_width() <= 1e-12, "{b:?}");
            assert!(d.lo <= b.hi && b.lo <= d.hi, "{b:?} vs {d:?}");
        }
        // A root on a window end in u (u = 2) cannot be decided there: an error, not an answer
        // (the caller then isolates in x).
        let on_end = p(&[-2.0, 1.0]).mul(&p(&[1.0, 1.0]));
        let local_u = |u0: f64| on_end.shift(I::point(u0));
        let r = positive_roots_windowed_even(&on_end, &local_u, &local, &value, 1e-12);
        assert_eq!(r, Err(Uncertified::Sign));
        // An odd coefficient that cannot vanish: not even, refused.
        assert_eq!(p(&[1.0, 1e-300, 1.0]).in_square(), None);
    }

    #[test]
    fn undecidable_cases_are_errors_not_answers() {
        // A double root: the Bernstein signs never separate it.
        let d = p(&[-1.0, 1.0]).mul(&p(&[-1.0, 1.0])).mul(&p(&[3.0, 1.0]));
        assert!(positive_roots(&d).is_err());
        // A constant term that may vanish.
        let z = IPoly::new(vec![I::new(-1e-20, 1e-20), I::point(1.0), I::point(1.0)]);
        assert_eq!(positive_roots(&z), Err(Uncertified::Degenerate));
        // No positive roots: x^2 + 1.
        assert_eq!(positive_roots(&p(&[1.0, 0.0, 1.0])), Ok(Vec::new()));
    }

    /// Two roots 1.8e-7 apart (0.62795908, 0.62795926) and a third at 1.8933: guided splits at
    /// sixteenths alone would use up the bits of the nodes' ends near the pair (no exact split
    /// point after 15 levels); yielding to bisection isolates all three.
    #[test]
    fn guided_splits_leave_clustered_roots_isolable() {
        let c = [
            -0.7465876718488366,
            2.7721550534404242,
            -3.149212077114739,
            1.0,
        ];
        let found = positive_roots(&p(&c)).expect("bisection certifies these roots");
        assert_eq!(found.len(), 3, "{found:?}");
        for (b, (root, tolerance)) in
            found
                .iter()
                .zip([(0.62795908, 5e-8), (0.62795926, 5e-8), (1.8932937, 1e-7)])
        {
            assert!((b.value - root).abs() < tolerance, "{b:?} against {root}");
        }
    }

    /// A root beyond the range of doubles' bound: -1e10 + 1e-300 x^3 has its root near
    /// 2.2e103, but the root bound overflows; a bracket is finite or the answer is an error.
    #[test]
    fn brackets_are_finite_or_refused() {
        let c = p(&[-1e10, 0.0, 0.0, 1e-300]);
        match positive_roots(&c) {
            Ok(found) => {
                for b in &found {
                    assert!(
                        b.lo.is_finite() && b.hi.is_finite() && b.value.is_finite(),
                        "{b:?}"
                    );
                }
            }
            Err(e) => assert_eq!(e, Uncertified::Wide),
        }
    }
}
