//! The text tables of `model analyze` and `model continue`.

use super::numbers::{
    departure_cells, first_departure_text, fixed, hopf_cells, jump_cells, list, validity_mark,
};
use crate::aircraft::shown;
use crate::analysis::Analysis;
use crate::continuation::Diagram;

/// The marks of a reported point: beyond the control limits, outside the validity range.
fn marks(within_limits: Option<bool>, valid: bool) -> String {
    let mut m = String::new();
    if within_limits == Some(false) {
        m += "  [beyond limits]";
    }
    if !valid {
        m += "  [outside validity range]";
    }
    m
}

/// Whether a row is shown without `--all`: within the control limits (or none given) and the
/// validity range.
fn shown_row(within_limits: Option<bool>, valid: bool) -> bool {
    within_limits != Some(false) && valid
}

/// A table of `rows` (each with its limits and validity marks) under `title` and `header`:
/// the rows within the limits and the validity range, or every row with `all`, and the count
/// of the rows left out.
fn table(
    title: &str,
    header: &str,
    rows: &[(String, Option<bool>, bool)],
    what: &str,
    all: bool,
) -> String {
    let mut s = format!("{title}\n");
    if rows.is_empty() {
        return s + "  none\n";
    }
    let kept: Vec<&(String, Option<bool>, bool)> = rows
        .iter()
        .filter(|(_, l, v)| all || shown_row(*l, *v))
        .collect();
    if !kept.is_empty() {
        s += header;
        for (row, l, v) in &kept {
            s += &format!("{row}{}\n", marks(*l, *v));
        }
    }
    let left = rows.len() - kept.len();
    if left > 0 {
        let more = if kept.is_empty() { "" } else { " more" };
        s += &format!(
            "  {left}{more} {what} row{} beyond the limits or validity range: --all\n",
            if left == 1 { "" } else { "s" }
        );
    }
    s
}

/// The column header of a table (`columns` ending in a newline), saying where its `states`
/// (e.g. "alpha, beta, q, r") are increments from the trim.
fn header(columns: &str, states: &str, a: &Analysis) -> String {
    if a.trim.is_some() {
        format!(
            "{}   ({states}: increments from the trim)\n",
            columns.trim_end()
        )
    } else {
        columns.to_string()
    }
}

/// The Hopf points (complex pair on the imaginary axis), with omega and l1.
fn hopf_table(a: &Analysis, all: bool) -> String {
    let rows: Vec<(String, Option<bool>, bool)> = a
        .hopf
        .iter()
        .map(|h| {
            let [p0, da, alpha, beta, omega, period, l1, kind] = hopf_cells(h);
            (
                format!("  {p0:>11} {da:>13} {alpha:>11} {beta:>11} {omega:>12} {period:>11} {l1:>15}  {kind}"),
                h.point.within_limits,
                h.point.within_validity,
            )
        })
        .collect();
    table(
        "\nHopf points, Delta4 = 0 with omega^2 > 0 (oscillatory departure):",
        &header("     P0 rad/s   delta_a deg   alpha deg    beta deg  omega rad/s    period s              l1  kind\n", "alpha, beta", a),
        &rows,
        "Hopf",
        all,
    )
}

/// The critical jump with the aileron limit and the margin to it, or why there is none.
fn critical_text(a: &Analysis) -> String {
    let c = match (&a.critical, &a.critical_note) {
        (Some(c), _) => c,
        (None, Some(note)) => return format!("No critical jump: {note}.\n"),
        (None, None) => return String::new(),
    };
    let mut s = format!(
        "Critical jump (first fold of the primary branch): P0 = {} rad/s at delta_a = {} deg (and the mirror point -P0 at {:+.4} deg){}\n",
        fixed(c.p0, 6),
        fixed(c.delta_a_deg, 4),
        -c.delta_a_deg,
        validity_mark(c.alpha, c.beta, a)
    );
    s += &match (a.aileron_limit_deg, a.margin_deg) {
        (Some(limit), Some(m)) if m >= 0.0 => format!(
            "  aileron limit {} deg, margin {} deg (the limit minus |delta_a|): a full-stick roll reaches the jump with {} deg of travel to spare\n",
            fixed(limit, 4),
            fixed(m, 4),
            fixed(m, 4)
        ),
        (Some(limit), Some(m)) => format!(
            "  aileron limit {} deg, margin {} deg (the limit minus |delta_a|): the jump lies {} deg beyond the stick's travel\n",
            fixed(limit, 4),
            fixed(m, 4),
            fixed(-m, 4)
        ),
        _ => "  aileron limit: none in the aircraft file (no [limits] aileron), so no margin\n"
            .to_string(),
    };
    s
}

/// The text `model analyze` prints: the answer first (the critical jump with the aileron
/// limit and the margin, the first departure), then the tables, each with only its rows within
/// the limits and the validity range unless `all`.
pub fn analysis(a: &Analysis, all: bool) -> String {
    let mut s = String::new();
    let list = |v: &[f64]| list(v, 6, "rad/s");
    s += &format!(
        "{}  (delta_e = {} deg{}, delta_r = 0)\n\n",
        shown(&a.aircraft),
        fixed(a.delta_e_rad.to_degrees(), 4),
        if a.trim.is_some() {
            " from the trim"
        } else {
            ""
        }
    );
    if let Some(t) = &a.trim {
        s += &format!(
            "At the trim: n = {} g at V = {} m/s, the principal axis at alpha_t = {} deg; alpha, \
             beta, q, r and delta_e below are increments from it.\n\n",
            fixed(t.load_factor, 3),
            fixed(t.speed_m_s, 1),
            fixed(t.alpha_t_deg, 3)
        );
    }
    for w in &a.warnings {
        s += &format!("Warning: {w}.\n\n");
    }
    let critical = critical_text(a);
    if !critical.is_empty() {
        s += &critical;
        s += "\n";
    }
    s += &first_departure_text(a);
    s += &format!(
        "Divergence roll rates, Eq. 5:   {}\n",
        list(&a.divergence_roll_rates)
    );
    s += &format!(
        "Poles of det K, d = 0:          {}\n\n",
        list(&a.det_k_poles.iter().map(|j| j.p0).collect::<Vec<_>>())
    );
    let jumps: Vec<(String, Option<bool>, bool)> = a
        .jump
        .iter()
        .map(|j| {
            let [p0, da, alpha, beta, q, r] = jump_cells(j);
            (
                format!("  {p0:>11} {da:>13} {alpha:>11} {beta:>11} {q:>11} {r:>11}"),
                j.within_limits,
                j.within_validity,
            )
        })
        .collect();
    s += &table(
        "Jump points, det K = 0 (saddle-nodes of the PSS equilibria):",
        &header(
            "     P0 rad/s   delta_a deg   alpha deg    beta deg     q rad/s     r rad/s\n",
            "alpha, beta, q, r",
            a,
        ),
        &jumps,
        "jump",
        all,
    );
    s += &hopf_table(a, all);
    let title = "\nZero-sideslip departure, det K = 0 at beta = 0 (section V):";
    if let Some(why) = &a.zero_sideslip.withheld {
        s += &format!("{title}\n  withheld: {why}\n");
        return s;
    }
    let departures: Vec<(String, Option<bool>, bool)> = a
        .zero_sideslip
        .departure
        .iter()
        .map(|j| {
            let [p0, da, dr, alpha, q, r] = departure_cells(j);
            (
                format!("  {p0:>11} {da:>13} {dr:>13} {alpha:>11} {q:>11} {r:>11}"),
                j.within_limits,
                j.within_validity,
            )
        })
        .collect();
    s += &table(
        title,
        &header(
            "     P0 rad/s   delta_a deg   delta_r deg   alpha deg     q rad/s     r rad/s\n",
            "alpha, q, r",
            a,
        ),
        &departures,
        "departure",
        all,
    );
    s
}

/// The text `model continue` prints: the branches and their special points.
pub fn diagram(d: &Diagram) -> String {
    let points: usize = d.branches.iter().map(|b| b.points.len()).sum();
    let count =
        |n: usize, one: &str, many: &str| format!("{n} {}", if n == 1 { one } else { many });
    let mut s = format!(
        "{}: {}, {}, continuation in {}\n\n",
        shown(&d.aircraft),
        count(d.branches.len(), "branch", "branches"),
        count(points, "point", "points"),
        d.parameter
    );
    if d.special_points.is_empty() {
        s += "No special points.\n";
        return s;
    }
    s += &format!(
        "  kind    {:>12} {:>10} {:>10} {:>10} {:>10} {:>10} {:>12}\n",
        format!("{} deg", d.parameter),
        "p rad/s",
        "alpha deg",
        "beta deg",
        "q rad/s",
        "r rad/s",
        "freq rad/s"
    );
    for p in &d.special_points {
        s += &format!(
            "  {:<7} {:>12} {:>10} {:>10} {:>10} {:>10} {:>10} {:>12}{}\n",
            p.kind.name(),
            fixed(p.param.to_degrees(), 4),
            fixed(p.p, 6),
            fixed(p.alpha.to_degrees(), 4),
            fixed(p.beta.to_degrees(), 4),
            fixed(p.q, 5),
            fixed(p.r, 5),
            p.frequency.map_or(String::new(), |f| fixed(f, 5)),
            marks(p.within_limits, p.valid)
        );
    }
    s
}
