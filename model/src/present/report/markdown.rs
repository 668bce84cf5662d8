//! `summary.md` of `model report`: the numbers of `analyze` (first loss of stability, critical
//! roll rates, jump, Hopf and departure points), the continuation's special points, the
//! simulated jumps against the criterion, and Figs 1-11 with their captions.

use super::Summary;
use crate::analysis::Analysis;
use crate::present::numbers::{
    departure_cells, first_departure_text, fixed, hopf_cells, jump_cells, list,
};

/// A markdown table row of cells.
fn md_row(cells: &[String]) -> String {
    format!("| {} |\n", cells.join(" | "))
}

/// `summary.md`: the analysis' numbers, the special points, the simulated jumps, the figures
/// and what was skipped, for the elevator deflection `de` (rad).
pub(super) fn markdown(s: &Summary, de: f64) -> String {
    let a = &s.analysis;
    let mut m = format!(
        "# {}: roll-coupling report\n\nElevator {:.2} deg, rudder 0 (unconstrained roll). Criterion of Mahale & Ananthkrishnan (AIAA 2006-6267), derived exactly; see `docs/formulas.tex`.\n\n",
        crate::aircraft::shown(&a.aircraft),
        de.to_degrees()
    );
    for w in &a.warnings {
        m += &format!("**Warning**: {w}.\n\n");
    }
    m += &format!(
        "## First loss of stability\n\n```text\n{}\n```\n\n",
        first_departure_text(a).trim_end()
    );
    m += &critical_roll_rates(a);
    for (title, rows) in [
        (
            "Special points of the continuation (p >= 0)",
            &s.special_points,
        ),
        (
            "Special points of the zero-sideslip continuation (p >= 0)",
            &s.zero_sideslip_special_points,
        ),
    ] {
        m += &format!("\n## {title}\n\n| kind | delta_a deg | p rad/s | frequency rad/s |\n|---|---:|---:|---:|\n");
        for r in rows.iter() {
            m += &format!(
                "| {} | {} | {} | {} |\n",
                r.kind,
                fixed(r.delta_a_deg, 4),
                fixed(r.p, 6),
                r.frequency.map_or(String::new(), |f| fixed(f, 5))
            );
        }
    }
    if !s.simulated_jumps.is_empty() {
        m += "\n## Simulated jump (aileron steps from the trim, 0.25 deg apart, refined)\n\n| model | jump at delta_a deg | criterion fold deg |\n|---|---:|---:|\n";
        for j in &s.simulated_jumps {
            m += &format!(
                "| {} | {} | {:.4} |\n",
                j.model,
                j.delta_a_deg.map_or("none".into(), |d| format!("{d:.3}")),
                j.criterion_deg
            );
        }
    }
    if !s.failed_files.is_empty() {
        m += "\n## Files that could not be written\n\n";
        for f in &s.failed_files {
            m += &format!("- `{}`: {}\n", f.path.display(), f.reason);
        }
    }
    if !s.skipped.is_empty() {
        m += "\n## Not computed for this aircraft\n\n";
        for k in &s.skipped {
            m += &format!("- {k}\n");
        }
    }
    m += "\n## Figures\n";
    for f in &s.figures {
        let png = f
            .files
            .iter()
            .find(|p| p.ends_with(".png"))
            .or(f.files.first());
        m += &format!("\n### {}\n\n{}\n\n", f.paper, f.caption);
        if let Some(p) = png {
            m += &format!("![{}]({})\n", f.paper, p);
        }
    }
    m
}

/// The section on the critical roll rates of `a`: divergence, poles of det K, and the tables of
/// jump, Hopf and zero-sideslip departure points.
fn critical_roll_rates(a: &Analysis) -> String {
    let mut m = String::new();
    m += "## Critical roll rates\n\n";
    m += &format!(
        "- Pitch-yaw divergence, Eq. 5 (Table 1): {}\n",
        list(&a.divergence_roll_rates, 6, "rad/s")
    );
    m += &format!(
        "- Poles of det K (d = 0): {}\n\n",
        list(
            &a.det_k_poles.iter().map(|j| j.p0).collect::<Vec<_>>(),
            6,
            "rad/s"
        )
    );
    m += "### Jump points (det K = 0, saddle-nodes)\n\n| P0 rad/s | delta_a deg | alpha deg | beta deg | q rad/s | r rad/s |\n|---:|---:|---:|---:|---:|---:|\n";
    for j in &a.jump {
        m += &md_row(&jump_cells(j));
    }
    if a.jump.is_empty() {
        m += "| none | | | | | |\n";
    }
    m += "\n### Hopf points (closed form, Delta4 = 0 with omega^2 > 0)\n\n| P0 rad/s | delta_a deg | alpha deg | beta deg | omega rad/s | period s | l1 | kind |\n|---:|---:|---:|---:|---:|---:|---:|---|\n";
    for h in &a.hopf {
        m += &md_row(&hopf_cells(h));
    }
    if a.hopf.is_empty() {
        m += "| none | | | | | | | |\n";
    }
    m += "\n### Zero-sideslip departure (det K = 0 at beta = 0)\n\n| P0 rad/s | delta_a deg | delta_r deg | alpha deg | q rad/s | r rad/s |\n|---:|---:|---:|---:|---:|---:|\n";
    for d in &a.zero_sideslip.departure {
        m += &md_row(&departure_cells(d));
    }
    if let Some(why) = &a.zero_sideslip.withheld {
        m += &format!("\nWithheld: {why}\n");
    }
    m
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::aircraft::Aircraft;

    #[test]
    fn the_summary_says_which_instability_comes_first_with_l1_and_kind_for_a_hopf_point() {
        let mut a = crate::analysis::analyze_with(&Aircraft::a(), 0.0349, false).unwrap();
        a.first_departure = None;
        let none = first_departure_text(&a);
        assert!(none.contains("none within the aileron range"), "{none}");
        // A Hopf point first (numbers made up for the text): its frequency, l1 and kind.
        a.first_departure = Some(crate::analysis::FirstDeparture {
            kind: "hopf",
            p0: 3.1,
            delta_a_rad: -0.36,
            delta_a_deg: -20.6,
            alpha: Some(-0.1),
            beta: Some(0.05),
            within_validity: Some(true),
            omega: Some(0.88),
            l1: Some(-0.1746),
            hopf_kind: Some("supercritical"),
            lands_at: None,
            unstable_trim: None,
        });
        let text = first_departure_text(&a);
        assert!(
            text.starts_with(
                "First loss of stability on the primary branch: HOPF at P0 = 3.100000 rad/s, \
                 delta_a = -20.6000 deg (oscillation omega = 0.8800 rad/s, l1 = -0.1746, \
                 supercritical)\n"
            ),
            "{text}"
        );
        let summary = Summary {
            analysis: a,
            special_points: vec![],
            zero_sideslip_special_points: vec![],
            simulated_jumps: vec![],
            figures: vec![],
            skipped: vec![],
            failed_files: vec![],
        };
        let md = markdown(&summary, 0.0349);
        let section = format!(
            "## First loss of stability\n\n```text\n{}\n```",
            text.trim_end()
        );
        assert!(md.contains(&section), "{md}");
    }
}
