//! A JSBSim model read from its XML: the metrics, the mass properties as loaded and the
//! aerodynamics, with the functions they define and the properties they read.

use super::aerodynamics::{Aerodynamics, Loads};
use super::error::JsbsimError;
use super::evaluate::{Env, Functions};
use super::mass::{MassBalance, Totals};
use super::metrics::Metrics;
use super::readers::Readers;
use super::xml::{child, Source};
use std::path::Path;
use std::sync::OnceLock;

/// The largest model file read, bytes: the catalogue's largest is well under 1 MB.
pub const MAX_FILE_BYTES: u64 = 16 << 20;

/// A JSBSim aircraft model.
#[derive(Clone, Debug)]
pub struct Model {
    /// The file it was read from (as given).
    pub file: String,
    /// The `name` of `<fdm_config>`.
    pub name: String,
    /// Reference geometry.
    pub metrics: Metrics,
    /// Mass properties as loaded.
    pub mass: MassBalance,
    /// Every named function.
    pub functions: Functions,
    /// The aerodynamics.
    pub aero: Aerodynamics,
    /// Which functions read each property, found at the first use.
    readers: OnceLock<Option<Readers>>,
}

impl Model {
    /// Reads the model at `path`.
    pub fn load(path: &Path) -> Result<Model, JsbsimError> {
        let file = path.display().to_string();
        let err = |m: String| JsbsimError::new(&file, 0, "fdm_config", m);
        let size = std::fs::metadata(path)
            .map_err(|e| err(format!("cannot read: {e}")))?
            .len();
        if size > MAX_FILE_BYTES {
            return Err(err(format!(
                "the file has {size} bytes (expected a model of at most {MAX_FILE_BYTES})"
            )));
        }
        let text = std::fs::read_to_string(path)
            .map_err(|e| err(format!("cannot read: {e} (expected a UTF-8 XML file)")))?;
        Model::parse(&text, &file)
    }

    /// Parses the XML `text` of a model; `file` names it in messages.
    pub fn parse(text: &str, file: &str) -> Result<Model, JsbsimError> {
        let doc = roxmltree::Document::parse(text).map_err(|e| {
            let pos = e.pos();
            JsbsimError::new(file, pos.row, "xml", format!("not well-formed XML: {e}"))
        })?;
        let src = Source { file };
        let root = doc.root_element();
        if root.tag_name().name() != "fdm_config" {
            return Err(src.error(
                root,
                "the root element is not <fdm_config> (expected a JSBSim aircraft model)",
            ));
        }
        let section = |name: &str| {
            child(root, name).ok_or_else(|| src.error(root, format!("no <{name}> section")))
        };
        let metrics = Metrics::read(src, section("metrics")?)?;
        let mass = MassBalance::read(src, section("mass_balance")?, child(root, "propulsion"))?;
        let mut functions = Functions::default();
        let aero = Aerodynamics::read(src, section("aerodynamics")?, &mut functions)?;
        functions.link();
        Ok(Model {
            file: file.to_string(),
            name: root.attribute("name").unwrap_or("").to_string(),
            metrics,
            mass,
            functions,
            aero,
            readers: OnceLock::new(),
        })
    }

    /// Which functions read each property, directly or through others; `None` when the
    /// functions may loop or chain too deep for an evaluation to keep any value
    /// ([`Env::keep_from`]).
    pub fn readers(&self) -> Option<&Readers> {
        self.readers
            .get_or_init(|| Readers::of(&self.functions))
            .as_ref()
    }

    /// Weight, CG and inertia as loaded.
    pub fn totals(&self) -> Totals {
        self.mass.totals()
    }

    /// An evaluation with the model's own properties set: the `metrics/` values and the weight
    /// (`inertia/weight-lbs`). The flight state and the surfaces are the caller's to set.
    pub fn environment(&self) -> Env<'_> {
        let mut env = Env::new(&self.functions, &self.file);
        for (name, value) in self.metrics.properties() {
            env.set(name, value);
        }
        env.set("inertia/weight-lbs", self.totals().weight);
        env
    }

    /// Forces and moments about the CG as loaded, in body axes (lbs, lbs ft), with `env`'s
    /// inputs, at angle of attack `alpha` and sideslip `beta` (rad, for the wind-to-body
    /// rotation).
    pub fn loads(&self, env: &mut Env, alpha: f64, beta: f64) -> Result<Loads, JsbsimError> {
        let cg = self.totals().cg;
        self.aero.loads(
            env,
            (alpha, beta),
            cg,
            self.metrics.aero_rp,
            self.metrics.chord,
        )
    }
}
