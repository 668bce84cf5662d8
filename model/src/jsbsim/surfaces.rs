//! The control surfaces as the aerodynamics read them: the aileron, elevator and rudder
//! positions in rad (`fcs/*-pos-rad`), with the other forms that move with them (`-pos-deg`,
//! `mag-*-pos-rad`, and `-pos-norm` through the range of the flight control system's
//! `aerosurface_scale` (or `clipto`) whose output is the position), and the deflection limits
//! read from that range.

use super::model::Model;
use super::xml::{child, parse_number};
use std::path::Path;

/// A primary control.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Control {
    /// Aileron (JSBSim's sign: the left aileron's position).
    Aileron,
    /// Elevator.
    Elevator,
    /// Rudder.
    Rudder,
}

/// How a property reads a control's deflection.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Form {
    /// Radians.
    Rad,
    /// Degrees.
    Deg,
    /// The magnitude, radians.
    Mag,
    /// Normalised travel, -1 to 1.
    Norm,
}

impl Control {
    /// Every control.
    pub const ALL: [Control; 3] = [Control::Aileron, Control::Elevator, Control::Rudder];

    /// Its name in messages and in the aircraft file.
    pub fn name(self) -> &'static str {
        match self {
            Control::Aileron => "aileron",
            Control::Elevator => "elevator",
            Control::Rudder => "rudder",
        }
    }

    /// The position property in rad that the flight control system writes.
    pub fn rad_property(self) -> &'static str {
        match self {
            Control::Aileron => "fcs/left-aileron-pos-rad",
            Control::Elevator => "fcs/elevator-pos-rad",
            Control::Rudder => "fcs/rudder-pos-rad",
        }
    }

    /// The properties that read this control, with their form and sign (the right aileron moves
    /// opposite to the left).
    pub fn properties(self) -> Vec<(&'static str, Form, f64)> {
        use Form::*;
        match self {
            Control::Aileron => vec![
                ("fcs/left-aileron-pos-rad", Rad, 1.0),
                ("fcs/left-aileron-pos-deg", Deg, 1.0),
                ("fcs/left-aileron-pos-norm", Norm, 1.0),
                ("fcs/mag-left-aileron-pos-rad", Mag, 1.0),
                ("fcs/aileron-pos-rad", Rad, 1.0),
                ("fcs/aileron-pos-deg", Deg, 1.0),
                ("fcs/aileron-pos-norm", Norm, 1.0),
                ("fcs/right-aileron-pos-rad", Rad, -1.0),
                ("fcs/right-aileron-pos-deg", Deg, -1.0),
                ("fcs/right-aileron-pos-norm", Norm, -1.0),
                ("fcs/mag-right-aileron-pos-rad", Mag, 1.0),
            ],
            Control::Elevator => vec![
                ("fcs/elevator-pos-rad", Rad, 1.0),
                ("fcs/elevator-pos-deg", Deg, 1.0),
                ("fcs/elevator-pos-norm", Norm, 1.0),
                ("fcs/mag-elevator-pos-rad", Mag, 1.0),
            ],
            Control::Rudder => vec![
                ("fcs/rudder-pos-rad", Rad, 1.0),
                ("fcs/rudder-pos-deg", Deg, 1.0),
                ("fcs/rudder-pos-norm", Norm, 1.0),
                ("fcs/mag-rudder-pos-rad", Mag, 1.0),
            ],
        }
    }
}

/// A control's range in rad (negative and positive end) and where it was read.
#[derive(Clone, Debug, PartialEq)]
pub struct Range {
    /// The most negative deflection, rad (negative or zero).
    pub min: f64,
    /// The most positive deflection, rad.
    pub max: f64,
    /// The file and component it came from.
    pub source: String,
}

/// How a control is set: by its angle (the forms in rad, deg, magnitude, and normalised travel
/// through its range) or, when the aerodynamics read its normalised travel and no range is
/// known, by the travel itself.
#[derive(Clone, Debug, PartialEq)]
pub struct Surface {
    /// Which control.
    pub control: Control,
    /// Its range, if the flight control system gives one.
    pub range: Option<Range>,
    /// Whether the variable is the normalised travel (no angle known).
    pub per_unit_travel: bool,
}

impl Surface {
    /// The values of every form at deflection `x` (rad, or travel when per unit travel).
    pub fn values(&self, x: f64) -> Vec<(&'static str, Option<f64>)> {
        let (rad, norm) = if self.per_unit_travel {
            (None, Some(x))
        } else {
            let norm = self
                .range
                .as_ref()
                .map(|r| if x >= 0.0 { x / r.max } else { -x / r.min });
            (Some(x), norm)
        };
        self.control
            .properties()
            .into_iter()
            .map(|(name, form, sign)| {
                let v = match form {
                    Form::Rad => rad.map(|r| sign * r),
                    Form::Deg => rad.map(|r| sign * r.to_degrees()),
                    Form::Mag => rad.map(f64::abs),
                    Form::Norm => norm.map(|n| sign * n),
                };
                (name, v)
            })
            .collect()
    }
}

/// The surfaces of `model` (whose file is at `path`): ranges from its flight control system.
pub fn surfaces(model: &Model, path: &Path) -> Vec<Surface> {
    Control::ALL
        .iter()
        .map(|&control| {
            let range = range(path, control.rad_property());
            let reads = |form: Form| {
                control
                    .properties()
                    .iter()
                    .any(|(n, f, _)| *f == form && model.functions.symbols.get(n).is_some())
            };
            // Without a range the angle and the travel are unrelated (JSBSim's flight control
            // system then writes one of them only): the travel is the variable, and an angle
            // form the aerodynamics also read stays at zero, as in JSBSim.
            let per_unit_travel = range.is_none() && reads(Form::Norm);
            Surface {
                control,
                range,
                per_unit_travel,
            }
        })
        .collect()
}

/// The files that may hold the flight control system: the model and its `Systems/*.xml`.
fn system_files(path: &Path) -> Vec<std::path::PathBuf> {
    let mut files = vec![path.to_path_buf()];
    if let Some(dir) = path.parent() {
        for sub in ["Systems", "systems"] {
            let mut more: Vec<_> = std::fs::read_dir(dir.join(sub))
                .into_iter()
                .flatten()
                .flatten()
                .map(|e| e.path())
                .filter(|p| p.extension().is_some_and(|e| e == "xml"))
                .collect();
            more.sort();
            files.extend(more);
        }
    }
    files
}

/// The range of the component whose `<output>` is `property`: its `<range>` (aerosurface_scale)
/// or `<clipto>` with numeric `<min>` and `<max>`.
pub fn range(path: &Path, property: &str) -> Option<Range> {
    for file in system_files(path) {
        let Ok(text) = std::fs::read_to_string(&file) else {
            continue;
        };
        let Ok(doc) = roxmltree::Document::parse(&text) else {
            continue;
        };
        for out in doc.descendants().filter(|n| n.has_tag_name("output")) {
            if out.text().map(str::trim) != Some(property) {
                continue;
            }
            let Some(component) = out.parent_element() else {
                continue;
            };
            for limits in ["range", "clipto"] {
                let Some(r) = child(component, limits) else {
                    continue;
                };
                let num = |n: &str| child(r, n).and_then(|c| parse_number(c.text()?.trim()));
                if let (Some(min), Some(max)) = (num("min"), num("max")) {
                    if min <= 0.0 && max > 0.0 {
                        let name = component
                            .attribute("name")
                            .unwrap_or(component.tag_name().name());
                        return Some(Range {
                            min,
                            max,
                            source: format!(
                                "{} <{}> \"{name}\" <{limits}>",
                                file.display(),
                                component.tag_name().name()
                            ),
                        });
                    }
                }
            }
        }
    }
    None
}
