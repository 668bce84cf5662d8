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
    rows: Vec<[T; POWERS + 1]>,
    /// The row of each symbol, [`NO_VALUE`] for a symbol without one.
    row_of: [u8; MAX_SYMS],
}

/// [`Table::row_of`] of a symbol without a value.
const NO_VALUE: u8 = u8::MAX;
const _: () = assert!(MAX_SYMS < NO_VALUE as usize, "a row index for every symbol");

impl<T: Num> Table<T> {
    /// The table of `values`, indexed by symbol (`None`: no value).
    pub fn new(values: &[Option<T>; MAX_SYMS]) -> Table<T> {
        let mut row_of = [NO_VALUE; MAX_SYMS];
        let mut rows = Vec::with_capacity(values.iter().flatten().count());
        for (sym, v) in values.iter().enumerate() {
            if let Some(x) = v {
                row_of[sym] = rows.len() as u8;
                rows.push(Table::row(*x));
            }
        }
        Table { rows, row_of }
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
        let Some(p) = self.rows.get(self.row_of[sym as usize] as usize) else {
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
            terms,
        }
    }

    /// The enclosure as a polynomial in P0 and delta_a.
    pub fn lift<T: Num>(&self, table: &Table<T>) -> Dense2<T> {
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
