//! Which derived results become which generated functions, and with what documentation.
//!
//! Each [`Function`] is a straight-line program over a [`Dag`] built from the derivation's
//! polynomials: the trim first (one division by det A), then the quantities that use it, so
//! that det K costs one trim, one reciprocal of d and a 2x2 determinant.

use super::formulas::{block, Formula};
use crate::derivation::Derivation;
pub(crate) use crate::program::builder::Arg;
use crate::program::builder::Ctx;
use crate::program::expr::{Dag, Id};
use crate::program::linear::merge_like_terms;

mod catalogue;
mod hopf;
mod prepared;
pub use catalogue::functions;
pub(crate) use hopf::polynomial as hopf_polynomial;
pub use prepared::{prepared, Prepared, TYPE as PREPARED_TYPE};

/// How a generated function returns its outputs.
#[derive(Clone, Debug, PartialEq)]
pub enum Ret {
    /// A single f64.
    Scalar,
    /// `[f64; N]`.
    Array(usize),
    /// `[[f64; C]; R]`.
    Matrix(usize, usize),
    /// A named struct with one f64 field per output.
    Struct(&'static str),
    /// `[S; N]` of a named struct: N values of S, outputs in order (all fields of the first,
    /// then of the second, ...); e.g. the trims of a roll rate, one per trim branch.
    Structs(&'static str, usize),
}

/// One generated function.
#[derive(Clone, Debug)]
pub struct Function {
    /// Rust name.
    pub name: &'static str,
    /// Doc comment lines (formula, equation numbers, units).
    pub doc: Vec<String>,
    /// Whether the function takes `k: &Derivatives` (parametric) or has the data folded in.
    pub takes_derivatives: bool,
    /// Scalar arguments.
    pub args: Vec<Arg>,
    /// The program.
    pub dag: Dag,
    /// Output names (struct fields, or `""` for arrays) and nodes.
    pub outputs: Vec<(String, Id)>,
    /// Return shape.
    pub ret: Ret,
    /// The type whose `impl` block holds the function (`Some("Prepared")` for `Prepared::new`
    /// and `Prepared::det_k`), or `None` for a free function. A function whose program reads
    /// fields `self.fN` takes `&self`.
    pub owner: Option<&'static str>,
}

impl Function {
    /// Whether the function reads the fields of its owner (a method taking `&self`).
    pub fn takes_self(&self) -> bool {
        self.dag.inputs().iter().any(|i| i.starts_with("self."))
    }
}

/// A struct the functions return: name, doc, fields (name, doc).
pub type StructSpec = (
    &'static str,
    &'static str,
    Vec<(&'static str, &'static str)>,
);

/// The struct types the functions return.
pub fn structs() -> Vec<StructSpec> {
    vec![
        (
            "Trim",
            "A pseudo-steady trim of the unconstrained roll at roll rate P0 (Eqs 3-4 and the roll equation); `trim` returns one per trim branch.",
            vec![
                ("alpha", "Angle of attack alpha_0, rad."),
                ("beta", "Sideslip beta_0, rad."),
                ("q", "Pitch rate Q_0, rad/s."),
                ("r", "Yaw rate R_0, rad/s."),
                ("delta_a", "Aileron deflection holding the trim, rad."),
            ],
        ),
        (
            "ZeroSideslipTrim",
            "Trim of the zero-sideslip roll at roll rate P0 (Eqs 32-35): beta = 0, rudder freed.",
            vec![
                ("alpha", "Angle of attack alpha_0, rad."),
                ("q", "Pitch rate Q_0, rad/s."),
                ("r", "Yaw rate R_0, rad/s."),
                ("delta_a", "Aileron deflection holding the trim, rad."),
                (
                    "delta_r",
                    "Rudder deflection holding zero sideslip (the schedule), rad; non-finite without lateral control authority (l_delta_a n_delta_r = l_delta_r n_delta_a).",
                ),
            ],
        ),
    ]
}
/// The generated function `name` of the program built in `c` with the outputs `outputs`.
fn finish(
    c: Ctx,
    name: &'static str,
    doc: Vec<String>,
    takes: bool,
    args: Vec<Arg>,
    outputs: Vec<(String, Id)>,
    ret: Ret,
) -> Function {
    // Like terms merged exactly before anything is printed or counted.
    let ids: Vec<Id> = outputs.iter().map(|(_, id)| *id).collect();
    let (dag, ids) = merge_like_terms(&c.dag, &ids);
    Function {
        name,
        doc,
        takes_derivatives: takes,
        args,
        dag,
        outputs: outputs
            .into_iter()
            .zip(ids)
            .map(|((n, _), id)| (n, id))
            .collect(),
        ret,
        owner: None,
    }
}

fn lines(v: &[&str]) -> Vec<String> {
    v.iter().map(|s| s.to_string()).collect()
}

/// K0, g, h and d of Eqs 16, 22 and 27-31, the quantities det K is built from.
fn stiffness_formulas(par: &Derivation) -> [(&'static str, Formula<'_>); 4] {
    [
        (
            "K0",
            Formula::Matrix(par.k0.iter().map(|r| r.iter().collect()).collect()),
        ),
        ("g", Formula::Vector(par.g.iter().collect())),
        ("h", Formula::Vector(par.h.iter().collect())),
        ("d", Formula::Poly(&par.d)),
    ]
}

/// Prose lines followed by the block of formulas they name.
fn with_formulas(v: &[&str], items: &[(&str, Formula)]) -> Vec<String> {
    let mut out = lines(v);
    out.extend(block(items));
    out
}
