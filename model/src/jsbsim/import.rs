//! An import from start to end: the model, the flight condition (alpha given or level flight:
//! lift equal to weight), the coefficients and their derivatives there, and the aircraft file.
//! A model read once ([`Loaded`]) gives the aircraft file of any number of flight conditions.

use super::catalogue;
use super::coefficients::{Setup, CL};
use super::condition::{Condition, Speed, State};
use super::derivatives::derivatives;
use super::model::Model;
use super::surfaces::surfaces;
use super::units::SLUG_PER_LB;
use super::write::Import;
use std::path::PathBuf;

/// How the angle of attack is chosen.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Alpha {
    /// Given, rad.
    Given(f64),
    /// Where lift equals weight.
    LevelFlight,
}

/// What to import.
#[derive(Clone, Debug, PartialEq)]
pub struct Request {
    /// Catalogue name or path of the model XML.
    pub model: String,
    /// The models' root directory, if given.
    pub root: Option<PathBuf>,
    /// Geometric altitude, m.
    pub altitude_m: f64,
    /// Speed.
    pub speed: Speed,
    /// Angle of attack.
    pub alpha: Alpha,
    /// `--set` values.
    pub settings: Vec<(String, f64)>,
}

/// The aircraft file (TOML text) of `request`, or why not.
pub fn import(request: &Request) -> Result<String, String> {
    let loaded = Loaded::new(&request.model, request.root.as_deref(), &request.settings)?;
    let condition = Condition::new(request.altitude_m, request.speed)?;
    let setup = loaded.setup(condition);
    let (alpha, alpha_source) = match request.alpha {
        Alpha::Given(a) => (a, "given".to_string()),
        Alpha::LevelFlight => (level_flight(&setup)?, LEVEL_FLIGHT.to_string()),
    };
    aircraft_file(&setup, alpha, &alpha_source)
}

/// How a level-flight alpha is described in the aircraft file.
pub const LEVEL_FLIGHT: &str = "level flight: lift equals weight, surfaces neutral";

/// A model read once, with its surfaces and the user's settings checked against it: the setup
/// of any number of flight conditions.
#[derive(Clone, Debug)]
pub struct Loaded {
    /// The model.
    pub model: Model,
    /// Its surfaces and how they are set.
    pub surfaces: Vec<super::surfaces::Surface>,
    /// The user's `--set` values.
    pub settings: Vec<(String, f64)>,
}

impl Loaded {
    /// Reads `model` (a catalogue name, looked up under `root` if given, or a path) and checks
    /// the `settings` against it.
    pub fn new(
        model: &str,
        root: Option<&std::path::Path>,
        settings: &[(String, f64)],
    ) -> Result<Loaded, String> {
        let given = std::path::Path::new(model);
        let path = if given.is_file() {
            given.to_path_buf()
        } else {
            let root = catalogue::root(root);
            catalogue::model_path(root.as_deref(), model)?
        };
        let model = Model::load(&path).map_err(|e| e.to_string())?;
        if let Some((name, _)) = settings
            .iter()
            .find(|(name, _)| model.functions.symbols.get(name).is_none())
        {
            return Err(format!(
                "--set {name}: the aerodynamics of {} neither read nor define this property",
                model.file
            ));
        }
        refuse_driven(&model, settings)?;
        let surfaces = surfaces(&model, &path)?;
        Ok(Loaded {
            model,
            surfaces,
            settings: settings.to_vec(),
        })
    }

    /// The setup at `condition`.
    pub fn setup(&self, condition: Condition) -> Setup<'_> {
        Setup {
            model: &self.model,
            condition,
            surfaces: self.surfaces.clone(),
            settings: self.settings.clone(),
        }
    }
}

/// Refuses a `--set` of a property the import moves itself: a flight-state property (alpha,
/// beta, the rates, the speed, the atmosphere) or a form of the aileron, elevator or rudder
/// position. Held fixed, the derivatives taken by moving it would silently come out zero.
fn refuse_driven(model: &Model, settings: &[(String, f64)]) -> Result<(), String> {
    use super::surfaces::Control;
    let surfaces = [Control::Aileron, Control::Elevator, Control::Rudder]
        .into_iter()
        .flat_map(|c| c.properties().into_iter().map(|(name, _, _)| name));
    let driven: Vec<&str> = super::condition::state_properties(model)
        .into_iter()
        .chain(surfaces)
        .collect();
    match settings
        .iter()
        .find(|(name, _)| driven.contains(&name.as_str()))
    {
        Some((name, _)) => Err(format!(
            "--set {name}: the import sets this property itself, from the flight state or a \
             control surface whose derivatives it takes (expected a configuration input such \
             as fcs/flap-pos-norm; give the flight condition with --altitude-m, --mach or \
             --speed and --alpha-deg or --level-flight)"
        )),
        None => Ok(()),
    }
}

/// The aircraft file (TOML text) of `setup` linearised at angle of attack `alpha` (rad),
/// chosen as `alpha_source` says, wings level and surfaces neutral.
pub fn aircraft_file(setup: &Setup, alpha: f64, alpha_source: &str) -> Result<String, String> {
    let state = State {
        alpha,
        beta: 0.0,
        rates: [0.0; 3],
        surfaces: [0.0; 3],
    };
    let (base, derivs) = derivatives(setup, &state).map_err(|e| e.to_string())?;
    Ok(Import {
        model: setup.model,
        condition: setup.condition,
        state,
        alpha_source: alpha_source.to_string(),
        surfaces: &setup.surfaces,
        settings: &setup.settings,
        base: &base,
        derivatives: &derivs,
    }
    .toml())
}

/// The reference condition of the catalogue listing: 3,000 m, Mach 0.3, alpha 2 deg.
pub const REFERENCE: (f64, f64, f64) = (3000.0, 0.3, 2.0);

/// Whether `model` (read from `path`) evaluates at the [`REFERENCE`] condition with nothing set
/// by the user; the error says which input is missing.
pub fn evaluates(model: &Model, path: &std::path::Path) -> Result<(), String> {
    let (h, mach, alpha) = REFERENCE;
    let setup = Setup {
        model,
        condition: Condition::new(h, Speed::Mach(mach))?,
        surfaces: surfaces(model, path)?,
        settings: Vec::new(),
    };
    let state = State {
        alpha: alpha.to_radians(),
        beta: 0.0,
        rates: [0.0; 3],
        surfaces: [0.0; 3],
    };
    setup
        .coefficients(&state)
        .map(|_| ())
        .map_err(|e| e.to_string())
}

/// The angle of attack (rad) at which lift equals weight, surfaces neutral: the first sign
/// change of CL - W/(qbar S) from -5 deg up to 30 deg, refined by bisection.
pub fn level_flight(setup: &Setup) -> Result<f64, String> {
    let weight = setup.model.totals().weight;
    let need = weight / (setup.condition.qbar_psf() * setup.model.metrics.wing_area);
    let excess = |alpha: f64| -> Result<f64, String> {
        let state = State {
            alpha,
            beta: 0.0,
            rates: [0.0; 3],
            surfaces: [0.0; 3],
        };
        let c = setup.coefficients(&state).map_err(|e| e.to_string())?;
        Ok(c.values[CL] - need)
    };
    let step = 0.25f64.to_radians();
    let mut lo = (-5.0f64).to_radians();
    let mut f_lo = excess(lo)?;
    if f_lo > 0.0 {
        return Err(format!(
            "no level flight: at -5 deg alpha the lift coefficient {:.4} already exceeds the \
             {need:.4} the weight ({weight:.0} lbs) needs (fly slower or higher)",
            f_lo + need
        ));
    }
    let mut best = f_lo;
    while lo < 30f64.to_radians() {
        let hi = lo + step;
        let f_hi = excess(hi)?;
        best = best.max(f_hi);
        if f_lo <= 0.0 && f_hi >= 0.0 {
            let (mut a, mut b) = (lo, hi);
            for _ in 0..60 {
                let m = 0.5 * (a + b);
                if excess(m)? < 0.0 {
                    a = m;
                } else {
                    b = m;
                }
            }
            return Ok(0.5 * (a + b));
        }
        lo = hi;
        f_lo = f_hi;
    }
    Err(format!(
        "no level flight between -5 and 30 deg alpha: the largest CL found is {:.4}, the weight \
         ({weight:.0} lbs, {:.0} kg) needs CL = {need:.4} (fly faster or lower)",
        best + need,
        weight * SLUG_PER_LB * super::units::KG_PER_SLUG
    ))
}
