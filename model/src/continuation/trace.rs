//! Tracing every branch of the unconstrained diagram: from every seed of the roll-rate grid not
//! yet passed, both directions, and branch switching at each new branch point.

use super::collect::Collect;
use super::engine::{End, Engine, Half, Node, System, Verdict, V6};
use super::seeds::{Sections, SeedBook};
use super::systems::Unconstrained;
use super::{limits, ContinuationError, Settings};
use crate::pss_model::{Controls, PssModel};

/// The unconstrained diagram: every seed on the P0 grid not yet passed by a branch starts one;
/// every new branch point starts the crossing branch.
pub(super) fn unconstrained(
    model: &PssModel,
    s: &Settings,
    out: &mut Collect,
    progress: &mut dyn FnMut(f64),
) -> Result<(), ContinuationError> {
    let base = Controls {
        delta_a: s.delta_a,
        delta_e: s.delta_e,
        delta_r: s.delta_r,
    };
    let control = s.param.index();
    let sys = Unconstrained {
        model,
        base,
        control,
    };
    let eng = Engine {
        sys: &sys,
        lim: limits(s, s.min, s.max),
    };
    let sections = Sections::new(model, base, control)?;
    let mut book = SeedBook::build(&sections, s.seed_spacing, s.max_state, s.min, s.max);
    let e_p = V6::new(0.0, 0.0, 1.0, 0.0, 0.0, 0.0);
    let e_mu = V6::new(0.0, 0.0, 0.0, 0.0, 0.0, 1.0);
    let n_k = book.seeds.len();
    let mut last_report = 0usize;
    for k in 0..n_k {
        if 200 * k >= (last_report + 1) * n_k {
            last_report = 200 * k / n_k;
            progress(k as f64 / n_k as f64);
        }
        for i in 0..book.seeds[k].len() {
            if out.branches.len() >= s.max_branches {
                return Ok(());
            }
            let seed = &book.seeds[k][i];
            if seed.owner.is_some() {
                continue;
            }
            let line = seed.line;
            if line && out.on_a_branch(&seed.z) {
                book.seeds[k][i].owner = Some(usize::MAX);
                continue;
            }
            // Polish at fixed P0 (or, on a line of constant p, at fixed parameter).
            let n = if line { e_mu } else { e_p };
            let Some(start) = eng.start(seed.z, &n, |t| if t[2] != 0.0 { t[2] } else { t[5] })
            else {
                book.seeds[k][i].owner = Some(usize::MAX);
                continue;
            };
            let id = out.branches.len();
            book.seeds[k][i].owner = Some(id);
            let bps = trace_both(&eng, &start, id, Some(&mut book), out, false);
            switch_all(&eng, bps, Some(&mut book), out, s.max_branches);
        }
    }
    Ok(())
}

/// Traces both directions from `start` as branch `id`; adds it unless it duplicates known
/// branches (both directions ran onto them, or a switched branch ran onto one). Returns the new
/// branch points on it.
pub(super) fn trace_both<S: System>(
    eng: &Engine<'_, S>,
    start: &Node,
    id: usize,
    mut book: Option<&mut SeedBook>,
    out: &mut Collect,
    switched: bool,
) -> Vec<Node> {
    let exact = |z: &V6, p0: f64| {
        let e_p = V6::new(0.0, 0.0, 1.0, 0.0, 0.0, 0.0);
        eng.correct(*z, &e_p, p0).map(|(z, _)| z)
    };
    let mut watch = |a: &V6, b: &V6| match book.as_deref_mut() {
        Some(bk) => bk.crossed(a, b, id, &exact),
        None => Verdict::Continue,
    };
    let plus = eng.trace(start, &mut watch);
    let minus = (plus.end != End::Loop).then(|| eng.trace(&start.reversed(), &mut watch));
    let known = |h: &Half| h.end == End::Known;
    let duplicate = match &minus {
        Some(m) => (known(&plus) && known(m)) || (switched && (known(&plus) || known(m))),
        None => switched && known(&plus),
    };
    if duplicate {
        return Vec::new();
    }
    out.add(eng.sys, start, plus, minus)
}

/// Branch switching at each new branch point, depth first, until none is left.
pub(super) fn switch_all<S: System>(
    eng: &Engine<'_, S>,
    mut stack: Vec<Node>,
    mut book: Option<&mut SeedBook>,
    out: &mut Collect,
    max_branches: usize,
) {
    while let Some(bp) = stack.pop() {
        if out.branches.len() >= max_branches {
            return;
        }
        if out.crossed_twice(&bp.z) {
            continue;
        }
        let Some(start) = eng.switch(&bp) else {
            continue;
        };
        let id = out.branches.len();
        let more = trace_both(eng, &start, id, book.as_deref_mut(), out, true);
        stack.extend(more.into_iter().rev());
    }
}
