//! The enclosed data of a box's aircraft at exact coordinates, without building the aircraft:
//! every parameter is an affine function of the coordinates with exact rational weights
//! ([`DataMap`]), evaluated over one common denominator and reduced once.

use crate::aircraft::{Aircraft, Param, Uncertain};
use crate::interval::I;
use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Zero};

/// The parameters of the aircraft [`super::at`] builds from a box, as affine functions of the
/// coordinates: the worst-case search's probes screen dozens of aircraft per sub-box by the
/// certified route, which needs only their data enclosed, and building each aircraft moved
/// coordinate by coordinate cost a reduction of growing fractions per parameter moved, more
/// than the certified route itself.
pub(super) struct DataMap {
    rows: Vec<Row>,
}

/// One parameter `(constant + sum_j weights_j x_j) / denom` (integers over the common
/// denominator of its constant and weights), or fixed at its enclosed value.
enum Row {
    Fixed(I),
    Affine {
        denom: BigInt,
        constant: BigInt,
        weights: Vec<(usize, BigInt)>,
    },
}

impl DataMap {
    /// The map of the box `params` around `base` (see [`super::split_box`]): the same values
    /// as moving `base` by each coordinate in turn ([`Uncertain::moved`]).
    pub(super) fn new(base: &Aircraft, params: &[Uncertain]) -> DataMap {
        // Each parameter as constant + sum_j w_j x_j, in exact rationals.
        let mut forms: Vec<(BigRational, Vec<(usize, BigRational)>)> = Param::ALL
            .iter()
            .map(|p| (base.exact(*p).clone(), Vec::new()))
            .collect();
        for (j, u) in params.iter().enumerate() {
            match &u.coefficient {
                None => {
                    forms[u.param.index()] = (BigRational::zero(), vec![(j, BigRational::one())])
                }
                Some(c) => {
                    for (p, slope) in &c.moves {
                        let (constant, weights) = &mut forms[p.index()];
                        *constant -= slope * &c.nominal;
                        weights.push((j, slope.clone()));
                    }
                }
            }
        }
        let rows = forms
            .into_iter()
            .map(|(constant, weights)| Row::of(constant, weights))
            .collect();
        DataMap { rows }
    }

    /// The enclosures of the data (in [`Param::ALL`] order, each bracketed by the two nearest
    /// doubles, as [`crate::certified::Values::data`] encloses them) of the aircraft at
    /// coordinates `x`, equal to those of [`super::at`]'s aircraft; `None` unless every
    /// coordinate is a dyadic rational (a double's value, as the probes' are).
    pub(super) fn data(&self, x: &[BigRational]) -> Option<[I; Param::COUNT]> {
        // x_j = n_j / 2^k_j.
        let shifts: Vec<u64> = x.iter().map(dyadic_shift).collect::<Option<_>>()?;
        let mut out = [I::point(0.0); Param::COUNT];
        for (o, row) in out.iter_mut().zip(&self.rows) {
            *o = row.at(x, &shifts);
        }
        Some(out)
    }
}

impl Row {
    /// The row of `constant + sum_j w_j x_j` over the common denominator of its rationals.
    fn of(constant: BigRational, weights: Vec<(usize, BigRational)>) -> Row {
        if weights.is_empty() {
            return Row::Fixed(I::from_q(&constant));
        }
        let denom = weights
            .iter()
            .fold(constant.denom().clone(), |l, (_, w)| l.lcm(w.denom()));
        let scaled = |q: &BigRational| q.numer() * (&denom / q.denom());
        Row::Affine {
            constant: scaled(&constant),
            weights: weights.iter().map(|(j, w)| (*j, scaled(w))).collect(),
            denom,
        }
    }

    /// The enclosed value at `x` (`x_j = numer_j / 2^shifts_j`).
    fn at(&self, x: &[BigRational], shifts: &[u64]) -> I {
        let (denom, constant, weights) = match self {
            Row::Fixed(v) => return *v,
            Row::Affine {
                denom,
                constant,
                weights,
            } => (denom, constant, weights),
        };
        let k = weights.iter().map(|(j, _)| shifts[*j]).max().unwrap_or(0);
        let mut numer = constant << k;
        for (j, w) in weights {
            numer += (w * x[*j].numer()) << (k - shifts[*j]);
        }
        I::from_q(&BigRational::new(numer, denom << k))
    }
}

/// `k` with `q = n / 2^k` (its reduced denominator a power of two), if there is one.
fn dyadic_shift(q: &BigRational) -> Option<u64> {
    let d = q.denom();
    let k = d.trailing_zeros().unwrap_or(0);
    (d.bits() == k + 1).then_some(k)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::certified::Values;
    use crate::clearance::{at, exact_coordinates, split_box};

    /// The map's enclosures are those of the aircraft built coordinate by coordinate, on the
    /// committed uncertain aircraft (parameters as coordinates) and on a nondimensional file
    /// with `ixz != 0` (coefficients moving several derivatives each), at the box's corners,
    /// centre and an inner point.
    #[test]
    fn the_map_encloses_the_data_of_the_aircraft_at_the_coordinates() {
        let fighter = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../aircraft/fighter_uncertain.toml");
        let boxes = [
            crate::clearance::tests::a_uncertain(),
            crate::aircraft::load(&fighter).expect("the committed uncertain fighter"),
        ];
        for aircraft in boxes {
            let (base, params) = split_box(&aircraft);
            assert!(!params.is_empty());
            let map = DataMap::new(&base, &params);
            for t in [0.0, 1.0, 0.5, 0.3172] {
                let x: Vec<f64> = params
                    .iter()
                    .map(|u| {
                        let b = I::from_q_pair(&u.lo, &u.hi);
                        b.lo + t * (b.hi - b.lo)
                    })
                    .collect();
                let x = exact_coordinates(&params, &x);
                let expected = Values::data(&at(&base, &params, &x));
                match map.data(&x) {
                    Some(data) => assert_eq!(data, expected, "{} at {t}", aircraft.name),
                    // Ends that are no double's value.
                    None => assert!(t == 0.0 || t == 1.0, "{} at {t}", aircraft.name),
                }
            }
        }
    }
}
