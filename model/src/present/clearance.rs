//! What `model clear` prints and writes: the text summary, the JSON object, summary.md and the
//! CSV of the Monte Carlo samples.
//!
//! ```
//! use model::present::clearance::samples_csv;
//!
//! // The CSV's columns, with their units: one row per Monte Carlo sample of each run.
//! assert_eq!(samples_csv(&[]), "delta_e_deg,sample,p0_rad_s,abs_delta_a_deg\n");
//! ```

use crate::clearance::run::Run;
use crate::clearance::{Bounds, CaseAircraft, Clearance, Verdict};
use crate::present::numbers::fixed;

fn bounds(name: &str, unit: &str, b: &Bounds, digits: usize) -> String {
    if b.lo == f64::INFINITY {
        return format!("{name}: none (proven: no aircraft of the box has a critical jump)\n");
    }
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

/// The verdict's lines: which way it went and, when the bounds were tightened past the
/// tolerance or it is undecided, why.
fn verdict(c: &Clearance) -> String {
    let tightened = c.verdict_reason.contains("tightening");
    let why = format!("  ({})\n", c.verdict_reason);
    match c.verdict {
        Some(Verdict::Cleared) => {
            "\nCleared: no aircraft of the box has a critical jump within the aileron limit.\n"
                .to_string()
                + if tightened { &why } else { "" }
        }
        Some(Verdict::NotCleared) => {
            "\nNOT cleared: the counterexample below has its critical jump within the aileron \
             limit.\n"
                .to_string()
                + if tightened { &why } else { "" }
        }
        Some(Verdict::UndecidedBudget) => {
            "\nCleared: undecided, the budget ran out first.\n".to_string() + &why
        }
        Some(Verdict::Undecided) => "\nCleared: undecided.\n".to_string() + &why,
        None => "\nCleared: undecided (no aileron limit in [limits]).\n".to_string(),
    }
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
    if c.no_critical_jump {
        s += "No critical jump (proven): along its primary branch no aircraft of the box meets \
              a jump within the aileron range (the limit in [limits], at least 90 deg).\n";
    }
    if let Some(w) = &c.worst_case {
        s += &aircraft("Worst case (roll rate)", w);
    }
    if let Some(w) = &c.worst_case_aileron {
        s += &aircraft("Worst case (aileron)", w);
    }
    s += &verdict(c);
    if let Some(w) = &c.counterexample {
        s += &aircraft("Counterexample", w);
    }
    let m = &r.monte_carlo;
    let opt = |x: Option<f64>, d: usize| x.map_or("none".to_string(), |v| fixed(v, d));
    s += &format!(
        "\nMonte Carlo ({} seeded samples, certified route, {} of them by the exact path): min P0 = {} rad/s, min |delta_a| = {} deg, within limit: {}\n",
        m.samples,
        m.exact_fallbacks,
        opt(m.min_p0, 6),
        opt(m.min_abs_delta_a_deg, 4),
        match (m.fraction_within_limit, m.samples) {
            (Some(f), _) => format!("{f:.4}"),
            (None, 0) => "none (no samples)".to_string(),
            (None, _) => "no limit".to_string(),
        }
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

/// The CSV of the Monte Carlo samples (every run): each sample's box coordinates by their
/// `[uncertainty]` keys, written to the last digit, so that the aircraft file with those values
/// analyses to the sample's critical jump.
pub fn samples_csv(runs: &[Run]) -> String {
    // Every run is of the same box: the coordinates' keys from the first.
    let keys: Vec<&str> = runs
        .first()
        .map(|r| {
            r.clearance
                .box_
                .iter()
                .map(|(k, _, _)| k.as_str())
                .collect()
        })
        .unwrap_or_default();
    let mut s = String::from("delta_e_deg,sample,");
    for k in &keys {
        s += &format!("{k},");
    }
    s += "p0_rad_s,abs_delta_a_deg\n";
    for r in runs {
        let draws = &r.monte_carlo.draws;
        for (i, v) in r.monte_carlo.values.iter().enumerate() {
            let o = |x: Option<f64>| x.map_or(String::new(), |v| v.to_string());
            s += &format!("{},{i},", r.clearance.delta_e_rad.to_degrees());
            for x in draws.get(i).into_iter().flatten() {
                s += &format!("{x:?},");
            }
            s += &format!("{},{}\n", o(v.p0), o(v.abs_delta_a_deg));
        }
    }
    s
}

/// Writes the folder of `model clear --out DIR`: `summary.json` (the JSON `json` printed),
/// `summary.md`, `samples.csv`, the histogram (`clearance_histogram`; for several elevator
/// settings one per setting, `clearance_histogram_K` numbered from 1 in their order, and the
/// clearance map), each figure as SVG, PNG and CSV. Every file is written whole or not at all;
/// the error names the file that failed and why.
pub fn write_folder(dir: &std::path::Path, runs: &[Run], json: &str) -> Result<(), String> {
    let write = |name: &str, contents: String| {
        let path = dir.join(name);
        crate::files::write_output(&path, contents.as_bytes())
            .map_err(|e| format!("cannot write {}: {e}", path.display()))
    };
    crate::files::create_dir_all(dir)
        .map_err(|e| format!("cannot create {}: {e}", dir.display()))?;
    write("summary.json", format!("{json}\n"))?;
    write("summary.md", markdown(runs))?;
    write("samples.csv", samples_csv(runs))?;
    let mut figures = Vec::new();
    if let [run] = runs {
        figures.push(("clearance_histogram".to_string(), histogram(run)));
    } else {
        for (k, run) in runs.iter().enumerate() {
            figures.push((format!("clearance_histogram_{}", k + 1), histogram(run)));
        }
        figures.push(("clearance_map".to_string(), map(runs)));
    }
    let style = crate::plot::PlotStyle::default();
    for (stem, f) in figures {
        crate::plot::render(&dir.join(stem), &f, &style).map_err(|e| e.to_string())?;
    }
    Ok(())
}

use crate::plot::{Axis, Dash, Figure, LegendPlace, Line, Panel, Rgb};

fn line(label: &str, points: Vec<(f64, f64)>, color: Rgb, dash: Dash) -> Line {
    Line {
        label: Some(label.to_string()),
        points,
        color,
        dash,
        width: 2,
    }
}

fn panel(title: &str, x: Axis, y: Axis, lines: Vec<Line>) -> Panel {
    Panel {
        title: title.to_string(),
        area: [0.0, 0.0, 1.0, 1.0],
        x,
        y,
        lines,
        markers: Vec::new(),
        legend: LegendPlace::UpperRight,
    }
}

/// The histogram of the Monte Carlo critical roll rates with the certified bounds.
pub fn histogram(r: &Run) -> Figure {
    let v: Vec<f64> = r.monte_carlo.values.iter().filter_map(|s| s.p0).collect();
    let c = &r.clearance;
    // The bounds drawn where they exist: no `lo` line when no aircraft of the box has a
    // critical jump (lo infinite), no `hi` line without a worst case.
    let lo = Some(c.critical_p0.lo).filter(|l| l.is_finite());
    let hi = c.critical_p0.hi;
    let xs = || v.iter().copied().chain(lo).chain(hi);
    let (xmin, xmax) = match (
        xs().fold(f64::INFINITY, f64::min),
        xs().fold(f64::NEG_INFINITY, f64::max),
    ) {
        (a, b) if a.is_finite() && b.is_finite() => (a, b),
        _ => (0.0, 1.0),
    };
    let (x0, x1) = (
        xmin - 0.05 * (xmax - xmin).max(1e-3),
        xmax + 0.05 * (xmax - xmin).max(1e-3),
    );
    let bins = 40;
    let w = (x1 - x0) / bins as f64;
    let mut counts = vec![0usize; bins];
    for x in &v {
        counts[(((x - x0) / w) as usize).min(bins - 1)] += 1;
    }
    let top = counts.iter().copied().max().unwrap_or(1).max(1) as f64 * 1.15;
    let mut steps = vec![(x0, 0.0)];
    for (i, n) in counts.iter().enumerate() {
        let a = x0 + i as f64 * w;
        steps.push((a, *n as f64));
        steps.push((a + w, *n as f64));
    }
    steps.push((x1, 0.0));
    let blue = Rgb(31, 119, 180);
    let red = Rgb(214, 39, 40);
    let green = Rgb(44, 160, 44);
    Figure {
        title: format!(
            "{}: critical jump roll rate over the uncertainty box (delta_e = {:.2} deg)",
            c.aircraft,
            c.delta_e_rad.to_degrees()
        ),
        panels: vec![panel(
            "",
            Axis::linear("critical jump P0 (rad/s)", x0, x1),
            Axis::linear("Monte Carlo samples (count)", 0.0, top),
            std::iter::once(line(
                &format!("{} samples", v.len()),
                steps,
                blue,
                Dash::Solid,
            ))
            .chain(lo.map(|lo| {
                line(
                    "proven lower bound lo",
                    vec![(lo, 0.0), (lo, top)],
                    red,
                    Dash::Dashed,
                )
            }))
            .chain(hi.map(|hi| {
                line(
                    "worst case found hi",
                    vec![(hi, 0.0), (hi, top)],
                    green,
                    Dash::Dotted,
                )
            }))
            .collect(),
        )],
        legend_area: None,
        note: String::new(),
    }
}

/// The clearance map: certified band and Monte Carlo minimum of the critical aileron and roll
/// rate versus delta_e.
pub fn map(runs: &[Run]) -> Figure {
    let de: Vec<f64> = runs
        .iter()
        .map(|r| r.clearance.delta_e_rad.to_degrees())
        .collect();
    let series = |f: &dyn Fn(&Run) -> Option<f64>| -> Vec<(f64, f64)> {
        runs.iter()
            .zip(&de)
            .filter_map(|(r, d)| f(r).map(|v| (*d, v)))
            .collect()
    };
    let range = |pts: &[&Vec<(f64, f64)>]| {
        let ys: Vec<f64> = pts.iter().flat_map(|p| p.iter().map(|q| q.1)).collect();
        let lo = ys.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = ys.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        if lo.is_finite() && hi.is_finite() {
            let m = 0.05 * (hi - lo).max(1e-3);
            (lo - m, hi + m)
        } else {
            (0.0, 1.0)
        }
    };
    let (d0, d1) = (
        de.first().copied().unwrap_or(0.0),
        de.last()
            .copied()
            .unwrap_or(1.0)
            .max(de.first().copied().unwrap_or(0.0) + 1e-3),
    );
    let red = Rgb(214, 39, 40);
    let green = Rgb(44, 160, 44);
    let blue = Rgb(31, 119, 180);
    let mut panels = Vec::new();
    for (k, (title, unit)) in [("critical |delta_a|", "deg"), ("critical P0", "rad/s")]
        .iter()
        .enumerate()
    {
        let b = |r: &Run| {
            if k == 0 {
                r.clearance.critical_delta_a_deg.clone()
            } else {
                r.clearance.critical_p0.clone()
            }
        };
        // A setting without any critical jump in its box (lo infinite) has no point.
        let lo = series(&|r| Some(b(r).lo).filter(|l| l.is_finite()));
        let hi = series(&|r| b(r).hi);
        let mc = series(&|r| {
            if k == 0 {
                r.monte_carlo.min_abs_delta_a_deg
            } else {
                r.monte_carlo.min_p0
            }
        });
        let (y0, y1) = range(&[&lo, &hi, &mc]);
        let mut p = panel(
            &format!("{title} vs delta_e"),
            Axis::linear("delta_e (deg)", d0, d1),
            Axis::linear(format!("{title} ({unit})"), y0, y1),
            vec![
                line("proven lower bound lo", lo, red, Dash::Solid),
                line("worst case found hi", hi, green, Dash::Dashed),
                line("Monte Carlo minimum", mc, blue, Dash::Dotted),
            ],
        );
        p.area = if k == 0 {
            [0.0, 0.0, 1.0, 0.5]
        } else {
            [0.0, 0.5, 1.0, 1.0]
        };
        panels.push(p);
    }
    Figure {
        title: format!(
            "{}: clearance map",
            runs.first().map_or("", |r| &r.clearance.aircraft)
        ),
        panels,
        legend_area: None,
        note: none_note(runs),
    }
}

/// The map's note on the settings whose box has no critical jump at all (proven), which
/// have no point on its lines.
fn none_note(runs: &[Run]) -> String {
    let none: Vec<String> = runs
        .iter()
        .filter(|r| r.clearance.no_critical_jump)
        .map(|r| format!("{:.2}", r.clearance.delta_e_rad.to_degrees()))
        .collect();
    if none.is_empty() {
        String::new()
    } else {
        format!(
            "No critical jump for any aircraft of the box (proven) at delta_e = {} deg",
            none.join(", ")
        )
    }
}
