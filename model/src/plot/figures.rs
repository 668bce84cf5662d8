//! From the paper's data to [`Figure`]s (Figs 1-4 bifurcation diagrams and trims, Figs 5, 6, 10
//! time histories, Figs 7, 8, 11 det K, Fig. 9 zero-sideslip diagram): unit conversion (angles
//! to deg), axis ranges, clipping, line styles (stable solid, unstable dashed, as in the paper),
//! markers and legends.
//!
//! ```
//! use model::plot::figures::clip;
//! use model::plot::Axis;
//!
//! // A polyline that leaves y in [-1, 1] is split where it leaves and where it comes back.
//! let (x, y) = (Axis::linear("x", 0.0, 4.0), Axis::linear("y", -1.0, 1.0));
//! let pieces = clip(&[(0.0, 0.0), (1.0, 2.0), (2.0, 2.0), (3.0, 0.0)], &x, &y);
//! assert_eq!(pieces, [vec![(0.0, 0.0), (0.5, 1.0)], vec![(2.5, 1.0), (3.0, 0.0)]]);
//! ```

use super::data::{
    BifurcationData, Branch, DetKData, SpecialKind, SpecialPoint, State, TimeHistoryData,
    ZeroSideslipData,
};
use super::spec::{
    Axis, Dash, Figure, LegendPlace, Line, Marker, Panel, Rgb, Scale, Shape, TextAt,
};
use super::PlotError;

/// Width of the plotting panels when a legend column is on the right (fraction of the width).
const PANEL_W: f64 = 0.79;
/// The legend column.
const LEGEND_AREA: [f64; 4] = [0.795, 0.0, 1.0, 1.0];

/// Splits a polyline where it leaves the axes' ranges (in drawing coordinates, so an asinh axis
/// is clipped where it is drawn) and at non-finite points; returns the visible pieces.
pub fn clip(points: &[(f64, f64)], x: &Axis, y: &Axis) -> Vec<Vec<(f64, f64)>> {
    let fx = |v: f64| x.scale.forward(v);
    let fy = |v: f64| y.scale.forward(v);
    let (x0, x1) = (fx(x.lo.min(x.hi)), fx(x.lo.max(x.hi)));
    let (y0, y1) = (fy(y.lo.min(y.hi)), fy(y.lo.max(y.hi)));
    let back = |(a, b): (f64, f64)| (x.scale.inverse(a), y.scale.inverse(b));
    let mut out: Vec<Vec<(f64, f64)>> = Vec::new();
    let mut cur: Vec<(f64, f64)> = Vec::new();
    let flush = |cur: &mut Vec<(f64, f64)>, out: &mut Vec<Vec<(f64, f64)>>| {
        if cur.len() >= 2 {
            out.push(std::mem::take(cur));
        } else {
            cur.clear();
        }
    };
    for w in points.windows(2) {
        let (a, b) = ((fx(w[0].0), fy(w[0].1)), (fx(w[1].0), fy(w[1].1)));
        if !(a.0.is_finite() && a.1.is_finite() && b.0.is_finite() && b.1.is_finite()) {
            flush(&mut cur, &mut out);
            continue;
        }
        // Liang-Barsky.
        let (dx, dy) = (b.0 - a.0, b.1 - a.1);
        let (mut t0, mut t1) = (0.0f64, 1.0f64);
        let mut visible = true;
        for (p, q) in [
            (-dx, a.0 - x0),
            (dx, x1 - a.0),
            (-dy, a.1 - y0),
            (dy, y1 - a.1),
        ] {
            if p == 0.0 {
                if q < 0.0 {
                    visible = false;
                }
            } else {
                let t = q / p;
                if p < 0.0 {
                    t0 = t0.max(t);
                } else {
                    t1 = t1.min(t);
                }
            }
        }
        if !visible || t0 > t1 {
            flush(&mut cur, &mut out);
            continue;
        }
        let start = if t0 > 0.0 {
            back((a.0 + t0 * dx, a.1 + t0 * dy))
        } else {
            w[0]
        };
        let end = if t1 < 1.0 {
            back((a.0 + t1 * dx, a.1 + t1 * dy))
        } else {
            w[1]
        };
        if t0 > 0.0 {
            flush(&mut cur, &mut out);
        }
        if cur.is_empty() {
            cur.push(start);
        }
        cur.push(end);
        if t1 < 1.0 {
            flush(&mut cur, &mut out);
        }
    }
    flush(&mut cur, &mut out);
    out
}

/// Lines for one polyline after clipping; only the first piece keeps the label.
fn clipped_lines(points: &[(f64, f64)], x: &Axis, y: &Axis, proto: &Line) -> Vec<Line> {
    clip(points, x, y)
        .into_iter()
        .enumerate()
        .map(|(i, pts)| Line {
            label: if i == 0 { proto.label.clone() } else { None },
            points: pts,
            ..proto.clone()
        })
        .collect()
}

/// Leaves each legend text on the first item (line or marker) carrying it, so that the legend
/// lists it once.
fn dedup_labels<T>(items: &mut [T], label: fn(&mut T) -> &mut Option<String>) {
    let mut seen: Vec<String> = Vec::new();
    for item in items {
        let l = label(item);
        if let Some(t) = l.as_ref() {
            if seen.contains(t) {
                *l = None;
            } else {
                seen.push(t.clone());
            }
        }
    }
}

/// `[lo, hi]` widened by `frac` of its span on both sides (a degenerate range by +-1).
fn padded(lo: f64, hi: f64, frac: f64) -> (f64, f64) {
    if !(lo.is_finite() && hi.is_finite()) {
        return (-1.0, 1.0);
    }
    let span = hi - lo;
    if span <= 1e-12 * lo.abs().max(hi.abs()).max(1e-300) {
        let d = lo.abs().max(1.0) * 0.1;
        return (lo - d, hi + d);
    }
    (lo - frac * span, hi + frac * span)
}

/// The quantiles `lo_q`, `hi_q` of the finite values (nearest rank).
fn quantiles(values: &mut Vec<f64>, lo_q: f64, hi_q: f64) -> Option<(f64, f64)> {
    values.retain(|v| v.is_finite());
    if values.is_empty() {
        return None;
    }
    values.sort_by(f64::total_cmp);
    let at = |q: f64| values[((values.len() - 1) as f64 * q).round() as usize];
    Some((at(lo_q), at(hi_q)))
}

/// Style of one kind of special point: shape, filled, colour, size. The closed-form Hopf point
/// is a small black diamond, drawn after (inside) the square of a continuation's Hopf point at
/// the same place.
fn special_style(kind: SpecialKind) -> (Shape, bool, Rgb, u32) {
    match kind {
        SpecialKind::Fold => (Shape::Circle, true, Rgb::RED, 6),
        SpecialKind::Hopf => (Shape::Square, true, Rgb::ORANGE, 6),
        SpecialKind::HopfClosedForm => (Shape::Diamond, true, Rgb::BLACK, 4),
        SpecialKind::Transcritical => (Shape::Square, false, Rgb::RED, 6),
    }
}

/// A variable of a bifurcation diagram in plot units, and its axis label.
fn state_axis(v: State) -> (&'static str, fn(f64) -> f64) {
    fn id(x: f64) -> f64 {
        x
    }
    fn deg(x: f64) -> f64 {
        x.to_degrees()
    }
    match v {
        State::Alpha => ("angle of attack \u{3b1}\u{2080} (deg)", deg),
        State::Beta => ("sideslip \u{3b2}\u{2080} (deg)", deg),
        State::P => ("roll rate p (rad/s)", id),
        State::Q => ("pitch rate Q\u{2080} (rad/s)", id),
        State::R => ("yaw rate R\u{2080} (rad/s)", id),
    }
}

const DELTA_A_LABEL: &str = "aileron deflection \u{3b4}a (deg)";

/// The aileron range of a diagram, deg: given, or symmetric around 0 covering the folds and
/// transcritical points with 40 % margin (at least +-5 deg), within the data.
fn delta_a_range(d: &BifurcationData) -> (f64, f64) {
    if let Some(r) = d.delta_a_range_deg {
        return r;
    }
    let special = d
        .special
        .iter()
        .filter(|s| !matches!(s.kind, SpecialKind::Hopf | SpecialKind::HopfClosedForm))
        .map(|s| s.point.param.to_degrees().abs())
        .fold(0.0, f64::max);
    let data = d
        .branches
        .iter()
        .flat_map(|b| b.points.iter())
        .map(|p| p.param.to_degrees().abs())
        .filter(|v| v.is_finite())
        .fold(0.0, f64::max);
    let half = (1.4 * special).max(5.0).min(data.max(1e-3));
    let step = super::axis::nice_step(2.0 * half, 8);
    let half = if step > 0.0 {
        (half / step).ceil() * step
    } else {
        half
    };
    (-half, half)
}

/// The y range of a state over the points inside the x range: the 1st-99th percentile span,
/// padded, so that trims blowing up near det A = 0 do not flatten the rest.
fn state_range(d: &BifurcationData, v: State, xr: (f64, f64), conv: fn(f64) -> f64) -> (f64, f64) {
    let mut vals: Vec<f64> = d
        .branches
        .iter()
        .flat_map(|b| b.points.iter())
        .filter(|p| (xr.0..=xr.1).contains(&p.param.to_degrees()))
        .map(|p| conv(p.get(v)))
        .collect();
    let robust = v != State::P;
    let (lo, hi) = if robust {
        quantiles(&mut vals, 0.01, 0.99).unwrap_or((-1.0, 1.0))
    } else {
        quantiles(&mut vals, 0.0, 1.0).unwrap_or((-1.0, 1.0))
    };
    // Keep the special points visible.
    let (lo, hi) = d
        .special
        .iter()
        .filter(|s| (xr.0..=xr.1).contains(&s.point.param.to_degrees()))
        .map(|s| conv(s.point.get(v)))
        .filter(|x| x.is_finite())
        .fold((lo, hi), |(a, b), x| (a.min(x), b.max(x)));
    padded(lo, hi, 0.06)
}

/// Lines of the branches in the (delta_a deg, state) plane: stable solid, unstable dashed.
fn branch_lines(branches: &[Branch], v: State, x: &Axis, y: &Axis, color: Rgb) -> Vec<Line> {
    let (_, conv) = state_axis(v);
    let mut lines = Vec::new();
    for b in branches {
        let mut i = 0;
        while i + 1 < b.points.len() {
            let stable = b.points[i].stable;
            let mut j = i;
            while j + 1 < b.points.len() && b.points[j + 1].stable == stable {
                j += 1;
            }
            // Share the boundary point with the next run so the curve has no gap.
            let end = (j + 1).min(b.points.len() - 1);
            let pts: Vec<(f64, f64)> = b.points[i..=end]
                .iter()
                .map(|p| (p.param.to_degrees(), conv(p.get(v))))
                .collect();
            let proto = Line {
                label: Some(
                    if stable {
                        "stable equilibria"
                    } else {
                        "unstable equilibria"
                    }
                    .into(),
                ),
                points: Vec::new(),
                color,
                dash: if stable { Dash::Solid } else { Dash::Dashed },
                width: 2,
            };
            lines.extend(clipped_lines(&pts, x, y, &proto));
            i = end.max(i + 1);
        }
    }
    lines
}

fn special_markers(
    special: &[SpecialPoint],
    v: State,
    x: &Axis,
    y: &Axis,
    text: bool,
) -> Vec<Marker> {
    let (_, conv) = state_axis(v);
    special
        .iter()
        .filter_map(|s| {
            let (px, py) = (s.point.param.to_degrees(), conv(s.point.get(v)));
            if !(x.contains(px) && y.contains(py)) {
                return None;
            }
            let (shape, filled, color, size) = special_style(s.kind);
            Some(Marker {
                label: Some(s.kind.describe().into()),
                text: if text { s.label.clone() } else { None },
                // On the outer side of a fold of an S-shaped curve.
                text_at: if px < 0.0 {
                    TextAt::AboveLeft
                } else {
                    TextAt::AboveRight
                },
                x: px,
                y: py,
                shape,
                color,
                filled,
                size,
            })
        })
        .collect()
}

fn horizontal(v: f64, x: &Axis, label: &str) -> Line {
    Line {
        label: Some(label.into()),
        points: vec![(x.lo, v), (x.hi, v)],
        color: Rgb::GREY,
        dash: Dash::Dotted,
        width: 2,
    }
}

fn vertical(v: f64, y: &Axis, label: &str, dash: Dash) -> Line {
    Line {
        label: Some(label.into()),
        points: vec![(v, y.lo), (v, y.hi)],
        color: Rgb::GREY,
        dash,
        width: 2,
    }
}

fn check_branches(d: &BifurcationData) -> Result<(), PlotError> {
    if d.branches.iter().all(|b| b.points.len() < 2) {
        return Err(PlotError::NoData(
            "bifurcation diagram without a branch of two or more points",
        ));
    }
    Ok(())
}

/// The (delta_a, state) panel of a diagram.
fn diagram_panel(d: &BifurcationData, v: State, area: [f64; 4], title: &str, text: bool) -> Panel {
    let (xl, xh) = delta_a_range(d);
    let (label, conv) = state_axis(v);
    let (yl, yh) = state_range(d, v, (xl, xh), conv);
    let x = Axis::linear(DELTA_A_LABEL, xl, xh);
    let y = Axis::linear(label, yl, yh);
    let mut lines = branch_lines(&d.branches, v, &x, &y, Rgb::BLUE);
    if v == State::P {
        for p in &d.divergence_p {
            if y.contains(*p) {
                lines.push(horizontal(*p, &x, "det A = 0 (Eq. 5)"));
            }
        }
    }
    // Legend order: stable, unstable, reference lines (a stable sort keeps the drawing order
    // within each kind).
    lines.sort_by_key(|l| l.dash as u8);
    dedup_labels(&mut lines, |l| &mut l.label);
    let mut markers = special_markers(&d.special, v, &x, &y, text);
    markers.sort_by_key(|m| m.shape as u8);
    dedup_labels(&mut markers, |m| &mut m.label);
    Panel {
        title: title.into(),
        area,
        x,
        y,
        lines,
        markers,
        legend: LegendPlace::Figure,
    }
}

/// Figs 1, 2: roll rate versus aileron deflection, stable equilibria solid, unstable dashed,
/// special points marked.
pub fn bifurcation_figure(d: &BifurcationData) -> Result<Figure, PlotError> {
    check_branches(d)?;
    let panel = diagram_panel(d, State::P, [0.0, 0.0, PANEL_W, 1.0], "", true);
    Ok(Figure {
        title: d.title.clone(),
        panels: vec![panel],
        legend_area: Some(LEGEND_AREA),
        note: String::new(),
    })
}

/// Figs 3, 4: the trim states alpha, beta, Q0, R0 versus aileron deflection in a 2 x 2 grid.
pub fn trim_states_figure(d: &BifurcationData) -> Result<Figure, PlotError> {
    check_branches(d)?;
    let cells = [
        (State::Alpha, [0.0, 0.0, 0.5, 0.5], "(a) angle of attack"),
        (State::Beta, [0.5, 0.0, 1.0, 0.5], "(b) sideslip"),
        (State::Q, [0.0, 0.5, 0.5, 1.0], "(c) pitch rate"),
        (State::R, [0.5, 0.5, 1.0, 1.0], "(d) yaw rate"),
    ];
    let panels = cells
        .iter()
        .map(|(v, a, t)| {
            let area = [a[0] * PANEL_W, a[1], a[2] * PANEL_W, a[3]];
            diagram_panel(d, *v, area, t, false)
        })
        .collect();
    Ok(Figure {
        title: d.title.clone(),
        panels,
        legend_area: Some(LEGEND_AREA),
        note: String::new(),
    })
}

/// The asinh unit of a det K plot: a power of ten near the median |det K| over the samples
/// divided by 10, so the bulk of the curve is in the logarithmic part and zero crossings are
/// resolved linearly.
pub fn det_k_unit(d: &DetKData) -> f64 {
    let mut mags: Vec<f64> = d
        .det_k
        .iter()
        .map(|v| v.abs())
        .filter(|v| v.is_finite() && *v > 0.0)
        .collect();
    let med = quantiles(&mut mags, 0.5, 0.5).map_or(1.0, |q| q.0);
    10f64.powf((med / 10.0).log10().round()).clamp(1e-12, 1e12)
}

/// Figs 7, 8, 11: det K versus P0 on an asinh scale, roots marked, poles as dashed lines.
pub fn det_k_figure(d: &DetKData) -> Result<Figure, PlotError> {
    if d.p0.len() < 2 || d.p0.len() != d.det_k.len() {
        return Err(PlotError::NoData(
            "det K curve needs two or more (P0, det K) samples",
        ));
    }
    let unit = det_k_unit(d);
    // y range: the 95th percentile of |det K| away from the poles, up to the next decade.
    let mut mags: Vec<f64> = d.det_k.iter().map(|v| v.abs()).collect();
    let top = quantiles(&mut mags, 0.95, 0.95)
        .map_or(unit * 100.0, |q| q.0)
        .max(unit * 10.0);
    let top = 10f64.powf(top.log10().ceil());
    let (x0, x1) = (d.p0[0], d.p0[d.p0.len() - 1]);
    let x = Axis::linear("trim roll rate P\u{2080} (rad/s)", x0, x1);
    let y = Axis {
        label: "det K (s\u{207b}\u{2074}), asinh scale".into(),
        lo: -top,
        hi: top,
        scale: Scale::Asinh { unit },
    };
    let pts: Vec<(f64, f64)> = d.p0.iter().copied().zip(d.det_k.iter().copied()).collect();
    // Break the curve at the poles (it passes through infinity there).
    let mut pieces: Vec<Vec<(f64, f64)>> = vec![Vec::new()];
    for (i, p) in pts.iter().enumerate() {
        if i > 0
            && d.poles
                .iter()
                .any(|pole| (pts[i - 1].0 - pole) * (p.0 - pole) <= 0.0)
        {
            pieces.push(Vec::new());
        }
        if let Some(last) = pieces.last_mut() {
            last.push(*p);
        }
    }
    let proto = Line {
        label: Some("det K".into()),
        points: Vec::new(),
        color: Rgb::BLUE,
        dash: Dash::Solid,
        width: 2,
    };
    let mut lines: Vec<Line> = vec![Line {
        label: None,
        points: vec![(x0, 0.0), (x1, 0.0)],
        color: Rgb(90, 90, 90),
        dash: Dash::Solid,
        width: 1,
    }];
    for piece in &pieces {
        lines.extend(clipped_lines(piece, &x, &y, &proto));
    }
    for p in d.poles.iter().filter(|p| x.contains(**p)) {
        lines.push(vertical(*p, &y, "poles of det K (d = 0)", Dash::Dashed));
    }
    for p in d.divergence.iter().filter(|p| x.contains(**p)) {
        lines.push(vertical(*p, &y, "det A = 0 (Eq. 5)", Dash::Dotted));
    }
    dedup_labels(&mut lines, |l| &mut l.label);
    let mut markers: Vec<Marker> = d
        .roots
        .iter()
        .filter(|r| x.contains(**r))
        .enumerate()
        .map(|(i, r)| Marker {
            label: Some("roots of det K".into()),
            text: Some(format!("{r:.3}")),
            // Alternate above and below: neighbouring roots can be close (Fig. 8).
            text_at: if i % 2 == 0 {
                TextAt::AboveRight
            } else {
                TextAt::BelowRight
            },
            x: *r,
            y: 0.0,
            shape: Shape::Circle,
            color: Rgb::RED,
            filled: true,
            size: 6,
        })
        .collect();
    dedup_labels(&mut markers, |m| &mut m.label);
    let panel = Panel {
        title: String::new(),
        area: [0.0, 0.0, PANEL_W, 1.0],
        x,
        y,
        lines,
        markers,
        legend: LegendPlace::Figure,
    };
    let (u, t) = (
        super::axis::label(unit, &panel.y, 10),
        super::axis::label(top, &panel.y, 10),
    );
    let s4 = "s\u{207b}\u{2074}";
    let note = format!(
        "Vertical axis: asinh(det K / {u}) scale: linear for |det K| < {u} {s4}, logarithmic \
         beyond; clipped at \u{b1}{t} {s4}."
    );
    Ok(Figure {
        title: d.title.clone(),
        panels: vec![panel],
        legend_area: Some(LEGEND_AREA),
        note,
    })
}

/// Fig. 9: the rudder schedule (left) and the equilibria with the rudder on it (right),
/// stable solid, unstable dashed, the transcritical point an empty square.
pub fn zero_sideslip_figure(d: &ZeroSideslipData) -> Result<Figure, PlotError> {
    check_branches(&d.diagram)?;
    if d.schedule.len() < 2 {
        return Err(PlotError::NoData(
            "rudder schedule needs two or more points",
        ));
    }
    let right = diagram_panel(
        &d.diagram,
        State::P,
        [0.33, 0.0, PANEL_W, 1.0],
        "PSS equilibria with the schedule",
        true,
    );
    let (xl, xh) = (right.x.lo, right.x.hi);
    let sched: Vec<(f64, f64)> = d
        .schedule
        .iter()
        .map(|(a, r)| (a.to_degrees(), r.to_degrees()))
        .filter(|(a, _)| (xl..=xh).contains(a))
        .collect();
    let (lo, hi) = sched
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), (_, r)| {
            (a.min(*r), b.max(*r))
        });
    let (lo, hi) = padded(lo, hi, 0.06);
    let x = Axis::linear(DELTA_A_LABEL, xl, xh);
    let y = Axis::linear("rudder deflection \u{3b4}r (deg)", lo, hi);
    let proto = Line {
        label: Some("rudder schedule".into()),
        points: Vec::new(),
        color: Rgb::GREEN,
        dash: Dash::Solid,
        width: 2,
    };
    let lines = clipped_lines(&sched, &x, &y, &proto);
    let left = Panel {
        title: "aileron-rudder interconnect".into(),
        area: [0.0, 0.0, 0.33, 1.0],
        x,
        y,
        lines,
        markers: Vec::new(),
        legend: LegendPlace::Figure,
    };
    Ok(Figure {
        title: d.diagram.title.clone(),
        panels: vec![left, right],
        legend_area: Some(LEGEND_AREA),
        note: String::new(),
    })
}

/// Figs 5, 6, 10: time histories of a family of runs, one panel per variable.
pub fn time_history_figure(d: &TimeHistoryData) -> Result<Figure, PlotError> {
    if d.runs.is_empty() || d.variables.is_empty() {
        return Err(PlotError::NoData(
            "time histories need at least one run and one variable",
        ));
    }
    let all = || d.runs.iter().chain(d.overlay.iter());
    if all().any(|h| h.t.len() < 2) {
        return Err(PlotError::NoData(
            "a time history has fewer than two samples",
        ));
    }
    let t_end = all().map(|h| h.t[h.t.len() - 1]).fold(0.0, f64::max);
    let n = d.variables.len();
    let n_runs = d.runs.len();
    let mut panels = Vec::new();
    for (k, v) in d.variables.iter().enumerate() {
        // (run index, overlay?, points)
        type Series = (usize, bool, Vec<(f64, f64)>);
        let series: Vec<Series> = d
            .runs
            .iter()
            .enumerate()
            .map(|(i, h)| (i, false, h))
            .chain(d.overlay.iter().enumerate().map(|(i, h)| (i, true, h)))
            .map(|(i, dashed, h)| (i, dashed, h.t.iter().copied().zip(v.series(h)).collect()))
            .collect();
        let (lo, hi) = series
            .iter()
            .flat_map(|(_, _, s)| s.iter().map(|p| p.1))
            .filter(|v| v.is_finite())
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
                (a.min(v), b.max(v))
            });
        let (lo, hi) = padded(lo, hi, 0.04);
        let x = Axis::linear("time t (s)", 0.0, t_end);
        let y = Axis::linear(v.label(), lo, hi);
        let mut lines = Vec::new();
        for (i, dashed, pts) in &series {
            let h = if *dashed { &d.overlay[*i] } else { &d.runs[*i] };
            let label = if *dashed {
                Some(format!("{} (dashed)", h.settings.model.name()))
            } else {
                Some(format!(
                    "\u{3b4}a = {} deg",
                    fmt_deg(h.settings.aileron.final_value())
                ))
            };
            let proto = Line {
                label,
                points: Vec::new(),
                color: if *dashed && *i >= n_runs {
                    Rgb::GREY
                } else {
                    Rgb::sequential(*i, n_runs)
                },
                dash: if *dashed { Dash::Dashed } else { Dash::Solid },
                width: 2,
            };
            lines.extend(clipped_lines(pts, &x, &y, &proto));
        }
        dedup_labels(&mut lines, |l| &mut l.label);
        let h0 = 1.0 / n as f64;
        panels.push(Panel {
            title: String::new(),
            area: [0.0, k as f64 * h0, PANEL_W, (k + 1) as f64 * h0],
            x,
            y,
            lines,
            markers: Vec::new(),
            legend: LegendPlace::Figure,
        });
    }
    Ok(Figure {
        title: d.title.clone(),
        panels,
        legend_area: Some(LEGEND_AREA),
        note: String::new(),
    })
}

/// Degrees with at most two decimals and a typographic minus.
fn fmt_deg(rad: f64) -> String {
    let s = format!("{:.2}", rad.to_degrees());
    let s = s.trim_end_matches('0').trim_end_matches('.').to_string();
    match s.strip_prefix('-') {
        Some(rest) if rest != "0" => format!("\u{2212}{rest}"),
        Some(_) => "0".into(),
        None => s,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn clipping_splits_at_the_range_and_interpolates_the_boundary() {
        let x = Axis::linear("x", 0.0, 10.0);
        let y = Axis::linear("y", -1.0, 1.0);
        let pts = [
            (0.0, 0.0),
            (2.0, 0.5),
            (4.0, 3.0),
            (6.0, 3.0),
            (8.0, 0.0),
            (9.0, f64::NAN),
            (10.0, 0.0),
        ];
        let pieces = clip(&pts, &x, &y);
        assert_eq!(pieces.len(), 2, "{pieces:?}");
        assert_eq!(pieces[0][0], (0.0, 0.0));
        let (bx, by) = pieces[0][pieces[0].len() - 1];
        assert!(
            (by - 1.0).abs() < 1e-12 && (bx - 2.4).abs() < 1e-12,
            "{bx} {by}"
        );
        assert!((pieces[1][0].1 - 1.0).abs() < 1e-12);
        assert_eq!(pieces[1][pieces[1].len() - 1], (8.0, 0.0));
    }

    #[test]
    fn degrees_are_printed_compactly() {
        assert_eq!(fmt_deg(f64::to_radians(-4.0)), "\u{2212}4");
        assert_eq!(fmt_deg(f64::to_radians(-3.5)), "\u{2212}3.5");
        assert_eq!(fmt_deg(0.0), "0");
    }
}
