//! Dense polynomials in P0, and in P0 and delta_a, with enclosed coefficients ([`Num`]): the
//! criterion polynomials of one aircraft (or of a box of aircraft) enclosed in f64.
//!
//! Every operation is a finite sequence of additions and multiplications of enclosures (and,
//! for [`Dense::div_exact`], divisions by one that excludes zero), so each coefficient of a
//! result encloses the exact coefficient that the same operations give on the exact inputs.
//!
//! ```
//! use model::certified::dense::IPoly;
//! use model::interval::I;
//!
//! // (x + 1)(x - 2) = x^2 - x - 2 in exact (point) coefficients, and back by exact division.
//! let p = |c: &[f64]| IPoly::new(c.iter().map(|x| I::point(*x)).collect());
//! let (a, b) = (p(&[1.0, 1.0]), p(&[-2.0, 1.0]));
//! assert_eq!(a.mul(&b), p(&[-2.0, -1.0, 1.0]));
//! assert_eq!(a.mul(&b).div_exact(&a), Some(b));
//! ```

use super::num::Num;
use crate::interval::I;
use crate::roots::F64Poly;

/// A polynomial in one variable with enclosed coefficients, ascending; trailing coefficients
/// that are exact zeros are dropped, so the degree is exact whenever the leading coefficient
/// cannot vanish.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Dense<T>(pub Vec<T>);

/// A polynomial with interval coefficients.
pub type IPoly = Dense<I>;

impl<T: Num> Dense<T> {
    /// The zero polynomial.
    pub fn zero() -> Dense<T> {
        Dense(Vec::new())
    }

    /// The constant `c`.
    pub fn constant(c: T) -> Dense<T> {
        Dense(vec![c]).trimmed()
    }

    /// From ascending coefficients.
    pub fn new(c: Vec<T>) -> Dense<T> {
        Dense(c).trimmed()
    }

    fn trimmed(mut self) -> Dense<T> {
        while self.0.last().is_some_and(|c| c.is_exact_zero()) {
            self.0.pop();
        }
        self
    }

    /// The degree (`None` for the zero polynomial). Exact only when the leading coefficient
    /// excludes zero.
    pub fn degree(&self) -> Option<usize> {
        self.0.len().checked_sub(1)
    }

    /// Whether this is exactly the zero polynomial.
    pub fn is_zero(&self) -> bool {
        self.0.is_empty()
    }

    /// The coefficients.
    pub fn coeffs(&self) -> &[T] {
        &self.0
    }

    /// `self + o`.
    pub fn add(&self, o: &Dense<T>) -> Dense<T> {
        let n = self.0.len().max(o.0.len());
        let zero = T::constant(I::point(0.0));
        Dense::new(
            (0..n)
                .map(|i| {
                    let a = self.0.get(i).copied().unwrap_or(zero);
                    let b = o.0.get(i).copied().unwrap_or(zero);
                    a + b
                })
                .collect(),
        )
    }

    /// `self += a * b`, in place (the product's terms added one by one: no temporary).
    pub fn add_product(&mut self, a: &Dense<T>, b: &Dense<T>) {
        if a.is_zero() || b.is_zero() {
            return;
        }
        let n = a.0.len() + b.0.len() - 1;
        if self.0.len() < n {
            grow(&mut self.0, n);
            self.0.resize(n, T::constant(I::point(0.0)));
        }
        for (i, x) in a.0.iter().enumerate() {
            if x.is_exact_zero() {
                continue;
            }
            // An exact zero term adds nothing (and adding it would only widen the sum by an
            // ulp): the even and odd polynomials in P0 have every other coefficient zero.
            for (j, y) in b.0.iter().enumerate() {
                if !y.is_exact_zero() {
                    self.0[i + j] = self.0[i + j] + *x * *y;
                }
            }
        }
        while self.0.last().is_some_and(|c| c.is_exact_zero()) {
            self.0.pop();
        }
    }

    /// `-self`.
    pub fn neg(&self) -> Dense<T> {
        Dense(self.0.iter().map(|c| -*c).collect())
    }

    /// `self - o`.
    pub fn sub(&self, o: &Dense<T>) -> Dense<T> {
        self.add(&o.neg())
    }

    /// `self * o`.
    pub fn mul(&self, o: &Dense<T>) -> Dense<T> {
        if self.is_zero() || o.is_zero() {
            return Dense::zero();
        }
        let mut r = vec![T::constant(I::point(0.0)); self.0.len() + o.0.len() - 1];
        for (i, a) in self.0.iter().enumerate() {
            if a.is_exact_zero() {
                continue;
            }
            for (j, b) in o.0.iter().enumerate() {
                if !b.is_exact_zero() {
                    r[i + j] = r[i + j] + *a * *b;
                }
            }
        }
        Dense::new(r)
    }

    /// `c * self`.
    pub fn scale(&self, c: T) -> Dense<T> {
        Dense::new(self.0.iter().map(|a| *a * c).collect())
    }

    /// `self^k`.
    pub fn pow(&self, k: u32) -> Dense<T> {
        (0..k).fold(Dense::constant(T::constant(I::point(1.0))), |acc, _| {
            acc.mul(self)
        })
    }

    /// The value at `x` by Horner's scheme (an enclosure of the range over `x`).
    pub fn eval(&self, x: T) -> T {
        horner(&self.0, x)
    }

    /// `self(x0 + y)` as a polynomial in `y` (the Taylor expansion at `x0`, enclosed), by
    /// repeated synthetic division in place.
    pub fn shift(&self, x0: T) -> Dense<T> {
        let mut a = self.0.clone();
        let n = a.len();
        for i in 0..n {
            for j in (i..n - 1).rev() {
                a[j] = a[j] + x0 * a[j + 1];
            }
        }
        Dense::new(a)
    }

    /// The derivative.
    pub fn derivative(&self) -> Dense<T> {
        Dense::new(
            self.0
                .iter()
                .enumerate()
                .skip(1)
                .map(|(i, c)| *c * T::constant(I::point(i as f64)))
                .collect(),
        )
    }

    /// `self / d` for a `d` that divides `self` exactly in exact arithmetic: an enclosure of the
    /// exact quotient, or `None` when the division cannot be certified (`d`'s leading and
    /// constant coefficients may both vanish) or the enclosure of the remainder excludes zero
    /// (then `d` does not divide `self`, and the caller's structural claim fails for these data).
    ///
    /// Long division from the top determines the high coefficients of the quotient well and
    /// passes its rounding errors down to the low ones; division from the bottom (as of power
    /// series, when `d(0) != 0`) does the opposite. For an exact division both compute the same
    /// exact quotient, so both enclosures hold and their intersection is kept.
    pub fn div_exact(&self, d: &Dense<T>) -> Option<Dense<T>> {
        let (Some(n), Some(m)) = (self.degree(), d.degree()) else {
            return d.degree().map(|_| Dense::zero());
        };
        if n < m {
            return self.0.iter().all(|c| c.may_vanish()).then(Dense::zero);
        }
        let top = self.div_from_top(d, n, m);
        let bottom = self.div_from_bottom(d, n, m);
        match (top, bottom) {
            (Some(a), Some(b)) => {
                let q: Option<Vec<T>> = a.iter().zip(&b).map(|(x, y)| x.meet(*y)).collect();
                q.map(Dense::new)
            }
            (Some(a), None) | (None, Some(a)) => Some(Dense::new(a)),
            (None, None) => None,
        }
    }

    fn div_from_top(&self, d: &Dense<T>, n: usize, m: usize) -> Option<Vec<T>> {
        let lead = d.0[m];
        if lead.may_vanish() {
            return None;
        }
        let mut r = self.0.clone();
        let mut q = vec![T::constant(I::point(0.0)); n - m + 1];
        for k in (0..=n - m).rev() {
            let c = r[k + m].div(lead)?;
            q[k] = c;
            for (j, dj) in d.0.iter().enumerate() {
                r[k + j] = r[k + j] - c * *dj;
            }
        }
        r[..m].iter().all(|c| c.may_vanish()).then_some(q)
    }

    fn div_from_bottom(&self, d: &Dense<T>, n: usize, m: usize) -> Option<Vec<T>> {
        let d0 = d.0[0];
        if d0.may_vanish() {
            return None;
        }
        let mut r = self.0.clone();
        let mut q = vec![T::constant(I::point(0.0)); n - m + 1];
        for k in 0..=n - m {
            let c = r[k].div(d0)?;
            q[k] = c;
            for (j, dj) in d.0.iter().enumerate() {
                r[k + j] = r[k + j] - c * *dj;
            }
        }
        r[n - m + 1..].iter().all(|c| c.may_vanish()).then_some(q)
    }
}

impl IPoly {
    /// The polynomial with every coefficient whose index has the other parity than the degree
    /// set to an exact zero.
    ///
    /// For a polynomial with `p(-x) = (-1)^n p(x)` exactly, those coefficients *are* zero and
    /// their enclosures carry only rounding; zeroing them removes that noise (and lets
    /// [`super::isolate`] work in `x^2`). Every criterion polynomial in P0 has that symmetry:
    /// with `delta_r = 0` the PSS model is invariant under `(P0, beta, r, delta_a) -> -(...)`
    /// (and the zero-sideslip trim, which frees the rudder, under the same with `delta_r`), so
    /// det A, the trims' determinants, det J5 and d on the trim, and the resultants that
    /// eliminate delta_a are even or odd in P0. Unchanged when the degree is uncertain (the
    /// leading coefficient may vanish).
    pub fn symmetric(&self) -> IPoly {
        let Some(n) = self.degree() else {
            return self.clone();
        };
        if self.0[n].contains_zero() {
            return self.clone();
        }
        IPoly::new(
            self.0
                .iter()
                .enumerate()
                .map(|(i, c)| if (n - i) % 2 == 0 { *c } else { I::point(0.0) })
                .collect(),
        )
    }

    /// `q` with `p(x) = q(x^2)`, for a polynomial known to be even (`p(-x) = p(x)` exactly,
    /// see [`IPoly::symmetric`]): its odd coefficients are zero, and their enclosures carry
    /// only rounding. `None` when one of them excludes zero (the polynomial is not even).
    pub fn in_square(&self) -> Option<IPoly> {
        if self.0.iter().skip(1).step_by(2).any(|c| !c.contains_zero()) {
            return None;
        }
        Some(IPoly::new(self.0.iter().step_by(2).copied().collect()))
    }

    /// `p(-x)`.
    pub fn mirror(&self) -> IPoly {
        IPoly::new(
            self.0
                .iter()
                .enumerate()
                .map(|(i, c)| if i % 2 == 1 { -*c } else { *c })
                .collect(),
        )
    }

    /// The midpoints of the coefficients, for floating-point evaluation.
    pub fn mid(&self) -> F64Poly {
        F64Poly(self.0.iter().map(|c| c.mid()).collect())
    }
}

/// A polynomial in P0 and delta_a: `self.0[i]` (a polynomial in P0) multiplies `delta_a^i`.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Dense2<T>(pub Vec<Dense<T>>);

/// The value at `x` of the polynomial with ascending coefficients `c`, by Horner's scheme: the
/// one evaluation of enclosed coefficients (an enclosure of the range over `x`).
pub fn horner<T: Num>(c: &[T], x: T) -> T {
    let mut acc = T::constant(I::point(0.0));
    for c in c.iter().rev() {
        acc.mul_add_assign(&x, c);
    }
    acc
}

/// A polynomial with enclosed coefficients, made ready to enclose its value at many doubles
/// (root refinement evaluates it a few times per root): Horner's scheme in f64 on the midpoint
/// polynomial with a running bound on its rounding error, instead of [`horner`] in intervals
/// (outward-rounded interval products and sums, several times the work). The enclosure is
/// about as tight: both widen by an ulp or two of each partial sum.
///
/// The bound, for midpoints `m_i` and radii `r_i` (`|c_i - m_i| <= r_i` for every coefficient
/// `c_i` in the enclosures), `u = 2^-53` and a double `x`:
/// - the coefficients: `|p_c(x) - p_m(x)| <= sum r_i |x|^i`;
/// - Horner's rounding (the running error analysis of Higham, *Accuracy and Stability of
///   Numerical Algorithms*, 2nd ed., section 5.1): with `q_k = fl(x y_(k+1))` and
///   `y_k = fl(q_k + m_k)`, step `k` is off by at most `u / (1 - u) (|q_k| + |y_k|)`, and that
///   error reaches the value multiplied by `x^k`; so `|p_m(x) - y_0| <= u / (1 - u) E` with
///   `E = sum_k (|q_k| + |y_k|) |x|^k`. An underflowing product adds at most `2^-1075 |x|^k`,
///   which a floor of `2^-1000` added to every `r_k` covers;
/// - `E` and `R = sum r_k |x|^k` are accumulated by Horner's scheme in f64: sums of
///   nonnegative terms, each computed value at least `(1 - u)^3` of its exact step, so the
///   final `fl(fl(u' E) + R)` times `1 + g`, `g = (6 n + 8) u`, rounded up, bounds the error.
///   `R` has no underflow for `|x| >= 2^-20` (every partial sum is at least `2^-1000`). `E` may
///   (tiny midpoints): each such step loses at most `2^-1075 |x|^k`, times `u'` in the bound,
///   far less than the slack `g R >= g 2^-1000 |x|^k` that the inflation leaves.
///
/// The enclosure is `y_0 -+ that bound`, rounded outward. Outside that range of `x`, and wherever
/// anything overflows, it is [`horner`] in intervals.
#[derive(Clone, Debug)]
pub struct PointEnclosure<'a> {
    poly: &'a IPoly,
    mid: Vec<f64>,
    rad: Vec<f64>,
    /// `1 + g`, exact.
    factor: f64,
}

/// Below this `|x|`, [`PointEnclosure::at`] is [`horner`] in intervals.
const MIN_POINT: f64 = 1.0 / (1u64 << 20) as f64;

/// What [`PointEnclosure`] adds to each coefficient's radius for underflow: `2^-1000` (biased
/// exponent 1023 - 1000, zero mantissa).
const FLOOR: f64 = f64::from_bits(23 << 52);

impl<'a> PointEnclosure<'a> {
    /// Prepares `poly`.
    pub fn new(poly: &'a IPoly) -> PointEnclosure<'a> {
        let n = poly.0.len().saturating_sub(1);
        let up = crate::interval::next_up;
        let (mid, rad) = poly
            .0
            .iter()
            .map(|c| {
                let (m, r) = c.mid_rad();
                (m, up(r + FLOOR))
            })
            .unzip();
        PointEnclosure {
            poly,
            mid,
            rad,
            // (6 n + 8) 2^-53 = (3 n + 4) 2^-52: exact, and so is 1 + g below degree 2^50.
            factor: 1.0 + (3 * n + 4) as f64 * f64::EPSILON,
        }
    }

    /// An enclosure of the value at `x` of every polynomial with coefficients in the
    /// enclosures.
    pub fn at(&self, x: f64) -> I {
        let fallback = || self.poly.eval(I::point(x));
        let (Some((m_n, m)), Some((r_n, r))) = (self.mid.split_last(), self.rad.split_last())
        else {
            return fallback();
        };
        if m.is_empty() || !(x.abs() >= MIN_POINT && x.is_finite()) {
            return fallback();
        }
        let ax = x.abs();
        let (mut y, mut e, mut rc) = (*m_n, 0.0, *r_n);
        for (m_k, r_k) in m.iter().zip(r).rev() {
            let q = x * y;
            y = q + m_k;
            e = ax * e + q.abs() + y.abs();
            rc = ax * rc + r_k;
        }
        // u / (1 - u) <= next_up(u) = u (1 + 2^-52).
        let u = crate::interval::next_up(f64::EPSILON / 2.0);
        let t = crate::interval::next_up((u * e + rc) * self.factor);
        if !(y.is_finite() && t.is_finite()) {
            return fallback();
        }
        I::new(
            crate::interval::next_down(y - t),
            crate::interval::next_up(y + t),
        )
    }
}

/// Room for `n` coefficients in an accumulator of products (step 8's sums grow term by term
/// from nothing): at least eight, so that the criterion's sums (degree at most 12 in P0, 2 in
/// delta_a) rarely move.
fn grow<T>(v: &mut Vec<T>, n: usize) {
    if v.capacity() < n {
        v.reserve_exact(n.max(8).max(2 * v.capacity()) - v.len());
    }
}

/// A polynomial in P0 and delta_a with interval coefficients.
pub type IPoly2 = Dense2<I>;

impl<T: Num> Dense2<T> {
    /// The zero polynomial.
    pub fn zero() -> Dense2<T> {
        Dense2(Vec::new())
    }

    fn trimmed(mut self) -> Dense2<T> {
        while self.0.last().is_some_and(Dense::is_zero) {
            self.0.pop();
        }
        self
    }

    /// From the coefficients of `delta_a^0, delta_a^1, ...`.
    pub fn new(c: Vec<Dense<T>>) -> Dense2<T> {
        Dense2(c).trimmed()
    }

    /// The degree in delta_a (`None` for the zero polynomial).
    pub fn degree(&self) -> Option<usize> {
        self.0.len().checked_sub(1)
    }

    /// The coefficient of `delta_a^i` (zero beyond the degree).
    pub fn coeff(&self, i: usize) -> Dense<T> {
        self.0.get(i).cloned().unwrap_or_else(Dense::zero)
    }

    /// `self + o`.
    pub fn add(&self, o: &Dense2<T>) -> Dense2<T> {
        let (long, short) = if self.0.len() >= o.0.len() {
            (self, o)
        } else {
            (o, self)
        };
        let mut r = long.0.clone();
        for (c, s) in r.iter_mut().zip(&short.0) {
            *c = c.add(s);
        }
        Dense2::new(r)
    }

    /// `self * o`.
    pub fn mul(&self, o: &Dense2<T>) -> Dense2<T> {
        if self.0.is_empty() || o.0.is_empty() {
            return Dense2::zero();
        }
        let mut r = Dense2::zero();
        r.add_product(self, o);
        r
    }

    /// `self += a * b`, in place.
    pub fn add_product(&mut self, a: &Dense2<T>, b: &Dense2<T>) {
        if a.0.is_empty() || b.0.is_empty() {
            return;
        }
        let n = a.0.len() + b.0.len() - 1;
        if self.0.len() < n {
            grow(&mut self.0, n);
            self.0.resize(n, Dense::zero());
        }
        for (i, x) in a.0.iter().enumerate() {
            for (j, y) in b.0.iter().enumerate() {
                self.0[i + j].add_product(x, y);
            }
        }
        while self.0.last().is_some_and(Dense::is_zero) {
            self.0.pop();
        }
    }

    /// The polynomial in P0 at `delta_a = da`.
    pub fn at_aileron(&self, da: T) -> Dense<T> {
        self.0
            .iter()
            .rev()
            .fold(Dense::zero(), |acc, c| acc.scale(da).add(c))
    }

    /// The polynomial in P0 when delta_a does not occur (`None` otherwise).
    pub fn univariate(&self) -> Option<Dense<T>> {
        match self.0.len() {
            0 => Some(Dense::zero()),
            1 => Some(self.0[0].clone()),
            _ => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(c: &[f64]) -> IPoly {
        IPoly::new(c.iter().map(|x| I::point(*x)).collect())
    }

    #[test]
    fn exact_operations_stay_points_and_division_recovers_the_factor() {
        // (x + 1)(x - 2) = x^2 - x - 2, all exact in f64.
        let a = p(&[1.0, 1.0]);
        let b = p(&[-2.0, 1.0]);
        let ab = a.mul(&b);
        assert_eq!(ab, p(&[-2.0, -1.0, 1.0]));
        assert_eq!(ab.div_exact(&a), Some(b.clone()));
        // x^2 + 1 is not divisible by x + 1: the remainder 2 excludes zero.
        assert_eq!(p(&[1.0, 0.0, 1.0]).div_exact(&a), None);
        // 0.1 is not a double: its enclosure is not a point, and products keep enclosing.
        let tenth = I::from_q(&num_rational::BigRational::new(1.into(), 10.into()));
        assert!(tenth.lo < tenth.hi);
        // (x + 0.1)(x + 1) at x = 2 is 6.3: enclosed, and away from zero.
        let q = IPoly::new(vec![tenth, I::point(1.0)]).mul(&a);
        let v = q.eval(I::point(2.0));
        assert!(v.lo <= 6.3 && 6.3 <= v.hi && !v.contains_zero(), "{v:?}");
        // Sums of exact zeros stay exact zeros, so degrees are exact.
        let z = IPoly::new(vec![I::point(1.0), I::point(0.0) + I::point(0.0)]);
        assert_eq!(z.degree(), Some(0));
    }

    /// The exact value at `x` of the polynomial with the exact (double) coefficients `c`.
    fn exact_value(c: &[f64], x: f64) -> num_rational::BigRational {
        let q = |v: f64| num_rational::BigRational::from_float(v).expect("finite");
        c.iter().rev().fold(q(0.0), |acc, a| acc * q(x) + q(*a))
    }

    proptest::proptest! {
        /// The fast point enclosure holds the exact value of every polynomial whose coefficients
        /// lie in the enclosures (here the two corners of the box where the value is largest
        /// and smallest, another corner and an interior point, evaluated in exact rationals),
        /// at points near and far from its roots, of both signs, tiny (the interval fallback)
        /// and large, for ordinary, tiny (underflowing) and huge (overflowing: the interval
        /// fallback) coefficients, and it is tight for exact ordinary coefficients.
        #[test]
        fn point_enclosures_hold_the_exact_value_of_every_polynomial_in_the_box(
            roots in proptest::collection::vec(-20.0f64..20.0, 1..14),
            lead_exp in proptest::prop_oneof![-8i32..8, -1060i32..-1000, 880i32..905],
            rel in proptest::sample::select(vec![0.0, 1e-16, 1e-12, 1e-6, 1e-2]),
            corner in proptest::collection::vec(proptest::bool::ANY, 14),
            x_kind in 0usize..4,
            x_raw in -1.0f64..1.0,
            pick in 0usize..14,
        ) {
            // (x - r_1)...(x - r_k) times 2^lead_exp, its coefficients widened by `rel`.
            // 2^lead_exp in two exact halves (powi alone would overflow on the way to 2^-1060).
            let mut c = vec![2f64.powi(lead_exp / 2) * 2f64.powi(lead_exp - lead_exp / 2)];
            for r in &roots {
                let mut next = vec![0.0; c.len() + 1];
                for (i, a) in c.iter().enumerate() {
                    next[i + 1] += a;
                    next[i] -= r * a;
                }
                c = next;
            }
            let box_ = IPoly::new(
                c.iter()
                    .map(|m| {
                        let h = (m.abs() * rel).max(if rel > 0.0 { 1e-300 } else { 0.0 });
                        I::new(m - h, m + h)
                    })
                    .collect(),
            );
            let x = match x_kind {
                // Next to a root (where the value cancels).
                0 => roots[pick % roots.len()] * (1.0 + 1e-9 * x_raw),
                // Anywhere in the roots' range.
                1 => 25.0 * x_raw,
                // Below 2^-20: the interval fallback.
                2 => 1e-7 * x_raw,
                // Far out.
                _ => 1e4 * x_raw,
            };
            let e = PointEnclosure::new(&box_);
            let v = e.at(x);
            let q = |v: f64| num_rational::BigRational::from_float(v).expect("finite");
            let coefficients = |f: &dyn Fn(usize, &I) -> f64| -> Vec<f64> {
                box_.0.iter().enumerate().map(|(i, c)| f(i, c)).collect()
            };
            let corner_c = coefficients(&|i, c| if corner[i % corner.len()] { c.hi } else { c.lo });
            let inside_c = coefficients(&|_, c| c.lo + 0.3 * (c.hi - c.lo));
            // The largest value: each coefficient at the end its power of x favours.
            let up = |i: usize| x.powi(i as i32) >= 0.0;
            let largest = coefficients(&|i, c| if up(i) { c.hi } else { c.lo });
            let smallest = coefficients(&|i, c| if up(i) { c.lo } else { c.hi });
            for cs in [largest, smallest, corner_c, inside_c] {
                let exact = exact_value(&cs, x);
                let above = v.lo == f64::NEG_INFINITY || q(v.lo) <= exact;
                let below = v.hi == f64::INFINITY || exact <= q(v.hi);
                proptest::prop_assert!(above && below, "{v:?} misses the value at {x} of {cs:?}");
            }
            if rel == 0.0 && x_kind == 1 && lead_exp.abs() < 8 {
                // Exact coefficients away from roots: a tight enclosure, not just a true one.
                let sum: f64 = c.iter().enumerate().map(|(i, a)| a.abs() * x.abs().powi(i as i32)).sum();
                proptest::prop_assert!(v.hi - v.lo <= 1e-13 * sum.max(1e-300), "{v:?}");
            }
        }
    }
}
