//! A model's mass properties as loaded: the empty weight at its CG with its inertia
//! (`<mass_balance>`), the point masses, and the fuel tanks of `<propulsion>` with their
//! `<contents>`; the total weight, the centre of gravity and the inertia about it (parallel-axis
//! theorem), in JSBSim's units (lbs, inches in the structural frame, slug ft^2 in body axes).
//!
//! JSBSim writes the products of inertia with the sign of the tensor's off-diagonal elements:
//! by default (`negated_crossproduct_inertia` absent or true) its `ixz` is minus the integral of
//! x z dm in body axes, so this crate's `ixz` (the integral itself) is `-ixz` of the file.

use super::error::JsbsimError;
use super::units::{Quantity, SLUG_PER_LB};
use super::xml::{child, children, Source};
use roxmltree::Node;

/// One mass: weight (lbs), location (inches, structural frame) and its own inertia tensor about
/// its own centre (slug ft^2, body axes).
#[derive(Clone, Debug, PartialEq)]
pub struct Mass {
    /// What it is (`empty`, a point mass's or a tank's name).
    pub name: String,
    /// Weight, lbs.
    pub weight: f64,
    /// Location, inches, structural frame.
    pub location: [f64; 3],
    /// Own inertia tensor, slug ft^2, body axes.
    pub inertia: [[f64; 3]; 3],
}

/// The mass properties of a model as loaded.
#[derive(Clone, Debug, PartialEq)]
pub struct MassBalance {
    /// Every mass: the empty aircraft first, then point masses, then tanks.
    pub masses: Vec<Mass>,
}

/// The whole aircraft's weight, CG and inertia.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Totals {
    /// Weight, lbs.
    pub weight: f64,
    /// Centre of gravity, inches, structural frame.
    pub cg: [f64; 3],
    /// Inertia tensor about the CG, slug ft^2, body axes.
    pub tensor: [[f64; 3]; 3],
}

impl Totals {
    /// Ixx, Iyy, Izz and this crate's Ixz (the integral of x z dm, body axes), slug ft^2.
    pub fn moments(&self) -> [f64; 4] {
        let j = &self.tensor;
        [j[0][0], j[1][1], j[2][2], -j[0][2]]
    }
}

/// The body-axis vector (ft) from `cg` to `point` (inches, structural frame): x forward, z down.
pub fn structural_to_body(point: [f64; 3], cg: [f64; 3]) -> [f64; 3] {
    [
        (cg[0] - point[0]) / 12.0,
        (point[1] - cg[1]) / 12.0,
        (cg[2] - point[2]) / 12.0,
    ]
}

/// The inertia tensor of a point mass of `mass` slugs at body vector `v` ft from the reference.
fn point_tensor(mass: f64, v: [f64; 3]) -> [[f64; 3]; 3] {
    let [x, y, z] = v;
    [
        [mass * (y * y + z * z), -mass * x * y, -mass * x * z],
        [-mass * x * y, mass * (x * x + z * z), -mass * y * z],
        [-mass * x * z, -mass * y * z, mass * (x * x + y * y)],
    ]
}

/// The empty aircraft's inertia tensor from `<mass_balance>`.
fn empty_tensor(src: Source, node: Node) -> Result<[[f64; 3]; 3], JsbsimError> {
    let get = |name: &str| -> Result<f64, JsbsimError> {
        Ok(src
            .child_quantity(node, name, Quantity::Inertia)?
            .unwrap_or(0.0))
    };
    let (ixx, iyy, izz) = (get("ixx")?, get("iyy")?, get("izz")?);
    let (ixy, ixz, iyz) = (get("ixy")?, get("ixz")?, get("iyz")?);
    let s = if node.attribute("negated_crossproduct_inertia") == Some("false") {
        -1.0
    } else {
        1.0
    };
    Ok([
        [ixx, -s * ixy, s * ixz],
        [-s * ixy, iyy, -s * iyz],
        [s * ixz, -s * iyz, izz],
    ])
}

/// A required weight child.
fn weight(src: Source, node: Node, name: &str) -> Result<f64, JsbsimError> {
    src.child_quantity(node, name, Quantity::Weight)?
        .ok_or_else(|| src.error(node, format!("no <{name}> (expected a weight)")))
}

/// The `<location>` child of `node`.
fn location(src: Source, node: Node) -> Result<[f64; 3], JsbsimError> {
    let l = child(node, "location")
        .ok_or_else(|| src.error(node, "no <location> (expected where this mass is)"))?;
    src.location(l)
}

impl MassBalance {
    /// Reads `<mass_balance>` and the tanks of `<propulsion>` (if any).
    pub fn read(
        src: Source,
        node: Node,
        propulsion: Option<Node>,
    ) -> Result<MassBalance, JsbsimError> {
        let cg = children(node, "location")
            .find(|l| l.attribute("name").is_none_or(|n| n == "CG"))
            .ok_or_else(|| src.error(node, "no <location name=\"CG\"> (expected the empty CG)"))?;
        let mut masses = vec![Mass {
            name: "empty".into(),
            weight: weight(src, node, "emptywt")?,
            location: src.location(cg)?,
            inertia: empty_tensor(src, node)?,
        }];
        for pm in children(node, "pointmass") {
            if child(pm, "form").is_some() {
                return Err(src.error(
                    pm,
                    "point masses with a <form> (own inertia) are not supported",
                ));
            }
            masses.push(Mass {
                name: pm.attribute("name").unwrap_or("pointmass").into(),
                weight: weight(src, pm, "weight")?,
                location: location(src, pm)?,
                inertia: [[0.0; 3]; 3],
            });
        }
        for (k, tank) in propulsion
            .into_iter()
            .flat_map(|p| children(p, "tank"))
            .enumerate()
        {
            masses.push(Self::tank(src, tank, k)?);
        }
        let balance = MassBalance { masses };
        balance.physical(src, node)?;
        Ok(balance)
    }

    /// Refuses mass properties no aircraft has: a negative weight, a total weight that is not
    /// positive (the CG, a weighted mean, would be 0/0 and every inertia NaN), a moment of
    /// inertia about the CG that is not positive, or an x-z block with ixx izz <= ixz^2 (its
    /// principal moments not both positive): the equations of motion divide by them.
    fn physical(&self, src: Source, node: Node) -> Result<(), JsbsimError> {
        let parts: Vec<String> = self
            .masses
            .iter()
            .map(|m| format!("{} {} lbs", m.name, m.weight))
            .collect();
        let parts = parts.join(", ");
        let weight: f64 = self.masses.iter().map(|m| m.weight).sum();
        if let Some(m) = self.masses.iter().find(|m| m.weight < 0.0) {
            return Err(src.error(
                node,
                format!(
                    "the weight of {} is {} lbs (expected zero or more)",
                    m.name, m.weight
                ),
            ));
        }
        if !(weight.is_finite() && weight > 0.0) {
            return Err(src.error(
                node,
                format!(
                    "the total weight is {weight} lbs ({parts}; expected a positive weight from \
                     <emptywt>, the point masses and the tanks' contents: without one the CG \
                     and the inertia about it are undefined)"
                ),
            ));
        }
        let [ix, iy, iz, ixz] = self.totals().moments();
        let empty = &self.masses[0].inertia;
        for (k, (name, v)) in [("ixx", ix), ("iyy", iy), ("izz", iz)]
            .into_iter()
            .enumerate()
        {
            if !(v.is_finite() && v > 0.0) {
                return Err(src.error(
                    node,
                    format!(
                        "the moment of inertia {name} about the CG is {v} slug ft^2 (<{name}> \
                         {} slug ft^2 and the masses' parallel-axis terms; expected a positive \
                         moment: the equations of motion divide by it)",
                        empty[k][k]
                    ),
                ));
            }
        }
        if ix * iz <= ixz * ixz {
            return Err(src.error(
                node,
                format!(
                    "ixx izz - ixz^2 = {:e} slug^2 ft^4 about the CG (ixx {ix}, izz {iz}, ixz \
                     {ixz}; expected a positive value: otherwise a principal moment of the x-z \
                     plane is zero or negative, which no rigid body has)",
                    ix * iz - ixz * ixz
                ),
            ));
        }
        Ok(())
    }

    /// One tank as loaded: its contents at its location, with the inertia of a sphere of its
    /// radius when one is given.
    fn tank(src: Source, tank: Node, k: usize) -> Result<Mass, JsbsimError> {
        if child(tank, "grain_config").is_some() {
            return Err(src.error(tank, "solid-fuel tanks (<grain_config>) are not supported"));
        }
        let contents = src
            .child_quantity(tank, "contents", Quantity::Weight)?
            .unwrap_or(0.0);
        let radius_in = src
            .child_quantity(tank, "radius", Quantity::Location)?
            .unwrap_or(0.0);
        let factor = match child(tank, "inertia_factor") {
            Some(f) => src.number(f)?,
            None => 1.0,
        };
        let i = contents * SLUG_PER_LB * factor * 0.4 * radius_in * radius_in / 144.0;
        Ok(Mass {
            name: format!("tank {k}"),
            weight: contents,
            location: location(src, tank)?,
            inertia: [[i, 0.0, 0.0], [0.0, i, 0.0], [0.0, 0.0, i]],
        })
    }

    /// Weight, CG and inertia about the CG of everything on board.
    pub fn totals(&self) -> Totals {
        let weight: f64 = self.masses.iter().map(|m| m.weight).sum();
        let mut cg = [0.0; 3];
        for m in &self.masses {
            for (c, x) in cg.iter_mut().zip(m.location) {
                *c += m.weight * x;
            }
        }
        cg.iter_mut().for_each(|c| *c /= weight);
        let mut tensor = [[0.0; 3]; 3];
        for m in &self.masses {
            let shift = point_tensor(m.weight * SLUG_PER_LB, structural_to_body(m.location, cg));
            for (r, row) in tensor.iter_mut().enumerate() {
                for (c, t) in row.iter_mut().enumerate() {
                    *t += m.inertia[r][c] + shift[r][c];
                }
            }
        }
        Totals { weight, cg, tensor }
    }
}
