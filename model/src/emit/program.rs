//! A function's DAG as straight-line statements, decided once for every target language.
//!
//! The Rust and C printers must evaluate the same operations in the same order with the same
//! grouping, or their results would differ in the last bits: floating-point addition is not
//! associative. This module makes every such decision (which nodes get a temporary `tN`, where
//! parentheses go) once, so the printers only spell the result. Nodes used once are inlined
//! into their parent; a right operand that is itself a sum or product is parenthesized, so
//! evaluation order is the DAG's, never a re-association.

use super::expr::{Dag, Id, Node};
use crate::algebra::Q;

/// A binary arithmetic operator.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Op {
    /// `+`
    Add,
    /// `-`
    Sub,
    /// `*`
    Mul,
    /// `/`
    Div,
}

impl Op {
    /// The operator's symbol, the same in Rust and C.
    pub fn symbol(self) -> &'static str {
        match self {
            Op::Add => "+",
            Op::Sub => "-",
            Op::Mul => "*",
            Op::Div => "/",
        }
    }
}

/// An expression of the target language's common arithmetic subset.
#[derive(Clone, Debug, PartialEq)]
pub enum Expr {
    /// An exact constant; the printer rounds it once to the nearest f64.
    Const(Q),
    /// An input by its DAG name (`k.field` for a field of the derivatives argument).
    Input(String),
    /// The temporary `t{n}` bound by statement `n`.
    Temp(usize),
    /// `a op b`, evaluated left to right.
    Binary(Op, Box<Expr>, Box<Expr>),
    /// `-a`
    Neg(Box<Expr>),
    /// The correctly rounded square root of `a`.
    Sqrt(Box<Expr>),
    /// `(a)`: grouping the printer must keep.
    Paren(Box<Expr>),
}

/// Straight-line code: statement `n` binds the temporary `t{n}`; then the outputs.
#[derive(Clone, Debug, PartialEq)]
pub struct Program {
    /// Right-hand sides of `let tN = ...`, in order.
    pub temps: Vec<Expr>,
    /// One expression per output.
    pub outputs: Vec<Expr>,
}

/// Precedence of an expression: atoms bind tightest.
#[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
enum Prec {
    Atom,
    Unary,
    Product,
    Sum,
}

fn wrap((e, p): (Expr, Prec), max: Prec) -> Expr {
    if p > max {
        Expr::Paren(Box::new(e))
    } else {
        e
    }
}

/// The program computing `outputs` of `dag`: live nodes in DAG order (children first), a
/// temporary for every operation used more than once.
pub fn program(dag: &Dag, outputs: &[Id]) -> Program {
    let live = dag.live(outputs);
    let n = dag.nodes().len();
    let mut uses = vec![0usize; n];
    for (i, l) in live.iter().enumerate() {
        if *l {
            for c in dag.children(Id(i as u32)) {
                uses[c.0 as usize] += 1;
            }
        }
    }
    for o in outputs {
        uses[o.0 as usize] += 1;
    }
    let mut expr: Vec<Option<(Expr, Prec)>> = vec![None; n];
    let mut temps = Vec::new();
    for (i, node) in dag.nodes().iter().enumerate() {
        if !live[i] {
            continue;
        }
        let get = |id: &Id| {
            expr[id.0 as usize]
                .clone()
                .expect("children are emitted before parents")
        };
        let binary = |op: Op, a: &Id, b: &Id, (left, right, prec): (Prec, Prec, Prec)| {
            let x = Box::new(wrap(get(a), left));
            let y = Box::new(wrap(get(b), right));
            (Expr::Binary(op, x, y), prec)
        };
        const SUM: (Prec, Prec, Prec) = (Prec::Sum, Prec::Product, Prec::Sum);
        const PRODUCT: (Prec, Prec, Prec) = (Prec::Product, Prec::Atom, Prec::Product);
        let (e, prec) = match node {
            Node::Const(q) => {
                let prec = if q.is_negative() {
                    Prec::Unary
                } else {
                    Prec::Atom
                };
                (Expr::Const(q.clone()), prec)
            }
            Node::Input(k) => (Expr::Input(dag.inputs()[*k as usize].clone()), Prec::Atom),
            Node::Add(a, b) => binary(Op::Add, a, b, SUM),
            Node::Sub(a, b) => binary(Op::Sub, a, b, SUM),
            Node::Mul(a, b) => binary(Op::Mul, a, b, PRODUCT),
            Node::Div(a, b) => binary(Op::Div, a, b, PRODUCT),
            Node::Neg(a) => (Expr::Neg(Box::new(wrap(get(a), Prec::Atom))), Prec::Unary),
            Node::Sqrt(a) => (Expr::Sqrt(Box::new(get(a).0)), Prec::Atom),
        };
        let is_leaf = matches!(node, Node::Const(_) | Node::Input(_));
        if is_leaf || uses[i] <= 1 {
            expr[i] = Some((e, prec));
        } else {
            expr[i] = Some((Expr::Temp(temps.len()), Prec::Atom));
            temps.push(e);
        }
    }
    let outputs = outputs
        .iter()
        .map(|o| expr[o.0 as usize].clone().expect("output emitted").0)
        .collect();
    Program { temps, outputs }
}

/// The inputs the program reads, by DAG name (a function may ignore an argument).
pub fn inputs_used(dag: &Dag, outputs: &[Id]) -> Vec<String> {
    let live = dag.live(outputs);
    dag.nodes()
        .iter()
        .enumerate()
        .filter_map(|(i, node)| match node {
            Node::Input(k) if live[i] => Some(dag.inputs()[*k as usize].clone()),
            _ => None,
        })
        .collect()
}
