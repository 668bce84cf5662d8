//! The verdict of a clearance against the aileron limit, and why: cleared (the proven lower
//! bound of |delta_a| at the critical jump lies above the limit), not cleared (an aircraft of
//! the box, analysed by the exact path, has its critical jump within it), or undecided (the
//! bounds still straddle the limit when the work budget ran out, or where the proof cannot
//! raise its bound), with the gap reached on each side of the limit. A verdict the tolerance
//! leaves undecided is tightened past it first ([`super::clear`]); [`Tightening`] says how that
//! went.

use serde::Serialize;

/// Which way a clearance against the aileron limit went.
#[derive(Clone, Copy, Debug, Serialize, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum Verdict {
    /// Proven: no aircraft of the box has a critical jump within the limit.
    Cleared,
    /// An aircraft of the box (the counterexample) has its critical jump within the limit.
    NotCleared,
    /// The bounds straddle the limit: the work budget (or the wall-clock guard) ran out first.
    UndecidedBudget,
    /// The bounds straddle the limit and the proof cannot raise its bound further (every
    /// remaining sub-box stuck or at the cap, or |delta_a|'s bound held at 0).
    Undecided,
}

/// How far an undecided verdict got: the gap from the proven bound up to the limit and from
/// the limit up to the worst case found, deg.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct LimitGap {
    /// The aileron limit less the proven lower bound `lo`, deg.
    pub limit_minus_lo_deg: f64,
    /// The worst case's |delta_a| (`hi`) less the aileron limit, deg.
    pub hi_minus_limit_deg: f64,
}

/// The branch and bound past the tolerance, run when the limit fell between the bounds: the
/// lower bound it started from (deg), why it stopped, and whether a budget of work (or the
/// wall-clock guard) stopped it.
#[derive(Clone, Debug)]
pub(super) struct Tightening {
    pub(super) from_lo_deg: f64,
    pub(super) note: String,
    pub(super) by_budget: bool,
}

/// The bounds of |delta_a| at the critical jump (deg) a verdict is decided from.
pub(super) struct AileronBounds {
    pub(super) lo: f64,
    pub(super) hi: Option<f64>,
}

/// The verdict against the aileron `limit` (deg; none without one), with its reason and, when
/// undecided, the gap: from the counterexample's |delta_a| (deg) if one was found, the bounds
/// `b`, and the tightening past the tolerance if it ran (`tight`).
pub(super) fn decide(
    limit: Option<f64>,
    counterexample: Option<f64>,
    b: &AileronBounds,
    tight: Option<&Tightening>,
) -> (Option<Verdict>, String, Option<LimitGap>) {
    let Some(l) = limit else {
        return (None, "no aileron limit in [limits]".to_string(), None);
    };
    let by = |what: &str| match tight {
        Some(t) => format!(
            "{what}, decided by tightening the bounds past the tolerance (lo from {:.4} deg)",
            t.from_lo_deg
        ),
        None => what.to_string(),
    };
    if let Some(d) = counterexample {
        let what = format!(
            "the counterexample (exact analysis) has its critical jump at |delta_a| = {d:.4} deg, \
             within the {l} deg limit"
        );
        return (Some(Verdict::NotCleared), by(&what), None);
    }
    if b.lo > l {
        let what = if b.lo == f64::INFINITY {
            "proven: no aircraft of the box has a critical jump".to_string()
        } else {
            format!(
                "proven: |delta_a| >= {:.4} deg, above the {l} deg limit",
                b.lo
            )
        };
        return (Some(Verdict::Cleared), by(&what), None);
    }
    let gap = LimitGap {
        limit_minus_lo_deg: l - b.lo,
        hi_minus_limit_deg: b.hi.map_or(f64::INFINITY, |h| h - l),
    };
    let why = match tight {
        Some(t) => format!("tightening past the tolerance {}", t.note),
        None => "the bounds were not tightened".to_string(),
    };
    let reason = format!(
        "the bounds straddle the {l} deg limit ({why}): limit - lo = {:.2e} deg, hi - limit = \
         {:.2e} deg",
        gap.limit_minus_lo_deg, gap.hi_minus_limit_deg
    );
    let verdict = if tight.is_some_and(|t| t.by_budget) {
        Verdict::UndecidedBudget
    } else {
        Verdict::Undecided
    };
    (Some(verdict), reason, Some(gap))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tight(by_budget: bool) -> Tightening {
        Tightening {
            from_lo_deg: 3.1,
            note: if by_budget {
                "stopped at the budget of 3 slabs"
            } else {
                "stopped: every remaining box is stuck at a point where the proof cannot continue"
            }
            .to_string(),
            by_budget,
        }
    }

    /// The three outcomes, decided from the counterexample first, then the proven bound, and
    /// null without a limit; an undecided one carries the gap on each side of the limit.
    #[test]
    fn a_verdict_says_which_way_and_how_far() {
        let b = AileronBounds {
            lo: 3.1,
            hi: Some(3.2),
        };
        let none = decide(None, None, &b, None);
        assert_eq!((none.0, none.2), (None, None));
        let (v, why, _) = decide(Some(3.0), None, &b, None);
        assert_eq!(v, Some(Verdict::Cleared));
        assert!(why.starts_with("proven: |delta_a| >= 3.1000 deg"), "{why}");
        let (v, why, _) = decide(Some(3.15), Some(3.12), &b, Some(&tight(false)));
        assert_eq!(v, Some(Verdict::NotCleared));
        assert!(
            why.contains("3.1200") && why.contains("tightening"),
            "{why}"
        );
        let (v, why, gap) = decide(Some(3.15), None, &b, Some(&tight(true)));
        assert_eq!(v, Some(Verdict::UndecidedBudget));
        assert!(why.contains("budget of 3 slabs"), "{why}");
        let gap = gap.expect("a gap");
        assert!((gap.limit_minus_lo_deg - 0.05).abs() < 1e-12, "{gap:?}");
        assert!((gap.hi_minus_limit_deg - 0.05).abs() < 1e-12, "{gap:?}");
        let (v, why, _) = decide(Some(3.15), None, &b, Some(&tight(false)));
        assert_eq!(v, Some(Verdict::Undecided));
        assert!(
            why.contains("tightening past the tolerance stopped"),
            "{why}"
        );
    }
}
