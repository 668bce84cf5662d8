//! The control surfaces as the aerodynamics read them: the aileron, elevator and rudder
//! positions in rad (`fcs/*-pos-rad`), with the other forms that move with them (`-pos-deg`,
//! `mag-*-pos-rad`, and `-pos-norm` through the travel), and the travel itself as JSBSim moves
//! the surface: the flight control system's chain from the pilot's command at +1 and -1 to the
//! position the aerodynamics read.

use super::fcs::Fcs;
use super::model::Model;
use super::systems::system_files;
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

/// A control's travel as JSBSim moves the surface at full stick, rad: the position the
/// flight control system settles at with the pilot's command at +1 and at -1 (trims neutral,
/// wings level, no rates, no sideslip), and where it was read.
#[derive(Clone, Debug, PartialEq)]
pub struct Range {
    /// The most negative deflection, rad (negative or zero).
    pub min: f64,
    /// The most positive deflection, rad.
    pub max: f64,
    /// The position at command +1, rad.
    pub at_plus: f64,
    /// The position at command -1, rad.
    pub at_minus: f64,
    /// The command, the position property and the components between them.
    pub source: String,
}

impl Range {
    /// The symmetric limit of the analysis, rad: the smaller end, the travel the surface
    /// reaches to either side (the analysis takes one limit on |deflection|, and a roll to
    /// either side must stay within what the surface can do).
    pub fn limit(&self) -> f64 {
        (-self.min).min(self.max)
    }

    /// The command end (+1 or -1) whose position is the limit.
    pub fn limiting_command(&self) -> f64 {
        let end = if -self.min < self.max {
            self.min
        } else {
            self.max
        };
        if end == self.at_plus {
            1.0
        } else {
            -1.0
        }
    }
}

/// How a control is set: by its angle (the forms in rad, deg, magnitude, and normalised travel
/// through its range) or, when the aerodynamics read its normalised travel and no range is
/// known, by the travel itself.
#[derive(Clone, Debug, PartialEq)]
pub struct Surface {
    /// Which control.
    pub control: Control,
    /// Its travel, if the chain from the stick to the surface is followed.
    pub range: Option<Range>,
    /// Why no travel is known, if the flight control system writes the surface but its chain
    /// is not followed (the component named).
    pub note: Option<String>,
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

/// The surfaces of `model` (whose file is at `path`): their travel from its flight control
/// system. An error names a system file the model references that is missing or unreadable.
pub fn surfaces(model: &Model, path: &Path) -> Result<Vec<Surface>, String> {
    let fcs = Fcs::read(&system_files(path)?);
    Ok(Control::ALL
        .iter()
        .map(|&control| {
            let reads = |name: &str| model.functions.symbols.get(name).is_some();
            let (range, note) = match travel(&fcs, control, &reads) {
                Some(Ok(r)) => (Some(r), None),
                Some(Err(why)) => (None, Some(why)),
                None => (None, None),
            };
            // Without an angle written by the flight control system the travel is the
            // variable; an angle form the aerodynamics also read stays at zero, as in JSBSim.
            let per_unit_travel = range.is_none()
                && note.is_none()
                && control
                    .properties()
                    .iter()
                    .any(|(n, f, _)| *f == Form::Norm && reads(n));
            Surface {
                control,
                range,
                note,
                per_unit_travel,
            }
        })
        .collect())
}

/// The pilot's command of a control.
pub fn command(control: Control) -> &'static str {
    match control {
        Control::Aileron => "fcs/aileron-cmd-norm",
        Control::Elevator => "fcs/elevator-cmd-norm",
        Control::Rudder => "fcs/rudder-cmd-norm",
    }
}

/// The position property whose travel is read: an angle form (rad or deg, JSBSim's sign) that
/// the flight control system writes, one the aerodynamics read first.
pub fn position(
    fcs: &Fcs,
    control: Control,
    reads: &dyn Fn(&str) -> bool,
) -> Option<(&'static str, Form)> {
    let angles: Vec<(&'static str, Form)> = control
        .properties()
        .into_iter()
        .filter(|(_, f, sign)| matches!(f, Form::Rad | Form::Deg) && *sign > 0.0)
        .map(|(n, f, _)| (n, f))
        .filter(|(n, _)| fcs.writers.contains_key(*n))
        .collect();
    angles
        .iter()
        .find(|(n, _)| reads(n))
        .or(angles.first())
        .copied()
}

/// The travel of `control` at full command, `None` when the flight control system writes no
/// angle of it, an error naming the component where the chain is not followed.
pub fn travel(
    fcs: &Fcs,
    control: Control,
    reads: &dyn Fn(&str) -> bool,
) -> Option<Result<Range, String>> {
    let (property, form) = position(fcs, control, reads)?;
    let cmd = command(control);
    let at = |v: f64| {
        fcs.value(property, &[(cmd, v)]).map(|x| match form {
            Form::Deg => x.to_radians(),
            _ => x,
        })
    };
    let ends = at(1.0).and_then(|p| Ok((p, at(-1.0)?)));
    let not_followed = |why: String| {
        format!(
            "no {} limit: the chain from {cmd} to {property} is not followed: {why}",
            control.name()
        )
    };
    Some(match ends {
        Err(why) => Err(not_followed(why)),
        Ok((plus, minus)) if plus.min(minus) >= 0.0 || plus.max(minus) <= 0.0 => Err(format!(
            "no {} limit: {cmd} does not move {property} to both sides of neutral ({plus:.6} \
             rad at +1, {minus:.6} rad at -1)",
            control.name()
        )),
        Ok((plus, minus)) => Ok(Range {
            min: plus.min(minus),
            max: plus.max(minus),
            at_plus: plus,
            at_minus: minus,
            source: format!(
                "{cmd} -> {property} through {}",
                fcs.chain(property).join(" <- ")
            ),
        }),
    })
}
