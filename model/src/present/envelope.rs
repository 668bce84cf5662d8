//! `model envelope`: the options checked (every range before any work starts), the envelope
//! computed with a progress bar on a terminal, and printed as a table or JSON; `--out` writes
//! the folder ([`super::envelope_folder`]).

use super::failure::{stdout_error, Failure};
use super::numbers::fixed;
use super::options::{elevator, EnvelopeArgs};
use super::progress::{progress_bar, set};
use crate::envelope::source::Source;
use crate::envelope::uncertainty::Uncertainty;
use crate::envelope::{cleared_envelope, Elevator, Envelope, Grid, Point, Range};
use std::io::Write;
use std::process::ExitCode;

/// The elevator of `a`: the load factor (finite, within +-20 g), the increment, or 1 g.
fn chosen_elevator(a: &EnvelopeArgs) -> Result<Elevator, Failure> {
    match (a.load_factor, a.delta_e_deg) {
        (Some(n), _) if !(n.is_finite() && n.abs() <= 20.0) => Err(Failure::Input(format!(
            "--load-factor = {n}: expected a finite load factor of at most 20 g"
        ))),
        (Some(n), _) => Ok(Elevator::LoadFactor(n)),
        (None, Some(d)) => Ok(Elevator::Increment(elevator(d)?)),
        (None, None) => Ok(Elevator::default()),
    }
}

/// `model envelope`.
pub fn command(a: &EnvelopeArgs, out: &mut dyn Write) -> Result<ExitCode, Failure> {
    let source = Source::parse(&a.source)?;
    let grid = Grid::new(
        Range::parse(&a.altitude_m, "--altitude-m")?,
        Range::parse(&a.mach, "--mach")?,
    )?;
    let elevator = chosen_elevator(a)?;
    let uncertainty = match &a.uncertainty {
        Some(spec) => Some(Uncertainty::parse(spec).map_err(Failure::Input)?),
        None => None,
    };
    let loaded = source.load()?;
    if let Some(u) = &uncertainty {
        u.check(&loaded, &a.source, &grid).map_err(Failure::Input)?;
    }
    let bar = progress_bar("envelope");
    let chosen = (elevator, uncertainty.as_ref());
    let env = cleared_envelope(&loaded, &a.source, &grid, chosen, &|f| set(&bar, f));
    if let Some(b) = bar {
        b.finish_and_clear();
    }
    let json = serde_json::to_string_pretty(&env).map_err(|e| e.to_string())?;
    let printed = if a.json {
        writeln!(out, "{json}")
    } else {
        write!(out, "{}", text(&env))
    }
    .and_then(|()| out.flush())
    .map_err(stdout_error);
    if let Some(dir) = &a.out {
        super::envelope_folder::write_folder(dir, &env, &json).map_err(Failure::Output)?;
    }
    printed?;
    Ok(ExitCode::SUCCESS)
}

/// `x` with `digits` decimals, or `-`.
pub fn cell(x: Option<f64>, digits: usize) -> String {
    x.map_or("-".to_string(), |v| fixed(v, digits))
}

/// The first departure's kind at `p`: `unstable_trim` (at P0 = 0), `jump`, `hopf`, `none` (stable
/// throughout), or `-` where there is no analysis.
pub fn departure_kind(p: &Point) -> &'static str {
    match (&p.first_departure, p.route) {
        (Some(d), _) => d.kind,
        (None, Some(_)) => "none",
        (None, None) => "-",
    }
}

/// The table: one line per point, then the counts.
pub fn text(env: &Envelope) -> String {
    let mut s = format!(
        "{}: envelope at elevator {} (delta_e is the increment from each point's level flight)\n\n",
        env.source, env.elevator
    );
    s += "altitude_m   mach   V_m_s  alpha_deg  delta_e_deg  p0_rad_s  delta_a_deg  margin_deg  first_departure\n";
    for p in &env.points {
        let c = p.critical.as_ref();
        s += &format!(
            "{:>10}  {:>5}  {:>6}  {:>9}  {:>11}  {:>8}  {:>11}  {:>10}  {}\n",
            fixed(p.altitude_m, 0),
            fixed(p.mach, 3),
            fixed(p.speed_m_s, 1),
            cell(p.alpha_deg, 3),
            cell(p.delta_e_deg, 3),
            cell(c.map(|c| c.p0), 4),
            cell(c.map(|c| c.delta_a_deg), 3),
            cell(p.margin_deg, 3),
            match (&p.reason, &p.error) {
                (Some(_), _) => "no level flight".to_string(),
                (None, Some(_)) => "not analysed (see --json)".to_string(),
                _ => departure_kind(p).to_string(),
            }
        );
    }
    s += &format!(
        "\n{} points: {} without level flight, {} answered by the exact path (a case the \
         certified route does not cover, or a failed certificate), {} with a full-stick roll that jumps (margin >= 0)\n",
        env.points.len(),
        env.untrimmed,
        env.exact_fallbacks,
        env.points
            .iter()
            .filter(|p| p.margin_deg.is_some_and(|m| m >= 0.0))
            .count()
    );
    let unstable = env
        .points
        .iter()
        .filter(|p| departure_kind(p) == "unstable_trim")
        .count();
    if unstable > 0 {
        s += &format!(
            "{unstable} with an unstable trim at P0 = 0 (first_departure unstable_trim): the bare \
             airframe needs its stability augmentation there, and their jump figures describe an \
             airframe that cannot hold the trim unaided\n"
        );
    }
    s + &super::envelope_clearance::text(env)
}
