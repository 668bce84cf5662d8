//! The program builder: the derivation's polynomials, matrices and trims as nodes of one
//! [`Dag`], with the leaves bound to a function's inputs (the parameters `k.*`, the controls and
//! P0 as named arguments, the trim symbols as nodes already built).
//!
//! It knows the paper's constructions once, for every program built from them: Cramer's rule on
//! the trim equations (Eqs 3-4), the trim branches of the roll equation, the zero-sideslip trim
//! (Eq. 35), step 8 of the derivation ([`clear_trim`]) on single nodes and on polynomials in P0
//! given by coefficient nodes, and det K by the matrix determinant lemma (Eqs 16, 27-31).

use crate::aircraft::Param;
use crate::algebra::{Matrix, Poly, Sym, Q};
use crate::derivation::{clear_trim, Clearing, Derivation, TRIM_DEGREE};
use crate::equations::symbols;
use crate::program::expr::{Dag, Id};

/// A scalar argument of a generated function (besides `k: &Derivatives`).
#[derive(Clone, Debug, PartialEq)]
pub struct Arg {
    /// Rust name.
    pub name: &'static str,
    /// Doc: meaning and unit.
    pub doc: &'static str,
}

pub(crate) const P0: Arg = Arg {
    name: "p0",
    doc: "trim roll rate P0, rad/s",
};
pub(crate) const DE: Arg = Arg {
    name: "delta_e",
    doc: "elevator deflection, rad",
};
pub(crate) const DR: Arg = Arg {
    name: "delta_r",
    doc: "rudder deflection, rad",
};

/// Builds the leaf map of a function: parameters from `k`, controls and P0 from arguments,
/// trim symbols from already-computed nodes.
pub(crate) struct Ctx {
    pub(crate) dag: Dag,
    pub(crate) bound: Vec<(Sym, Id)>,
    /// Symbols every polynomial is built as a Horner scheme in first ([`Dag::poly_over`]):
    /// empty for the greedy scheme; the late symbols for a program split by [`super::stage`].
    pub(crate) outer: Vec<Sym>,
}

impl Ctx {
    pub(crate) fn new(takes_derivatives: bool, args: &[Arg]) -> Ctx {
        let s = symbols();
        let mut dag = Dag::new();
        let mut bound = Vec::new();
        for a in args {
            let id = dag.input(a.name);
            let sym = match a.name {
                "p0" => s.p0,
                "delta_e" => s.delta_e,
                "delta_r" => s.delta_r,
                "alpha" => s.alpha0,
                "beta" => s.beta0,
                "p" => s.p0,
                "q" => s.q0,
                "r" => s.r0,
                other => unreachable!("argument {other}"),
            };
            bound.push((sym, id));
        }
        if takes_derivatives {
            for p in Param::ALL {
                let id = dag.input(&format!("k.{}", p.key().to_lowercase()));
                bound.push((s.param(p), id));
            }
        }
        Ctx {
            dag,
            bound,
            outer: Vec::new(),
        }
    }

    pub(crate) fn poly(&mut self, p: &Poly) -> Id {
        let bound = self.bound.clone();
        let leaf = move |x: Sym| -> Id {
            // The innermost (latest) binding wins: `cleared` rebinds the trim symbols to
            // numerators on top of the trim itself.
            bound
                .iter()
                .rev()
                .find(|(s, _)| *s == x)
                .map(|(_, id)| *id)
                .unwrap_or_else(|| panic!("symbol {x} is not bound in this function"))
        };
        if self.outer.is_empty() {
            self.dag.poly(p, &leaf)
        } else {
            self.dag.poly_over(p, &self.outer.clone(), &leaf)
        }
    }

    pub(crate) fn bind(&mut self, s: Sym, id: Id) {
        self.bound.push((s, id));
    }

    /// Nodes of a matrix's entries.
    pub(crate) fn matrix(&mut self, m: &Matrix) -> Vec<Vec<Id>> {
        (0..m.rows())
            .map(|i| (0..m.cols()).map(|j| self.poly(m.get(i, j))).collect())
            .collect()
    }

    /// Determinant of the submatrix on the row and column masks, by Laplace expansion along
    /// its first row, memoised so that cofactors shared by det A and Cramer's rule are built
    /// once (the DAG shares them anyway; the memo saves the work).
    pub(crate) fn minor(
        &mut self,
        m: &[Vec<Id>],
        rows: u32,
        cols: u32,
        memo: &mut Vec<((u32, u32), Id)>,
    ) -> Id {
        if rows == 0 {
            return self.dag.constant(Q::ONE);
        }
        if let Some((_, id)) = memo.iter().find(|(k, _)| *k == (rows, cols)) {
            return *id;
        }
        let r = rows.trailing_zeros() as usize;
        let mut acc = self.dag.constant(Q::ZERO);
        let mut positive = true;
        for (c, entry) in m[r].iter().enumerate() {
            if cols & (1 << c) == 0 {
                continue;
            }
            let sub = self.minor(m, rows & !(1 << r), cols & !(1 << c), memo);
            let t = self.dag.mul(*entry, sub);
            acc = if positive {
                self.dag.add(acc, t)
            } else {
                self.dag.sub(acc, t)
            };
            positive = !positive;
        }
        memo.push(((rows, cols), acc));
        acc
    }

    /// Solves `A x + c = 0` by Cramer's rule in the DAG: `x_i = -sum_r C_ri c_r / det A`
    /// with cofactors `C_ri`, one reciprocal of det A.
    pub(crate) fn cramer(&mut self, a: &Matrix, c: &[Poly]) -> Vec<Id> {
        let (nums, det) = self.cramer_numerators(a, c);
        let one = self.dag.constant(Q::ONE);
        let inv = self.dag.div(one, det);
        nums.iter().map(|n| self.dag.mul(*n, inv)).collect()
    }

    /// Cramer's numerators `-sum_r C_ri c_r` and the denominator det A, without dividing.
    pub(crate) fn cramer_numerators(&mut self, a: &Matrix, c: &[Poly]) -> (Vec<Id>, Id) {
        let m = self.matrix(a);
        let c: Vec<Id> = c.iter().map(|p| self.poly(p)).collect();
        let n = m.len();
        let all = (1u32 << n) - 1;
        let mut memo = Vec::new();
        let det = self.minor(&m, all, all, &mut memo);
        let nums = (0..n)
            .map(|i| {
                let mut acc = self.dag.constant(Q::ZERO);
                for (r, cr) in c.iter().enumerate() {
                    let minor = self.minor(&m, all & !(1 << r), all & !(1 << i), &mut memo);
                    let t = self.dag.mul(*cr, minor);
                    // x_i = -sum_r (-1)^(r+i) M_ri c_r / det
                    acc = if (r + i) % 2 == 0 {
                        self.dag.sub(acc, t)
                    } else {
                        self.dag.add(acc, t)
                    };
                }
                acc
            })
            .collect();
        (nums, det)
    }

    /// `f * den^k` with the trim symbols `t` bound to `num / den`, built without division
    /// (step 8, [`clear_trim`] on single nodes).
    pub(crate) fn cleared(&mut self, f: &Poly, t: &[Sym], num: &[Id], den: Id, k: u32) -> Id {
        clear_trim(&mut Nodes(self), f, t, num, &den, k)
    }

    /// det K with a single division (Eq. 27 by the matrix determinant lemma): with the trim
    /// numerators N over det A, `det K = det K0 - (h^ . adj(K0) g^) / d^` where g^ = g det A,
    /// h^ = h det A and d^ = d det(A)^2 are polynomials in N and det A.
    pub(crate) fn det_k_one_division(
        &mut self,
        d: &Derivation,
        a: &Matrix,
        rhs: &[Poly],
        t: &[Sym],
    ) -> Id {
        let (num, det) = self.cramer_numerators(a, rhs);
        self.det_k_cleared(d, t, &num, det, None)
    }

    /// det K from the trim numerators `num` over `det` (the second half of
    /// [`Ctx::det_k_one_division`]); `det_k0` is det K0 when the caller has it already, else it
    /// is built from K0's entries.
    pub(crate) fn det_k_cleared(
        &mut self,
        d: &Derivation,
        t: &[Sym],
        num: &[Id],
        det: Id,
        det_k0: Option<Id>,
    ) -> Id {
        let g = [
            self.cleared(&d.g[0], t, num, det, 1),
            self.cleared(&d.g[1], t, num, det, 1),
        ];
        let h = [
            self.cleared(&d.h[0], t, num, det, 1),
            self.cleared(&d.h[1], t, num, det, 1),
        ];
        let dd = self.cleared(&d.d, t, num, det, 2);
        let k0: Vec<Vec<Id>> = (0..2)
            .map(|i| (0..2).map(|j| self.poly(&d.k0[i][j])).collect())
            .collect();
        let det_k0 =
            det_k0.unwrap_or_else(|| self.det2([[k0[0][0], k0[0][1]], [k0[1][0], k0[1][1]]]));
        // adj(K0) g^ = [K0_11 g0 - K0_01 g1, K0_00 g1 - K0_10 g0]
        let a0 = {
            let x = self.dag.mul(k0[1][1], g[0]);
            let y = self.dag.mul(k0[0][1], g[1]);
            self.dag.sub(x, y)
        };
        let a1 = {
            let x = self.dag.mul(k0[0][0], g[1]);
            let y = self.dag.mul(k0[1][0], g[0]);
            self.dag.sub(x, y)
        };
        let quad = {
            let x = self.dag.mul(h[0], a0);
            let y = self.dag.mul(h[1], a1);
            self.dag.add(x, y)
        };
        let frac = self.dag.div(quad, dd);
        self.dag.sub(det_k0, frac)
    }

    /// Binds alpha0, beta0, Q0, R0 and delta_a of the unconstrained trim at P0 (Eqs 3-4 and the
    /// roll equation), on the trim branch that continues the trim without aileron yaw.
    ///
    /// The four trim equations give `x0 = a + delta_a b` (Cramer, one reciprocal of det A; `b` is
    /// the response to the `n_delta_a delta_a` term of the yaw equation), and the roll equation
    /// `f(x0, delta_a) = 0` is then the quadratic `g2 delta_a^2 + g1 delta_a + g0 = 0` with
    /// `g0 = f(a)`, `g1 = grad f(a) . b + l_delta_a`, `g2 = b^T H b / 2` (f is quadratic in the
    /// trim through `-E Q0 R0`). Its root `delta_a = -2 g0 / (g1 (1 + sqrt(1 - 4 g0 g2 / g1^2)))`
    /// is the cancellation-free form of the quadratic formula for the root that tends to
    /// `-g0 / g1` as `g2 -> 0`: exact for `n_delta_a = 0`, NaN where the two trims of P0 are
    /// complex, without a branch. Returns `[alpha0, beta0, Q0, R0, delta_a]`.
    pub(crate) fn trim(&mut self, d: &Derivation) -> [Id; 5] {
        self.trim_branch(d, 0)
    }

    /// As [`Ctx::trim`] for trim branch `branch`: 0 is the branch that continues the trim
    /// without aileron yaw (the root that tends to `-g0 / g1`), 1 the other root of the
    /// quadratic, `delta_a = -g1 (1 + sqrt(1 - 4 g0 g2 / g1^2)) / (2 g2)` (the quadratic's other
    /// root, also cancellation-free). Branch 1 is NaN where the two trims are complex and
    /// infinite or NaN without aileron yaw (g2 = 0: a single trim). The shared nodes (the trim's
    /// affine parts, g0, g1, g2, the square root) are built once: the DAG hash-conses them.
    pub(crate) fn trim_branch(&mut self, d: &Derivation, branch: usize) -> [Id; 5] {
        let s = symbols();
        let rhs0: Vec<Poly> = d.a_rhs.iter().map(|p| p.coeff(s.delta_a, 0)).collect();
        let rhs1: Vec<Poly> = d.a_rhs.iter().map(|p| p.coeff(s.delta_a, 1)).collect();
        let a = self.cramer(&d.a, &rhs0);
        let b = self.cramer(&d.a, &rhs1);
        let syms = [s.alpha0, s.beta0, s.q0, s.r0];
        for (sym, id) in syms.iter().zip(&a) {
            self.bind(*sym, *id);
        }
        let f0 = d.roll_at_trim.coeff(s.delta_a, 0);
        let g0 = self.poly(&f0);
        let mut g1 = self.poly(&d.roll_at_trim.coeff(s.delta_a, 1));
        let mut g2 = self.dag.constant(Q::ZERO);
        for (i, ti) in syms.iter().enumerate() {
            let grad = f0.diff(*ti);
            let gi = self.poly(&grad);
            let t = self.dag.mul(gi, b[i]);
            g1 = self.dag.add(g1, t);
            for (j, tj) in syms.iter().enumerate() {
                let h = grad.diff(*tj).scale(&Q::ratio(1, 2));
                if h.is_zero() {
                    continue;
                }
                let hij = self.poly(&h);
                let bb = self.dag.mul(b[i], b[j]);
                let t = self.dag.mul(hij, bb);
                g2 = self.dag.add(g2, t);
            }
        }
        let dag = &mut self.dag;
        let g0g2 = dag.mul(g0, g2);
        let g1sq = dag.mul(g1, g1);
        let w = dag.div(g0g2, g1sq);
        let four = dag.constant(Q::int(4));
        let one = dag.constant(Q::ONE);
        let w4 = dag.mul(four, w);
        let disc = dag.sub(one, w4);
        let root = dag.sqrt(disc);
        let onep = dag.add(one, root);
        let two = dag.constant(Q::int(2));
        let da = if branch == 0 {
            let den = dag.mul(g1, onep);
            let num = dag.mul(two, g0);
            let q = dag.div(num, den);
            dag.neg(q)
        } else {
            let num = dag.mul(g1, onep);
            let den = dag.mul(two, g2);
            let q = dag.div(num, den);
            dag.neg(q)
        };
        let mut x = [da; 4];
        for i in 0..4 {
            let t = self.dag.mul(da, b[i]);
            x[i] = self.dag.add(a[i], t);
        }
        self.bound.retain(|(sym, _)| !syms.contains(sym));
        for (sym, id) in syms.iter().zip(&x) {
            self.bind(*sym, *id);
        }
        self.bind(s.delta_a, da);
        [x[0], x[1], x[2], x[3], da]
    }

    /// Binds alpha0, Q0, R0 of the zero-sideslip trim (Eq. 35) and beta0 = 0.
    pub(crate) fn zs_trim(&mut self, d: &Derivation) -> [Id; 3] {
        let s = symbols();
        let x = self.cramer(&d.zs_a, &d.zs_rhs);
        for (sym, id) in [s.alpha0, s.q0, s.r0].iter().zip(&x) {
            self.bind(*sym, *id);
        }
        let zero = self.dag.constant(Q::ZERO);
        self.bind(s.beta0, zero);
        [x[0], x[1], x[2]]
    }

    /// Coefficients of a polynomial in `x` as nodes (ascending powers).
    pub(crate) fn in_var(&mut self, p: &Poly, x: Sym) -> Vec<Id> {
        p.coeffs(x).iter().map(|c| self.poly(c)).collect()
    }

    /// Product of two polynomials in P0 given by coefficient nodes.
    pub(crate) fn conv(&mut self, a: &[Id], b: &[Id]) -> Vec<Id> {
        let zero = self.dag.constant(Q::ZERO);
        let mut out = vec![zero; a.len() + b.len() - 1];
        for (i, x) in a.iter().enumerate() {
            for (j, y) in b.iter().enumerate() {
                let t = self.dag.mul(*x, *y);
                out[i + j] = self.dag.add(out[i + j], t);
            }
        }
        out
    }

    /// `f(t = num / den) * den^k` as coefficient nodes in P0, with k = [`TRIM_DEGREE`] (step 8
    /// of the derivation, [`clear_trim`] by univariate convolutions).
    pub(crate) fn homogenize(&mut self, f: &Poly, t: &[Sym], num: &[Poly], den: &Poly) -> Vec<Id> {
        let p0 = symbols().p0;
        let num: Vec<Vec<Id>> = num.iter().map(|n| self.in_var(n, p0)).collect();
        let den = self.in_var(den, p0);
        clear_trim(&mut InVar(self, p0), f, t, &num, &den, TRIM_DEGREE)
    }
    /// det K from the bound trim: K = K0 - g h^T / d (Eqs 16, 27-31), then the 2x2 determinant.
    pub(crate) fn stiffness(&mut self, d: &Derivation) -> [[Id; 2]; 2] {
        let dd = self.poly(&d.d);
        let one = self.dag.constant(Q::ONE);
        let inv_d = self.dag.div(one, dd);
        let g = [self.poly(&d.g[0]), self.poly(&d.g[1])];
        let h = [self.poly(&d.h[0]), self.poly(&d.h[1])];
        let mut k = [[inv_d; 2]; 2];
        for i in 0..2 {
            let gi = self.dag.mul(g[i], inv_d);
            for j in 0..2 {
                let k0 = self.poly(&d.k0[i][j]);
                let f = self.dag.mul(gi, h[j]);
                k[i][j] = self.dag.sub(k0, f);
            }
        }
        k
    }

    pub(crate) fn det2(&mut self, k: [[Id; 2]; 2]) -> Id {
        let a = self.dag.mul(k[0][0], k[1][1]);
        let b = self.dag.mul(k[0][1], k[1][0]);
        self.dag.sub(a, b)
    }
}

/// The DAG as the ring of step 8, one node a value.
struct Nodes<'a>(&'a mut Ctx);

impl Clearing for Nodes<'_> {
    type Value = Id;
    fn lift(&mut self, p: &Poly) -> Id {
        self.0.poly(p)
    }
    fn add(&mut self, a: &Id, b: &Id) -> Id {
        self.0.dag.add(*a, *b)
    }
    fn mul(&mut self, a: &Id, b: &Id) -> Id {
        self.0.dag.mul(*a, *b)
    }
    fn pow(&mut self, a: &Id, n: u32) -> Id {
        self.0.dag.power(*a, n)
    }
}

/// Polynomials in one symbol as coefficient nodes (ascending powers): the ring of step 8 for the
/// jump polynomials (in P0) and for the trim condition in delta_a.
pub(crate) struct InVar<'a>(pub(crate) &'a mut Ctx, pub(crate) Sym);

impl Clearing for InVar<'_> {
    type Value = Vec<Id>;
    fn lift(&mut self, p: &Poly) -> Vec<Id> {
        self.0.in_var(p, self.1)
    }
    fn add(&mut self, a: &Vec<Id>, b: &Vec<Id>) -> Vec<Id> {
        let zero = self.0.dag.constant(Q::ZERO);
        (0..a.len().max(b.len()))
            .map(|i| {
                let (x, y) = (a.get(i).copied(), b.get(i).copied());
                self.0.dag.add(x.unwrap_or(zero), y.unwrap_or(zero))
            })
            .collect()
    }
    fn mul(&mut self, a: &Vec<Id>, b: &Vec<Id>) -> Vec<Id> {
        self.0.conv(a, b)
    }
}
