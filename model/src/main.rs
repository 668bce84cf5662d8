//! `model`: the command-line front end. Argument parsing and printing only.

use clap::{CommandFactory, FromArgMatches, Parser, Subcommand};
use model::aircraft::{self, Aircraft};
use model::analysis::analyze;
use model::analysis::fast::analyze_routed_with;
use model::continuation::{continue_equilibria, ContinuationParam, Settings};
use model::present::report::{fixed, report, ReportError, ReportSettings};
use model::simulation::{simulate, Model, Rudder, SimError, SimSettings};
use std::io::Write;
use std::path::Path;
use std::process::ExitCode;

/// The allocator of the command-line tool. The certified route, the Monte Carlo and the branch
/// and bound allocate many small, short-lived vectors on every core; under glibc's allocator
/// malloc and free were about a fifth of the certified `analyze`'s instructions (callgrind),
/// under mimalloc far less. The library sets no allocator: programs that embed it choose their
/// own.
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

#[derive(Parser)]
#[command(
    name = "model",
    version,
    about = "Roll-coupling jump criterion (Mahale & Ananthkrishnan, AIAA 2006-6267)",
    after_help = "AIRCRAFT is `A` or `B` (the paper's aircraft, any case) or else the path of an \
                  aircraft TOML file (e.g. aircraft/c.toml); write ./A to read a file named A. \
                  \"jsbsim:MODEL --altitude-m H --mach M --level-flight\" (the arguments of \
                  `import jsbsim`, quoted as one) imports a JSBSim model at that condition."
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Divergence and jump roll rates, det K poles and zero-sideslip departure of an aircraft.
    Analyze {
        /// `A` or `B` (the paper's aircraft), else the path of an aircraft TOML file.
        aircraft: String,
        /// Elevator deflection in degrees.
        #[arg(long, default_value_t = 2.0, allow_hyphen_values = true)]
        delta_e_deg: f64,
        /// Print JSON instead of a table. JSON carries every digit of every number, so it comes
        /// from the exact path (correctly rounded roots) unless the table's route is asked for
        /// with --certified.
        #[arg(long)]
        json: bool,
        /// Force the exact (big-rational) path; by default the table comes from the certified
        /// floating-point route, which falls back to the exact path whenever a certificate fails.
        #[arg(long, conflicts_with = "certified")]
        exact: bool,
        /// With --json: the certified route's numbers (each roll rate within its certified bracket
        /// of about 1e-10 relative width, the trim evaluated from the enclosures' midpoints, so
        /// the last digits differ from the exact path's).
        #[arg(long)]
        certified: bool,
    },
    /// Continuation of the PSS equilibria: every branch, folds, Hopf and branch points (Figs 1-4, 9).
    Continue {
        /// `A` or `B` (the paper's aircraft), else the path of an aircraft TOML file.
        aircraft: String,
        /// The continuation parameter: delta_a, delta_e or delta_r.
        #[arg(long, default_value = "delta_a")]
        param: String,
        /// Lower end of the parameter range, deg (default -0.8 rad).
        #[arg(long, default_value_t = -45.8366, allow_hyphen_values = true)]
        min_deg: f64,
        /// Upper end of the parameter range, deg (default 0.8 rad).
        #[arg(long, default_value_t = 45.8366, allow_hyphen_values = true)]
        max_deg: f64,
        /// Elevator deflection in degrees (when it is not the parameter).
        #[arg(long, default_value_t = 2.0, allow_hyphen_values = true)]
        delta_e_deg: f64,
        /// Zero-sideslip manoeuvre by extended bifurcation analysis (section V.B, Fig. 9).
        #[arg(long)]
        zero_sideslip: bool,
        /// Print JSON instead of a summary.
        #[arg(long)]
        json: bool,
        /// Also write every point as CSV to this file (units in the header).
        #[arg(long, value_name = "FILE")]
        csv: Option<std::path::PathBuf>,
    },
    /// Every result of the paper for an aircraft in DIR: Figs 1-11 (SVG, PNG and the plotted
    /// data as CSV), summary.md and summary.json.
    Report {
        /// `A` or `B` (the paper's aircraft), else the path of an aircraft TOML file.
        aircraft: String,
        /// Output folder DIR (created if needed).
        #[arg(long, value_name = "DIR")]
        out: std::path::PathBuf,
        /// Elevator deflection in degrees.
        #[arg(long, default_value_t = 2.0, allow_hyphen_values = true)]
        delta_e_deg: f64,
    },
    /// Figs 1-11 only (SVG, PNG and the plotted data as CSV) in DIR, without the summary.
    Plot {
        /// `A` or `B` (the paper's aircraft), else the path of an aircraft TOML file.
        aircraft: String,
        /// Output folder DIR (created if needed).
        #[arg(long, value_name = "DIR")]
        out: std::path::PathBuf,
        /// Elevator deflection in degrees.
        #[arg(long, default_value_t = 2.0, allow_hyphen_values = true)]
        delta_e_deg: f64,
    },
    /// Time history of an aileron step from the trim (7th-order model unless --pss).
    Simulate {
        /// `A` or `B` (the paper's aircraft), else the path of an aircraft TOML file.
        aircraft: String,
        /// Aileron step, degrees.
        #[arg(long, allow_hyphen_values = true)]
        delta_a_deg: f64,
        /// Elevator deflection in degrees.
        #[arg(long, default_value_t = 2.0, allow_hyphen_values = true)]
        delta_e_deg: f64,
        /// Length of the run, s.
        #[arg(long, default_value_t = 20.0, allow_hyphen_values = true)]
        t_end: f64,
        /// Rudder on the zero-sideslip schedule (aileron-rudder interconnect, Fig. 10).
        #[arg(long)]
        zero_sideslip: bool,
        /// Integrate the PSS model instead of the 7th-order model.
        #[arg(long)]
        pss: bool,
        /// Write the time history as CSV to this file (units in the header).
        #[arg(long, value_name = "FILE")]
        csv: Option<std::path::PathBuf>,
    },
    /// Certified clearance of the critical jump over the file's `[uncertainty]` box.
    Clear {
        /// Path of an aircraft TOML file with an `[uncertainty]` table (or `A`/`B`: a point).
        aircraft: String,
        /// Elevator deflection in degrees.
        #[arg(
            long,
            default_value_t = 2.0,
            allow_hyphen_values = true,
            conflicts_with = "delta_e_range"
        )]
        delta_e_deg: f64,
        /// A range of elevator deflections `A:B:STEP` in degrees (a clearance map).
        #[arg(long, value_name = "A:B:STEP", allow_hyphen_values = true)]
        delta_e_range: Option<String>,
        /// Monte Carlo samples (certified route; the exact path where a certificate fails), 0
        /// to 10^7 per setting.
        #[arg(long, default_value_t = 1000, allow_hyphen_values = true)]
        samples: usize,
        /// Tolerance on the roll-rate gap, rad/s (the aileron gap is 10 times it, in deg).
        #[arg(long, default_value_t = 1e-3, allow_hyphen_values = true)]
        tolerance: f64,
        /// Seed of the Monte Carlo samples and of the worst-case search.
        #[arg(long, default_value_t = 1, allow_hyphen_values = true)]
        seed: u64,
        /// Print JSON instead of text.
        #[arg(long)]
        json: bool,
        /// Write summary.md, summary.json and samples.csv into DIR.
        #[arg(long, value_name = "DIR")]
        out: Option<std::path::PathBuf>,
    },
    /// Print the dimensional principal-axis TOML equivalent to a nondimensional body-axis file.
    Convert {
        /// Path of a nondimensional body-axis aircraft TOML file.
        file: std::path::PathBuf,
    },
    /// Write an aircraft file from another tool's model: `import jsbsim <MODEL> --altitude-m H
    /// (--mach M | --speed V) (--alpha-deg A | --level-flight) [--set PROPERTY=VALUE]...
    /// [--out FILE] [--jsbsim-root DIR]`, or `import jsbsim --list`.
    #[command(disable_help_flag = true)]
    Import {
        /// The source (`jsbsim`) and its arguments.
        #[arg(trailing_var_arg = true, allow_hyphen_values = true, num_args = 0..)]
        args: Vec<String>,
    },
    /// Write the generated criterion crate (generated/) and docs/formulas.tex.
    Emit {
        /// Write nothing; exit 1 naming every stale file (first finishes an emit that was killed
        /// after staging every file, and removes temporaries of killed runs).
        #[arg(long)]
        check: bool,
        /// Workspace root (default: the workspace this binary was built from).
        #[arg(long, value_name = "DIR")]
        root: Option<std::path::PathBuf>,
    },
}

/// Exit code for bad input (file, key or value), as for clap's usage errors.
const BAD_INPUT: u8 = 2;

/// Exit code of `emit --check` when outputs are stale, and of a requested output that could not
/// be written.
const FAILED: u8 = 1;

/// Why a command did not finish.
enum Failure {
    /// Bad input: file, key or value (exit 2).
    Input(String),
    /// An output could not be written (exit 1).
    Output(String),
    /// stdout was closed by its reader (`| head`): end quietly, like other Unix tools.
    Closed,
}

impl From<String> for Failure {
    fn from(msg: String) -> Failure {
        Failure::Input(msg)
    }
}

/// A write to stdout failed.
fn stdout_error(e: std::io::Error) -> Failure {
    if e.kind() == std::io::ErrorKind::BrokenPipe {
        Failure::Closed
    } else {
        Failure::Output(format!("cannot write to stdout: {e}"))
    }
}

/// Prints to `out` (stdout), turning a write error into a [`Failure`].
macro_rules! say {
    ($out:expr, $($arg:tt)*) => {
        writeln!($out, $($arg)*).map_err(stdout_error)?
    };
}

fn main() -> ExitCode {
    use std::io::IsTerminal;
    // Colour only on a terminal (clap would also colour in CI logs, where CI is set).
    let tty = std::io::stdout().is_terminal() && std::io::stderr().is_terminal();
    let color = if tty {
        clap::ColorChoice::Auto
    } else {
        clap::ColorChoice::Never
    };
    let cli = Cli::command()
        .color(color)
        .try_get_matches()
        .and_then(|m| Cli::from_arg_matches(&m));
    let cli = match cli {
        Ok(cli) => cli,
        Err(e) => {
            let code = e.exit_code();
            // Help and version go to stdout; a closed pipe there is not an error.
            let _ = e.print();
            return ExitCode::from(u8::try_from(code).unwrap_or(BAD_INPUT));
        }
    };
    let mut out = std::io::BufWriter::new(std::io::stdout().lock());
    let result = run(cli, &mut out).and_then(|code| {
        out.flush().map_err(stdout_error)?;
        Ok(code)
    });
    let (msg, code) = match result {
        Ok(code) => return code,
        Err(Failure::Closed) => return ExitCode::SUCCESS,
        Err(Failure::Input(msg)) => (msg, BAD_INPUT),
        Err(Failure::Output(msg)) => (msg, FAILED),
    };
    // What was printed before the failure still goes out (ignoring a second failure).
    let _ = out.flush();
    let _ = writeln!(std::io::stderr(), "error: {msg}");
    ExitCode::from(code)
}

fn run(cli: Cli, out: &mut dyn Write) -> Result<ExitCode, Failure> {
    let summary = matches!(cli.command, Command::Report { .. });
    match cli.command {
        Command::Analyze {
            aircraft,
            delta_e_deg,
            json,
            exact,
            certified,
        } => {
            let ac = load_aircraft(&aircraft)?;
            let delta_e = elevator(delta_e_deg)?;
            let result = if exact || (json && !certified) {
                analyze(&ac, delta_e)
            } else {
                analyze_routed_with(&ac, delta_e, true).map(|(a, _)| a)
            }
            .map_err(|e| named(&ac, e))?;
            if json {
                let text = serde_json::to_string_pretty(&result).map_err(|e| e.to_string())?;
                say!(out, "{text}");
            } else {
                write!(out, "{}", model::present::tables::analysis(&result))
                    .map_err(stdout_error)?;
            }
            Ok(ExitCode::SUCCESS)
        }
        Command::Continue {
            aircraft,
            param,
            min_deg,
            max_deg,
            delta_e_deg,
            zero_sideslip,
            json,
            csv,
        } => {
            let ac = load_aircraft(&aircraft)?;
            let (min, max) = (finite_angle("min", min_deg)?, finite_angle("max", max_deg)?);
            if min_deg >= max_deg {
                return Err(Failure::Input(format!(
                    "--min-deg = {min_deg} and --max-deg = {max_deg}: expected the lower end of \
                     the parameter range below the upper end, in deg"
                )));
            }
            let settings = Settings {
                param: param
                    .parse::<ContinuationParam>()
                    .map_err(|e| e.to_string())?,
                min,
                max,
                delta_e: elevator(delta_e_deg)?,
                zero_sideslip,
                ..Settings::default()
            };
            let bar = progress_bar("continuation");
            let diagram = continue_equilibria(&ac, &settings, &mut |f| {
                if let Some(b) = &bar {
                    b.set_position((f * 1000.0) as u64);
                }
            })
            .map_err(|e| named(&ac, e))?;
            if let Some(b) = bar {
                b.finish_and_clear();
            }
            if let Some(path) = csv {
                write_file(&path, diagram.to_csv().as_bytes())?;
            }
            if json {
                let text = serde_json::to_string_pretty(&diagram).map_err(|e| e.to_string())?;
                say!(out, "{text}");
            } else {
                write!(out, "{}", model::present::tables::diagram(&diagram))
                    .map_err(stdout_error)?;
            }
            Ok(ExitCode::SUCCESS)
        }
        Command::Report {
            aircraft,
            out: dir,
            delta_e_deg,
        }
        | Command::Plot {
            aircraft,
            out: dir,
            delta_e_deg,
        } => {
            let ac = load_aircraft(&aircraft)?;
            let settings = ReportSettings {
                summary,
                ..ReportSettings::new(elevator(delta_e_deg)?)
            };
            let bar = progress_bar(if summary { "report" } else { "plot" });
            let result = report(&ac, &dir, &settings, &mut |f| {
                if let Some(b) = &bar {
                    b.set_position((f * 1000.0) as u64);
                }
            });
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
        Command::Simulate {
            aircraft,
            delta_a_deg,
            delta_e_deg,
            t_end,
            zero_sideslip,
            pss,
            csv,
        } => {
            let ac = load_aircraft(&aircraft)?;
            if !(t_end.is_finite() && t_end > 0.0) {
                return Err(Failure::Input(format!(
                    "--t-end = {t_end}: expected the length of the run, a positive finite number \
                     of seconds"
                )));
            }
            let model = if pss { Model::Pss } else { Model::SeventhOrder };
            let settings = SimSettings {
                rudder: if zero_sideslip {
                    Rudder::ZeroSideslip
                } else {
                    Rudder::Fixed(0.0)
                },
                t_end,
                ..SimSettings::step(
                    model,
                    elevator(delta_e_deg)?,
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
            if let Some(path) = csv {
                write_file(&path, h.to_csv().as_bytes())?;
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
        Command::Clear {
            aircraft,
            delta_e_deg,
            delta_e_range,
            samples,
            tolerance,
            seed,
            json,
            out: dir,
        } => {
            let ac = load_aircraft(&aircraft)?;
            let settings: Vec<f64> = match delta_e_range {
                Some(r) => delta_e_list(&r)?,
                None => vec![elevator(delta_e_deg)?],
            };
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
            let runs = model::clearance::run::clear_each(
                &ac,
                &settings,
                (samples, seed, tolerance),
                &mut |f| {
                    if let Some(b) = &bar {
                        b.set_position((1000.0 * f) as u64);
                    }
                },
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
            // The result first, so that a proof of up to a minute is not lost to a failing
            // --out; the files are written even when stdout is closed (the quiet end of a
            // closed pipe comes after them).
            let printed = if json {
                writeln!(out, "{text}")
            } else {
                runs.iter()
                    .try_for_each(|r| write!(out, "{}", model::present::clearance::text(r)))
            }
            .and_then(|()| out.flush())
            .map_err(stdout_error);
            if let Some(dir) = dir {
                model::present::clearance::write_folder(&dir, &runs, &text)
                    .map_err(Failure::Output)?;
            }
            printed?;
            Ok(ExitCode::SUCCESS)
        }
        Command::Import { args } => Ok(ExitCode::from(model::jsbsim::cli::run(&args, out))),
        Command::Convert { file } => {
            let text = aircraft::convert_file(&file).map_err(|e| e.to_string())?;
            write!(out, "{text}").map_err(stdout_error)?;
            Ok(ExitCode::SUCCESS)
        }
        Command::Emit { check, root } => {
            let root = root.unwrap_or_else(|| Path::new(env!("CARGO_MANIFEST_DIR")).join(".."));
            let outputs = model::emit::generate().map_err(|e| e.to_string())?;
            if check {
                model::emit::tidy(&root, &outputs)
                    .map_err(|e| Failure::Output(format!("cannot tidy {}: {e}", root.display())))?;
                let stale = model::emit::stale(&root, &outputs);
                if stale.is_empty() {
                    say!(out, "{} generated files are up to date", outputs.len());
                    return Ok(ExitCode::SUCCESS);
                }
                out.flush().map_err(stdout_error)?;
                let mut err = std::io::stderr();
                for p in &stale {
                    let _ = writeln!(err, "stale: {}", p.display());
                }
                let _ = writeln!(err, "run `{}` to regenerate", model::emit::COMMAND);
                return Ok(ExitCode::from(FAILED));
            }
            let written =
                model::emit::write(&root, &outputs).map_err(|e| Failure::Output(e.to_string()))?;
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
    }
}

/// An error of a computation for `ac`, prefixed with its (escaped) name.
fn named(ac: &Aircraft, e: impl std::fmt::Display) -> Failure {
    Failure::Input(format!("{}: {e}", shown(&ac.name)))
}

/// Writes a requested output file (`--csv`): see [`model::files::write_output`].
fn write_file(path: &Path, contents: &[u8]) -> Result<(), Failure> {
    model::files::write_output(path, contents).map_err(|e| {
        if e.kind() == std::io::ErrorKind::BrokenPipe {
            // `--csv /dev/stdout | head`: as for stdout itself.
            Failure::Closed
        } else {
            Failure::Output(format!("cannot write {}: {e}", path.display()))
        }
    })
}

/// `name` with control characters escaped (`\u{1b}`, `\n`, ...), safe to print on a terminal.
fn shown(name: &str) -> String {
    aircraft::shown(name)
}

/// An elevator deflection in degrees converted to rad, or an error in degrees.
fn elevator(deg: f64) -> Result<f64, Failure> {
    if deg.is_finite() && deg.abs() <= 90.0 {
        Ok(deg.to_radians())
    } else {
        Err(Failure::Input(format!(
            "--delta-e-deg = {deg}: expected a finite elevator deflection of at most 90 deg \
             (delta_e)"
        )))
    }
}

/// Tells on stderr, once the first of `n` elevator settings took `first_s` seconds, how long
/// the others will take at that pace (each proof is bounded by its budgets of work, so a map
/// of many settings can take minutes).
fn say_how_long(n: usize, first_s: f64) {
    let rest = first_s * (n - 1) as f64;
    let _ = writeln!(
        std::io::stderr(),
        "clear: {n} elevator settings; the first took {first_s:.1} s, so the other {} will \
         take about {} at that pace",
        n - 1,
        if rest < 120.0 {
            format!("{rest:.0} s")
        } else {
            format!("{:.1} min", rest / 60.0)
        }
    );
}

/// `A:B:STEP` in degrees as the list of elevator deflections in rad.
fn delta_e_list(r: &str) -> Result<Vec<f64>, Failure> {
    let bad = || {
        Failure::Input(format!(
            "--delta-e-range = {r:?}: expected A:B:STEP in degrees with A <= B, STEP > 0, at most \
             1000 settings, each of at most 90 deg"
        ))
    };
    let v: Vec<f64> = r
        .split(':')
        .map(|x| x.trim().parse::<f64>())
        .collect::<Result<_, _>>()
        .map_err(|_| bad())?;
    let [a, b, step] = v[..] else {
        return Err(bad());
    };
    if !(a <= b && step > 0.0 && ((b - a) / step) < 1000.0) {
        return Err(bad());
    }
    let n = ((b - a) / step + 1e-9).floor() as usize;
    (0..=n)
        .map(|i| elevator(a + i as f64 * step).map_err(|_| bad()))
        .collect()
}

/// An angle in degrees converted to rad, or an error naming the option.
fn finite_angle(name: &str, deg: f64) -> Result<f64, Failure> {
    if deg.is_finite() {
        Ok(deg.to_radians())
    } else {
        Err(Failure::Input(format!(
            "--{}-deg = {deg}: expected a finite angle in degrees",
            name.replace('_', "-")
        )))
    }
}

/// A progress bar on stderr when it is a terminal; nothing when piped.
fn progress_bar(what: &str) -> Option<indicatif::ProgressBar> {
    use std::io::IsTerminal;
    if !std::io::stderr().is_terminal() {
        return None;
    }
    let bar = indicatif::ProgressBar::new(1000);
    if let Ok(style) = indicatif::ProgressStyle::with_template("{msg} [{bar:40}] {percent}%") {
        bar.set_style(style.progress_chars("=> "));
    }
    bar.set_message(what.to_string());
    Some(bar)
}

/// `A`/`B` (any case) name the built-in aircraft; anything else is a TOML file. A name that is
/// neither a built-in nor a file gets the list of built-ins and the shipped file it may mean.
fn load_aircraft(arg: &str) -> Result<Aircraft, String> {
    if let Some(ac) = Aircraft::builtin(arg) {
        return Ok(ac);
    }
    if arg.starts_with("jsbsim:") {
        return model::jsbsim::cli::source(arg);
    }
    let path = Path::new(arg);
    aircraft::load(path).map_err(|e| {
        let looks_like_name =
            !path.exists() && path.components().count() == 1 && path.extension().is_none();
        if !looks_like_name {
            return e.to_string();
        }
        let mut msg = format!(
            "{arg:?} is neither a built-in aircraft nor a file; the built-in aircraft are A and B \
             (the paper's), and any other argument is read as the path of an aircraft TOML file"
        );
        let shipped = Path::new("aircraft").join(format!("{}.toml", arg.to_ascii_lowercase()));
        let in_repo = Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("..")
            .join(&shipped);
        if shipped.is_file() {
            msg += &format!(" (did you mean {}?)", shipped.display());
        } else if in_repo.is_file() {
            msg += &format!(" (did you mean {}?)", in_repo.display());
        }
        msg
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;
    use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};

    /// Random argument lists from the commands' own words and numbers of every kind: parsing
    /// never panics, and every number that reaches a command is finite or refused naming its
    /// option.
    #[test]
    fn random_argument_lists_parse_or_fail_without_panics() {
        let command = prop::sample::select(vec![
            "analyze", "continue", "report", "plot", "simulate", "emit",
        ]);
        let aircraft = prop::sample::select(vec!["A", "b", "C", "aircraft/c.toml", "-x", ""]);
        let option = prop::sample::select(vec![
            "--delta-e-deg",
            "--delta-a-deg",
            "--min-deg",
            "--max-deg",
            "--t-end",
            "--out",
            "--csv",
            "--param",
            "--root",
        ]);
        let number = prop_oneof![
            prop::sample::select(vec![
                "-1", "-1e-300", "1e9", "nan", "NaN", "-inf", "inf", "0", "-0", "1e308", "1e309",
                "--json", "x", "",
            ])
            .prop_map(str::to_string),
            any::<f64>().prop_map(|v| v.to_string()),
        ];
        let flag = prop::sample::select(vec!["--json", "--pss", "--zero-sideslip", "--check"]);
        let args = (
            command,
            aircraft,
            prop::collection::vec((option, number), 0..5),
            prop::collection::vec(flag, 0..2),
        )
            .prop_map(|(c, a, opts, flags)| {
                let mut v = vec![c.to_string(), a.to_string()];
                for (o, n) in opts {
                    v.push(o.to_string());
                    v.push(n);
                }
                v.extend(flags.iter().map(|f| f.to_string()));
                v
            });
        let cases = 3000;
        let config = Config {
            cases,
            failure_persistence: None,
            ..Config::default()
        };
        let mut runner =
            TestRunner::new_with_rng(config, TestRng::deterministic_rng(RngAlgorithm::ChaCha));
        let parsed = std::cell::Cell::new(0);
        runner
            .run(&args, |args| {
                let argv = std::iter::once("model").chain(args.iter().map(String::as_str));
                let Ok(cli) = Cli::try_parse_from(argv) else {
                    return Ok(());
                };
                parsed.set(parsed.get() + 1);
                let checks: Vec<Result<f64, Failure>> = match cli.command {
                    Command::Analyze { delta_e_deg, .. }
                    | Command::Report { delta_e_deg, .. }
                    | Command::Plot { delta_e_deg, .. } => vec![elevator(delta_e_deg)],
                    Command::Continue {
                        min_deg,
                        max_deg,
                        delta_e_deg,
                        ..
                    } => vec![
                        elevator(delta_e_deg),
                        finite_angle("min", min_deg),
                        finite_angle("max", max_deg),
                    ],
                    Command::Simulate {
                        delta_a_deg,
                        delta_e_deg,
                        ..
                    } => vec![elevator(delta_e_deg), finite_angle("delta_a", delta_a_deg)],
                    Command::Clear { delta_e_deg, .. } => vec![elevator(delta_e_deg)],
                    Command::Emit { .. } | Command::Convert { .. } | Command::Import { .. } => {
                        vec![]
                    }
                };
                for c in checks {
                    match c {
                        Ok(v) => prop_assert!(v.is_finite()),
                        Err(Failure::Input(m)) => prop_assert!(m.starts_with("--"), "{m}"),
                        Err(_) => prop_assert!(false, "not an input error"),
                    }
                }
                Ok(())
            })
            .unwrap();
        println!(
            "command line: {cases} random argument lists, {} parsed",
            parsed.get()
        );
        assert!(parsed.get() > 50, "{}", parsed.get());
    }

    #[test]
    fn names_are_escaped_and_numbers_never_print_as_negative_zero() {
        assert_eq!(shown("A\u{1b}[2J\n"), "A\\u{1b}[2J\\n");
        assert_eq!(shown("Aircraft A"), "Aircraft A");
        assert_eq!(fixed(-0.00001, 4), "0.0000");
    }
}
