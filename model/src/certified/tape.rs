//! A straight-line program ([`crate::program::expr::Dag`]) evaluated in f64 with an
//! a priori bound on its rounding: the certified route's fast enclosure of the criterion
//! polynomials' coefficients.
//!
//! Each node is evaluated twice in one pass, on two lanes: its value `v` from the inputs, and
//! `V`, the same program on the inputs' magnitudes with every subtraction made an addition (all
//! terms positive: no cancellation). The bound is the classical one for sums and products
//! (Higham, *Accuracy and Stability of Numerical Algorithms*, 2nd ed., section 3.1 and lemma
//! 3.3, with `gamma_k = k u / (1 - k u)`, `u = 2^-53`): give every node a rounding count `K`,
//! 2 for an input enclosed between adjacent doubles (`|x~ - x| <= 2 u |x~|`, so
//! `|x~ - x| <= gamma_2 |x|`), 0 for a constant that is a double and 1 for one rounded to the
//! nearest, `max(K_a, K_b) + 1` for a sum or difference, `K_a + K_b + 1` for a product and `K_a`
//! for a negation. Then, with `v` and `V` the exact values (exact inputs, exact arithmetic) and
//! `v~` the computed value, `|v~ - v| <= gamma_K V` at every node, by induction:
//!
//! - a sum: `|v~ - v| <= |a~ - a| + |b~ - b| + u |a~ + b~|
//!   <= (gamma_K' + u (1 + gamma_K')) (V_a + V_b) <= gamma_(K' + 1) V`, `K' = max(K_a, K_b)`;
//! - a product: `|a~ b~ - a b| <= (gamma_Ka + gamma_Kb + gamma_Ka gamma_Kb) V_a V_b
//!   <= gamma_(Ka + Kb) V_a V_b` (lemma 3.3), and its rounding adds `u |a~ b~|`
//!   `<= u (1 + gamma_(Ka + Kb)) V_a V_b`, also where the product underflows: its error is then
//!   at most `2^-1075 <= u V_a V_b`, as long as `V_a V_b >= 2^-1022` (see the gate below); a sum
//!   whose result is subnormal is exact.
//!
//! The computed `V~` is the same program on positive numbers, so `|V~ - V| <= gamma_K V` as
//! well, and `|v~ - v| <= gamma_K / (1 - gamma_K) V~ = K u / (1 - 2 K u) V~`: the output
//! enclosure is `v~` plus or minus that radius (rounded up, ends pushed out by an ulp).
//!
//! **The gate.** The bound needs every nonzero `V` (at every node, on both passes) to stay
//! within the normal doubles. With `D` the multiplicative degree (1 for inputs and nonzero
//! constants, the larger one for a sum, the sum for a product) and every nonzero input and
//! constant between `2^-E` and `2^E` in magnitude, `E D <= 900` for every node, each nonzero `V`
//! is at least `2^-900` (a sum is at least its larger part, a product the product of its parts),
//! and so are the computed ones and the radius `F V~` (`F >= 2^-53`) far above the subnormals.
//! Overflow and NaN propagate to the outputs (`V` is a positive sum of products; a zero `V`
//! is an exact zero, so `0 * inf` shows as NaN), where every value and radius must be finite.
//! Inputs outside the gate, wider than one ulp or not finite make [`Tape::eval`] decline; the
//! caller then encloses the polynomials the general way.
//!
//! Operations are stored level by level (a node's level is one more than its children's), and
//! within a level by kind, so the evaluation is a few tight loops without a branch per
//! operation; both lanes of a node are one packed f64 operation.

use crate::interval::{next_down, next_up, I};
use crate::program::expr::{Dag, Id, Node};

/// The unit roundoff of round-to-nearest f64.
const UNIT: f64 = f64::EPSILON / 2.0;

/// The bound on `E D` of the gate (see the module documentation).
const MAX_EXPONENT_DEGREE: u32 = 900;

thread_local! {
    /// The working slots of [`Tape::eval`] on this thread.
    static SLOTS: std::cell::RefCell<Vec<[f64; 2]>> = const { std::cell::RefCell::new(Vec::new()) };
}

/// The kinds of operation a tape holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
enum Kind {
    Add,
    Sub,
    Mul,
    Neg,
}

/// A compiled straight-line program with its static rounding counts.
#[derive(Clone, Debug)]
pub struct Tape {
    /// The number of inputs (slots `0..inputs`).
    inputs: usize,
    /// The constants as `[v, |v|]` (the slots after the inputs).
    constants: Vec<[f64; 2]>,
    /// The operands of each operation; operation `j` writes slot `inputs + constants + j`.
    operands: Vec<[u32; 2]>,
    /// Runs of operations of one kind: the kind and the end of the run in `operands`.
    batches: Vec<(Kind, usize)>,
    /// Each output: its slot and the factor `F >= K u / (1 - 2 K u)` of its radius.
    outputs: Vec<(u32, f64)>,
    /// `E` of the gate: every nonzero input must lie within `[2^-E, 2^E]` in magnitude.
    exponent: i32,
}

impl Tape {
    /// Compiles the part of `dag` that computes `outputs` (sums, differences, products and
    /// negations of inputs and constants only).
    ///
    /// # Panics
    /// On a division, square root or copysign, or a constant beyond the gate: the criterion
    /// programs have none (a programming error, caught by the tests).
    pub fn new(dag: &Dag, outputs: &[Id]) -> Tape {
        let live = dag.live(outputs);
        let n = dag.nodes().len();
        // Per node: level, rounding count K, multiplicative degree D.
        let (mut level, mut count, mut degree) = (vec![0u32; n], vec![0u32; n], vec![0u32; n]);
        let mut constants = Vec::new();
        let mut largest_exponent = 0i32;
        // Inputs keep their index as slot, constants follow them, operations are placed below.
        let mut slot = vec![u32::MAX; n];
        let inputs = dag.inputs().len();
        let mut ops: Vec<(u32, Kind, usize)> = Vec::new();
        for (i, node) in dag.nodes().iter().enumerate() {
            if !live[i] {
                continue;
            }
            let at = |id: &Id| id.0 as usize;
            let (l, k, d) = match node {
                Node::Input(j) => {
                    slot[i] = *j;
                    (0, 2, 1)
                }
                Node::Const(q) => {
                    let v = q.to_f64();
                    assert!(v.is_finite(), "constant {v} beyond f64");
                    let exact = I::from_q(&q.to_big()).is_point();
                    if v != 0.0 {
                        largest_exponent = largest_exponent.max(v.abs().log2().abs().ceil() as i32);
                    }
                    slot[i] = (inputs + constants.len()) as u32;
                    constants.push([v, v.abs()]);
                    (0, u32::from(!exact), u32::from(v != 0.0))
                }
                Node::Add(a, b) | Node::Sub(a, b) => (
                    1 + level[at(a)].max(level[at(b)]),
                    count[at(a)].max(count[at(b)]) + 1,
                    degree[at(a)].max(degree[at(b)]),
                ),
                Node::Mul(a, b) => (
                    1 + level[at(a)].max(level[at(b)]),
                    count[at(a)] + count[at(b)] + 1,
                    degree[at(a)] + degree[at(b)],
                ),
                Node::Neg(a) => (1 + level[at(a)], count[at(a)], degree[at(a)]),
                Node::Div(..) | Node::Sqrt(_) | Node::CopySign(..) => {
                    panic!("a tape holds sums, differences, products and negations only")
                }
            };
            (level[i], count[i], degree[i]) = (l, k, d);
            let kind = match node {
                Node::Add(..) => Kind::Add,
                Node::Sub(..) => Kind::Sub,
                Node::Mul(..) => Kind::Mul,
                Node::Neg(_) => Kind::Neg,
                _ => continue,
            };
            ops.push((l, kind, i));
        }
        ops.sort_by_key(|&(l, kind, i)| (l, kind, i));
        let first = inputs + constants.len();
        let mut operands = Vec::with_capacity(ops.len());
        let mut batches: Vec<(Kind, usize)> = Vec::new();
        for (j, &(l, kind, i)) in ops.iter().enumerate() {
            slot[i] = (first + j) as u32;
            let children = dag.children(Id(i as u32));
            let [a, b] = [children[0], *children.get(1).unwrap_or(&children[0])];
            operands.push([slot[a.0 as usize], slot[b.0 as usize]]);
            // A run is one kind at one level: what it reads lies in the runs before it.
            match batches.last_mut() {
                Some((k, end)) if *k == kind && ops[*end - 1].0 == l => *end = j + 1,
                _ => batches.push((kind, j + 1)),
            }
        }
        let max_degree = degree.iter().copied().max().unwrap_or(1).max(1);
        let exponent = (MAX_EXPONENT_DEGREE / max_degree) as i32;
        assert!(
            largest_exponent <= exponent,
            "a constant of the program is beyond the gate's 2^{exponent}"
        );
        let outputs = outputs
            .iter()
            .map(|o| {
                let k = count[o.0 as usize];
                assert!(k < 1 << 20, "rounding count {k} beyond the bound's margin");
                // K u (1 + 2^-20) >= K u / (1 - 2 K u) for K < 2^20; the product rounded up.
                (
                    slot[o.0 as usize],
                    next_up(k as f64 * UNIT * (1.0 + 1.0 / 1048576.0)),
                )
            })
            .collect();
        Tape {
            inputs,
            constants,
            operands,
            batches,
            outputs,
            exponent,
        }
    }

    /// Encloses every output at the enclosures `inputs` (in the program's input order), or
    /// `None` when the bound cannot be promised: an input wider than one ulp, not finite, or
    /// outside the gate, or a value or radius that is not finite.
    pub fn eval(&self, inputs: &[I]) -> Option<Vec<I>> {
        if inputs.len() != self.inputs {
            return None;
        }
        SLOTS.with_borrow_mut(|s| self.eval_in(inputs, s))
    }

    /// [`Tape::eval`] with `s` as the slots (grown to the tape's size, never shrunk: a tape
    /// evaluated many times allocates once per thread).
    fn eval_in(&self, inputs: &[I], s: &mut Vec<[f64; 2]>) -> Option<Vec<I>> {
        let (small, large) = (2f64.powi(-self.exponent), 2f64.powi(self.exponent));
        let first = self.inputs + self.constants.len();
        let needed = first + self.operands.len();
        if s.len() < needed {
            s.resize(needed, [0.0; 2]);
        }
        // Every slot below is written before it is read: inputs, constants, then the runs.
        let s = &mut s[..needed];
        for (slot, x) in s.iter_mut().zip(inputs) {
            // A point, or two adjacent doubles of one sign: either end is within 2 u of its
            // own magnitude of every real between them.
            let adjacent = next_up(x.lo) == x.hi && (x.lo > 0.0 || x.hi < 0.0);
            if !(x.lo == x.hi || adjacent) {
                return None;
            }
            let v = x.lo;
            if !(v == 0.0 || (small..=large).contains(&v.abs())) {
                return None;
            }
            *slot = [v, v.abs()];
        }
        s[self.inputs..first].copy_from_slice(&self.constants);
        let (mut start, mut base) = (0, first);
        for &(kind, end) in &self.batches {
            let run = &self.operands[start..end];
            // A run reads only slots of lower levels, all before it.
            let (done, out) = s.split_at_mut(base);
            let out = &mut out[..run.len()];
            (start, base) = (end, base + run.len());
            let pairs = out.iter_mut().zip(run);
            match kind {
                Kind::Add => pairs.for_each(|(o, &[a, b])| {
                    let (x, y) = (done[a as usize], done[b as usize]);
                    *o = [x[0] + y[0], x[1] + y[1]];
                }),
                Kind::Sub => pairs.for_each(|(o, &[a, b])| {
                    let (x, y) = (done[a as usize], done[b as usize]);
                    *o = [x[0] - y[0], x[1] + y[1]];
                }),
                Kind::Mul => pairs.for_each(|(o, &[a, b])| {
                    let (x, y) = (done[a as usize], done[b as usize]);
                    *o = [x[0] * y[0], x[1] * y[1]];
                }),
                Kind::Neg => pairs.for_each(|(o, &[a, _])| {
                    let x = done[a as usize];
                    *o = [-x[0], x[1]];
                }),
            }
        }
        let mut out = Vec::with_capacity(self.outputs.len());
        for &(slot, factor) in &self.outputs {
            let [v, magnitude] = s[slot as usize];
            let r = factor * magnitude;
            if !(v.is_finite() && r.is_finite()) {
                return None;
            }
            out.push(if r == 0.0 {
                I::point(v)
            } else {
                I::new(next_down(v - r), next_up(v + r))
            });
        }
        Some(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::aircraft::{Aircraft, Param};
    use crate::algebra::Q;
    use num_rational::BigRational;

    /// The exact value of every node of `dag` at the exact `inputs` (rational arithmetic).
    fn exact(dag: &Dag, inputs: &[Q]) -> Vec<Q> {
        let mut v: Vec<Q> = Vec::with_capacity(dag.nodes().len());
        for n in dag.nodes() {
            let g = |id: &Id| &v[id.0 as usize];
            let x = match n {
                Node::Const(q) => q.clone(),
                Node::Input(k) => inputs[*k as usize].clone(),
                Node::Add(a, b) => g(a) + g(b),
                Node::Sub(a, b) => g(a) - g(b),
                Node::Mul(a, b) => g(a) * g(b),
                Node::Neg(a) => -g(a),
                other => panic!("not in a tape: {other:?}"),
            };
            v.push(x);
        }
        v
    }

    /// Whether the exact `q` lies in `x`.
    fn holds(x: I, q: &Q) -> bool {
        let big = q.to_big();
        let at = |f: f64| BigRational::from_float(f).expect("finite end");
        at(x.lo) <= big && big <= at(x.hi)
    }

    /// `x` as an exact decimal with five significant digits, as data files write them.
    fn decimal(x: f64) -> BigRational {
        crate::aircraft::decimal_to_rational(&format!("{x:.4e}")).expect("a decimal literal")
    }

    proptest::proptest! {
        #![proptest_config(proptest::test_runner::Config { cases: 40, ..Default::default() })]

        /// The soundness of the bound, on the criterion program: for random aircraft around A
        /// or B (every parameter moved by up to 30 % and written with five significant digits,
        /// a random trim lift and principal-axis angle of attack, no aileron yaw, a random
        /// elevator), every output enclosure holds the program's exact
        /// value at the exact data, computed here in rationals. (How tight the enclosures are
        /// is `certified::enclosed::tests::the_tape_encloses_what_the_general_route_encloses`.)
        #[test]
        fn enclosures_hold_the_exact_values_of_the_criterion_program(
            on_b in proptest::bool::ANY,
            scales in proptest::array::uniform20(0.7f64..1.3),
            de in -0.1f64..0.1,
        ) {
            let p = crate::program::criterion::criterion_program(crate::specialise::parametric());
            let outputs = p.outputs();
            let tape = Tape::new(&p.dag, &outputs);
            let base = if on_b { Aircraft::b() } else { Aircraft::a() };
            let data: Vec<BigRational> = Param::ALL
                .iter()
                .zip(scales)
                .map(|(q, s)| match q {
                    Param::NDeltaA => BigRational::from_integer(0.into()),
                    // A trim of 0.6 to 1.3 g at 100 m/s, the principal axis up to 0.06 rad
                    // above the flight path.
                    Param::Z0 => decimal(-0.098 * s),
                    Param::AlphaT => decimal(0.1 * (s - 0.7)),
                    _ => decimal(base.value(*q) * s),
                })
                .collect();
            let exact_inputs: Vec<Q> = std::iter::once(BigRational::from_float(de).unwrap())
                .chain(data.iter().cloned())
                .map(Q::from_big)
                .collect();
            let enclosures: Vec<I> = std::iter::once(I::point(de))
                .chain(data.iter().map(I::from_q))
                .collect();
            let got = tape.eval(&enclosures).expect("data within the gate");
            let values = exact(&p.dag, &exact_inputs);
            for (k, (x, o)) in got.iter().zip(&outputs).enumerate() {
                let q = &values[o.0 as usize];
                proptest::prop_assert!(holds(*x, q), "output {}: {:?} misses {}", k, x, q);
            }
        }
    }

    /// A program that cancels: `(x + c) - c` for a tiny `x` next to a large `c` loses the digits
    /// of `x` in f64, and the bound says so (its enclosure holds `x` and is as wide as the
    /// rounding of `c`'s magnitude), where a bound relative to the computed value would not.
    #[test]
    fn cancellation_is_covered() {
        let mut dag = Dag::new();
        let x = dag.input("x");
        let c = dag.constant(Q::from(1_000_000_007));
        let s = dag.add(x, c);
        let d = dag.sub(s, c);
        let tape = Tape::new(&dag, &[d]);
        let tenth = BigRational::new(1.into(), 10.into());
        let got = tape.eval(&[I::from_q(&tenth)]).unwrap()[0];
        assert!(holds(got, &Q::from_big(tenth)), "{got:?}");
        assert!(got.width() > 1e-8, "the rounding of 1e9 shows: {got:?}");
    }

    /// What the bound cannot promise is declined, not enclosed: an input wider than an ulp, not
    /// finite, of either sign, or beyond the gate.
    #[test]
    fn inputs_the_bound_does_not_cover_are_declined() {
        let mut dag = Dag::new();
        let x = dag.input("x");
        let y = dag.mul(x, x);
        let tape = Tape::new(&dag, &[y]);
        assert!(tape.eval(&[I::point(3.0)]).is_some());
        assert!(tape.eval(&[I::new(3.0, next_up(3.0))]).is_some());
        assert!(tape.eval(&[I::point(0.0)]).is_some());
        for refused in [
            I::new(3.0, next_up(next_up(3.0))),
            I::new(-f64::from_bits(1), 0.0),
            I::point(f64::INFINITY),
            I::point(f64::NAN),
            I::point(2f64.powi(-600)),
            I::point(2f64.powi(600)),
        ] {
            assert!(tape.eval(&[refused]).is_none(), "{refused:?}");
        }
    }
}
