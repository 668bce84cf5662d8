//! The options of each command of `model` (clap), and the checks that turn their values into
//! what a computation takes: angles in rad (refused, naming the option, when not finite or out
//! of range), the elevator range of a clearance map, and the aircraft argument (`A`, `B` or a
//! file).

use crate::aircraft::{self, Aircraft};
use crate::present::failure::Failure;
use clap::Args;
use std::path::{Path, PathBuf};

/// Options of `analyze`.
#[derive(Args)]
pub struct AnalyzeArgs {
    /// `A` or `B` (the paper's aircraft), the path of an aircraft TOML file, or a JSBSim model
    /// as "jsbsim:MODEL --altitude-m H (--mach M | --speed V) [--load-factor N]" (quoted as
    /// one).
    pub aircraft: String,
    /// Elevator in degrees: the increment from the trim for an aircraft whose file gives its
    /// trim (an import; default 0), else the deflection from zero lift (default 2, Figs 7-8).
    #[arg(long, allow_hyphen_values = true)]
    pub delta_e_deg: Option<f64>,
    /// Print JSON instead of a table. JSON carries every digit of every number, so it comes
    /// from the exact path (correctly rounded roots) unless the table's route is asked for
    /// with --certified.
    #[arg(long)]
    pub json: bool,
    /// Force the exact (big-rational) path; by default the table comes from the certified
    /// floating-point route, which falls back to the exact path whenever a certificate fails.
    #[arg(long, conflicts_with = "certified")]
    pub exact: bool,
    /// With --json: the certified route's numbers (each roll rate within its certified bracket
    /// of about 1e-10 relative width, the trim evaluated from the enclosures' midpoints, so
    /// the last digits differ from the exact path's).
    #[arg(long)]
    pub certified: bool,
    /// Print every row of the tables; by default a table shows the rows within the aircraft's
    /// limits and validity range and counts the others (JSON always has every row).
    #[arg(long)]
    pub all: bool,
}

/// Options of `continue`.
#[derive(Args)]
pub struct ContinueArgs {
    /// `A` or `B` (the paper's aircraft), the path of an aircraft TOML file, or a JSBSim model
    /// as "jsbsim:MODEL --altitude-m H (--mach M | --speed V) [--load-factor N]" (quoted as
    /// one).
    pub aircraft: String,
    /// The continuation parameter: delta_a, delta_e or delta_r.
    #[arg(long, default_value = "delta_a")]
    pub param: String,
    /// Lower end of the parameter range, deg (default -0.8 rad).
    #[arg(long, default_value_t = -45.8366, allow_hyphen_values = true)]
    pub min_deg: f64,
    /// Upper end of the parameter range, deg (default 0.8 rad).
    #[arg(long, default_value_t = 45.8366, allow_hyphen_values = true)]
    pub max_deg: f64,
    /// Elevator in degrees when it is not the parameter: the increment from the trim for an
    /// aircraft whose file gives its trim (an import; default 0), else the deflection from zero
    /// lift (default 2, Figs 7-8).
    #[arg(long, allow_hyphen_values = true)]
    pub delta_e_deg: Option<f64>,
    /// Zero-sideslip manoeuvre by extended bifurcation analysis (section V.B, Fig. 9).
    #[arg(long)]
    pub zero_sideslip: bool,
    /// Print JSON instead of a summary.
    #[arg(long)]
    pub json: bool,
    /// Also write every point as CSV to the one file FILE (units in the header), replaced
    /// whole.
    #[arg(long, value_name = "FILE")]
    pub csv: Option<PathBuf>,
}

/// Options of `report` and `plot`.
#[derive(Args)]
pub struct FiguresArgs {
    /// `A` or `B` (the paper's aircraft), the path of an aircraft TOML file, or a JSBSim model
    /// as "jsbsim:MODEL --altitude-m H (--mach M | --speed V) [--load-factor N]" (quoted as
    /// one).
    pub aircraft: String,
    /// The folder to write the files into (default `out/<command>-<aircraft>`, e.g.
    /// out/report-a). Checked before any work; replaced whole when every file is written (an
    /// existing folder only if `model` wrote it or it is empty).
    #[arg(long, value_name = "DIR")]
    pub out: Option<PathBuf>,
    /// Elevator in degrees: the increment from the trim for an aircraft whose file gives its
    /// trim (an import; default 0), else the deflection from zero lift (default 2, Figs 7-8).
    #[arg(long, allow_hyphen_values = true)]
    pub delta_e_deg: Option<f64>,
}

/// Options of `simulate`.
#[derive(Args)]
pub struct SimulateArgs {
    /// `A` or `B` (the paper's aircraft), the path of an aircraft TOML file, or a JSBSim model
    /// as "jsbsim:MODEL --altitude-m H (--mach M | --speed V) [--load-factor N]" (quoted as
    /// one).
    pub aircraft: String,
    /// Aileron step, degrees.
    #[arg(long, allow_hyphen_values = true)]
    pub delta_a_deg: f64,
    /// Elevator in degrees: the increment from the trim for an aircraft whose file gives its
    /// trim (an import; default 0), else the deflection from zero lift (default 2, Figs 7-8).
    #[arg(long, allow_hyphen_values = true)]
    pub delta_e_deg: Option<f64>,
    /// Length of the run, s.
    #[arg(long, default_value_t = 20.0, allow_hyphen_values = true)]
    pub t_end: f64,
    /// Rudder on the zero-sideslip schedule (aileron-rudder interconnect, Fig. 10).
    #[arg(long)]
    pub zero_sideslip: bool,
    /// Integrate the PSS model instead of the 7th-order model.
    #[arg(long)]
    pub pss: bool,
    /// Also write the time history as CSV to the one file FILE (units in the header),
    /// replaced whole.
    #[arg(long, value_name = "FILE")]
    pub csv: Option<PathBuf>,
    /// The native nonlinear 6-DOF of a `jsbsim:` source instead, from its n-g trim
    /// (`--delta-a-deg` in the paper's sign: positive rolls left).
    #[arg(long)]
    pub six_dof: bool,
    /// 6-DOF: geometric altitude, m (or inside the `jsbsim:` source).
    #[arg(long, allow_hyphen_values = true, requires = "six_dof")]
    pub altitude_m: Option<f64>,
    /// 6-DOF: Mach number (or inside the `jsbsim:` source).
    #[arg(long, allow_hyphen_values = true, requires = "six_dof")]
    pub mach: Option<f64>,
    /// 6-DOF: load factor of the trim the run starts from (default 1; or inside the source).
    #[arg(long, allow_hyphen_values = true, requires = "six_dof")]
    pub load_factor: Option<f64>,
    /// 6-DOF: thrust `off` (gliding) or `trim` (held at the trim's drag balance).
    #[arg(
        long,
        value_name = "off|trim",
        default_value = "off",
        requires = "six_dof"
    )]
    pub thrust: String,
    /// 6-DOF: integration step, s (default 1/120, JSBSim's rate).
    #[arg(long, allow_hyphen_values = true, requires = "six_dof")]
    pub dt: Option<f64>,
    /// 6-DOF: write the time-history figure (SVG, PNG and its CSV) into DIR.
    #[arg(long, value_name = "DIR", requires = "six_dof")]
    pub out: Option<PathBuf>,
}

/// Options of `validate`.
#[derive(Args)]
pub struct ValidateArgs {
    /// The model: "jsbsim:MODEL" (the flight condition inside it or as the options below).
    pub source: String,
    /// Geometric altitude, m.
    #[arg(long, allow_hyphen_values = true)]
    pub altitude_m: Option<f64>,
    /// Mach number.
    #[arg(long, allow_hyphen_values = true)]
    pub mach: Option<f64>,
    /// Load factor of the trim both models start from (default 1).
    #[arg(long, allow_hyphen_values = true)]
    pub load_factor: Option<f64>,
    /// The aileron steps `A:B:STEP`, deg of |delta_a| (default 1 to the aileron limit + 4, every 1).
    #[arg(long, value_name = "A:B:STEP")]
    pub delta_a_deg: Option<String>,
    /// Length of each run, s.
    #[arg(long, default_value_t = 10.0, allow_hyphen_values = true)]
    pub t_end: f64,
    /// Where the plateau figure goes (default `out/validate-<model>/`).
    #[arg(long, value_name = "DIR")]
    pub out: Option<PathBuf>,
}

/// Options of `clear`.
#[derive(Args)]
pub struct ClearArgs {
    /// The path of an aircraft TOML file with an `[uncertainty]` table (or `A`/`B`, or a JSBSim
    /// model as "jsbsim:MODEL --altitude-m H (--mach M | --speed V) [--load-factor N]": a
    /// point).
    pub aircraft: String,
    /// Elevator in degrees: the increment from the trim for an aircraft whose file gives its
    /// trim (an import; default 0), else the deflection from zero lift (default 2, Figs 7-8).
    #[arg(long, allow_hyphen_values = true, conflicts_with = "delta_e_range")]
    pub delta_e_deg: Option<f64>,
    /// A range of elevator deflections `A:B:STEP` in degrees (a clearance map).
    #[arg(long, value_name = "A:B:STEP", allow_hyphen_values = true)]
    pub delta_e_range: Option<String>,
    /// Monte Carlo samples (certified route; the exact path where a certificate fails), 0
    /// to 10^7 per setting.
    #[arg(long, default_value_t = 1000, allow_hyphen_values = true)]
    pub samples: usize,
    /// Tolerance on the roll-rate gap, rad/s, at least 1e-12 (the aileron gap is 10 times it,
    /// in deg).
    #[arg(long, default_value_t = 1e-3, allow_hyphen_values = true)]
    pub tolerance: f64,
    /// Seed of the Monte Carlo samples and of the worst-case search.
    #[arg(long, default_value_t = 1, allow_hyphen_values = true)]
    pub seed: u64,
    /// Print JSON instead of text.
    #[arg(long)]
    pub json: bool,
    /// Also write summary.md, summary.json, samples.csv and the histograms into the folder DIR
    /// (nothing is written without it). Checked before any work; replaced whole when every
    /// file is written (an existing folder only if `model` wrote it or it is empty).
    #[arg(long, value_name = "DIR")]
    pub out: Option<PathBuf>,
}

/// Options of `envelope`.
#[derive(Args)]
pub struct EnvelopeArgs {
    /// The model: "jsbsim:MODEL [--set PROPERTY=VALUE]... [--jsbsim-root DIR]" (quoted as one;
    /// the ranges below give the flight conditions, each point trimmed at the load factor).
    pub source: String,
    /// Altitudes, m: START:STOP:STEP or one value.
    #[arg(long, value_name = "START:STOP:STEP", allow_hyphen_values = true)]
    pub altitude_m: String,
    /// Mach numbers: START:STOP:STEP or one value.
    #[arg(long, value_name = "START:STOP:STEP", allow_hyphen_values = true)]
    pub mach: String,
    /// Trim every point in a wings-level pull-up at this load factor (g) and linearise there:
    /// alpha and elevator for lift N x weight and no pitching moment, pitch rate (N - 1) g / V
    /// (default 1, level flight; 0 is the unloaded roll). A point where the elevator's travel
    /// or the lift cannot hold it is untrimmable.
    #[arg(long, allow_hyphen_values = true)]
    pub load_factor: Option<f64>,
    /// The elevator increment from each point's trim elevator, deg (the paper's delta_e;
    /// default 0, the trim itself).
    #[arg(long, allow_hyphen_values = true)]
    pub delta_e_deg: Option<f64>,
    /// Print JSON instead of a table.
    #[arg(long)]
    pub json: bool,
    /// Also write envelope.csv, summary.md, summary.json and the maps (SVG, PNG, CSV) into the
    /// folder DIR (nothing is written without it). Checked before any work; replaced whole
    /// when every file is written (an existing folder only if `model` wrote it or it is empty).
    #[arg(long, value_name = "DIR")]
    pub out: Option<PathBuf>,
    /// Make every point a certified clearance over a box of its coefficients: a relative width
    /// for every coefficient ("10%"), a list "Cl_p=10%,Cn_r=0.02" (relative or absolute
    /// half-widths), or a TOML file whose `[uncertainty]` table is read as `model clear` reads it.
    #[arg(long, value_name = "SPEC", allow_hyphen_values = true)]
    pub uncertainty: Option<String>,
    /// Check the criterion with the native 6-DOF: every point that predicts a jump within the
    /// aileron limit, and a seeded sample of the others, gets a short aileron sweep and the
    /// verdict of `model validate` (JSON `validation`, CSV columns, the map `validation`).
    #[arg(long)]
    pub validate: bool,
    /// With --validate: the fraction of the other analysed points validated too (seeded), 0 to 1.
    #[arg(
        long,
        value_name = "F",
        default_value_t = 0.1,
        allow_hyphen_values = true,
        requires = "validate"
    )]
    pub validate_sample: f64,
}

/// Options of `convert`.
#[derive(Args)]
pub struct ConvertArgs {
    /// The path of a nondimensional body-axis aircraft TOML file, or a JSBSim model as
    /// "jsbsim:MODEL --altitude-m H (--mach M | --speed V) [--load-factor N]" (quoted as one).
    #[arg(value_name = "AIRCRAFT")]
    pub file: String,
}

/// Options of `emit`.
#[derive(Args)]
pub struct EmitArgs {
    /// Write nothing; exit 1 naming every stale file (first finishes an emit that was killed
    /// after staging every file, and removes temporaries of killed runs).
    #[arg(long)]
    pub check: bool,
    /// Workspace root (default: the workspace this binary was built from).
    #[arg(long, value_name = "DIR")]
    pub root: Option<PathBuf>,
}

/// The elevator of a command on `ac`, rad: `--delta-e-deg` when given, else the aircraft's
/// default ([`Aircraft::default_delta_e_rad`]).
pub fn elevator_of(ac: &Aircraft, deg: Option<f64>) -> Result<f64, Failure> {
    deg.map_or(Ok(ac.default_delta_e_rad()), elevator)
}

/// An elevator deflection in degrees converted to rad, or an error in degrees.
pub fn elevator(deg: f64) -> Result<f64, Failure> {
    if deg.is_finite() && deg.abs() <= 90.0 {
        Ok(deg.to_radians())
    } else {
        Err(Failure::Input(format!(
            "--delta-e-deg = {deg}: expected a finite elevator deflection of at most 90 deg \
             (delta_e)"
        )))
    }
}

/// `A:B:STEP` in degrees as the list of elevator deflections in rad.
pub fn delta_e_list(r: &str) -> Result<Vec<f64>, Failure> {
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
pub fn finite_angle(name: &str, deg: f64) -> Result<f64, Failure> {
    if deg.is_finite() {
        Ok(deg.to_radians())
    } else {
        Err(Failure::Input(format!(
            "--{}-deg = {deg}: expected a finite angle in degrees",
            name.replace('_', "-")
        )))
    }
}

/// `A`/`B` (any case) name the built-in aircraft; anything else is a TOML file. A name that is
/// neither a built-in nor a file gets the list of built-ins and the shipped file it may mean.
/// The aircraft's warnings (an inertia no rigid body has) go to stderr.
pub fn load_aircraft(arg: &str) -> Result<Aircraft, String> {
    let ac = read_aircraft(arg)?;
    for w in &ac.warnings {
        eprintln!("warning: {w}");
    }
    Ok(ac)
}

/// The aircraft `arg` names, as [`load_aircraft`] without printing its warnings (for a command
/// whose output carries them).
pub fn read_aircraft(arg: &str) -> Result<Aircraft, String> {
    if let Some(ac) = Aircraft::builtin(arg) {
        return Ok(ac);
    }
    if arg.starts_with("jsbsim:") {
        return crate::jsbsim::cli::source(arg);
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
