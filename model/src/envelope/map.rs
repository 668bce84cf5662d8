//! An envelope computed: every point of the grid in parallel (rayon), the model read once, with
//! the fraction done reported as the points finish.

use super::elevator::Elevator;
use super::grid::Grid;
use super::point::Point;
use super::uncertainty::Uncertainty;
use crate::jsbsim::import::Loaded;
use rayon::prelude::*;
use serde::Serialize;
use std::sync::atomic::{AtomicUsize, Ordering};

/// The envelope of one model: its points, altitude by altitude, Mach ascending within each.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct Envelope {
    /// The source as given.
    pub source: String,
    /// The aircraft's own name (a JSBSim model's `<fdm_config name>`; the source when the
    /// model has none): what the maps' titles say.
    pub aircraft: String,
    /// The trim and the elevator increment: `"trim at N g, increment D deg"`.
    pub elevator: String,
    /// Points without a trim (untrimmable or outside the atmosphere).
    pub untrimmed: usize,
    /// Trimmed points the certified route could not answer, so the exact path did.
    pub exact_fallbacks: usize,
    /// `--uncertainty` as given, when every point is a clearance of its box.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub uncertainty: Option<String>,
    /// `--validate-sample` as given, when the points were validated by the 6-DOF
    /// ([`super::validation`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub validate_sample: Option<f64>,
    /// Every grid point.
    pub points: Vec<Point>,
}

/// The name an envelope of `loaded` (read from `source`) gives its aircraft: the model's own,
/// else the source.
pub fn aircraft_name(loaded: &Loaded, source: &str) -> String {
    match loaded.model.name.trim() {
        "" => source.to_string(),
        name => name.to_string(),
    }
}

/// The envelope of `loaded` (named `source`) over `grid` at `elevator`; `progress` gets the
/// fraction done (from any thread).
pub fn envelope(
    loaded: &Loaded,
    source: &str,
    grid: &Grid,
    elevator: Elevator,
    progress: &(dyn Fn(f64) + Sync),
) -> Envelope {
    cleared_envelope(loaded, source, grid, (elevator, None), progress)
}

/// [`envelope`], and with `uncertainty` every point also the certified clearance of its box.
pub fn cleared_envelope(
    loaded: &Loaded,
    source: &str,
    grid: &Grid,
    (elevator, uncertainty): (Elevator, Option<&Uncertainty>),
    progress: &(dyn Fn(f64) + Sync),
) -> Envelope {
    let all = grid.points();
    let done = AtomicUsize::new(0);
    let points: Vec<Point> = all
        .par_iter()
        .map(|&(h, m)| {
            let p = Point::cleared_at(loaded, source, (h, m), elevator, uncertainty);
            let k = done.fetch_add(1, Ordering::Relaxed) + 1;
            progress(k as f64 / all.len() as f64);
            p
        })
        .collect();
    Envelope {
        source: source.to_string(),
        aircraft: aircraft_name(loaded, source),
        elevator: elevator.to_string(),
        untrimmed: points.iter().filter(|p| !p.trimmed).count(),
        exact_fallbacks: points.iter().filter(|p| p.route == Some("exact")).count(),
        uncertainty: uncertainty.map(|u| u.spec.clone()),
        validate_sample: None,
        points,
    }
}
