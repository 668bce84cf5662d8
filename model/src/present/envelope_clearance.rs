//! What `model envelope --uncertainty` adds to the envelope's table and CSV: at every point the
//! proven lower bounds of the critical jump over the box (|delta_a| and P0), the worst case
//! found, and the verdict against the aileron limit with what decided it (the counterexample's
//! critical aileron, or the gap the proof reached when its budget ran out).

use super::envelope::{cell, state_cells, STATE_HEADER};
use super::numbers::fixed;
use crate::clearance::Verdict;
use crate::envelope::clearance::PointClearance;
use crate::envelope::{Envelope, Point};

/// A verdict as one word, `-` without one.
pub fn verdict_word(v: Option<Verdict>) -> &'static str {
    match v {
        Some(Verdict::Cleared) => "cleared",
        Some(Verdict::NotCleared) => "not_cleared",
        Some(Verdict::UndecidedBudget) => "undecided_budget",
        Some(Verdict::Undecided) => "undecided",
        None => "-",
    }
}

/// What decided the verdict, in a few words: the counterexample's critical aileron, or the gap
/// on each side of the limit, or the proven bound (or no jump) above the limit.
fn detail(c: &PointClearance) -> String {
    if let Some(d) = c.counterexample_delta_a_deg {
        return format!("counterexample at delta_a = {} deg", fixed(d, 3));
    }
    if let Some(g) = &c.gap_to_limit {
        // Without a worst case found, hi - limit is infinite: said as "no hi".
        let above = match g.hi_minus_limit_deg {
            x if x.is_finite() => format!("hi - limit = {x:.2e} deg"),
            _ => "no hi".to_string(),
        };
        return format!(
            "gap: limit - lo = {:.2e} deg, {above}",
            g.limit_minus_lo_deg
        );
    }
    if c.no_critical_jump {
        return "proven: no critical jump in the box".to_string();
    }
    match c.verdict {
        Some(Verdict::Cleared) => "proven bound above the limit".to_string(),
        _ => String::new(),
    }
}

/// The table of the clearances, after the envelope's (empty without `--uncertainty`).
pub fn text(env: &Envelope) -> String {
    let Some(spec) = &env.uncertainty else {
        return String::new();
    };
    let mut s = format!(
        "\nCertified clearance over the box of --uncertainty {spec} (lo proven for every \
         aircraft of the box, hi attained by one):\n\n"
    );
    s += STATE_HEADER;
    s += "  boxed  delta_a_lo_deg  delta_a_hi_deg  p0_lo_rad_s  verdict           detail\n";
    for p in &env.points {
        let Some(c) = &p.clearance else {
            if let Some(e) = &p.clearance_error {
                s += &format!("{}  clearance refused: {e}\n", state_cells(p));
            }
            continue;
        };
        s += &format!(
            "{}  {:>5}  {:>14}  {:>14}  {:>11}  {:<16}  {}\n",
            state_cells(p),
            c.uncertain,
            cell(c.delta_a_lo_deg, 4),
            cell(c.delta_a_hi_deg, 4),
            cell(c.p0_lo, 5),
            verdict_word(c.verdict),
            detail(c)
        );
    }
    let count = |v: Verdict| {
        env.points
            .iter()
            .filter(|p| p.clearance.as_ref().is_some_and(|c| c.verdict == Some(v)))
            .count()
    };
    s + &format!(
        "\n{} points cleared, {} not cleared (a counterexample), {} undecided when the budget \
         ran out, {} undecided, {} without a clearance (untrimmable, an error, or a refused proof)\n",
        count(Verdict::Cleared),
        count(Verdict::NotCleared),
        count(Verdict::UndecidedBudget),
        count(Verdict::Undecided),
        env.points.iter().filter(|p| p.clearance.is_none()).count()
    )
}

/// The CSV columns the clearance adds, with their units.
pub const CSV_HEADER: &str = ",uncertain_coordinates,delta_a_lo_deg,delta_a_hi_deg,p0_lo_rad_s,\
     p0_hi_rad_s,verdict,counterexample_delta_a_deg,limit_minus_lo_deg,hi_minus_limit_deg";

/// The clearance's cells of `p`'s CSV row, empty where a number does not exist.
pub fn csv_cells(p: &Point) -> Vec<String> {
    let num = |x: Option<f64>| x.map_or(String::new(), |v| v.to_string());
    let Some(c) = &p.clearance else {
        return vec![String::new(); CSV_HEADER.matches(',').count()];
    };
    let gap = c.gap_to_limit.as_ref();
    vec![
        c.uncertain.to_string(),
        num(c.delta_a_lo_deg),
        num(c.delta_a_hi_deg),
        num(c.p0_lo),
        num(c.p0_hi),
        verdict_word(c.verdict).replace('-', ""),
        num(c.counterexample_delta_a_deg),
        num(gap.map(|g| g.limit_minus_lo_deg)),
        num(gap.map(|g| g.hi_minus_limit_deg).filter(|x| x.is_finite())),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::clearance::LimitGap;

    fn undecided(hi_minus_limit_deg: f64) -> PointClearance {
        PointClearance {
            uncertain: 15,
            p0_lo: Some(2.3),
            p0_hi: None,
            delta_a_lo_deg: Some(19.5),
            delta_a_hi_deg: None,
            no_critical_jump: false,
            verdict: Some(Verdict::UndecidedBudget),
            verdict_reason: String::new(),
            counterexample_delta_a_deg: None,
            gap_to_limit: Some(LimitGap {
                limit_minus_lo_deg: 0.55,
                hi_minus_limit_deg,
            }),
            note: String::new(),
        }
    }

    /// A verdict the budget left undecided says the gap it reached on each side of the limit,
    /// and "no hi" rather than an infinity when no worst case was found.
    #[test]
    fn an_undecided_point_says_the_gap_reached() {
        assert_eq!(
            detail(&undecided(0.25)),
            "gap: limit - lo = 5.50e-1 deg, hi - limit = 2.50e-1 deg"
        );
        assert_eq!(
            detail(&undecided(f64::INFINITY)),
            "gap: limit - lo = 5.50e-1 deg, no hi"
        );
        assert_eq!(verdict_word(undecided(1.0).verdict), "undecided_budget");
    }
}
