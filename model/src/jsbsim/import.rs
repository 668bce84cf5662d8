//! An import from start to end: the model, the flight condition, the point of linearisation
//! (the n-g trim, or an angle of attack given), the coefficients and their derivatives there,
//! and the aircraft file.
//! A model read once ([`Loaded`]) gives the aircraft file of any number of flight conditions.

use super::catalogue;
use super::coefficients::{Setup, CL};
use super::condition::{Condition, Speed, State};
use super::derivatives::derivatives;
use super::model::Model;
use super::surfaces::surfaces;
use super::trim::{lift_in_weights, trim, Trim};
use super::write::Import;
use std::path::PathBuf;

/// Where the derivatives are taken.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Alpha {
    /// At this angle of attack, rad, elevator neutral, no pitch rate (not a trim).
    Given(f64),
    /// At the trim of a wings-level pull-up at this load factor (1: level flight).
    Trim(f64),
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
    import_trimmed(request).map(|(text, _)| text)
}

/// The aircraft file of `request` and the trim it was linearised at (`None` for an angle of
/// attack given), for a caller that says where the aircraft flies.
pub fn import_trimmed(request: &Request) -> Result<(String, Option<Trim>), String> {
    let loaded = Loaded::new(&request.model, request.root.as_deref(), &request.settings)?;
    let condition = Condition::new(request.altitude_m, request.speed)?;
    let setup = loaded.setup(condition);
    match request.alpha {
        Alpha::Given(a) => Ok((
            given_alpha_file(&setup, a)
                .map_err(|e| super::trim::with_settings(e, &setup.settings))?,
            None,
        )),
        Alpha::Trim(n) => {
            let t = trim(&setup, n)?;
            Ok((trimmed_file(&setup, &t)?, Some(t)))
        }
    }
}

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
        Setup::new(
            &self.model,
            condition,
            self.surfaces.clone(),
            self.settings.clone(),
        )
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
             --speed, and --load-factor or --alpha-deg)"
        )),
        None => Ok(()),
    }
}

/// The aircraft file (TOML text) of `setup` linearised at its trim `trim`: the derivatives
/// taken at the trimmed alpha, elevator and pitch rate.
pub fn trimmed_file(setup: &Setup, trim: &Trim) -> Result<String, String> {
    linearised_file(setup, trim.state(), trim.load_factor, Some(trim))
}

/// The aircraft file (TOML text) of `setup` linearised at angle of attack `alpha` (rad) as
/// given, wings level, surfaces neutral, no pitch rate: not a trim. Its load factor is the
/// lift there over the weight.
pub fn given_alpha_file(setup: &Setup, alpha: f64) -> Result<String, String> {
    let state = State {
        alpha,
        beta: 0.0,
        rates: [0.0; 3],
        surfaces: [0.0; 3],
    };
    let cl = setup
        .coefficients(&state)
        .map_err(|e| e.to_string())?
        .values[CL];
    linearised_file(setup, state, lift_in_weights(setup, cl), None)
}

/// The aircraft file of `setup` linearised at `state`, whose lift is `load_factor` weights.
fn linearised_file(
    setup: &Setup,
    state: State,
    load_factor: f64,
    trim: Option<&Trim>,
) -> Result<String, String> {
    let (base, derivs) = derivatives(setup, &state).map_err(|e| e.to_string())?;
    Ok(Import {
        model: setup.model,
        condition: setup.condition,
        state,
        load_factor,
        trim: trim.copied(),
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
    let setup = Setup::new(
        model,
        Condition::new(h, Speed::Mach(mach))?,
        surfaces(model, path)?,
        Vec::new(),
    );
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
