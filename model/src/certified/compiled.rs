//! The parametric trim-level results compiled once per process for interval evaluation: every
//! term's coefficient as an interval and its exponents as small integers, and step 8's grouping
//! ([`crate::derivation::TrimGroups`]) made once, so that enclosing one aircraft's polynomials
//! is a pass over a few hundred terms.
//!
//! ```
//! use model::certified::compiled::Parametric;
//!
//! // det A (Eq. 4), compiled once per process: biquadratic in P0 (the divergence biquadratic).
//! assert_eq!(Parametric::get().det_a.p0_degree(), 4);
//! ```

use super::dense::{Dense, Dense2};
use super::num::Num;
use crate::algebra::{Poly, Sym, MAX_SYMS};
use crate::derivation::{Derivation, TrimGroups, TRIM_DEGREE};
use crate::equations::symbols;
use crate::interval::I;
use std::sync::OnceLock;

/// Highest power of a valued symbol kept in the table of powers (higher ones are computed).
const POWERS: usize = 8;

/// The enclosures of the valued symbols (parameters, delta_e, delta_r) and their powers: a row
/// of powers for each symbol with a value, and none for the others.
#[derive(Clone, Debug)]
pub struct Table<T> {
    /// The values, in symbol order.
    values: Vec<T>,
    /// Their powers, made on first use (the lift in f64 reads [`Table::relative`] instead).
    rows: std::sync::OnceLock<Vec<[T; POWERS + 1]>>,
    /// The row of each symbol, [`NO_VALUE`] for a symbol without one.
    row_of: [u8; MAX_SYMS],
    /// The same powers as midpoints with relative radii, when every value is a plain enclosure
    /// of a modest relative width (see [`Relative`]).
    relative: Option<Relative>,
}

/// A table's powers `x^e` as f64 midpoints `m_e` with relative bounds `eps_e`
/// (`x^e = m_e prod (1 + h_i)` with `sum |h_i| <= eps_e`, for every real in the enclosure: for
/// `e = 1` a relative radius, for higher powers the sum of the value's and the roundings'
/// relative errors, see [`Relative::new`]), for [`Compiled::lift`]'s evaluation in f64 with a
/// rounding error bound: an enclosure as tight as interval arithmetic gives, at a fraction of
/// the cost.
#[derive(Clone, Debug)]
struct Relative {
    rows: Vec<[(f64, f64); POWERS + 1]>,
    /// The largest `eps`.
    eps: f64,
    /// Binary exponents `(lo, hi)`, `lo <= 0 <= hi`, with every nonzero midpoint `|m|` in
    /// `[2^lo, 2^hi]`; the computed power `m_e` then lies in `[2^(e lo), 2^(e hi)]` as long as
    /// that range is within the normal doubles (rounding is monotone, powers of two are
    /// doubles).
    exponents: (i32, i32),
}

impl Relative {
    /// The relative form of the powers of `values`, or `None` when a value has none (a number
    /// that is more than an enclosure, an interval holding zero without being the exact zero,
    /// one not finite).
    ///
    /// The power `e` is the computed product `m_e` of `e` copies of `m = m_1`, and
    /// `x^e = m_e prod (1 + h_i)` over the `e` relative errors of `x` and the `e - 1`
    /// roundings: their sum `eps_e = e eps + (e - 1) u` (rounded up) bounds them as one
    /// relative radius does in the bound of [`Compiled::lift_rounded`].
    fn new<T: Num>(values: &[T]) -> Option<Relative> {
        let (mut eps, mut exponents) = (0.0f64, (0, 0));
        let mut out = Vec::with_capacity(values.len());
        for x in values {
            let (m, e1) = relative(x.interval()?)?;
            let mut r = [(1.0, 0.0); POWERS + 1];
            r[1] = (m, e1);
            for e in 2..=POWERS {
                let (p, s) = r[e - 1];
                r[e] = (p * m, crate::interval::next_up(s + e1 + UNIT));
            }
            eps = eps.max(r[POWERS].1);
            if m != 0.0 {
                let (lo, hi) = binary_exponents(m);
                exponents = (exponents.0.min(lo), exponents.1.max(hi));
            }
            out.push(r);
        }
        Some(Relative {
            rows: out,
            eps,
            exponents,
        })
    }
}

/// `(m, eps)` with `x = m (1 + h)`, `|h| <= eps`, for every real `x` in `i`; the exact zero is
/// `(0, 0)`. `None` for an interval without such a form (holding zero but not the point zero,
/// or not finite).
fn relative(i: I) -> Option<(f64, f64)> {
    if i.is_exact_zero() {
        return Some((0.0, 0.0));
    }
    let (m, r) = i.mid_rad();
    // r / |m| rounded to nearest, then up by an ulp: above the exact quotient (finite and
    // positive operands; a subnormal quotient is off by at most half its ulp).
    let eps = crate::interval::next_up(r / m.abs());
    (m != 0.0 && eps.is_finite() && !i.contains_zero()).then_some((m, eps))
}

/// `(e, e + 1)` with `2^e <= |x| < 2^(e + 1)` for a nonzero normal `x` (a subnormal `x` gets
/// a range no product passes).
fn binary_exponents(x: f64) -> (i32, i32) {
    let biased = ((x.to_bits() >> 52) & 0x7ff) as i32;
    if biased == 0 {
        return (-2 * MAX_EXPONENT, 2 * MAX_EXPONENT);
    }
    let e = biased - 1023;
    (e, e + 1)
}

/// [`Table::row_of`] of a symbol without a value.
const NO_VALUE: u8 = u8::MAX;
const _: () = assert!(MAX_SYMS < NO_VALUE as usize, "a row index for every symbol");

impl<T: Num> Table<T> {
    /// The table of `values`, indexed by symbol (`None`: no value).
    pub fn new(values: &[Option<T>; MAX_SYMS]) -> Table<T> {
        let mut row_of = [NO_VALUE; MAX_SYMS];
        let mut valued = Vec::with_capacity(values.iter().flatten().count());
        for (sym, v) in values.iter().enumerate() {
            if let Some(x) = v {
                row_of[sym] = valued.len() as u8;
                valued.push(*x);
            }
        }
        Table {
            relative: Relative::new(&valued),
            values: valued,
            rows: std::sync::OnceLock::new(),
            row_of,
        }
    }

    fn rows(&self) -> &[[T; POWERS + 1]] {
        self.rows
            .get_or_init(|| self.values.iter().map(|x| Table::row(*x)).collect())
    }

    fn row(x: T) -> [T; POWERS + 1] {
        let mut p = [T::constant(I::point(1.0)); POWERS + 1];
        for e in 1..=POWERS {
            p[e] = if e % 2 == 0 {
                p[e / 2].powi(2)
            } else {
                p[e - 1] * x
            };
        }
        p
    }

    fn pow(&self, sym: u8, e: u8) -> T {
        let Some(p) = self.rows().get(self.row_of[sym as usize] as usize) else {
            // No value (a trim symbol, P0 or delta_a, which the compiled results never read; a
            // parameter folded into the coefficients, for a sample's table): the whole line
            // keeps any use of it honest.
            return T::constant(I::entire());
        };
        match p.get(e as usize) {
            Some(v) => *v,
            None => p[1].powi(e as u32),
        }
    }
}

/// One term: coefficient, powers of valued symbols, and the exponents of P0 and delta_a.
#[derive(Clone, Debug)]
struct Term {
    coef: I,
    factors: Vec<(u8, u8)>,
    /// How many leading factors this term shares with the term before it (terms are sorted by
    /// their factors, so the shared prefix's product is computed once: a walk of the trie of
    /// the monomials, about half the multiplications of term-by-term evaluation).
    shared: usize,
    p0: usize,
    da: usize,
}

/// A polynomial in the valued symbols, P0 and delta_a, compiled for interval evaluation.
#[derive(Clone, Debug)]
pub struct Compiled {
    terms: Vec<Term>,
    p0_degree: usize,
    da_degree: usize,
    /// The most factors of one term (the depth of the trie of the monomials).
    depth: usize,
    /// The coefficients in relative form, for the lift in f64 (`None` when one has none).
    relative: Option<RelativeTerms>,
}

/// [`Compiled`]'s coefficients as midpoints `m` with relative radii (see [`Relative`]), each
/// with the count of roundings its term's product takes added: `sigma = eps + (k + 1) u` for a
/// term of `k` factors (one rounding per factor and one for the coefficient).
#[derive(Clone, Debug)]
struct RelativeTerms {
    coefs: Vec<(f64, f64)>,
    /// The largest `sigma`.
    sigma: f64,
    /// Binary exponents `(lo, hi)`, `lo <= 0 <= hi`, bounding every `|m|`.
    exponents: (i32, i32),
    /// The highest power of a valued symbol.
    max_power: usize,
    /// The highest total degree of a term in the valued symbols.
    max_degree: usize,
}

impl RelativeTerms {
    fn new(terms: &[Term]) -> Option<RelativeTerms> {
        let (mut sigma, mut exponents, mut max_power, mut max_degree) = (0.0f64, (0, 0), 0, 0);
        let coefs = terms
            .iter()
            .map(|t| {
                let (m, eps) = relative(t.coef)?;
                // An exact zero coefficient (a folded term whose folded data are zero) makes its
                // term exactly zero, whatever its factors.
                if m != 0.0 {
                    let (lo, hi) = binary_exponents(m);
                    exponents = (exponents.0.min(lo), exponents.1.max(hi));
                }
                max_power =
                    max_power.max(t.factors.iter().map(|f| f.1 as usize).max().unwrap_or(0));
                max_degree = max_degree.max(t.factors.iter().map(|f| f.1 as usize).sum());
                // Rounded to nearest, then up by an ulp: above the exact value.
                let s = crate::interval::next_up(eps + (t.factors.len() + 1) as f64 * UNIT);
                sigma = sigma.max(s);
                Some((m, s))
            })
            .collect::<Option<Vec<_>>>()?;
        Some(RelativeTerms {
            coefs,
            sigma,
            exponents,
            max_power,
            max_degree,
        })
    }
}

/// The unit roundoff of f64, `2^-53`.
const UNIT: f64 = f64::EPSILON / 2.0;

/// The largest relative error bound of one term the lift in f64 accepts (above it, the
/// bound's own first-order treatment would need more care than it is worth: interval
/// arithmetic takes over).
const MAX_SIGMA: f64 = 1.0 / (1u64 << 20) as f64;

/// The binary exponent range the lift in f64 keeps every product of (no overflow, no
/// underflow, no subnormal: every rounding within a relative `u`).
const MAX_EXPONENT: i32 = 900;

/// The most coefficients (in P0 and delta_a) the lift in f64 evaluates on the stack.
const MAX_CELLS: usize = 16;

/// The most factors of a term the lift in f64 takes.
const MAX_DEPTH: usize = 24;

/// A cell of [`Compiled::lift`]'s evaluation in f64: the running sum `s` of the terms'
/// computed values, `a`, the sum of their bounds `|t| sigma`, and `b`, the sum of the
/// absolute partial sums (whose rounding errors are at most `u` times each).
#[derive(Clone, Copy, Default)]
struct Cell {
    s: f64,
    a: f64,
    b: f64,
}

impl Compiled {
    /// Compiles `p`; panics if a trim symbol occurs (step 8 has grouped them out).
    pub fn new(p: &Poly) -> Compiled {
        let s = symbols();
        let terms: Vec<Term> = p
            .terms()
            .iter()
            .map(|(m, c)| {
                let coef = match c.as_i64() {
                    Some(n) if n.unsigned_abs() <= 1 << 53 => I::point(n as f64),
                    _ => I::from_q(&c.to_big()),
                };
                let (mut p0, mut da, mut factors) = (0, 0, Vec::new());
                for (sym, e) in m.factors() {
                    if sym == s.p0 {
                        p0 = e as usize;
                    } else if sym == s.delta_a {
                        da = e as usize;
                    } else {
                        assert!(
                            !s.trims().contains(&sym),
                            "trim symbols are grouped out before compiling"
                        );
                        factors.push((sym.index() as u8, e as u8));
                    }
                }
                Term {
                    coef,
                    factors,
                    shared: 0,
                    p0,
                    da,
                }
            })
            .collect();
        Compiled::of_terms(terms)
    }

    /// The compiled form of `terms` (sorted by their factors, shared prefixes counted).
    fn of_terms(mut terms: Vec<Term>) -> Compiled {
        terms.sort_by(|a, b| a.factors.cmp(&b.factors));
        if let Some(first) = terms.first_mut() {
            first.shared = 0;
        }
        for i in 1..terms.len() {
            let (before, this) = (&terms[i - 1].factors, &terms[i].factors);
            terms[i].shared = before.iter().zip(this).take_while(|(a, b)| a == b).count();
        }
        Compiled {
            p0_degree: terms.iter().map(|t| t.p0).max().unwrap_or(0),
            da_degree: terms.iter().map(|t| t.da).max().unwrap_or(0),
            depth: terms.iter().map(|t| t.factors.len()).max().unwrap_or(0),
            relative: RelativeTerms::new(&terms),
            terms,
        }
    }

    /// The enclosure as a polynomial in P0 and delta_a: evaluated in f64 with a bound on its
    /// rounding (`Compiled::lift_rounded`) where the table and the coefficients allow it,
    /// otherwise in interval arithmetic.
    pub fn lift<T: Num>(&self, table: &Table<T>) -> Dense2<T> {
        let mut cells = [I::point(0.0); MAX_CELLS];
        let rounded = (table.relative.as_ref())
            .is_some_and(|r| self.lift_rounded(&table.row_of, r, &mut cells));
        if !rounded {
            return self.lift_intervals(table);
        }
        let width = self.p0_degree + 1;
        let rows = cells[..width * (self.da_degree + 1)].chunks(width);
        Dense2::new(
            rows.map(|row| Dense::new(row.iter().map(|c| T::constant(*c)).collect()))
                .collect(),
        )
    }

    /// Writes to `out` the enclosures of the coefficients of `P0^i delta_a^j` (row by row in
    /// `j`, `i` ascending within a row), evaluated in f64 from the relative form of the table;
    /// `false` (and `out` meaningless) when the evaluation cannot promise its bound: a term's
    /// relative error bound above [`MAX_SIGMA`], a product that could leave the exponent range
    /// of [`MAX_EXPONENT`], a power beyond the table's, too many cells or factors for the
    /// stack, a value not finite.
    ///
    /// Why the bound holds. Each factor is `x^e = m_e prod (1 + h_i)` with `sum |h_i| <= eps_e`
    /// (its table entry, [`Relative::new`]), the coefficient `c = m_c (1 + h_c)` with
    /// `|h_c| <= eps_c`, and the computed product of the `k` midpoints and `m_c` takes `k + 1`
    /// roundings, each within a relative `u` (no underflow, no overflow: the exponent check).
    /// So the exact term `t` and the computed `t~` satisfy
    /// `t = t~ (1 + h_c) prod (1 + h_i) / prod (1 + d)` with `|d| <= u`, and
    /// `|t - t~| <= |t~| (exp(sigma') - 1)` for `sigma' = eps_c + sum eps_e + (k + 1) u / (1 - u)`;
    /// for `sigma' <= 2^-20` that is below `|t~| sigma (1 + 2^-19)`, `sigma` the sum of the
    /// term's `eps_c + (k + 1) u` and its factors' `eps_e`. The recursive sum `s` of the `t~`
    /// is off from their exact sum by at most `u` times the sum `b` of its absolute partial
    /// sums (Higham, Accuracy and Stability, section 4.2: one rounding of at most `u |s_k|` per
    /// addition, none for a subnormal sum). So the exact coefficient lies within
    /// `a (1 + 2^-19) + u b` of `s`, `a = sum |t~| sigma`. `a`, `b` and the `sigma` are computed
    /// from nonnegative terms in round-to-nearest, each low by a relative `(n + k + 3) u` at
    /// most (`n` terms per cell, fewer than 2^20); the factor `1 + 2^-10` covers all of it and
    /// the two roundings of the radius itself, and the ends are pushed out by an ulp. (The
    /// count is generous: the first factor's product with 1 is exact; `b u` is exact unless
    /// every partial sum is below about `2^-969`, when the additions were exact too; the
    /// `MAX_SIGMA` test is itself rounded, and the exponential bound holds far beyond it.)
    ///
    /// A cell all of whose terms hold an exact zero factor or coefficient (a parameter that is
    /// exactly zero) comes out as the exact zero, as in interval arithmetic: structural zeros
    /// stay exact, so that degrees stay exact. Unlike interval arithmetic, terms of exact data
    /// that cancel exactly give a small interval around zero, not the exact zero: sound, and
    /// at worst a coefficient that may vanish, which sends the aircraft to the exact path.
    fn lift_rounded(
        &self,
        row_of: &[u8; MAX_SYMS],
        t: &Relative,
        out: &mut [I; MAX_CELLS],
    ) -> bool {
        let Some(c) = self.relative.as_ref() else {
            return false;
        };
        let degree = c.max_degree as i32;
        // Every product of entries of total degree at most `degree` and a coefficient lies in
        // [2^(degree lo + lo_c), 2^(degree hi + hi_c)] (lo <= 0 <= hi), and so does its
        // computed value (rounding is monotone and powers of two are doubles).
        let low = degree * t.exponents.0 + c.exponents.0;
        let high = degree * t.exponents.1 + c.exponents.1;
        let width = self.p0_degree + 1;
        let n = width * (self.da_degree + 1);
        if c.max_power > POWERS
            || self.depth >= MAX_DEPTH
            || n > MAX_CELLS
            || self.terms.len() >= 1 << 20
            || c.sigma + self.depth as f64 * t.eps > MAX_SIGMA
            || low < -MAX_EXPONENT
            || high > MAX_EXPONENT
        {
            return false;
        }
        let mut cells = [Cell::default(); MAX_CELLS];
        // prefix[k]: the computed product of the current term's first k midpoints, and the sum
        // of their relative radii.
        let mut prefix = [(1.0f64, 0.0f64); MAX_DEPTH + 1];
        for (term, &(m_c, sigma_c)) in self.terms.iter().zip(&c.coefs) {
            let mut k = term.shared;
            for &(sym, e) in &term.factors[term.shared..] {
                let Some(row) = t.rows.get(row_of[sym as usize] as usize) else {
                    return false;
                };
                let (m, eps) = row[e as usize];
                let (p, s) = prefix[k];
                k += 1;
                prefix[k] = (p * m, s + eps);
            }
            let (p, s) = prefix[k];
            let v = p * m_c;
            let cell = &mut cells[term.da * width + term.p0];
            cell.s += v;
            cell.a += v.abs() * (s + sigma_c);
            cell.b += cell.s.abs();
        }
        let safety = 1.0 + 1.0 / 1024.0;
        for (o, &Cell { s, a, b }) in out.iter_mut().zip(&cells[..n]) {
            let r = (a + b * UNIT) * safety;
            if !(s.is_finite() && r.is_finite()) {
                return false;
            }
            *o = if r == 0.0 {
                // Every term exactly zero (sigma > 0: a nonzero term gives a > 0).
                I::point(s)
            } else {
                I::new(
                    crate::interval::next_down(s - r),
                    crate::interval::next_up(s + r),
                )
            };
        }
        true
    }

    /// The enclosure as a polynomial in P0 and delta_a, in interval arithmetic.
    fn lift_intervals<T: Num>(&self, table: &Table<T>) -> Dense2<T> {
        let zero = T::constant(I::point(0.0));
        let mut grid = vec![vec![zero; self.p0_degree + 1]; self.da_degree + 1];
        // prefix[k]: the product of the current term's first k factors.
        let mut prefix = Vec::with_capacity(self.depth + 1);
        prefix.push(T::constant(I::point(1.0)));
        for t in &self.terms {
            prefix.truncate(t.shared + 1);
            for (sym, e) in &t.factors[t.shared..] {
                let next = prefix[prefix.len() - 1] * table.pow(*sym, *e);
                prefix.push(next);
            }
            let value = prefix[t.factors.len()] * T::constant(t.coef);
            grid[t.da][t.p0] = grid[t.da][t.p0] + value;
        }
        Dense2::new(grid.into_iter().map(Dense::new).collect())
    }

    /// The highest power of P0.
    pub fn p0_degree(&self) -> usize {
        self.p0_degree
    }

    /// `self` with every symbol not in `keep` folded into the coefficients: each term's
    /// coefficient times the enclosures of those symbols' powers from `fixed`, terms that then
    /// share their monomial summed. Lifting the result by a table of the kept symbols encloses
    /// what lifting `self` by `fixed` with those kept values encloses, in a pass over the terms
    /// in the kept symbols only (a box's samples, where only the uncertain data vary). A folded
    /// symbol without a value in `fixed` folds in the whole real line: sound, and useless.
    pub fn folded(&self, fixed: &Table<I>, keep: &[bool; MAX_SYMS]) -> Compiled {
        let mut terms: Vec<Term> = self
            .terms
            .iter()
            .map(|t| {
                let kept = |(sym, _): &&(u8, u8)| keep[*sym as usize];
                let coef = t
                    .factors
                    .iter()
                    .filter(|f| !kept(f))
                    .fold(t.coef, |c, (sym, e)| c * fixed.pow(*sym, *e));
                Term {
                    coef,
                    factors: t.factors.iter().filter(kept).copied().collect(),
                    ..*t
                }
            })
            .collect();
        terms.sort_by(|a, b| (&a.factors, a.p0, a.da).cmp(&(&b.factors, b.p0, b.da)));
        let mut merged: Vec<Term> = Vec::with_capacity(terms.len());
        for t in terms {
            match merged.last_mut() {
                Some(m) if (&m.factors, m.p0, m.da) == (&t.factors, t.p0, t.da) => {
                    m.coef = m.coef + t.coef;
                }
                _ => merged.push(t),
            }
        }
        Compiled::of_terms(merged)
    }
}

/// Step 8 of one trim quantity: its grouping and each group's coefficient compiled.
#[derive(Clone, Debug)]
pub struct Cleared {
    /// The grouping by monomials in the trim symbols.
    pub groups: TrimGroups,
    /// The coefficient of each group, compiled.
    pub coefficients: Vec<Compiled>,
}

impl Cleared {
    fn new(f: &Poly, t: &[Sym]) -> Cleared {
        Cleared::with_power(f, t, TRIM_DEGREE)
    }

    /// Step 8 of `f` (of degree at most `k` in the trim symbols `t`) with clearing power `k`.
    fn with_power(f: &Poly, t: &[Sym], k: u32) -> Cleared {
        let groups = TrimGroups::new(f, t, k);
        let coefficients = groups.coefficients().map(Compiled::new).collect();
        Cleared {
            groups,
            coefficients,
        }
    }
}

/// Every parametric result the certified route evaluates, compiled once.
#[derive(Debug)]
pub struct Parametric {
    /// det A (Eq. 4).
    pub det_a: Compiled,
    /// The trim numerators (Eqs 3-4).
    pub trim: [Compiled; 4],
    /// The roll equation at the trim, det J5 and d, grouped for step 8 with the trim of Eqs 3-4.
    pub roll: Cleared,
    /// det J5 on the trim.
    pub det_j5: Cleared,
    /// The static-residual denominator d (Eq. 22) on the trim.
    pub d: Cleared,
    /// det A1 of the zero-sideslip trim (Eq. 35).
    pub zs_det: Compiled,
    /// Its numerators (Eq. 35).
    pub zs_trim: [Compiled; 3],
    /// det J5 and d at beta0 = 0, grouped for step 8 with the zero-sideslip trim.
    pub zs_det_j5: Cleared,
    /// d at beta0 = 0.
    pub zs_d: Cleared,
    /// The lateral control determinant `l_delta_a n_delta_r - l_delta_r n_delta_a` (the
    /// denominator of the zero-sideslip controls).
    pub lateral: Compiled,
}

/// The characteristic coefficients `c1..c5` of J5 ([`crate::specialise::parametric_characteristic`])
/// grouped for step 8 with clearing power `k` for `c_k` (`C_k = den^k c_k(num / den)`, as
/// [`crate::derivation::hopf::cleared_coefficients`] clears them): the Hopf polynomial's
/// ingredients, compiled on first use (the jump analysis, Monte Carlo and clearance never need
/// them).
#[derive(Debug)]
pub struct Characteristic {
    /// `c1..c5` on the trim of Eqs 3-4.
    pub c: [Cleared; 5],
    /// `c1..c5` at beta0 = 0 on the zero-sideslip trim (Eq. 35).
    pub zs_c: [Cleared; 5],
}

impl Characteristic {
    /// The compiled characteristic coefficients of the process's parametric derivation.
    pub fn get() -> &'static Characteristic {
        static C: OnceLock<Characteristic> = OnceLock::new();
        C.get_or_init(|| {
            let s = symbols();
            let c = crate::specialise::parametric_characteristic();
            let t4 = [s.alpha0, s.beta0, s.q0, s.r0];
            let t3 = [s.alpha0, s.q0, s.r0];
            let zero = Poly::zero();
            Characteristic {
                c: std::array::from_fn(|k| Cleared::with_power(&c[k], &t4, k as u32 + 1)),
                zs_c: std::array::from_fn(|k| {
                    Cleared::with_power(&c[k].subs(s.beta0, &zero), &t3, k as u32 + 1)
                }),
            }
        })
    }
}

impl Parametric {
    /// The compiled form of the process's parametric derivation.
    pub fn get() -> &'static Parametric {
        static P: OnceLock<Parametric> = OnceLock::new();
        P.get_or_init(|| Parametric::new(crate::specialise::parametric()))
    }

    /// The highest power of P0 in any compiled result.
    pub fn p0_degree(&self) -> usize {
        let cleared = [
            &self.roll,
            &self.det_j5,
            &self.d,
            &self.zs_det_j5,
            &self.zs_d,
        ];
        cleared
            .iter()
            .flat_map(|c| c.coefficients.iter())
            .chain([&self.det_a, &self.zs_det, &self.lateral])
            .chain(self.trim.iter())
            .chain(self.zs_trim.iter())
            .map(Compiled::p0_degree)
            .max()
            .unwrap_or(0)
    }

    /// Every result with the symbols valued in `fixed` (not `keep`) folded into its
    /// coefficients ([`Compiled::folded`]); the groupings are the same.
    pub fn folded(&self, fixed: &Table<I>, keep: &[bool; MAX_SYMS]) -> Parametric {
        let one = |c: &Compiled| c.folded(fixed, keep);
        let cleared = |c: &Cleared| Cleared {
            groups: c.groups.clone(),
            coefficients: c.coefficients.iter().map(one).collect(),
        };
        Parametric {
            det_a: one(&self.det_a),
            trim: std::array::from_fn(|i| one(&self.trim[i])),
            roll: cleared(&self.roll),
            det_j5: cleared(&self.det_j5),
            d: cleared(&self.d),
            zs_det: one(&self.zs_det),
            zs_trim: std::array::from_fn(|i| one(&self.zs_trim[i])),
            zs_det_j5: cleared(&self.zs_det_j5),
            zs_d: cleared(&self.zs_d),
            lateral: one(&self.lateral),
        }
    }

    fn new(par: &Derivation) -> Parametric {
        let s = symbols();
        let t4 = [s.alpha0, s.beta0, s.q0, s.r0];
        let t3 = [s.alpha0, s.q0, s.r0];
        let zero = Poly::zero();
        Parametric {
            det_a: Compiled::new(&par.det_a),
            trim: std::array::from_fn(|i| Compiled::new(&par.trim[i])),
            roll: Cleared::new(&par.roll_at_trim, &t4),
            det_j5: Cleared::new(&par.det_j5, &t4),
            d: Cleared::new(&par.d, &t4),
            zs_det: Compiled::new(&par.zs_det),
            zs_trim: std::array::from_fn(|i| Compiled::new(&par.zs_trim[i])),
            zs_det_j5: Cleared::new(&par.det_j5.subs(s.beta0, &zero), &t3),
            zs_d: Cleared::new(&par.d.subs(s.beta0, &zero), &t3),
            lateral: Compiled::new(&par.zs_delta_a.den),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::aircraft::Param;
    use crate::algebra::{Mono, Q};
    use num_rational::BigRational;

    /// A polynomial in four parameters, P0 and delta_a from `terms` (coefficient numerator,
    /// whether it is divided by 3, which no double holds, and exponents), and exact data for the four from `data` (mantissa, binary exponent, kind:
    /// an exact double, a tenth of one, which no double holds, or the exact zero).
    fn case(terms: &[(i64, bool, [u32; 6])], data: &[(f64, i32, u8)]) -> (Poly, Vec<(Sym, Q)>) {
        let s = symbols();
        let params = [Param::Lp, Param::NBeta, Param::C, Param::MDeltaE].map(|p| s.param(p));
        let vars = [params[0], params[1], params[2], params[3], s.p0, s.delta_a];
        let poly = Poly::from_terms(terms.iter().map(|(c, third, e)| {
            let mut m = Mono::ONE;
            for (v, k) in vars.iter().zip(e) {
                m.set(*v, *k);
            }
            (m, Q::ratio(*c, if *third { 3 } else { 1 }))
        }));
        let values = params
            .iter()
            .zip(data)
            .map(|(p, (m, e, kind))| {
                let x = BigRational::from_float(m * 2f64.powi(*e)).expect("finite");
                let v = match kind {
                    0 => x,
                    1 => x / BigRational::from_integer(10.into()),
                    _ => BigRational::from_integer(0.into()),
                };
                (*p, Q::from_big(v))
            })
            .collect();
        (poly, values)
    }

    proptest::proptest! {
        /// The lift in f64 with its rounding bound encloses the exact coefficients, in
        /// rationals, of random polynomials at random exact data (doubles, values no double
        /// holds, exact zeros; enclosed to an ulp or widened) and coefficients (integers,
        /// thirds), over magnitudes from tiny to huge; exact zeros stay exact, the
        /// enclosures stay as tight as a few ulps of the terms' magnitudes, and the evaluation
        /// is taken wherever the magnitudes allow it.
        #[test]
        fn the_lift_in_f64_encloses_the_exact_coefficients(
            terms in proptest::collection::vec(
                (-50i64..50, proptest::bool::ANY, proptest::array::uniform6(0u32..4)), 1..40),
            data in proptest::collection::vec((0.5f64..1.0, -3i32..3, 0u8..3), 4),
            scale in proptest::sample::select(vec![0, 20, -20, 60, -60, 130, -130]),
            sign in proptest::collection::vec(proptest::bool::ANY, 4),
            widen in proptest::sample::select(vec![0.0, 1e-12, 1e-9]),
        ) {
            let data: Vec<(f64, i32, u8)> = data
                .iter()
                .zip(&sign)
                .map(|((m, e, k), neg)| (if *neg { -m } else { *m }, e + scale, *k))
                .collect();
            let (poly, values) = case(&terms, &data);
            let compiled = Compiled::new(&poly);
            let mut by_symbol = [None; MAX_SYMS];
            for (sym, q) in &values {
                // Widened by a relative `widen` (as a box of uncertain data would be): the
                // exact value stays inside.
                let i = I::from_q(&q.to_big());
                let w = |x: f64| x.abs() * widen;
                by_symbol[sym.index()] = Some(if i.is_exact_zero() {
                    i
                } else {
                    I::new(
                        crate::interval::next_down(i.lo - w(i.lo)),
                        crate::interval::next_up(i.hi + w(i.hi)),
                    )
                });
            }
            let table = Table::new(&by_symbol);
            let mut out = [I::point(0.0); MAX_CELLS];
            let rounded = compiled.lift_rounded(
                &table.row_of,
                table.relative.as_ref().expect("point data have a relative form"),
                &mut out,
            );
            // Total degree at most 12 in data of magnitude up to 2^(3 + 130): the products stay
            // within 2^900 when the scale is at most 60.
            proptest::prop_assert!(rounded || scale.abs() > 60, "refused at scale {scale}");
            if !rounded {
                return Ok(());
            }
            let exact = poly.subs_values(&values);
            let s = symbols();
            let width = compiled.p0_degree + 1;
            for j in 0..=compiled.da_degree {
                for i in 0..width {
                    let cell = out[j * width + i];
                    let mono = {
                        let mut m = Mono::ONE;
                        m.set(s.p0, i as u32);
                        m.set(s.delta_a, j as u32);
                        m
                    };
                    let q = exact
                        .terms()
                        .iter()
                        .find(|(m, _)| *m == mono)
                        .map_or(BigRational::from_integer(0.into()), |(_, c)| c.to_big());
                    let f = |v: f64| BigRational::from_float(v).expect("finite");
                    proptest::prop_assert!(
                        f(cell.lo) <= q && q <= f(cell.hi),
                        "P0^{i} delta_a^{j}: {cell:?} misses {q}"
                    );
                    if q == BigRational::from_integer(0.into()) && cell.lo != cell.hi {
                        // Only a cancellation may leave a nonzero width around zero.
                        proptest::prop_assert!(cell.width() < 1e-10 * 2f64.powi(12 * scale.abs()));
                    }
                }
            }
        }
    }
}
