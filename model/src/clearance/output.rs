//! What `model clear` prints and writes: the text summary, the JSON object, summary.md and the
//! CSV of the Monte Carlo samples.

use super::monte_carlo::MonteCarlo;
use super::{Bounds, CaseAircraft, Clearance};
use crate::report::fixed;
use serde::Serialize;

/// One elevator setting's clearance with its Monte Carlo comparison.
#[derive(Clone, Debug, Serialize)]
pub struct Run {
    /// The certified bounds and worst cases.
    #[serde(flatten)]
    pub clearance: Clearance,
    /// The Monte Carlo comparison.
    pub monte_carlo: MonteCarlo,
}

fn bounds(name: &str, unit: &str, b: &Bounds, digits: usize) -> String {
    let hi = b.hi.map_or("none".to_string(), |h| fixed(h, digits));
    let gap = b.gap.map_or("-".to_string(), |g| format!("{g:.2e}"));
    format!(
        "{name}: [{}, {}] {unit}  (gap {gap}{})\n",
        fixed(b.lo, digits),
        hi,
        if b.converged { "" } else { ", not converged" }
    )
}

fn aircraft(title: &str, c: &CaseAircraft) -> String {
    let mut s = format!(
        "{title}: critical jump P0 = {} rad/s at delta_a = {} deg\n",
        fixed(c.p0, 6),
        fixed(c.delta_a_deg, 4)
    );
    let kv: Vec<String> = c
        .parameters
        .iter()
        .map(|(k, v)| format!("{k} = {v}"))
        .collect();
    for line in kv.chunks(6) {
        s += &format!("    {}\n", line.join(", "));
    }
    s
}

/// The text summary of one run.
pub fn text(r: &Run) -> String {
    let c = &r.clearance;
    let mut s = format!(
        "{}  (delta_e = {} deg), {} uncertain parameters\n\n",
        c.aircraft,
        fixed(c.delta_e_rad.to_degrees(), 4),
        c.box_.len()
    );
    for (k, lo, hi) in &c.box_ {
        s += &format!("    {k:<10} [{lo}, {hi}]\n");
    }
    s += "\nMinimum over the box of the critical jump (lo proven, hi attained):\n";
    s += &bounds("  roll rate P0    ", "rad/s", &c.critical_p0, 6);
    s += &bounds("  |delta_a|       ", "deg", &c.critical_delta_a_deg, 4);
    s += &format!(
        "  proof: {} boxes, {} slabs, {:.2} s; {}\n\n",
        c.boxes, c.slabs, c.seconds, c.note
    );
    if let Some(w) = &c.worst_case {
        s += &aircraft("Worst case (roll rate)", w);
    }
    if let Some(w) = &c.worst_case_aileron {
        s += &aircraft("Worst case (aileron)", w);
    }
    s += &match c.cleared {
        Some(true) => "\nCleared: no aircraft of the box has a critical jump within the aileron limit.\n"
            .to_string(),
        Some(false) => "\nNOT cleared: the counterexample below has its critical jump within the aileron limit.\n"
            .to_string(),
        None => "\nCleared: undecided (no aileron limit in [limits], or the bounds straddle it).\n"
            .to_string(),
    };
    if let Some(w) = &c.counterexample {
        s += &aircraft("Counterexample", w);
    }
    let m = &r.monte_carlo;
    let opt = |x: Option<f64>, d: usize| x.map_or("none".to_string(), |v| fixed(v, d));
    s += &format!(
        "\nMonte Carlo ({} seeded samples, exact path): min P0 = {} rad/s, min |delta_a| = {} deg, within limit: {}\n",
        m.samples,
        opt(m.min_p0, 6),
        opt(m.min_abs_delta_a_deg, 4),
        m.fraction_within_limit.map_or("no limit".to_string(), |f| format!("{:.4}", f))
    );
    s
}

/// summary.md of a run set.
pub fn markdown(runs: &[Run]) -> String {
    let mut s = String::from("# Clearance\n\n");
    for r in runs {
        s += "```text\n";
        s += &text(r);
        s += "```\n\n";
    }
    s
}

/// The CSV of the Monte Carlo samples (every run).
pub fn samples_csv(runs: &[Run]) -> String {
    let mut s = String::from("delta_e_deg,sample,p0_rad_s,abs_delta_a_deg\n");
    for r in runs {
        for (i, v) in r.monte_carlo.values.iter().enumerate() {
            let o = |x: Option<f64>| x.map_or(String::new(), |v| v.to_string());
            s += &format!(
                "{},{},{},{}\n",
                r.clearance.delta_e_rad.to_degrees(),
                i,
                o(v.p0),
                o(v.abs_delta_a_deg)
            );
        }
    }
    s
}
