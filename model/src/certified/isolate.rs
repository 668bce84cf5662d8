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
//! Step 1 and the entry points are here; the root bounds are in `isolate/bounds.rs`, step 2 in
//! `isolate/bernstein.rs`, step 3 in `isolate/local.rs`, and the refinement of a high-degree
//! polynomial's roots on Taylor expansions in windows in `isolate/windowed.rs`.
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

mod bernstein;
mod bounds;
mod local;
#[cfg(test)]
mod tests;
mod windowed;

use super::dense::{IPoly, PointEnclosure};
use crate::interval::{next_down, next_up, I};
use crate::roots::F64Poly;
use bernstein::{isolate_unit, isolate_unit_ends, sign_changes};
use bounds::root_bound;
use local::{refine_local, Local};
pub use windowed::{positive_roots_windowed, positive_roots_windowed_even, MAX_WINDOW_SPLITS};

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

/// An isolating interval `(lo, hi, guess)`: exactly one root in `[lo, hi]` (strictly inside),
/// and a guess of where (a heuristic for the refinement's start only; NaN for none).
type Isolating = (f64, f64, f64);
