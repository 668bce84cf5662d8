//! A model's `<aerodynamics>`: the named functions outside the axes, the functions of each
//! `<axis>` (LIFT, DRAG, SIDE in wind axes; X, Y, Z in body axes; AXIAL, NORMAL; ROLL, PITCH, YAW
//! in body axes), and the forces and moments they sum to. The moments about the centre of
//! gravity add the moment of the forces applied at the aerodynamic reference point (moved aft
//! by `aero_ref_pt_shift_x` chords where the model gives it); functions marked
//! `apply_at_cg="true"` add their force at the CG.

use super::error::JsbsimError;
use super::evaluate::{Env, Function, Functions};
use super::function::{parse_function, Expr};
use super::mass::structural_to_body;
use super::xml::{child, children, Source};
use roxmltree::Node;

/// The axes a model may sum its functions on.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Axis {
    /// Drag, wind axes, positive aft.
    Drag,
    /// Side force, wind axes, positive right.
    Side,
    /// Lift, wind axes, positive up.
    Lift,
    /// Body x force, positive forward.
    X,
    /// Body y force.
    Y,
    /// Body z force, positive down.
    Z,
    /// Axial force, body, positive aft.
    Axial,
    /// Normal force, body, positive up.
    Normal,
    /// Rolling moment, body.
    Roll,
    /// Pitching moment, body.
    Pitch,
    /// Yawing moment, body.
    Yaw,
}

impl Axis {
    /// The axis an `<axis name=...>` names.
    fn named(name: &str) -> Option<Axis> {
        Some(match name {
            "DRAG" => Axis::Drag,
            "SIDE" => Axis::Side,
            "LIFT" => Axis::Lift,
            "X" => Axis::X,
            "Y" => Axis::Y,
            "Z" => Axis::Z,
            "AXIAL" => Axis::Axial,
            "NORMAL" => Axis::Normal,
            "ROLL" => Axis::Roll,
            "PITCH" => Axis::Pitch,
            "YAW" => Axis::Yaw,
            _ => return None,
        })
    }
}

/// One function of an axis.
#[derive(Clone, Debug)]
pub struct Term {
    /// The axis it adds to.
    pub axis: Axis,
    /// Its index in the model's [`Functions`].
    pub function: usize,
    /// Whether it acts at the CG (no moment transfer).
    pub at_cg: bool,
}

/// The aerodynamics of a model.
#[derive(Clone, Debug)]
pub struct Aerodynamics {
    /// The axis functions, in file order.
    pub terms: Vec<Term>,
    /// The named functions outside the axes (read by others as properties).
    pub helpers: Vec<usize>,
    /// The shift of the reference point aft, in chords, if the model moves it.
    pub rp_shift: Option<Expr>,
    /// Whether SIDE is in wind axes (with LIFT and DRAG) rather than body axes (with AXIAL and
    /// NORMAL).
    pub wind: bool,
}

/// Forces and moments in body axes (lbs, lbs ft) about the CG.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Loads {
    /// Force, body axes (x forward, y right, z down), lbs.
    pub force: [f64; 3],
    /// Moment about the CG, body axes, lbs ft.
    pub moment: [f64; 3],
}

/// Reads a `<function>` into `functions`, naming it `fallback` if it has no name.
fn read_function(
    src: Source,
    node: Node,
    functions: &mut Functions,
    fallback: String,
) -> Result<usize, JsbsimError> {
    let name = node
        .attribute("name")
        .map(str::to_string)
        .unwrap_or(fallback);
    if functions.list.iter().any(|f| f.name == name) {
        return Err(src.error(node, format!("a second function named `{name}`")));
    }
    let expr = parse_function(src, node, &mut functions.symbols)?;
    functions.symbols.intern(&name);
    functions.list.push(Function {
        name,
        line: src.line(node),
        expr,
    });
    Ok(functions.list.len() - 1)
}

impl Aerodynamics {
    /// Reads `<aerodynamics>` element `node`, adding its functions to `functions`.
    pub fn read(
        src: Source,
        node: Node,
        functions: &mut Functions,
    ) -> Result<Aerodynamics, JsbsimError> {
        if node.attribute("file").is_some() {
            return Err(src.error(
                node,
                "aerodynamics in a separate file (`file=`) are not supported",
            ));
        }
        let mut helpers = Vec::new();
        for f in children(node, "function") {
            let fallback = format!("aero/function/unnamed-{}", src.line(f));
            helpers.push(read_function(src, f, functions, fallback)?);
        }
        let rp_shift = match child(node, "aero_ref_pt_shift_x") {
            Some(s) => {
                let f = child(s, "function")
                    .ok_or_else(|| src.error(s, "no <function> (expected the shift in chords)"))?;
                Some(parse_function(src, f, &mut functions.symbols)?)
            }
            None => None,
        };
        let mut terms = Vec::new();
        for a in children(node, "axis") {
            let name = a.attribute("name").unwrap_or("");
            let axis = Axis::named(name).ok_or_else(|| {
                src.error(a, format!("axis `{name}` not understood (expected LIFT, DRAG, SIDE, X, Y, Z, AXIAL, NORMAL, ROLL, PITCH or YAW)"))
            })?;
            if let Some(frame) = a
                .attribute("frame")
                .filter(|f| !f.is_empty() && *f != "BODY")
            {
                return Err(src.error(
                    a,
                    format!("axis frame `{frame}` is not supported (expected none or BODY)"),
                ));
            }
            for f in children(a, "function") {
                let fallback = format!("aero/{}/unnamed-{}", name.to_lowercase(), src.line(f));
                let function = read_function(src, f, functions, fallback)?;
                let at_cg = f.attribute("apply_at_cg") == Some("true");
                terms.push(Term {
                    axis,
                    function,
                    at_cg,
                });
            }
        }
        let forces = terms.iter().map(|t| t.axis).collect::<Vec<_>>();
        let wind = forces.iter().any(|a| matches!(a, Axis::Lift | Axis::Drag));
        let body = forces
            .iter()
            .any(|a| matches!(a, Axis::X | Axis::Y | Axis::Z | Axis::Axial | Axis::Normal));
        if wind && body {
            return Err(src.error(
                node,
                "wind (LIFT, DRAG) and body (X, Y, Z, AXIAL, NORMAL) force axes mixed",
            ));
        }
        let wind = !forces
            .iter()
            .any(|a| matches!(a, Axis::Axial | Axis::Normal));
        Ok(Aerodynamics {
            terms,
            helpers,
            rp_shift,
            wind,
        })
    }

    /// The sum of each axis's functions (at the reference point and at the CG).
    pub fn sums(&self, env: &mut Env) -> Result<[[f64; 11]; 2], JsbsimError> {
        let mut sums = [[0.0; 11]; 2];
        for t in &self.terms {
            sums[usize::from(t.at_cg)][t.axis as usize] += env.function(t.function)?;
        }
        Ok(sums)
    }

    /// Forces and moments about the CG at alpha, beta (rad), for a CG at `cg` (inches,
    /// structural frame), the reference point at `rp` and chord `chord` ft.
    pub fn loads(
        &self,
        env: &mut Env,
        (alpha, beta): (f64, f64),
        cg: [f64; 3],
        rp: [f64; 3],
        chord: f64,
    ) -> Result<Loads, JsbsimError> {
        let sums = self.sums(env)?;
        let body = |s: &[f64; 11]| -> [f64; 3] {
            let (ca, sa, cb, sb) = (alpha.cos(), alpha.sin(), beta.cos(), beta.sin());
            let (side_wind, side_body) = if self.wind {
                (s[Axis::Side as usize], 0.0)
            } else {
                (0.0, s[Axis::Side as usize])
            };
            let w = [-s[Axis::Drag as usize], side_wind, -s[Axis::Lift as usize]];
            let wind = [
                ca * cb * w[0] - ca * sb * w[1] - sa * w[2],
                sb * w[0] + cb * w[1],
                sa * cb * w[0] - sa * sb * w[1] + ca * w[2],
            ];
            [
                wind[0] + s[Axis::X as usize] - s[Axis::Axial as usize],
                wind[1] + s[Axis::Y as usize] + side_body,
                wind[2] + s[Axis::Z as usize] - s[Axis::Normal as usize],
            ]
        };
        let at_rp = body(&sums[0]);
        let at_cg = body(&sums[1]);
        let shift_in = match &self.rp_shift {
            Some(e) => env.eval(e)? * chord * 12.0,
            None => 0.0,
        };
        let r = structural_to_body([rp[0] + shift_in, rp[1], rp[2]], cg);
        let m = [
            sums[0][Axis::Roll as usize],
            sums[0][Axis::Pitch as usize],
            sums[0][Axis::Yaw as usize],
        ];
        let cross = [
            r[1] * at_rp[2] - r[2] * at_rp[1],
            r[2] * at_rp[0] - r[0] * at_rp[2],
            r[0] * at_rp[1] - r[1] * at_rp[0],
        ];
        Ok(Loads {
            force: [0, 1, 2].map(|k| at_rp[k] + at_cg[k]),
            moment: [0, 1, 2].map(|k| m[k] + cross[k]),
        })
    }
}
