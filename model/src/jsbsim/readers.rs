//! Which of a model's functions read each property, directly or through other functions: what
//! must be computed again when an evaluation's inputs change in a few properties. A trim
//! evaluates the coefficients hundreds of times at one condition, each time moving only alpha
//! or the elevator, and most of a model's functions read neither; an evaluation that keeps the
//! others' values from the previous one ([`Env::keep_from`]) gives the same
//! numbers and the same errors, for a function's value is a function of what it reads.
//!
//! The reads are those of every branch of every `<ifthen>`: a superset of what one evaluation
//! reads, so nothing is kept that a branch could have changed. Kept values skip the checks an
//! evaluation makes on the way to them (a function reading itself, a chain of more than
//! [`MAX_CHAIN`] functions), so the readers are known only for functions where neither can
//! happen at all.

use super::evaluate::{Env, Functions, MAX_CHAIN};
use super::function::Expr;

/// For each property, the functions that read it.
#[derive(Clone, Debug)]
pub struct Readers {
    /// For each symbol, the functions reading it, directly or through others.
    of_symbol: Vec<Vec<usize>>,
    /// For each function, the symbol of its name.
    symbol_of: Vec<usize>,
}

impl Readers {
    /// The readers of `functions`' properties; `None` when a function may read itself or a
    /// chain of functions may be longer than [`MAX_CHAIN`].
    pub fn of(functions: &Functions) -> Option<Readers> {
        let n = functions.list.len();
        let direct: Vec<Vec<usize>> = functions
            .list
            .iter()
            .map(|f| {
                let mut reads = Vec::new();
                symbols_read(&f.expr, &mut reads);
                reads.sort_unstable();
                reads.dedup();
                reads
            })
            .collect();
        let order = callees_first(functions, &direct)?;
        let mut closure: Vec<Vec<bool>> = vec![Vec::new(); n];
        let mut height = vec![0usize; n];
        for &f in &order {
            let mut reads = vec![false; functions.symbols.len()];
            let mut h = 1;
            for &s in &direct[f] {
                reads[s] = true;
                if let Some(g) = functions.defined_by[s] {
                    reads
                        .iter_mut()
                        .zip(&closure[g])
                        .for_each(|(r, &c)| *r |= c);
                    h = h.max(height[g] + 1);
                }
            }
            if h > MAX_CHAIN {
                return None;
            }
            closure[f] = reads;
            height[f] = h;
        }
        let of_symbol = (0..functions.symbols.len())
            .map(|s| (0..n).filter(|&f| closure[f][s]).collect())
            .collect();
        let symbol_of = functions
            .list
            .iter()
            .map(|f| {
                functions
                    .symbols
                    .get(&f.name)
                    .expect("a function's name is a symbol")
            })
            .collect();
        Some(Readers {
            of_symbol,
            symbol_of,
        })
    }

    /// The functions reading symbol `s`, directly or through others.
    pub fn of_symbol(&self, s: usize) -> &[usize] {
        &self.of_symbol[s]
    }

    /// The functions reading function `f`'s value, directly or through others.
    pub fn of_function(&self, f: usize) -> &[usize] {
        &self.of_symbol[self.symbol_of[f]]
    }

    /// Keeps in `env` the values of `previous` that its inputs leave unchanged
    /// ([`Env::keep_from`]); `stale` is scratch memory.
    pub fn keep(&self, env: &mut Env, previous: &Env, stale: &mut Vec<bool>) {
        env.keep_from(previous, (&self.of_symbol, &self.symbol_of), stale);
    }
}

/// Adds to `reads` every symbol `e` reads itself (properties and table keys).
fn symbols_read(e: &Expr, reads: &mut Vec<usize>) {
    match e {
        Expr::Value(_) => {}
        Expr::Property(r) => reads.push(r.symbol),
        Expr::Table(t) => reads.extend(t.keys.iter().map(|r| r.symbol)),
        Expr::Apply(_, args) => args.iter().for_each(|a| symbols_read(a, reads)),
    }
}

/// The functions ordered so that each comes after every function it reads; `None` when some
/// function reads itself, directly or through others.
fn callees_first(functions: &Functions, direct: &[Vec<usize>]) -> Option<Vec<usize>> {
    #[derive(Clone, Copy, PartialEq)]
    enum Mark {
        New,
        Open,
        Closed,
    }
    let n = functions.list.len();
    let mut mark = vec![Mark::New; n];
    let mut order = Vec::with_capacity(n);
    for root in 0..n {
        if mark[root] != Mark::New {
            continue;
        }
        // Depth-first with an explicit stack: (function, next read to follow).
        let mut stack = vec![(root, 0usize)];
        mark[root] = Mark::Open;
        while let Some(top) = stack.last_mut() {
            let (f, next) = *top;
            let callee = direct[f][next..]
                .iter()
                .position(|&s| functions.defined_by[s].is_some());
            match callee {
                Some(k) => {
                    let s = direct[f][next + k];
                    top.1 = next + k + 1;
                    let g = functions.defined_by[s].expect("a function's symbol");
                    match mark[g] {
                        Mark::Open => return None,
                        Mark::Closed => {}
                        Mark::New => {
                            mark[g] = Mark::Open;
                            stack.push((g, 0));
                        }
                    }
                }
                None => {
                    mark[f] = Mark::Closed;
                    order.push(f);
                    stack.pop();
                }
            }
        }
    }
    Some(order)
}
