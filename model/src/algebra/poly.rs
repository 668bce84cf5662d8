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
            Poly { terms: vec![(m, c)] }
        }
    }

    /// Builds a polynomial from arbitrary terms (combining equal monomials, dropping zeros).
    pub fn from_terms(terms: impl IntoIterator<Item = (Mono, Q)>) -> Poly {
        let mut map: FxHashMap<Mono, Q> = FxHashMap::default();
        for (m, c) in terms {
            map.entry(m).and_modify(|a| a.add_assign_ref(&c)).or_insert(c);
        }
        Poly::from_map(map)
    }

    fn from_map(map: FxHashMap<Mono, Q>) -> Poly {
        let mut terms: Vec<(Mono, Q)> = map.into_iter().filter(|(_, c)| !c.is_zero()).collect();
        terms.sort_unstable_by(|a, b| a.0.cmp(&b.0));
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
            terms: self.terms.iter().map(|(t, a)| (t.mul(m), a.clone())).collect(),
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
                    let c = if negate { &a[i].1 - &b[j].1 } else { &a[i].1 + &b[j].1 };
                    if !c.is_zero() {
                        out.push((a[i].0, c));
                    }
                    i += 1;
                    j += 1;
                }
            }
        }
        out.extend_from_slice(&a[i..]);
        out.extend(b[j..].iter().map(|(m, c)| (*m, if negate { -c } else { c.clone() })));
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
        let terms = self.terms.iter().filter(|(m, _)| m.exp(s) == k).map(|(m, c)| {
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
                map.entry(fm).and_modify(|a| a.add_assign_ref(&fc)).or_insert(fc);
            }
        }
        Poly::from_map(map)
    }

    /// Substitutes exact rational values for symbols.
    pub fn subs_values(&self, values: &[(Sym, Q)]) -> Poly {
        let subs: Vec<(Sym, Poly)> =
            values.iter().map(|(s, v)| (*s, Poly::constant(v.clone()))).collect();
        self.subs_all(&subs)
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
