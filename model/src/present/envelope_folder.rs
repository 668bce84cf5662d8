//! What `model envelope --out DIR` writes: envelope.csv (one row per grid point, every number),
//! summary.md, summary.json and the maps ([`super::envelope_maps`], SVG, PNG and the plotted
//! data as CSV; with `--uncertainty` the clearance's, with `--validate` the 6-DOF's agreement),
//! each file atomically.

use super::envelope::{cell, departure_kind, text};
use super::envelope_clearance::{csv_cells, CSV_HEADER};
use super::envelope_validation as validation;
use crate::envelope::Envelope;
use std::path::Path;

/// The CSV: one row per point, units in the header, empty where a number does not exist; with
/// `--uncertainty`, the clearance's columns after the others.
pub fn csv(env: &Envelope) -> String {
    let cleared = env.uncertainty.is_some();
    let mut s = String::from(
        "altitude_m,mach,speed_m_s,trimmed,alpha_deg,elevator_trim_deg,delta_e_deg,\
         critical_p0_rad_s,\
         critical_delta_a_deg,within_limits,aileron_limit_deg,margin_deg,first_departure,\
         first_departure_p0_rad_s,first_departure_delta_a_deg,first_departure_within_validity,\
         route",
    );
    if cleared {
        s += CSV_HEADER;
    }
    let validated = env.validate_sample.is_some();
    if validated {
        s += validation::CSV_HEADER;
    }
    s.push('\n');
    let num = |x: Option<f64>| x.map_or(String::new(), |v| v.to_string());
    for p in &env.points {
        let c = p.critical.as_ref();
        let d = p.first_departure.as_ref();
        let mut row = vec![
            p.altitude_m.to_string(),
            p.mach.to_string(),
            p.speed_m_s.to_string(),
            p.trimmed.to_string(),
            num(p.alpha_deg),
            num(p.elevator_trim_deg),
            num(p.delta_e_deg),
            num(c.map(|c| c.p0)),
            num(c.map(|c| c.delta_a_deg)),
            c.and_then(|c| c.within_limits)
                .map_or(String::new(), |w| w.to_string()),
            num(p.aileron_limit_deg),
            num(p.margin_deg),
            departure_kind(p).replace('-', ""),
            num(d.map(|d| d.p0)),
            num(d.map(|d| d.delta_a_deg)),
            d.and_then(|d| d.within_validity)
                .map_or(String::new(), |w| w.to_string()),
            p.route.unwrap_or("").to_string(),
        ];
        if cleared {
            row.extend(csv_cells(p));
        }
        if validated {
            row.extend(validation::csv_cells(p));
        }
        s += &row.join(",");
        s.push('\n');
    }
    s
}

/// summary.md: the table and the counts, with the maps.
pub fn markdown(env: &Envelope) -> String {
    let worst = env
        .points
        .iter()
        .filter_map(|p| p.margin_deg.map(|m| (m, p)))
        .max_by(|a, b| a.0.total_cmp(&b.0));
    let mut s = format!(
        "# Flight envelope: {} ({}), altitude x {}\n\n",
        env.aircraft,
        env.source,
        env.speed_axis.label()
    );
    s += &format!("Elevator: {}.\n\n", env.elevator);
    if let Some((m, p)) = worst {
        s += &format!(
            "Largest margin to the aileron limit (how far inside the stick's travel the \
             jump comes; negative: beyond it everywhere): {} deg at {} m, Mach {}, {} m/s.\n\n",
            cell(Some(m), 3),
            p.altitude_m,
            p.mach,
            p.speed_m_s
        );
    }
    s += "![critical aileron](critical_aileron.svg)\n\n![first departure](first_departure.svg)\n\n\
          ![critical roll rate](critical_roll_rate.svg)\n\n";
    if env.uncertainty.is_some() {
        s += "![clearance over the box](clearance.svg)\n\n";
    }
    if env.validate_sample.is_some() {
        s += "![the criterion against the 6-DOF](validation.svg)\n\n";
    }
    s + "```\n" + &text(env) + "```\n"
}

/// Writes the folder `dir`.
pub fn write_folder(dir: &Path, env: &Envelope, json: &str) -> Result<(), String> {
    crate::files::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let write = |name: &str, bytes: &[u8]| {
        let path = dir.join(name);
        crate::files::write_atomic(&path, bytes).map_err(|e| format!("{}: {e}", path.display()))
    };
    write("envelope.csv", csv(env).as_bytes())?;
    write("summary.md", markdown(env).as_bytes())?;
    write("summary.json", format!("{json}\n").as_bytes())?;
    let style = crate::plot::PlotStyle::default();
    let clearance = super::envelope_clearance_map::clearance_regions(env, &style);
    let agreement = super::envelope_validation_map::agreement(env, &style);
    let maps = super::envelope_maps::maps(env, &style)
        .into_iter()
        .chain(clearance.map(|f| ("clearance", f)))
        .chain(agreement.map(|f| ("validation", f)));
    for (stem, figure) in maps {
        crate::plot::render(&dir.join(stem), &figure, &style).map_err(|e| e.to_string())?;
    }
    Ok(())
}
