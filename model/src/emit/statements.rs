//! A function's DAG as straight-line statements, decided once for every target language.
//!
//! The Rust and C printers must evaluate the same operations in the same order with the same
//! grouping, or their results would differ in the last bits: floating-point addition is not
//! associative. This module makes every such decision (which nodes get a temporary `tN`, which
//! constants get a name `KN`, where parentheses go) once, so the printers only spell the result.
//!
//! - Nodes used once are inlined into their parent; a right operand that is itself a sum or
//!   product is parenthesized, so evaluation order is the DAG's, never a re-association.
//! - No expression is longer than [`MAX_WIDTH`] characters (as printed in either language, one
//!   line, spaces included): a node whose inlined expression would be longer gets its widest
//!   operands bound to temporaries first. A temporary only names a value the program computes
//!   anyway, so the split changes no operation and no result, only what a reviewer reads at once.
//! - A constant whose shortest round-trip literal is its exact value (`0.959`, `2.0`: the data of
//!   Table A.1 and small integers) stays inline: the literal is the exact rational. Any other
//!   folded constant (a product of data such as `81.084922887...` that needs more digits than a
//!   double holds, or `1/3`) is a named constant `KN` of the function, declared before the
//!   temporaries with its exact value in a comment ([`exact_text`]), so a reviewer can check
//!   each of the roundings.

use crate::algebra::Q;
use crate::program::expr::{Dag, Id, Node};
use num_traits::{One, Zero};

/// The longest expression a program holds, in characters of either printed language on one line
/// (`let tN = ` / `const double tN = ` and the `;` not counted). 120 characters is one
/// line and a half of the generated crate's width, about ten operations: what a reviewer checks
/// against the derivation at a glance.
pub const MAX_WIDTH: usize = 120;

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
    /// A constant whose literal is its exact value, printed inline.
    Const(Q),
    /// The named constant `K{n}`, [`Program::constants`]`[n]`.
    Named(usize),
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
    /// `copysign(a, b)`: the magnitude of `a` with the sign of `b`.
    CopySign(Box<Expr>, Box<Expr>),
    /// `(a)`: grouping the printer must keep.
    Paren(Box<Expr>),
}

/// Straight-line code: the named constants, then statement `n` binding the temporary `t{n}`,
/// then the outputs.
#[derive(Clone, Debug, PartialEq)]
pub struct Program {
    /// Exact values of the named constants `K0, K1, ...`, each rounded once by the printer.
    pub constants: Vec<Q>,
    /// Right-hand sides of `let tN = ...`, in order.
    pub temps: Vec<Expr>,
    /// One expression per output.
    pub outputs: Vec<Expr>,
}

/// Precedence of an expression: atoms bind tightest.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
enum Prec {
    Atom,
    Unary,
    Product,
    Sum,
}

/// An expression with its precedence and printed width.
#[derive(Clone, Debug)]
struct Piece {
    e: Expr,
    prec: Prec,
    width: usize,
}

impl Piece {
    fn atom(e: Expr) -> Piece {
        let width = width(&e);
        Piece {
            e,
            prec: Prec::Atom,
            width,
        }
    }
}

fn wrap(p: &Piece, max: Prec) -> (Expr, usize) {
    if p.prec > max {
        (Expr::Paren(Box::new(p.e.clone())), p.width + 2)
    } else {
        (p.e.clone(), p.width)
    }
}

/// The printed width of a literal, the longer of the two printers' spellings (Rust writes
/// `1e16` as `10000000000000000.0`, C as `1e16`).
fn literal_width(q: &Q) -> usize {
    let x = q.to_f64();
    let sign = usize::from(x.is_sign_negative() && x != 0.0);
    let display = format!("{}", x.abs());
    let rust = display.len() + if display.contains(['.', 'e']) { 0 } else { 2 };
    sign + rust.max(format!("{:?}", x.abs()).len())
}

/// The width of an expression on one line, the longer of its Rust and C spellings
/// (`libm::sqrt(a)` against `sqrt(a)`, `(a).copysign(b)` against `copysign(a, b)`, `k->l_p`
/// against `k.l_p`).
fn width(e: &Expr) -> usize {
    match e {
        Expr::Const(q) => literal_width(q),
        Expr::Named(n) => format!("K{n}").len(),
        Expr::Input(name) => name.len() + usize::from(name.contains('.')),
        Expr::Temp(n) => format!("t{n}").len(),
        Expr::Binary(_, a, b) => width(a) + 3 + width(b),
        Expr::Neg(a) => 1 + width(a),
        Expr::Sqrt(a) => "libm::sqrt()".len() + width(a),
        Expr::CopySign(a, b) => "().copysign()".len() + width(a) + width(b),
        Expr::Paren(a) => 2 + width(a),
    }
}

/// Whether a constant's literal (the shortest decimal that rounds to its double, which both
/// printers write) is its exact value: then the literal itself carries the exact rational
/// (`0.959`, `2.0`) and only the compiler's one rounding stands between them.
fn literal_is_exact(q: &Q) -> bool {
    let x = q.to_f64();
    x.is_finite() && decimal(&format!("{x:?}")).is_some_and(|d| d == q.to_big())
}

/// The exact value of a decimal literal such as `-0.959`, `1e16` or `2.5e-7`.
fn decimal(lit: &str) -> Option<num_rational::BigRational> {
    use num_bigint::BigInt;
    let (mantissa, exp) = match lit.split_once('e') {
        Some((m, e)) => (m, e.parse::<i32>().ok()?),
        None => (lit, 0),
    };
    let (int, frac) = mantissa.split_once('.').unwrap_or((mantissa, ""));
    let digits: BigInt = format!("{int}{frac}").parse().ok()?;
    let e = exp - frac.len() as i32;
    let ten = num_rational::BigRational::from_integer(BigInt::from(10));
    let scale = if e >= 0 {
        num_traits::pow(ten, e as usize)
    } else {
        num_traits::pow(ten.recip(), (-e) as usize)
    };
    Some(num_rational::BigRational::from_integer(digits) * scale)
}

/// The exact value of a constant for a reviewer: a terminating decimal of at most 40 places
/// when the denominator has no prime factor but 2 and 5 (folded decimal data always), else
/// `p/q` in lowest terms.
///
/// ```
/// use model::algebra::Q;
/// use model::emit::statements::exact_text;
///
/// assert_eq!(exact_text(&Q::ratio(753774, 1000000)), "0.753774");
/// assert_eq!(exact_text(&Q::ratio(-1, 3)), "-1/3");
/// ```
pub fn exact_text(q: &Q) -> String {
    let r = q.to_big();
    let fraction = format!("{}/{}", r.numer(), r.denom());
    if r.is_integer() {
        return r.numer().to_string();
    }
    // Decimal digits after the point: the larger of the powers of 2 and 5 in the denominator.
    let mut d = r.denom().clone();
    let (two, five) = (num_bigint::BigInt::from(2), num_bigint::BigInt::from(5));
    let (mut twos, mut fives) = (0usize, 0usize);
    while (&d % &two).is_zero() {
        d /= &two;
        twos += 1;
    }
    while (&d % &five).is_zero() {
        d /= &five;
        fives += 1;
    }
    let digits = twos.max(fives);
    if !d.is_one() || digits > 40 {
        return fraction;
    }
    let scaled = r * num_rational::BigRational::from_integer(
        num_bigint::BigInt::from(10).pow(digits as u32),
    );
    let n = scaled.to_integer();
    let (sign, n) = if n < num_bigint::BigInt::zero() {
        ("-", -n)
    } else {
        ("", n)
    };
    let s = format!("{:0>width$}", n.to_string(), width = digits + 1);
    let (int, frac) = s.split_at(s.len() - digits);
    format!("{sign}{int}.{frac}")
}

/// The program computing `outputs` of `dag`: live nodes in DAG order (children first), a
/// temporary for every operation used more than once or needed to keep an expression within
/// [`MAX_WIDTH`], a named constant for every constant whose literal is not its exact value.
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
    let mut piece: Vec<Option<Piece>> = vec![None; n];
    let mut temps = Vec::new();
    let mut constants: Vec<Q> = Vec::new();
    for (i, node) in dag.nodes().iter().enumerate() {
        if !live[i] {
            continue;
        }
        let p = match node {
            Node::Const(q) if literal_is_exact(q) => Piece {
                e: Expr::Const(q.clone()),
                prec: if q.is_negative() {
                    Prec::Unary
                } else {
                    Prec::Atom
                },
                width: literal_width(q),
            },
            Node::Const(q) => {
                constants.push(q.clone());
                Piece::atom(Expr::Named(constants.len() - 1))
            }
            Node::Input(k) => Piece::atom(Expr::Input(dag.inputs()[*k as usize].clone())),
            _ => {
                let children = dag.children(Id(i as u32));
                let mut p = compose(node, &children, &piece);
                // Too wide: bind the widest operand that is still an inline expression, repeat.
                while p.width > MAX_WIDTH {
                    let widest = children
                        .iter()
                        .filter(|c| {
                            let c = piece[c.0 as usize].as_ref().expect("child first");
                            !matches!(
                                c.e,
                                Expr::Temp(_) | Expr::Named(_) | Expr::Const(_) | Expr::Input(_)
                            )
                        })
                        .max_by_key(|c| piece[c.0 as usize].as_ref().map_or(0, |p| p.width));
                    let Some(c) = widest else { break };
                    let cp = piece[c.0 as usize].take().expect("child first");
                    temps.push(cp.e);
                    piece[c.0 as usize] = Some(Piece::atom(Expr::Temp(temps.len() - 1)));
                    p = compose(node, &children, &piece);
                }
                if uses[i] > 1 {
                    temps.push(p.e);
                    Piece::atom(Expr::Temp(temps.len() - 1))
                } else {
                    p
                }
            }
        };
        piece[i] = Some(p);
    }
    let outputs = outputs
        .iter()
        .map(|o| piece[o.0 as usize].clone().expect("output emitted").e)
        .collect();
    Program {
        constants,
        temps,
        outputs,
    }
}

/// The inline expression of an operation from its children's current pieces.
fn compose(node: &Node, children: &[Id], piece: &[Option<Piece>]) -> Piece {
    let get = |k: usize| piece[children[k].0 as usize].as_ref().expect("child first");
    let binary = |op: Op, (left, right, prec): (Prec, Prec, Prec)| {
        let (x, wx) = wrap(get(0), left);
        let (y, wy) = wrap(get(1), right);
        Piece {
            e: Expr::Binary(op, Box::new(x), Box::new(y)),
            prec,
            width: wx + 3 + wy,
        }
    };
    const SUM: (Prec, Prec, Prec) = (Prec::Sum, Prec::Product, Prec::Sum);
    const PRODUCT: (Prec, Prec, Prec) = (Prec::Product, Prec::Atom, Prec::Product);
    match node {
        Node::Add(..) => binary(Op::Add, SUM),
        Node::Sub(..) => binary(Op::Sub, SUM),
        Node::Mul(..) => binary(Op::Mul, PRODUCT),
        Node::Div(..) => binary(Op::Div, PRODUCT),
        Node::Neg(_) => {
            let (x, w) = wrap(get(0), Prec::Atom);
            Piece {
                e: Expr::Neg(Box::new(x)),
                prec: Prec::Unary,
                width: 1 + w,
            }
        }
        Node::Sqrt(_) => Piece::atom(Expr::Sqrt(Box::new(get(0).e.clone()))),
        Node::CopySign(..) => Piece::atom(Expr::CopySign(
            Box::new(get(0).e.clone()),
            Box::new(get(1).e.clone()),
        )),
        Node::Const(_) | Node::Input(_) => unreachable!("leaves are not composed"),
    }
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

#[cfg(test)]
mod tests {
    use super::*;

    /// A long sum is split into temporaries within the cap, and the split program computes the
    /// same bits as the DAG evaluated node by node.
    #[test]
    fn long_expressions_are_split_within_the_cap_without_changing_a_bit() {
        let mut d = Dag::new();
        let xs: Vec<Id> = (0..40).map(|i| d.input(&format!("k.input_{i}"))).collect();
        let mut acc = xs[0];
        for (i, x) in xs.iter().enumerate().skip(1) {
            let c = d.constant(Q::ratio(i as i64, 7));
            let t = d.mul(*x, c);
            acc = if i % 3 == 0 {
                d.sub(acc, t)
            } else {
                d.add(acc, t)
            };
        }
        let p = program(&d, &[acc]);
        assert!(p.temps.len() > 3, "{p:?}");
        for e in p.temps.iter().chain(&p.outputs) {
            assert!(width(e) <= MAX_WIDTH, "{} > {MAX_WIDTH}: {e:?}", width(e));
        }
        // Every i/7 that is not an integer is a named constant; 7/7 ... are inline.
        assert_eq!(p.constants.len(), 34);
        assert!(literal_is_exact(&Q::ratio(959, 1000)) && literal_is_exact(&Q::int(-3)));
        assert!(
            !literal_is_exact(&Q::ratio(1, 3))
                && !literal_is_exact(&Q::ratio(1, 1024 * 1024 * 1024 * 1024))
        );
        let inputs: Vec<f64> = (0..40).map(|i| 1.0 + i as f64 / 3.0).collect();
        let want = d.eval(&[acc], &inputs)[0];
        assert_eq!(eval(&p, &inputs).to_bits(), want.to_bits());
    }

    /// Evaluates a program in f64 as the printers' code would (inputs `k.input_N` by index).
    fn eval(p: &Program, inputs: &[f64]) -> f64 {
        fn go(e: &Expr, p: &Program, t: &[f64], inputs: &[f64]) -> f64 {
            match e {
                Expr::Const(q) => q.to_f64(),
                Expr::Named(n) => p.constants[*n].to_f64(),
                Expr::Input(name) => inputs[name["k.input_".len()..].parse::<usize>().unwrap()],
                Expr::Temp(n) => t[*n],
                Expr::Binary(op, a, b) => {
                    let (x, y) = (go(a, p, t, inputs), go(b, p, t, inputs));
                    match op {
                        Op::Add => x + y,
                        Op::Sub => x - y,
                        Op::Mul => x * y,
                        Op::Div => x / y,
                    }
                }
                Expr::Neg(a) => -go(a, p, t, inputs),
                Expr::Sqrt(a) => go(a, p, t, inputs).sqrt(),
                Expr::CopySign(a, b) => go(a, p, t, inputs).copysign(go(b, p, t, inputs)),
                Expr::Paren(a) => go(a, p, t, inputs),
            }
        }
        let mut t = Vec::new();
        for e in &p.temps {
            let v = go(e, p, &t, inputs);
            t.push(v);
        }
        go(&p.outputs[0], p, &t, inputs)
    }

    #[test]
    fn exact_text_is_the_exact_value() {
        assert_eq!(
            exact_text(&Q::ratio(81084922887, 1_000_000_000)),
            "81.084922887"
        );
        assert_eq!(exact_text(&Q::ratio(-3, 8)), "-0.375");
        assert_eq!(exact_text(&Q::ratio(1, 1024)), "0.0009765625");
        assert_eq!(exact_text(&Q::ratio(1, 1 << 50)), "1/1125899906842624");
        assert_eq!(exact_text(&Q::ratio(22, 7)), "22/7");
        assert_eq!(exact_text(&Q::int(-4)), "-4");
        assert_eq!(exact_text(&Q::ratio(1, 20)), "0.05");
    }
}
