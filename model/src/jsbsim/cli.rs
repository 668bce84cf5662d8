//! `model import jsbsim ...`: the command line of the import, parsed here so that the binary's
//! own parser only hands over the arguments; the same arguments after `jsbsim:` name an aircraft
//! source for the other commands ([`source`]). `--list` prints the catalogue, every model with
//! whether it reads and, if not, why.

use super::catalogue;
use super::condition::Speed;
use super::import::{evaluates, import, import_trimmed, Alpha, Request, REFERENCE};
use super::trim::Trim;
use std::io::Write;
use std::path::PathBuf;

/// Usage, for errors (and the help's Usage lines).
pub const USAGE: &str = "Usage: model import jsbsim [OPTIONS] --altitude-m <H> <--mach <M>|--speed <V>> <MODEL>\n       \
     model import jsbsim --list [--jsbsim-root <DIR>]\n       \
     model import jsbsim --list --analyze [OPTIONS] --altitude-m <H> <--mach <M>|--speed <V>>";

/// What `--help` (or `-h`, or `model help import`) prints, in the layout clap gives the other
/// commands: what the command does, its usage, its arguments and its options.
pub const HELP: &str = "Write an aircraft file from a JSBSim model: nondimensional body-axis \
coefficients linearised at one flight condition, trimmed at n g (1 g unless --load-factor or \
--alpha-deg)

Usage: model import jsbsim [OPTIONS] --altitude-m <H> <--mach <M>|--speed <V>> <MODEL>
       model import jsbsim --list [--jsbsim-root <DIR>]
       model import jsbsim --list --analyze [OPTIONS] --altitude-m <H> <--mach <M>|--speed <V>>

Arguments:
  <MODEL>  A model of the catalogue (e.g. f104; --list shows them), or the path of its XML file

Options:
      --altitude-m <H>          Geometric altitude, m (standard atmosphere 1976, 0 to 86,000 m)
      --mach <M>                Mach number
      --speed <V>               True airspeed, m/s (instead of --mach)
      --load-factor <N>         Linearise at the trim of a wings-level pull-up at N g: alpha and elevator such that lift = N x weight (thrust left out) and the pitching moment is zero, pitch rate (N - 1) g / V, the elevator within its travel (else untrimmable, exit 2); the analysis's delta_e is the increment from this trim's elevator [default: 1; 0 is the unloaded roll]
      --alpha-deg <A>           Linearise at this angle of attack instead, deg, elevator neutral (not a trim)
      --set <PROPERTY=VALUE>    A JSBSim property set before the import (not a flight state or control); may be repeated
      --out <FILE>              Write the aircraft file there instead of standard output
      --jsbsim-root <DIR>       The JSBSim root, the folder holding aircraft/NAME/NAME.xml [default: $JSBSIM_ROOT, else the Python package's]
      --list                    The catalogue: every model, and whether it imports (trimmed at 1 g at 3000 m, Mach 0.3)
      --analyze                 With --list: each model's analysis at the flight condition given
  -h, --help                    Print help
";

/// The exit code of bad input.
pub const BAD_INPUT: u8 = 2;

/// Runs `model import` with `args` (after `import`), writing to `out`; returns the exit code.
/// Errors go to standard error; `--help` anywhere prints [`HELP`] instead.
pub fn run(args: &[String], out: &mut dyn Write) -> u8 {
    if args.iter().any(|a| a == "--help" || a == "-h") {
        // A closed pipe ends the help quietly.
        let _ = write!(out, "{HELP}");
        return 0;
    }
    match parse_and_run(args, out) {
        Ok(()) => 0,
        Err(msg) => {
            eprintln!("error: {msg}");
            BAD_INPUT
        }
    }
}

/// The value after flag `flag` at `args[*i]`.
fn value<'a>(args: &'a [String], i: &mut usize, flag: &str) -> Result<&'a str, String> {
    *i += 1;
    args.get(*i)
        .map(String::as_str)
        .ok_or_else(|| format!("{flag} needs a value\n{USAGE}"))
}

/// A finite number given for `flag`.
fn number(text: &str, flag: &str) -> Result<f64, String> {
    text.parse::<f64>()
        .ok()
        .filter(|v| v.is_finite())
        .ok_or_else(|| format!("{flag} {text}: not a number (expected a finite decimal)"))
}

/// What the command line asks for.
enum Command {
    /// The catalogue listing, from the root if given.
    List(Option<PathBuf>),
    /// An import, written to the file if given.
    Import(Request, Option<PathBuf>),
}

/// Parses the arguments after `import` (`jsbsim` first).
fn parse(args: &[String]) -> Result<Command, String> {
    if args.first().map(String::as_str) != Some("jsbsim") {
        return Err(format!("the only import source is `jsbsim`\n{USAGE}"));
    }
    let (mut model, mut root, mut altitude, mut speed) = (None, None, None, None);
    let (mut alpha, mut list, mut file, mut load_factor) = (None, false, None, None);
    let mut settings = Vec::new();
    let mut i = 1;
    while i < args.len() {
        let a = args[i].as_str();
        match a {
            "--list" => list = true,
            // The same as --load-factor 1 (kept for scripts; the help shows --load-factor).
            "--level-flight" => alpha = Some(Alpha::Trim(1.0)),
            "--load-factor" => {
                load_factor = Some(number(value(args, &mut i, a)?, a)?);
            }
            "--jsbsim-root" => root = Some(PathBuf::from(value(args, &mut i, a)?)),
            "--out" => file = Some(PathBuf::from(value(args, &mut i, a)?)),
            "--altitude-m" => altitude = Some(number(value(args, &mut i, a)?, a)?),
            "--mach" => speed = Some(Speed::Mach(number(value(args, &mut i, a)?, a)?)),
            "--speed" => speed = Some(Speed::True(number(value(args, &mut i, a)?, a)?)),
            "--alpha-deg" => {
                alpha = Some(Alpha::Given(
                    number(value(args, &mut i, a)?, a)?.to_radians(),
                ))
            }
            "--set" => settings.push(setting(value(args, &mut i, a)?)?),
            _ if a.starts_with("--") => return Err(format!("unknown option {a}\n{USAGE}")),
            _ if model.is_none() => model = Some(a.to_string()),
            _ => return Err(format!("unexpected argument {a}\n{USAGE}")),
        }
        i += 1;
    }
    if list {
        return Ok(Command::List(root));
    }
    let model = model.ok_or_else(|| format!("no model given\n{USAGE}"))?;
    let altitude_m = altitude.ok_or_else(|| format!("--altitude-m is required\n{USAGE}"))?;
    let speed = speed.ok_or_else(|| format!("--mach or --speed is required\n{USAGE}"))?;
    let alpha = match (alpha, load_factor) {
        (None, n) => Alpha::Trim(n.unwrap_or(1.0)),
        (Some(Alpha::Trim(_)), Some(n)) if n != 1.0 => {
            return Err(format!(
                "--level-flight is the trim at --load-factor 1; give one of them\n{USAGE}"
            ))
        }
        (Some(Alpha::Given(_)), Some(_)) => {
            return Err(format!(
                "--alpha-deg linearises at a given angle of attack, --load-factor at the trim: \
                 give one of them\n{USAGE}"
            ))
        }
        (Some(a), _) => a,
    };
    let request = Request {
        model,
        root,
        altitude_m,
        speed,
        alpha,
        settings,
    };
    Ok(Command::Import(request, file))
}

/// One `--set PROPERTY=VALUE` (of an import, a `jsbsim:` source or an envelope's source).
pub fn setting(kv: &str) -> Result<(String, f64), String> {
    let (k, v) = kv.split_once('=').ok_or_else(|| {
        format!("--set {kv}: expected PROPERTY=VALUE, e.g. fcs/flap-pos-norm=0.5")
    })?;
    Ok((
        k.trim().to_string(),
        number(v.trim(), &format!("--set {k}"))?,
    ))
}

/// Parses the arguments and runs the import or the listing.
fn parse_and_run(args: &[String], out: &mut dyn Write) -> Result<(), String> {
    match parse(args)? {
        Command::List(root) => listing(root, out),
        Command::Import(request, file) => {
            let (text, trim) = import_trimmed(&request)?;
            match file {
                Some(path) => {
                    crate::files::write_output(&path, text.as_bytes())
                        .map_err(|e| format!("{}: cannot write: {e}", path.display()))?;
                    let said = written(&path, &request, trim.as_ref());
                    writeln!(out, "{said}").map_err(|e| e.to_string())
                }
                None => out.write_all(text.as_bytes()).map_err(|e| e.to_string()),
            }
        }
    }
}

/// What `--out` wrote, and at which flight state: the line a user reads after the import.
fn written(path: &std::path::Path, r: &Request, trim: Option<&Trim>) -> String {
    let speed = match r.speed {
        Speed::Mach(m) => format!("Mach {m}"),
        Speed::True(v) => format!("{v} m/s true airspeed"),
    };
    let at = match trim {
        Some(t) if t.per_unit_travel => format!(
            "trimmed at n = {} (alpha {:.4} deg, elevator {:.4} of its travel)",
            t.load_factor,
            t.alpha.to_degrees(),
            t.elevator
        ),
        Some(t) => format!(
            "trimmed at n = {} (alpha {:.4} deg, elevator {:.4} deg, JSBSim's sign)",
            t.load_factor,
            t.alpha.to_degrees(),
            t.elevator.to_degrees()
        ),
        None => "linearised at the alpha given (not a trim)".to_string(),
    };
    format!(
        "wrote {}: {} at {} m, {speed}, {at}",
        path.display(),
        r.model,
        r.altitude_m
    )
}

/// The aircraft of a `jsbsim:` source, the import's arguments after the colon in one string
/// (`"jsbsim:f104 --altitude-m 6096 --mach 0.53 --load-factor 1"`): what `analyze`, `continue`,
/// `simulate` and `report` accept in place of an aircraft file.
pub fn source(spec: &str) -> Result<crate::aircraft::Aircraft, String> {
    let text = source_text(spec)?;
    crate::aircraft::parse(&text, spec).map_err(|e| e.to_string())
}

/// The aircraft file (TOML text) of a `jsbsim:` source, as `import` writes it: what `convert`
/// converts in place of a file.
pub fn source_text(spec: &str) -> Result<String, String> {
    import(&request(spec)?)
}

/// The import a `jsbsim:` source asks for (see [`source`]), its words checked as `import jsbsim`
/// checks them.
pub fn request(spec: &str) -> Result<Request, String> {
    let rest = spec
        .strip_prefix("jsbsim:")
        .ok_or_else(|| format!("{spec}: not a jsbsim: source (expected jsbsim:MODEL ...)"))?;
    let mut args = vec!["jsbsim".to_string()];
    args.extend(rest.split_whitespace().map(str::to_string));
    match parse(&args)? {
        Command::Import(request, None) => Ok(request),
        _ => Err(format!("{spec}: a jsbsim: source takes the import's model and flight condition, not --list or --out")),
    }
}

/// Whether catalogue model `name` under `root` imports at the [`REFERENCE`] altitude and Mach,
/// trimmed at 1 g, as an aircraft the analysis loads: the check of a `jsbsim:` source (and so
/// of `--list --analyze`), its refusal as the reason.
fn imports(name: &str, root: &std::path::Path) -> Result<(), String> {
    let (h, mach, _) = REFERENCE;
    let spec = format!(
        "jsbsim:{name} --altitude-m {h} --mach {mach} --jsbsim-root {}",
        root.display()
    );
    source(&spec).map(|_| ()).map_err(|e| {
        let rest = e.strip_prefix(&spec).unwrap_or(&e);
        let rest = rest.trim_start_matches(|c: char| c == ':' || c.is_ascii_digit());
        rest.trim_start().to_string()
    })
}

/// Prints the catalogue.
fn listing(root: Option<PathBuf>, out: &mut dyn Write) -> Result<(), String> {
    out.write_all(listing_text(root)?.as_bytes())
        .map_err(|e| e.to_string())
}

/// What `import jsbsim --list` prints for `args` (after `import`, `jsbsim` first), or its
/// message for bad arguments: shared by the command line and Python.
pub fn listing_of(args: &[String]) -> Result<String, String> {
    match parse(args)? {
        Command::List(root) => listing_text(root),
        Command::Import(..) => Err(format!("expected --list\n{USAGE}")),
    }
}

/// The catalogue listing: every model of the root, and whether it reads.
fn listing_text(root: Option<PathBuf>) -> Result<String, String> {
    let root = catalogue::root(root.as_deref()).ok_or_else(|| catalogue::HOW_TO_GET.to_string())?;
    catalogue::checked_root(&root)?;
    let entries: Vec<(String, Result<String, String>)> = catalogue::listing(&root)
        .into_iter()
        .map(|(name, model)| {
            let path = root
                .join("aircraft")
                .join(&name)
                .join(format!("{name}.xml"));
            let checked = model
                .and_then(|m| evaluates(&m, &path).map(|()| m.name))
                .and_then(|full| imports(&name, &root).map(|()| full));
            (name, checked)
        })
        .collect();
    // The trim's refusals (`jsbsim::trim`) start so; the loader's name the source first.
    let untrimmable = |e: &String| e.starts_with("untrimmable at");
    let ok = entries.iter().filter(|(_, m)| m.is_ok()).count();
    let no_trim = entries
        .iter()
        .filter(|(_, m)| m.as_ref().is_err_and(untrimmable))
        .count();
    let (h, mach, _) = REFERENCE;
    let mut text = format!(
        "{} ({} models, {ok} importable: read, trimmed at 1 g at {h} m, Mach {mach} and loaded as \
         an aircraft, the check of `import` and of `--list --analyze`; {no_trim} read but do not \
         trim there (\"no trim\": another flight condition may); the others are refused \
         anywhere)\n",
        root.join("aircraft").display(),
        entries.len()
    );
    for (name, model) in entries {
        let line = match model {
            Ok(full) => format!("{name:<18} ok      {full}\n"),
            Err(e) if untrimmable(&e) => format!("{name:<18} no trim {e}\n"),
            Err(e) => format!("{name:<18} refused {e}\n"),
        };
        text.push_str(&line);
    }
    Ok(text)
}
