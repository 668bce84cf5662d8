//! The text tables of `model analyze` and `model continue`.

use super::numbers::{departure_cells, first_departure_text, fixed, hopf_cells, jump_cells, list};
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

/// The Hopf points (complex pair on the imaginary axis), with omega and l1.
fn hopf_table(a: &Analysis) -> String {
    let mut s = "\nHopf points, Delta4 = 0 with omega^2 > 0 (oscillatory departure):\n".to_string();
    if a.hopf.is_empty() {
        return s + "  none\n";
    }
    s += "     P0 rad/s   delta_a deg   alpha deg    beta deg  omega rad/s    period s          l1  kind\n";
    for h in &a.hopf {
        let [p0, da, alpha, beta, omega, period, l1, kind] = hopf_cells(h);
        s += &format!(
            "  {p0:>11} {da:>13} {alpha:>11} {beta:>11} {omega:>12} {period:>11} {l1:>11}  {kind}{}\n",
            marks(h.point.within_limits, h.point.valid)
        );
    }
    s
}

/// The text `model analyze` prints.
pub fn analysis(a: &Analysis) -> String {
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
    match (&a.critical, &a.critical_note) {
        (Some(c), _) => {
            s += &format!(
                "Critical jump (first fold of the primary branch): P0 = {:.6} rad/s at delta_a = {:.4} deg (and the mirror point -P0 at {:+.4} deg){}\n\n",
                c.p0,
                c.delta_a_deg,
                -c.delta_a_deg,
                match c.within_limits {
                    Some(true) => ", within the aileron limit",
                    Some(false) => ", OUTSIDE the aileron limit",
                    None => "",
                }
            );
        }
        (None, Some(note)) => s += &format!("No critical jump: {note}.\n\n"),
        (None, None) => {}
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
    s += "Jump points, det K = 0 (saddle-nodes of the PSS equilibria):\n";
    if a.jump.is_empty() {
        s += "  none\n";
    } else {
        s += "     P0 rad/s   delta_a deg   alpha deg    beta deg     q rad/s     r rad/s\n";
        for j in &a.jump {
            let [p0, da, alpha, beta, q, r] = jump_cells(j);
            s += &format!(
                "  {p0:>11} {da:>13} {alpha:>11} {beta:>11} {q:>11} {r:>11}{}\n",
                marks(j.within_limits, j.valid)
            );
        }
    }
    s += &hopf_table(a);
    s += "\nZero-sideslip departure, det K = 0 at beta = 0 (section V):\n";
    if let Some(why) = &a.zero_sideslip.withheld {
        s += &format!("  withheld: {why}\n");
    } else if a.zero_sideslip.departure.is_empty() {
        s += "  none\n";
    } else {
        s += "     P0 rad/s   delta_a deg   delta_r deg   alpha deg     q rad/s     r rad/s\n";
        for j in &a.zero_sideslip.departure {
            let [p0, da, dr, alpha, q, r] = departure_cells(j);
            s += &format!(
                "  {p0:>11} {da:>13} {dr:>13} {alpha:>11} {q:>11} {r:>11}{}\n",
                marks(j.within_limits, j.valid)
            );
        }
    }
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
