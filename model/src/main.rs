//! `model`: the command-line front end. Argument parsing and printing only.

use clap::{Parser, Subcommand};
use model::aircraft::{self, Aircraft};
use model::analysis::{analyze, Analysis};
use std::path::Path;
use std::process::ExitCode;

#[derive(Parser)]
#[command(name = "model", version, about = "Roll-coupling jump criterion (Mahale & Ananthkrishnan, AIAA 2006-6267)")]
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
}

/// Exit code for bad input (file, key or value), as for clap's usage errors.
const BAD_INPUT: u8 = 2;

fn main() -> ExitCode {
    let cli = Cli::parse();
    match run(cli) {
        Ok(()) => ExitCode::SUCCESS,
        Err(msg) => {
            eprintln!("error: {msg}");
            ExitCode::from(BAD_INPUT)
        }
    }
}

fn run(cli: Cli) -> Result<(), String> {
    match cli.command {
        Command::Analyze { aircraft, delta_e_deg, json } => {
            let ac = load_aircraft(&aircraft)?;
            let result = analyze(&ac, delta_e_deg.to_radians()).map_err(|e| format!("{}: {e}", ac.name))?;
            if json {
                let text = serde_json::to_string_pretty(&result).map_err(|e| e.to_string())?;
                println!("{text}");
            } else {
                print!("{}", table(&result));
            }
            Ok(())
        }
    }
}

/// `A`/`B` name the built-in aircraft; anything else is a TOML file.
fn load_aircraft(arg: &str) -> Result<Aircraft, String> {
    if let Some(ac) = Aircraft::builtin(arg) {
        return Ok(ac);
    }
    aircraft::load(Path::new(arg)).map_err(|e| e.to_string())
}

fn table(a: &Analysis) -> String {
    let mut s = String::new();
    let list = |v: &[f64]| {
        if v.is_empty() {
            "none".to_string()
        } else {
            v.iter().map(|x| format!("{x:.6}")).collect::<Vec<_>>().join(", ")
        }
    };
    s += &format!("{}  (delta_e = {:.4} deg, delta_r = 0)\n\n", a.aircraft, a.delta_e_rad.to_degrees());
    s += &format!("Divergence roll rates, Eq. 5 (rad/s):   {}\n", list(&a.divergence_roll_rates));
    s += &format!("Poles of det K, d = 0 (rad/s):          {}\n\n", list(&a.det_k_poles));
    s += "Jump points, det K = 0 (saddle-nodes of the PSS equilibria):\n";
    if a.jump.is_empty() {
        s += "  none\n";
    } else {
        s += "     P0 rad/s   delta_a deg   alpha deg    beta deg     q rad/s     r rad/s\n";
        for j in &a.jump {
            s += &format!(
                "  {:>11.6} {:>13.4} {:>11.4} {:>11.4} {:>11.5} {:>11.5}\n",
                j.p0, j.delta_a_deg, j.alpha.to_degrees(), j.beta.to_degrees(), j.q, j.r
            );
        }
    }
    s += "\nZero-sideslip departure, det K = 0 at beta = 0 (section V):\n";
    if a.zero_sideslip.departure.is_empty() {
        s += "  none\n";
    } else {
        s += "     P0 rad/s   delta_a deg   alpha deg     q rad/s     r rad/s\n";
        for j in &a.zero_sideslip.departure {
            s += &format!(
                "  {:>11.6} {:>13.4} {:>11.4} {:>11.5} {:>11.5}\n",
                j.p0, j.delta_a_deg, j.alpha.to_degrees(), j.q, j.r
            );
        }
    }
    s
}
