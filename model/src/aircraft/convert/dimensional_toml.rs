//! The converted aircraft written as a dimensional principal-axis TOML file that loads back
//! exactly (`model convert`): terminating decimals in full, any other rational as `"p/q"`.

use super::super::{rational_to_f64, Aircraft, Param};
use super::Converted;
use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};
use std::fmt::Write;

impl Converted {
    /// The dimensional principal-axis TOML of this conversion, for `model convert`: principal
    /// moments in `[inertia]`, every derivative, the speed, and `aircraft`'s name, limits and
    /// validity. Values are exact: a terminating decimal is written out in full, any other
    /// rational as the string `"p/q"` with its approximate value in a comment, so that loading
    /// the output gives exactly the aircraft the body-axis file gives.
    pub fn to_toml(&self, aircraft: &Aircraft, file: &str) -> String {
        let mut out = String::new();
        // The path goes into a comment: no control character may end it.
        let file: String = file
            .chars()
            .map(|c| if c.is_control() { '?' } else { c })
            .collect();
        let precision = if self.rounded {
            "each value went through f64 (the ISA density and/or the cosine and sine of the\n\
             # tilt) and was rounded once to the nearest f64, so it is within about 1e-16\n\
             # relative of the exact conversion"
        } else {
            "exact (density given and ixz = 0: rational arithmetic throughout)"
        };
        let _ = writeln!(
            out,
            "# Converted by `model convert` from {file}: nondimensional body-axis coefficients\n\
             # to dimensional principal-axis derivatives (formulas in docs/nondimensional.md).\n\
             # Principal x axis tilt: {:.6} deg (positive: x_p below body x, forward and down).\n\
             # Flight: V = {} m/s, rho = {} kg/m^3 ({}).\n\
             # Precision: {precision}.\n",
            self.tilt_deg,
            self.speed_f64(),
            self.density,
            self.density_source,
        );
        let _ = writeln!(out, "name = {}\n", toml_string(&aircraft.name));
        let _ = writeln!(out, "[inertia]\n# Principal moments of inertia, kg m^2.");
        for (key, m) in ["ix", "iy", "iz"].iter().zip(&self.principal) {
            let _ = writeln!(out, "{key} = {}", toml_number(m));
        }
        let _ = writeln!(out, "\n[derivatives]\n# Principal axes, angles in rad.");
        let trim = [Param::Z0, Param::AlphaT];
        for p in Param::ALL.iter().skip(3) {
            if trim.contains(p) && !aircraft.trimmed {
                // Without a trim the file keeps the paper's convention (and its elevator).
                continue;
            }
            let _ = writeln!(
                out,
                "{} = {}   # {}",
                p.key(),
                toml_number(self.derivative(*p)),
                p.unit()
            );
        }
        let _ = writeln!(out, "\n[flight]\nspeed = {:?}   # m/s", aircraft.speed);
        let l = aircraft.limits;
        let limits: Vec<(&str, f64)> = [
            ("aileron", l.aileron_deg),
            ("elevator", l.elevator_deg),
            ("rudder", l.rudder_deg),
        ]
        .into_iter()
        .filter_map(|(k, v)| v.map(|v| (k, v)))
        .collect();
        if !limits.is_empty() {
            let _ = writeln!(out, "\n[limits]\n# Deflection limits, deg.");
            for (k, v) in limits {
                let _ = writeln!(out, "{k} = {v:?}");
            }
        }
        let v = aircraft.validity;
        let _ = writeln!(
            out,
            "\n[validity]\n# |alpha| and |beta| in which the linear aerodynamics are trusted, deg.\n\
             alpha_max = {:?}\nbeta_max = {:?}",
            v.alpha_max_deg, v.beta_max_deg
        );
        if !aircraft.uncertainty.is_empty() {
            let _ = writeln!(
                out,
                "\n[uncertainty]\n# Each coefficient's interval as its derivative's: the conversion of its ends."
            );
        }
        for u in &aircraft.uncertainty {
            let (lo, hi) = (toml_number(&u.lo), toml_number(&u.hi));
            match &u.coefficient {
                None => {
                    let _ = writeln!(out, "{} = [{lo}, {hi}]", u.param.key());
                }
                Some(c) => {
                    let moved: Vec<&str> = c.moves.iter().map(|(p, _)| p.key()).collect();
                    let _ = writeln!(
                        out,
                        "# {} = [{lo}, {hi}] moves {} together (ixz != 0), which a box per \
                         derivative cannot hold: `model clear` the nondimensional file for it.",
                        c.key,
                        moved.join(", ")
                    );
                }
            }
        }
        out
    }
}

/// A TOML basic string.
pub(super) fn toml_string(s: &str) -> String {
    let mut out = String::from("\"");
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            c if c.is_control() => {
                let _ = write!(out, "\\u{:04X}", u32::from(c));
            }
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

/// An exact rational as TOML the loader reads back exactly: a terminating decimal in full (always
/// with a decimal point), otherwise the string `"p/q"` followed by a comment with its value.
pub fn toml_number(q: &BigRational) -> String {
    match terminating_decimal(q) {
        Some(d) => d,
        None => format!(
            "\"{}/{}\"   # ~ {:e}",
            q.numer(),
            q.denom(),
            rational_to_f64(q)
        ),
    }
}

/// The decimal expansion of `q` if its denominator has no prime factor but 2 and 5.
fn terminating_decimal(q: &BigRational) -> Option<String> {
    let mut d = q.denom().clone();
    let (two, five) = (BigInt::from(2), BigInt::from(5));
    let (mut a, mut b) = (0usize, 0usize);
    while d.is_even() {
        d /= &two;
        a += 1;
    }
    while (&d % &five).is_zero() {
        d /= &five;
        b += 1;
    }
    if !d.is_one() {
        return None;
    }
    let k = a.max(b);
    let scaled = q.numer().abs() * num_traits::pow(BigInt::from(10), k) / q.denom();
    let digits = scaled.to_string();
    let (int, frac) = if k == 0 {
        (digits, "0".to_string())
    } else {
        let padded = format!("{digits:0>width$}", width = k + 1);
        let (i, f) = padded.split_at(padded.len() - k);
        (i.to_string(), f.to_string())
    };
    let sign = if q.is_negative() { "-" } else { "" };
    Some(format!("{sign}{int}.{frac}"))
}
