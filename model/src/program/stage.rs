//! A program split in two stages: what depends only on the early inputs (the aircraft and the
//! controls), computed once, and what depends on a late input (the roll rate), computed per call.
//!
//! A node that does not depend on a late input but is an operand of one that does is a *field*:
//! the early program computes every field, the late program reads them as inputs `self.fN`.
//! Every operation is copied as it is (no folding, no reordering), so the two stages together
//! perform exactly the operations of the original program: the results are bit for bit those
//! of the unsplit program, and both printers spell both stages.

use crate::program::expr::{Dag, Id, Node};

/// The input name of field `n` of the late stage (`self.f3`: a field of the Rust `&self`, and of
/// the C `const struct ... *self` through `->`).
pub fn field_input(n: usize) -> String {
    format!("self.f{n}")
}

/// A program in two stages.
#[derive(Clone, Debug)]
pub struct Staged {
    /// The early program (the original inputs but the late ones).
    pub early: Dag,
    /// Its outputs: field `n` is `fields[n]`.
    pub fields: Vec<Id>,
    /// The late program: inputs `self.fN` and the late inputs.
    pub late: Dag,
    /// The original outputs in the late program.
    pub outputs: Vec<Id>,
}

/// Splits the program computing `outputs` of `dag` at the inputs named `late`.
pub fn stage(dag: &Dag, outputs: &[Id], late: &[&str]) -> Staged {
    let live = dag.live(outputs);
    let n = dag.nodes().len();
    let mut dep = vec![false; n];
    for (i, node) in dag.nodes().iter().enumerate() {
        dep[i] = match node {
            Node::Input(k) => late.contains(&dag.inputs()[*k as usize].as_str()),
            Node::Const(_) => false,
            _ => dag.children(Id(i as u32)).iter().any(|c| dep[c.0 as usize]),
        };
    }
    // Fields: early operands of late operations, and early outputs; constants stay constants.
    let mut is_field = vec![false; n];
    for i in 0..n {
        if live[i] && dep[i] {
            for c in dag.children(Id(i as u32)) {
                if !dep[c.0 as usize] && !matches!(dag.node(c), Node::Const(_)) {
                    is_field[c.0 as usize] = true;
                }
            }
        }
    }
    for o in outputs {
        if !dep[o.0 as usize] && !matches!(dag.node(*o), Node::Const(_)) {
            is_field[o.0 as usize] = true;
        }
    }
    let field_ids: Vec<Id> = (0..n)
        .filter(|i| is_field[*i])
        .map(|i| Id(i as u32))
        .collect();
    let (early, fields) = copy(dag, &field_ids, &Dag::with_inputs(dag.inputs()), &|_| None);
    let mut late_dag = Dag::new();
    let field_nodes: Vec<(Id, Id)> = field_ids
        .iter()
        .enumerate()
        .map(|(k, id)| (*id, late_dag.input(&field_input(k))))
        .collect();
    for name in late {
        late_dag.input(name);
    }
    let substitute = |id: Id| {
        field_nodes
            .iter()
            .find(|(f, _)| *f == id)
            .map(|(_, input)| *input)
    };
    let (late_dag, outs) = copy(dag, outputs, &late_dag, &substitute);
    Staged {
        early,
        fields,
        late: late_dag,
        outputs: outs,
    }
}

/// Copies the nodes `roots` need from `dag` into `into` (inputs by name), node for node; a node
/// for which `substitute` gives a node of `into` is replaced by it (and its children not
/// copied).
fn copy(
    dag: &Dag,
    roots: &[Id],
    into: &Dag,
    substitute: &dyn Fn(Id) -> Option<Id>,
) -> (Dag, Vec<Id>) {
    let mut out = into.clone();
    let n = dag.nodes().len();
    let mut needed = vec![false; n];
    let mut stack = roots.to_vec();
    while let Some(id) = stack.pop() {
        if std::mem::replace(&mut needed[id.0 as usize], true) {
            continue;
        }
        if substitute(id).is_none() {
            stack.extend(dag.children(id));
        }
    }
    let mut map: Vec<Option<Id>> = vec![None; n];
    for (i, node) in dag.nodes().iter().enumerate() {
        if !needed[i] {
            continue;
        }
        let id = Id(i as u32);
        let new = match (substitute(id), node) {
            (Some(s), _) => s,
            (None, Node::Input(k)) => out.input(&dag.inputs()[*k as usize]),
            (None, _) => out
                .push(node.map_children(|c| map[c.0 as usize].expect("children are copied first"))),
        };
        map[i] = Some(new);
    }
    let outs = roots
        .iter()
        .map(|r| map[r.0 as usize].expect("roots are copied"))
        .collect();
    (out, outs)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::Q;

    /// `(a * b + p) * (a * b) - sqrt(a)`, late in p: the early stage computes `a * b` and
    /// `sqrt(a)`, the late one the rest, and together they give the bits of the whole.
    #[test]
    fn stages_compute_the_same_bits_with_early_work_done_once() {
        let mut d = Dag::new();
        let (a, b, p) = (d.input("a"), d.input("b"), d.input("p"));
        let ab = d.mul(a, b);
        let s = d.add(ab, p);
        let m = d.mul(s, ab);
        let r = d.sqrt(a);
        let three = d.constant(Q::int(3));
        let r3 = d.mul(r, three);
        let out = d.sub(m, r3);
        let st = stage(&d, &[out], &["p"]);
        assert_eq!(st.fields.len(), 2, "a * b and 3 sqrt(a)");
        assert_eq!(st.early.op_count(&st.fields).total(), 3);
        assert_eq!(st.late.op_count(&st.outputs).total(), 3);
        for (x, y, z) in [(2.0, 3.5, 0.25), (0.1, -7.0, 1e3)] {
            let whole = d.eval(&[out], &[x, y, z])[0];
            let fields = st.early.eval(&st.fields, &[x, y, z]);
            let mut late_inputs = fields.clone();
            late_inputs.push(z);
            let staged = st.late.eval(&st.outputs, &late_inputs)[0];
            assert_eq!(staged.to_bits(), whole.to_bits());
        }
    }
}
