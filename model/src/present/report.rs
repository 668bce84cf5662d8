//! `model report`: every result of the paper for one aircraft, as a folder that reads as a
//! report — the numbers of `analyze`, the special points of the continuation, the simulated
//! jumps, and Figs 1-11 (SVG and PNG) embedded in `summary.md` (also `summary.json`).
//!
//! Data flow: [`crate::analysis`] and [`crate::continuation`] give the numbers and the
//! branches of Figs 1-4 and 9; the closed-form det K curves give Figs 7, 8 and 11;
//! [`crate::simulation`] gives the time histories of Figs 5, 6 and 10 and the simulated
//! jump; [`crate::plot`] draws.
//!
//! ```
//! use model::present::report::ReportSettings;
//!
//! // The report's simulations stay within +-30 deg of aileron unless told otherwise.
//! let settings = ReportSettings::new(2f64.to_radians());
//! assert_eq!(settings.max_abs_delta_a(), 30f64.to_radians());
//! ```

mod markdown;
mod sections;

pub use sections::bifurcation_data;

use crate::aircraft::Aircraft;
use crate::analysis::{analyze, Analysis, AnalysisError};
use crate::continuation::{self, ContinuationError};
use crate::plot::{PlotError, PlotStyle};
use crate::simulation::SimError;
use sections::{rows, Notes, Sections};
use serde::Serialize;
use std::path::{Path, PathBuf};

/// Why a report could not be produced.
#[derive(Debug, thiserror::Error)]
pub enum ReportError {
    /// The closed-form analysis failed.
    #[error(transparent)]
    Analysis(#[from] AnalysisError),
    /// The continuation failed.
    #[error(transparent)]
    Continuation(#[from] ContinuationError),
    /// A simulation failed.
    #[error(transparent)]
    Simulation(#[from] SimError),
    /// A figure failed.
    #[error(transparent)]
    Plot(#[from] PlotError),
    /// The aileron range of the simulations is not a positive number.
    #[error("max_abs_delta_a = {0} rad: expected a positive finite aileron range")]
    AileronRange(f64),
    /// Writing the summary failed.
    #[error("cannot write {}: {source}", path.display())]
    Io {
        /// The file.
        path: PathBuf,
        /// The cause.
        source: std::io::Error,
    },
}

/// One figure of the report.
#[derive(Clone, Debug, Serialize)]
pub struct FigureEntry {
    /// The paper's figure numbers it reproduces.
    pub paper: &'static str,
    /// Caption.
    pub caption: String,
    /// Files written (relative to the report folder).
    pub files: Vec<String>,
}

/// The simulated jump of an aileron-step sweep against the criterion's fold.
#[derive(Clone, Debug, Serialize)]
pub struct SimulatedJump {
    /// `pss` or `seventh-order`.
    pub model: &'static str,
    /// Aileron step at which the steady roll rate jumps, deg (None: no jump in the sweep).
    pub delta_a_deg: Option<f64>,
    /// The criterion's first fold, deg.
    pub criterion_deg: f64,
}

/// A special point of a continuation, in report units.
#[derive(Clone, Debug, Serialize)]
pub struct SpecialRow {
    /// fold, hopf or branch.
    pub kind: &'static str,
    /// Aileron deflection, deg.
    pub delta_a_deg: f64,
    /// Roll rate, rad/s.
    pub p: f64,
    /// Hopf frequency, rad/s.
    pub frequency: Option<f64>,
}

/// Everything in `summary.json`.
#[derive(Clone, Debug, Serialize)]
pub struct Summary {
    /// The numbers of `model analyze`.
    pub analysis: Analysis,
    /// Special points of the unconstrained continuation (Figs 1-2), p >= 0.
    pub special_points: Vec<SpecialRow>,
    /// Special points of the zero-sideslip continuation (Fig. 9), p >= 0.
    pub zero_sideslip_special_points: Vec<SpecialRow>,
    /// Simulated jumps (Figs 5-6).
    pub simulated_jumps: Vec<SimulatedJump>,
    /// The figures.
    pub figures: Vec<FigureEntry>,
    /// Sections that could not be computed for this aircraft, with the reason.
    pub skipped: Vec<String>,
    /// Files that could not be written, with the reason (the command then fails).
    pub failed_files: Vec<FailedFile>,
}

/// A file of the report that could not be written.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct FailedFile {
    /// The file.
    pub path: PathBuf,
    /// Why (the system's message).
    pub reason: String,
}

/// What to draw.
#[derive(Clone, Copy, Debug)]
pub struct ReportSettings {
    /// Elevator deflection, rad.
    pub delta_e: f64,
    /// Figure size and formats.
    pub style: PlotStyle,
    /// Write `summary.md` and `summary.json` (false: figures only, `model plot`).
    pub summary: bool,
    /// Largest aileron deflection simulated, |delta_a| in rad (steps of Figs 5, 6 and 10 and
    /// the jump sweep stay within it); `None`: [`ReportSettings::DEFAULT_MAX_ABS_DELTA_A`].
    /// What lies beyond is named in [`Summary::skipped`].
    pub max_abs_delta_a: Option<f64>,
}

impl ReportSettings {
    /// Default aileron range of the simulations, 30 deg (in rad): beyond the travel of the
    /// ailerons of any aircraft of this class, and wide enough for the paper's A (fold at
    /// -3.85 deg) and B.
    pub const DEFAULT_MAX_ABS_DELTA_A: f64 = 30.0 * std::f64::consts::PI / 180.0;

    /// `delta_e` (rad), default style, with the summary, default aileron range.
    pub fn new(delta_e: f64) -> ReportSettings {
        ReportSettings {
            delta_e,
            style: PlotStyle::default(),
            summary: true,
            max_abs_delta_a: None,
        }
    }

    /// The aileron range of the simulations, rad.
    pub fn max_abs_delta_a(&self) -> f64 {
        self.max_abs_delta_a
            .unwrap_or(Self::DEFAULT_MAX_ABS_DELTA_A)
    }
}

/// Produces the report for `aircraft` in `out`; `progress(fraction)` is called as it goes.
pub fn report(
    aircraft: &Aircraft,
    out: &Path,
    settings: &ReportSettings,
    progress: &mut dyn FnMut(f64),
) -> Result<Summary, ReportError> {
    let de = settings.delta_e;
    // The simulations stay within the aircraft's aileron limit when its file gives one.
    let max_da = match (settings.max_abs_delta_a, aircraft.limits.aileron_deg) {
        (None, Some(limit)) => limit.to_radians(),
        _ => settings.max_abs_delta_a(),
    };
    if !(max_da.is_finite() && max_da > 0.0) {
        return Err(ReportError::AileronRange(max_da));
    }
    crate::files::create_dir_all(out).map_err(|source| ReportError::Io {
        path: out.to_path_buf(),
        source,
    })?;
    // Temporaries of a killed run, also of files this run may not write again.
    crate::files::remove_stale_temporaries_in(out);
    let analysis = analyze(aircraft, de)?;
    progress(0.05);
    // Each section that cannot be computed for this aircraft is skipped with its reason; the
    // rest of the report still appears.
    let mut sections = Sections {
        aircraft,
        out,
        style: &settings.style,
        de,
        max_da,
        analysis: &analysis,
        notes: Notes::default(),
        figures: Vec::new(),
    };
    let cont = continuation::Settings {
        delta_e: de,
        ..continuation::Settings::default()
    };
    let diagram = sections.bifurcation_figures(&cont);
    progress(0.3);
    sections.det_k_figures();
    progress(0.4);
    let zs = sections.zero_sideslip_figure(&cont);
    progress(0.5);
    let simulated_jumps = sections.simulations(progress);
    let partial: Vec<FigureEntry> = sections.notes.partial.iter().map(|(paper, files)| {
        sections.fig(
            paper,
            "Incomplete: some files of this figure could not be written (listed under Files that could not be written).".into(),
            files,
        )
    }).collect();
    let Sections {
        mut figures, notes, ..
    } = sections;
    figures.extend(partial);
    let mut summary = Summary {
        special_points: diagram.as_ref().map(rows).unwrap_or_default(),
        zero_sideslip_special_points: zs.as_ref().map(rows).unwrap_or_default(),
        analysis,
        simulated_jumps,
        figures,
        skipped: notes.skipped,
        failed_files: notes.failed,
    };
    if settings.summary {
        write_summary(&mut summary, out, de);
    }
    progress(1.0);
    Ok(summary)
}

/// Writes `summary.json` and `summary.md` into `out`; a file that cannot be written is named in
/// [`Summary::failed_files`].
fn write_summary(summary: &mut Summary, out: &Path, de: f64) {
    let json = serde_json::to_string_pretty(&*summary).unwrap_or_default() + "\n";
    let md = markdown::markdown(summary, de);
    for (file, text) in [("summary.json", json), ("summary.md", md)] {
        let path = out.join(file);
        if let Err(e) = crate::files::write_atomic(&path, text.as_bytes()) {
            summary.failed_files.push(FailedFile {
                path,
                reason: e.to_string(),
            });
        }
    }
}
