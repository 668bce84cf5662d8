//! Local refinement of an isolated root on the original polynomial: Newton steps (and Illinois
//! steps where Newton stalls) in f64 propose a point, and a bracket around it is certified by
//! the signs of enclosures of the values at its ends, from the narrowest width the enclosure
//! can certify, doubling.

use super::*;

/// A polynomial near its root as [`refine_local`] uses it: a cheap enclosure of its value and
/// floating-point values of it and its derivative, made once per polynomial (every root of it
/// is refined on the same one).
pub(super) struct Local<'a> {
    /// The expansion in `y = x - x0`.
    pub(super) q: &'a IPoly,
    pub(super) x0: f64,
    /// `q` made ready for evaluation at doubles (`x0 = 0`: `y = x` exactly).
    pub(super) at_point: Option<PointEnclosure<'a>>,
    /// The midpoint polynomial for Newton's method, in `y^2` where it is even or odd in `y`
    /// (the criterion polynomials are, about P0 = 0): half the steps of Horner's scheme.
    pub(super) f: Midpoint,
}

/// A polynomial of doubles `f(y)`, given as `g(y^2)` (even), `y g(y^2)` (odd) or itself.
pub(super) enum Midpoint {
    Even(F64Poly),
    Odd(F64Poly),
    General(F64Poly),
}

impl Midpoint {
    /// The midpoints of `q`'s coefficients, with the parity their exact zeros show.
    pub(super) fn of(q: &IPoly) -> Midpoint {
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
    pub(super) fn value_slope(&self, y: f64) -> (f64, f64) {
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
    pub(super) fn of(q: &IPoly, x0: f64) -> Local<'_> {
        Local {
            q,
            x0,
            at_point: (x0 == 0.0).then(|| PointEnclosure::new(q)),
            f: Midpoint::of(q),
        }
    }

    /// An enclosure of the value at `x`.
    pub(super) fn cheap(&self, x: f64) -> I {
        match &self.at_point {
            Some(e) => e.at(x),
            None => self.q.eval(I::point(x) - I::point(self.x0)),
        }
    }

    /// The floating-point value and derivative at `x` (nothing certified).
    pub(super) fn f_df(&self, x: f64) -> (f64, f64) {
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
pub(super) fn keeps_bits(tl: f64, tm: f64, tr: f64) -> bool {
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
pub(super) fn split_point(tl: f64, tr: f64, t: f64) -> Option<f64> {
    let p = I::point(tl) + I::point(t) * (I::point(tr) - I::point(tl));
    (p.lo == p.hi && p.lo > tl && p.lo < tr).then_some(p.lo)
}

/// How many ulps a Newton step of [`refine_local`] may move and still count as converged.
pub(super) const NEWTON_ULPS: f64 = 16.0;

/// Refines the bracket `[lo, hi]` of the single root of `p` in it, to relative width `target`
/// if the enclosures allow.
///
/// A guess first, by safeguarded Newton on the midpoint polynomial (nothing certified). Then a
/// bracket around the guess certified by the signs of the cheap enclosure ([`Local::cheap`]),
/// starting from the enclosure's half-width over the slope (the narrowest bracket it can
/// possibly certify) and doubling; only when that is wider than `target` is the same done with
/// `value` (a tighter, costlier enclosure), intersected with the cheap one.
pub(super) fn refine_local(
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
pub(super) fn illinois(f: &dyn Fn(f64) -> f64, mut a: f64, mut b: f64, x: f64) -> f64 {
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
pub(super) const ILLINOIS_STEPS: usize = 4;

/// The narrowest bracket around `x` within `(lo, hi)` (whose ends have the known signs `slo`,
/// `shi`) that `enclose` certifies: half-width from the enclosure's width over `slope`, doubled
/// until both ends have certain, opposite signs; a root found outside moves the search to its
/// side (first next to the end passed, then to the middle of what is left). Returns the
/// bracket and its centre.
pub(super) fn certified_bracket(
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
