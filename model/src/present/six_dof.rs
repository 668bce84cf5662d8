//! `model simulate jsbsim:MODEL --six-dof ...`: the native nonlinear 6-DOF of a JSBSim airframe
//! from its n-g trim, an aileron step; a summary line, the time history as CSV (`--csv`) and its
//! figure (`--out DIR`).

use super::failure::{stdout_error, write_file, Failure};
use super::numbers::fixed;
use super::options::SimulateArgs;
use super::outputs::{begin_folder, commit_folder, wrote};
use crate::jsbsim::coefficients::Setup;
use crate::jsbsim::condition::Condition;
use crate::jsbsim::import::{Alpha, Loaded};
use crate::jsbsim::surfaces::Control;
use crate::jsbsim::trim::{trim, Trim};
use crate::plot::{render, Axis, Dash, Figure, LegendPlace, Line, Panel, PlotStyle, Rgb};
use crate::six_dof::sweep::settled;
use crate::six_dof::{simulate, History, Settings, Thrust};
use std::io::Write;
use std::process::ExitCode;

/// The model, condition and load factor of a 6-DOF command, and the `jsbsim:` source with the
/// options given outside it appended (they win), which the import reads.
pub fn loaded_source(
    source: &str,
    (altitude_m, mach, load_factor): (Option<f64>, Option<f64>, Option<f64>),
) -> Result<(Loaded, Condition, f64, String), Failure> {
    if !source.starts_with("jsbsim:") {
        return Err(Failure::Input(format!(
            "{source}: the 6-DOF simulates a JSBSim airframe (expected a source jsbsim:MODEL, \
             e.g. jsbsim:f104 --altitude-m 7300 --mach 0.75); an aircraft file holds only the \
             linearised derivatives of the 7th-order model"
        )));
    }
    let mut spec = source.to_string();
    for (flag, v) in [
        ("--altitude-m", altitude_m),
        ("--mach", mach),
        ("--load-factor", load_factor),
    ] {
        if let Some(v) = v {
            spec += &format!(" {flag} {v}");
        }
    }
    let request = crate::jsbsim::cli::request(&spec)?;
    let n = match request.alpha {
        Alpha::Trim(n) => n,
        Alpha::Given(_) => {
            return Err(Failure::Input(
                "--alpha-deg: the 6-DOF starts from the n-g trim (expected --load-factor N)"
                    .to_string(),
            ))
        }
    };
    let speed = request.speed;
    let condition = Condition::new(request.altitude_m, speed)?;
    let loaded = Loaded::new(&request.model, request.root.as_deref(), &request.settings)?;
    Ok((loaded, condition, n, spec))
}

/// The trim of `setup` at `n`, and the JSBSim aileron surface (rad) of the paper's `delta_a_deg`;
/// refused when the model reads its aileron only as normalised travel.
pub fn trim_and_aileron(setup: &Setup, n: f64, delta_a_deg: f64) -> Result<(Trim, f64), Failure> {
    if !delta_a_deg.is_finite() || delta_a_deg.abs() > 90.0 {
        return Err(Failure::Input(format!(
            "--delta-a-deg = {delta_a_deg}: expected a finite aileron deflection of at most 90 deg"
        )));
    }
    let per_unit = setup
        .surfaces
        .iter()
        .any(|s| s.control == Control::Aileron && s.per_unit_travel);
    if per_unit {
        return Err(Failure::Input(format!(
            "{}: the aerodynamics read the aileron only as normalised travel, which has no angle \
             to step (expected a model with fcs/left-aileron-pos-rad or -deg)",
            setup.model.file
        )));
    }
    let t = trim(setup, n)?;
    Ok((t, -delta_a_deg.to_radians()))
}

/// A 6-DOF run as `simulate --six-dof` makes it: the time history, the trim it started from
/// and the summary line the command prints.
pub struct SixDofRun {
    /// The time history.
    pub history: History,
    /// The n-g trim the run started from.
    pub trim: Trim,
    /// The summary line.
    pub summary: String,
}

/// Runs the command.
pub fn command(a: &SimulateArgs, out: &mut dyn Write) -> Result<ExitCode, Failure> {
    let run = six_dof_of(a)?;
    writeln!(out, "{}", run.summary).map_err(stdout_error)?;
    Ok(ExitCode::SUCCESS)
}

/// What `simulate --six-dof` computes and writes for the options of `a` (the CSV of `--csv`,
/// the folder of `--out`): everything but the printing, shared by the command line and Python.
pub fn six_dof_of(a: &SimulateArgs) -> Result<SixDofRun, Failure> {
    if a.pss || a.zero_sideslip || a.delta_e_deg.is_some() {
        return Err(Failure::Input(
            "--six-dof: --pss, --zero-sideslip and --delta-e-deg belong to the 7th-order model \
             (the 6-DOF holds the trim's elevator and the rudder neutral)"
                .to_string(),
        ));
    }
    let thrust = match a.thrust.as_str() {
        "off" => Thrust::Off,
        "trim" => Thrust::Trim,
        other => {
            return Err(Failure::Input(format!(
                "--thrust {other}: expected off or trim"
            )))
        }
    };
    let (loaded, condition, n, _) =
        loaded_source(&a.aircraft, (a.altitude_m, a.mach, a.load_factor))?;
    let setup = loaded.setup(condition);
    let (t, aileron) = trim_and_aileron(&setup, n, a.delta_a_deg)?;
    let mut settings = Settings::step(aileron, a.t_end);
    settings.thrust = thrust;
    if let Some(dt) = a.dt {
        settings.dt = dt;
    }
    if !(a.t_end.is_finite() && a.t_end > 0.0 && a.t_end <= 3600.0) {
        return Err(Failure::Input(format!(
            "--t-end = {}: expected the length of the run, 0 to 3600 s",
            a.t_end
        )));
    }
    if !(settings.dt.is_finite() && settings.dt >= 1e-4 && settings.dt <= 0.1) {
        return Err(Failure::Input(format!(
            "--dt = {}: expected an integration step of 1e-4 to 0.1 s",
            settings.dt
        )));
    }
    let staged = a
        .out
        .as_ref()
        .map(|dir| begin_folder(dir, "simulate"))
        .transpose()?;
    let h = simulate(&setup, &t, &settings)?;
    if let Some(path) = &a.csv {
        write_file(path, h.to_csv().as_bytes())?;
        wrote(path, "the time history as CSV");
    }
    let title = format!(
        "{} 6-DOF, {} m, Mach {}, n = {n}: aileron step {} deg",
        loaded.model.name,
        condition.altitude_m,
        fixed(condition.mach, 3),
        a.delta_a_deg
    );
    if let Some(staged) = staged {
        render(
            &staged.path().join("six_dof"),
            &figure(&h, &title),
            &PlotStyle::default(),
        )
        .map_err(|e| Failure::Output(e.to_string()))?;
        commit_folder(staged)?;
    }
    Ok(SixDofRun {
        summary: summary(&h, &t, &title),
        history: h,
        trim: t,
    })
}

/// The summary line: the trim, the settled roll rate (last 2 s) and how far the speed,
/// altitude and Mach moved.
pub fn summary(h: &History, t: &Trim, title: &str) -> String {
    let p = settled(h, 2.0);
    let end = h.t.len() - 1;
    format!(
        "{title}; trim alpha {} deg, elevator {}; {} s: settled roll rate {} rad/s (mean of the \
         last 2 s), V {} -> {} m/s, h {} -> {} m, Mach {} -> {}",
        fixed(t.alpha.to_degrees(), 3),
        t.elevator_text(),
        fixed(h.t[end], 2),
        fixed(p, 4),
        fixed(h.speed[0], 1),
        fixed(h.speed[end], 1),
        fixed(h.altitude[0], 0),
        fixed(h.altitude[end], 0),
        fixed(h.mach[0], 3),
        fixed(h.mach[end], 3)
    )
}

/// A panel of series against time.
fn panel(h: &History, area: [f64; 4], label: &str, series: &[(&str, &[f64], f64, Rgb)]) -> Panel {
    let t_end = h.t.last().copied().unwrap_or(1.0);
    let values = series
        .iter()
        .flat_map(|(_, v, k, _)| v.iter().map(move |x| x * k));
    let (lo, hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
        (lo.min(v), hi.max(v))
    });
    let pad = ((hi - lo) * 0.05).max(1e-6 * hi.abs().max(1.0));
    let lines = series
        .iter()
        .map(|(name, v, k, color)| Line {
            label: Some(name.to_string()),
            points: h.t.iter().zip(v.iter()).map(|(t, x)| (*t, x * k)).collect(),
            color: *color,
            dash: Dash::Solid,
            width: 2,
        })
        .collect();
    Panel {
        title: String::new(),
        area,
        x: Axis::linear("t (s)", 0.0, t_end),
        y: Axis::linear(label, lo - pad, hi + pad),
        lines,
        markers: vec![],
        legend: LegendPlace::UpperRight,
    }
}

/// The time-history figure: rates, aerodynamic angles, attitude, speed and altitude.
pub fn figure(h: &History, title: &str) -> Figure {
    let deg = 180.0 / std::f64::consts::PI;
    let cell = |row: f64, col: f64| [col * 0.5, row / 3.0, (col + 1.0) * 0.5, (row + 1.0) / 3.0];
    let panels = vec![
        panel(
            h,
            cell(0.0, 0.0),
            "rate (rad/s)",
            &[
                ("p", &h.p, 1.0, Rgb::BLUE),
                ("q", &h.q, 1.0, Rgb::GREEN),
                ("r", &h.r, 1.0, Rgb::RED),
            ],
        ),
        panel(
            h,
            cell(0.0, 1.0),
            "angle (deg)",
            &[
                ("alpha", &h.alpha, deg, Rgb::BLUE),
                ("beta", &h.beta, deg, Rgb::RED),
            ],
        ),
        panel(
            h,
            cell(1.0, 0.0),
            "attitude (deg)",
            &[
                ("phi", &h.phi, deg, Rgb::BLUE),
                ("theta", &h.theta, deg, Rgb::GREEN),
            ],
        ),
        panel(
            h,
            cell(1.0, 1.0),
            "V (m/s)",
            &[("V", &h.speed, 1.0, Rgb::BLUE)],
        ),
        panel(
            h,
            cell(2.0, 0.0),
            "h (m)",
            &[("h", &h.altitude, 1.0, Rgb::ORANGE)],
        ),
        panel(
            h,
            cell(2.0, 1.0),
            "Mach",
            &[("Mach", &h.mach, 1.0, Rgb::BLACK)],
        ),
    ];
    Figure {
        title: title.to_string(),
        panels,
        legend_area: None,
        note: String::new(),
    }
}
