//! Seeded Monte Carlo over the uncertainty box by the certified route (the exact path where a
//! certificate fails), for comparison with the proof.
//!
//! ```
//! use model::aircraft::{Aircraft, Param, Uncertain};
//! use model::clearance::monte_carlo::run;
//!
//! // Aircraft A with n_beta in a box of zero width: every sample is A itself.
//! let mut a = Aircraft::a();
//! let n_beta = a.exact(Param::NBeta).clone();
//! a.uncertainty = vec![Uncertain::param(Param::NBeta, n_beta.clone(), n_beta)];
//! let mc = run(&a, 2f64.to_radians(), 2, 1, 1);
//! assert_eq!(mc.samples, 2);
//! assert!(mc.values.iter().all(|s| s.p0 == mc.min_p0 && s.p0.is_some()));
//! ```

use super::{clamp_exact, critical, exact_coordinates, split_box, Coordinate, Rng};
use crate::aircraft::{Aircraft, Param, Uncertain};
use crate::analysis::fast;
use crate::certified::{Sampler, Values};
use crate::interval::I;
use rayon::prelude::*;
use serde::Serialize;

/// One sample: its critical jump (None when its primary branch has none).
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct Sample {
    /// Critical jump roll rate, rad/s.
    pub p0: Option<f64>,
    /// |delta_a| at it, deg.
    pub abs_delta_a_deg: Option<f64>,
}

/// The Monte Carlo summary.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct MonteCarlo {
    /// Number of samples.
    pub samples: usize,
    /// Smallest critical jump roll rate among the samples (null if none has one).
    pub min_p0: Option<f64>,
    /// Smallest |delta_a| at a critical jump among the samples, deg.
    pub min_abs_delta_a_deg: Option<f64>,
    /// Fraction of samples whose critical jump lies within the aileron limit (null without one).
    pub fraction_within_limit: Option<f64>,
    /// Samples the certified route could not certify, answered by the exact path.
    pub exact_fallbacks: usize,
    /// Every sample, in order.
    #[serde(skip)]
    pub values: Vec<Sample>,
    /// Every sample's box coordinates (one per `[uncertainty]` entry, in its order), in the
    /// order of `values`: with them `samples.csv` lets `analyze` reproduce any sample.
    #[serde(skip)]
    pub draws: Vec<Vec<f64>>,
    /// The box coordinates (one per `[uncertainty]` entry) of the sample with the lowest
    /// critical roll rate and of the one with the lowest |delta_a| (once when they are the
    /// same), if any sample has a critical jump: candidates for the proof's worst case
    /// ([`super::Settings::candidates_at`]).
    #[serde(skip)]
    pub lowest_at: Vec<Vec<f64>>,
}

/// `n` seeded uniform samples of the box, each analysed by the certified route
/// ([`fast::critical`]: every critical roll rate bracketed to 1e-9 relative around the exact
/// one) and by the exact path where a certificate fails, on `threads` threads (0: rayon's
/// global pool, every core unless `RAYON_NUM_THREADS` says otherwise). The samples are the
/// first `n` of the seeded sequence, whatever the threads.
pub fn run(
    aircraft: &Aircraft,
    delta_e_rad: f64,
    n: usize,
    seed: u64,
    threads: usize,
) -> MonteCarlo {
    let sampled = SampledBox::of(aircraft, delta_e_rad);
    let mut rng = Rng::new(seed);
    let draws: Vec<Vec<f64>> = (0..n)
        .map(|_| {
            sampled
                .ends
                .iter()
                .map(|(b, _, _)| b.lo + rng.unit() * (b.hi - b.lo))
                .collect()
        })
        .collect();
    let one = |x: &Vec<f64>| sampled.analyse(x);
    let results: Vec<(Sample, bool)> = if threads == 1 {
        draws.iter().map(one).collect()
    } else if threads == 0 {
        // All cores: rayon's global pool, whose threads (and their allocator arenas) outlive
        // this call, so repeated runs do not pay for new ones.
        draws.par_iter().map(one).collect()
    } else {
        let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build();
        match pool {
            Ok(pool) => pool.install(|| draws.par_iter().map(one).collect()),
            Err(_) => draws.iter().map(one).collect(),
        }
    };
    summary(aircraft, results, draws)
}

/// The box of an aircraft as the samples see it: the exact aircraft's parts (for the exact
/// path's fallback), each coordinate's ends, and the certified route's sampler of the data the
/// coordinates move.
struct SampledBox {
    base: Aircraft,
    params: Vec<Uncertain>,
    /// Each coordinate's interval and its exact ends, enclosed.
    ends: Vec<(I, I, I)>,
    coordinates: Vec<Coordinate>,
    /// The parameters the coordinates move, each once (the sampler's varying data).
    varying: Vec<Param>,
    /// For each coordinate the indices in `varying` of those it moves.
    slots: Vec<Vec<usize>>,
    /// The data of the aircraft without its box.
    fixed: [I; Param::COUNT],
    sampler: Sampler,
    delta_e_rad: f64,
    /// The aileron range the primary branch is followed to, rad.
    bound: f64,
}

impl SampledBox {
    /// The box of `aircraft` at the elevator deflection `delta_e_rad` (rad).
    fn of(aircraft: &Aircraft, delta_e_rad: f64) -> SampledBox {
        let (base, params) = split_box(aircraft);
        let fixed = Values::data(&base);
        let ends: Vec<(I, I, I)> = params
            .iter()
            .map(|u| {
                (
                    I::from_q_pair(&u.lo, &u.hi),
                    I::from_q(&u.lo),
                    I::from_q(&u.hi),
                )
            })
            .collect();
        let coordinates: Vec<Coordinate> = params.iter().map(Coordinate::of).collect();
        let mut varying: Vec<Param> = Vec::new();
        let slots: Vec<Vec<usize>> = coordinates
            .iter()
            .map(|c| {
                c.params()
                    .into_iter()
                    .map(|p| match varying.iter().position(|v| *v == p) {
                        Some(i) => i,
                        None => {
                            varying.push(p);
                            varying.len() - 1
                        }
                    })
                    .collect()
            })
            .collect();
        let sampler = Sampler::new(fixed, &varying, delta_e_rad, 0.0);
        SampledBox {
            base,
            params,
            ends,
            coordinates,
            varying,
            slots,
            fixed,
            sampler,
            delta_e_rad,
            bound: aircraft.aileron_range(),
        }
    }

    /// The sample at the box coordinates `x` and whether it fell back to the exact path.
    fn analyse(&self, x: &[f64]) -> (Sample, bool) {
        let (params, delta_e_rad) = (&self.params, self.delta_e_rad);
        // A draw strictly inside the exact ends is its own exact value; one at an end is
        // clamped to the exact end, as the exact path's sample.
        let mut data: Vec<I> = self.varying.iter().map(|p| self.fixed[p.index()]).collect();
        let how = self.coordinates.iter().zip(&self.slots);
        for (((u, xi), (_, lo, hi)), (how, slots)) in params.iter().zip(x).zip(&self.ends).zip(how)
        {
            let xi = if *xi > lo.hi && *xi < hi.lo {
                I::point(*xi)
            } else {
                I::from_q(&clamp_exact(u, *xi))
            };
            match how {
                Coordinate::Param(_) => {
                    for i in slots {
                        data[*i] = xi;
                    }
                }
                Coordinate::Coefficient { nominal, moves } => {
                    for ((_, a), i) in moves.iter().zip(slots) {
                        data[*i] = data[*i] + *a * (xi - *nominal);
                    }
                }
            }
        }
        // The whole data of the sample, for the tape (which folds nothing); the sampler lifts
        // the varying part only should the tape not answer.
        let mut all = self.fixed;
        for (p, d) in self.varying.iter().zip(&data) {
            all[p.index()] = *d;
        }
        let lift = || self.sampler.values(&data);
        let (point, fell_back) =
            match fast::critical_of(&all, delta_e_rad, &lift, self.bound, fast::MAX_WIDTH) {
                Ok(c) => (c, false),
                Err(_) => {
                    let a = super::at(&self.base, params, &exact_coordinates(params, x));
                    let c = critical(&a, delta_e_rad)
                        .ok()
                        .flatten()
                        .map(|j| (j.p0, j.delta_a_rad));
                    (c, true)
                }
            };
        let sample = Sample {
            p0: point.map(|(p, _)| p),
            abs_delta_a_deg: point.map(|(_, da)| da.to_degrees().abs()),
        };
        (sample, fell_back)
    }
}

/// The Monte Carlo summary of the samples `results` (each with whether it fell back to the
/// exact path) drawn at `draws`, against `aircraft`'s aileron limit.
fn summary(aircraft: &Aircraft, results: Vec<(Sample, bool)>, draws: Vec<Vec<f64>>) -> MonteCarlo {
    let exact_fallbacks = results.iter().filter(|(_, f)| *f).count();
    let values: Vec<Sample> = results.into_iter().map(|(s, _)| s).collect();
    let min = |f: fn(&Sample) -> Option<f64>| values.iter().filter_map(f).reduce(f64::min);
    // The first sample attaining each minimum (in the seeded order).
    let mut lowest_at = [|s: &Sample| s.p0, |s: &Sample| s.abs_delta_a_deg]
        .into_iter()
        .filter_map(|f| {
            let m = min(f)?;
            values.iter().position(|s| f(s) == Some(m))
        })
        .collect::<Vec<usize>>();
    lowest_at.dedup();
    let lowest_at = lowest_at.into_iter().map(|i| draws[i].clone()).collect();
    // No samples, no fraction (0/0 is not a measurement).
    let fraction_within_limit = (aircraft.limits.aileron_deg)
        .filter(|_| !values.is_empty())
        .map(|l| {
            values
                .iter()
                .filter(|s| s.abs_delta_a_deg.is_some_and(|d| d <= l))
                .count() as f64
                / values.len() as f64
        });
    MonteCarlo {
        samples: values.len(),
        min_p0: min(|s| s.p0),
        min_abs_delta_a_deg: min(|s| s.abs_delta_a_deg),
        fraction_within_limit,
        exact_fallbacks,
        values,
        lowest_at,
        draws,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The samples are one seeded sequence: one thread, two, and rayon's global pool give the
    /// same samples in the same order, and the same summary.
    #[test]
    fn the_samples_do_not_depend_on_the_threads() {
        let a = super::super::tests::a_uncertain();
        let de = 2f64.to_radians();
        let one = run(&a, de, 40, 3, 1);
        assert_eq!(one.values.len(), 40);
        assert!(
            one.values.iter().all(|s| s.p0.is_some()),
            "{:?}",
            one.values
        );
        for threads in [2, 0] {
            assert_eq!(run(&a, de, 40, 3, threads), one, "{threads} threads");
        }
        assert_ne!(run(&a, de, 40, 4, 0), one, "another seed, other samples");
    }
}
