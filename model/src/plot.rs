//! Figures of the paper for any aircraft, drawn with plotters as SVG and PNG:
//!
//! | function | paper | what |
//! |---|---|---|
//! | [`bifurcation`] | Figs 1, 2 | PSS equilibria, p vs aileron; folds, Hopf points marked |
//! | [`trim_states`] | Figs 3, 4 | alpha, beta, Q0, R0 vs aileron, 2 x 2 |
//! | [`det_k`] | Figs 7, 8, 11 | det K vs P0 (asinh scale), roots and poles marked |
//! | [`zero_sideslip`] | Fig. 9 | rudder schedule, equilibria with it, transcritical point |
//! | [`time_histories`] | Figs 5, 6, 10 | roll rate, sideslip, ... for a family of steps |
//!
//! Stable equilibria are drawn solid and unstable ones dashed, as in the paper.
//!
//! Each function turns plain data ([`data`]) into a [`Figure`] (panels, clipped polylines and
//! markers in plot units: angles in deg, rates in rad/s) and renders it to `<stem>.svg` and
//! `<stem>.png`, with the series drawn in `<stem>.csv` for replotting elsewhere, written
//! atomically; the returned [`Rendered`] holds the files and the figure, so
//! callers and tests see exactly the series that were drawn. [`crate::analysis::trim_curves`] computes the data
//! of Figs 1-4, 7-9 and 11 from the closed-form trims; a continuation can supply the same
//! [`BifurcationData`].
//!
//! Output is deterministic (same bytes on every run and machine): the PNG text is rasterised
//! with DejaVu Sans embedded from `model/assets/` (no system fonts), and nothing depends on
//! time or hashing order.
//!
//! ```
//! use model::plot::{self, DetKData, PlotStyle};
//!
//! // det K = 1 - P0^2 sampled on [0, 2]: one root, at P0 = 1 rad/s.
//! let p0: Vec<f64> = (0..=40).map(|k| f64::from(k) / 20.0).collect();
//! let data = DetKData {
//!     title: "det K = 1 - P0^2".into(),
//!     det_k: p0.iter().map(|p| 1.0 - p * p).collect(),
//!     p0,
//!     roots: vec![1.0],
//!     poles: vec![],
//!     divergence: vec![],
//! };
//! // Written to a scratch directory, SVG only (no PNG), then removed.
//! let dir = std::env::temp_dir().join(format!("model-plot-doc-{}", std::process::id()));
//! std::fs::create_dir_all(&dir).unwrap();
//! let style = PlotStyle { png: false, ..PlotStyle::default() };
//! let r = plot::det_k(&dir.join("fig07_det_k"), &data, &style).unwrap();
//! // The SVG and the CSV of the series drawn; the root is marked on the P0 axis.
//! assert_eq!(r.files.len(), 2);
//! let root = &r.figure.panels[0].markers[0];
//! assert_eq!((root.x, root.y), (1.0, 0.0));
//! std::fs::remove_dir_all(&dir).unwrap();
//! ```

pub mod data;
pub mod figures;
pub mod isoline;
pub mod spec;

mod axis;
mod render;

pub use axis::{nice_step, ticks};
pub use data::{
    BifurcationData, Branch, BranchPoint, DetKData, SpecialKind, SpecialPoint, State,
    TimeHistoryData, Variable, ZeroSideslipData,
};
pub use spec::{Axis, Dash, Figure, LegendPlace, Line, Marker, Panel, Rgb, Scale, Shape, TextAt};

use crate::analysis::diagram::DiagramError;
use crate::analysis::AnalysisError;
use crate::simulation::SimError;
use std::path::{Path, PathBuf};

/// Size and formats of the output.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PlotStyle {
    /// Width, px (200 to 10000).
    pub width: u32,
    /// Height, px (150 to 10000); font sizes scale with it.
    pub height: u32,
    /// Write `<stem>.svg`.
    pub svg: bool,
    /// Write `<stem>.png`.
    pub png: bool,
    /// Embed the font in each SVG (`@font-face` with the TTF as base64, about 1 MB per file) so
    /// that viewers draw exactly the glyphs the layout was measured with. Off by default: the
    /// SVG then names `DejaVu Sans, sans-serif` and viewers without DejaVu Sans substitute
    /// their sans-serif (labels stay in place; their widths may differ slightly).
    pub embed_font: bool,
}

impl Default for PlotStyle {
    /// 1000 x 700 px, SVG and PNG, font not embedded: readable on a laptop screen.
    fn default() -> Self {
        PlotStyle {
            width: 1000,
            height: 700,
            svg: true,
            png: true,
            embed_font: false,
        }
    }
}

/// Why a figure could not be produced.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum PlotError {
    /// Reading or writing a file failed.
    #[error("{}: {message}", path.display())]
    Io {
        /// The file or directory.
        path: PathBuf,
        /// The system's message.
        message: String,
    },
    /// plotters failed to draw.
    #[error("drawing failed: {0}")]
    Draw(String),
    /// The embedded font could not be loaded.
    #[error("the embedded font could not be loaded")]
    Font,
    /// The requested size is out of range.
    #[error("figure size {width} x {height} px is outside 200..=10000 x 150..=10000")]
    Size {
        /// Width, px.
        width: u32,
        /// Height, px.
        height: u32,
    },
    /// The data cannot make a figure.
    #[error("nothing to plot: {0}")]
    NoData(&'static str),
    /// The closed-form analysis failed.
    #[error(transparent)]
    Analysis(AnalysisError),
    /// The closed-form trims or the rudder schedule failed.
    #[error(transparent)]
    Simulation(SimError),
    /// Some of a figure's files could not be written (the others were).
    #[error("{}", failed.iter().map(|(p, m)| format!("cannot write {}: {m}", p.display())).collect::<Vec<_>>().join("; "))]
    Files {
        /// The files written.
        written: Vec<PathBuf>,
        /// Each file that could not be written, and why.
        failed: Vec<(PathBuf, String)>,
    },
}

impl From<DiagramError> for PlotError {
    fn from(e: DiagramError) -> PlotError {
        match e {
            DiagramError::Analysis(e) => PlotError::Analysis(e),
            DiagramError::Simulation(e) => PlotError::Simulation(e),
        }
    }
}

/// A rendered figure: the files written and the figure as drawn.
#[derive(Clone, Debug, PartialEq)]
pub struct Rendered {
    /// `<stem>.svg` and/or `<stem>.png`.
    pub files: Vec<PathBuf>,
    /// The figure (series in plot units, after clipping).
    pub figure: Figure,
}

/// Renders any [`Figure`] to `<stem>.svg` and `<stem>.png` (as selected by `style`) and its
/// plotted series to `<stem>.csv`; returns the files written. Each file is written to a
/// temporary name in the same directory and renamed, so a reader never sees a half-written
/// file; every file that can be written is, and [`PlotError::Files`] names those that could not.
pub fn render(stem: &Path, figure: &Figure, style: &PlotStyle) -> Result<Vec<PathBuf>, PlotError> {
    render::render(stem, figure, style)
}

fn rendered(stem: &Path, figure: Figure, style: &PlotStyle) -> Result<Rendered, PlotError> {
    let files = render::render(stem, &figure, style)?;
    Ok(Rendered { files, figure })
}

/// Figs 1, 2: the bifurcation diagram, roll rate versus aileron deflection.
pub fn bifurcation(
    stem: &Path,
    data: &BifurcationData,
    style: &PlotStyle,
) -> Result<Rendered, PlotError> {
    rendered(stem, figures::bifurcation_figure(data)?, style)
}

/// Figs 3, 4: the trim states alpha, beta, Q0, R0 versus aileron deflection.
pub fn trim_states(
    stem: &Path,
    data: &BifurcationData,
    style: &PlotStyle,
) -> Result<Rendered, PlotError> {
    rendered(stem, figures::trim_states_figure(data)?, style)
}

/// Figs 7, 8, 11: det K versus trim roll rate with roots and poles.
pub fn det_k(stem: &Path, data: &DetKData, style: &PlotStyle) -> Result<Rendered, PlotError> {
    rendered(stem, figures::det_k_figure(data)?, style)
}

/// Fig. 9: the zero-sideslip rudder schedule and the equilibria with it.
pub fn zero_sideslip(
    stem: &Path,
    data: &ZeroSideslipData,
    style: &PlotStyle,
) -> Result<Rendered, PlotError> {
    rendered(stem, figures::zero_sideslip_figure(data)?, style)
}

/// Figs 5, 6, 10: time histories of a family of runs.
pub fn time_histories(
    stem: &Path,
    data: &TimeHistoryData,
    style: &PlotStyle,
) -> Result<Rendered, PlotError> {
    rendered(stem, figures::time_history_figure(data)?, style)
}
