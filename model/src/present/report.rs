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
//! use model::present::report::{fixed, list, ReportSettings};
//!
//! // Numbers as the summary prints them: never "-0.0000", and "none" for an empty list.
//! assert_eq!(fixed(-0.00001, 4), "0.0000");
//! assert_eq!(list(&[1.23456, 2.5], 2, "rad/s"), "1.23, 2.50 rad/s");
//! assert_eq!(list(&[], 6, "rad/s"), "none");
//! // The report's simulations stay within +-30 deg of aileron unless told otherwise.
//! let settings = ReportSettings::new(2f64.to_radians());
//! assert_eq!(settings.max_abs_delta_a(), 30f64.to_radians());
//! ```

use crate::aircraft::Aircraft;
use crate::analysis::{analyze, Analysis, AnalysisError, DeparturePoint, HopfPoint, JumpPoint};
use crate::continuation::{self, continue_equilibria, ContinuationError, Diagram};
use crate::plot::{
    self, closed_form, BifurcationData, BranchPoint, PlotError, PlotStyle, SpecialKind,
    SpecialPoint, TimeHistoryData, Variable, ZeroSideslipData,
};
use crate::simulation::{
    jump_sweep, Model, Rudder, SimError, SimSettings, Simulator, SweepSettings, TimeHistory,
};
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

/// What could not be done: sections not computed for this aircraft, files not written.
#[derive(Default)]
struct Notes {
    skipped: Vec<String>,
    failed: Vec<FailedFile>,
    /// Figures of which some files were written and some not: (paper figures, files written).
    partial: Vec<(&'static str, Vec<PathBuf>)>,
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

/// The steps of `steps` within `max` (rad); those beyond are named in `notes.skipped`. When
/// none is within, the default family ([`family`] of `None`, within `max`) instead.
fn within(notes: &mut Notes, what: &str, steps: Vec<f64>, max: f64) -> Vec<f64> {
    let (inside, beyond): (Vec<f64>, Vec<f64>) = steps.into_iter().partition(|d| d.abs() <= max);
    if beyond.is_empty() {
        return inside;
    }
    let (inside, instead) = if inside.is_empty() {
        let default: Vec<f64> = family(None)
            .into_iter()
            .filter(|d| d.abs() <= max)
            .collect();
        let text = format!("; steps of {} deg instead", degrees(&default));
        (default, text)
    } else {
        (inside, String::new())
    };
    notes.skipped.push(format!(
        "{what}: aileron steps of {} deg not simulated (beyond the aileron range of +-{:.1} \
         deg){instead}",
        degrees(&beyond),
        max.to_degrees()
    ));
    inside
}

fn to_plot(d: &Diagram, title: String, divergence: &[f64]) -> BifurcationData {
    BifurcationData {
        title,
        branches: d.branches.clone(),
        special: d
            .special_points
            .iter()
            .map(|s| SpecialPoint {
                kind: match s.kind {
                    continuation::SpecialKind::Fold => SpecialKind::Fold,
                    continuation::SpecialKind::Hopf => SpecialKind::Hopf,
                    continuation::SpecialKind::Branch => SpecialKind::Transcritical,
                },
                point: BranchPoint {
                    param: s.param,
                    alpha: s.alpha,
                    beta: s.beta,
                    p: s.p,
                    q: s.q,
                    r: s.r,
                    stable: false,
                },
                label: None,
            })
            .collect(),
        divergence_p: divergence.iter().flat_map(|p| [*p, -*p]).collect(),
        delta_a_range_deg: Some((-0.8f64.to_degrees(), 0.8f64.to_degrees())),
    }
}

/// The data of Figs 1-4 in the report: the continuation's branches and special points, the
/// closed-form Hopf points of the analysis ([`closed_form::hopf_points`]) and its divergence
/// roll rates.
pub fn bifurcation_data(diagram: &Diagram, analysis: &Analysis, name: &str) -> BifurcationData {
    let mut data = to_plot(
        diagram,
        format!(
            "{name}: PSS equilibria, \u{3b4}e = {:.1} deg, \u{3b4}r = 0",
            analysis.delta_e_rad.to_degrees()
        ),
        &analysis.divergence_roll_rates,
    );
    data.special.extend(closed_form::hopf_points(analysis));
    data
}

fn rows(d: &Diagram) -> Vec<SpecialRow> {
    d.special_points
        .iter()
        .filter(|s| s.p >= 0.0)
        .map(|s| SpecialRow {
            kind: s.kind.name(),
            delta_a_deg: s.param.to_degrees(),
            p: s.p,
            frequency: s.frequency,
        })
        .collect()
}

/// Aileron steps (rad) bracketing a critical deflection `critical` (rad): a family like the
/// paper's (A: -1 to -8 deg around the fold at -3.85 deg).
fn family(critical: Option<f64>) -> Vec<f64> {
    let c = critical.unwrap_or(-8f64.to_radians());
    [0.25, 0.5, 0.75, 0.9, 1.1, 1.25, 1.5, 2.0]
        .iter()
        .map(|k| k * c)
        .collect()
}

/// The value of `r`, or `None` with the files that could not be written recorded in
/// `notes.failed` and any other reason as `what: reason` in `notes.skipped`.
fn keep<T>(notes: &mut Notes, what: &'static str, r: Result<T, ReportError>) -> Option<T> {
    match r {
        Ok(v) => Some(v),
        Err(ReportError::Plot(PlotError::Files { written, failed })) => {
            if !written.is_empty() {
                notes.partial.push((what, written));
            }
            notes.failed.extend(
                failed
                    .into_iter()
                    .map(|(path, reason)| FailedFile { path, reason }),
            );
            None
        }
        Err(ReportError::Plot(PlotError::Io { path, message })) => {
            notes.failed.push(FailedFile {
                path,
                reason: message,
            });
            None
        }
        Err(e) => {
            notes.skipped.push(format!("{what}: {e}"));
            None
        }
    }
}

/// Aileron steps as a list of degrees.
fn degrees(steps: &[f64]) -> String {
    steps
        .iter()
        .map(|d| format!("{:.2}", d.to_degrees()))
        .collect::<Vec<_>>()
        .join(", ")
}

fn rel(out: &Path, files: &[PathBuf]) -> Vec<String> {
    files
        .iter()
        .map(|f| {
            f.strip_prefix(out)
                .unwrap_or(f)
                .to_string_lossy()
                .into_owned()
        })
        .collect()
}

/// Produces the report for `aircraft` in `out`; `progress(fraction)` is called as it goes.
pub fn report(
    aircraft: &Aircraft,
    out: &Path,
    settings: &ReportSettings,
    progress: &mut dyn FnMut(f64),
) -> Result<Summary, ReportError> {
    let de = settings.delta_e;
    let style = &settings.style;
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
    let name = &aircraft.name;
    let mut figures = Vec::new();
    progress(0.05);
    // Each section that cannot be computed for this aircraft (no rudder authority, a run that
    // does not settle, ...) is skipped with its reason; the rest of the report still appears.
    let mut notes = Notes::default();
    let fig = |paper: &'static str, caption: String, files: &[PathBuf]| FigureEntry {
        paper,
        caption,
        files: rel(out, files),
    };

    // Figs 1-4: continuation of every branch.
    let cont = continuation::Settings {
        delta_e: de,
        ..continuation::Settings::default()
    };
    let diagram = keep(
        &mut notes,
        "Figs 1-4 (continuation)",
        continue_equilibria(aircraft, &cont, &mut |_| {}).map_err(ReportError::from),
    );
    if let Some(diagram) = &diagram {
        let data = bifurcation_data(diagram, &analysis, name);
        let r = plot::bifurcation(&out.join("fig01_bifurcation"), &data, style);
        if let Some(r) = keep(&mut notes, "Figs 1, 2", r.map_err(ReportError::from)) {
            figures.push(fig("Figs 1, 2", "Roll rate of the PSS equilibria vs aileron (solid stable, dashed unstable; saddle-nodes and Hopf points of the continuation marked, the closed-form Hopf points as black diamonds).".into(), &r.files));
        }
        let r = plot::trim_states(&out.join("fig03_trim_states"), &data, style);
        if let Some(r) = keep(&mut notes, "Figs 3, 4", r.map_err(ReportError::from)) {
            figures.push(fig(
                "Figs 3, 4",
                "Trim angle of attack, sideslip, pitch and yaw rate vs aileron (special points as in Figs 1, 2).".into(),
                &r.files,
            ));
        }
    }
    progress(0.3);

    // Figs 7, 8, 11: det K from the closed form.
    let r = closed_form::det_k_curve(aircraft, de)
        .and_then(|c| plot::det_k(&out.join("fig07_det_k"), &c, style));
    if let Some(r) = keep(&mut notes, "Figs 7, 8", r.map_err(ReportError::from)) {
        figures.push(fig(
            "Figs 7, 8",
            "det K vs trim roll rate P0, roots (jump points) and poles (d = 0) marked.".into(),
            &r.files,
        ));
    }
    let r = closed_form::zero_sideslip_det_k_curve(aircraft, de)
        .and_then(|c| plot::det_k(&out.join("fig11_zero_sideslip_det_k"), &c, style));
    if let Some(r) = keep(&mut notes, "Fig. 11", r.map_err(ReportError::from)) {
        figures.push(fig(
            "Fig. 11",
            "det K at the zero-sideslip trims vs P0: departure points.".into(),
            &r.files,
        ));
    }
    progress(0.4);

    // Fig. 9: extended bifurcation analysis of the zero-sideslip roll.
    let zs_settings = continuation::Settings {
        zero_sideslip: true,
        ..cont
    };
    let zs = keep(
        &mut notes,
        "Fig. 9 (zero-sideslip continuation)",
        continue_equilibria(aircraft, &zs_settings, &mut |_| {}).map_err(ReportError::from),
    );
    if let Some(zs) = &zs {
        // Show 1.5 times the first departure's aileron (at least 5 deg), as the paper's Fig. 9
        // does: beyond it the schedule asks for rudder deflections no aircraft has.
        let zs_range = analysis
            .zero_sideslip
            .departure
            .first()
            .map_or(5f64.to_radians(), |d| {
                (1.5 * d.delta_a_rad.abs()).max(5f64.to_radians())
            });
        let mut zs_plot = to_plot(
            zs,
            format!("{name}: zero-sideslip roll with the rudder schedule (EBA)"),
            &[],
        );
        zs_plot.delta_a_range_deg = Some((-zs_range.to_degrees(), zs_range.to_degrees()));
        let zs_data = ZeroSideslipData {
            schedule: zs
                .rudder_schedule
                .iter()
                .filter(|s| s.delta_a.abs() <= zs_range)
                .map(|s| (s.delta_a, s.delta_r))
                .collect(),
            diagram: zs_plot,
        };
        let r = plot::zero_sideslip(&out.join("fig09_zero_sideslip"), &zs_data, style);
        if let Some(r) = keep(&mut notes, "Fig. 9", r.map_err(ReportError::from)) {
            figures.push(fig("Fig. 9", "Rudder schedule for zero sideslip (aileron-rudder interconnect) and the PSS equilibria with it; the branch point marks the departure.".into(), &r.files));
        }
    }
    progress(0.5);

    // Figs 5, 6 and 10: time histories; the simulated jump (section III).
    let sim = keep(
        &mut notes,
        "Figs 5, 6, 10 (simulation)",
        Simulator::new(aircraft, de).map_err(ReportError::from),
    );
    // The first jump a pilot meets: the critical point of the primary branch.
    let fold = analysis.critical.as_ref().map(|c| c.delta_a_rad);
    let mut simulated_jumps = Vec::new();
    if let Some(sim) = &sim {
        let run =
            |model: Model, rudder: Rudder, da: &[f64]| -> Result<Vec<TimeHistory>, SimError> {
                let settings: Vec<SimSettings> = da
                    .iter()
                    .map(|d| SimSettings {
                        rudder,
                        ..SimSettings::step(model, de, *d)
                    })
                    .collect();
                sim.run_all(&settings)
            };
        // Figs 5, 6: aileron steps from the trim, 7th-order model solid, PSS dashed.
        let steps = within(&mut notes, "Figs 5, 6", family(fold), max_da);
        let r = run(Model::SeventhOrder, Rudder::Fixed(0.0), &steps)
            .and_then(|seventh| Ok((seventh, run(Model::Pss, Rudder::Fixed(0.0), &steps)?)))
            .map_err(ReportError::from)
            .and_then(|(seventh, pss)| {
                plot::time_histories(
                    &out.join("fig05_roll_response"),
                    &TimeHistoryData {
                        title: format!(
                            "{name}: response to aileron steps (7th-order solid, PSS dashed)"
                        ),
                        runs: &seventh,
                        overlay: &pss,
                        variables: vec![Variable::P, Variable::Beta],
                    },
                    style,
                )
                .map_err(ReportError::from)
            });
        if let Some(r) = keep(&mut notes, "Figs 5, 6", r) {
            figures.push(fig(
                "Figs 5, 6",
                format!(
                    "Roll rate and sideslip after aileron steps of {} deg.",
                    degrees(&steps)
                ),
                &r.files,
            ));
        }
        progress(0.7);

        // The rudder limit: the schedule saturates there, and the sideslip builds up beyond.
        for (side, at) in ["negative", "positive"].iter().zip(sim.rudder_saturation()) {
            if let Some(da) = at {
                notes.skipped.push(format!(
                    "zero-sideslip schedule: the rudder saturates at its limit for {side} aileron \
                     beyond delta_a = {:.2} deg; Fig. 10 steps past it hold the rudder at the limit",
                    da.to_degrees()
                ));
            }
        }
        // Fig. 10: zero-sideslip scheduling; steps up to past the departure point, where the
        // schedule exists.
        let departure = analysis
            .zero_sideslip
            .departure
            .first()
            .map(|d| d.delta_a_rad);
        let zs_steps: Vec<f64> = within(&mut notes, "Fig. 10", family(departure), max_da)
            .into_iter()
            .filter(|d| sim.rudder_at(Rudder::ZeroSideslip, *d).is_ok())
            .collect();
        if zs_steps.is_empty() {
            notes
                .skipped
                .push("Fig. 10: no aileron step has a zero-sideslip rudder setting".into());
        } else {
            let r = run(Model::SeventhOrder, Rudder::ZeroSideslip, &zs_steps)
                .map_err(ReportError::from)
                .and_then(|zs_runs| {
                    plot::time_histories(
                        &out.join("fig10_zero_sideslip_response"),
                        &TimeHistoryData {
                            title: format!(
                                "{name}: aileron steps with the zero-sideslip rudder schedule"
                            ),
                            runs: &zs_runs,
                            overlay: &[],
                            variables: vec![Variable::Beta, Variable::P],
                        },
                        style,
                    )
                    .map_err(ReportError::from)
                });
            if let Some(r) = keep(&mut notes, "Fig. 10", r) {
                figures.push(fig(
                    "Fig. 10",
                    format!(
                        "Sideslip and roll rate after aileron steps of {} deg with the rudder on the zero-sideslip schedule (7th-order model).",
                        degrees(&zs_steps)
                    ),
                    &r.files,
                ));
            }
        }
        progress(0.85);

        match fold {
            Some(f) if f.abs() > max_da => notes.skipped.push(format!(
                "simulated jump: the criterion's fold at {:.3} deg lies beyond the aileron range \
                 of +-{:.1} deg; no sweep",
                f.to_degrees(),
                max_da.to_degrees()
            )),
            Some(f) => {
                // Out to twice the fold, within the aileron range.
                let to = (2.0 * f).clamp(-max_da, max_da);
                if to.abs() < 2.0 * f.abs() {
                    notes.skipped.push(format!(
                        "simulated jump: swept to {:.1} deg only (aileron range), not to twice \
                         the fold ({:.1} deg)",
                        to.to_degrees(),
                        2.0 * f.to_degrees()
                    ));
                }
                for (model, label) in [(Model::Pss, "pss"), (Model::SeventhOrder, "seventh-order")]
                {
                    let sweep =
                        jump_sweep(sim, &SweepSettings::new(model, to, 0.25f64.to_radians()));
                    if let Some(sweep) = keep(
                        &mut notes,
                        "simulated jump",
                        sweep.map_err(ReportError::from),
                    ) {
                        simulated_jumps.push(SimulatedJump {
                            model: label,
                            delta_a_deg: sweep.jump.map(|j| j.delta_a.to_degrees()),
                            criterion_deg: f.to_degrees(),
                        });
                    }
                }
            }
            None => notes.skipped.push(format!(
                "simulated jump: no sweep, the criterion finds no jump within the aileron range \
                 it follows: {}",
                analysis
                    .critical_note
                    .as_deref()
                    .unwrap_or("the primary branch has no fold")
            )),
        }
    }
    figures.extend(notes.partial.iter().map(|(paper, files)| {
        fig(
            paper,
            "Incomplete: some files of this figure could not be written (listed under Files that could not be written).".into(),
            files,
        )
    }));
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
        let json = serde_json::to_string_pretty(&summary).unwrap_or_default() + "\n";
        let md = markdown(&summary, de);
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
    progress(1.0);
    Ok(summary)
}

/// `x` with `digits` decimals, never `-0.0000` (a value that rounds to zero prints as zero).
pub fn fixed(x: f64, digits: usize) -> String {
    let s = format!("{x:.digits$}");
    match s.strip_prefix('-') {
        Some(rest) if rest.chars().all(|c| c == '0' || c == '.') => rest.to_string(),
        _ => s,
    }
}

/// `v` with `digits` decimals, comma-separated and followed by `unit`, or `none`.
pub fn list(v: &[f64], digits: usize, unit: &str) -> String {
    if v.is_empty() {
        "none".into()
    } else {
        let v: Vec<String> = v.iter().map(|x| fixed(*x, digits)).collect();
        format!("{} {unit}", v.join(", "))
    }
}

/// Which instability the primary branch meets first (a jump, or a Hopf point with its
/// frequency, first Lyapunov coefficient and kind) and where a jump lands, as `analyze` prints
/// it and the summary repeats it: lines ending in a blank line.
pub fn first_departure_text(a: &Analysis) -> String {
    let Some(f) = &a.first_departure else {
        return "First loss of stability on the primary branch: none within the aileron range.\n\n"
            .into();
    };
    let mut s = format!(
        "First loss of stability on the primary branch: {} at P0 = {} rad/s, delta_a = {} deg",
        if f.kind == "jump" { "JUMP" } else { "HOPF" },
        fixed(f.p0, 6),
        fixed(f.delta_a_deg, 4)
    );
    if let (Some(w), Some(l1), Some(k)) = (f.omega, f.l1, f.hopf_kind) {
        s += &format!(
            " (oscillation omega = {} rad/s, l1 = {:.4e}, {k})",
            fixed(w, 4),
            l1
        );
    }
    s += "\n";
    if let Some(l) = &f.lands_at {
        if l.is_empty() {
            s += "  the jump lands on no stable equilibrium (divergence)\n";
        }
        for e in l {
            s += &format!(
                "  lands at P0 = {} rad/s (jump {} rad/s), alpha = {} deg, beta = {} deg\n",
                fixed(e.p0, 6),
                fixed(e.p0 - f.p0, 6),
                fixed(e.alpha.to_degrees(), 4),
                fixed(e.beta.to_degrees(), 4)
            );
        }
    }
    s + "\n"
}

/// The cells of a reported point's row, as `analyze` and the summary print them: P0 (rad/s),
/// delta_a, alpha and beta (deg).
fn point_cells(j: &JumpPoint) -> [String; 4] {
    [
        fixed(j.p0, 6),
        fixed(j.delta_a_deg, 4),
        fixed(j.alpha.to_degrees(), 4),
        fixed(j.beta.to_degrees(), 4),
    ]
}

/// The cells of a jump point's row: P0 (rad/s), delta_a, alpha, beta (deg), q and r (rad/s).
pub fn jump_cells(j: &JumpPoint) -> [String; 6] {
    let [p0, da, alpha, beta] = point_cells(j);
    [p0, da, alpha, beta, fixed(j.q, 5), fixed(j.r, 5)]
}

/// The cells of a Hopf point's row: P0 (rad/s), delta_a, alpha, beta (deg), omega (rad/s),
/// period (s), l1 and its kind (supercritical or subcritical).
pub fn hopf_cells(h: &HopfPoint) -> [String; 8] {
    let [p0, da, alpha, beta] = point_cells(&h.point);
    [
        p0,
        da,
        alpha,
        beta,
        fixed(h.omega, 4),
        fixed(h.period, 4),
        format!("{:.3e}", h.l1),
        h.kind.to_string(),
    ]
}

/// The cells of a zero-sideslip departure's row: P0 (rad/s), delta_a, delta_r, alpha (deg), q
/// and r (rad/s).
pub fn departure_cells(d: &DeparturePoint) -> [String; 6] {
    [
        fixed(d.p0, 6),
        fixed(d.delta_a_deg, 4),
        fixed(d.delta_r_deg, 4),
        fixed(d.alpha.to_degrees(), 4),
        fixed(d.q, 5),
        fixed(d.r, 5),
    ]
}

/// A markdown table row of cells.
fn md_row(cells: &[String]) -> String {
    format!("| {} |\n", cells.join(" | "))
}

fn markdown(s: &Summary, de: f64) -> String {
    let a = &s.analysis;
    let mut m = format!(
        "# {}: roll-coupling report\n\nElevator {:.2} deg, rudder 0 (unconstrained roll). Criterion of Mahale & Ananthkrishnan (AIAA 2006-6267), derived exactly; see `docs/formulas.tex`.\n\n",
        crate::aircraft::shown(&a.aircraft),
        de.to_degrees()
    );
    m += &format!(
        "## First loss of stability\n\n```text\n{}\n```\n\n",
        first_departure_text(a).trim_end()
    );
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_never_print_as_negative_zero_and_empty_lists_carry_no_unit() {
        assert_eq!(fixed(-0.00001, 4), "0.0000");
        assert_eq!(fixed(-0.0, 2), "0.00");
        assert_eq!(fixed(-0.00006, 4), "-0.0001");
        assert_eq!(fixed(2.5, 1), "2.5");
        assert_eq!(list(&[], 6, "rad/s"), "none");
        assert_eq!(list(&[1.0, -0.0], 2, "rad/s"), "1.00, 0.00 rad/s");
    }

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
            omega: Some(0.88),
            l1: Some(-0.1746),
            hopf_kind: Some("supercritical"),
            lands_at: None,
        });
        let text = first_departure_text(&a);
        assert!(
            text.starts_with(
                "First loss of stability on the primary branch: HOPF at P0 = 3.100000 rad/s, \
                 delta_a = -20.6000 deg (oscillation omega = 0.8800 rad/s, l1 = -1.7460e-1, \
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

    #[test]
    fn steps_beyond_the_aileron_range_are_named_and_replaced_by_the_default_family() {
        let mut notes = Notes::default();
        let max = 30f64.to_radians();
        // A fold at -3.85 deg: the family (up to twice it) is inside the range.
        let steps = within(&mut notes, "Figs 5, 6", family(Some(-0.0671)), max);
        assert_eq!(steps.len(), 8);
        assert!(notes.skipped.is_empty());
        // A fold at -110905 deg (n_beta = 0): nothing inside; the default family instead.
        let steps = within(&mut notes, "Figs 5, 6", family(Some(-1935.6)), max);
        assert_eq!(steps, family(None));
        assert!(steps.iter().all(|d| d.abs() <= max));
        assert_eq!(notes.skipped.len(), 1);
        assert!(notes.skipped[0].contains("beyond the aileron range of +-30.0 deg"));
    }
}
