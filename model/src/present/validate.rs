//! `model validate jsbsim:MODEL ...`: aileron steps in the 7th-order model (the import's
//! linearised aircraft, [`crate::simulation`]) and in the native 6-DOF ([`crate::six_dof`]) from
//! the same n-g trim; the settled roll rate of each (mean |p| over the last 2 s) against the
//! aileron, both judged by one rule ([`crate::six_dof::jump`]); a verdict line per model, how far
//! the 6-DOF's speed, altitude and Mach moved, and the plateau figure with the criterion's
//! critical aileron.

use super::failure::{stdout_error, Failure};
use super::numbers::fixed;
use super::options::ValidateArgs;
use super::outputs::{begin_folder, commit_folder, default_folder};
use super::six_dof::{loaded_source, trim_and_aileron};
use crate::analysis::analyze;
use crate::plot::{render, Axis, Dash, Figure, LegendPlace, Line, Panel, PlotStyle, Rgb};
use crate::simulation::{simulate, Model, SimSettings};
use crate::six_dof::jump::{find_jump, Jump};
use crate::six_dof::sweep::{sweep, WINDOW_S};
use std::io::Write;
use std::path::PathBuf;
use std::process::ExitCode;

/// The aileron steps of `spec` (`A:B:STEP`, deg), or from 1 deg to 4 deg past `limit`.
fn steps(spec: Option<&str>, limit: Option<f64>) -> Result<Vec<f64>, Failure> {
    let (a, b, s) = match spec {
        None => (1.0, (limit.unwrap_or(20.0) + 4.0).round(), 1.0),
        Some(text) => {
            let v: Vec<f64> = text
                .split(':')
                .filter_map(|x| x.trim().parse().ok())
                .collect();
            match v[..] {
                [a, b, s] if 0.0 <= a && a < b && b <= 90.0 && s > 0.0 && (b - a) / s <= 200.0 => {
                    (a, b, s)
                }
                _ => {
                    return Err(Failure::Input(format!(
                        "--delta-a-deg {text}: expected A:B:STEP in deg of |delta_a|, \
                         0 <= A < B <= 90, STEP > 0, at most 200 steps"
                    )))
                }
            }
        }
    };
    let n = ((b - a) / s + 1e-9).floor() as usize;
    Ok((0..=n).map(|k| a + k as f64 * s).collect())
}

/// A verdict line: where the model jumps and how far from the prediction.
fn verdict(name: &str, jump: Option<Jump>, critical: Option<f64>, range: (f64, f64)) -> String {
    let predicted = critical.map_or("no jump predicted".to_string(), |c| {
        format!("predicted at {} deg", fixed(c, 2))
    });
    match jump {
        Some(j) => {
            let (lo, hi) = j.between_deg;
            let off = critical.map_or(String::new(), |c| {
                format!(", {} deg past the prediction", fixed(hi - c, 2))
            });
            format!(
                "{name}: jumps between {lo} and {hi} deg (slope {} rad/s per deg, {} x the \
                 median){off}; {predicted}",
                fixed(j.slope, 3),
                fixed(j.slope / j.median.max(1e-12), 1)
            )
        }
        None => format!(
            "{name}: no jump from {} to {} deg; {predicted}",
            range.0, range.1
        ),
    }
}

/// What `validate` computes and writes: the aileron steps, each model's settled |p| at each,
/// the criterion's critical aileron and the aileron limit, the folder written and the lines the
/// command prints.
#[derive(Clone, Debug, serde::Serialize)]
pub struct Validation {
    /// The aileron steps, deg of |delta_a|.
    pub delta_a_deg: Vec<f64>,
    /// The 7th-order model's settled |p| at each step, rad/s.
    pub seventh_order_p: Vec<f64>,
    /// The 6-DOF's settled |p| at each step, rad/s.
    pub six_dof_p: Vec<f64>,
    /// The criterion's critical aileron, deg of |delta_a| (none without a jump).
    pub critical_deg: Option<f64>,
    /// The model's aileron limit, deg (when it gives one).
    pub limit_deg: Option<f64>,
    /// The folder holding the plateau figure.
    pub folder: PathBuf,
    /// The lines the command prints: title, a verdict per model, the 6-DOF's drift.
    pub lines: Vec<String>,
}

/// Runs the command.
pub fn command(a: &ValidateArgs, out: &mut dyn Write) -> Result<ExitCode, Failure> {
    for l in validation_of(a)?.lines {
        writeln!(out, "{l}").map_err(stdout_error)?;
    }
    Ok(ExitCode::SUCCESS)
}

/// What `validate` computes and writes for the options of `a`: everything but the printing,
/// shared by the command line and Python.
pub fn validation_of(a: &ValidateArgs) -> Result<Validation, Failure> {
    if !(a.t_end.is_finite() && a.t_end >= 2.0 * WINDOW_S && a.t_end <= 600.0) {
        return Err(Failure::Input(format!(
            "--t-end = {}: expected the length of each run, {} to 600 s",
            a.t_end,
            2.0 * WINDOW_S
        )));
    }
    let (loaded, condition, n, spec) =
        loaded_source(&a.source, (a.altitude_m, a.mach, a.load_factor))?;
    let target = a
        .out
        .clone()
        .unwrap_or_else(|| default_folder("validate", &a.source));
    let staged = begin_folder(&target, "validate")?;
    let ac = crate::jsbsim::cli::source(&spec)?;
    let analysis = analyze(&ac, 0.0).map_err(|e| e.to_string())?;
    let critical = analysis.critical.as_ref().map(|j| j.delta_a_deg.abs());
    let limit = ac.limits.aileron_deg;
    let degs = steps(a.delta_a_deg.as_deref(), limit)?;
    let setup = loaded.setup(condition);
    let (trim, _) = trim_and_aileron(&setup, n, 0.0)?;
    let mut seventh = Vec::new();
    for &d in &degs {
        let settings = SimSettings {
            t_end: a.t_end,
            ..SimSettings::step(Model::SeventhOrder, 0.0, -d.to_radians())
        };
        let run = simulate(&ac, &settings).map_err(|e| e.to_string())?;
        seventh.push(run.steady(WINDOW_S).p_mean.abs());
    }
    let six = sweep(&setup, &trim, &degs, a.t_end)?;
    let drift = six.drift;
    let range = (degs[0], degs[degs.len() - 1]);
    let name = &loaded.model.name;
    let title = format!(
        "{name}, {} m, Mach {}, n = {n}: settled roll rate after an aileron step",
        condition.altitude_m,
        fixed(condition.mach, 3)
    );
    render(
        &staged.path().join("plateau"),
        &figure(&title, &degs, (&seventh, &six.settled), critical, limit),
        &PlotStyle::default(),
    )
    .map_err(|e| Failure::Output(e.to_string()))?;
    let lines = [
        title.clone(),
        verdict(
            "7th-order model",
            find_jump(&degs, &seventh),
            critical,
            range,
        ),
        verdict("6-DOF", six.jump, critical, range),
        format!(
            "6-DOF over each {} s run, largest change: V {} m/s, altitude {} m, Mach {}",
            a.t_end,
            fixed(drift[0], 1),
            fixed(drift[1], 0),
            fixed(drift[2], 3)
        ),
    ];
    commit_folder(staged)?;
    Ok(Validation {
        delta_a_deg: degs,
        seventh_order_p: seventh,
        six_dof_p: six.settled,
        critical_deg: critical,
        limit_deg: limit,
        folder: target,
        lines: lines.to_vec(),
    })
}

/// The plateau figure: both models' settled |p| against |delta_a|, the critical aileron and
/// the limit as vertical lines.
fn figure(
    title: &str,
    degs: &[f64],
    (seventh, six): (&[f64], &[f64]),
    critical: Option<f64>,
    limit: Option<f64>,
) -> Figure {
    let top = seventh.iter().chain(six).copied().fold(0.0, f64::max) * 1.1 + 1e-3;
    let x_hi = degs[degs.len() - 1];
    let series = |label: &str, p: &[f64], color| Line {
        label: Some(label.to_string()),
        points: degs.iter().copied().zip(p.iter().copied()).collect(),
        color,
        dash: Dash::Solid,
        width: 2,
    };
    let mut lines = vec![
        series("7th-order model", seventh, Rgb::BLUE),
        series("6-DOF", six, Rgb::RED),
    ];
    for (label, x, color) in [
        ("criterion's critical aileron", critical, Rgb::BLACK),
        ("aileron limit", limit, Rgb::GREY),
    ] {
        if let Some(x) = x.filter(|x| *x <= x_hi) {
            lines.push(Line {
                label: Some(label.to_string()),
                points: vec![(x, 0.0), (x, top)],
                color,
                dash: Dash::Dashed,
                width: 1,
            });
        }
    }
    Figure {
        title: title.to_string(),
        panels: vec![Panel {
            title: String::new(),
            area: [0.0, 0.0, 1.0, 1.0],
            x: Axis::linear("|delta_a| (deg)", degs[0].min(0.0), x_hi),
            y: Axis::linear("settled |p| (rad/s)", 0.0, top),
            lines,
            markers: vec![],
            legend: LegendPlace::UpperLeft,
        }],
        legend_area: None,
        note: String::new(),
    }
}
