//! `model envelope`: the options checked (every range before any work starts), the envelope
//! computed with a progress bar on a terminal, and printed as a table or JSON; `--out` writes
//! the folder ([`super::envelope_folder`]).

use super::failure::{stdout_error, Failure};
use super::numbers::fixed;
use super::options::{elevator, EnvelopeArgs};
use super::outputs::{begin_folder, commit_folder};
use super::progress::{progress_bar, set};
use crate::analysis::FirstDeparture;
use crate::envelope::source::Source;
use crate::envelope::uncertainty::Uncertainty;
use crate::envelope::validation::validate_envelope;
use crate::envelope::{cleared_envelope, Elevator, Envelope, Grid, Point, Range, SpeedAxis};
use crate::jsbsim::import::Loaded;
use std::io::Write;
use std::process::ExitCode;

/// The elevator of `a` with `source`: the load factor of the trim (the envelope's or the
/// source's, the same if both; finite, within +-20 g; default 1) and the increment from it
/// (default 0).
fn chosen_elevator(a: &EnvelopeArgs, source: &Source) -> Result<Elevator, Failure> {
    let load_factor = match (a.load_factor, source.load_factor) {
        (Some(n), Some(m)) if n != m => {
            return Err(Failure::Input(format!(
                "--load-factor = {n} but the source says --load-factor {m}: give one"
            )))
        }
        (Some(n), _) | (None, Some(n)) => n,
        (None, None) => 1.0,
    };
    if !(load_factor.is_finite() && load_factor.abs() <= 20.0) {
        return Err(Failure::Input(format!(
            "--load-factor = {load_factor}: expected a finite load factor of at most 20 g"
        )));
    }
    Ok(Elevator {
        load_factor,
        increment: elevator(a.delta_e_deg.unwrap_or(0.0))?,
    })
}

/// The grid's speed axis of `a` and its range as given: `--mach` or `--speed`, exactly one
/// (the command line's parser says so too; a caller that fills in the options checks here).
fn speed_axis(a: &EnvelopeArgs) -> Result<(SpeedAxis, &str), Failure> {
    match (&a.mach, &a.speed) {
        (Some(m), None) => Ok((SpeedAxis::Mach, m)),
        (None, Some(v)) => Ok((SpeedAxis::TrueAirspeed, v)),
        (Some(_), Some(_)) => Err(Failure::Input(
            "--mach and --speed: give one (the grid's speeds are Mach numbers or true \
             airspeeds in m/s, not both)"
                .to_string(),
        )),
        (None, None) => Err(Failure::Input(
            "--mach or --speed is required: the grid's speeds, Mach numbers (--mach \
             START:STOP:STEP) or true airspeeds in m/s (--speed START:STOP:STEP)"
                .to_string(),
        )),
    }
}

/// What `model envelope` computes, every option checked and the model read before any work.
pub struct Plan {
    /// The model, read once.
    pub loaded: Loaded,
    /// The grid of altitudes and speeds.
    pub grid: Grid,
    /// The load factor of every point's trim and the elevator increment from it.
    pub elevator: Elevator,
    /// The box every point is cleared over, with `--uncertainty`.
    pub uncertainty: Option<Uncertainty>,
    /// With `--validate`, the fraction of the points without a predicted jump validated too.
    pub validate_sample: Option<f64>,
}

/// The sample of `--validate`, checked: `None` without it.
fn validate_sample(a: &EnvelopeArgs, elevator: Elevator) -> Result<Option<f64>, Failure> {
    if !a.validate {
        return Ok(None);
    }
    if !(a.validate_sample.is_finite() && (0.0..=1.0).contains(&a.validate_sample)) {
        return Err(Failure::Input(format!(
            "--validate-sample = {}: expected a fraction of the points, 0 to 1",
            a.validate_sample
        )));
    }
    if elevator.increment != 0.0 {
        return Err(Failure::Input(format!(
            "--validate with --delta-e-deg {}: the 6-DOF holds each point's trim elevator \
             (expected no --delta-e-deg, or 0)",
            elevator.increment.to_degrees()
        )));
    }
    Ok(Some(a.validate_sample))
}

impl Plan {
    /// The plan of `a`, or the first option that is wrong.
    pub fn new(a: &EnvelopeArgs) -> Result<Plan, Failure> {
        let source = Source::parse(&a.source)?;
        let (axis, speeds) = speed_axis(a)?;
        let grid = Grid::over(
            Range::parse(&a.altitude_m, "--altitude-m")?,
            axis,
            Range::parse(speeds, axis.flag())?,
        )?;
        let elevator = chosen_elevator(a, &source)?;
        let uncertainty = match &a.uncertainty {
            Some(spec) => Some(Uncertainty::parse(spec).map_err(Failure::Input)?),
            None => None,
        };
        let validate_sample = validate_sample(a, elevator)?;
        let loaded = source.load()?;
        if let Some(u) = &uncertainty {
            u.check(&loaded, &a.source, &grid, elevator.load_factor)
                .map_err(Failure::Input)?;
        }
        Ok(Plan {
            loaded,
            grid,
            elevator,
            uncertainty,
            validate_sample,
        })
    }

    /// The envelope of the plan, named `source`, validated with `--validate`; `progress` gets
    /// the fraction done (from any thread): with `--validate`, the analysis counts for the
    /// first fifth and the 6-DOF's sweeps for the rest.
    pub fn run(&self, source: &str, progress: &(dyn Fn(f64) + Sync)) -> Envelope {
        let chosen = (self.elevator, self.uncertainty.as_ref());
        let Some(sample) = self.validate_sample else {
            return cleared_envelope(&self.loaded, source, &self.grid, chosen, progress);
        };
        let first = |f: f64| progress(0.2 * f);
        let mut env = cleared_envelope(&self.loaded, source, &self.grid, chosen, &first);
        validate_envelope(&mut env, &self.loaded, sample, &|f| progress(0.2 + 0.8 * f));
        env
    }
}

/// `model envelope`.
pub fn command(a: &EnvelopeArgs, out: &mut dyn Write) -> Result<ExitCode, Failure> {
    let plan = Plan::new(a)?;
    let staged = a
        .out
        .as_ref()
        .map(|dir| begin_folder(dir, "envelope"))
        .transpose()?;
    let bar = progress_bar("envelope");
    let env = plan.run(&a.source, &|f| set(&bar, f));
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
    if let Some(staged) = staged {
        super::envelope_folder::write_folder(staged.path(), &env, &json)
            .map_err(Failure::Output)?;
        commit_folder(staged)?;
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

/// Whether the first departure at `p` is a jump or Hopf point whose trim lies outside the
/// aircraft's validity range.
pub fn beyond_validity(p: &Point) -> bool {
    p.first_departure
        .as_ref()
        .is_some_and(FirstDeparture::outside_validity)
}

/// The headers of the flight state's columns that begin every table's rows: altitude, Mach and
/// true airspeed, whichever the grid steps over.
pub const STATE_HEADER: &str = "altitude_m   mach   V_m_s";

/// The flight state's cells of `p` under [`STATE_HEADER`].
pub fn state_cells(p: &Point) -> String {
    format!(
        "{:>10}  {:>5}  {:>6}",
        fixed(p.altitude_m, 0),
        fixed(p.mach, 3),
        fixed(p.speed_m_s, 1)
    )
}

/// The flight state of `p` in words: `"altitude 3000 m, Mach 0.500, 164.3 m/s"`.
fn state_words(p: &Point) -> String {
    format!(
        "altitude {} m, Mach {}, {} m/s",
        fixed(p.altitude_m, 0),
        fixed(p.mach, 3),
        fixed(p.speed_m_s, 1)
    )
}

/// The table: one line per point, then the counts.
pub fn text(env: &Envelope) -> String {
    let mut s = format!(
        "{}: envelope over altitude x {}; {} (each point linearised at its own trim; delta_e \
         is the increment from each point's trim elevator)\n\n",
        env.source,
        env.speed_axis.label(),
        env.elevator
    );
    s += STATE_HEADER;
    s += "  alpha_deg  de_trim_deg  delta_e_deg  p0_rad_s  delta_a_deg  margin_deg  first_departure\n";
    for p in &env.points {
        // A Hopf departure without a jump shows the Hopf point's roll rate, aileron and margin.
        let hopf_only =
            p.critical.is_none() && p.first_departure.as_ref().is_some_and(|d| d.kind == "hopf");
        let (p0, delta_a, margin) = match (&p.critical, &p.first_departure) {
            (Some(c), _) => (Some(c.p0), Some(c.delta_a_deg), p.margin_deg),
            (None, Some(d)) if hopf_only => {
                (Some(d.p0), Some(d.delta_a_deg), p.departure_margin_deg)
            }
            _ => (None, None, None),
        };
        s += &format!(
            "{}  {:>9}  {:>11}  {:>11}  {:>8}  {:>11}  {:>10}  {}\n",
            state_cells(p),
            cell(p.alpha_deg, 3),
            cell(p.elevator_trim_deg, 3),
            cell(p.delta_e_deg, 3),
            cell(p0, 4),
            cell(delta_a, 3),
            cell(margin, 3),
            match (&p.reason, &p.error) {
                (Some(_), _) => "untrimmable (see --json)".to_string(),
                (None, Some(_)) => "not analysed (see --json)".to_string(),
                _ if hopf_only =>
                    "hopf (no jump: p0, delta_a, margin of the Hopf point)".to_string(),
                _ => departure_kind(p).to_string(),
            } + if beyond_validity(p) {
                "  [outside validity range]"
            } else {
                ""
            }
        );
    }
    s += &format!(
        "\n{} points: {} untrimmable, {} answered by the exact path (a case the \
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
    let beyond = env.points.iter().filter(|p| beyond_validity(p)).count();
    if beyond > 0 {
        s += &format!(
            "{beyond} whose first departure lies outside the validity range (|alpha| or |beta| \
             of its trim beyond the aircraft's [validity]): a departure of the linear \
             aerodynamics, which the aircraft's own need not share\n"
        );
    }
    s += &warnings_text(env);
    s + &super::envelope_clearance::text(env) + &super::envelope_validation::text(env)
}

/// The aircraft's warnings over the grid, each kind once: an inertia no rigid body has (with
/// the first point's sentence) and tables read beyond their breakpoints, with how many points
/// have each.
fn warnings_text(env: &Envelope) -> String {
    let clamped = |w: &String| w.starts_with(crate::jsbsim::clamp::WARNING_START);
    let mut s = String::new();
    let inertia: Vec<(&Point, &String)> = env
        .points
        .iter()
        .filter_map(|p| p.warnings.iter().find(|w| !clamped(w)).map(|w| (p, w)))
        .collect();
    if let Some((p, w)) = inertia.first() {
        s += &format!(
            "Warning: at {} of {} points the aircraft is analysed with a warning; at {}: {w}\n",
            inertia.len(),
            env.points.len(),
            state_words(p)
        );
    }
    let tables = env
        .points
        .iter()
        .filter(|p| p.warnings.iter().any(clamped))
        .count();
    if tables > 0 {
        s += &format!(
            "Warning: at {tables} of {} points the flight state reads tables beyond their \
             breakpoints (each point's warnings are in --json)\n",
            env.points.len()
        );
    }
    s
}
