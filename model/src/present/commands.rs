//! One function per command of `model`: each loads the aircraft, checks the options' values,
//! computes through the library (analysis, continuation, report, simulation, clearance, emit)
//! and prints to `out` (stdout) or writes the requested files. `main.rs` parses the arguments
//! and calls one of these; each returns the exit code or why it did not finish.

use super::failure::{named, stdout_error, write_file, Failure, FAILED};
use super::numbers::fixed;
use super::options::{
    delta_e_list, elevator_of, finite_angle, load_aircraft, AnalyzeArgs, ClearArgs, ContinueArgs,
    ConvertArgs, EmitArgs, FiguresArgs, SimulateArgs,
};
use super::progress::{progress_bar, say_how_long, set};
use super::report::{report, ReportError, ReportSettings};
use crate::aircraft::{self, shown};
use crate::analysis::analyze;
use crate::analysis::fast::{analyze_routed_with, Route};
use crate::analysis::Analysis;
use crate::continuation::{continue_equilibria, ContinuationParam, Settings};
use crate::simulation::{simulate, Model, Rudder, SimError, SimSettings};
use std::io::Write;
use std::path::Path;
use std::process::ExitCode;

/// Prints to `out` (stdout), turning a write error into a [`Failure`].
macro_rules! say {
    ($out:expr, $($arg:tt)*) => {
        writeln!($out, $($arg)*).map_err(stdout_error)?
    };
}

/// The JSON of `model analyze`: the analysis and, with `--certified`, the route that answered
/// and, when the certified route fell back, why. The exact path's JSON (plain `--json`, or
/// `--exact`) is the analysis alone.
#[derive(serde::Serialize)]
struct Routed<'a> {
    #[serde(flatten)]
    analysis: &'a Analysis,
    #[serde(skip_serializing_if = "Option::is_none")]
    route: Option<&'static str>,
    #[serde(skip_serializing_if = "Option::is_none")]
    fallback: Option<&'static str>,
}

/// `model analyze`: the table of the certified route (the exact path with `--exact`), or JSON
/// of the exact path (the certified route's with `--certified`).
pub fn analyze_command(a: &AnalyzeArgs, out: &mut dyn Write) -> Result<ExitCode, Failure> {
    let ac = load_aircraft(&a.aircraft)?;
    let delta_e = elevator_of(&ac, a.delta_e_deg)?;
    let (result, route) = if a.exact || (a.json && !a.certified) {
        analyze(&ac, delta_e).map(|r| (r, None))
    } else {
        analyze_routed_with(&ac, delta_e, true).map(|(a, route)| (a, Some(route)))
    }
    .map_err(|e| named(&ac, e))?;
    if a.json {
        let routed = Routed {
            analysis: &result,
            route: route.map(Route::name),
            fallback: route.and_then(Route::fallback),
        };
        let text = serde_json::to_string_pretty(&routed).map_err(|e| e.to_string())?;
        say!(out, "{text}");
    } else {
        write!(out, "{}", super::tables::analysis(&result)).map_err(stdout_error)?;
    }
    Ok(ExitCode::SUCCESS)
}

/// `model continue`: the continuation's diagram as a summary or JSON, and as CSV with `--csv`.
pub fn continue_command(a: &ContinueArgs, out: &mut dyn Write) -> Result<ExitCode, Failure> {
    let ac = load_aircraft(&a.aircraft)?;
    let (min_deg, max_deg) = (a.min_deg, a.max_deg);
    let (min, max) = (finite_angle("min", min_deg)?, finite_angle("max", max_deg)?);
    if min_deg >= max_deg {
        return Err(Failure::Input(format!(
            "--min-deg = {min_deg} and --max-deg = {max_deg}: expected the lower end of \
             the parameter range below the upper end, in deg"
        )));
    }
    let settings = Settings {
        param: a
            .param
            .parse::<ContinuationParam>()
            .map_err(|e| e.to_string())?,
        min,
        max,
        delta_e: elevator_of(&ac, a.delta_e_deg)?,
        zero_sideslip: a.zero_sideslip,
        ..Settings::default()
    };
    let bar = progress_bar("continuation");
    let diagram =
        continue_equilibria(&ac, &settings, &mut |f| set(&bar, f)).map_err(|e| named(&ac, e))?;
    if let Some(b) = bar {
        b.finish_and_clear();
    }
    if let Some(path) = &a.csv {
        write_file(path, diagram.to_csv().as_bytes())?;
    }
    if a.json {
        let text = serde_json::to_string_pretty(&diagram).map_err(|e| e.to_string())?;
        say!(out, "{text}");
    } else {
        write!(out, "{}", super::tables::diagram(&diagram)).map_err(stdout_error)?;
    }
    Ok(ExitCode::SUCCESS)
}

/// `model report` (`summary`: with summary.md and summary.json) and `model plot` (the figures
/// alone): the files written, the sections skipped, and the files that could not be written
/// (exit 1).
pub fn report_command(
    a: &FiguresArgs,
    summary: bool,
    out: &mut dyn Write,
) -> Result<ExitCode, Failure> {
    let ac = load_aircraft(&a.aircraft)?;
    let dir = &a.out;
    let settings = ReportSettings {
        summary,
        ..ReportSettings::new(elevator_of(&ac, a.delta_e_deg)?)
    };
    let bar = progress_bar(if summary { "report" } else { "plot" });
    let result = report(&ac, dir, &settings, &mut |f| set(&bar, f));
    if let Some(b) = bar {
        b.finish_and_clear();
    }
    let result = result.map_err(|e| match e {
        ReportError::Io { .. } => Failure::Output(e.to_string()),
        e => named(&ac, e),
    })?;
    let failed: Vec<&Path> = result
        .failed_files
        .iter()
        .map(|f| f.path.as_path())
        .collect();
    for f in &result.figures {
        for file in &f.files {
            say!(out, "wrote {}", dir.join(file).display());
        }
    }
    if summary {
        for file in ["summary.md", "summary.json"] {
            let path = dir.join(file);
            if !failed.contains(&path.as_path()) {
                say!(out, "wrote {}", path.display());
            }
        }
    }
    for k in &result.skipped {
        say!(out, "skipped: {}", shown(k));
    }
    if result.failed_files.is_empty() {
        return Ok(ExitCode::SUCCESS);
    }
    out.flush().map_err(stdout_error)?;
    let mut err = std::io::stderr();
    for f in &result.failed_files {
        let _ = writeln!(
            err,
            "error: cannot write {}: {}",
            f.path.display(),
            f.reason
        );
    }
    Ok(ExitCode::from(FAILED))
}

/// `model simulate`: one aileron step's steady state in a line, and the time history as CSV
/// with `--csv`.
pub fn simulate_command(a: &SimulateArgs, out: &mut dyn Write) -> Result<ExitCode, Failure> {
    let ac = load_aircraft(&a.aircraft)?;
    let (t_end, delta_a_deg) = (a.t_end, a.delta_a_deg);
    if !(t_end.is_finite() && t_end > 0.0) {
        return Err(Failure::Input(format!(
            "--t-end = {t_end}: expected the length of the run, a positive finite number \
             of seconds"
        )));
    }
    let model = if a.pss {
        Model::Pss
    } else {
        Model::SeventhOrder
    };
    let settings = SimSettings {
        rudder: if a.zero_sideslip {
            Rudder::ZeroSideslip
        } else {
            Rudder::Fixed(0.0)
        },
        t_end,
        ..SimSettings::step(
            model,
            elevator_of(&ac, a.delta_e_deg)?,
            finite_angle("delta_a", delta_a_deg)?,
        )
    };
    let h = simulate(&ac, &settings).map_err(|e| match e {
        // In the unit typed.
        SimError::ScheduleRange { lo, hi, .. } => named(
            &ac,
            format!(
                "--delta-a-deg = {delta_a_deg} is outside the zero-sideslip rudder \
                 schedule, which covers {} to {} deg",
                lo.to_degrees(),
                hi.to_degrees()
            ),
        ),
        e => named(&ac, e),
    })?;
    if let Some(path) = &a.csv {
        write_file(path, h.to_csv().as_bytes())?;
    }
    let st = h.steady(5.0_f64.min(t_end / 2.0));
    say!(
        out,
        "{} ({}), aileron step {delta_a_deg} deg, {} s: steady roll rate {} rad/s (range {} to {}), mean sideslip {} deg, peak |sideslip| {} deg",
        shown(&ac.name),
        model.name(),
        t_end,
        fixed(st.p_mean, 4),
        fixed(st.p_min, 4),
        fixed(st.p_max, 4),
        fixed(st.beta_mean.to_degrees(), 3),
        fixed(st.beta_peak_abs.to_degrees(), 3)
    );
    Ok(ExitCode::SUCCESS)
}

/// `model clear`: for each elevator setting the Monte Carlo and the proof
/// ([`crate::clearance::run::clear_each`]), printed as text or JSON, and with `--out` the
/// folder of summaries, samples and figures.
pub fn clear_command(a: &ClearArgs, out: &mut dyn Write) -> Result<ExitCode, Failure> {
    let ac = load_aircraft(&a.aircraft)?;
    let settings: Vec<f64> = match &a.delta_e_range {
        Some(r) => delta_e_list(r)?,
        None => vec![elevator_of(&ac, a.delta_e_deg)?],
    };
    let (samples, tolerance) = (a.samples, a.tolerance);
    if !(tolerance.is_finite() && tolerance > 0.0) {
        return Err(Failure::Input(format!(
            "--tolerance = {tolerance}: expected a finite tolerance > 0 in rad/s"
        )));
    }
    // Each sample's draws and result are kept (samples.csv): about 300 bytes apiece.
    const MAX_SAMPLES: usize = 10_000_000;
    if samples > MAX_SAMPLES {
        return Err(Failure::Input(format!(
            "--samples = {samples}: expected 0 to {MAX_SAMPLES} Monte Carlo samples"
        )));
    }
    let bar = progress_bar("clear");
    let runs = crate::clearance::run::clear_each(
        &ac,
        &settings,
        (samples, a.seed, tolerance),
        &mut |f| set(&bar, f),
        &mut |k, seconds| {
            if k == 0 && settings.len() > 1 {
                say_how_long(settings.len(), seconds);
            }
        },
    )
    .map_err(|e| named(&ac, e))?;
    if let Some(b) = bar {
        b.finish_and_clear();
    }
    let text = serde_json::to_string_pretty(
        &if runs.len() == 1 {
            serde_json::to_value(&runs[0])
        } else {
            serde_json::to_value(&runs)
        }
        .map_err(|e| e.to_string())?,
    )
    .map_err(|e| e.to_string())?;
    // The result first, so that a proof of up to a minute is not lost to a failing --out; the
    // files are written even when stdout is closed (the quiet end of a closed pipe comes after
    // them).
    let printed = if a.json {
        writeln!(out, "{text}")
    } else {
        runs.iter()
            .try_for_each(|r| write!(out, "{}", super::clearance::text(r)))
    }
    .and_then(|()| out.flush())
    .map_err(stdout_error);
    if let Some(dir) = &a.out {
        super::clearance::write_folder(dir, &runs, &text).map_err(Failure::Output)?;
    }
    printed?;
    Ok(ExitCode::SUCCESS)
}

/// `model convert`: the dimensional principal-axis TOML of a nondimensional body-axis file.
pub fn convert_command(a: &ConvertArgs, out: &mut dyn Write) -> Result<ExitCode, Failure> {
    let text = aircraft::convert_file(&a.file).map_err(|e| e.to_string())?;
    write!(out, "{text}").map_err(stdout_error)?;
    Ok(ExitCode::SUCCESS)
}

/// `model emit`: writes the generated crate and docs/formulas.tex under the workspace root, or
/// with `--check` writes nothing and names every stale file (exit 1).
pub fn emit_command(a: &EmitArgs, out: &mut dyn Write) -> Result<ExitCode, Failure> {
    let root = a
        .root
        .clone()
        .unwrap_or_else(|| Path::new(env!("CARGO_MANIFEST_DIR")).join(".."));
    let outputs = crate::emit::generate().map_err(|e| e.to_string())?;
    if a.check {
        crate::emit::tidy(&root, &outputs)
            .map_err(|e| Failure::Output(format!("cannot tidy {}: {e}", root.display())))?;
        let stale = crate::emit::stale(&root, &outputs);
        if stale.is_empty() {
            say!(out, "{} generated files are up to date", outputs.len());
            return Ok(ExitCode::SUCCESS);
        }
        out.flush().map_err(stdout_error)?;
        let mut err = std::io::stderr();
        for p in &stale {
            let _ = writeln!(err, "stale: {}", p.display());
        }
        let _ = writeln!(err, "run `{}` to regenerate", crate::emit::COMMAND);
        return Ok(ExitCode::from(FAILED));
    }
    let written =
        crate::emit::write(&root, &outputs).map_err(|e| Failure::Output(e.to_string()))?;
    for o in &outputs {
        let state = if written.contains(&o.path) {
            "wrote"
        } else {
            "unchanged"
        };
        say!(out, "{state:>9} {}", o.path.display());
    }
    Ok(ExitCode::SUCCESS)
}
