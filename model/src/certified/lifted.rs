//! The parametric results of [`super::compiled`] lifted to one aircraft (or box): dense
//! polynomials in P0 and delta_a with enclosed coefficients, computed once per data; the
//! zero-sideslip results and the characteristic coefficients lifted on first use.

use super::compiled::{Characteristic, Cleared, Parametric, Table};
use super::dense::Dense2;
use super::num::Num;
use crate::aircraft::Param;
use crate::algebra::MAX_SYMS;
use crate::equations::symbols;
use crate::interval::I;

/// What values are lifted from: the data (in [`Param::ALL`] order) and the controls.
#[derive(Clone, Copy, Debug)]
pub(super) struct Inputs<T> {
    pub(super) params: [T; Param::COUNT],
    pub(super) delta_e_rad: f64,
    pub(super) delta_r_rad: f64,
}

impl<T: Num> Inputs<T> {
    /// The table of every valued symbol.
    pub(super) fn table(&self) -> Table<T> {
        Table::new(&by_symbol(self.params, self.delta_e_rad, self.delta_r_rad))
    }
}

/// The values of the model's symbols: the data `params` (in [`Param::ALL`] order) and the
/// controls.
pub(super) fn by_symbol<T: Num>(
    params: [T; Param::COUNT],
    delta_e_rad: f64,
    delta_r_rad: f64,
) -> [Option<T>; MAX_SYMS] {
    let s = symbols();
    let mut by_symbol = [None; MAX_SYMS];
    for (p, v) in Param::ALL.iter().zip(params) {
        by_symbol[s.param(*p).index()] = Some(v);
    }
    by_symbol[s.delta_e.index()] = Some(T::constant(I::point(delta_e_rad)));
    by_symbol[s.delta_r.index()] = Some(T::constant(I::point(delta_r_rad)));
    by_symbol
}

/// Every compiled result of [`Parametric`] lifted to one aircraft (or box): polynomials in P0
/// and delta_a, computed once; the criterion polynomials are built from them
/// ([`EnclosedPolys`]) and evaluated at single roll rates ([`value_at`]) without touching the
/// parameters again.
#[derive(Clone, Debug)]
pub(super) struct Lifted<T> {
    pub(super) det_a: Dense2<T>,
    pub(super) trim: [Dense2<T>; 4],
    pub(super) roll: Vec<Dense2<T>>,
    pub(super) det_j5: Vec<Dense2<T>>,
    pub(super) d: Vec<Dense2<T>>,
    pub(super) lateral: Dense2<T>,
    /// The zero-sideslip results, lifted on first use (clearance never needs them).
    pub(super) zs: std::sync::OnceLock<LiftedZs<T>>,
    /// The characteristic coefficients, lifted on first use (only the Hopf points need them).
    pub(super) hopf: std::sync::OnceLock<LiftedHopf<T>>,
    /// What they are lifted from.
    pub(super) inputs: Inputs<T>,
    /// The table of every valued symbol, for the parts lifted on first use (built from
    /// `inputs` when first needed, unless given).
    pub(super) table: std::sync::OnceLock<Table<T>>,
}

/// The zero-sideslip part of [`Lifted`].
#[derive(Clone, Debug)]
pub(super) struct LiftedZs<T> {
    pub(super) zs_det: Dense2<T>,
    pub(super) zs_trim: [Dense2<T>; 3],
    pub(super) zs_det_j5: Vec<Dense2<T>>,
    pub(super) zs_d: Vec<Dense2<T>>,
}

/// The characteristic coefficients of [`Characteristic`] lifted (group coefficients of each
/// `c_k`, unconstrained and zero-sideslip).
#[derive(Clone, Debug)]
pub(super) struct LiftedHopf<T> {
    pub(super) c: [Vec<Dense2<T>>; 5],
    pub(super) zs_c: [Vec<Dense2<T>>; 5],
}

pub(super) fn lift_groups<T: Num>(g: &Cleared, t: &Table<T>) -> Vec<Dense2<T>> {
    g.coefficients.iter().map(|c| c.lift(t)).collect()
}

impl<T: Num> Lifted<T> {
    /// The main results of `c` lifted by `t`, and `inputs` (the data `t` stands for) for the
    /// parts lifted on first use.
    pub(super) fn new(c: &Parametric, t: &Table<T>, inputs: Inputs<T>) -> Lifted<T> {
        Lifted {
            det_a: c.det_a.lift(t),
            trim: std::array::from_fn(|i| c.trim[i].lift(t)),
            roll: lift_groups(&c.roll, t),
            det_j5: lift_groups(&c.det_j5, t),
            d: lift_groups(&c.d, t),
            lateral: c.lateral.lift(t),
            zs: std::sync::OnceLock::new(),
            hopf: std::sync::OnceLock::new(),
            inputs,
            table: std::sync::OnceLock::new(),
        }
    }

    pub(super) fn table(&self) -> &Table<T> {
        self.table.get_or_init(|| self.inputs.table())
    }

    pub(super) fn zs(&self) -> &LiftedZs<T> {
        self.zs.get_or_init(|| {
            let (c, t) = (Parametric::get(), self.table());
            LiftedZs {
                zs_det: c.zs_det.lift(t),
                zs_trim: std::array::from_fn(|i| c.zs_trim[i].lift(t)),
                zs_det_j5: lift_groups(&c.zs_det_j5, t),
                zs_d: lift_groups(&c.zs_d, t),
            }
        })
    }

    pub(super) fn hopf(&self) -> &LiftedHopf<T> {
        self.hopf.get_or_init(|| {
            let (c, t) = (Characteristic::get(), self.table());
            LiftedHopf {
                c: std::array::from_fn(|k| lift_groups(&c.c[k], t)),
                zs_c: std::array::from_fn(|k| lift_groups(&c.zs_c[k], t)),
            }
        })
    }
}
