//! Certified floating-point evaluation of the criterion: the same polynomials as the exact path,
//! enclosed in f64 intervals, and their positive roots with proven brackets.
//!
//! The exact path ([`crate::specialise`], [`crate::roots`]) substitutes an aircraft's exact
//! rational data into the parametric derivation and works in big rationals: every digit is
//! right, at milliseconds per aircraft (much more for data with long fractions). Clearance and
//! Monte Carlo analyse thousands to millions of aircraft, so they need the same answers in
//! floating point, without giving up the guarantee. Here every number is an interval
//! ([`crate::interval::I`], outward rounding) that encloses the exact value:
//!
//! 1. the parametric trim-level results of [`crate::derivation`] (det A, the trim numerators,
//!    the roll equation, det J5 and d in the trim symbols) are evaluated at the data's
//!    enclosures into dense polynomials in P0 and delta_a ([`dense`]);
//! 2. the trim's denominator is cleared by the one step-8 routine,
//!    [`crate::derivation::clear_trim`], in the ring of those interval polynomials, and the
//!    aileron is eliminated by the resultant with the trim condition ([`eliminate`]);
//! 3. [`isolate`] brackets the positive roots of every polynomial whose coefficients lie in
//!    the enclosures, or says it cannot (its inner loops keep f64 midpoints with radii that
//!    bound their rounding instead of intervals: the same guarantee, less work).
//!
//! So a certified answer is exactly the exact path's, up to the width of the brackets (an ulp or
//! two). Where a certificate fails (a root too close to another, a coefficient that may vanish)
//! callers fall back to the exact path: the answer is never a guess.
//!
//! ```
//! use model::aircraft::Aircraft;
//! use model::certified::{positive_roots_by, EnclosedPolys, Values};
//!
//! // Aircraft A at delta_e = 2 deg: its first jump root (Table 1: 1.706288 rad/s) lies in a
//! // certified bracket of relative width at most 1e-9.
//! let v = Values::of(&Aircraft::a(), 2f64.to_radians(), 0.0);
//! let e = EnclosedPolys::new(&v).unwrap();
//! let first = positive_roots_by(&e.jump, None, 1e-9).unwrap()[0];
//! assert!(first.lo < 1.7062880 && first.hi > 1.7062879);
//! ```

pub mod compiled;
pub mod dense;
pub mod isolate;
pub mod num;
pub(crate) mod tape;

use crate::aircraft::{Aircraft, Param};
use crate::algebra::MAX_SYMS;
use crate::derivation::hopf::{stripped_delta4_in, TRIM_FACTOR_POWERS};
use crate::derivation::{Clearing, TrimProducts, TRIM_DEGREE};
use crate::equations::symbols;
use crate::interval::I;
use compiled::{Characteristic, Cleared, Parametric, Table};
use dense::{Dense, Dense2, IPoly, IPoly2};
pub use isolate::{
    positive_roots, positive_roots_by, positive_roots_windowed, positive_roots_windowed_even,
    real_roots_outside, Bracket, Uncertified,
};
use num::Num;
use std::borrow::Cow;
use std::cell::RefCell;

/// The enclosures of an aircraft's data and controls (one per symbol of the model that has a
/// value: the parameters, delta_e and delta_r) and every parametric result lifted to them.
#[derive(Clone, Debug)]
pub struct Values<T = I> {
    lifted: Lifted<T>,
}

impl Values<I> {
    /// The exact data of `aircraft` (each bracketed by the two nearest doubles) at elevator
    /// `delta_e_rad` and rudder `delta_r_rad` (both exact doubles).
    pub fn of(aircraft: &Aircraft, delta_e_rad: f64, delta_r_rad: f64) -> Values<I> {
        Values::new(Values::data(aircraft), delta_e_rad, delta_r_rad)
    }

    /// The exact data of `aircraft` in [`Param::ALL`] order, each bracketed by the two nearest
    /// doubles (exact ones stay points).
    pub fn data(aircraft: &Aircraft) -> [I; 18] {
        std::array::from_fn(|i| I::from_q(aircraft.exact(Param::ALL[i])))
    }
}

impl<T: Num> Values<T> {
    /// Enclosures `params` (in [`Param::ALL`] order) of the data.
    pub fn new(params: [T; 18], delta_e_rad: f64, delta_r_rad: f64) -> Values<T> {
        let inputs = Inputs {
            params,
            delta_e_rad,
            delta_r_rad,
        };
        let table = inputs.table();
        let lifted = Lifted::new(Parametric::get(), &table, inputs);
        // The whole table, kept for the parts lifted on first use.
        let _ = lifted.table.set(table);
        Values { lifted }
    }
}

/// What values are lifted from: the data (in [`Param::ALL`] order) and the controls.
#[derive(Clone, Copy, Debug)]
struct Inputs<T> {
    params: [T; 18],
    delta_e_rad: f64,
    delta_r_rad: f64,
}

impl<T: Num> Inputs<T> {
    /// The table of every valued symbol.
    fn table(&self) -> Table<T> {
        Table::new(&by_symbol(self.params, self.delta_e_rad, self.delta_r_rad))
    }
}

/// The values of the model's symbols: the data `params` (in [`Param::ALL`] order) and the
/// controls.
fn by_symbol<T: Num>(params: [T; 18], delta_e_rad: f64, delta_r_rad: f64) -> [Option<T>; MAX_SYMS] {
    let s = symbols();
    let mut by_symbol = [None; MAX_SYMS];
    for (p, v) in Param::ALL.iter().zip(params) {
        by_symbol[s.param(*p).index()] = Some(v);
    }
    by_symbol[s.delta_e.index()] = Some(T::constant(I::point(delta_e_rad)));
    by_symbol[s.delta_r.index()] = Some(T::constant(I::point(delta_r_rad)));
    by_symbol
}

/// [`Values`] for many samples of a box where only a few parameters vary (Monte Carlo): the
/// parametric results with every other parameter and the controls folded into their
/// coefficients once ([`Parametric::folded`]), so that lifting one sample is a pass over the
/// terms in the varying parameters only. The values enclose the same exact quantities as
/// [`Values::new`] on the whole data (each folded coefficient encloses its exact value).
#[derive(Debug)]
pub struct Sampler {
    parametric: Parametric,
    inputs: Inputs<I>,
    varying: Vec<Param>,
}

impl Sampler {
    /// The data `params` (in [`Param::ALL`] order; the entries of `varying` are replaced by
    /// each sample's) at elevator `delta_e_rad` and rudder `delta_r_rad`.
    pub fn new(params: [I; 18], varying: &[Param], delta_e_rad: f64, delta_r_rad: f64) -> Sampler {
        let s = symbols();
        let inputs = Inputs {
            params,
            delta_e_rad,
            delta_r_rad,
        };
        let mut keep = [false; MAX_SYMS];
        for p in varying {
            keep[s.param(*p).index()] = true;
        }
        Sampler {
            parametric: Parametric::get().folded(&inputs.table(), &keep),
            inputs,
            varying: varying.to_vec(),
        }
    }

    /// The values of the sample whose varying parameters (in the order given to
    /// [`Sampler::new`]) are enclosed by `x`.
    pub fn values(&self, x: &[I]) -> Values<I> {
        debug_assert_eq!(
            x.len(),
            self.varying.len(),
            "one value per varying parameter"
        );
        // The folded results read only the varying symbols: a table of those alone (small,
        // no large allocation per sample).
        let s = symbols();
        let mut inputs = self.inputs;
        let mut varying = [None; MAX_SYMS];
        for (p, xi) in self.varying.iter().zip(x) {
            inputs.params[p.index()] = *xi;
            varying[s.param(*p).index()] = Some(*xi);
        }
        Values {
            lifted: Lifted::new(&self.parametric, &Table::new(&varying), inputs),
        }
    }
}

/// Every compiled result of [`Parametric`] lifted to one aircraft (or box): polynomials in P0
/// and delta_a, computed once; the criterion polynomials are built from them
/// ([`EnclosedPolys`]) and evaluated at single roll rates ([`value_at`]) without touching the
/// parameters again.
#[derive(Clone, Debug)]
struct Lifted<T> {
    det_a: Dense2<T>,
    trim: [Dense2<T>; 4],
    roll: Vec<Dense2<T>>,
    det_j5: Vec<Dense2<T>>,
    d: Vec<Dense2<T>>,
    lateral: Dense2<T>,
    /// The zero-sideslip results, lifted on first use (clearance never needs them).
    zs: std::sync::OnceLock<LiftedZs<T>>,
    /// The characteristic coefficients, lifted on first use (only the Hopf points need them).
    hopf: std::sync::OnceLock<LiftedHopf<T>>,
    /// What they are lifted from.
    inputs: Inputs<T>,
    /// The table of every valued symbol, for the parts lifted on first use (built from
    /// `inputs` when first needed, unless given).
    table: std::sync::OnceLock<Table<T>>,
}

/// The zero-sideslip part of [`Lifted`].
#[derive(Clone, Debug)]
struct LiftedZs<T> {
    zs_det: Dense2<T>,
    zs_trim: [Dense2<T>; 3],
    zs_det_j5: Vec<Dense2<T>>,
    zs_d: Vec<Dense2<T>>,
}

/// The characteristic coefficients of [`Characteristic`] lifted (group coefficients of each
/// `c_k`, unconstrained and zero-sideslip).
#[derive(Clone, Debug)]
struct LiftedHopf<T> {
    c: [Vec<Dense2<T>>; 5],
    zs_c: [Vec<Dense2<T>>; 5],
}

fn lift_groups<T: Num>(g: &Cleared, t: &Table<T>) -> Vec<Dense2<T>> {
    g.coefficients.iter().map(|c| c.lift(t)).collect()
}

impl<T: Num> Lifted<T> {
    /// The main results of `c` lifted by `t`, and `inputs` (the data `t` stands for) for the
    /// parts lifted on first use.
    fn new(c: &Parametric, t: &Table<T>, inputs: Inputs<T>) -> Lifted<T> {
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

    fn table(&self) -> &Table<T> {
        self.table.get_or_init(|| self.inputs.table())
    }

    fn zs(&self) -> &LiftedZs<T> {
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

    fn hopf(&self) -> &LiftedHopf<T> {
        self.hopf.get_or_init(|| {
            let (c, t) = (Characteristic::get(), self.table());
            LiftedHopf {
                c: std::array::from_fn(|k| lift_groups(&c.c[k], t)),
                zs_c: std::array::from_fn(|k| lift_groups(&c.zs_c[k], t)),
            }
        })
    }
}

/// The coefficient rings of the criterion polynomials in delta_a: polynomials in P0
/// ([`Dense`]) when the polynomials are built, numbers ([`Num`]) when they are evaluated at
/// one roll rate. [`eliminate`] is written once over both.
pub trait Coeff: Clone {
    /// `a + b`.
    fn add(&self, o: &Self) -> Self;
    /// `a - b`.
    fn sub(&self, o: &Self) -> Self;
    /// `a * b`.
    fn mul(&self, o: &Self) -> Self;
    /// `a^k`.
    fn pow(&self, k: u32) -> Self;
    /// `a / d` for an exact division (`None` when it cannot be certified).
    fn div_exact(&self, d: &Self) -> Option<Self>;
    /// Zero.
    fn zero() -> Self;
    /// The constant `c`.
    fn constant(c: I) -> Self;
}

impl<T: Num> Coeff for Dense<T> {
    fn add(&self, o: &Dense<T>) -> Dense<T> {
        Dense::add(self, o)
    }
    fn sub(&self, o: &Dense<T>) -> Dense<T> {
        Dense::sub(self, o)
    }
    fn mul(&self, o: &Dense<T>) -> Dense<T> {
        Dense::mul(self, o)
    }
    fn pow(&self, k: u32) -> Dense<T> {
        Dense::pow(self, k)
    }
    fn div_exact(&self, d: &Dense<T>) -> Option<Dense<T>> {
        Dense::div_exact(self, d)
    }
    fn zero() -> Dense<T> {
        Dense::zero()
    }
    fn constant(c: I) -> Dense<T> {
        Dense::constant(T::constant(c))
    }
}

/// A number as a [`Coeff`] (the ring of values at one roll rate).
#[derive(Clone, Copy, Debug)]
pub struct Scalar<T>(pub T);

impl<T: Num> Coeff for Scalar<T> {
    fn add(&self, o: &Self) -> Self {
        Scalar(self.0 + o.0)
    }
    fn sub(&self, o: &Self) -> Self {
        Scalar(self.0 - o.0)
    }
    fn mul(&self, o: &Self) -> Self {
        Scalar(self.0 * o.0)
    }
    fn pow(&self, k: u32) -> Self {
        Scalar(self.0.powi(k))
    }
    fn div_exact(&self, d: &Self) -> Option<Self> {
        self.0.div(d.0).map(Scalar)
    }
    fn zero() -> Self {
        Scalar(T::constant(I::point(0.0)))
    }
    fn constant(c: I) -> Self {
        Scalar(T::constant(c))
    }
}

/// How the lifted results are evaluated: the ring of step 8 (polynomials in delta_a over
/// [`Mode::Coef`]) and the lift of a lifted polynomial into it.
trait Mode: Clearing {
    /// The numbers.
    type Num: Num;
    /// Coefficients of the polynomials in delta_a.
    type Coef: Coeff;
    /// A lifted result as a value of the ring.
    fn lifted(&self, p: &Dense2<Self::Num>) -> Self::Value {
        self.lifted_ref(p).into_owned()
    }
    /// [`Mode::lifted`], borrowed where the value is the lifted result itself.
    fn lifted_ref<'a>(&self, p: &'a Dense2<Self::Num>) -> Cow<'a, Self::Value>;
    /// The coefficients of `delta_a^0, delta_a^1, ...` (trailing exact zeros dropped).
    fn in_aileron(v: &Self::Value) -> Vec<Self::Coef>;
    /// Step 8 of a grouped result whose group coefficients are `lifted`, on the trim of
    /// `products` (extended and reused).
    fn clear_with(
        &mut self,
        c: &Cleared,
        lifted: &[Dense2<Self::Num>],
        num: &[Self::Value],
        den: &Self::Value,
        products: &mut TrimProducts<Self::Value>,
    ) -> Self::Value
    where
        Self: Sized,
    {
        c.groups
            .clear_with(self, num, den, products, |m, i| m.lifted_ref(&lifted[i]))
    }
    /// The value when delta_a does not occur.
    fn univariate(v: &Self::Value) -> Result<Self::Coef, Uncertified> {
        let mut c = Self::in_aileron(v);
        match c.len() {
            0 => Ok(Self::Coef::zero()),
            1 => Ok(c.remove(0)),
            _ => Err(Uncertified::Degenerate),
        }
    }
}

/// A constant step 8 lifts through the ring (only 0 and 1: the coefficients come lifted).
fn constant(p: &crate::algebra::Poly) -> I {
    let c = p
        .as_constant()
        .expect("step 8 lifts only constants through the ring");
    match c.as_i64() {
        Some(n) if n.unsigned_abs() <= 1 << 53 => I::point(n as f64),
        _ => I::from_q(&c.to_big()),
    }
}

/// The criterion polynomials in P0 (and delta_a): values are [`Dense2`].
struct InP0<T>(std::marker::PhantomData<T>);

impl<T> InP0<T> {
    fn new() -> InP0<T> {
        InP0(std::marker::PhantomData)
    }
}

impl<T: Num> Clearing for InP0<T> {
    type Value = Dense2<T>;
    fn lift(&mut self, p: &crate::algebra::Poly) -> Dense2<T> {
        Dense2::new(vec![Dense::constant(T::constant(constant(p)))])
    }
    fn add(&mut self, a: &Dense2<T>, b: &Dense2<T>) -> Dense2<T> {
        a.add(b)
    }
    fn mul(&mut self, a: &Dense2<T>, b: &Dense2<T>) -> Dense2<T> {
        a.mul(b)
    }
    fn add_product(&mut self, acc: &mut Dense2<T>, a: &Dense2<T>, b: &Dense2<T>) {
        acc.add_product(a, b);
    }
}

impl<T: Num> Mode for InP0<T> {
    type Num = T;
    type Coef = Dense<T>;
    fn lifted_ref<'a>(&self, p: &'a Dense2<T>) -> Cow<'a, Dense2<T>> {
        Cow::Borrowed(p)
    }
    fn in_aileron(v: &Dense2<T>) -> Vec<Dense<T>> {
        v.0.clone()
    }
}

/// The criterion at one roll rate `.0`: values are polynomials in delta_a ([`Da`]).
struct AtP0<T>(T);

/// A polynomial in delta_a of degree at most 3 (no allocation).
#[derive(Clone, Copy, Debug)]
struct Da<T> {
    c: [T; 4],
    len: usize,
}

impl<T: Num> Da<T> {
    fn new(c: [T; 4]) -> Da<T> {
        let len = c
            .iter()
            .rposition(|x| !x.is_exact_zero())
            .map_or(0, |i| i + 1);
        Da { c, len }
    }

    fn anything() -> Da<T> {
        Da::new([T::constant(I::entire()); 4])
    }
}

impl<T: Num> Clearing for AtP0<T> {
    type Value = Da<T>;
    fn lift(&mut self, p: &crate::algebra::Poly) -> Da<T> {
        let mut c = [T::constant(I::point(0.0)); 4];
        c[0] = T::constant(constant(p));
        Da::new(c)
    }
    fn add(&mut self, a: &Da<T>, b: &Da<T>) -> Da<T> {
        Da::new(std::array::from_fn(|i| a.c[i] + b.c[i]))
    }
    fn mul(&mut self, a: &Da<T>, b: &Da<T>) -> Da<T> {
        let mut c = [T::constant(I::point(0.0)); 4];
        for i in 0..a.len {
            for j in 0..b.len {
                // Step 8's products stay within degree 3 in delta_a (trim numerators are affine
                // in it, every trim quantity at most quadratic in the trim states); a product
                // beyond would be no value at all, never a truncated one.
                let Some(slot) = c.get_mut(i + j) else {
                    return Da::anything();
                };
                *slot = *slot + a.c[i] * b.c[j];
            }
        }
        Da::new(c)
    }
}

impl<T: Num> Mode for AtP0<T> {
    type Num = T;
    type Coef = Scalar<T>;
    fn lifted_ref<'a>(&self, p: &'a Dense2<T>) -> Cow<'a, Da<T>> {
        if p.0.len() > 4 {
            return Cow::Owned(Da::anything());
        }
        let mut out = [T::constant(I::point(0.0)); 4];
        for (o, c) in out.iter_mut().zip(&p.0) {
            *o = c.eval(self.0);
        }
        Cow::Owned(Da::new(out))
    }
    fn in_aileron(v: &Da<T>) -> Vec<Scalar<T>> {
        v.c[..v.len].iter().map(|c| Scalar(*c)).collect()
    }
}

/// The criterion quantities of the unconstrained roll in a [`Mode`].
struct Unconstrained<M: Mode> {
    det_a: M::Coef,
    det_a_value: M::Value,
    trim: [M::Value; 4],
    trim_condition: M::Value,
    /// Step 8's products on this trim (`trim / det_a_value`), shared by the trim condition,
    /// det J5 and d.
    products: RefCell<TrimProducts<M::Value>>,
}

impl<M: Mode> Unconstrained<M> {
    /// det A, the trim and the trim condition; det J5 and d on the trim on demand
    /// ([`Unconstrained::on_trim`]).
    fn new(m: &mut M, l: &Lifted<M::Num>) -> Result<Unconstrained<M>, Uncertified> {
        let c = Parametric::get();
        let det_a_value = m.lifted(&l.det_a);
        let det_a = M::univariate(&det_a_value)?;
        let trim: [M::Value; 4] = std::array::from_fn(|i| m.lifted(&l.trim[i]));
        let mut products = TrimProducts::new(m, &det_a_value, TRIM_DEGREE);
        Ok(Unconstrained {
            trim_condition: m.clear_with(&c.roll, &l.roll, &trim, &det_a_value, &mut products),
            det_a,
            det_a_value,
            trim,
            products: RefCell::new(products),
        })
    }

    /// `det J5 det(A)^2` (`jump`) or `d det(A)^2` on the trim.
    fn on_trim(&self, m: &mut M, l: &Lifted<M::Num>, jump: bool) -> M::Value {
        let c = Parametric::get();
        let (groups, lifted) = if jump {
            (&c.det_j5, &l.det_j5)
        } else {
            (&c.d, &l.d)
        };
        let mut products = self.products.borrow_mut();
        m.clear_with(groups, lifted, &self.trim, &self.det_a_value, &mut products)
    }

    fn eliminate(&self, f: &M::Value) -> Result<M::Coef, Uncertified> {
        eliminate(
            &M::in_aileron(&self.trim_condition),
            &M::in_aileron(f),
            &self.det_a,
        )
    }
}

/// The numerators of [alpha0, Q0, R0] of the zero-sideslip trim and their denominator det A1,
/// as values of the ring `m`.
fn zs_trim_in<M: Mode>(m: &mut M, l: &Lifted<M::Num>) -> ([M::Value; 3], M::Value) {
    let l = l.zs();
    (
        std::array::from_fn(|i| m.lifted(&l.zs_trim[i])),
        m.lifted(&l.zs_det),
    )
}

/// The criterion quantities of the zero-sideslip roll in a [`Mode`].
struct ZeroSideslip<M: Mode> {
    zs_det: M::Coef,
    zs_trim: [M::Coef; 3],
    zs_jump: M::Coef,
    zs_d_det: M::Coef,
}

impl<M: Mode> ZeroSideslip<M> {
    fn new(m: &mut M, l: &Lifted<M::Num>) -> Result<ZeroSideslip<M>, Uncertified> {
        let c = Parametric::get();
        let (num, den) = zs_trim_in(m, l);
        let l = l.zs();
        let mut products = TrimProducts::new(m, &den, TRIM_DEGREE);
        let zs_jump = m.clear_with(&c.zs_det_j5, &l.zs_det_j5, &num, &den, &mut products);
        let zs_d_det = m.clear_with(&c.zs_d, &l.zs_d, &num, &den, &mut products);
        Ok(ZeroSideslip {
            zs_jump: M::univariate(&zs_jump)?,
            zs_d_det: M::univariate(&zs_d_det)?,
            zs_trim: [
                M::univariate(&num[0])?,
                M::univariate(&num[1])?,
                M::univariate(&num[2])?,
            ],
            zs_det: M::univariate(&den)?,
        })
    }
}

/// The criterion polynomials of one aircraft, enclosed: the interval counterpart of
/// [`crate::analysis::CriterionPolys`] (same names, same construction, each proportional to
/// the exact one by a positive or negative constant).
#[derive(Clone, Debug)]
pub struct EnclosedPolys {
    /// det A (Eq. 4) in P0.
    pub det_a: IPoly,
    /// Numerators of [alpha0, beta0, Q0, R0] over `det_a`, in P0 and delta_a.
    pub trim: [IPoly2; 4],
    /// The trim condition `det(A)^2 p_dot` on the trim.
    pub trim_condition: IPoly2,
    /// `det J5 det(A)^2` on the trim.
    pub jump_at: IPoly2,
    /// `d det(A)^2` on the trim.
    pub d_at: IPoly2,
    /// The jump polynomial in P0 (delta_a eliminated; with aileron yaw divided by det(A)^4,
    /// a factor of every aircraft's resultant).
    pub jump: IPoly,
    /// The pole polynomial in P0 (as `jump`).
    pub poles: IPoly,
    /// det A1 of the zero-sideslip trim (Eq. 35) in P0.
    pub zs_det: IPoly,
    /// Numerators of [alpha0, Q0, R0] of the zero-sideslip trim over `zs_det`.
    pub zs_trim: [IPoly; 3],
    /// `det J5 det(A1)^2` at the zero-sideslip trim.
    pub zs_jump: IPoly,
    /// `d det(A1)^2` at the zero-sideslip trim.
    pub zs_d_det: IPoly,
    /// The lateral control determinant `l_delta_a n_delta_r - l_delta_r n_delta_a`.
    pub lateral: I,
}

impl EnclosedPolys {
    /// Encloses the criterion polynomials of the data `v`.
    pub fn new(v: &Values) -> Result<EnclosedPolys, Uncertified> {
        let JumpPolys {
            det_a,
            trim_condition,
            jump_at,
            jump,
            unconstrained: u,
        } = JumpPolys::new(v)?;
        let (l, m) = (&v.lifted, &mut InP0::new());
        let d_at = u.on_trim(m, l, false);
        let z = ZeroSideslip::new(m, l)?;
        let lateral = l.lateral.coeff(0);
        // Every polynomial isolated below is even or odd in P0 (see `IPoly::symmetric`).
        Ok(EnclosedPolys {
            jump,
            poles: u.eliminate(&d_at)?.symmetric(),
            det_a,
            trim: u.trim,
            trim_condition,
            jump_at,
            d_at,
            zs_det: z.zs_det.symmetric(),
            zs_trim: z.zs_trim,
            zs_jump: z.zs_jump.symmetric(),
            zs_d_det: z.zs_d_det.symmetric(),
            lateral: lateral.coeffs().first().copied().unwrap_or(I::point(0.0)),
        })
    }
}

impl EnclosedPolys {
    /// The criterion polynomials of the data `params` (in [`Param::ALL`] order) at elevator
    /// `delta_e_rad` and `delta_r = 0`, from one evaluation of the criterion program (the
    /// straight-line program of their coefficients, `program::criterion`) in
    /// f64 with an a priori bound on its rounding (`certified::tape`): the same exact
    /// polynomials as [`EnclosedPolys::new`] on the same data, in enclosures of about the same
    /// width, at a small fraction of the cost. `None` where the tape does not apply: aileron
    /// yaw (`n_delta_a` not exactly zero), or data the tape's bound does not cover (an
    /// enclosure wider than an ulp, a magnitude outside its gate); [`EnclosedPolys::new`]
    /// answers those.
    pub fn by_tape(
        params: &[I; 18],
        delta_e_rad: f64,
    ) -> Option<Result<EnclosedPolys, Uncertified>> {
        let yaw = Param::ALL.iter().position(|p| *p == Param::NDeltaA)?;
        if !params[yaw].is_exact_zero() {
            return None;
        }
        let t = CriterionTape::get();
        let inputs: Vec<I> = std::iter::once(I::point(delta_e_rad))
            .chain(params.iter().copied())
            .collect();
        let mut values = t.tape.eval(&inputs)?.into_iter();
        let mut next = |n: usize| IPoly::new(values.by_ref().take(n).collect());
        let mut lengths = t.lengths.iter().copied();
        let mut take = || next(lengths.next().unwrap_or(0));
        let det_a = take();
        let trim: [IPoly2; 4] = std::array::from_fn(|_| IPoly2::new(vec![take()]));
        let trim_condition = IPoly2::new(vec![take(), take()]);
        let jump_at = IPoly2::new(vec![take()]);
        let d_at = IPoly2::new(vec![take()]);
        let zs_det = take();
        let zs_trim: [IPoly; 3] = std::array::from_fn(|_| take());
        let (zs_jump, zs_d_det) = (take(), take());
        let at = |p: Param| params[Param::ALL.iter().position(|q| *q == p).unwrap_or(0)];
        let lateral =
            at(Param::LDeltaA) * at(Param::NDeltaR) - at(Param::LDeltaR) * at(Param::NDeltaA);
        // As the general route: delta_a eliminated from the trim condition (linear here).
        let eliminate =
            |f: &IPoly2| eliminate(&trim_condition.0, &f.0, &det_a).map(|p: IPoly| p.symmetric());
        Some((|| {
            Ok(EnclosedPolys {
                jump: eliminate(&jump_at)?,
                poles: eliminate(&d_at)?,
                det_a: det_a.symmetric(),
                trim,
                trim_condition: trim_condition.clone(),
                jump_at,
                d_at,
                zs_det: zs_det.symmetric(),
                zs_trim,
                zs_jump: zs_jump.symmetric(),
                zs_d_det: zs_d_det.symmetric(),
                lateral,
            })
        })())
    }
}

/// The criterion program ([`crate::program::criterion::criterion_program`]) of the process's
/// parametric derivation, compiled once, with the number of coefficients of each of its
/// polynomials (in the order of [`crate::program::criterion::CriterionProgram::polys`]).
struct CriterionTape {
    tape: tape::Tape,
    lengths: Vec<usize>,
}

impl CriterionTape {
    fn get() -> &'static CriterionTape {
        static T: std::sync::OnceLock<CriterionTape> = std::sync::OnceLock::new();
        T.get_or_init(|| {
            let p = crate::program::criterion::criterion_program(crate::specialise::parametric());
            // The inputs the data are given in: delta_e, then the parameters.
            let names: Vec<String> = std::iter::once("delta_e".to_string())
                .chain(
                    Param::ALL
                        .iter()
                        .map(|p| format!("k.{}", p.key().to_lowercase())),
                )
                .collect();
            assert_eq!(
                p.dag.inputs(),
                names.as_slice(),
                "the criterion program's inputs"
            );
            CriterionTape {
                lengths: p.polys().iter().map(|c| c.len()).collect(),
                tape: tape::Tape::new(&p.dag, &p.outputs()),
            }
        })
    }
}

/// The part of [`EnclosedPolys`] the critical jump needs: det A, the trim condition, det J5 on
/// the trim and the jump polynomial (the Monte Carlo's lean route).
pub struct JumpPolys {
    /// det A (Eq. 4) in P0.
    pub det_a: IPoly,
    /// The trim condition `det(A)^2 p_dot` on the trim.
    pub trim_condition: IPoly2,
    /// `det J5 det(A)^2` on the trim.
    pub jump_at: IPoly2,
    /// The jump polynomial in P0.
    pub jump: IPoly,
    unconstrained: Unconstrained<InP0<I>>,
}

impl JumpPolys {
    /// Encloses the jump part of the criterion polynomials of the data `v`.
    pub fn new(v: &Values) -> Result<JumpPolys, Uncertified> {
        let (l, m) = (&v.lifted, &mut InP0::new());
        let u = Unconstrained::new(m, l)?;
        let jump_at = u.on_trim(m, l, true);
        Ok(JumpPolys {
            jump: u.eliminate(&jump_at)?.symmetric(),
            det_a: u.det_a.symmetric(),
            trim_condition: u.trim_condition.clone(),
            jump_at,
            unconstrained: u,
        })
    }

    /// det A and the numerators of [alpha0, beta0, Q0, R0] in P0 and delta_a.
    pub fn trim(&self) -> (&IPoly2, &[IPoly2; 4]) {
        (&self.unconstrained.det_a_value, &self.unconstrained.trim)
    }

    /// The pole polynomial in P0 (as in [`EnclosedPolys`]) of the same data `v`.
    pub fn poles(&self, v: &Values) -> Result<IPoly, Uncertified> {
        let u = &self.unconstrained;
        let d_at = u.on_trim(&mut InP0::new(), &v.lifted, false);
        Ok(u.eliminate(&d_at)?.symmetric())
    }
}

/// `den^10 Delta4 / den^4` of a trim `t_i = num_i / den` (the Hopf polynomial with the factor
/// the exact path strips, `analysis::strip`) from the lifted characteristic coefficients: each
/// `C_k = den^k c_k(num / den)` by step 8, divided by its own power of `den`
/// ([`TRIM_FACTOR_POWERS`], a certified exact division of a polynomial of low degree), and
/// Delta4 with that factor taken out ([`stripped_delta4_in`]): the routines of the exact path,
/// in the ring `m`. Dividing the expanded degree-48 polynomial by `den^4` instead would lose
/// eight digits of its middle coefficients. Without aileron yaw only: delta_a must not occur
/// ([`Uncertified::Uncovered`] otherwise).
fn hopf_in<M: Mode>(
    m: &mut M,
    groups: &[Cleared; 5],
    lifted: &[Vec<Dense2<M::Num>>; 5],
    num: &[M::Value],
    den: &M::Value,
) -> Result<Reduced<M::Coef>, Uncertified> {
    let uncovered = |_| Uncertified::Uncovered;
    let scale = M::univariate(den).map_err(uncovered)?;
    for n in num {
        M::univariate(n).map_err(uncovered)?;
    }
    let mut c = Vec::with_capacity(5);
    let mut products = TrimProducts::new(m, den, 1);
    for (k, power) in TRIM_FACTOR_POWERS.iter().enumerate() {
        let cleared = M::univariate(&m.clear_with(&groups[k], &lifted[k], num, den, &mut products))
            .map_err(uncovered)?;
        c.push(
            cleared
                .div_exact(&scale.pow(*power))
                .ok_or(Uncertified::Degenerate)?,
        );
    }
    Ok(Reduced {
        c: c.try_into()
            .unwrap_or_else(|_| unreachable!("five coefficients")),
        f: scale,
    })
}

/// The characteristic coefficients at a trim, cleared and divided by their own powers of the
/// trim's denominator `f` (`c'_k = C_k / f^(e_k)`), and `f`: what the Hopf polynomial is built
/// from.
#[derive(Clone, Debug)]
struct Reduced<C> {
    c: [C; 5],
    f: C,
}

impl<C: Coeff> Reduced<C> {
    /// `Delta4(C) / f^4`, the Hopf polynomial with det A's factor stripped.
    fn delta4(&self) -> C {
        stripped_delta4_in(&mut InCoef(std::marker::PhantomData), &self.c, &self.f)
    }
}

impl Reduced<IPoly> {
    /// The same in `u = P0^2` ([`IPoly::in_square`]): every ingredient is even in P0 (see
    /// [`EnclosedHopf::positive_roots`]).
    fn in_square(&self) -> Option<Reduced<IPoly>> {
        let [c1, c2, c3, c4, c5] = &self.c;
        Some(Reduced {
            c: [
                c1.in_square()?,
                c2.in_square()?,
                c3.in_square()?,
                c4.in_square()?,
                c5.in_square()?,
            ],
            f: self.f.in_square()?,
        })
    }

    /// The same at `P0 = x0 + y`, in `y`.
    fn shift(&self, x0: f64) -> Reduced<IPoly> {
        let x0 = I::point(x0);
        Reduced {
            c: std::array::from_fn(|k| self.c[k].shift(x0)),
            f: self.f.shift(x0),
        }
    }
}

/// The coefficient ring of a [`Mode`] as a ring of step 8 (for the Hopf polynomial, whose
/// ingredients are free of delta_a).
struct InCoef<C>(std::marker::PhantomData<C>);

impl<C: Coeff> Clearing for InCoef<C> {
    type Value = C;
    fn lift(&mut self, p: &crate::algebra::Poly) -> C {
        C::constant(constant(p))
    }
    fn add(&mut self, a: &C, b: &C) -> C {
        a.add(b)
    }
    fn mul(&mut self, a: &C, b: &C) -> C {
        a.mul(b)
    }
}

/// The Hopf polynomials of one aircraft without aileron yaw, enclosed: the interval counterpart
/// of `analysis::HopfPolys`' `hopf` and `zs_hopf` (each proportional to the exact one by a
/// constant, with the factor `det(A)^4` the exact path strips taken out, see `hopf_in`), and
/// their certified positive roots.
#[derive(Clone, Debug)]
pub struct EnclosedHopf {
    /// `det(A)^10 Delta4 / det(A)^4` in P0.
    pub hopf: IPoly,
    /// `det(A1)^10 Delta4 / det(A1)^4` at the zero-sideslip trim (beta0 = 0), in P0.
    pub zs_hopf: IPoly,
    reduced: Reduced<IPoly>,
    zs_reduced: Reduced<IPoly>,
}

impl EnclosedHopf {
    /// Encloses the Hopf polynomials of the data `v`; [`Uncertified::Uncovered`] with aileron
    /// yaw (the trim then depends on delta_a, and the exact path eliminates it by a resultant).
    pub fn new(v: &Values) -> Result<EnclosedHopf, Uncertified> {
        let (l, m) = (&v.lifted, &mut InP0::new());
        let (c, h) = (Characteristic::get(), l.hopf());
        let u = Unconstrained::new(m, l)?;
        let reduced = hopf_in(m, &c.c, &h.c, &u.trim, &u.det_a_value)?;
        let (num, den) = zs_trim_in(m, l);
        let zs_reduced = hopf_in(m, &c.zs_c, &h.zs_c, &num, &den)?;
        Ok(EnclosedHopf {
            hopf: reduced.delta4().symmetric(),
            zs_hopf: zs_reduced.delta4().symmetric(),
            reduced,
            zs_reduced,
        })
    }

    /// The certified positive roots of the Hopf polynomial (`zero_sideslip`: of the
    /// zero-sideslip one) of the data `v`, each refined towards relative width `width`: by
    /// [`positive_roots_windowed`] from Taylor expansions built from the reduced coefficients
    /// (degree at most 12, shifted cheaply and accurately), with [`value_at`] through the trim.
    ///
    /// The Hopf polynomial is even in P0, and so are its ingredients (the characteristic
    /// coefficients are invariant under the model's mirror symmetry, see [`IPoly::symmetric`],
    /// and det A is even): the roots are first isolated in `P0^2`
    /// ([`positive_roots_windowed_even`], half the degree), and in P0 only where that cannot
    /// decide.
    pub fn positive_roots(
        &self,
        v: &Values,
        zero_sideslip: bool,
        width: f64,
    ) -> Result<Vec<Bracket>, Uncertified> {
        let (global, reduced, which) = if zero_sideslip {
            (&self.zs_hopf, &self.zs_reduced, Criterion::ZsHopf)
        } else {
            (&self.hopf, &self.reduced, Criterion::Hopf)
        };
        let value = |x| value_at(v, which, x);
        let local = |x0| reduced.shift(x0).delta4();
        if let (Some(global_u), Some(reduced_u)) = (global.in_square(), reduced.in_square()) {
            let local_u = |u0| reduced_u.shift(u0).delta4();
            if let Ok(roots) =
                positive_roots_windowed_even(&global_u, &local_u, &local, &value, width)
            {
                return Ok(roots);
            }
        }
        positive_roots_windowed(global, &local, &value, width)
    }
}

/// Which criterion polynomial [`value_at`] encloses.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Criterion {
    /// det A.
    DetA,
    /// The jump polynomial.
    Jump,
    /// The pole polynomial.
    Poles,
    /// det A1 of the zero-sideslip trim.
    ZsDet,
    /// `det J5 det(A1)^2` at the zero-sideslip trim.
    ZsJump,
    /// `d det(A1)^2` at the zero-sideslip trim.
    ZsDDet,
    /// The Hopf polynomial of [`EnclosedHopf`].
    Hopf,
    /// The zero-sideslip Hopf polynomial of [`EnclosedHopf`].
    ZsHopf,
}

/// An enclosure of the value at `P0 = x` of a criterion polynomial of [`EnclosedPolys`],
/// computed through the trim (the same construction at one roll rate): the trim-level factors
/// are small, so this is much tighter near a root than the expanded polynomial's Horner sum.
pub fn value_at(v: &Values, which: Criterion, x: f64) -> I {
    type M1 = AtP0<I>;
    let mut m = AtP0(I::point(x));
    let t = &v.lifted;
    let value = match which {
        Criterion::DetA | Criterion::Jump | Criterion::Poles => {
            if which == Criterion::DetA {
                M1::univariate(&m.lifted(&t.det_a))
            } else {
                Unconstrained::new(&mut m, t).and_then(|u| {
                    let f = u.on_trim(&mut m, t, which == Criterion::Jump);
                    u.eliminate(&f)
                })
            }
        }
        Criterion::Hopf => {
            let den = m.lifted(&t.det_a);
            let num: [Da<I>; 4] = std::array::from_fn(|i| m.lifted(&t.trim[i]));
            hopf_in(&mut m, &Characteristic::get().c, &t.hopf().c, &num, &den).map(|r| r.delta4())
        }
        Criterion::ZsHopf => {
            let (num, den) = zs_trim_in(&mut m, t);
            hopf_in(
                &mut m,
                &Characteristic::get().zs_c,
                &t.hopf().zs_c,
                &num,
                &den,
            )
            .map(|r| r.delta4())
        }
        _ => ZeroSideslip::new(&mut m, t).map(|z| match which {
            Criterion::ZsDet => z.zs_det,
            Criterion::ZsJump => z.zs_jump,
            _ => z.zs_d_det,
        }),
    };
    value.map_or_else(|_| I::entire(), |s| s.0)
}

/// An enclosure of the trim condition `det(A)^2 p_dot` at `P0 = x` and `delta_a = da`, through
/// the trim (as [`value_at`]): the tight value of [`EnclosedPolys::trim_condition`] there.
pub fn trim_condition_at(v: &Values, x: f64, da: f64) -> I {
    let mut m = AtP0(I::point(x));
    Unconstrained::new(&mut m, &v.lifted).map_or_else(
        |_| I::entire(),
        |u| {
            let g = &u.trim_condition;
            g.c[..g.len]
                .iter()
                .rev()
                .fold(I::point(0.0), |acc, c| acc * I::point(da) + *c)
        },
    )
}

/// The unconstrained roll's criterion quantities at one roll rate, as polynomials in delta_a
/// (coefficients of `delta_a^0, delta_a^1, ...`), all cleared of det A as in
/// [`EnclosedPolys`]: what clearance evaluates over a box of data and a slab of roll rates.
#[derive(Clone, Debug)]
pub struct AtRollRate<T> {
    /// det A.
    pub det_a: T,
    /// The trim condition `det(A)^2 p_dot`.
    pub g: Vec<T>,
    /// `det J5 det(A)^2` on the trim.
    pub jump_at: Vec<T>,
}

/// [`AtRollRate`] of the data `v` at the roll rate `p0` (both in the numbers `T`).
pub fn at_roll_rate<T: Num>(v: &Values<T>, p0: T) -> Result<AtRollRate<T>, Uncertified> {
    let m = &mut AtP0(p0);
    let l = &v.lifted;
    let u = Unconstrained::new(m, l)?;
    let jump_at = u.on_trim(m, l, true);
    let coeffs = |d: &Da<T>| d.c[..d.len].to_vec();
    Ok(AtRollRate {
        det_a: u.det_a.0,
        g: coeffs(&u.trim_condition),
        jump_at: coeffs(&jump_at),
    })
}

/// The resultant in delta_a of the trim condition `g` and a trim quantity `f` (the enclosure of
/// [`crate::derivation::eliminate_aileron`] on numeric data, up to sign): `f` itself when
/// delta_a does not occur in `f` and `g` is linear in it; `g1^n f(-g0/g1)` for a linear `g`;
/// for a quadratic `g` and `f` (aileron yaw) Bezout's form
/// `(g2 f0 - g0 f2)^2 - (g2 f1 - g1 f2)(g1 f0 - g0 f1)`, divided by `det(A)^4`, which divides the
/// resultant of every aircraft with aileron yaw (Jacobi's identity for the 2x2 minors of
/// adj(A): the delta_a-parts of the trim numerators are columns of adj(A)).
pub fn eliminate<C: Coeff>(g: &[C], f: &[C], det_a: &C) -> Result<C, Uncertified> {
    let (Some(dg), Some(df)) = (g.len().checked_sub(1), f.len().checked_sub(1)) else {
        return Err(Uncertified::Degenerate);
    };
    let at = |p: &[C], i: usize| p.get(i).cloned().unwrap_or_else(C::zero);
    match (dg, df) {
        // f free of delta_a (no aileron yaw): the resultant is f itself, kept as it is (each
        // product by the exact 1 = g1^0 would widen it by an ulp).
        (1, 0) => Ok(f[0].clone()),
        (1, _) => {
            // g1^n f(-g0 / g1) = sum_i f_i (-g0)^i g1^(n - i).
            let (g0, g1) = (C::zero().sub(&g[0]), &g[1]);
            Ok((0..=df).fold(C::zero(), |acc, i| {
                acc.add(&f[i].mul(&g0.pow(i as u32)).mul(&g1.pow((df - i) as u32)))
            }))
        }
        // Every trim quantity of the criterion (det J5, d) is quadratic in delta_a with aileron
        // yaw; the factor det(A)^4 is established for that case only.
        (2, 2) => {
            let (g0, g1, g2) = (&g[0], &g[1], &g[2]);
            let (f0, f1, f2) = (at(f, 0), at(f, 1), at(f, 2));
            let a = g2.mul(&f0).sub(&g0.mul(&f2));
            let b = g2.mul(&f1).sub(&g1.mul(&f2));
            let c = g1.mul(&f0).sub(&g0.mul(&f1));
            let res = a.mul(&a).sub(&b.mul(&c));
            res.div_exact(&det_a.pow(4)).ok_or(Uncertified::Degenerate)
        }
        _ => Err(Uncertified::Degenerate),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every coefficient of two sets of criterion polynomials, as pairs (a missing one is an
    /// exact zero).
    fn polynomial_pairs(a: &EnclosedPolys, b: &EnclosedPolys) -> Vec<(I, I)> {
        let all = |e: &EnclosedPolys| -> Vec<IPoly> {
            let mut v = vec![e.det_a.clone(), e.jump.clone(), e.poles.clone()];
            v.extend([e.zs_det.clone(), e.zs_jump.clone(), e.zs_d_det.clone()]);
            v.extend(e.zs_trim.iter().cloned());
            for p in e
                .trim
                .iter()
                .chain([&e.trim_condition, &e.jump_at, &e.d_at])
            {
                v.extend((0..p.0.len().max(2)).map(|i| p.coeff(i)));
            }
            v
        };
        let zero = I::point(0.0);
        let (a, b) = (all(a), all(b));
        assert_eq!(a.len(), b.len());
        a.iter()
            .zip(&b)
            .flat_map(|(p, q)| {
                (0..p.0.len().max(q.0.len())).map(|i| {
                    let at = |d: &IPoly| d.0.get(i).copied().unwrap_or(zero);
                    (at(p), at(q))
                })
            })
            .collect()
    }

    /// The tape ([`EnclosedPolys::by_tape`]) and the general route ([`EnclosedPolys::new`])
    /// enclose the same exact coefficients of every criterion polynomial (every pair of
    /// enclosures overlaps), the tape's as tightly: on the paper's aircraft, none wider than
    /// 1e-12 relative to its magnitude, against which the general route's widest is given.
    #[test]
    fn the_tape_encloses_what_the_general_route_encloses() {
        for (name, ac) in [("A", Aircraft::a()), ("B", Aircraft::b())] {
            let de = 2f64.to_radians();
            let general = EnclosedPolys::new(&Values::of(&ac, de, 0.0)).unwrap();
            let tape = EnclosedPolys::by_tape(&Values::data(&ac), de)
                .expect("the tape covers the paper's aircraft")
                .unwrap();
            let relative = |c: I| c.width() / c.mag().max(f64::MIN_POSITIVE);
            let (mut widest_tape, mut widest_general) = (0.0f64, 0.0f64);
            for (t, g) in polynomial_pairs(&tape, &general) {
                assert!(
                    t.intersect(g).is_some(),
                    "{name}: tape {t:?} vs general {g:?}"
                );
                widest_tape = widest_tape.max(relative(t));
                widest_general = widest_general.max(relative(g));
            }
            println!(
                "{name}: widest relative width: tape {widest_tape:e}, general {widest_general:e}"
            );
            assert!(widest_tape <= 1e-12, "{name}: {widest_tape:e}");
        }
    }

    /// Every coefficient of every polynomial of two liftings, as pairs (a missing one is an
    /// exact zero).
    fn coefficient_pairs(a: &Lifted<I>, b: &Lifted<I>) -> Vec<(I, I)> {
        let all = |l: &Lifted<I>| -> Vec<Dense2<I>> {
            let mut v = vec![l.det_a.clone(), l.lateral.clone()];
            v.extend(l.trim.iter().cloned());
            v.extend(l.roll.iter().chain(&l.det_j5).chain(&l.d).cloned());
            v
        };
        let (a, b) = (all(a), all(b));
        assert_eq!(a.len(), b.len());
        let zero = I::point(0.0);
        let mut pairs = Vec::new();
        for (p, q) in a.iter().zip(&b) {
            for i in 0..p.0.len().max(q.0.len()) {
                let (pi, qi) = (p.coeff(i), q.coeff(i));
                for j in 0..pi.0.len().max(qi.0.len()) {
                    let at = |d: &Dense<I>| d.0.get(j).copied().unwrap_or(zero);
                    pairs.push((at(&pi), at(&qi)));
                }
            }
        }
        pairs
    }

    /// A sample's values through the sampler (the other parameters folded into the
    /// coefficients) and through the whole data enclose the same exact coefficients: every
    /// pair of enclosures overlaps, and the folded ones stay tight.
    #[test]
    fn sampler_values_enclose_what_the_whole_data_encloses() {
        let b = Aircraft::b();
        let data = Values::data(&b);
        let varying = [Param::Lp, Param::NBeta, Param::C, Param::MDeltaE];
        let de = 0.03;
        let sampler = Sampler::new(data, &varying, de, 0.0);
        let mut moved = data;
        let x: Vec<I> = varying
            .iter()
            .map(|p| {
                moved[p.index()] = data[p.index()] * I::point(1.03);
                moved[p.index()]
            })
            .collect();
        let pairs = coefficient_pairs(
            &sampler.values(&x).lifted,
            &Values::new(moved, de, 0.0).lifted,
        );
        assert!(pairs.len() > 50, "{} coefficients", pairs.len());
        for (folded, whole) in pairs {
            assert!(folded.intersect(whole).is_some(), "{folded:?} vs {whole:?}");
            let scale = 1.0 + folded.lo.abs().max(folded.hi.abs());
            assert!(folded.width() <= 1e-12 * scale, "{folded:?}");
        }
        // The sampler answers for the sample, not for the data it was built from.
        let pairs = coefficient_pairs(
            &sampler.values(&x).lifted,
            &Values::new(data, de, 0.0).lifted,
        );
        assert!(pairs.iter().any(|(f, w)| f.intersect(*w).is_none()));
    }
}
