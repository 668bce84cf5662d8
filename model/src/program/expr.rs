//! Straight-line programs as a hash-consed expression DAG (egg's `RecExpr` idea).
//!
//! Every node's children come before it, and building a node that already exists returns the
//! existing id, so common subexpressions are shared by construction; emission is a walk that
//! prints `let tN = ...;`. Polynomials enter through a greedy multivariate Horner scheme
//! ([`Dag::poly`]), which writes powers as products (never a `powi` call) and keeps the
//! operation count low. Constants are exact rationals, rounded to f64 once at emission.
//!
//! The folding rules (sign hoisting, `x + (-c) = x - c`, `0 * x = 0`, `1 * x = x`) are exact
//! for finite values up to the sign of a zero result; `0 * x = 0` also drops the NaN that
//! IEEE arithmetic would give for an infinite or NaN `x`.

use crate::algebra::{Poly, Sym, Q};
use rustc_hash::FxHashMap;

/// The factors of a monomial, symbol and exponent.
type Factors = Vec<(Sym, u32)>;

/// Terms of a polynomial as (factors, coefficient), the input of the Horner scheme.
type Terms<C> = Vec<(Factors, C)>;

/// A coefficient of the Horner scheme: an exact constant, or a node (a polynomial in other
/// symbols, [`Dag::poly_over`]).
trait Coefficient: Sized {
    /// The coefficient as a node.
    fn node(self, dag: &mut Dag) -> Id;
    /// The sum of coefficients of one monomial, as a node.
    fn sum(dag: &mut Dag, cs: Vec<Self>) -> Id;
}

impl Coefficient for Q {
    fn node(self, dag: &mut Dag) -> Id {
        dag.constant(self)
    }
    fn sum(dag: &mut Dag, cs: Vec<Q>) -> Id {
        // Exact: the constants of one monomial add in rational arithmetic.
        let total = cs.iter().fold(Q::ZERO, |acc, c| &acc + c);
        dag.constant(total)
    }
}

impl Coefficient for Id {
    fn node(self, _: &mut Dag) -> Id {
        self
    }
    fn sum(dag: &mut Dag, cs: Vec<Id>) -> Id {
        let mut it = cs.into_iter();
        let first = it.next().unwrap_or_else(|| dag.constant(Q::ZERO));
        it.fold(first, |acc, c| dag.add(acc, c))
    }
}

/// Index of a node in a [`Dag`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Id(pub u32);

/// One operation of a straight-line program.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum Node {
    /// An exact constant.
    Const(Q),
    /// An input, by index into the program's input list.
    Input(u32),
    /// a + b
    Add(Id, Id),
    /// a - b
    Sub(Id, Id),
    /// a * b
    Mul(Id, Id),
    /// a / b
    Div(Id, Id),
    /// -a
    Neg(Id),
    /// sqrt(a) (libm; NaN for negative a, which is how "no root" is signalled without a branch)
    Sqrt(Id),
    /// copysign(a, b): the magnitude of a with the sign of b (IEEE 754 `copySign`, C99
    /// `copysign`, core's `f64::copysign`); exact, and how the stable quadratic formula picks
    /// the root without cancellation without a branch.
    CopySign(Id, Id),
}

impl Node {
    /// The same operation on the children `f` gives for this node's children (a leaf as it is):
    /// how passes that copy a DAG node for node rebuild a node.
    pub fn map_children(&self, f: impl Fn(Id) -> Id) -> Node {
        match *self {
            Node::Const(_) | Node::Input(_) => self.clone(),
            Node::Add(a, b) => Node::Add(f(a), f(b)),
            Node::Sub(a, b) => Node::Sub(f(a), f(b)),
            Node::Mul(a, b) => Node::Mul(f(a), f(b)),
            Node::Div(a, b) => Node::Div(f(a), f(b)),
            Node::Neg(a) => Node::Neg(f(a)),
            Node::Sqrt(a) => Node::Sqrt(f(a)),
            Node::CopySign(a, b) => Node::CopySign(f(a), f(b)),
        }
    }
}

/// Operation counts after common-subexpression elimination.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct OpCount {
    /// Additions and subtractions.
    pub add: usize,
    /// Multiplications.
    pub mul: usize,
    /// Divisions.
    pub div: usize,
    /// Negations.
    pub neg: usize,
    /// libm calls.
    pub libm: usize,
}

impl OpCount {
    /// Total arithmetic operations (SymPy's `count_ops` convention: negations count).
    pub fn total(&self) -> usize {
        self.add + self.mul + self.div + self.neg + self.libm
    }
}

/// A hash-consed expression DAG with named inputs.
#[derive(Clone, Debug, Default)]
pub struct Dag {
    nodes: Vec<Node>,
    index: FxHashMap<Node, Id>,
    inputs: Vec<String>,
}

impl Dag {
    /// An empty DAG.
    pub fn new() -> Dag {
        Dag::default()
    }

    /// The nodes, children before parents.
    pub fn nodes(&self) -> &[Node] {
        &self.nodes
    }

    /// Input names in declaration order.
    pub fn inputs(&self) -> &[String] {
        &self.inputs
    }

    /// Node by id.
    pub fn node(&self, id: Id) -> &Node {
        &self.nodes[id.0 as usize]
    }

    /// A DAG with the given inputs (in this order) and no node yet: the start of a pass that
    /// rebuilds a DAG ([`Dag::push`]).
    pub fn with_inputs(inputs: &[String]) -> Dag {
        Dag {
            inputs: inputs.to_vec(),
            ..Dag::default()
        }
    }

    /// Adds a node exactly as given (hash-consed, not folded): for passes that copy nodes of
    /// another DAG whose children they have already copied.
    pub fn push(&mut self, n: Node) -> Id {
        self.add_node(n)
    }

    fn add_node(&mut self, n: Node) -> Id {
        if let Some(id) = self.index.get(&n) {
            return *id;
        }
        let id = Id(self.nodes.len() as u32);
        self.nodes.push(n.clone());
        self.index.insert(n, id);
        id
    }

    /// Declares (or finds) the input called `name`.
    pub fn input(&mut self, name: &str) -> Id {
        let i = match self.inputs.iter().position(|n| n == name) {
            Some(i) => i,
            None => {
                self.inputs.push(name.to_string());
                self.inputs.len() - 1
            }
        };
        self.add_node(Node::Input(i as u32))
    }

    /// A constant.
    pub fn constant(&mut self, q: Q) -> Id {
        self.add_node(Node::Const(q))
    }

    fn as_const(&self, id: Id) -> Option<&Q> {
        match self.node(id) {
            Node::Const(q) => Some(q),
            _ => None,
        }
    }

    /// a + b (folds constants and zeros; a + (-b) becomes a - b).
    pub fn add(&mut self, a: Id, b: Id) -> Id {
        match (self.as_const(a).cloned(), self.as_const(b).cloned()) {
            (Some(x), Some(y)) => return self.constant(&x + &y),
            (Some(x), _) if x.is_zero() => return b,
            (_, Some(y)) if y.is_zero() => return a,
            _ => {}
        }
        if let Node::Neg(inner) = *self.node(b) {
            return self.sub(a, inner);
        }
        if let Node::Neg(inner) = *self.node(a) {
            return self.sub(b, inner);
        }
        // x + (-c) = x - c for a negative constant (exact).
        if let Some(y) = self.as_const(b).filter(|y| y.is_negative()).cloned() {
            let c = self.constant(-&y);
            return self.sub(a, c);
        }
        if let Some(x) = self.as_const(a).filter(|x| x.is_negative()).cloned() {
            let c = self.constant(-&x);
            return self.sub(b, c);
        }
        let (x, y) = if a <= b { (a, b) } else { (b, a) };
        self.add_node(Node::Add(x, y))
    }

    /// a - b.
    pub fn sub(&mut self, a: Id, b: Id) -> Id {
        match (self.as_const(a).cloned(), self.as_const(b).cloned()) {
            (Some(x), Some(y)) => return self.constant(&x - &y),
            (Some(x), _) if x.is_zero() => return self.neg(b),
            (_, Some(y)) if y.is_zero() => return a,
            _ => {}
        }
        if let Node::Neg(inner) = *self.node(b) {
            return self.add(a, inner);
        }
        // (-x) - y = -(x + y): exact in IEEE arithmetic, and lets a parent absorb the sign.
        if let Node::Neg(inner) = *self.node(a) {
            let s = self.add(inner, b);
            return self.neg(s);
        }
        self.add_node(Node::Sub(a, b))
    }

    /// a * b (folds constants, ones, zeros and signs).
    pub fn mul(&mut self, a: Id, b: Id) -> Id {
        match (self.as_const(a).cloned(), self.as_const(b).cloned()) {
            (Some(x), Some(y)) => return self.constant(&x * &y),
            (Some(x), _) if x.is_zero() => return a,
            (_, Some(y)) if y.is_zero() => return b,
            (Some(x), _) if x.is_one() => return b,
            (_, Some(y)) if y.is_one() => return a,
            (Some(x), _) if (-&x).is_one() => return self.neg(b),
            (_, Some(y)) if (-&y).is_one() => return self.neg(a),
            (Some(x), _) if x.is_negative() => {
                let c = self.constant(-&x);
                let m = self.mul(c, b);
                return self.neg(m);
            }
            (_, Some(y)) if y.is_negative() => {
                let c = self.constant(-&y);
                let m = self.mul(a, c);
                return self.neg(m);
            }
            _ => {}
        }
        if let Node::Neg(inner) = *self.node(a) {
            let m = self.mul(inner, b);
            return self.neg(m);
        }
        if let Node::Neg(inner) = *self.node(b) {
            let m = self.mul(a, inner);
            return self.neg(m);
        }
        let (x, y) = if a <= b { (a, b) } else { (b, a) };
        self.add_node(Node::Mul(x, y))
    }

    /// a / b.
    pub fn div(&mut self, a: Id, b: Id) -> Id {
        if let Some(y) = self.as_const(b).cloned() {
            if y.is_one() {
                return a;
            }
            // Exact quotient of constants (never by zero: that stays an IEEE division).
            if let Some(x) = self.as_const(a).cloned().filter(|_| !y.is_zero()) {
                return self.constant(x.div(&y));
            }
        }
        if let Node::Neg(inner) = *self.node(b) {
            let d = self.div(a, inner);
            return self.neg(d);
        }
        if let Node::Neg(inner) = *self.node(a) {
            let d = self.div(inner, b);
            return self.neg(d);
        }
        self.add_node(Node::Div(a, b))
    }

    /// -a. Sign rewrites are exact in IEEE arithmetic for finite values (up to the sign of a
    /// zero result), so they never change a finite result.
    pub fn neg(&mut self, a: Id) -> Id {
        if let Some(x) = self.as_const(a).cloned() {
            if x.is_negative() || x.is_zero() {
                return self.constant(-&x);
            }
        }
        match *self.node(a) {
            Node::Neg(inner) => inner,
            // -(x - y) = y - x exactly (rounding is symmetric).
            Node::Sub(x, y) => self.sub(y, x),
            _ => self.add_node(Node::Neg(a)),
        }
    }

    /// sqrt(a).
    pub fn sqrt(&mut self, a: Id) -> Id {
        // sqrt(0) = 0 and sqrt(1) = 1 exactly (folded data without aileron yaw reach them).
        if self.as_const(a).is_some_and(|x| x.is_zero() || x.is_one()) {
            return a;
        }
        self.add_node(Node::Sqrt(a))
    }

    /// copysign(a, b). Folded only when both are constants: the sign of a rational zero is +.
    pub fn copysign(&mut self, a: Id, b: Id) -> Id {
        if let (Some(x), Some(y)) = (self.as_const(a).cloned(), self.as_const(b).cloned()) {
            let m = if x.is_negative() { -&x } else { x };
            return self.constant(if y.is_negative() { -&m } else { m });
        }
        self.add_node(Node::CopySign(a, b))
    }

    /// `b + copysign(sqrt(b^2 - 4 (x y)), b)` for a quadratic `a t^2 + b t + c` with `x y = a c`:
    /// the cancellation-free denominator of its roots (two numbers of the same sign added;
    /// the roots are `-2 c / D` and `-D / (2 a)`), the one construction of every quadratic
    /// formula the emitter writes.
    pub fn stable_quadratic_sum(&mut self, b: Id, x: Id, y: Id) -> Id {
        let b_sq = self.mul(b, b);
        let xy = self.mul(x, y);
        let four = self.constant(Q::int(4));
        let f = self.mul(four, xy);
        let disc = self.sub(b_sq, f);
        let root = self.sqrt(disc);
        let signed = self.copysign(root, b);
        self.add(b, signed)
    }

    /// Builds a polynomial with a greedy multivariate Horner scheme: factor out the symbol that
    /// occurs in most terms, recurse on its coefficients. `leaf` maps each symbol to a node.
    pub fn poly(&mut self, p: &Poly, leaf: &dyn Fn(Sym) -> Id) -> Id {
        let terms: Terms<Q> = p
            .terms()
            .iter()
            .map(|(m, c)| (m.factors(), c.clone()))
            .collect();
        self.horner(terms, leaf)
    }

    /// Builds a polynomial as a Horner scheme in the symbols `outer` only, each coefficient (a
    /// polynomial in the other symbols) one node built by [`Dag::poly`]: the operations that
    /// involve `outer` are then only those of the scheme, and everything else is a coefficient
    /// that does not depend on them (what [`super::stage`] computes once per aircraft).
    pub fn poly_over(&mut self, p: &Poly, outer: &[Sym], leaf: &dyn Fn(Sym) -> Id) -> Id {
        let mut groups: Vec<(Vec<(Sym, u32)>, Poly)> = Vec::new();
        for (m, c) in p.terms() {
            let (out, rest): (Factors, Factors) = m
                .factors()
                .into_iter()
                .partition(|(s, _)| outer.contains(s));
            let mut r = crate::algebra::Mono::ONE;
            for (s, e) in rest {
                r.set(s, e);
            }
            let term = Poly::term(r, c.clone());
            match groups.iter_mut().find(|(f, _)| *f == out) {
                Some((_, q)) => *q = &*q + &term,
                None => groups.push((out, term)),
            }
        }
        let terms: Terms<Id> = groups
            .into_iter()
            .map(|(f, q)| (f, self.poly(&q, leaf)))
            .collect();
        self.horner(terms, leaf)
    }

    fn horner<C: Coefficient>(&mut self, terms: Terms<C>, leaf: &dyn Fn(Sym) -> Id) -> Id {
        if terms.is_empty() {
            return self.constant(Q::ZERO);
        }
        // Count in how many terms each symbol occurs; ties broken by symbol order (deterministic).
        let mut count: Vec<(Sym, usize)> = Vec::new();
        for (f, _) in &terms {
            for (s, _) in f {
                match count.iter_mut().find(|(t, _)| t == s) {
                    Some(e) => e.1 += 1,
                    None => count.push((*s, 1)),
                }
            }
        }
        if count.is_empty() {
            return C::sum(self, terms.into_iter().map(|(_, c)| c).collect());
        }
        count.sort_by(|a, b| b.1.cmp(&a.1).then(a.0.cmp(&b.0)));
        let (v, n) = count[0];
        if n == 1 && terms.len() > 1 {
            // No symbol is shared: a sum of monomials.
            let mut acc: Option<Id> = None;
            for (f, c) in terms {
                let t = self.monomial(&f, c, leaf);
                acc = Some(match acc {
                    None => t,
                    Some(a) => self.add(a, t),
                });
            }
            return acc.unwrap_or_else(|| self.constant(Q::ZERO));
        }
        if terms.len() == 1 {
            let (f, c) = terms.into_iter().next().expect("one term");
            return self.monomial(&f, c, leaf);
        }
        // Split by the power of v: p = sum_k v^k c_k, then Horner in v.
        let max = terms
            .iter()
            .map(|(f, _)| f.iter().find(|(s, _)| *s == v).map_or(0, |(_, e)| *e))
            .max()
            .unwrap_or(0);
        let mut by_power: Vec<Terms<C>> = (0..=max).map(|_| Vec::new()).collect();
        for (f, c) in terms {
            let e = f.iter().find(|(s, _)| *s == v).map_or(0, |(_, e)| *e);
            let rest: Vec<(Sym, u32)> = f.into_iter().filter(|(s, _)| *s != v).collect();
            by_power[e as usize].push((rest, c));
        }
        let x = leaf(v);
        let mut acc: Option<Id> = None;
        let mut pending = 0u32; // powers of v not yet multiplied in
        for k in (0..=max as usize).rev() {
            if let Some(a) = acc {
                pending += 1;
                if by_power[k].is_empty() && k > 0 {
                    continue;
                }
                let pw = self.power(x, pending);
                acc = Some(self.mul(a, pw));
                pending = 0;
            }
            if !by_power[k].is_empty() {
                let c = self.horner(std::mem::take(&mut by_power[k]), leaf);
                acc = Some(match acc {
                    None => c,
                    Some(a) => self.add(a, c),
                });
            }
        }
        let mut out = acc.unwrap_or_else(|| self.constant(Q::ZERO));
        if pending > 0 {
            let pw = self.power(x, pending);
            out = self.mul(out, pw);
        }
        out
    }

    /// x^k by repeated squaring, as products (shared through the DAG).
    pub fn power(&mut self, x: Id, k: u32) -> Id {
        match k {
            0 => self.constant(Q::ONE),
            1 => x,
            _ => {
                let half = self.power(x, k / 2);
                let sq = self.mul(half, half);
                if k % 2 == 1 {
                    self.mul(sq, x)
                } else {
                    sq
                }
            }
        }
    }

    fn monomial<C: Coefficient>(&mut self, f: &[(Sym, u32)], c: C, leaf: &dyn Fn(Sym) -> Id) -> Id {
        let mut acc: Option<Id> = None;
        for (s, e) in f {
            let x = leaf(*s);
            let p = self.power(x, *e);
            acc = Some(match acc {
                None => p,
                Some(a) => self.mul(a, p),
            });
        }
        let k = c.node(self);
        match acc {
            None => k,
            Some(a) => self.mul(k, a),
        }
    }

    /// Nodes reachable from `outputs`, in order (children first).
    pub fn live(&self, outputs: &[Id]) -> Vec<bool> {
        let mut live = vec![false; self.nodes.len()];
        let mut stack: Vec<Id> = outputs.to_vec();
        while let Some(id) = stack.pop() {
            if live[id.0 as usize] {
                continue;
            }
            live[id.0 as usize] = true;
            stack.extend(self.children(id));
        }
        live
    }

    /// Children of a node.
    pub fn children(&self, id: Id) -> Vec<Id> {
        match *self.node(id) {
            Node::Const(_) | Node::Input(_) => vec![],
            Node::Add(a, b)
            | Node::Sub(a, b)
            | Node::Mul(a, b)
            | Node::Div(a, b)
            | Node::CopySign(a, b) => vec![a, b],
            Node::Neg(a) | Node::Sqrt(a) => vec![a],
        }
    }

    /// Operation counts of the program computing `outputs` (after CSE).
    pub fn op_count(&self, outputs: &[Id]) -> OpCount {
        let live = self.live(outputs);
        let mut c = OpCount::default();
        for (i, n) in self.nodes.iter().enumerate() {
            if !live[i] {
                continue;
            }
            match n {
                Node::Add(..) | Node::Sub(..) => c.add += 1,
                Node::Mul(..) => c.mul += 1,
                Node::Div(..) => c.div += 1,
                Node::Neg(_) => c.neg += 1,
                Node::Sqrt(_) | Node::CopySign(..) => c.libm += 1,
                Node::Const(_) | Node::Input(_) => {}
            }
        }
        c
    }

    /// Evaluates `outputs` in f64 with the given input values (for tests of the emitter).
    pub fn eval(&self, outputs: &[Id], inputs: &[f64]) -> Vec<f64> {
        let mut v = vec![0.0; self.nodes.len()];
        for (i, n) in self.nodes.iter().enumerate() {
            let g = |id: &Id| v[id.0 as usize];
            v[i] = match n {
                Node::Const(q) => q.to_f64(),
                Node::Input(k) => inputs[*k as usize],
                Node::Add(a, b) => g(a) + g(b),
                Node::Sub(a, b) => g(a) - g(b),
                Node::Mul(a, b) => g(a) * g(b),
                Node::Div(a, b) => g(a) / g(b),
                Node::Neg(a) => -g(a),
                Node::Sqrt(a) => g(a).sqrt(),
                Node::CopySign(a, b) => g(a).copysign(g(b)),
            };
        }
        outputs.iter().map(|o| v[o.0 as usize]).collect()
    }
}
