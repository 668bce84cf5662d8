//! The Hopf polynomials of one aircraft without aileron yaw, enclosed ([`EnclosedHopf`]): the
//! characteristic coefficients at the trim, cleared and reduced, and Delta4 built from them by
//! the routines of the exact path; their positive roots refined through Taylor expansions.

use super::at_roll_rate::{value_at, Criterion};
use super::characteristic::{hopf_in, Reduced};
use super::compiled::Characteristic;
use super::dense::IPoly;
use super::isolate::{positive_roots_windowed, positive_roots_windowed_even, Bracket, Uncertified};
use super::mode::InP0;
use super::rolls::{zs_trim_in, Unconstrained};
use super::values::Values;

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
    pub(super) reduced: Reduced<IPoly>,
    pub(super) zs_reduced: Reduced<IPoly>,
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
