//! The criterion quantities of the two rolls in a [`Mode`]: the unconstrained roll (det A, the
//! trim, the trim condition, det J5 and d on the trim; Eqs 3-4 and step 8) and the
//! zero-sideslip roll (Eqs 32-35).

use super::compiled::Parametric;
use super::elimination::{eliminate, Coeff};
use super::isolate::Uncertified;
use super::lifted::Lifted;
use super::mode::{at_origin, Mode};
use crate::derivation::{TrimProducts, TRIM_DEGREE};
use std::cell::RefCell;

/// The criterion quantities of the unconstrained roll in a [`Mode`].
pub(super) struct Unconstrained<M: Mode> {
    pub(super) det_a: M::Coef,
    pub(super) det_a_value: M::Value,
    pub(super) trim: [M::Value; 4],
    pub(super) trim_condition: M::Value,
    /// Step 8's products on this trim (`trim / det_a_value`), shared by the trim condition,
    /// det J5 and d.
    pub(super) products: RefCell<TrimProducts<M::Value>>,
}

impl<M: Mode> Unconstrained<M> {
    /// det A, the trim and the trim condition; det J5 and d on the trim on demand
    /// ([`Unconstrained::on_trim`]).
    pub(super) fn new(m: &mut M, l: &Lifted<M::Num>) -> Result<Unconstrained<M>, Uncertified> {
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
    pub(super) fn on_trim(&self, m: &mut M, l: &Lifted<M::Num>, jump: bool) -> M::Value {
        let c = Parametric::get();
        let (groups, lifted) = if jump {
            (&c.det_j5, &l.det_j5)
        } else {
            (&c.d, &l.d)
        };
        let mut products = self.products.borrow_mut();
        m.clear_with(groups, lifted, &self.trim, &self.det_a_value, &mut products)
    }

    pub(super) fn eliminate(&self, f: &M::Value) -> Result<M::Coef, Uncertified> {
        eliminate(
            &M::in_aileron(&self.trim_condition),
            &M::in_aileron(f),
            &self.det_a,
        )
    }
}

/// The numerators of [alpha0, Q0, R0] of the zero-sideslip trim and their denominator det A1,
/// as values of the ring `m`.
pub(super) fn zs_trim_in<M: Mode>(m: &mut M, l: &Lifted<M::Num>) -> ([M::Value; 3], M::Value) {
    let l = l.zs();
    (
        std::array::from_fn(|i| m.lifted(&l.zs_trim[i])),
        m.lifted(&l.zs_det),
    )
}

/// The criterion quantities of the zero-sideslip roll in a [`Mode`].
pub(super) struct ZeroSideslip<M: Mode> {
    pub(super) zs_det: M::Coef,
    pub(super) zs_trim: [M::Coef; 3],
    pub(super) zs_jump: M::Coef,
    pub(super) zs_d_det: M::Coef,
}

impl<M: Mode> ZeroSideslip<M> {
    pub(super) fn new(m: &mut M, l: &Lifted<M::Num>) -> Result<ZeroSideslip<M>, Uncertified> {
        let c = Parametric::get();
        let (num, den) = zs_trim_in(m, l);
        let l = l.zs();
        let mut products = TrimProducts::new(m, &den, TRIM_DEGREE);
        let zs_jump = m.clear_with(&c.zs_det_j5, &l.zs_det_j5, &num, &den, &mut products);
        let zs_d_det = m.clear_with(&c.zs_d, &l.zs_d, &num, &den, &mut products);
        let zs_det = M::univariate(&den)?;
        let (zs_jump, zs_d_det) = (M::univariate(&zs_jump)?, M::univariate(&zs_d_det)?);
        let (zs_jump, zs_d_det) = if at_origin::<M>(&num) {
            without_origin_factor(&zs_jump, &zs_d_det, &zs_det)?
        } else {
            (zs_jump, zs_d_det)
        };
        Ok(ZeroSideslip {
            zs_jump,
            zs_d_det,
            zs_trim: [
                M::univariate(&num[0])?,
                M::univariate(&num[1])?,
                M::univariate(&num[2])?,
            ],
            zs_det,
        })
    }
}

/// The zero-sideslip jump and pole polynomials `zs_jump = det(A1)^2 det J5` and
/// `zs_d_det = det(A1)^2 d` of a zero-sideslip trim at the origin (every numerator of Eq. 35 is
/// a multiple of `m_delta_e delta_e`, so at `delta_e = 0` alpha0 = Q0 = R0 = 0), divided by
/// their common factor `det(A1)^2`: step 8 makes them `det(A1)^2 f(0)` there, whose double
/// roots at det A1's roots no isolation can separate, and which the exact path cancels
/// (`zs_jump / zs_d_det` is det K either way). The division is exact by that structure, so the
/// quotients' enclosures hold.
pub(super) fn without_origin_factor<C: Coeff>(
    zs_jump: &C,
    zs_d_det: &C,
    zs_det: &C,
) -> Result<(C, C), Uncertified> {
    let square = zs_det.pow(TRIM_DEGREE);
    let divide = |p: &C| p.div_exact(&square).ok_or(Uncertified::Degenerate);
    Ok((divide(zs_jump)?, divide(zs_d_det)?))
}
