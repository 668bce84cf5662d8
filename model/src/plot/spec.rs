//! A figure as plain data (any of Figs 1-11 of the paper): panels with axes, polylines and
//! markers in plot units (deg, rad/s, ...). The figure builders of [`super::figures`] produce it
//! from the paper's data; [`super::render()`] draws it with plotters. Tests compare the series
//! here with what the library computes.
//!
//! ```
//! use model::plot::{Axis, Dash, Figure, LegendPlace, Line, Panel, Rgb};
//!
//! let line = Line {
//!     label: Some("det K".into()),
//!     points: vec![(0.0, 1.0), (1.0, 0.0)],
//!     color: Rgb::BLUE,
//!     dash: Dash::Solid,
//!     width: 2,
//! };
//! let panel = Panel {
//!     title: String::new(),
//!     area: [0.0, 0.0, 1.0, 1.0],
//!     x: Axis::linear("P0 (rad/s)", 0.0, 1.0),
//!     y: Axis::linear("det K", -1.0, 1.0),
//!     lines: vec![line],
//!     markers: vec![],
//!     legend: LegendPlace::None,
//! };
//! let fig = Figure {
//!     title: "t".into(),
//!     panels: vec![panel],
//!     legend_area: None,
//!     note: String::new(),
//! };
//! // One CSV row per point drawn, with its panel, series, legend entry and axis labels.
//! let csv = fig.to_csv();
//! let rows: Vec<&str> = csv.lines().collect();
//! assert_eq!(rows[0], "panel,panel_title,series,kind,label,x_axis,y_axis,x,y");
//! assert_eq!(
//!     rows[1..],
//!     ["1,,1,line,det K,P0 (rad/s),det K,0,1", "1,,1,line,det K,P0 (rad/s),det K,1,0"]
//! );
//! ```

use serde::Serialize;

/// An RGB colour.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct Rgb(pub u8, pub u8, pub u8);

impl Rgb {
    /// Black.
    pub const BLACK: Rgb = Rgb(0, 0, 0);
    /// Mid grey for reference lines.
    pub const GREY: Rgb = Rgb(120, 120, 120);
    /// Blue of the equilibrium branches.
    pub const BLUE: Rgb = Rgb(31, 86, 160);
    /// Red of the special points.
    pub const RED: Rgb = Rgb(200, 30, 40);
    /// Green of the second data set (e.g. the rudder schedule).
    pub const GREEN: Rgb = Rgb(30, 130, 60);
    /// Orange.
    pub const ORANGE: Rgb = Rgb(230, 120, 20);

    /// Colour `i` of `n` on a sequential dark-blue to orange scale (families of runs ordered
    /// by aileron: the ordering stays readable).
    pub fn sequential(i: usize, n: usize) -> Rgb {
        // Anchors of a perceptually ordered scale (dark blue, teal, green, olive, orange, red).
        const ANCHORS: [(f64, f64, f64); 6] = [
            (38.0, 50.0, 140.0),
            (20.0, 120.0, 160.0),
            (40.0, 160.0, 90.0),
            (150.0, 160.0, 30.0),
            (235.0, 130.0, 20.0),
            (200.0, 30.0, 40.0),
        ];
        let s = if n <= 1 {
            0.0
        } else {
            i as f64 / (n - 1) as f64
        } * (ANCHORS.len() - 1) as f64;
        let k = (s.floor() as usize).min(ANCHORS.len() - 2);
        let f = s - k as f64;
        let (a, b) = (ANCHORS[k], ANCHORS[k + 1]);
        let mix = |x: f64, y: f64| (x + (y - x) * f).round().clamp(0.0, 255.0) as u8;
        Rgb(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
    }
}

/// Scale of an axis.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub enum Scale {
    /// Linear.
    Linear,
    /// `asinh(v / unit)`: linear within about +-unit of zero, logarithmic beyond, for
    /// quantities with poles (det K, Figs 7, 8, 11). Ticks at 0 and +-unit * 10^k.
    Asinh {
        /// The value where the scale changes from linear to logarithmic.
        unit: f64,
    },
}

impl Scale {
    /// The value on the (linear) drawing scale.
    pub fn forward(self, v: f64) -> f64 {
        match self {
            Scale::Linear => v,
            Scale::Asinh { unit } => (v / unit).asinh(),
        }
    }

    /// The inverse of [`Scale::forward`].
    pub fn inverse(self, t: f64) -> f64 {
        match self {
            Scale::Linear => t,
            Scale::Asinh { unit } => unit * t.sinh(),
        }
    }
}

/// An axis: label with unit, range in plot units, scale.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Axis {
    /// Label, with the unit in parentheses.
    pub label: String,
    /// Lower end, plot units.
    pub lo: f64,
    /// Upper end, plot units.
    pub hi: f64,
    /// Scale.
    pub scale: Scale,
}

impl Axis {
    /// A linear axis.
    pub fn linear(label: impl Into<String>, lo: f64, hi: f64) -> Axis {
        Axis {
            label: label.into(),
            lo,
            hi,
            scale: Scale::Linear,
        }
    }

    /// Whether `v` lies within the range.
    pub fn contains(&self, v: f64) -> bool {
        v >= self.lo.min(self.hi) && v <= self.lo.max(self.hi)
    }
}

/// Dash pattern of a line.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum Dash {
    /// Solid.
    Solid,
    /// Dashed (unstable equilibria, second model).
    Dashed,
    /// Dotted (reference lines).
    Dotted,
    /// Solid, painting an area rather than tracing a curve (a cell of a map, as wide as the
    /// cell): the legend shows its colour as a filled box.
    Band,
}

/// A polyline in plot units, already clipped to its panel's ranges.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Line {
    /// Legend entry (only the first line of a kind carries one).
    pub label: Option<String>,
    /// Points (x, y) in plot units.
    pub points: Vec<(f64, f64)>,
    /// Colour.
    pub color: Rgb,
    /// Dash pattern.
    pub dash: Dash,
    /// Stroke width, px.
    pub width: u32,
}

/// Marker shape.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum Shape {
    /// Circle.
    Circle,
    /// Square.
    Square,
    /// Upward triangle.
    Triangle,
    /// Diamond.
    Diamond,
}

/// A marked point.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Marker {
    /// Legend entry (only the first marker of a kind carries one).
    pub label: Option<String>,
    /// Text drawn next to the marker (e.g. the paper's a, b, c, d).
    pub text: Option<String>,
    /// Where the text goes relative to the marker.
    pub text_at: TextAt,
    /// Position, plot units.
    pub x: f64,
    /// Position, plot units.
    pub y: f64,
    /// Shape.
    pub shape: Shape,
    /// Colour.
    pub color: Rgb,
    /// Filled or outlined.
    pub filled: bool,
    /// Size (radius), px.
    pub size: u32,
}

impl Marker {
    /// What tells markers apart in a legend: shape, fill, colour and size.
    fn style(&self) -> (Shape, bool, Rgb, u32) {
        (self.shape, self.filled, self.color, self.size)
    }
}

/// Placement of a marker's text.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum TextAt {
    /// Above, to the right.
    AboveRight,
    /// Above, to the left.
    AboveLeft,
    /// Below, to the right.
    BelowRight,
    /// Below, to the left.
    BelowLeft,
}

/// Where a panel's legend goes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum LegendPlace {
    /// No legend.
    None,
    /// Inside the plotting area, upper left.
    UpperLeft,
    /// Inside, upper right.
    UpperRight,
    /// Inside, lower left.
    LowerLeft,
    /// Inside, lower right.
    LowerRight,
    /// In the figure's legend column ([`Figure::legend_area`]).
    Figure,
}

/// One chart of a figure.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Panel {
    /// Caption above the chart (may be empty).
    pub title: String,
    /// Position in the figure below its title: (x0, y0, x1, y1) as fractions of width and
    /// height.
    pub area: [f64; 4],
    /// Horizontal axis.
    pub x: Axis,
    /// Vertical axis.
    pub y: Axis,
    /// Lines, drawn in order.
    pub lines: Vec<Line>,
    /// Markers, drawn after the lines.
    pub markers: Vec<Marker>,
    /// Legend placement.
    pub legend: LegendPlace,
}

/// A complete figure.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Figure {
    /// Title at the top.
    pub title: String,
    /// Panels.
    pub panels: Vec<Panel>,
    /// Area (as in [`Panel::area`]) of the legend column collecting the entries of panels with
    /// [`LegendPlace::Figure`].
    pub legend_area: Option<[f64; 4]>,
    /// Footnote below the panels (e.g. the scale of an axis), may be empty.
    pub note: String,
}

impl Figure {
    /// The plotted data as CSV, one row per point in drawing order, for replotting in other
    /// tools: `panel` (number, from 1) and `panel_title`, `series` (line or marker number
    /// within the panel, from 1), `kind` (`line` or `marker`), `label` (legend entry or marker
    /// text, may be empty; a marker without either carries the legend entry of the markers of
    /// its style in the panel, so that every marked point says what it is), `x_axis` and
    /// `y_axis` (the axis labels, with their units), `x`, `y` (plot units, after clipping:
    /// exactly what was drawn).
    pub fn to_csv(&self) -> String {
        use std::fmt::Write;
        let mut s = String::from("panel,panel_title,series,kind,label,x_axis,y_axis,x,y\n");
        for (i, p) in self.panels.iter().enumerate() {
            let head = |k: usize, kind: &str, label: &str| {
                format!(
                    "{},{},{},{kind},{},{},{}",
                    i + 1,
                    csv_field(&p.title),
                    k + 1,
                    csv_field(label),
                    csv_field(&p.x.label),
                    csv_field(&p.y.label)
                )
            };
            for (k, l) in p.lines.iter().enumerate() {
                let h = head(k, "line", l.label.as_deref().unwrap_or(""));
                for (x, y) in &l.points {
                    let _ = writeln!(s, "{h},{x},{y}");
                }
            }
            let legend = |m: &Marker| {
                p.markers
                    .iter()
                    .find(|o| o.label.is_some() && o.style() == m.style())
                    .and_then(|o| o.label.as_deref())
            };
            for (k, m) in p.markers.iter().enumerate() {
                let label = (m.text.as_deref().or(m.label.as_deref()))
                    .or_else(|| legend(m))
                    .unwrap_or("");
                let _ = writeln!(s, "{},{},{}", head(k, "marker", label), m.x, m.y);
            }
        }
        s
    }
}

/// A CSV field, quoted when it holds a comma, quote or line break (RFC 4180).
fn csv_field(v: &str) -> String {
    if v.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", v.replace('"', "\"\""))
    } else {
        v.to_string()
    }
}

impl Panel {
    /// Every point of every line, in drawing order.
    pub fn points(&self) -> impl Iterator<Item = &(f64, f64)> {
        self.lines.iter().flat_map(|l| l.points.iter())
    }
}
