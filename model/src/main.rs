//! `model`: the command-line front end. It parses the arguments and calls one function of
//! [`model::present::commands`] per command, which computes, prints and writes; a failure ends
//! with its message on stderr and exit code 2 (bad input) or 1 (an output not written).

use clap::{CommandFactory, FromArgMatches, Parser, Subcommand};
use model::present::commands;
use model::present::failure::{stdout_error, Failure, BAD_INPUT, FAILED};
use model::present::options::{
    AnalyzeArgs, ClearArgs, ContinueArgs, ConvertArgs, EmitArgs, EnvelopeArgs, FiguresArgs,
    SimulateArgs, ValidateArgs,
};
use std::io::Write;
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
                  \"jsbsim:MODEL --altitude-m H --mach M [--load-factor N]\" (the arguments of \
                  `import jsbsim`, quoted as one) imports a JSBSim model at its n-g trim there \
                  (default 1 g); for it, --delta-e-deg is the increment from the trim elevator."
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

/// The commands; their options are in [`model::present::options`].
#[derive(Subcommand)]
enum Command {
    /// Divergence and jump roll rates, det K poles and zero-sideslip departure of an aircraft.
    Analyze(AnalyzeArgs),
    /// Continuation of the PSS equilibria: every branch, folds, Hopf and branch points (Figs 1-4, 9).
    Continue(ContinueArgs),
    /// Every result of the paper for an aircraft in DIR: Figs 1-11 (SVG, PNG and the plotted
    /// data as CSV), summary.md and summary.json.
    Report(FiguresArgs),
    /// Figs 1-11 only (SVG, PNG and the plotted data as CSV) in DIR, without the summary.
    Plot(FiguresArgs),
    /// Time history of an aileron step from the trim (7th-order model unless --pss).
    Simulate(SimulateArgs),
    /// Aileron steps in the 7th-order model and the native 6-DOF of a JSBSim airframe at the
    /// same trim: the settled roll rates against the criterion's critical aileron.
    Validate(ValidateArgs),
    /// Certified clearance of the critical jump over the file's `[uncertainty]` box.
    Clear(ClearArgs),
    /// The analysis at every altitude and Mach of a grid, each point at its n-g trim (1 g unless
    /// --load-factor):
    /// critical jump, first departure and margin to the aileron limit, as a table, JSON or maps.
    Envelope(EnvelopeArgs),
    /// Print the dimensional principal-axis TOML equivalent to a nondimensional body-axis file.
    Convert(ConvertArgs),
    /// Write an aircraft file from a JSBSim model, trimmed at n g (1 g unless --load-factor or
    /// --alpha-deg); `import jsbsim --help` for its options.
    #[command(disable_help_flag = true, override_help = model::jsbsim::cli::HELP)]
    Import {
        /// The source (`jsbsim`) and its arguments.
        #[arg(trailing_var_arg = true, allow_hyphen_values = true, num_args = 0..)]
        args: Vec<String>,
    },
    /// Write the generated criterion crate (generated/) and docs/formulas.tex.
    Emit(EmitArgs),
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

/// Runs the command of `cli`, printing to `out` (stdout).
fn run(cli: Cli, out: &mut dyn Write) -> Result<ExitCode, Failure> {
    match &cli.command {
        Command::Analyze(a) => commands::analyze_command(a, out),
        Command::Continue(a) => commands::continue_command(a, out),
        Command::Report(a) => commands::report_command(a, true, out),
        Command::Plot(a) => commands::report_command(a, false, out),
        Command::Simulate(a) => commands::simulate_command(a, out),
        Command::Clear(a) => commands::clear_command(a, out),
        Command::Validate(a) => model::present::validate::command(a, out),
        Command::Envelope(a) => model::present::envelope::command(a, out),
        Command::Convert(a) => commands::convert_command(a, out),
        Command::Import { args } if args.iter().any(|a| a == "--analyze") => Ok(ExitCode::from(
            model::present::catalogue::catalogue_command(args, out),
        )),
        Command::Import { args } => Ok(ExitCode::from(model::jsbsim::cli::run(args, out))),
        Command::Emit(a) => commands::emit_command(a, out),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use model::present::numbers::fixed;
    use model::present::options::{elevator, finite_angle};
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
                    Command::Analyze(a) => vec![elevator(a.delta_e_deg.unwrap_or(0.0))],
                    Command::Report(a) | Command::Plot(a) => {
                        vec![elevator(a.delta_e_deg.unwrap_or(0.0))]
                    }
                    Command::Continue(a) => vec![
                        elevator(a.delta_e_deg.unwrap_or(0.0)),
                        finite_angle("min", a.min_deg),
                        finite_angle("max", a.max_deg),
                    ],
                    Command::Simulate(a) => vec![
                        elevator(a.delta_e_deg.unwrap_or(0.0)),
                        finite_angle("delta_a", a.delta_a_deg),
                    ],
                    Command::Clear(a) => vec![elevator(a.delta_e_deg.unwrap_or(0.0))],
                    Command::Emit(_)
                    | Command::Convert(_)
                    | Command::Envelope(_)
                    | Command::Validate(_)
                    | Command::Import { .. } => vec![],
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
        assert_eq!(model::aircraft::shown("A\u{1b}[2J\n"), "A\\u{1b}[2J\\n");
        assert_eq!(model::aircraft::shown("Aircraft A"), "Aircraft A");
        assert_eq!(fixed(-0.00001, 4), "0.0000");
    }
}
