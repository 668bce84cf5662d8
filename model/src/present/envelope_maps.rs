//! The maps of `model envelope --out`: over the grid's speed (across: Mach, or true airspeed in
//! m/s with `--speed`) and altitude (up), one cell per grid
//! point, each drawn as a band of its colour ([`crate::plot`] draws polylines and markers, so a
//! cell is a line as wide as the cell, as thick as its row, which the legend shows as a filled
//! box). The critical aileron and the critical roll rate in eight colour bands, small (the
//! dangerous end) warm and large cool, and the first departure's kind as a region map (an
//! unstable trim at P0 = 0, a jump or a Hopf point within or beyond the aileron's travel,
//! none). Titles name the aircraft; the axes span the grid.
//!
//! On the critical aileron map, the aileron-limit contour is drawn: the line where the margin
//! (aileron limit minus |critical delta_a|) is zero, by marching squares over the grid's
//! margins ([`crate::plot::isoline`]) through the cells whose four corners have a margin (a
//! point without a trim or without a critical jump has none, and the line stops there).
//! On its side of positive margin a full-stick roll reaches the jump. Those points stay
//! marked with a dot as well: the dots say on which side of the line the departures lie, and
//! they still show a departure where the line cannot be drawn (a grid of one row or one
//! column, a point whose neighbours have no margin).

use super::envelope::{beyond_validity, departure_kind};
use crate::envelope::{Envelope, Point, SpeedAxis};
use crate::plot::isoline::{isolines, Field};
use crate::plot::TextAt;
use crate::plot::{Axis, Dash, Figure, LegendPlace, Line, Marker, Panel, PlotStyle, Rgb, Shape};

/// Light grey of cells without the mapped number.
const EMPTY: Rgb = Rgb(215, 215, 215);
/// Dark grey of cells without a trim.
const UNTRIMMED: Rgb = Rgb(110, 110, 110);
/// Purple of cells whose trim at P0 = 0 is unstable (the bare airframe needs its augmentation).
const UNSTABLE_TRIM: Rgb = Rgb(120, 40, 150);
/// The number of colour bands of a heat map.
const BANDS: usize = 8;

/// Pale blue of trimmed, analysed cells without a critical jump (no jump at any aileron: the
/// safe side of a map whose danger is warm).
const NO_JUMP: Rgb = Rgb(200, 225, 245);

/// The distinct values of `xs`, ascending, and half the smallest spacing (`fallback` for one).
fn axis_of(xs: impl Iterator<Item = f64>, fallback: f64) -> (Vec<f64>, f64) {
    let mut v: Vec<f64> = xs.collect();
    v.sort_by(f64::total_cmp);
    v.dedup();
    let half = v
        .windows(2)
        .map(|w| w[1] - w[0])
        .fold(f64::INFINITY, f64::min);
    (
        v,
        if half.is_finite() {
            half / 2.0
        } else {
            fallback
        },
    )
}

/// The value of `p` across the maps: its Mach number or true airspeed, as the grid steps.
fn across(env: &Envelope, p: &Point) -> f64 {
    env.speed_axis.of(p.mach, p.speed_m_s)
}

/// Half a cell's width across a grid of one speed: 0.025 in Mach, 10 m/s in true airspeed.
fn lone_half(env: &Envelope) -> f64 {
    match env.speed_axis {
        SpeedAxis::Mach => 0.025,
        SpeedAxis::TrueAirspeed => 10.0,
    }
}

/// A cell's colour, legend entry and the entry's place in the legend.
pub(super) type Cell = (Rgb, String, usize);

/// A figure of cells: `cell(p)` gives each point's colour and legend entry, the legend ordered
/// by the entries' places.
pub(super) fn cells(
    env: &Envelope,
    title: String,
    style: &PlotStyle,
    cell: &dyn Fn(&Point) -> Cell,
) -> Figure {
    let (speeds, dm) = axis_of(env.points.iter().map(|p| across(env, p)), lone_half(env));
    let (alts, dh) = axis_of(env.points.iter().map(|p| p.altitude_m), 250.0);
    let x = within_grid(Axis::linear(env.speed_axis.label(), 0.0, 0.0), &speeds, dm);
    let y = within_grid(Axis::linear("altitude (m)", 0.0, 0.0), &alts, dh);
    let px_per_m = (style.height as f64 * 0.83 - 10.0) / (y.hi - y.lo);
    // A pixel and a half across (the plot area is over 60 % of the figure's width), so that
    // neighbouring cells overlap rather than leave a gap where their ends round apart.
    let overlap = 1.5 * (x.hi - x.lo) / (style.width as f64 * 0.6);
    let mut painted: Vec<(usize, &Point, Rgb, String)> = env
        .points
        .iter()
        .map(|p| {
            let (color, label, place) = cell(p);
            (place, p, color, label)
        })
        .collect();
    painted.sort_by_key(|c| c.0);
    let mut seen = std::collections::BTreeSet::new();
    let lines = painted
        .into_iter()
        .map(|(_, p, color, label)| {
            // The cell's rows within the axis: an edge row shows its inner half.
            let (lo, hi) = ((p.altitude_m - dh).max(y.lo), (p.altitude_m + dh).min(y.hi));
            let at = (lo + hi) / 2.0;
            // Two pixels more than a row, so that neighbouring rows overlap rather than leave
            // a gap.
            let width = ((hi - lo) * px_per_m).clamp(1.0, 400.0).ceil() as u32 + 2;
            Line {
                label: seen.insert(label.clone()).then_some(label),
                points: vec![
                    (across(env, p) - dm - overlap, at),
                    (across(env, p) + dm + overlap, at),
                ],
                color,
                dash: Dash::Band,
                width,
            }
        })
        .collect();
    Figure {
        title,
        panels: vec![Panel {
            title: String::new(),
            area: [0.0, 0.0, 0.72, 1.0],
            x,
            y,
            lines,
            markers: Vec::new(),
            legend: LegendPlace::Figure,
        }],
        legend_area: Some([0.72, 0.0, 1.0, 1.0]),
        note: format!("elevator: {}", env.elevator),
    }
}

/// `axis` spanning the grid's values `vs` (ascending): from the first to the last, so that no
/// axis runs beyond the grid (an altitude below sea level); the cells at the edges show half.
/// A grid of one value gets `half` either side of it.
fn within_grid(axis: Axis, vs: &[f64], half: f64) -> Axis {
    let (lo, hi) = (vs[0], vs[vs.len() - 1]);
    if hi > lo {
        Axis { lo, hi, ..axis }
    } else {
        Axis {
            lo: lo - half,
            hi: hi + half,
            ..axis
        }
    }
}

/// The colour and legend entry of a point without the mapped number, one entry per reason:
/// no critical jump (analysed: no jump at any aileron), not analysed (the analysis failed),
/// untrimmable.
pub(super) fn missing(p: &Point) -> Cell {
    match (p.trimmed, p.route) {
        (true, Some(_)) => (NO_JUMP, "no critical jump".to_string(), 100),
        (true, None) => (EMPTY, "not analysed".to_string(), 101),
        (false, _) => (UNTRIMMED, "untrimmable".to_string(), 102),
    }
}

/// A heat map of `value` (in `unit`) in eight bands from its smallest to its largest value,
/// the smallest warm (red) and the largest cool (blue): the mapped numbers say how far a roll
/// is from its jump, so small is the dangerous end.
pub fn heat_map(
    env: &Envelope,
    what: &str,
    unit: &str,
    style: &PlotStyle,
    value: &dyn Fn(&Point) -> Option<f64>,
) -> Figure {
    let vs: Vec<f64> = env.points.iter().filter_map(value).collect();
    let lo = vs.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = vs.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let step = ((hi - lo) / BANDS as f64).max(1e-9);
    let band = |v: f64| (((v - lo) / step) as usize).min(BANDS - 1);
    let title = format!("{}: {what} over the envelope", env.aircraft);
    cells(env, title, style, &|p| match value(p) {
        Some(v) => {
            let k = band(v);
            let (a, b) = (lo + k as f64 * step, lo + (k + 1) as f64 * step);
            (
                Rgb::sequential(BANDS - 1 - k, BANDS),
                format!("{a:.2} to {b:.2} {unit}"),
                k,
            )
        }
        None => missing(p),
    })
}

/// The critical aileron map, with the aileron-limit contour drawn and the points where a
/// full-stick roll reaches the jump marked.
pub fn critical_aileron(env: &Envelope, style: &PlotStyle) -> Figure {
    let mut f = heat_map(env, "critical |delta_a|", "deg", style, &|p| {
        p.critical.as_ref().map(|c| c.delta_a_deg.abs())
    });
    let limit = env.points.iter().find_map(|p| p.aileron_limit_deg);
    let contour = format!(
        "aileron limit{}",
        limit.map_or(String::new(), |l| format!(" ({l:.2} deg)"))
    );
    let lines = isolines(&margins(env), 0.0);
    f.panels[0]
        .lines
        .extend(lines.into_iter().enumerate().map(|(k, points)| Line {
            label: (k == 0).then(|| contour.clone()),
            points,
            color: Rgb::BLACK,
            dash: Dash::Solid,
            width: 3,
        }));
    let mut first = true;
    for p in env
        .points
        .iter()
        .filter(|p| p.margin_deg.is_some_and(|m| m >= 0.0))
    {
        f.panels[0].markers.push(Marker {
            label: std::mem::take(&mut first).then(|| "full-stick roll jumps".to_string()),
            text: None,
            text_at: TextAt::AboveRight,
            x: across(env, p),
            y: p.altitude_m,
            shape: Shape::Circle,
            color: Rgb::BLACK,
            filled: true,
            size: 2,
        });
    }
    f
}

/// The margin to the aileron limit over the grid (speed across, altitude up), missing where a
/// point has none or the grid has no point.
fn margins(env: &Envelope) -> Field {
    let (xs, _) = axis_of(env.points.iter().map(|p| across(env, p)), 0.0);
    let (ys, _) = axis_of(env.points.iter().map(|p| p.altitude_m), 0.0);
    let mut values = vec![None; xs.len() * ys.len()];
    for p in &env.points {
        let i = xs.iter().position(|&x| x == across(env, p));
        let j = ys.iter().position(|&y| y == p.altitude_m);
        if let (Some(i), Some(j)) = (i, j) {
            values[j * xs.len() + i] = p.margin_deg;
        }
    }
    Field { xs, ys, values }
}

/// Pale red of cells whose first departure is a jump beyond the aileron's travel.
const JUMP_BEYOND: Rgb = Rgb(240, 170, 170);
/// Pale orange of cells whose first departure is a Hopf point beyond the aileron's travel.
const HOPF_BEYOND: Rgb = Rgb(250, 215, 160);

/// Lavender of cells whose first departure lies outside the aircraft's validity range.
const BEYOND_VALIDITY: Rgb = Rgb(200, 185, 225);

/// Whether the first departure of `p` needs more aileron than its limit (a full-stick roll
/// does not reach it, which the map must not paint as the departure a pilot meets); `None`
/// when the model gives no aileron limit.
fn beyond_the_stick(p: &Point) -> Option<bool> {
    match (&p.first_departure, p.aileron_limit_deg) {
        (Some(d), Some(limit)) => Some(d.delta_a_deg.abs() > limit),
        _ => None,
    }
}

/// The region map of the first departure's kind, an unstable trim at P0 = 0 its own class,
/// a jump or Hopf point beyond the aileron's travel drawn pale, apart from those a full-stick
/// roll reaches, and one whose trim lies outside the validity range a class of its own: the
/// linear aerodynamics' departure, which the aircraft's own need not share.
pub fn departure_regions(env: &Envelope, style: &PlotStyle) -> Figure {
    let title = format!("{}: first departure on the primary branch", env.aircraft);
    cells(
        env,
        title,
        style,
        &|p| match (departure_kind(p), beyond_the_stick(p)) {
            _ if beyond_validity(p) => (
                BEYOND_VALIDITY,
                "jump or Hopf outside the validity range".to_string(),
                7,
            ),
            ("unstable_trim", _) => (
                UNSTABLE_TRIM,
                "unstable trim (bare airframe)".to_string(),
                0,
            ),
            ("jump", Some(false)) => (Rgb::RED, "jump within the stick's travel".to_string(), 1),
            ("hopf", Some(false)) => (Rgb::ORANGE, "Hopf within the stick's travel".to_string(), 2),
            ("jump", Some(true)) => (JUMP_BEYOND, "jump beyond the stick's travel".to_string(), 3),
            ("hopf", Some(true)) => (HOPF_BEYOND, "Hopf beyond the stick's travel".to_string(), 4),
            ("jump", None) => (Rgb::RED, "jump (no aileron limit known)".to_string(), 5),
            ("hopf", None) => (Rgb::ORANGE, "Hopf (no aileron limit known)".to_string(), 6),
            ("none", _) => (Rgb::GREEN, "none: stable throughout".to_string(), 8),
            _ => missing(p),
        },
    )
}

/// Every map with its file stem.
pub fn maps(env: &Envelope, style: &PlotStyle) -> Vec<(&'static str, Figure)> {
    vec![
        ("critical_aileron", critical_aileron(env, style)),
        (
            "critical_roll_rate",
            heat_map(env, "critical jump roll rate P0", "rad/s", style, &|p| {
                p.critical.as_ref().map(|c| c.p0)
            }),
        ),
        ("first_departure", departure_regions(env, style)),
    ]
}
