//! What `model envelope --validate` adds to the envelope's table and CSV: at every validated
//! point the criterion's prediction, the aileron steps the 6-DOF swept, where its settled roll
//! rate jumps and whether it agrees ([`crate::envelope::validation`]); the counts after the
//! table.

use super::numbers::fixed;
use crate::envelope::{Envelope, Point};

/// The table of the verdicts, after the envelope's (empty without `--validate`).
pub fn text(env: &Envelope) -> String {
    let Some(sample) = env.validate_sample else {
        return String::new();
    };
    let mut s = format!(
        "\nThe native 6-DOF's verdict (--validate: every point with a predicted jump within the \
         aileron limit, and a seeded {} % of the others; aileron steps of 1 deg, 10 s each):\n\n",
        fixed(100.0 * sample, 0)
    );
    s += "altitude_m   mach  predicted   swept_deg  6-DOF_jump_deg  mach_change  agrees\n";
    for p in &env.points {
        if let Some(e) = &p.validation_error {
            s += &format!(
                "{:>10}  {:>5}  6-DOF refused: {e}\n",
                fixed(p.altitude_m, 0),
                fixed(p.mach, 3)
            );
        }
        let Some(v) = &p.validation else { continue };
        s += &format!(
            "{:>10}  {:>5}  {:>9}  {:>10}  {:>14}  {:>11}  {}\n",
            fixed(p.altitude_m, 0),
            fixed(p.mach, 3),
            v.predicted,
            format!("{}-{}", fixed(v.swept_deg[0], 1), fixed(v.swept_deg[1], 1)),
            v.between_deg.map_or("none".to_string(), |[a, b]| {
                format!("{}-{}", fixed(a, 1), fixed(b, 1))
            }),
            fixed(v.mach_change, 3),
            v.agrees
        );
    }
    let count = |f: &dyn Fn(&Point) -> bool| env.points.iter().filter(|p| f(p)).count();
    let validated = |p: &Point| p.validation.is_some();
    s + &format!(
        "\n{} points validated ({} with a predicted jump within the limit): {} agree, {} \
         disagree; {} refused by the 6-DOF\n",
        count(&validated),
        count(&|p| p.validation.as_ref().is_some_and(|v| v.predicted)),
        count(&|p| p.validation.as_ref().is_some_and(|v| v.agrees)),
        count(&|p| p.validation.as_ref().is_some_and(|v| !v.agrees)),
        count(&|p| p.validation_error.is_some())
    )
}

/// The CSV columns `--validate` adds, with their units.
pub const CSV_HEADER: &str = ",validation_predicted,validation_swept_from_deg,\
     validation_swept_to_deg,validation_jumps,validation_between_lo_deg,\
     validation_between_hi_deg,validation_agrees,validation_mach_change";

/// The validation's cells of `p`'s CSV row, empty where the point was not validated.
pub fn csv_cells(p: &Point) -> Vec<String> {
    let Some(v) = &p.validation else {
        return vec![String::new(); CSV_HEADER.matches(',').count()];
    };
    let between = |i: usize| v.between_deg.map_or(String::new(), |b| b[i].to_string());
    vec![
        v.predicted.to_string(),
        v.swept_deg[0].to_string(),
        v.swept_deg[1].to_string(),
        v.jumps.to_string(),
        between(0),
        between(1),
        v.agrees.to_string(),
        v.mach_change.to_string(),
    ]
}
