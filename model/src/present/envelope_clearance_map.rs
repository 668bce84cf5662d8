//! The region map of `model envelope --uncertainty --out`: at every grid point the verdict of
//! its clearance against the aileron limit (cleared for every aircraft of the box, not cleared
//! with a counterexample, or undecided when the proof's budget ran out), drawn with the cells of
//! the envelope's maps.

use super::envelope_maps::{cells, missing};
use crate::clearance::Verdict;
use crate::envelope::Envelope;
use crate::plot::{Figure, PlotStyle, Rgb};

/// Colour of the undecided cells.
const UNDECIDED: Rgb = Rgb(240, 200, 60);

/// The map of the verdicts; `None` without `--uncertainty`.
pub fn clearance_regions(env: &Envelope, style: &PlotStyle) -> Option<Figure> {
    let spec = env.uncertainty.as_ref()?;
    let title = format!("{}: cleared against the aileron limit", env.aircraft);
    let mut f = cells(
        env,
        title,
        style,
        &|p| match p.clearance.as_ref().map(|c| c.verdict) {
            Some(Some(Verdict::Cleared)) => (Rgb::GREEN, "cleared (proven)".to_string(), 0),
            Some(Some(Verdict::NotCleared)) => {
                (Rgb::RED, "not cleared (counterexample)".to_string(), 1)
            }
            Some(Some(Verdict::UndecidedBudget)) => {
                (UNDECIDED, "undecided: budget ran out".to_string(), 2)
            }
            Some(Some(Verdict::Undecided)) => {
                (Rgb::ORANGE, "undecided: proof stuck".to_string(), 3)
            }
            Some(None) => (Rgb::BLUE, "no aileron limit".to_string(), 4),
            None => missing(p),
        },
    );
    f.note = format!("{}; box: --uncertainty {spec}", f.note);
    Some(f)
}
