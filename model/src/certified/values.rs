//! The enclosures of an aircraft's data and controls ([`Values`]), and the sampler that lifts
//! many samples of a box in which only a few parameters vary ([`Sampler`], for Monte Carlo).

use super::compiled::{Parametric, Table};
use super::lifted::{Inputs, Lifted};
use super::num::Num;
use crate::aircraft::{Aircraft, Param};
use crate::algebra::MAX_SYMS;
use crate::equations::symbols;
use crate::interval::I;

/// The enclosures of an aircraft's data and controls (one per symbol of the model that has a
/// value: the parameters, delta_e and delta_r) and every parametric result lifted to them.
#[derive(Clone, Debug)]
pub struct Values<T = I> {
    pub(super) lifted: Lifted<T>,
}

impl Values<I> {
    /// The exact data of `aircraft` (each bracketed by the two nearest doubles) at elevator
    /// `delta_e_rad` and rudder `delta_r_rad` (both exact doubles).
    pub fn of(aircraft: &Aircraft, delta_e_rad: f64, delta_r_rad: f64) -> Values<I> {
        Values::new(Values::data(aircraft), delta_e_rad, delta_r_rad)
    }

    /// The exact data of `aircraft` in [`Param::ALL`] order, each bracketed by the two nearest
    /// doubles (exact ones stay points).
    pub fn data(aircraft: &Aircraft) -> [I; Param::COUNT] {
        std::array::from_fn(|i| I::from_q(aircraft.exact(Param::ALL[i])))
    }
}

impl<T: Num> Values<T> {
    /// Enclosures `params` (in [`Param::ALL`] order) of the data.
    pub fn new(params: [T; Param::COUNT], delta_e_rad: f64, delta_r_rad: f64) -> Values<T> {
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

/// [`Values`] for many samples of a box where only a few parameters vary (Monte Carlo): the
/// parametric results with every other parameter and the controls folded into their
/// coefficients once ([`Parametric::folded`]), so that lifting one sample is a pass over the
/// terms in the varying parameters only. The values enclose the same exact quantities as
/// [`Values::new`] on the whole data (each folded coefficient encloses its exact value).
#[derive(Debug)]
pub struct Sampler {
    pub(super) parametric: Parametric,
    pub(super) inputs: Inputs<I>,
    pub(super) varying: Vec<Param>,
}

impl Sampler {
    /// The data `params` (in [`Param::ALL`] order; the entries of `varying` are replaced by
    /// each sample's) at elevator `delta_e_rad` and rudder `delta_r_rad`.
    pub fn new(
        params: [I; Param::COUNT],
        varying: &[Param],
        delta_e_rad: f64,
        delta_r_rad: f64,
    ) -> Sampler {
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::aircraft::Aircraft;
    use crate::certified::dense::{Dense, Dense2};
    use crate::certified::lifted::Lifted;

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
