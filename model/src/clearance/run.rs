//! `model clear` as a library call: for each elevator setting, the Monte Carlo and then the
//! proof, whose worst-case search starts from the Monte Carlo's lowest samples.

use super::monte_carlo::{self, MonteCarlo};
use super::{clear, ClearError, Clearance, Settings};
use crate::aircraft::Aircraft;
use serde::Serialize;

/// One elevator setting's clearance with its Monte Carlo comparison.
#[derive(Clone, Debug, Serialize)]
pub struct Run {
    /// The certified bounds and worst cases.
    #[serde(flatten)]
    pub clearance: Clearance,
    /// The Monte Carlo comparison.
    pub monte_carlo: MonteCarlo,
}

/// The clearance of `aircraft`'s box at each elevator deflection of `delta_e_rad`, with
/// `samples` Monte Carlo samples each (seeded by `seed`) and the roll-rate tolerance
/// `tolerance` (rad/s; the aileron's is ten times it in degrees). `progress` gets the fraction
/// done over all settings; `done(k, seconds)` is called when setting `k` is finished, with the
/// wall-clock seconds since the start (for an estimate of the rest; nothing here depends on it).
pub fn clear_each(
    aircraft: &Aircraft,
    delta_e_rad: &[f64],
    (samples, seed, tolerance): (usize, u64, f64),
    progress: &mut dyn FnMut(f64),
    done: &mut dyn FnMut(usize, f64),
) -> Result<Vec<Run>, ClearError> {
    let started = std::time::Instant::now();
    let n = delta_e_rad.len() as f64;
    let mut runs = Vec::with_capacity(delta_e_rad.len());
    for (k, de) in delta_e_rad.iter().enumerate() {
        // 0 threads: every core, on rayon's global pool (one set of threads for every run).
        let monte_carlo = monte_carlo::run(aircraft, *de, samples, seed, 0);
        let settings = Settings {
            delta_e_rad: *de,
            tolerance_p0: tolerance,
            tolerance_deg: 10.0 * tolerance,
            seed,
            candidates_at: monte_carlo.lowest_at.clone(),
            ..Default::default()
        };
        let clearance = clear(aircraft, &settings, &mut |f| progress((k as f64 + f) / n))?;
        runs.push(Run {
            clearance,
            monte_carlo,
        });
        done(k, started.elapsed().as_secs_f64());
    }
    Ok(runs)
}
