//! One function per command of `model`: each loads the aircraft, checks the options' values,
//! computes through the library (analysis, continuation, report, simulation, clearance, emit)
//! and prints to `out` (stdout) or writes the requested files. `main.rs` parses the arguments
//! and calls one of these; each returns the exit code or why it did not finish.

use super::failure::{named, stdout_error, write_file, Failure, FAILED};
use super::numbers::fixed;
use super::options::{
    delta_e_list, elevator_of, finite_angle, load_aircraft, read_aircraft, AnalyzeArgs, ClearArgs,
    ContinueArgs, ConvertArgs, EmitArgs, FiguresArgs, SimulateArgs,
};
use super::outputs::{begin_folder, commit_folder, default_folder, wrote};
use super::progress::{progress_bar, say_how_long, set};
use super::report::{report, ReportError, ReportSettings};
use crate::aircraft::{self, shown, Aircraft};
use crate::analysis::fast::{analyze_routed_with, Route};
use crate::analysis::{analyze, Analysis};
use crate::clearance::run::Run;
use crate::continuation::{continue_equilibria, ContinuationParam, Diagram, Settings};
use crate::simulation::{simulate, Model, Rudder, SimError, SimSettings, TimeHistory};
use std::io::Write;
use std::path::{Path, PathBuf};
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
pub struct Routed<'a> {
    #[serde(flatten)]
    analysis: &'a Analysis,
    #[serde(skip_serializing_if = "Option::is_none")]
    route: Option<&'static str>,
    #[serde(skip_serializing_if = "Option::is_none")]
    fallback: Option<&'static str>,
}

impl<'a> Routed<'a> {
    /// `analysis` with the route that answered it (none on the exact path by request).
    pub fn new(analysis: &'a Analysis, route: Option<Route>) -> Routed<'a> {
        Routed {
            analysis,
            route: route.map(Route::name),
            fallback: route.and_then(Route::fallback),
        }
    }
}

/// `model analyze`: the table of the certified route (the exact path with `--exact`), or JSON
/// of the exact path (the certified route's with `--certified`).
pub fn analyze_command(a: &AnalyzeArgs, out: &mut dyn Write) -> Result<ExitCode, Failure> {
    // The text carries the aircraft's warnings itself; JSON carries them as a field, and they
    // go to stderr as well.
    let ac = if a.json {
        load_aircraft(&a.aircraft)?
    } else {
        read_aircraft(&a.aircraft)?
    };
    let (result, route) = routed_analysis_of(&ac, a)?;
    if a.json {
        let routed = Routed::new(&result, route);
        let text = serde_json::to_string_pretty(&routed).map_err(|e| e.to_string())?;
        say!(out, "{text}");
    } else {
        write!(out, "{}", super::tables::analysis(&result, a.all)).map_err(stdout_error)?;
    }
    Ok(ExitCode::SUCCESS)
}

/// What `model analyze` computes for `ac` with the options of `a` (the aircraft loaded by the
/// caller): the exact path for `--exact` and for `--json` without `--certified`, else the
/// certified route.
pub fn analysis_of(ac: &Aircraft, a: &AnalyzeArgs) -> Result<Analysis, Failure> {
    routed_analysis_of(ac, a).map(|(analysis, _)| analysis)
}

/// [`analysis_of`] and the route that answered it (none on the exact path by request).
pub fn routed_analysis_of(
    ac: &Aircraft,
    a: &AnalyzeArgs,
) -> Result<(Analysis, Option<Route>), Failure> {
    let delta_e = elevator_of(ac, a.delta_e_deg)?;
    if a.exact || (a.json && !a.certified) {
        analyze(ac, delta_e).map(|r| (r, None))
    } else {
        analyze_routed_with(ac, delta_e, true).map(|(r, route)| (r, Some(route)))
    }
    .map_err(|e| named(ac, e))
}

/// `model continue`: the continuation's diagram as a summary or JSON, and as CSV with `--csv`.
pub fn continue_command(a: &ContinueArgs, out: &mut dyn Write) -> Result<ExitCode, Failure> {
    let ac = load_aircraft(&a.aircraft)?;
    let bar = progress_bar("continuation");
    let diagram = diagram_of(&ac, a, &mut |f| set(&bar, f))?;
    if let Some(b) = bar {
        b.finish_and_clear();
    }
    if let Some(path) = &a.csv {
        write_file(path, diagram.to_csv().as_bytes())?;
        wrote(path, "every point of the continuation as CSV");
    }
    if a.json {
        let text = serde_json::to_string_pretty(&diagram).map_err(|e| e.to_string())?;
        say!(out, "{text}");
    } else {
        write!(out, "{}", super::tables::diagram(&diagram)).map_err(stdout_error)?;
    }
    Ok(ExitCode::SUCCESS)
}

/// What `model continue` computes for `ac` with the options of `a`; `progress` gets the
/// fraction done.
pub fn diagram_of(
    ac: &Aircraft,
    a: &ContinueArgs,
    progress: &mut dyn FnMut(f64),
) -> Result<Diagram, Failure> {
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
        delta_e: elevator_of(ac, a.delta_e_deg)?,
        zero_sideslip: a.zero_sideslip,
        ..Settings::default()
    };
    continue_equilibria(ac, &settings, progress).map_err(|e| named(ac, e))
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
    let command = if summary { "report" } else { "plot" };
    let bar = progress_bar(command);
    let written = figures_of(&ac, a, summary, &mut |f| set(&bar, f));
    if let Some(b) = bar {
        b.finish_and_clear();
    }
    let written = written?;
    for k in &written.skipped {
        say!(out, "skipped: {}", shown(k));
    }
    if written.failed.is_empty() {
        return Ok(ExitCode::SUCCESS);
    }
    // The folder is not put in place: the previous run's stays as it was.
    out.flush().map_err(stdout_error)?;
    let mut err = std::io::stderr();
    for f in &written.failed {
        let _ = writeln!(err, "error: {f}");
    }
    Ok(ExitCode::from(FAILED))
}

/// What `model report` or `model plot` wrote.
pub struct Figures {
    /// The folder (in place only when `failed` is empty).
    pub folder: PathBuf,
    /// The sections skipped, each with its reason.
    pub skipped: Vec<String>,
    /// The files that could not be written: `cannot write PATH: reason`.
    pub failed: Vec<String>,
}

/// What `model report` (`summary`) or `model plot` writes for `ac` with the options of `a` (the
/// aircraft loaded by the caller, `a.aircraft` naming the default folder): the folder is put in
/// place when every file was written; `progress` gets the fraction done.
pub fn figures_of(
    ac: &Aircraft,
    a: &FiguresArgs,
    summary: bool,
    progress: &mut dyn FnMut(f64),
) -> Result<Figures, Failure> {
    let command = if summary { "report" } else { "plot" };
    let settings = ReportSettings {
        summary,
        ..ReportSettings::new(elevator_of(ac, a.delta_e_deg)?)
    };
    let target = a
        .out
        .clone()
        .unwrap_or_else(|| default_folder(command, &a.aircraft));
    let staged = begin_folder(&target, command)?;
    let result = report(ac, staged.path(), &settings, progress).map_err(|e| match e {
        ReportError::Io { .. } => Failure::Output(e.to_string()),
        e => named(ac, e),
    })?;
    let failed: Vec<String> = result
        .failed_files
        .iter()
        .map(|f| {
            let rel = f.path.strip_prefix(staged.path()).unwrap_or(&f.path);
            format!(
                "cannot write {}: {}",
                staged.target().join(rel).display(),
                f.reason
            )
        })
        .collect();
    if failed.is_empty() {
        commit_folder(staged)?;
    }
    Ok(Figures {
        folder: target,
        skipped: result.skipped,
        failed,
    })
}

/// `model simulate`: one aileron step's steady state in a line, and the time history as CSV
/// with `--csv`.
pub fn simulate_command(a: &SimulateArgs, out: &mut dyn Write) -> Result<ExitCode, Failure> {
    if a.six_dof {
        return super::six_dof::command(a, out);
    }
    let ac = load_aircraft(&a.aircraft)?;
    let (h, model) = history_of(&ac, a)?;
    if let Some(path) = &a.csv {
        write_file(path, h.to_csv().as_bytes())?;
        wrote(path, "the time history as CSV");
    }
    let (t_end, delta_a_deg) = (a.t_end, a.delta_a_deg);
    let st = h.steady(steady_window(t_end));
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

/// The window of the steady values `model simulate` prints, s: the last 5 s of the run, or its
/// second half when shorter.
pub fn steady_window(t_end: f64) -> f64 {
    5.0_f64.min(t_end / 2.0)
}

/// What `model simulate` computes for `ac` with the options of `a`: the time history and the
/// model integrated.
pub fn history_of(ac: &Aircraft, a: &SimulateArgs) -> Result<(TimeHistory, Model), Failure> {
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
            elevator_of(ac, a.delta_e_deg)?,
            finite_angle("delta_a", delta_a_deg)?,
        )
    };
    let h = simulate(ac, &settings).map_err(|e| match e {
        // In the unit typed.
        SimError::ScheduleRange { lo, hi, .. } => named(
            ac,
            format!(
                "--delta-a-deg = {delta_a_deg} is outside the zero-sideslip rudder \
                 schedule, which covers {} to {} deg",
                lo.to_degrees(),
                hi.to_degrees()
            ),
        ),
        e => named(ac, e),
    })?;
    Ok((h, model))
}

/// The smallest `--tolerance` of `clear`, rad/s. The proof's bounds are f64 interval enclosures:
/// on the shipped box of aircraft A (P0 = 1.57 rad/s) the roll-rate gap closes to 4e-14 rad/s at
/// `--tolerance 1e-13` in a second, while at 1e-14 it runs on (over a minute) without closing.
/// 1e-12 leaves a margin of ten for larger roll rates.
pub const MIN_TOLERANCE: f64 = 1e-12;

/// `model clear`: for each elevator setting the Monte Carlo and the proof
/// ([`crate::clearance::run::clear_each`]), printed as text or JSON, and with `--out` the
/// folder of summaries, samples and figures.
pub fn clear_command(a: &ClearArgs, out: &mut dyn Write) -> Result<ExitCode, Failure> {
    let ac = load_aircraft(&a.aircraft)?;
    let staged = a
        .out
        .as_ref()
        .map(|dir| begin_folder(dir, "clear"))
        .transpose()?;
    let bar = progress_bar("clear");
    let runs = runs_of(&ac, a, &mut |f| set(&bar, f))?;
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
    if let Some(staged) = staged {
        super::clearance::write_folder(staged.path(), &runs, &text).map_err(Failure::Output)?;
        commit_folder(staged)?;
    }
    printed?;
    Ok(ExitCode::SUCCESS)
}

/// What `model clear` computes for `ac` with the options of `a`: one run per elevator setting;
/// `progress` gets the fraction done over all settings.
pub fn runs_of(
    ac: &Aircraft,
    a: &ClearArgs,
    progress: &mut dyn FnMut(f64),
) -> Result<Vec<Run>, Failure> {
    let settings: Vec<f64> = match &a.delta_e_range {
        Some(r) => delta_e_list(r)?,
        None => vec![elevator_of(ac, a.delta_e_deg)?],
    };
    let (samples, tolerance) = (a.samples, a.tolerance);
    if !(tolerance.is_finite() && tolerance >= MIN_TOLERANCE) {
        return Err(Failure::Input(format!(
            "--tolerance = {tolerance:e}: expected a finite tolerance of at least \
             {MIN_TOLERANCE:e} rad/s, the smallest gap the proof can close (its bounds are f64 \
             interval enclosures of roll rates of order 1 rad/s, which resolve them to about \
             1e-13 rad/s, a few hundred f64 steps)"
        )));
    }
    // Each sample's draws and result are kept (samples.csv): about 300 bytes apiece.
    const MAX_SAMPLES: usize = 10_000_000;
    if samples > MAX_SAMPLES {
        return Err(Failure::Input(format!(
            "--samples = {samples}: expected 0 to {MAX_SAMPLES} Monte Carlo samples"
        )));
    }
    crate::clearance::run::clear_each(
        ac,
        &settings,
        (samples, a.seed, tolerance),
        progress,
        &mut |k, seconds| {
            if k == 0 && settings.len() > 1 {
                say_how_long(settings.len(), seconds);
            }
        },
    )
    .map_err(|e| named(ac, e))
}

/// `model convert`: the dimensional principal-axis TOML of a nondimensional body-axis file or
/// of a `jsbsim:` source (the file its import writes).
pub fn convert_command(a: &ConvertArgs, out: &mut dyn Write) -> Result<ExitCode, Failure> {
    let text = if a.file.starts_with("jsbsim:") {
        let imported = crate::jsbsim::cli::source_text(&a.file)?;
        aircraft::convert_text(&imported, &a.file)
    } else {
        aircraft::convert_file(Path::new(&a.file))
    }
    .map_err(|e| e.to_string())?;
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
