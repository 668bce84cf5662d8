//! A model's `<metrics>`: the reference area, span and chord its coefficients are made
//! dimensional with, the tail areas and arms, and the aerodynamic reference point (AERORP) about
//! which its moments are given.

use super::error::JsbsimError;
use super::units::Quantity;
use super::xml::{children, Source};
use roxmltree::Node;

/// The reference geometry, in ft, ft^2, rad and inches (locations, structural frame).
#[derive(Clone, Debug, PartialEq)]
pub struct Metrics {
    /// Wing reference area, ft^2.
    pub wing_area: f64,
    /// Wing span, ft.
    pub span: f64,
    /// Mean aerodynamic chord, ft.
    pub chord: f64,
    /// Wing incidence, rad.
    pub incidence: f64,
    /// Horizontal tail area, ft^2 (0 when not given).
    pub htail_area: f64,
    /// Horizontal tail arm, ft.
    pub htail_arm: f64,
    /// Vertical tail area, ft^2.
    pub vtail_area: f64,
    /// Vertical tail arm, ft.
    pub vtail_arm: f64,
    /// The aerodynamic reference point, inches, structural frame (x aft, y right, z up).
    pub aero_rp: [f64; 3],
}

impl Metrics {
    /// Reads `<metrics>` element `node`; area, span and chord must be given and positive.
    pub fn read(src: Source, node: Node) -> Result<Metrics, JsbsimError> {
        let need = |name: &str, q: Quantity| -> Result<f64, JsbsimError> {
            let v = src.child_quantity(node, name, q)?.ok_or_else(|| {
                src.error(node, format!("no <{name}> (expected the reference {name})"))
            })?;
            if v > 0.0 {
                Ok(v)
            } else {
                Err(src.error(node, format!("<{name}> is {v} (expected a positive value)")))
            }
        };
        let optional = |name: &str, q: Quantity| -> Result<f64, JsbsimError> {
            Ok(src.child_quantity(node, name, q)?.unwrap_or(0.0))
        };
        let aero_rp = children(node, "location")
            .find(|l| l.attribute("name") == Some("AERORP"))
            .ok_or_else(|| {
                src.error(
                    node,
                    "no <location name=\"AERORP\"> (expected the aerodynamic reference point)",
                )
            })?;
        Ok(Metrics {
            wing_area: need("wingarea", Quantity::Area)?,
            span: need("wingspan", Quantity::Length)?,
            chord: need("chord", Quantity::Length)?,
            incidence: optional("wing_incidence", Quantity::Angle)?,
            htail_area: optional("htailarea", Quantity::Area)?,
            htail_arm: optional("htailarm", Quantity::Length)?,
            vtail_area: optional("vtailarea", Quantity::Area)?,
            vtail_arm: optional("vtailarm", Quantity::Length)?,
            aero_rp: src.location(aero_rp)?,
        })
    }

    /// The `metrics/` properties a model's functions may read, with their values.
    pub fn properties(&self) -> Vec<(&'static str, f64)> {
        let lbar = |arm: f64| arm / self.chord;
        let vbar = |area: f64, arm: f64, length: f64| area * arm / (self.wing_area * length);
        vec![
            ("metrics/Sw-sqft", self.wing_area),
            ("metrics/bw-ft", self.span),
            ("metrics/cbarw-ft", self.chord),
            ("metrics/iw-rad", self.incidence),
            ("metrics/iw-deg", self.incidence.to_degrees()),
            ("metrics/Sh-sqft", self.htail_area),
            ("metrics/lh-ft", self.htail_arm),
            ("metrics/Sv-sqft", self.vtail_area),
            ("metrics/lv-ft", self.vtail_arm),
            ("metrics/lh-norm", lbar(self.htail_arm)),
            ("metrics/lv-norm", lbar(self.vtail_arm)),
            (
                "metrics/vbarh-norm",
                vbar(self.htail_area, self.htail_arm, self.chord),
            ),
            (
                "metrics/vbarv-norm",
                vbar(self.vtail_area, self.vtail_arm, self.span),
            ),
            ("metrics/aero-rp-x-in", self.aero_rp[0]),
            ("metrics/aero-rp-y-in", self.aero_rp[1]),
            ("metrics/aero-rp-z-in", self.aero_rp[2]),
        ]
    }
}
