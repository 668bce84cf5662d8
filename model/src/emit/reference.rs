//! Reference values for a generated function: its DAG evaluated in exact rational arithmetic,
//! with a bound on how far any IEEE double evaluation of the same program may fall from it.
//!
//! This is what the C self-test checks against, on whatever compiler and target a user builds
//! it with: not the f64 results of the Rust code (that would let the generator grade itself,
//! and would fail on a target that rounds differently), but the exact value of the program's
//! mathematics and a first-order forward error bound in units of `u = 2^-53`. Each operation
//! adds `u |v|` (IEEE rounding) and propagates its operands' errors (`|a| e_b + |b| e_a` for a
//! product, `(e_a + |v| e_b) / (|b| - e_b)` for a quotient, `e_a / sqrt(a)` for a root; a
//! `copysign` is exact and keeps the bound of its magnitude). Where the bound cannot be given (a
//! divisor or a root's argument within its error of zero, a `copysign` whose sign source is
//! within its error of zero, or an overflow) the value is [`Reference::Unknown`] and is not
//! checked.

use crate::algebra::Q;
use crate::program::expr::{Dag, Id, Node};
use crate::specialise::exact_f64;

/// Unit roundoff of f64.
const U: f64 = f64::EPSILON / 2.0;

/// The reference for one value of a program.
#[derive(Clone, Debug, PartialEq)]
pub enum Reference {
    /// Exact value (square roots rounded once) and the error bound of an f64 evaluation.
    Value(Q, f64),
    /// Every IEEE evaluation gives NaN (a square root of a clearly negative number).
    Nan,
    /// No bound can be given: not checked.
    Unknown,
}

fn value(q: Q, err: f64) -> Reference {
    let m = q.to_f64().abs();
    if m.is_finite() && err.is_finite() {
        Reference::Value(q, err)
    } else {
        Reference::Unknown
    }
}

fn binary(a: &Reference, b: &Reference, f: impl Fn(&Q, f64, &Q, f64) -> Reference) -> Reference {
    match (a, b) {
        (Reference::Nan, _) | (_, Reference::Nan) => Reference::Nan,
        (Reference::Value(x, ex), Reference::Value(y, ey)) => f(x, *ex, y, *ey),
        _ => Reference::Unknown,
    }
}

/// The references of `outputs`, with each input given by its DAG name as the double the
/// generated code receives (taken exactly).
pub fn evaluate(dag: &Dag, outputs: &[Id], input: &dyn Fn(&str) -> f64) -> Vec<Reference> {
    let live = dag.live(outputs);
    let mut v: Vec<Reference> = vec![Reference::Unknown; dag.nodes().len()];
    for (i, node) in dag.nodes().iter().enumerate() {
        if !live[i] {
            continue;
        }
        let g = |id: &Id| &v[id.0 as usize];
        v[i] = match node {
            Node::Const(q) => value(q.clone(), q.to_f64().abs() * U),
            Node::Input(k) => {
                let x = input(&dag.inputs()[*k as usize]);
                if x.is_finite() {
                    Reference::Value(exact_f64(x), 0.0)
                } else {
                    Reference::Unknown
                }
            }
            Node::Add(a, b) => binary(g(a), g(b), |x, ex, y, ey| {
                let s = x + y;
                let e = ex + ey + s.to_f64().abs() * U;
                value(s, e)
            }),
            Node::Sub(a, b) => binary(g(a), g(b), |x, ex, y, ey| {
                let s = x - y;
                let e = ex + ey + s.to_f64().abs() * U;
                value(s, e)
            }),
            Node::Mul(a, b) => binary(g(a), g(b), |x, ex, y, ey| {
                let p = x * y;
                let (mx, my) = (x.to_f64().abs(), y.to_f64().abs());
                let e = mx * ey + my * ex + ex * ey + p.to_f64().abs() * U;
                value(p, e)
            }),
            Node::Div(a, b) => binary(g(a), g(b), |x, ex, y, ey| {
                let my = y.to_f64().abs();
                if y.is_zero() || my <= 2.0 * ey {
                    return Reference::Unknown;
                }
                let q = x.div(y);
                let mq = q.to_f64().abs();
                value(q, (ex + mq * ey) / (my - ey) + mq * U)
            }),
            Node::Neg(a) => match g(a) {
                Reference::Value(x, e) => Reference::Value(-x, *e),
                other => other.clone(),
            },
            Node::Sqrt(a) => match g(a) {
                Reference::Value(x, e) => {
                    let mx = x.to_f64();
                    if mx + e < 0.0 {
                        Reference::Nan
                    } else if mx <= *e || mx <= 0.0 {
                        Reference::Unknown
                    } else {
                        // The reference root is itself rounded once: 2u for it, u for the code.
                        let r = mx.sqrt();
                        value(exact_f64(r), e / mx.sqrt() + 3.0 * r * U)
                    }
                }
                other => other.clone(),
            },
            // Exact: the magnitude keeps its bound (| |x| - |y| | <= |x - y|); the sign is taken
            // only where it is certain, away from zero by more than the sign's own bound.
            Node::CopySign(a, b) => match (g(a), g(b)) {
                (Reference::Nan, _) => Reference::Nan,
                (Reference::Value(x, ex), Reference::Value(y, ey))
                    if !y.is_zero() && y.to_f64().abs() > *ey =>
                {
                    let m = if x.is_negative() { -x } else { x.clone() };
                    Reference::Value(if y.is_negative() { -&m } else { m }, *ex)
                }
                _ => Reference::Unknown,
            },
        };
    }
    outputs.iter().map(|o| v[o.0 as usize].clone()).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bound_covers_f64_evaluation_and_nan_is_certain() {
        // (x + 1/3) * x - 1/7, then sqrt of -(that) for x = 0.1: f64 must land within the bound.
        let mut d = Dag::new();
        let x = d.input("x");
        let third = d.constant(Q::ratio(1, 3));
        let seventh = d.constant(Q::ratio(1, 7));
        let s = d.add(x, third);
        let p = d.mul(s, x);
        let r = d.sub(p, seventh);
        let n = d.neg(r);
        let root = d.sqrt(n);
        let neg_root = d.sqrt(r);
        let refs = evaluate(&d, &[r, root, neg_root], &|_| 0.1);
        let got = d.eval(&[r, root, neg_root], &[0.1]);
        for (i, want) in refs.iter().take(2).enumerate() {
            let Reference::Value(q, e) = want else {
                panic!("{want:?}")
            };
            assert!((got[i] - q.to_f64()).abs() <= e.max(f64::MIN_POSITIVE));
            assert!(*e > 0.0 && *e < 1e-15);
        }
        assert_eq!(refs[2], Reference::Nan);
        assert!(got[2].is_nan());
    }

    #[test]
    fn division_by_a_value_within_its_error_of_zero_is_unknown() {
        let mut d = Dag::new();
        let x = d.input("x");
        let c = d.constant(Q::ratio(1, 10));
        let den = d.sub(x, c); // 0.1 (as f64) - 1/10: tiny and dominated by rounding
        let one = d.constant(Q::ONE);
        let q = d.div(one, den);
        assert_eq!(evaluate(&d, &[q], &|_| 0.1), vec![Reference::Unknown]);
    }
}
