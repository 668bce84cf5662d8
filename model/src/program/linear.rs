//! Like terms of the DAG's sums merged exactly: `x * c1 + y - x * c2` becomes `x * (c1 - c2) + y`
//! with `c1 - c2` summed in rational arithmetic, before the one rounding to f64.
//!
//! Like terms arise where the derivation's results are combined as nodes, not as polynomials:
//! the step-8 convolutions in P0 of the jump polynomials add products of the same trim
//! coefficient with different folded constants. Merging them saves an operation per pair and
//! rounds the summed constant once instead of adding two rounded products.
//!
//! A *sum* is an addition or subtraction together with every operand that is itself a sum or a
//! negation used nowhere else (a shared partial sum stays a node: splitting it would compute it
//! twice). Its terms are `atom * coefficient` (a product by a constant used once contributes its
//! constant, anything else coefficient 1) and constants. A sum with two terms on the same atom
//! or two constants is rebuilt left to right in the order of first occurrence; every other sum is
//! kept exactly as built, so its evaluation order and its rounding are unchanged.
//!
//! Merging is exact for finite values; a term whose coefficients cancel to zero is dropped, which
//! (as the DAG's `0 * x = 0`) drops the NaN an infinite atom would have given.

use crate::algebra::Q;
use crate::program::expr::{Dag, Id, Node};

/// The flattened terms of a sum: atoms with coefficients and the constant part, in order of
/// first occurrence (the constant's position is where it first occurs).
#[derive(Default)]
struct Terms {
    atoms: Vec<(Id, Q)>,
    constant: Option<(usize, Q)>,
    /// Whether two terms shared an atom or two constants occurred: the sum must be rebuilt.
    merged: bool,
}

impl Terms {
    fn push(&mut self, atom: Id, c: Q) {
        match self.atoms.iter_mut().find(|(a, _)| *a == atom) {
            Some((_, acc)) => {
                *acc = &*acc + &c;
                self.merged = true;
            }
            None => self.atoms.push((atom, c)),
        }
    }

    fn push_constant(&mut self, c: Q) {
        match &mut self.constant {
            Some((_, acc)) => {
                *acc = &*acc + &c;
                self.merged = true;
            }
            None => self.constant = Some((self.atoms.len(), c)),
        }
    }
}

/// Use counts of the live nodes (outputs count as uses) and the parent of each node used once.
struct Uses {
    count: Vec<usize>,
    parent: Vec<Option<Id>>,
}

impl Uses {
    fn new(dag: &Dag, outputs: &[Id], live: &[bool]) -> Uses {
        let n = dag.nodes().len();
        let mut count = vec![0usize; n];
        let mut parent = vec![None; n];
        for (i, l) in live.iter().enumerate() {
            if *l {
                for c in dag.children(Id(i as u32)) {
                    count[c.0 as usize] += 1;
                    parent[c.0 as usize] = Some(Id(i as u32));
                }
            }
        }
        for o in outputs {
            count[o.0 as usize] += 1;
        }
        Uses { count, parent }
    }

    fn once(&self, id: Id) -> bool {
        self.count[id.0 as usize] == 1
    }
}

/// Whether `id` is an operand its parent's sum absorbs: used once, by an addition, a
/// subtraction, or a negation that is itself absorbed.
fn absorbed(dag: &Dag, uses: &Uses, id: Id) -> bool {
    if !uses.once(id) {
        return false;
    }
    match uses.parent[id.0 as usize].map(|p| (p, dag.node(p))) {
        Some((_, Node::Add(..) | Node::Sub(..))) => true,
        Some((p, Node::Neg(_))) => absorbed(dag, uses, p),
        _ => false,
    }
}

/// Adds term `t` with sign `positive` to `out`, descending into absorbed sums and negations.
fn term(dag: &Dag, uses: &Uses, t: Id, positive: bool, out: &mut Terms) {
    let sign = |q: &Q| if positive { q.clone() } else { -q };
    let once = uses.once(t);
    match dag.node(t) {
        Node::Add(a, b) | Node::Sub(a, b) if once => {
            let minus = matches!(dag.node(t), Node::Sub(..));
            term(dag, uses, *a, positive, out);
            term(dag, uses, *b, positive != minus, out);
        }
        Node::Neg(a) if once => term(dag, uses, *a, !positive, out),
        Node::Const(c) => out.push_constant(sign(c)),
        Node::Mul(x, y) if once => match (dag.node(*x), dag.node(*y)) {
            (_, Node::Const(c)) => out.push(*x, sign(c)),
            (Node::Const(c), _) => out.push(*y, sign(c)),
            _ => out.push(t, sign(&Q::ONE)),
        },
        _ => out.push(t, sign(&Q::ONE)),
    }
}

/// The DAG computing `outputs` with the like terms of every sum merged, and the new ids of the
/// outputs. Inputs keep their order, so the function's signature is unchanged.
pub fn merge_like_terms(dag: &Dag, outputs: &[Id]) -> (Dag, Vec<Id>) {
    let live = dag.live(outputs);
    let uses = Uses::new(dag, outputs, &live);
    let n = dag.nodes().len();
    // The sums to rebuild, by their root.
    let mut plans: Vec<Option<Terms>> = (0..n).map(|_| None).collect();
    for (i, node) in dag.nodes().iter().enumerate() {
        let id = Id(i as u32);
        if live[i] && matches!(node, Node::Add(..) | Node::Sub(..)) && !absorbed(dag, &uses, id) {
            let mut t = Terms::default();
            // The root itself is flattened whatever its use count.
            let (a, b) = match node {
                Node::Add(a, b) | Node::Sub(a, b) => (*a, *b),
                _ => unreachable!(),
            };
            term(dag, &uses, a, true, &mut t);
            term(dag, &uses, b, !matches!(node, Node::Sub(..)), &mut t);
            if t.merged {
                plans[i] = Some(t);
            }
        }
    }
    // The nodes the new DAG needs: a rebuilt sum needs its atoms, any other node its children.
    let mut needed = vec![false; n];
    let mut stack: Vec<Id> = outputs.to_vec();
    while let Some(id) = stack.pop() {
        if std::mem::replace(&mut needed[id.0 as usize], true) {
            continue;
        }
        match &plans[id.0 as usize] {
            Some(t) => stack.extend(t.atoms.iter().map(|(a, _)| *a)),
            None => stack.extend(dag.children(id)),
        }
    }
    let mut out = Dag::with_inputs(dag.inputs());
    let mut map: Vec<Option<Id>> = vec![None; n];
    for (i, node) in dag.nodes().iter().enumerate() {
        if !needed[i] {
            continue;
        }
        let m = |id: Id| map[id.0 as usize].expect("children are rebuilt first");
        let new = match &plans[i] {
            Some(t) => rebuild(&mut out, t, &|id: &Id| m(*id)),
            None => out.push(node.map_children(m)),
        };
        map[i] = Some(new);
    }
    let outs = outputs
        .iter()
        .map(|o| map[o.0 as usize].expect("outputs are rebuilt"))
        .collect();
    (out, outs)
}

/// A merged sum, left to right in the order of first occurrence; zero coefficients dropped.
fn rebuild(dag: &mut Dag, t: &Terms, map: &dyn Fn(&Id) -> Id) -> Id {
    let mut items: Vec<(Option<Id>, Q)> = t
        .atoms
        .iter()
        .map(|(a, c)| (Some(map(a)), c.clone()))
        .collect();
    if let Some((at, c)) = &t.constant {
        items.insert(*at, (None, c.clone()));
    }
    let mut acc: Option<Id> = None;
    for (atom, c) in items {
        if c.is_zero() {
            continue;
        }
        let magnitude = dag.constant(c.abs());
        let value = match atom {
            Some(x) => dag.mul(x, magnitude),
            None => magnitude,
        };
        acc = Some(match (acc, c.is_negative()) {
            (None, false) => value,
            (None, true) => dag.neg(value),
            (Some(a), false) => dag.add(a, value),
            (Some(a), true) => dag.sub(a, value),
        });
    }
    acc.unwrap_or_else(|| dag.constant(Q::ZERO))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `x * 81/10 + y - x * 83/10 + 2 - 3` merges to `x * (-1/5) + y - 1` with one exact
    /// constant per atom; a sum without like terms keeps its shape.
    #[test]
    fn like_terms_merge_into_one_exact_constant() {
        let mut d = Dag::new();
        let (x, y) = (d.input("x"), d.input("y"));
        let (c1, c2) = (d.constant(Q::ratio(81, 10)), d.constant(Q::ratio(83, 10)));
        let (two, three) = (d.constant(Q::int(2)), d.constant(Q::int(3)));
        let a = d.mul(x, c1);
        let b = d.mul(x, c2);
        let s = d.add(a, y);
        let s = d.sub(s, b);
        let s = d.add(s, two);
        let s = d.sub(s, three);
        let (m, outs) = merge_like_terms(&d, &[s]);
        let count = m.op_count(&outs);
        assert_eq!(
            (count.mul, count.add, count.neg),
            (1, 2, 0),
            "{:?}",
            m.nodes()
        );
        let consts: Vec<&Q> = m
            .nodes()
            .iter()
            .filter_map(|n| match n {
                Node::Const(q) => Some(q),
                _ => None,
            })
            .collect();
        assert!(
            consts.contains(&&Q::ratio(1, 5)) && consts.contains(&&Q::ONE),
            "{consts:?}"
        );
        for (xv, yv) in [(1.5, -2.0), (0.1, 7.25)] {
            let got = m.eval(&outs, &[xv, yv])[0];
            let want = xv * (-0.2) + yv - 1.0;
            assert!((got - want).abs() <= 1e-15 * want.abs(), "{got} {want}");
        }
        // No like terms: the same DAG shape (same operations in the same order).
        let mut e = Dag::new();
        let (x, y) = (e.input("x"), e.input("y"));
        let s = e.add(x, y);
        let three = e.constant(Q::int(3));
        let z = e.sub(s, three);
        let (m, outs) = merge_like_terms(&e, &[z]);
        assert_eq!(m.nodes(), e.nodes());
        assert_eq!(outs, vec![z]);
    }

    /// A shared partial sum is not split (it would be computed twice), and like terms on both
    /// sides of it are still merged.
    #[test]
    fn shared_partial_sums_stay_nodes() {
        let mut d = Dag::new();
        let (x, y) = (d.input("x"), d.input("y"));
        let shared = d.add(x, y);
        let k = d.constant(Q::int(5));
        let a = d.mul(shared, k);
        let s = d.add(shared, a); // shared + 5 shared = 6 shared
        let out2 = d.mul(shared, shared);
        let (m, outs) = merge_like_terms(&d, &[s, out2]);
        assert_eq!(m.op_count(&outs).total(), 3, "{:?}", m.nodes());
        let got = m.eval(&outs, &[1.0, 2.0]);
        assert_eq!(got, vec![18.0, 9.0]);
    }
}
