//! Sparse multivariate polynomials with exact rational coefficients.
//!
//! A [`Poly`] is a sorted list of (monomial, coefficient) pairs with no zero coefficients, so two
//! polynomials are equal exactly when their term lists are equal: "normalizes to zero" is
//! `is_zero()`. Products accumulate in a hash map and are sorted once; everything else is a
//! linear merge. There is no global rational normalization anywhere: the derivation keeps
//! numerators and denominators apart (see `crate::derivation`).

use super::mono::Mono;
use super::rational::Q;
use super::symbol::Sym;
use rustc_hash::FxHashMap;
use std::fmt;
use std::ops::{Add, Mul, Neg, Sub};

/// A polynomial in interned symbols with coefficients in Q.
#[derive(Clone, PartialEq, Eq, Hash, Default)]
pub struct Poly {
    terms: Vec<(Mono, Q)>,
}

impl Poly {
    /// The zero polynomial.
    pub fn zero() -> Poly {
        Poly { terms: Vec::new() }
    }

    /// A constant.
    pub fn constant(c: Q) -> Poly {
        Poly::term(Mono::ONE, c)
    }

    /// The integer constant `n`.
    pub fn int(n: i64) -> Poly {
        Poly::constant(Q::int(n))
    }

    /// The symbol `s` as a polynomial.
    pub fn var(s: Sym) -> Poly {
        Poly::term(Mono::var(s, 1), Q::ONE)
    }

    /// A single term `c * m`.
    pub fn term(m: Mono, c: Q) -> Poly {
        if c.is_zero() {
            Poly::zero()
        } else {
            Poly {
                terms: vec![(m, c)],
            }
        }
    }

    /// Builds a polynomial from arbitrary terms (combining equal monomials, dropping zeros).
    pub fn from_terms(terms: impl IntoIterator<Item = (Mono, Q)>) -> Poly {
        let mut map: FxHashMap<Mono, Q> = FxHashMap::default();
        for (m, c) in terms {
            map.entry(m)
                .and_modify(|a| a.add_assign_ref(&c))
                .or_insert(c);
        }
        Poly::from_map(map)
    }

    fn from_map(map: FxHashMap<Mono, Q>) -> Poly {
        let mut terms: Vec<(Mono, Q)> = map.into_iter().filter(|(_, c)| !c.is_zero()).collect();
        terms.sort_unstable_by_key(|t| t.0);
        Poly { terms }
    }

    /// The terms, sorted by monomial.
    pub fn terms(&self) -> &[(Mono, Q)] {
        &self.terms
    }

    /// Number of terms.
    pub fn len(&self) -> usize {
        self.terms.len()
    }

    /// True for the zero polynomial (no terms); the same as [`Poly::is_zero`].
    pub fn is_empty(&self) -> bool {
        self.terms.is_empty()
    }

    /// True for the zero polynomial.
    pub fn is_zero(&self) -> bool {
        self.terms.is_empty()
    }

    /// The constant value, if this polynomial is a constant.
    pub fn as_constant(&self) -> Option<Q> {
        match self.terms.as_slice() {
            [] => Some(Q::ZERO),
            [(m, c)] if m.is_one() => Some(c.clone()),
            _ => None,
        }
    }

    /// Multiplies every coefficient by `c`.
    pub fn scale(&self, c: &Q) -> Poly {
        if c.is_zero() {
            return Poly::zero();
        }
        Poly {
            terms: self.terms.iter().map(|(m, a)| (*m, a * c)).collect(),
        }
    }

    /// Multiplies by the monomial `m` (order is preserved, so no re-sort).
    pub fn mul_mono(&self, m: &Mono) -> Poly {
        Poly {
            terms: self
                .terms
                .iter()
                .map(|(t, a)| (t.mul(m), a.clone()))
                .collect(),
        }
    }

    fn merge(&self, o: &Poly, negate: bool) -> Poly {
        let (a, b) = (&self.terms, &o.terms);
        let mut out = Vec::with_capacity(a.len() + b.len());
        let (mut i, mut j) = (0, 0);
        while i < a.len() && j < b.len() {
            match a[i].0.cmp(&b[j].0) {
                std::cmp::Ordering::Less => {
                    out.push(a[i].clone());
                    i += 1;
                }
                std::cmp::Ordering::Greater => {
                    out.push((b[j].0, if negate { -&b[j].1 } else { b[j].1.clone() }));
                    j += 1;
                }
                std::cmp::Ordering::Equal => {
                    let c = if negate {
                        &a[i].1 - &b[j].1
                    } else {
                        &a[i].1 + &b[j].1
                    };
                    if !c.is_zero() {
                        out.push((a[i].0, c));
                    }
                    i += 1;
                    j += 1;
                }
            }
        }
        out.extend_from_slice(&a[i..]);
        out.extend(
            b[j..]
                .iter()
                .map(|(m, c)| (*m, if negate { -c } else { c.clone() })),
        );
        Poly { terms: out }
    }

    /// Product of two polynomials.
    pub fn mul_ref(&self, o: &Poly) -> Poly {
        if self.is_zero() || o.is_zero() {
            return Poly::zero();
        }
        if self.terms.len() == 1 {
            let (m, c) = &self.terms[0];
            return o.mul_mono(m).scale(c);
        }
        if o.terms.len() == 1 {
            let (m, c) = &o.terms[0];
            return self.mul_mono(m).scale(c);
        }
        let mut map: FxHashMap<Mono, Q> =
            FxHashMap::with_capacity_and_hasher(self.len() * o.len() / 2 + 1, Default::default());
        for (ma, ca) in &self.terms {
            for (mb, cb) in &o.terms {
                let c = ca * cb;
                map.entry(ma.mul(mb))
                    .and_modify(|acc| acc.add_assign_ref(&c))
                    .or_insert(c);
            }
        }
        Poly::from_map(map)
    }

    /// `self^k`.
    pub fn pow(&self, k: u32) -> Poly {
        let mut acc = Poly::int(1);
        let mut base = self.clone();
        let mut k = k;
        while k > 0 {
            if k & 1 == 1 {
                acc = acc.mul_ref(&base);
            }
            k >>= 1;
            if k > 0 {
                base = base.mul_ref(&base);
            }
        }
        acc
    }

    /// Partial derivative with respect to `s`.
    pub fn diff(&self, s: Sym) -> Poly {
        let mut terms = Vec::new();
        for (m, c) in &self.terms {
            let e = m.exp(s);
            if e > 0 {
                let mut m2 = *m;
                m2.set(s, e - 1);
                terms.push((m2, c * &Q::int(e as i64)));
            }
        }
        Poly::from_terms(terms)
    }

    /// Degree in `s` (0 for the zero polynomial).
    pub fn degree(&self, s: Sym) -> u32 {
        self.terms.iter().map(|(m, _)| m.exp(s)).max().unwrap_or(0)
    }

    /// Total degree in the given symbols jointly.
    pub fn degree_in(&self, syms: &[Sym]) -> u32 {
        self.terms
            .iter()
            .map(|(m, _)| syms.iter().map(|s| m.exp(*s)).sum::<u32>())
            .max()
            .unwrap_or(0)
    }

    /// True when `s` occurs.
    pub fn contains(&self, s: Sym) -> bool {
        self.terms.iter().any(|(m, _)| m.exp(s) > 0)
    }

    /// The coefficient of `s^k`, a polynomial free of `s`.
    pub fn coeff(&self, s: Sym, k: u32) -> Poly {
        let terms = self
            .terms
            .iter()
            .filter(|(m, _)| m.exp(s) == k)
            .map(|(m, c)| {
                let mut m2 = *m;
                m2.set(s, 0);
                (m2, c.clone())
            });
        Poly::from_terms(terms)
    }

    /// Coefficients of `s^0 ..= s^deg`.
    pub fn coeffs(&self, s: Sym) -> Vec<Poly> {
        (0..=self.degree(s)).map(|k| self.coeff(s, k)).collect()
    }

    /// `self / s^k`, when every term carries `s` to at least the power `k` (exact division by a
    /// power of a symbol); `None` otherwise.
    pub fn div_var_pow(&self, s: Sym, k: u32) -> Option<Poly> {
        let mut terms = Vec::with_capacity(self.terms.len());
        for (m, c) in &self.terms {
            let e = m.exp(s);
            if e < k {
                return None;
            }
            let mut m2 = *m;
            m2.set(s, e - k);
            terms.push((m2, c.clone()));
        }
        Some(Poly::from_terms(terms))
    }

    /// The resultant of `self` and `other` with respect to `x`, as the determinant of their
    /// Sylvester matrix built on their actual degrees in `x` (so a vanishing leading coefficient
    /// lowers the degree instead of zeroing the resultant). It vanishes exactly where the two
    /// polynomials, read as polynomials in `x` with the other symbols fixed, share a root.
    /// Both must contain `x` or be non-zero; `Res(f, c) = c^deg f` for a constant `c` in `x`.
    pub fn resultant(&self, other: &Poly, x: Sym) -> Poly {
        let (f, g) = (self.coeffs(x), other.coeffs(x));
        let (m, n) = (f.len() - 1, g.len() - 1);
        if self.is_zero() || other.is_zero() {
            return Poly::zero();
        }
        if m == 0 && n == 0 {
            return Poly::int(1);
        }
        let size = m + n;
        let mut rows = Vec::with_capacity(size);
        // n rows of f's coefficients (highest first), then m rows of g's, each shifted by one.
        for (coeffs, shifts) in [(&f, n), (&g, m)] {
            for shift in 0..shifts {
                let mut row = vec![Poly::zero(); size];
                for (i, c) in coeffs.iter().rev().enumerate() {
                    row[shift + i] = c.clone();
                }
                rows.push(row);
            }
        }
        super::Matrix::from_rows(rows).det()
    }

    /// Substitutes the polynomial `value` for the symbol `s`.
    pub fn subs(&self, s: Sym, value: &Poly) -> Poly {
        if !self.contains(s) {
            return self.clone();
        }
        let cs = self.coeffs(s);
        // Horner in the substituted value.
        let mut acc = Poly::zero();
        for c in cs.iter().rev() {
            acc = &acc.mul_ref(value) + c;
        }
        acc
    }

    /// Substitutes several symbols at once by polynomials (simultaneously).
    pub fn subs_all(&self, subs: &[(Sym, Poly)]) -> Poly {
        let mut powers: Vec<Vec<Poly>> = subs.iter().map(|_| vec![Poly::int(1)]).collect();
        let mut map: FxHashMap<Mono, Q> = FxHashMap::default();
        for (m, c) in &self.terms {
            let mut rest = *m;
            let mut factor = Poly::constant(c.clone());
            for (i, (s, v)) in subs.iter().enumerate() {
                let e = m.exp(*s) as usize;
                if e == 0 {
                    continue;
                }
                rest.set(*s, 0);
                while powers[i].len() <= e {
                    let next = powers[i].last().map(|p| p.mul_ref(v)).unwrap_or_default();
                    powers[i].push(next);
                }
                factor = factor.mul_ref(&powers[i][e]);
            }
            for (fm, fc) in factor.mul_mono(&rest).terms {
                map.entry(fm)
                    .and_modify(|a| a.add_assign_ref(&fc))
                    .or_insert(fc);
            }
        }
        Poly::from_map(map)
    }

    /// Substitutes exact rational values for symbols.
    ///
    /// Per term, the numerators and denominators of the factors are multiplied as big integers
    /// and reduced once, so substituting an aircraft's decimal data costs one gcd per term.
    pub fn subs_values(&self, values: &[(Sym, Q)]) -> Poly {
        use num_bigint::BigInt;
        let present: Vec<&(Sym, Q)> = values.iter().filter(|(s, _)| self.contains(*s)).collect();
        if present.is_empty() {
            return self.clone();
        }
        let parts: Vec<(BigInt, BigInt)> = present
            .iter()
            .map(|(_, v)| {
                let b = v.to_big();
                (b.numer().clone(), b.denom().clone())
            })
            .collect();
        // powers[i][e] = (n_i^e, d_i^e), grown on demand.
        let mut powers: Vec<Vec<(BigInt, BigInt)>> = parts
            .iter()
            .map(|_| vec![(BigInt::from(1), BigInt::from(1))])
            .collect();
        let mut map: FxHashMap<Mono, Q> = FxHashMap::default();
        for (m, c) in &self.terms {
            let mut rest = *m;
            let cb = c.to_big();
            let (mut num, mut den) = (cb.numer().clone(), cb.denom().clone());
            for (i, (s, _)) in present.iter().enumerate() {
                let e = m.exp(*s) as usize;
                if e == 0 {
                    continue;
                }
                rest.set(*s, 0);
                while powers[i].len() <= e {
                    let last = &powers[i][powers[i].len() - 1];
                    let next = (&last.0 * &parts[i].0, &last.1 * &parts[i].1);
                    powers[i].push(next);
                }
                num *= &powers[i][e].0;
                den *= &powers[i][e].1;
            }
            let q = Q::from_big(num_rational::BigRational::new(num, den));
            map.entry(rest)
                .and_modify(|a| a.add_assign_ref(&q))
                .or_insert(q);
        }
        Poly::from_map(map)
    }

    /// Substitutes exact values into several integer-coefficient polynomials at once and
    /// multiplies all of them by one positive integer, the least common multiple of the terms'
    /// denominators, so that the results have integer coefficients and keep every ratio between
    /// them. Decimal data and f64 values have denominators 2^a 5^b, for which the lcm is
    /// exponent arithmetic; other denominators fall back to big-integer lcm. Returns `None`
    /// if a coefficient is not an integer.
    pub fn subs_values_cleared(polys: &[&Poly], values: &[(Sym, Q)]) -> Option<Vec<Poly>> {
        use num_bigint::BigInt;
        use num_integer::Integer;
        use num_traits::{One, Zero};
        let parts: Vec<(Sym, BigInt, BigInt, usize)> = values
            .iter()
            .map(|(s, v)| {
                let b = v.to_big();
                let d = polys.iter().map(|p| p.degree(*s)).max().unwrap_or(0) as usize;
                (*s, b.numer().clone(), b.denom().clone(), d)
            })
            .filter(|(_, _, _, d)| *d > 0)
            .collect();
        // Denominators as 2^a 5^b when possible.
        let two_five = |d: &BigInt| -> Option<(u64, u64)> {
            let a = d.trailing_zeros().unwrap_or(0);
            let mut rest = d >> a;
            let mut b = 0;
            let five = BigInt::from(5);
            while !rest.is_one() {
                let (q, r) = rest.div_rem(&five);
                if !r.is_zero() {
                    return None;
                }
                rest = q;
                b += 1;
            }
            Some((a, b))
        };
        let exps: Option<Vec<(u64, u64)>> = parts.iter().map(|(_, _, d, _)| two_five(d)).collect();
        let num_pows: Vec<Vec<BigInt>> = parts
            .iter()
            .map(|(_, n, _, d)| (0..=*d).map(|e| num_traits::pow(n.clone(), e)).collect())
            .collect();
        let mut out = Vec::with_capacity(polys.len());
        // Per polynomial, per term: monomial, numerator, (2, 5) exponents or denominator.
        type Scaled = (Mono, BigInt, (u64, u64), BigInt);
        let mut terms: Vec<Vec<Scaled>> = Vec::new();
        for p in polys {
            let mut v = Vec::with_capacity(p.len());
            for (m, c) in &p.terms {
                if !c.is_integer() {
                    return None;
                }
                let mut num = c.to_big().numer().clone();
                let (mut a, mut b) = (0u64, 0u64);
                let mut den = BigInt::one();
                let mut rest = *m;
                for (i, (s, _, d, _)) in parts.iter().enumerate() {
                    let e = m.exp(*s) as usize;
                    if e > 0 {
                        rest.set(*s, 0);
                        num *= &num_pows[i][e];
                        match &exps {
                            Some(x) => {
                                a += x[i].0 * e as u64;
                                b += x[i].1 * e as u64;
                            }
                            None => den *= num_traits::pow(d.clone(), e),
                        }
                    }
                }
                v.push((rest, num, (a, b), den));
            }
            terms.push(v);
        }
        let all = terms.iter().flatten();
        let (max_a, max_b) = all
            .clone()
            .fold((0, 0), |m, t| (m.0.max(t.2 .0), m.1.max(t.2 .1)));
        let lcm = all.fold(BigInt::one(), |l, t| l.lcm(&t.3));
        let five_pows: Vec<BigInt> = (0..=max_b)
            .map(|k| num_traits::pow(BigInt::from(5), k as usize))
            .collect();
        for v in terms {
            let mut map: FxHashMap<Mono, Q> = FxHashMap::default();
            for (rest, num, (a, b), den) in v {
                let scaled = if exps.is_some() {
                    (num * &five_pows[(max_b - b) as usize]) << (max_a - a)
                } else {
                    num * (&lcm / den)
                };
                let q = Q::from_big(num_rational::BigRational::from_integer(scaled));
                map.entry(rest)
                    .and_modify(|x| x.add_assign_ref(&q))
                    .or_insert(q);
            }
            out.push(Poly::from_map(map));
        }
        Some(out)
    }

    /// Evaluates in f64 with `value(sym)` for every symbol.
    pub fn eval_f64(&self, value: &dyn Fn(Sym) -> f64) -> f64 {
        self.terms
            .iter()
            .map(|(m, c)| {
                m.factors()
                    .iter()
                    .fold(c.to_f64(), |acc, (s, e)| acc * value(*s).powi(*e as i32))
            })
            .sum()
    }

    /// The polynomial prepared for repeated [`Poly::eval_f64`]: coefficients converted to f64
    /// and monomials unpacked once ([`PolyF64`], same operations in the same order, so the same
    /// result to the bit).
    pub fn to_f64_form(&self) -> PolyF64 {
        PolyF64(
            self.terms
                .iter()
                .map(|(m, c)| {
                    let f = m.factors().iter().map(|(s, e)| (*s, *e as i32)).collect();
                    (c.to_f64(), f)
                })
                .collect(),
        )
    }

    /// The symbols that occur, in symbol order.
    pub fn symbols(&self) -> Vec<Sym> {
        let mut all: Vec<Sym> = self
            .terms
            .iter()
            .flat_map(|(m, _)| m.factors().into_iter().map(|(s, _)| s))
            .collect();
        all.sort();
        all.dedup();
        all
    }

    /// Coefficients in `s` as exact rationals, if `s` is the only symbol (ascending powers).
    pub fn univariate_coeffs(&self, s: Sym) -> Option<Vec<Q>> {
        if self.symbols().iter().any(|t| *t != s) {
            return None;
        }
        let mut out = vec![Q::ZERO; self.degree(s) as usize + 1];
        for (m, c) in &self.terms {
            out[m.exp(s) as usize] = c.clone();
        }
        Some(out)
    }
}

impl Add for &Poly {
    type Output = Poly;
    fn add(self, o: &Poly) -> Poly {
        self.merge(o, false)
    }
}

impl Sub for &Poly {
    type Output = Poly;
    fn sub(self, o: &Poly) -> Poly {
        self.merge(o, true)
    }
}

impl Mul for &Poly {
    type Output = Poly;
    fn mul(self, o: &Poly) -> Poly {
        self.mul_ref(o)
    }
}

impl Neg for &Poly {
    type Output = Poly;
    fn neg(self) -> Poly {
        Poly {
            terms: self.terms.iter().map(|(m, c)| (*m, -c)).collect(),
        }
    }
}

impl Add for Poly {
    type Output = Poly;
    fn add(self, o: Poly) -> Poly {
        &self + &o
    }
}

impl Sub for Poly {
    type Output = Poly;
    fn sub(self, o: Poly) -> Poly {
        &self - &o
    }
}

impl Mul for Poly {
    type Output = Poly;
    fn mul(self, o: Poly) -> Poly {
        &self * &o
    }
}

impl Neg for Poly {
    type Output = Poly;
    fn neg(self) -> Poly {
        -&self
    }
}

impl fmt::Debug for Poly {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.is_zero() {
            return f.write_str("0");
        }
        for (i, (m, c)) in self.terms.iter().enumerate() {
            if i > 0 {
                f.write_str(" + ")?;
            }
            if m.is_one() {
                write!(f, "{c}")?;
            } else if c.is_one() {
                write!(f, "{m:?}")?;
            } else {
                write!(f, "({c})*{m:?}")?;
            }
        }
        Ok(())
    }
}

/// A polynomial prepared for f64 evaluation ([`Poly::to_f64_form`]).
#[derive(Clone, Debug)]
pub struct PolyF64(Vec<(f64, Vec<(Sym, i32)>)>);

impl PolyF64 {
    /// [`Poly::eval_f64`] of the polynomial it was made from.
    pub fn eval(&self, value: &dyn Fn(Sym) -> f64) -> f64 {
        self.0
            .iter()
            .map(|(c, f)| f.iter().fold(*c, |acc, (s, e)| acc * value(*s).powi(*e)))
            .sum()
    }
}
