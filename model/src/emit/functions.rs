//! Which derived results become which generated functions, and with what documentation.
//!
//! Each [`Function`] is a straight-line program over a [`Dag`] built from the derivation's
//! polynomials: the trim first (one division by det A), then the quantities that use it, so
//! that det K costs one trim, one reciprocal of d and a 2x2 determinant.

use super::expr::{Dag, Id};
use super::formulas::{block, Formula};
use super::linear::merge_like_terms;
use crate::aircraft::Param;
use crate::algebra::{Matrix, Poly, Sym, Q};
use crate::derivation::{clear_trim, Clearing, Derivation, TRIM_DEGREE};
use crate::equations::symbols;

mod certified;
mod hopf;
mod prepared;
pub(crate) use certified::criterion_program;
pub(crate) use hopf::polynomial as hopf_polynomial;
pub use prepared::{prepared, Prepared, TYPE as PREPARED_TYPE};

/// How a generated function returns its outputs.
#[derive(Clone, Debug, PartialEq)]
pub enum Ret {
    /// A single f64.
    Scalar,
    /// `[f64; N]`.
    Array(usize),
    /// `[[f64; C]; R]`.
    Matrix(usize, usize),
    /// A named struct with one f64 field per output.
    Struct(&'static str),
    /// `[S; N]` of a named struct: N values of S, outputs in order (all fields of the first,
    /// then of the second, ...); e.g. the trims of a roll rate, one per trim branch.
    Structs(&'static str, usize),
}

/// A scalar argument of a generated function (besides `k: &Derivatives`).
#[derive(Clone, Debug, PartialEq)]
pub struct Arg {
    /// Rust name.
    pub name: &'static str,
    /// Doc: meaning and unit.
    pub doc: &'static str,
}

/// One generated function.
#[derive(Clone, Debug)]
pub struct Function {
    /// Rust name.
    pub name: &'static str,
    /// Doc comment lines (formula, equation numbers, units).
    pub doc: Vec<String>,
    /// Whether the function takes `k: &Derivatives` (parametric) or has the data folded in.
    pub takes_derivatives: bool,
    /// Scalar arguments.
    pub args: Vec<Arg>,
    /// The program.
    pub dag: Dag,
    /// Output names (struct fields, or `""` for arrays) and nodes.
    pub outputs: Vec<(String, Id)>,
    /// Return shape.
    pub ret: Ret,
    /// The type whose `impl` block holds the function (`Some("Prepared")` for `Prepared::new`
    /// and `Prepared::det_k`), or `None` for a free function. A function whose program reads
    /// fields `self.fN` takes `&self`.
    pub owner: Option<&'static str>,
}

impl Function {
    /// Whether the function reads the fields of its owner (a method taking `&self`).
    pub fn takes_self(&self) -> bool {
        self.dag.inputs().iter().any(|i| i.starts_with("self."))
    }
}

/// A struct the functions return: name, doc, fields (name, doc).
pub type StructSpec = (
    &'static str,
    &'static str,
    Vec<(&'static str, &'static str)>,
);

/// The struct types the functions return.
pub fn structs() -> Vec<StructSpec> {
    vec![
        (
            "Trim",
            "A pseudo-steady trim of the unconstrained roll at roll rate P0 (Eqs 3-4 and the roll equation); `trim` returns one per trim branch.",
            vec![
                ("alpha", "Angle of attack alpha_0, rad."),
                ("beta", "Sideslip beta_0, rad."),
                ("q", "Pitch rate Q_0, rad/s."),
                ("r", "Yaw rate R_0, rad/s."),
                ("delta_a", "Aileron deflection holding the trim, rad."),
            ],
        ),
        (
            "ZeroSideslipTrim",
            "Trim of the zero-sideslip roll at roll rate P0 (Eqs 32-35): beta = 0, rudder freed.",
            vec![
                ("alpha", "Angle of attack alpha_0, rad."),
                ("q", "Pitch rate Q_0, rad/s."),
                ("r", "Yaw rate R_0, rad/s."),
                ("delta_a", "Aileron deflection holding the trim, rad."),
                (
                    "delta_r",
                    "Rudder deflection holding zero sideslip (the schedule), rad; non-finite without lateral control authority (l_delta_a n_delta_r = l_delta_r n_delta_a).",
                ),
            ],
        ),
    ]
}

const P0: Arg = Arg {
    name: "p0",
    doc: "trim roll rate P0, rad/s",
};
const DE: Arg = Arg {
    name: "delta_e",
    doc: "elevator deflection, rad",
};
const DR: Arg = Arg {
    name: "delta_r",
    doc: "rudder deflection, rad",
};

/// Builds the leaf map of a function: parameters from `k`, controls and P0 from arguments,
/// trim symbols from already-computed nodes.
struct Ctx {
    dag: Dag,
    bound: Vec<(Sym, Id)>,
    /// Symbols every polynomial is built as a Horner scheme in first ([`Dag::poly_over`]):
    /// empty for the greedy scheme; the late symbols for a program split by [`super::stage`].
    outer: Vec<Sym>,
}

impl Ctx {
    fn new(takes_derivatives: bool, args: &[Arg]) -> Ctx {
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

    fn poly(&mut self, p: &Poly) -> Id {
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

    fn bind(&mut self, s: Sym, id: Id) {
        self.bound.push((s, id));
    }

    /// Nodes of a matrix's entries.
    fn matrix(&mut self, m: &Matrix) -> Vec<Vec<Id>> {
        (0..m.rows())
            .map(|i| (0..m.cols()).map(|j| self.poly(m.get(i, j))).collect())
            .collect()
    }

    /// Determinant of the submatrix on the row and column masks, by Laplace expansion along
    /// its first row, memoised so that cofactors shared by det A and Cramer's rule are built
    /// once (the DAG shares them anyway; the memo saves the work).
    fn minor(
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
    fn cramer(&mut self, a: &Matrix, c: &[Poly]) -> Vec<Id> {
        let (nums, det) = self.cramer_numerators(a, c);
        let one = self.dag.constant(Q::ONE);
        let inv = self.dag.div(one, det);
        nums.iter().map(|n| self.dag.mul(*n, inv)).collect()
    }

    /// Cramer's numerators `-sum_r C_ri c_r` and the denominator det A, without dividing.
    fn cramer_numerators(&mut self, a: &Matrix, c: &[Poly]) -> (Vec<Id>, Id) {
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
    fn cleared(&mut self, f: &Poly, t: &[Sym], num: &[Id], den: Id, k: u32) -> Id {
        clear_trim(&mut Nodes(self), f, t, num, &den, k)
    }

    /// det K with a single division (Eq. 27 by the matrix determinant lemma): with the trim
    /// numerators N over det A, `det K = det K0 - (h^ . adj(K0) g^) / d^` where g^ = g det A,
    /// h^ = h det A and d^ = d det(A)^2 are polynomials in N and det A.
    fn det_k_one_division(&mut self, d: &Derivation, a: &Matrix, rhs: &[Poly], t: &[Sym]) -> Id {
        let (num, det) = self.cramer_numerators(a, rhs);
        self.det_k_cleared(d, t, &num, det, None)
    }

    /// det K from the trim numerators `num` over `det` (the second half of
    /// [`Ctx::det_k_one_division`]); `det_k0` is det K0 when the caller has it already, else it
    /// is built from K0's entries.
    fn det_k_cleared(
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
    fn trim(&mut self, d: &Derivation) -> [Id; 5] {
        self.trim_branch(d, 0)
    }

    /// As [`Ctx::trim`] for trim branch `branch`: 0 is the branch that continues the trim
    /// without aileron yaw (the root that tends to `-g0 / g1`), 1 the other root of the
    /// quadratic, `delta_a = -g1 (1 + sqrt(1 - 4 g0 g2 / g1^2)) / (2 g2)` (the quadratic's other
    /// root, also cancellation-free). Branch 1 is NaN where the two trims are complex and
    /// infinite or NaN without aileron yaw (g2 = 0: a single trim). The shared nodes (the trim's
    /// affine parts, g0, g1, g2, the square root) are built once: the DAG hash-conses them.
    fn trim_branch(&mut self, d: &Derivation, branch: usize) -> [Id; 5] {
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
    fn zs_trim(&mut self, d: &Derivation) -> [Id; 3] {
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
    fn in_var(&mut self, p: &Poly, x: Sym) -> Vec<Id> {
        p.coeffs(x).iter().map(|c| self.poly(c)).collect()
    }

    /// Product of two polynomials in P0 given by coefficient nodes.
    fn conv(&mut self, a: &[Id], b: &[Id]) -> Vec<Id> {
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
    fn homogenize(&mut self, f: &Poly, t: &[Sym], num: &[Poly], den: &Poly) -> Vec<Id> {
        let p0 = symbols().p0;
        let num: Vec<Vec<Id>> = num.iter().map(|n| self.in_var(n, p0)).collect();
        let den = self.in_var(den, p0);
        clear_trim(&mut InVar(self, p0), f, t, &num, &den, TRIM_DEGREE)
    }
    /// det K from the bound trim: K = K0 - g h^T / d (Eqs 16, 27-31), then the 2x2 determinant.
    fn stiffness(&mut self, d: &Derivation) -> [[Id; 2]; 2] {
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

    fn det2(&mut self, k: [[Id; 2]; 2]) -> Id {
        let a = self.dag.mul(k[0][0], k[1][1]);
        let b = self.dag.mul(k[0][1], k[1][0]);
        self.dag.sub(a, b)
    }

    fn finish(
        self,
        name: &'static str,
        doc: Vec<String>,
        takes: bool,
        args: Vec<Arg>,
        outputs: Vec<(String, Id)>,
        ret: Ret,
    ) -> Function {
        // Like terms merged exactly before anything is printed or counted.
        let ids: Vec<Id> = outputs.iter().map(|(_, id)| *id).collect();
        let (dag, ids) = merge_like_terms(&self.dag, &ids);
        Function {
            name,
            doc,
            takes_derivatives: takes,
            args,
            dag,
            outputs: outputs
                .into_iter()
                .zip(ids)
                .map(|((n, _), id)| (n, id))
                .collect(),
            ret,
            owner: None,
        }
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
struct InVar<'a>(&'a mut Ctx, Sym);

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

fn lines(v: &[&str]) -> Vec<String> {
    v.iter().map(|s| s.to_string()).collect()
}

/// K0, g, h and d of Eqs 16, 22 and 27-31, the quantities det K is built from.
fn stiffness_formulas(par: &Derivation) -> [(&'static str, Formula<'_>); 4] {
    [
        (
            "K0",
            Formula::Matrix(par.k0.iter().map(|r| r.iter().collect()).collect()),
        ),
        ("g", Formula::Vector(par.g.iter().collect())),
        ("h", Formula::Vector(par.h.iter().collect())),
        ("d", Formula::Poly(&par.d)),
    ]
}

/// Prose lines followed by the block of formulas they name.
fn with_formulas(v: &[&str], items: &[(&str, Formula)]) -> Vec<String> {
    let mut out = lines(v);
    out.extend(block(items));
    out
}

/// All generated functions for a derivation (parametric when `takes_derivatives`).
pub fn functions(d: &Derivation, takes_derivatives: bool) -> Vec<Function> {
    let s = symbols();
    // The documented formulas are the parametric derivation's (the same polynomials as `d`'s
    // before the data are folded in).
    let par = crate::specialise::parametric();
    let t = takes_derivatives;
    let mut out = Vec::new();
    let trim_args = vec![P0, DE, DR];

    // trim: both branches
    {
        let mut c = Ctx::new(t, &trim_args);
        let mut outputs = Vec::new();
        for branch in 0..2 {
            let [a, b, q, r, da] = c.trim_branch(d, branch);
            for (name, id) in [
                ("alpha", a),
                ("beta", b),
                ("q", q),
                ("r", r),
                ("delta_a", da),
            ] {
                outputs.push((name.to_string(), id));
            }
        }
        out.push(c.finish(
            "trim",
            with_formulas(
                &[
                    "Pseudo-steady trims at roll rate `p0` (Eqs 1-4): `x0 = [alpha0, beta0, Q0, R0]` solves",
                    "`A x0 + b = 0` (Cramer's rule, one division by det A), affine in delta_a (aileron yaw",
                    "`n_delta_a` enters b); the aileron then solves the roll equation `p_dot = 0` along it,",
                    "a quadratic `g2 delta_a^2 + g1 delta_a + g0 = 0` (`g2 = 0` without aileron yaw). Element",
                    "0 is the trim that continues the trim without aileron yaw (the root that tends to",
                    "`-g0/g1`), element 1 the other root; both by the cancellation-free quadratic formula.",
                    "NaN where the two trims of `p0` are complex; element 1 is infinite or NaN without",
                    "aileron yaw (a single trim). Angles in rad, rates in rad/s. Non-finite where det A = 0",
                    "(the divergence roll rates). The other functions of `p0` use element 0.",
                ],
                &[
                    ("A", Formula::matrix(&par.a)),
                    ("b", Formula::Vector(par.a_rhs.iter().collect())),
                    ("p_dot", Formula::Poly(&par.roll_at_trim)),
                ],
            ),
            t,
            trim_args.clone(),
            outputs,
            Ret::Structs("Trim", 2),
        ));
    }
    // zero-sideslip trim
    {
        let args = vec![P0, DE];
        let mut c = Ctx::new(t, &args);
        let [a, q, r] = c.zs_trim(d);
        // The roll and yaw equations hold the trim with both lateral controls (Cramer on the
        // 2x2 system, one reciprocal of its determinant l_delta_a n_delta_r - l_delta_r n_delta_a).
        let den = c.poly(&d.zs_delta_a.den);
        let one = c.dag.constant(Q::ONE);
        let inv = c.dag.div(one, den);
        let num_a = c.poly(&d.zs_delta_a.num);
        let da = c.dag.mul(num_a, inv);
        let num_r = c.poly(&d.zs_delta_r.num);
        let dr = c.dag.mul(num_r, inv);
        let outputs = vec![
            ("alpha".into(), a),
            ("q".into(), q),
            ("r".into(), r),
            ("delta_a".into(), da),
            ("delta_r".into(), dr),
        ];
        out.push(c.finish(
            "zero_sideslip_trim",
            with_formulas(
                &[
                    "Trim of the zero-sideslip roll at roll rate `p0` (Eqs 32-35): beta = 0 with the",
                    "rudder freed; `[alpha0, Q0, R0]` solves `A1 x + b1 = 0` (the alpha, beta and q",
                    "equations), the aileron and the rudder the roll and yaw equations together (with",
                    "aileron yaw and roll due to rudder both controls enter both; the rudder is the",
                    "schedule of the aileron-rudder interconnect, Fig. 9). Angles in rad, rates in rad/s.",
                ],
                &[
                    ("A1", Formula::matrix(&par.zs_a)),
                    ("b1", Formula::Vector(par.zs_rhs.iter().collect())),
                    ("delta_a", Formula::Ratio(&par.zs_delta_a)),
                    ("delta_r", Formula::Ratio(&par.zs_delta_r)),
                ],
            ),
            t,
            args,
            outputs,
            Ret::Struct("ZeroSideslipTrim"),
        ));
    }
    // jacobian5
    {
        let args = vec![
            Arg {
                name: "alpha",
                doc: "angle of attack, rad",
            },
            Arg {
                name: "beta",
                doc: "sideslip, rad",
            },
            Arg {
                name: "p",
                doc: "roll rate, rad/s",
            },
            Arg {
                name: "q",
                doc: "pitch rate, rad/s",
            },
            Arg {
                name: "r",
                doc: "yaw rate, rad/s",
            },
        ];
        let mut c = Ctx::new(t, &args);
        let mut outputs = Vec::new();
        for i in 0..5 {
            for j in 0..5 {
                let id = c.poly(d.jacobian.get(i, j));
                outputs.push((String::new(), id));
            }
        }
        out.push(c.finish(
            "jacobian5",
            with_formulas(
                &[
                    "The 5x5 Jacobian of the PSS model (Appendix A.2) at the state",
                    "x = [alpha, beta, p, q, r]: the linearized Eqs 6-10, row i = d(x_i dot)/dx, 1/s;",
                    "below with `(alpha0, beta0, P0, Q0, R0) = (alpha, beta, p, q, r)`.",
                ],
                &[("J5", Formula::matrix(&par.jacobian))],
            ),
            t,
            args,
            outputs,
            Ret::Matrix(5, 5),
        ));
    }
    // residual denominator d
    {
        let mut c = Ctx::new(t, &trim_args);
        c.trim(d);
        let dd = c.poly(&d.d);
        out.push(c.finish(
            "residual_denominator",
            with_formulas(
                &[
                    "The static-residual denominator d (Eq. 22) at the trim of `p0`, 1/s. det K has",
                    "poles where d = 0 (Fig. 8).",
                ],
                &[("d", Formula::Poly(&par.d))],
            ),
            t,
            trim_args.clone(),
            vec![(String::new(), dd)],
            Ret::Scalar,
        ));
    }
    // stiffness
    {
        let mut c = Ctx::new(t, &trim_args);
        c.trim(d);
        let k = c.stiffness(d);
        let outputs = k.iter().flatten().map(|id| (String::new(), *id)).collect();
        out.push(c.finish(
            "stiffness",
            with_formulas(
                &[
                    "The stiffness matrix K of the second-order form (Eqs 15-16, 27-31) at the trim of",
                    "`p0`: `K = K0 - g h^T / d` where K0 holds the coefficients of [alpha, beta] in",
                    "Eqs 13-14, g those of p and `p_s = -(h . [alpha, beta]) / d` is the static residual",
                    "(Eqs 22-25). 1/s^2.",
                ],
                &stiffness_formulas(par),
            ),
            t,
            trim_args.clone(),
            outputs,
            Ret::Matrix(2, 2),
        ));
    }
    // det K
    {
        let mut c = Ctx::new(t, &trim_args);
        let trims = [s.alpha0, s.beta0, s.q0, s.r0];
        // The trim's aileron first (it enters the trim through n_delta_a), then the cleared form.
        c.trim(d);
        let det = c.det_k_one_division(d, &d.a, &d.a_rhs, &trims);
        out.push(c.finish(
            "det_k",
            with_formulas(
                &[
                    "The jump criterion det K (Eq. 27) at the trim of `p0`, 1/s^4. Its zeros are the",
                    "saddle-node (jump) points of the PSS equilibria (Figs 7-8); `det J5 = d det K`.",
                    "Evaluated as `det K0 - h^T adj(K0) g / d` (the matrix determinant lemma on",
                    "`K = K0 - g h^T / d`) with the trim's denominator det A cleared from g, h and d, on",
                    "the trim branch of [`trim`].",
                ],
                &stiffness_formulas(par),
            ),
            t,
            trim_args.clone(),
            vec![(String::new(), det)],
            Ret::Scalar,
        ));
    }
    // det J5
    {
        let mut c = Ctx::new(t, &trim_args);
        c.trim(d);
        let det = c.poly(&d.det_j5);
        out.push(c.finish(
            "det_j5",
            lines(&[
                "The determinant of the 5x5 Jacobian at the trim of `p0`, 1/s^5;",
                "equal to `residual_denominator * det_k` identically (step 7 of the derivation).",
            ]),
            t,
            trim_args.clone(),
            vec![(String::new(), det)],
            Ret::Scalar,
        ));
    }
    // zero-sideslip det K
    {
        let args = vec![P0, DE];
        let mut c = Ctx::new(t, &args);
        let zero = c.dag.constant(Q::ZERO);
        c.bind(s.beta0, zero);
        let det = c.det_k_one_division(d, &d.zs_a, &d.zs_rhs, &[s.alpha0, s.q0, s.r0]);
        out.push(c.finish(
            "zero_sideslip_det_k",
            lines(&[
                "det K (Eq. 27) at the zero-sideslip trim of `p0` (section V.D, Fig. 11), 1/s^4: its",
                "zeros mark the departure (transcritical point) of the zero-sideslip roll. K0, g, h",
                "and d are those of [`det_k`] with `beta0 = 0`.",
            ]),
            t,
            args,
            vec![(String::new(), det)],
            Ret::Scalar,
        ));
    }
    // divergence biquadratic and its roots
    {
        let mut c = Ctx::new(t, &[]);
        let outs: Vec<(String, Id)> = d
            .biquadratic
            .iter()
            .map(|p| (String::new(), c.poly(p)))
            .collect();
        out.push(c.finish(
            "divergence_biquadratic",
            with_formulas(
                &[
                    "Coefficients [c0, c2, c4] of `det A = c4 P0^4 + c2 P0^2 + c0` (Eq. 5); its",
                    "positive roots are the pitch-yaw divergence roll rates of Table 1.",
                ],
                &[
                    ("c0", Formula::Poly(&par.biquadratic[0])),
                    ("c2", Formula::Poly(&par.biquadratic[1])),
                    ("c4", Formula::Poly(&par.biquadratic[2])),
                ],
            ),
            t,
            vec![],
            outs,
            Ret::Array(3),
        ));
    }
    {
        let mut c = Ctx::new(t, &[]);
        let [c0, c2, c4] = [0, 1, 2].map(|i| c.poly(&d.biquadratic[i]));
        let dag = &mut c.dag;
        // The cancellation-free quadratic formula in x = P0^2: q = -(c2 + sign(c2) sqrt(disc)) / 2
        // adds two numbers of the same sign, and the roots are c0 / q (the smaller in
        // magnitude) and q / c4 (the larger), each a single rounding of well-conditioned parts.
        let sum = dag.stable_quadratic_sum(c2, c4, c0);
        let half = dag.constant(Q::ratio(1, 2));
        let half_sum = dag.mul(sum, half);
        let q = dag.neg(half_sum);
        let small = dag.div(c0, q);
        let large = dag.div(q, c4);
        let p1 = dag.sqrt(small);
        let p2 = dag.sqrt(large);
        out.push(c.finish(
            "divergence_roll_rates",
            lines(&[
                "The divergence roll rates P1 <= P2 of Eq. 5 (Table 1), rad/s, the positive roots of",
                "`det A = c4 P0^4 + c2 P0^2 + c0` ([`divergence_biquadratic`]), by the cancellation-free",
                "quadratic formula in `P0^2`: `q = -(c2 + copysign(sqrt(c2^2 - 4 c4 c0), c2)) / 2`,",
                "`P1 = sqrt(c0 / q)` (the root of smaller magnitude), `P2 = sqrt(q / c4)`. Both are",
                "accurate to a few ulps of well-conditioned coefficients even when one root is tiny",
                "against the other (the textbook `(-c2 -+ sqrt(...)) / (2 c4)` loses the small one to",
                "cancellation); `c4 = 0` gives `P1 = sqrt(-c0 / c2)`. NaN for a root that does not",
                "exist (negative discriminant or `P0^2 < 0`), without a branch.",
            ]),
            t,
            vec![],
            vec![(String::new(), p1), (String::new(), p2)],
            Ret::Array(2),
        ));
    }
    // jump polynomials: det J5 with the trim substituted, by convolutions in P0 (step 8)
    {
        let args = trim_args[1..].to_vec();
        let mut c = Ctx::new(t, &args);
        // The trim without aileron yaw: its delta_a part is n_delta_a times N^a, so it is the
        // trim at delta_a = 0 whether n_delta_a is a symbol or an aircraft's folded value.
        let trim0: Vec<Poly> = d.trim.iter().map(|p| p.coeff(s.delta_a, 0)).collect();
        let coeffs = c.homogenize(
            &d.det_j5,
            &[s.alpha0, s.beta0, s.q0, s.r0],
            &trim0,
            &d.det_a,
        );
        // `1 + sqrt(-n_delta_a^2)` is 1 without aileron yaw and NaN with it, without a branch.
        let guard = {
            // n_delta_a as the model has it: a symbol, or the aircraft's folded value.
            let nda = c.poly(&d.model[4].coeff(s.delta_a, 1));
            let sq = c.dag.mul(nda, nda);
            let neg = c.dag.neg(sq);
            let root = c.dag.sqrt(neg);
            let one = c.dag.constant(Q::ONE);
            c.dag.add(one, root)
        };
        let outs: Vec<(String, Id)> = coeffs
            .iter()
            .map(|id| (String::new(), c.dag.mul(*id, guard)))
            .collect();
        let n = outs.len();
        out.push(c.finish(
            "jump_polynomial",
            lines(&[
                "Coefficients of P0^0 ..= P0^12 of the jump polynomial `det J5 * det(A)^2` (step 8).",
                "Its positive real roots that are not roots of det A or d are the jump roll rates.",
                "A polynomial in P0 alone exists only without aileron yaw: every coefficient is NaN",
                "when `n_delta_a != 0` (then `model analyze` eliminates delta_a by a resultant).",
            ]),
            t,
            args,
            outs,
            Ret::Array(n),
        ));
    }
    {
        let args = vec![DE];
        let mut c = Ctx::new(t, &args);
        let det = d.det_j5.subs(s.beta0, &Poly::zero());
        let coeffs = c.homogenize(&det, &[s.alpha0, s.q0, s.r0], &d.zs_trim, &d.zs_det);
        let outs: Vec<(String, Id)> = coeffs.iter().map(|id| (String::new(), *id)).collect();
        let n = outs.len();
        out.push(c.finish(
            "zero_sideslip_jump_polynomial",
            lines(&[
                "Coefficients of P0^0 ..= P0^8 of `det J5 * det(A1)^2` at the zero-sideslip trim",
                "(Eqs 32-35); its positive roots (not roots of det A1 or d) are the departure roll rates.",
            ]),
            t,
            args,
            outs,
            Ret::Array(n),
        ));
    }
    out.extend(hopf::functions(d, t));
    out
}
