//! The sections of `model report`, each computed and drawn on its own so that one that cannot
//! be computed for an aircraft (no rudder authority, a run that does not settle, ...) is skipped
//! with its reason while the rest still appear: Figs 1-4 and 9 from the continuation, Figs 7, 8
//! and 11 from the closed-form det K, Figs 5, 6 and 10 and the simulated jump (section III) from
//! the simulation.

use super::{FailedFile, FigureEntry, ReportError, SimulatedJump, SpecialRow};
use crate::aircraft::Aircraft;
use crate::analysis::{trim_curves, Analysis};
use crate::continuation::{self, continue_equilibria, Diagram};
use crate::plot::{
    self, BifurcationData, BranchPoint, PlotError, PlotStyle, SpecialKind, SpecialPoint,
    TimeHistoryData, Variable, ZeroSideslipData,
};
use crate::simulation::{
    jump_sweep, Model, Rudder, SimError, SimSettings, Simulator, SweepSettings, TimeHistory,
};
use std::path::{Path, PathBuf};

/// What could not be done: sections not computed for this aircraft, files not written.
#[derive(Default)]
pub(super) struct Notes {
    pub(super) skipped: Vec<String>,
    pub(super) failed: Vec<FailedFile>,
    /// Figures of which some files were written and some not: (paper figures, files written).
    pub(super) partial: Vec<(&'static str, Vec<PathBuf>)>,
}

/// The report as it is written: where, for what, and what it holds so far.
pub(super) struct Sections<'a> {
    pub(super) aircraft: &'a Aircraft,
    pub(super) out: &'a Path,
    pub(super) style: &'a PlotStyle,
    /// Elevator deflection, rad.
    pub(super) de: f64,
    /// The aileron range of the simulations, rad.
    pub(super) max_da: f64,
    pub(super) analysis: &'a Analysis,
    pub(super) notes: Notes,
    pub(super) figures: Vec<FigureEntry>,
}

impl Sections<'_> {
    /// A figure entry, its files relative to the report folder.
    pub(super) fn fig(
        &self,
        paper: &'static str,
        caption: String,
        files: &[PathBuf],
    ) -> FigureEntry {
        FigureEntry {
            paper,
            caption,
            files: rel(self.out, files),
        }
    }

    /// Records the figure drawn as `r`, or why it was not (see [`keep`]).
    fn add<T: AsRef<[PathBuf]>>(
        &mut self,
        paper: &'static str,
        caption: impl FnOnce() -> String,
        r: Result<T, ReportError>,
    ) {
        if let Some(files) = keep(&mut self.notes, paper, r) {
            let entry = self.fig(paper, caption(), files.as_ref());
            self.figures.push(entry);
        }
    }

    /// Figs 1-4: the continuation of every branch; the diagram, for the summary's special points.
    pub(super) fn bifurcation_figures(&mut self, cont: &continuation::Settings) -> Option<Diagram> {
        let diagram = keep(
            &mut self.notes,
            "Figs 1-4 (continuation)",
            continue_equilibria(self.aircraft, cont, &mut |_| {}).map_err(ReportError::from),
        );
        if let Some(diagram) = &diagram {
            let data = bifurcation_data(diagram, self.analysis, &self.aircraft.name);
            let r = plot::bifurcation(&self.out.join("fig01_bifurcation"), &data, self.style);
            self.add("Figs 1, 2", || "Roll rate of the PSS equilibria vs aileron (solid stable, dashed unstable; saddle-nodes and Hopf points of the continuation marked, the closed-form Hopf points as black diamonds).".into(), r.map(|r| r.files).map_err(ReportError::from));
            let r = plot::trim_states(&self.out.join("fig03_trim_states"), &data, self.style);
            self.add(
                "Figs 3, 4",
                || "Trim angle of attack, sideslip, pitch and yaw rate vs aileron (special points as in Figs 1, 2).".into(),
                r.map(|r| r.files).map_err(ReportError::from),
            );
        }
        diagram
    }

    /// Figs 7, 8 and 11: det K from the closed form, unconstrained and at zero sideslip.
    pub(super) fn det_k_figures(&mut self) {
        let (aircraft, de, style) = (self.aircraft, self.de, self.style);
        let r = trim_curves::det_k_curve(aircraft, de)
            .map_err(PlotError::from)
            .and_then(|c| plot::det_k(&self.out.join("fig07_det_k"), &c, style));
        self.add(
            "Figs 7, 8",
            || "det K vs trim roll rate P0, roots (jump points) and poles (d = 0) marked.".into(),
            r.map(|r| r.files).map_err(ReportError::from),
        );
        let r = trim_curves::zero_sideslip_det_k_curve(aircraft, de)
            .map_err(PlotError::from)
            .and_then(|c| plot::det_k(&self.out.join("fig11_zero_sideslip_det_k"), &c, style));
        self.add(
            "Fig. 11",
            || "det K at the zero-sideslip trims vs P0: departure points.".into(),
            r.map(|r| r.files).map_err(ReportError::from),
        );
    }

    /// Fig. 9: the extended bifurcation analysis of the zero-sideslip roll; the diagram, for the
    /// summary's special points.
    pub(super) fn zero_sideslip_figure(
        &mut self,
        cont: &continuation::Settings,
    ) -> Option<Diagram> {
        let zs_settings = continuation::Settings {
            zero_sideslip: true,
            ..*cont
        };
        let zs = keep(
            &mut self.notes,
            "Fig. 9 (zero-sideslip continuation)",
            continue_equilibria(self.aircraft, &zs_settings, &mut |_| {})
                .map_err(ReportError::from),
        );
        if let Some(zs) = &zs {
            // Show 1.5 times the first departure's aileron (at least 5 deg), as the paper's Fig. 9
            // does: beyond it the schedule asks for rudder deflections no aircraft has.
            let zs_range = self
                .analysis
                .zero_sideslip
                .departure
                .first()
                .map_or(5f64.to_radians(), |d| {
                    (1.5 * d.delta_a_rad.abs()).max(5f64.to_radians())
                });
            let mut zs_plot = to_plot(
                zs,
                format!(
                    "{}: zero-sideslip roll with the rudder schedule (EBA)",
                    self.aircraft.name
                ),
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
            let r =
                plot::zero_sideslip(&self.out.join("fig09_zero_sideslip"), &zs_data, self.style);
            self.add("Fig. 9", || "Rudder schedule for zero sideslip (aileron-rudder interconnect) and the PSS equilibria with it; the branch point marks the departure.".into(), r.map(|r| r.files).map_err(ReportError::from));
        }
        zs
    }

    /// Figs 5, 6 and 10 (time histories) and the simulated jump (section III); `progress` gets
    /// the report's fraction done after each.
    pub(super) fn simulations(&mut self, progress: &mut dyn FnMut(f64)) -> Vec<SimulatedJump> {
        let sim = keep(
            &mut self.notes,
            "Figs 5, 6, 10 (simulation)",
            Simulator::new(self.aircraft, self.de).map_err(ReportError::from),
        );
        let Some(sim) = &sim else {
            return Vec::new();
        };
        self.step_responses(sim);
        progress(0.7);
        self.zero_sideslip_responses(sim);
        progress(0.85);
        self.simulated_jumps(sim)
    }

    /// Figs 5, 6: aileron steps from the trim bracketing the criterion's fold, 7th-order model
    /// solid, PSS dashed.
    fn step_responses(&mut self, sim: &Simulator) {
        // The first jump a pilot meets: the critical point of the primary branch.
        let fold = self.analysis.critical.as_ref().map(|c| c.delta_a_rad);
        let steps = within(&mut self.notes, "Figs 5, 6", family(fold), self.max_da);
        let de = self.de;
        let r = run(sim, de, Model::SeventhOrder, Rudder::Fixed(0.0), &steps)
            .and_then(|seventh| {
                Ok((
                    seventh,
                    run(sim, de, Model::Pss, Rudder::Fixed(0.0), &steps)?,
                ))
            })
            .map_err(ReportError::from)
            .and_then(|(seventh, pss)| {
                plot::time_histories(
                    &self.out.join("fig05_roll_response"),
                    &TimeHistoryData {
                        title: format!(
                            "{}: response to aileron steps (7th-order solid, PSS dashed)",
                            self.aircraft.name
                        ),
                        runs: &seventh,
                        overlay: &pss,
                        variables: vec![Variable::P, Variable::Beta],
                    },
                    self.style,
                )
                .map_err(ReportError::from)
            });
        self.add(
            "Figs 5, 6",
            || {
                format!(
                    "Roll rate and sideslip after aileron steps of {} deg.",
                    degrees(&steps)
                )
            },
            r.map(|r| r.files),
        );
    }

    /// Fig. 10: aileron steps with the rudder on the zero-sideslip schedule, up to past the
    /// departure point where the schedule exists; the rudder's saturation is noted.
    fn zero_sideslip_responses(&mut self, sim: &Simulator) {
        // The rudder limit: the schedule saturates there, and the sideslip builds up beyond.
        for (side, at) in ["negative", "positive"].iter().zip(sim.rudder_saturation()) {
            if let Some(da) = at {
                self.notes.skipped.push(format!(
                    "zero-sideslip schedule: the rudder saturates at its limit for {side} aileron \
                     beyond delta_a = {:.2} deg; Fig. 10 steps past it hold the rudder at the limit",
                    da.to_degrees()
                ));
            }
        }
        let departure = self
            .analysis
            .zero_sideslip
            .departure
            .first()
            .map(|d| d.delta_a_rad);
        let zs_steps: Vec<f64> = within(&mut self.notes, "Fig. 10", family(departure), self.max_da)
            .into_iter()
            .filter(|d| sim.rudder_at(Rudder::ZeroSideslip, *d).is_ok())
            .collect();
        if zs_steps.is_empty() {
            self.notes
                .skipped
                .push("Fig. 10: no aileron step has a zero-sideslip rudder setting".into());
            return;
        }
        let r = run(
            sim,
            self.de,
            Model::SeventhOrder,
            Rudder::ZeroSideslip,
            &zs_steps,
        )
        .map_err(ReportError::from)
        .and_then(|zs_runs| {
            plot::time_histories(
                &self.out.join("fig10_zero_sideslip_response"),
                &TimeHistoryData {
                    title: format!(
                        "{}: aileron steps with the zero-sideslip rudder schedule",
                        self.aircraft.name
                    ),
                    runs: &zs_runs,
                    overlay: &[],
                    variables: vec![Variable::Beta, Variable::P],
                },
                self.style,
            )
            .map_err(ReportError::from)
        });
        self.add(
            "Fig. 10",
            || format!(
                "Sideslip and roll rate after aileron steps of {} deg with the rudder on the zero-sideslip schedule (7th-order model).",
                degrees(&zs_steps)
            ),
            r.map(|r| r.files),
        );
    }

    /// The simulated jump (section III): aileron sweeps of the PSS and 7th-order models out to
    /// twice the criterion's fold, within the aileron range.
    fn simulated_jumps(&mut self, sim: &Simulator) -> Vec<SimulatedJump> {
        let max_da = self.max_da;
        let notes = &mut self.notes;
        let mut simulated_jumps = Vec::new();
        match self.analysis.critical.as_ref().map(|c| c.delta_a_rad) {
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
                    if let Some(sweep) =
                        keep(notes, "simulated jump", sweep.map_err(ReportError::from))
                    {
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
                self.analysis
                    .critical_note
                    .as_deref()
                    .unwrap_or("the primary branch has no fold")
            )),
        }
        simulated_jumps
    }
}

/// Aileron steps `da` (rad) from the trim at elevator `de` (rad), one run each.
fn run(
    sim: &Simulator,
    de: f64,
    model: Model,
    rudder: Rudder,
    da: &[f64],
) -> Result<Vec<TimeHistory>, SimError> {
    let settings: Vec<SimSettings> = da
        .iter()
        .map(|d| SimSettings {
            rudder,
            ..SimSettings::step(model, de, *d)
        })
        .collect();
    sim.run_all(&settings)
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
/// closed-form Hopf points of the analysis ([`trim_curves::hopf_points`]) and its divergence
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
    data.special.extend(trim_curves::hopf_points(analysis));
    data
}

pub(super) fn rows(d: &Diagram) -> Vec<SpecialRow> {
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
pub(super) fn keep<T>(
    notes: &mut Notes,
    what: &'static str,
    r: Result<T, ReportError>,
) -> Option<T> {
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

#[cfg(test)]
mod tests {
    use super::*;

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
