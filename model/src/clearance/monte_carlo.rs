//! Seeded Monte Carlo over the uncertainty box by the exact path, for comparison with the proof.
//!
//! ```
//! use model::aircraft::{Aircraft, Param, Uncertain};
//! use model::clearance::monte_carlo::run;
//!
//! // Aircraft A with n_beta in a box of zero width: every sample is A itself.
//! let mut a = Aircraft::a();
//! let n_beta = a.exact(Param::NBeta).clone();
//! a.uncertainty = vec![Uncertain { param: Param::NBeta, lo: n_beta.clone(), hi: n_beta }];
//! let mc = run(&a, 2f64.to_radians(), 2, 1, 1);
//! assert_eq!(mc.samples, 2);
//! assert!(mc.values.iter().all(|s| s.p0 == mc.min_p0 && s.p0.is_some()));
//! ```

use super::{critical, sample, split_box, Rng};
use crate::aircraft::Aircraft;
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
    /// Every sample, in order.
    #[serde(skip)]
    pub values: Vec<Sample>,
}

/// `n` seeded uniform samples of the box, each analysed exactly, on `threads` threads.
pub fn run(
    aircraft: &Aircraft,
    delta_e_rad: f64,
    n: usize,
    seed: u64,
    threads: usize,
) -> MonteCarlo {
    let (base, params) = split_box(aircraft);
    let threads = threads.max(1);
    let chunk = n.div_ceil(threads).max(1);
    let values: Vec<Sample> = std::thread::scope(|s| {
        let handles: Vec<_> = (0..threads)
            .map(|t| {
                let (base, params) = (&base, &params);
                s.spawn(move || {
                    let mut rng = Rng::new(seed);
                    // Skip to this thread's part of the one seeded sequence.
                    let first = (t * chunk).min(n);
                    let last = ((t + 1) * chunk).min(n);
                    for _ in 0..first {
                        sample(base, params, &mut rng);
                    }
                    (first..last)
                        .map(|_| {
                            let a = sample(base, params, &mut rng);
                            match critical(&a, delta_e_rad) {
                                Ok(Some(j)) => Sample {
                                    p0: Some(j.p0),
                                    abs_delta_a_deg: Some(j.delta_a_deg.abs()),
                                },
                                _ => Sample {
                                    p0: None,
                                    abs_delta_a_deg: None,
                                },
                            }
                        })
                        .collect::<Vec<_>>()
                })
            })
            .collect();
        handles
            .into_iter()
            .flat_map(|h| h.join().unwrap_or_default())
            .collect()
    });
    let min = |f: fn(&Sample) -> Option<f64>| values.iter().filter_map(f).reduce(f64::min);
    let fraction_within_limit = aircraft.limits.aileron_deg.map(|l| {
        values
            .iter()
            .filter(|s| s.abs_delta_a_deg.is_some_and(|d| d <= l))
            .count() as f64
            / values.len().max(1) as f64
    });
    MonteCarlo {
        samples: values.len(),
        min_p0: min(|s| s.p0),
        min_abs_delta_a_deg: min(|s| s.abs_delta_a_deg),
        fraction_within_limit,
        values,
    }
}
