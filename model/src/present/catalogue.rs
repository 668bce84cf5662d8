//! `model import jsbsim --list --analyze <flight condition>`: every model of JSBSim's catalogue
//! imported at one flight condition and analysed, as one Markdown table: whether it imports
//! (and why not), its critical jump (the first fold of the primary branch: roll rate P0,
//! aileron, within the aileron limit or not) and its first departure (jump or Hopf point) on
//! the primary branch. Each model is linearised at its n-g trim (`--load-factor N`, default 1,
//! as `import` and the envelope do) and analysed at elevator increment 0 from that trim, so that
//! a row and the envelope's point at the same condition agree. The models are imported and
//! analysed in parallel, each by the envelope's route (the first departure certified where it can be,
//! the exact path otherwise), and the table ends with how many the exact path answered.

use crate::aircraft::Aircraft;
use crate::analysis::fast::analyze_first_departure;
use crate::analysis::Analysis;
use crate::jsbsim::{catalogue, cli};
use rayon::prelude::*;
use std::io::Write;

/// The elevator increment of every row from its trim, deg (the envelope's default).
pub const DELTA_E_DEG: f64 = 0.0;

/// Runs the catalogue table with `args` (after `import`, `jsbsim` first, holding `--list` and
/// `--analyze`), writing to `out`; returns the exit code (2 with a message on bad input).
pub fn catalogue_command(args: &[String], out: &mut dyn Write) -> u8 {
    match table(args) {
        Ok(text) => match out.write_all(text.as_bytes()) {
            Ok(()) => 0,
            Err(e) => {
                eprintln!("error: {e}");
                cli::BAD_INPUT
            }
        },
        Err(msg) => {
            eprintln!("error: {msg}");
            cli::BAD_INPUT
        }
    }
}

/// The Markdown table `import jsbsim --list --analyze` prints for `args` (after `import`,
/// `jsbsim` first), or why it cannot be made (no models found, no flight condition): shared by
/// the command line and Python.
pub fn table(args: &[String]) -> Result<String, String> {
    if !args.iter().any(|a| a == "--list") {
        return Err(format!(
            "--analyze goes with --list (the whole catalogue); for one model, `model analyze \
             \"jsbsim:MODEL ...\"`\n{}",
            cli::USAGE
        ));
    }
    let mut rest: Vec<String> = args
        .iter()
        .skip(1)
        .filter(|a| *a != "--list" && *a != "--analyze")
        .cloned()
        .collect();
    let given_root = rest.iter().position(|a| a == "--jsbsim-root");
    let root = match given_root {
        Some(i) => rest.get(i + 1).map(std::path::PathBuf::from),
        None => catalogue::root(None),
    }
    .ok_or_else(|| catalogue::HOW_TO_GET.to_string())?;
    catalogue::checked_root(&root)?;
    if given_root.is_none() {
        rest.extend(["--jsbsim-root".to_string(), root.display().to_string()]);
    }
    let condition = rest.join(" ");
    if !condition.contains("--altitude-m") {
        return Err(format!(
            "--list --analyze needs a flight condition: --altitude-m H (--mach M | --speed V) \
             [--load-factor N | --alpha-deg A]\n{}",
            cli::USAGE
        ));
    }
    let names = catalogue::names(&root);
    let rows: Vec<(String, bool)> = names
        .par_iter()
        .map(|name| {
            let source = format!("jsbsim:{name} {condition}");
            routed_row(
                name,
                &cli::source(&source).map_err(|e| without(&e, &source)),
            )
        })
        .collect();
    let shown: Vec<&String> = args
        .iter()
        .skip(1)
        .filter(|a| *a != "--list" && *a != "--analyze")
        .collect();
    let mut text = format!(
        "{} models of {} at `{}`, each linearised at its trim (load factor 1 unless given), \
         elevator increment {DELTA_E_DEG} deg from the trim, rudder 0:\n\n\
         | model | import | critical jump P0 rad/s | delta_a deg | within aileron limit | \
         first departure | P0 rad/s | delta_a deg |\n|---|---|---:|---:|---|---|---:|---:|\n",
        names.len(),
        root.join("aircraft").display(),
        shown
            .iter()
            .map(|s| s.as_str())
            .collect::<Vec<_>>()
            .join(" ")
    );
    for (r, _) in &rows {
        text += r;
    }
    text += &format!(
        "\n{} models answered by the exact path (a case the certified route does not cover, or \
         a failed certificate)\n",
        rows.iter().filter(|(_, exact)| *exact).count()
    );
    Ok(text)
}

/// The table row of catalogue model `name` imported as `imported`.
pub fn row(name: &str, imported: &Result<Aircraft, String>) -> String {
    routed_row(name, imported).0
}

/// [`row`], and whether the exact path answered (the certified route did not: a case it does
/// not cover, or a failed certificate), as the envelope counts its points.
fn routed_row(name: &str, imported: &Result<Aircraft, String>) -> (String, bool) {
    let ac = match imported {
        Ok(ac) => ac,
        Err(e) => return (format!("| {name} | no: {} | | | | | | |\n", cell(e)), false),
    };
    let analysis = analyze_first_departure(ac, DELTA_E_DEG.to_radians());
    let import = import_cell(&ac.warnings);
    match analysis {
        Ok((a, route)) => (
            format!("| {name} | {import} | {} |\n", answers(&a)),
            route.fallback().is_some(),
        ),
        Err(e) => (
            format!(
                "| {name} | {import} | not analysed: {} | | | | | |\n",
                cell(&e.to_string())
            ),
            false,
        ),
    }
}

/// The import cell of an aircraft with `warnings`: "yes", with what the warnings concern.
fn import_cell(warnings: &[String]) -> String {
    let clamped = |w: &&String| w.starts_with(crate::jsbsim::clamp::WARNING_START);
    let mut notes = Vec::new();
    if warnings.iter().any(|w| !clamped(&w)) {
        notes.push("inertia breaks a triangle inequality");
    }
    if warnings.iter().any(|w| clamped(&w)) {
        notes.push("tables read beyond their range");
    }
    if notes.is_empty() {
        "yes".to_string()
    } else {
        format!("yes ({})", notes.join("; "))
    }
}

/// The six answer cells of an analysis.
fn answers(a: &Analysis) -> String {
    let critical = match (&a.critical, &a.critical_note) {
        (Some(c), _) => format!(
            "{:.4} | {:.2} | {}",
            c.p0,
            c.delta_a_deg,
            match c.within_limits {
                Some(true) => "yes",
                Some(false) => "no",
                None => "no limit given",
            }
        ),
        (None, note) => format!("none: {} | | ", cell(note.as_deref().unwrap_or("no fold"))),
    };
    let first = match &a.first_departure {
        Some(f) => format!(
            "{}{} | {:.4} | {:.2}",
            f.kind,
            if f.outside_validity() {
                " (outside validity range)"
            } else {
                ""
            },
            f.p0,
            f.delta_a_deg
        ),
        None => "none within the aileron range | | ".to_string(),
    };
    format!("{critical} | {first}")
}

/// `message` without the `source` it names first (with its line and column), the rest of a
/// loader's message.
fn without(message: &str, source: &str) -> String {
    match message.strip_prefix(source) {
        Some(rest) => rest
            .trim_start_matches(|c: char| c == ':' || c.is_ascii_digit())
            .trim_start()
            .to_string(),
        None => message.to_string(),
    }
}

/// A message as one Markdown table cell: its first line, the model's path left out, `|`
/// escaped.
fn cell(message: &str) -> String {
    let line = message.lines().next().unwrap_or_default();
    let line = match line.find(".xml") {
        Some(i) => line[i + 4..].trim_start_matches([':', ' ']).to_string(),
        None => line.to_string(),
    };
    line.replace('|', "\\|")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_refusal_is_one_cell_without_source_path_or_bars() {
        let source = "jsbsim:c172x --altitude-m 6096 --mach 0.6 --level-flight";
        let message = format!("{source}:42:14: key `coefficients.Cl_delta_a`: expected nonzero");
        assert_eq!(
            without(&message, source),
            "key `coefficients.Cl_delta_a`: expected nonzero"
        );
        assert_eq!(without("no level flight", source), "no level flight");
        assert_eq!(
            cell("/root/aircraft/J246/J246.xml:58: <mass_balance>: |x| too big\nmore"),
            "58: <mass_balance>: \\|x\\| too big"
        );
    }
}
