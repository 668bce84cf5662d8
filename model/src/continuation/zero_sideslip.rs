//! The extended bifurcation analysis of section V.B: the rudder schedule of zero sideslip (EBA
//! step 1, Eq. 36), then the model with the schedule substituted (step 2, Eq. 37), with branch
//! switching at the departure (Fig. 9).

use super::collect::Collect;
use super::engine::{Engine, Node, Verdict, V6};
use super::systems::{Schedule, ZsConstrained, ZsScheduled};
use super::trace::{switch_all, trace_both};
use super::{limits, ContinuationError, SchedulePoint, Settings};
use crate::pss_model::PssModel;

/// Section V.B: EBA step 1 (the rudder schedule, by continuation of Eq. 36), then step 2
/// (Eq. 37 with the exact schedule), with branch switching at the departure.
pub(super) fn zero_sideslip(
    model: &PssModel,
    s: &Settings,
    out: &mut Collect,
    progress: &mut dyn FnMut(f64),
) -> Result<Vec<SchedulePoint>, ContinuationError> {
    let schedule = Schedule::new(model, s.delta_e).ok_or_else(|| {
        ContinuationError::ZeroSideslip(
            "l_delta_a or n_delta_r is zero: no rudder schedule exists".into(),
        )
    })?;
    let level = schedule.at(0.0).ok_or_else(|| {
        ContinuationError::ZeroSideslip("no level zero-sideslip trim at P0 = 0".into())
    })?;
    if level.delta_a < s.min || level.delta_a > s.max {
        return Err(ContinuationError::ZeroSideslip(format!(
            "the level trim needs delta_a = {} rad, outside [min, max]",
            level.delta_a
        )));
    }
    // Step 1: z = (alpha, p, q, r, delta_r, delta_a), from the level trim both ways, each to the
    // range end or the schedule's first fold in delta_a.
    let step1 = ZsConstrained {
        model,
        delta_e: s.delta_e,
    };
    let mut lim1 = limits(s, s.min, s.max);
    lim1.stop_at_fold = true;
    let eng1 = Engine {
        sys: &step1,
        lim: lim1,
    };
    let x = level.x;
    let z1 = V6::new(x[0], x[2], x[3], x[4], level.delta_r, level.delta_a);
    let e_p1 = V6::new(0.0, 1.0, 0.0, 0.0, 0.0, 0.0);
    let start1 = eng1
        .start(z1, &e_p1, |t| t[1])
        .ok_or_else(|| ContinuationError::ZeroSideslip("the level trim is singular".into()))?;
    let mut never = |_: &V6, _: &V6| Verdict::Continue;
    let up = eng1.trace(&start1, &mut never);
    let down = eng1.trace(&start1.reversed(), &mut never);
    progress(0.2);
    let nodes: Vec<&Node> = down
        .nodes
        .iter()
        .rev()
        .chain(std::iter::once(&start1))
        .chain(up.nodes.iter())
        .collect();
    let rudder_schedule: Vec<SchedulePoint> = nodes
        .iter()
        .map(|n| SchedulePoint {
            delta_a: n.z[5],
            delta_r: n.z[4],
            p: n.z[1],
        })
        .collect();
    let (s_lo, s_hi) = (nodes[0].z[1], nodes[nodes.len() - 1].z[1]);
    if s_lo.is_nan() || s_hi.is_nan() || s_lo >= s_hi {
        return Err(ContinuationError::ZeroSideslip(
            "the rudder schedule is empty".into(),
        ));
    }
    // Step 2: z = (alpha, beta, p, q, r, s), s the schedule's roll rate, from the level trim.
    let step2 = ZsScheduled { schedule };
    let eng2 = Engine {
        sys: &step2,
        lim: limits(s, s_lo, s_hi),
    };
    let z2 = V6::new(x[0], x[1], x[2], x[3], x[4], 0.0);
    let e_s = V6::new(0.0, 0.0, 0.0, 0.0, 0.0, 1.0);
    let start2 = eng2
        .start(z2, &e_s, |t| t[5])
        .ok_or_else(|| ContinuationError::ZeroSideslip("the level trim is singular".into()))?;
    let bps = trace_both(&eng2, &start2, 0, None, out, false);
    progress(0.6);
    switch_all(&eng2, bps, None, out, s.max_branches);
    Ok(rudder_schedule)
}
