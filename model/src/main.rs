//! `model`: the command-line front end. Argument parsing and printing only.

use clap::{Parser, Subcommand};
use model::aircraft::{self, Aircraft};
use model::analysis::{analyze, Analysis};
use model::continuation::{continue_equilibria, ContinuationParam, Diagram, Settings};
use model::report::{report, ReportSettings};
use model::simulation::{simulate, Model, Rudder, SimSettings};
use std::path::Path;
use std::process::ExitCode;

#[derive(Parser)]
#[command(
    name = "model",
    version,
    about = "Roll-coupling jump criterion (Mahale & Ananthkrishnan, AIAA 2006-6267)"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Divergence and jump roll rates, det K poles and zero-sideslip departure of an aircraft.
    Analyze {
        /// `A`, `B` (the paper's aircraft) or the path of an aircraft TOML file.
        aircraft: String,
        /// Elevator deflection in degrees.
        #[arg(long, default_value_t = 2.0, allow_negative_numbers = true)]
        delta_e_deg: f64,
        /// Print JSON instead of a table.
        #[arg(long)]
        json: bool,
    },
    /// Continuation of the PSS equilibria: every branch, folds, Hopf and branch points (Figs 1-4, 9).
    Continue {
        /// `A`, `B` or the path of an aircraft TOML file.
        aircraft: String,
        /// The continuation parameter: delta_a, delta_e or delta_r.
        #[arg(long, default_value = "delta_a")]
        param: String,
        /// Lower end of the parameter range, rad.
        #[arg(long, default_value_t = -0.8, allow_negative_numbers = true)]
        min: f64,
        /// Upper end of the parameter range, rad.
        #[arg(long, default_value_t = 0.8, allow_negative_numbers = true)]
        max: f64,
        /// Elevator deflection in degrees (when it is not the parameter).
        #[arg(long, default_value_t = 2.0, allow_negative_numbers = true)]
        delta_e_deg: f64,
        /// Zero-sideslip manoeuvre by extended bifurcation analysis (section V.B, Fig. 9).
        #[arg(long)]
        zero_sideslip: bool,
        /// Print JSON instead of a summary.
        #[arg(long)]
        json: bool,
        /// Also write every point as CSV to this file.
        #[arg(long)]
        csv: Option<std::path::PathBuf>,
    },
    /// Every result of the paper for an aircraft: numbers, Figs 1-11 and summary.md in DIR.
    Report {
        /// `A`, `B` or the path of an aircraft TOML file.
        aircraft: String,
        /// Output folder (created if needed).
        #[arg(long)]
        out: std::path::PathBuf,
        /// Elevator deflection in degrees.
        #[arg(long, default_value_t = 2.0, allow_negative_numbers = true)]
        delta_e_deg: f64,
    },
    /// Figs 1-11 only (SVG and PNG) in DIR, without the summary.
    Plot {
        /// `A`, `B` or the path of an aircraft TOML file.
        aircraft: String,
        /// Output folder (created if needed).
        #[arg(long)]
        out: std::path::PathBuf,
        /// Elevator deflection in degrees.
        #[arg(long, default_value_t = 2.0, allow_negative_numbers = true)]
        delta_e_deg: f64,
    },
    /// Time history of an aileron step from the trim (7th-order model unless --pss).
    Simulate {
        /// `A`, `B` or the path of an aircraft TOML file.
        aircraft: String,
        /// Aileron step, degrees.
        #[arg(long, allow_negative_numbers = true)]
        delta_a_deg: f64,
        /// Elevator deflection in degrees.
        #[arg(long, default_value_t = 2.0, allow_negative_numbers = true)]
        delta_e_deg: f64,
        /// Length of the run, s.
        #[arg(long, default_value_t = 20.0)]
        t_end: f64,
        /// Rudder on the zero-sideslip schedule (aileron-rudder interconnect, Fig. 10).
        #[arg(long)]
        zero_sideslip: bool,
        /// Integrate the PSS model instead of the 7th-order model.
        #[arg(long)]
        pss: bool,
        /// Write the time history as CSV to this file.
        #[arg(long)]
        csv: Option<std::path::PathBuf>,
    },
    /// Print the dimensional principal-axis TOML equivalent to a nondimensional body-axis file.
    Convert {
        /// Path of a nondimensional body-axis aircraft TOML file.
        file: std::path::PathBuf,
    },
    /// Write the generated criterion crate (generated/) and docs/formulas.tex.
    Emit {
        /// Write nothing; exit 1 naming every stale file.
        #[arg(long)]
        check: bool,
        /// Workspace root (default: the workspace this binary was built from).
        #[arg(long)]
        root: Option<std::path::PathBuf>,
    },
}

/// Exit code for bad input (file, key or value), as for clap's usage errors.
const BAD_INPUT: u8 = 2;

/// Exit code of `emit --check` when outputs are stale.
const STALE: u8 = 1;

fn main() -> ExitCode {
    let cli = Cli::parse();
    match run(cli) {
        Ok(code) => code,
        Err(msg) => {
            eprintln!("error: {msg}");
            ExitCode::from(BAD_INPUT)
        }
    }
}

fn run(cli: Cli) -> Result<ExitCode, String> {
    let summary = matches!(cli.command, Command::Report { .. });
    match cli.command {
        Command::Analyze {
            aircraft,
            delta_e_deg,
            json,
        } => {
            let ac = load_aircraft(&aircraft)?;
            let result =
                analyze(&ac, delta_e_deg.to_radians()).map_err(|e| format!("{}: {e}", ac.name))?;
            if json {
                let text = serde_json::to_string_pretty(&result).map_err(|e| e.to_string())?;
                println!("{text}");
            } else {
                print!("{}", table(&result));
            }
            Ok(ExitCode::SUCCESS)
        }
        Command::Continue {
            aircraft,
            param,
            min,
            max,
            delta_e_deg,
            zero_sideslip,
            json,
            csv,
        } => {
            let ac = load_aircraft(&aircraft)?;
            let settings = Settings {
                param: param
                    .parse::<ContinuationParam>()
                    .map_err(|e| e.to_string())?,
                min,
                max,
                delta_e: delta_e_deg.to_radians(),
                zero_sideslip,
                ..Settings::default()
            };
            let bar = progress_bar("continuation");
            let diagram = continue_equilibria(&ac, &settings, &mut |f| {
                if let Some(b) = &bar {
                    b.set_position((f * 1000.0) as u64);
                }
            })
            .map_err(|e| format!("{}: {e}", ac.name))?;
            if let Some(b) = bar {
                b.finish_and_clear();
            }
            if let Some(path) = csv {
                model::files::write_atomic(&path, diagram.to_csv().as_bytes())
                    .map_err(|e| format!("cannot write {}: {e}", path.display()))?;
            }
            if json {
                println!(
                    "{}",
                    serde_json::to_string_pretty(&diagram).map_err(|e| e.to_string())?
                );
            } else {
                print!("{}", diagram_summary(&diagram));
            }
            Ok(ExitCode::SUCCESS)
        }
        Command::Report {
            aircraft,
            out,
            delta_e_deg,
        }
        | Command::Plot {
            aircraft,
            out,
            delta_e_deg,
        } => {
            let ac = load_aircraft(&aircraft)?;
            let settings = ReportSettings {
                delta_e: finite_angle("delta_e", delta_e_deg)?,
                style: model::plot::PlotStyle::default(),
                summary,
            };
            let bar = progress_bar(if summary { "report" } else { "plot" });
            let result = report(&ac, &out, &settings, &mut |f| {
                if let Some(b) = &bar {
                    b.set_position((f * 1000.0) as u64);
                }
            })
            .map_err(|e| format!("{}: {e}", ac.name))?;
            if let Some(b) = bar {
                b.finish_and_clear();
            }
            for f in &result.figures {
                for file in &f.files {
                    println!("wrote {}", out.join(file).display());
                }
            }
            if summary {
                println!("wrote {}", out.join("summary.md").display());
                println!("wrote {}", out.join("summary.json").display());
            }
            Ok(ExitCode::SUCCESS)
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
                    finite_angle("delta_e", delta_e_deg)?,
                    finite_angle("delta_a", delta_a_deg)?,
                )
            };
            let h = simulate(&ac, &settings).map_err(|e| format!("{}: {e}", ac.name))?;
            if let Some(path) = csv {
                model::files::write_atomic(&path, h.to_csv().as_bytes())
                    .map_err(|e| format!("cannot write {}: {e}", path.display()))?;
            }
            let st = h.steady(5.0_f64.min(t_end / 2.0));
            println!(
                "{} ({}), aileron step {delta_a_deg} deg, {} s: steady roll rate {:.4} rad/s (range {:.4} to {:.4}), mean sideslip {:.3} deg, peak |sideslip| {:.3} deg",
                ac.name,
                model.name(),
                t_end,
                st.p_mean,
                st.p_min,
                st.p_max,
                st.beta_mean.to_degrees(),
                st.beta_peak_abs.to_degrees()
            );
            Ok(ExitCode::SUCCESS)
        }
        Command::Convert { file } => {
            print!(
                "{}",
                aircraft::convert_file(&file).map_err(|e| e.to_string())?
            );
            Ok(ExitCode::SUCCESS)
        }
        Command::Emit { check, root } => {
            let root = root.unwrap_or_else(|| Path::new(env!("CARGO_MANIFEST_DIR")).join(".."));
            let outputs = model::emit::generate().map_err(|e| e.to_string())?;
            if check {
                let stale = model::emit::stale(&root, &outputs);
                if stale.is_empty() {
                    println!("{} generated files are up to date", outputs.len());
                    return Ok(ExitCode::SUCCESS);
                }
                for p in &stale {
                    eprintln!("stale: {}", p.display());
                }
                eprintln!("run `{}` to regenerate", model::emit::COMMAND);
                return Ok(ExitCode::from(STALE));
            }
            let written = model::emit::write(&root, &outputs).map_err(|e| e.to_string())?;
            for o in &outputs {
                let state = if written.contains(&o.path) {
                    "wrote"
                } else {
                    "unchanged"
                };
                println!("{state:>9} {}", o.path.display());
            }
            Ok(ExitCode::SUCCESS)
        }
    }
}

/// An angle in degrees converted to rad, or an error naming the option.
fn finite_angle(name: &str, deg: f64) -> Result<f64, String> {
    if deg.is_finite() {
        Ok(deg.to_radians())
    } else {
        Err(format!(
            "--{}-deg = {deg}: expected a finite angle in degrees",
            name.replace('_', "-")
        ))
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

fn diagram_summary(d: &Diagram) -> String {
    let points: usize = d.branches.iter().map(|b| b.points.len()).sum();
    let mut s = format!(
        "{}: {} branches, {} points, continuation in {}\n\n",
        d.aircraft,
        d.branches.len(),
        points,
        d.parameter
    );
    if d.special_points.is_empty() {
        s += "No special points.\n";
        return s;
    }
    s += &format!(
        "  kind    {:>12} {:>10} {:>10} {:>10} {:>10} {:>10} {:>12}\n",
        format!("{} deg", d.parameter),
        "p rad/s",
        "alpha deg",
        "beta deg",
        "q rad/s",
        "r rad/s",
        "freq rad/s"
    );
    for p in &d.special_points {
        s += &format!(
            "  {:<7} {:>12.4} {:>10.6} {:>10.4} {:>10.4} {:>10.5} {:>10.5} {:>12}\n",
            p.kind.name(),
            p.param.to_degrees(),
            p.p,
            p.alpha.to_degrees(),
            p.beta.to_degrees(),
            p.q,
            p.r,
            p.frequency.map_or(String::new(), |f| format!("{f:.5}"))
        );
    }
    s
}

/// `A`/`B` name the built-in aircraft; anything else is a TOML file.
fn load_aircraft(arg: &str) -> Result<Aircraft, String> {
    if let Some(ac) = Aircraft::builtin(arg) {
        return Ok(ac);
    }
    aircraft::load(Path::new(arg)).map_err(|e| e.to_string())
}

/// The marks of a reported point: beyond the control limits, outside the validity range.
fn marks(within_limits: Option<bool>, valid: bool) -> String {
    let mut m = String::new();
    if within_limits == Some(false) {
        m += "  [beyond limits]";
    }
    if !valid {
        m += "  [outside validity range]";
    }
    m
}

fn table(a: &Analysis) -> String {
    let mut s = String::new();
    let list = |v: &[f64]| {
        if v.is_empty() {
            "none".to_string()
        } else {
            v.iter()
                .map(|x| format!("{x:.6}"))
                .collect::<Vec<_>>()
                .join(", ")
        }
    };
    s += &format!(
        "{}  (delta_e = {:.4} deg, delta_r = 0)\n\n",
        a.aircraft,
        a.delta_e_rad.to_degrees()
    );
    match (&a.critical, &a.critical_note) {
        (Some(c), _) => {
            s += &format!(
                "Critical jump (first fold of the primary branch): P0 = {:.6} rad/s at delta_a = {:.4} deg (and the mirror point -P0 at {:+.4} deg){}\n\n",
                c.p0,
                c.delta_a_deg,
                -c.delta_a_deg,
                match c.within_limits {
                    Some(true) => ", within the aileron limit",
                    Some(false) => ", OUTSIDE the aileron limit",
                    None => "",
                }
            );
        }
        (None, Some(note)) => s += &format!("No critical jump: {note}.\n\n"),
        (None, None) => {}
    }
    s += &format!(
        "Divergence roll rates, Eq. 5 (rad/s):   {}\n",
        list(&a.divergence_roll_rates)
    );
    s += &format!(
        "Poles of det K, d = 0 (rad/s):          {}\n\n",
        list(&a.det_k_poles.iter().map(|j| j.p0).collect::<Vec<_>>())
    );
    s += "Jump points, det K = 0 (saddle-nodes of the PSS equilibria):\n";
    if a.jump.is_empty() {
        s += "  none\n";
    } else {
        s += "     P0 rad/s   delta_a deg   alpha deg    beta deg     q rad/s     r rad/s\n";
        for j in &a.jump {
            s += &format!(
                "  {:>11.6} {:>13.4} {:>11.4} {:>11.4} {:>11.5} {:>11.5}{}\n",
                j.p0,
                j.delta_a_deg,
                j.alpha.to_degrees(),
                j.beta.to_degrees(),
                j.q,
                j.r,
                marks(j.within_limits, j.valid)
            );
        }
    }
    s += "\nZero-sideslip departure, det K = 0 at beta = 0 (section V):\n";
    if a.zero_sideslip.departure.is_empty() {
        s += "  none\n";
    } else {
        s += "     P0 rad/s   delta_a deg   delta_r deg   alpha deg     q rad/s     r rad/s\n";
        for j in &a.zero_sideslip.departure {
            s += &format!(
                "  {:>11.6} {:>13.4} {:>13.4} {:>11.4} {:>11.5} {:>11.5}{}\n",
                j.p0,
                j.delta_a_deg,
                j.delta_r_deg,
                j.alpha.to_degrees(),
                j.q,
                j.r,
                marks(j.within_limits, j.valid)
            );
        }
    }
    s
}
