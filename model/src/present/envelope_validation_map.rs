//! The map of `model envelope --validate --out`: at every grid point whether the native 6-DOF
//! agrees with the criterion (a jump predicted within the aileron limit and met, no jump
//! predicted and none met, or either disagreement), drawn with the cells of the envelope's maps.

use super::envelope_maps::{cells, missing};
use crate::envelope::Envelope;
use crate::plot::{Figure, PlotStyle, Rgb};

/// Colour of the points chosen but refused by the 6-DOF.
const REFUSED: Rgb = Rgb(110, 110, 110);
/// Colour of the analysed points left out of the sample.
const NOT_VALIDATED: Rgb = Rgb(215, 215, 215);
/// Colour of a jump the criterion missed.
const MISSED: Rgb = Rgb(120, 40, 150);

/// The map of agreement; `None` without `--validate`.
pub fn agreement(env: &Envelope, style: &PlotStyle) -> Option<Figure> {
    let sample = env.validate_sample?;
    let title = format!("{}: the criterion against the 6-DOF", env.aircraft);
    let mut f = cells(env, title, style, &|p| {
        let v = p.validation.as_ref();
        match v.map(|v| (v.predicted, v.agrees)) {
            Some((true, true)) => (Rgb::RED, "jump predicted, 6-DOF jumps".to_string(), 0),
            Some((false, true)) => (
                Rgb::GREEN,
                "no jump predicted, none in 6-DOF".to_string(),
                1,
            ),
            Some((true, false)) => (Rgb::ORANGE, "jump predicted, not in 6-DOF".to_string(), 2),
            Some((false, false)) => (MISSED, "6-DOF jumps, none predicted".to_string(), 3),
            None if p.validation_error.is_some() => {
                (REFUSED, "refused by the 6-DOF".to_string(), 4)
            }
            None if p.route.is_some() => (NOT_VALIDATED, "not in the sample".to_string(), 5),
            None => missing(p),
        }
    });
    f.note = format!(
        "{}; --validate-sample {sample}: every predicted jump within the limit and a seeded \
         sample of the other points",
        f.note
    );
    Some(f)
}
