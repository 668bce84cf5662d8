//! Dense polynomials in P0, and in P0 and delta_a, with interval coefficients: the criterion
//! polynomials of one aircraft enclosed in f64.
//!
//! Every operation is a finite sequence of interval additions and multiplications (and, for
//! [`IPoly::div_exact`], divisions by an interval that excludes zero), so each coefficient of a
//! result encloses the exact coefficient that the same operations give on the exact inputs.

use crate::interval::I;
use crate::roots::F64Poly;

/// A polynomial in one variable with interval coefficients, ascending; trailing coefficients
/// that are exactly `[0, 0]` are dropped, so the degree is exact whenever the leading
/// coefficient excludes zero.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct IPoly(pub Vec<I>);

impl IPoly {
    /// The zero polynomial.
    pub fn zero() -> IPoly {
        IPoly(Vec::new())
    }

    /// The constant `c`.
    pub fn constant(c: I) -> IPoly {
        IPoly(vec![c]).trimmed()
    }

    /// From ascending coefficients.
    pub fn new(c: Vec<I>) -> IPoly {
        IPoly(c).trimmed()
    }

    fn trimmed(mut self) -> IPoly {
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
    pub fn coeffs(&self) -> &[I] {
        &self.0
    }

    /// `self + o`.
    pub fn add(&self, o: &IPoly) -> IPoly {
        let n = self.0.len().max(o.0.len());
        let zero = I::point(0.0);
        IPoly::new(
            (0..n)
                .map(|i| {
                    let a = self.0.get(i).copied().unwrap_or(zero);
                    let b = o.0.get(i).copied().unwrap_or(zero);
                    a + b
                })
                .collect(),
        )
    }

    /// `-self`.
    pub fn neg(&self) -> IPoly {
        IPoly(self.0.iter().map(|c| -*c).collect())
    }

    /// `self - o`.
    pub fn sub(&self, o: &IPoly) -> IPoly {
        self.add(&o.neg())
    }

    /// `self * o`.
    pub fn mul(&self, o: &IPoly) -> IPoly {
        if self.is_zero() || o.is_zero() {
            return IPoly::zero();
        }
        let mut r = vec![I::point(0.0); self.0.len() + o.0.len() - 1];
        for (i, a) in self.0.iter().enumerate() {
            if a.is_exact_zero() {
                continue;
            }
            for (j, b) in o.0.iter().enumerate() {
                r[i + j] = r[i + j] + *a * *b;
            }
        }
        IPoly::new(r)
    }

    /// `c * self`.
    pub fn scale(&self, c: I) -> IPoly {
        IPoly::new(self.0.iter().map(|a| *a * c).collect())
    }

    /// `self^k`.
    pub fn pow(&self, k: u32) -> IPoly {
        (0..k).fold(IPoly::constant(I::point(1.0)), |acc, _| acc.mul(self))
    }

    /// The value at `x` by Horner's scheme (an enclosure of the range over `x`).
    pub fn eval(&self, x: I) -> I {
        self.0
            .iter()
            .rev()
            .fold(I::point(0.0), |acc, c| acc * x + *c)
    }

    /// The derivative.
    pub fn derivative(&self) -> IPoly {
        IPoly::new(
            self.0
                .iter()
                .enumerate()
                .skip(1)
                .map(|(i, c)| *c * I::point(i as f64))
                .collect(),
        )
    }

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

    /// The midpoints of the coefficients, for floating-point evaluation.
    pub fn mid(&self) -> F64Poly {
        F64Poly(self.0.iter().map(|c| c.mid()).collect())
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
    pub fn div_exact(&self, d: &IPoly) -> Option<IPoly> {
        let (Some(n), Some(m)) = (self.degree(), d.degree()) else {
            return d.degree().map(|_| IPoly::zero());
        };
        if n < m {
            return self.0.iter().all(|c| c.contains_zero()).then(IPoly::zero);
        }
        let top = self.div_from_top(d, n, m);
        let bottom = self.div_from_bottom(d, n, m);
        match (top, bottom) {
            (Some(a), Some(b)) => {
                let q: Option<Vec<I>> = a.iter().zip(&b).map(|(x, y)| x.intersect(*y)).collect();
                q.map(IPoly::new)
            }
            (Some(a), None) | (None, Some(a)) => Some(IPoly::new(a)),
            (None, None) => None,
        }
    }

    fn div_from_top(&self, d: &IPoly, n: usize, m: usize) -> Option<Vec<I>> {
        let lead = d.0[m];
        if lead.contains_zero() {
            return None;
        }
        let mut r = self.0.clone();
        let mut q = vec![I::point(0.0); n - m + 1];
        for k in (0..=n - m).rev() {
            let c = r[k + m].checked_div(lead)?;
            q[k] = c;
            for (j, dj) in d.0.iter().enumerate() {
                r[k + j] = r[k + j] - c * *dj;
            }
        }
        r[..m].iter().all(|c| c.contains_zero()).then_some(q)
    }

    fn div_from_bottom(&self, d: &IPoly, n: usize, m: usize) -> Option<Vec<I>> {
        let d0 = d.0[0];
        if d0.contains_zero() {
            return None;
        }
        let mut r = self.0.clone();
        let mut q = vec![I::point(0.0); n - m + 1];
        for k in 0..=n - m {
            let c = r[k].checked_div(d0)?;
            q[k] = c;
            for (j, dj) in d.0.iter().enumerate() {
                r[k + j] = r[k + j] - c * *dj;
            }
        }
        r[n - m + 1..]
            .iter()
            .all(|c| c.contains_zero())
            .then_some(q)
    }
}

/// A polynomial in P0 and delta_a: `self.0[i]` (a polynomial in P0) multiplies `delta_a^i`.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct IPoly2(pub Vec<IPoly>);

impl IPoly2 {
    /// The zero polynomial.
    pub fn zero() -> IPoly2 {
        IPoly2(Vec::new())
    }

    fn trimmed(mut self) -> IPoly2 {
        while self.0.last().is_some_and(IPoly::is_zero) {
            self.0.pop();
        }
        self
    }

    /// From the coefficients of `delta_a^0, delta_a^1, ...`.
    pub fn new(c: Vec<IPoly>) -> IPoly2 {
        IPoly2(c).trimmed()
    }

    /// The degree in delta_a (`None` for the zero polynomial).
    pub fn degree(&self) -> Option<usize> {
        self.0.len().checked_sub(1)
    }

    /// The coefficient of `delta_a^i` (zero beyond the degree).
    pub fn coeff(&self, i: usize) -> IPoly {
        self.0.get(i).cloned().unwrap_or_default()
    }

    /// `self + o`.
    pub fn add(&self, o: &IPoly2) -> IPoly2 {
        let n = self.0.len().max(o.0.len());
        IPoly2::new((0..n).map(|i| self.coeff(i).add(&o.coeff(i))).collect())
    }

    /// `self * o`.
    pub fn mul(&self, o: &IPoly2) -> IPoly2 {
        if self.0.is_empty() || o.0.is_empty() {
            return IPoly2::zero();
        }
        let mut r = vec![IPoly::zero(); self.0.len() + o.0.len() - 1];
        for (i, a) in self.0.iter().enumerate() {
            for (j, b) in o.0.iter().enumerate() {
                r[i + j] = r[i + j].add(&a.mul(b));
            }
        }
        IPoly2::new(r)
    }

    /// The polynomial in P0 when delta_a does not occur (`None` otherwise).
    pub fn univariate(&self) -> Option<IPoly> {
        match self.0.len() {
            0 => Some(IPoly::zero()),
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
}
