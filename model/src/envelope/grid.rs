//! The grid of an envelope: a range `START:STOP:STEP` (or one value) of altitudes and one of
//! speeds, Mach numbers or true airspeeds (the two ways `import jsbsim` takes a speed), checked
//! before any work starts (reversed, zero step, too many points, altitudes outside the standard
//! atmosphere of the import, speeds not positive).

use crate::jsbsim::atmosphere::standard;
use crate::jsbsim::condition::Speed;
use crate::jsbsim::digits::every_digit;
use serde::Serialize;

/// The most grid points one envelope computes.
pub const MAX_POINTS: usize = 1_000_000;

/// One axis of the grid: `START:STOP:STEP`, or a single value.
#[derive(Clone, Debug, PartialEq)]
pub struct Range {
    /// The values, ascending.
    pub values: Vec<f64>,
}

impl Range {
    /// Parses `text` given for option `flag`: `START:STOP:STEP` with `START <= STOP` and
    /// `STEP > 0` (STOP is included when it lies on the grid, to 1e-9 of a step), or one number.
    pub fn parse(text: &str, flag: &str) -> Result<Range, String> {
        let bad = |why: &str| {
            format!("{flag} {text}: {why} (expected START:STOP:STEP with START <= STOP and STEP > 0, or one value)")
        };
        let parts: Vec<f64> = text
            .split(':')
            .map(|x| x.trim().parse::<f64>().ok().filter(|v| v.is_finite()))
            .collect::<Option<_>>()
            .ok_or_else(|| bad("not finite numbers"))?;
        let (start, stop, step) = match parts[..] {
            [v] => return Ok(Range { values: vec![v] }),
            [a, b, s] => (a, b, s),
            _ => return Err(bad("not one or three numbers")),
        };
        if start > stop {
            return Err(bad("reversed: START is above STOP"));
        }
        if step <= 0.0 {
            return Err(bad("the step is not positive"));
        }
        let steps = ((stop - start) / step + 1e-9).floor();
        if steps.is_nan() || steps >= MAX_POINTS as f64 {
            return Err(bad(&format!("more than {MAX_POINTS} points")));
        }
        let parts: Vec<&str> = text.split(':').map(str::trim).collect();
        let on_grid = decimal_grid(parts[0], parts[2]);
        let values = (0..=steps as usize)
            .map(|i| {
                on_grid.map_or(start + i as f64 * step, |(a, d, scale)| {
                    (a + i as f64 * d) / scale
                })
            })
            .collect();
        Ok(Range { values })
    }
}

/// The grid of `START` and `STEP` written as plain decimals, as integers of their finest
/// decimal place and that place's scale: the grid's `i`-th value `(a + i d) / scale` is then the
/// double nearest the decimal the user means (0.3:0.95:0.01 steps through 0.83, not
/// 0.8300000000000001, which `0.3 + 53 * 0.01` gives), because the integers and the scale are
/// exact in f64 and the division rounds once. `None` for exponents or more than 15 places.
fn decimal_grid(start: &str, step: &str) -> Option<(f64, f64, f64)> {
    let places = |t: &str| {
        let plain = t
            .bytes()
            .all(|b| b.is_ascii_digit() || b == b'.' || b == b'-' || b == b'+');
        plain.then(|| t.split_once('.').map_or(0, |(_, f)| f.len()))
    };
    let p = places(start)?.max(places(step)?);
    if p > 15 {
        return None;
    }
    let scale = 10f64.powi(p as i32);
    let as_integer = |t: &str| t.replacen('.', "", 1).parse::<i64>().ok();
    let shift = |t: &str| Some(as_integer(t)? as f64 * 10f64.powi((p - places(t)?) as i32));
    let (a, d) = (shift(start)?, shift(step)?);
    (a.abs() < 2f64.powi(53) && d.abs() < 2f64.powi(53)).then_some((a, d, scale))
}

/// What the speed axis of a grid holds: Mach numbers (`--mach`) or true airspeeds in m/s
/// (`--speed`). Serialised as the name of the points' field the grid steps over.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum SpeedAxis {
    /// Mach numbers: the points' `mach`.
    #[serde(rename = "mach")]
    Mach,
    /// True airspeeds, m/s: the points' `speed_m_s`.
    #[serde(rename = "speed_m_s")]
    TrueAirspeed,
}

impl SpeedAxis {
    /// The command line's option for the axis.
    pub fn flag(self) -> &'static str {
        match self {
            SpeedAxis::Mach => "--mach",
            SpeedAxis::TrueAirspeed => "--speed",
        }
    }

    /// The axis in words, with its unit: what the maps' axes say.
    pub fn label(self) -> &'static str {
        match self {
            SpeedAxis::Mach => "Mach",
            SpeedAxis::TrueAirspeed => "true airspeed, m/s",
        }
    }

    /// The values in the plural, for messages.
    fn plural(self) -> &'static str {
        match self {
            SpeedAxis::Mach => "Mach numbers",
            SpeedAxis::TrueAirspeed => "true airspeeds",
        }
    }

    /// The flight condition's speed of value `v` on this axis.
    pub fn speed(self, v: f64) -> Speed {
        match self {
            SpeedAxis::Mach => Speed::Mach(v),
            SpeedAxis::TrueAirspeed => Speed::True(v),
        }
    }

    /// The value on this axis of a point at Mach `mach` and true airspeed `speed_m_s`.
    pub fn of(self, mach: f64, speed_m_s: f64) -> f64 {
        match self {
            SpeedAxis::Mach => mach,
            SpeedAxis::TrueAirspeed => speed_m_s,
        }
    }
}

/// Altitudes (m) by speeds (Mach numbers or true airspeeds): the points of an envelope.
#[derive(Clone, Debug, PartialEq)]
pub struct Grid {
    /// Geometric altitudes, m.
    pub altitudes_m: Range,
    /// What `speeds` holds.
    pub axis: SpeedAxis,
    /// Mach numbers or true airspeeds (m/s), as `axis` says.
    pub speeds: Range,
}

impl Grid {
    /// The grid of altitudes by Mach numbers: [`Grid::over`] [`SpeedAxis::Mach`].
    pub fn new(altitudes_m: Range, machs: Range) -> Result<Grid, String> {
        Grid::over(altitudes_m, SpeedAxis::Mach, machs)
    }

    /// The grid of the two ranges, `speeds` on `axis`, or why it cannot be flown: more than
    /// [`MAX_POINTS`] points, an altitude outside the standard atmosphere, a speed not
    /// positive (at every altitude a positive true airspeed is a positive Mach number and back,
    /// so the import takes every point's speed then).
    pub fn over(altitudes_m: Range, axis: SpeedAxis, speeds: Range) -> Result<Grid, String> {
        let n = altitudes_m.values.len().saturating_mul(speeds.values.len());
        if n > MAX_POINTS {
            return Err(format!(
                "{} altitudes by {} {} is {n} points, more than the {MAX_POINTS} an envelope \
                 computes (take larger steps)",
                altitudes_m.values.len(),
                speeds.values.len(),
                axis.plural()
            ));
        }
        let (lo, hi) = (
            altitudes_m.values[0],
            *altitudes_m.values.last().unwrap_or(&0.0),
        );
        if let Some(h) = [lo, hi].into_iter().find(|h| standard(*h).is_none()) {
            return Err(format!(
                "--altitude-m: {} m is outside the standard atmosphere of the import (0 to \
                 86,000 m)",
                every_digit(h)
            ));
        }
        if speeds.values[0] <= 0.0 {
            let what = match axis {
                SpeedAxis::Mach => "a positive Mach number",
                SpeedAxis::TrueAirspeed => "a positive true airspeed, m/s",
            };
            return Err(format!(
                "{}: {} is not {what}",
                axis.flag(),
                every_digit(speeds.values[0])
            ));
        }
        Ok(Grid {
            altitudes_m,
            axis,
            speeds,
        })
    }

    /// Every point (altitude m, value on the speed axis), altitude by altitude, speed
    /// ascending within each.
    pub fn pairs(&self) -> Vec<(f64, f64)> {
        self.altitudes_m
            .values
            .iter()
            .flat_map(|h| self.speeds.values.iter().map(move |v| (*h, *v)))
            .collect()
    }

    /// Every point (altitude m, speed) in the order of [`Grid::pairs`].
    pub fn points(&self) -> Vec<(f64, Speed)> {
        self.pairs()
            .into_iter()
            .map(|(h, v)| (h, self.axis.speed(v)))
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_range_includes_its_stop_on_the_grid() {
        let r = Range::parse("0.3:0.95:0.05", "--mach").unwrap();
        assert_eq!(r.values.len(), 14);
        assert!((r.values[13] - 0.95).abs() < 1e-12);
        assert_eq!(
            Range::parse("6096", "--altitude-m").unwrap().values,
            [6096.0]
        );
    }

    /// Every value of a decimal grid is the double nearest its decimal, as Rust parses it.
    #[test]
    fn a_decimal_range_steps_through_the_decimals_written() {
        let r = Range::parse("0.3:0.95:0.01", "--mach").unwrap();
        assert_eq!(r.values.len(), 66);
        for (i, v) in r.values.iter().enumerate() {
            let written: f64 = format!("0.{:02}", 30 + i).parse().unwrap();
            assert_eq!(*v, written, "the value {i}");
        }
        let r = Range::parse("-1.5:2:0.25", "--x").unwrap();
        assert_eq!(r.values[7], 0.25);
        let r = Range::parse("1e2:3e2:50", "--x").unwrap();
        assert_eq!(r.values, [100.0, 150.0, 200.0, 250.0, 300.0]);
    }

    #[test]
    fn bad_ranges_are_refused_naming_why() {
        let why = |t: &str| Range::parse(t, "--mach").unwrap_err();
        assert!(
            why("0.9:0.3:0.1").contains("reversed"),
            "{}",
            why("0.9:0.3:0.1")
        );
        assert!(why("0.3:0.9:0").contains("step"));
        assert!(why("0:1:1e-9").contains("more than"));
        assert!(why("0:nan:1").contains("finite"));
        assert!(why("0:1").contains("three"));
        let r = |t: &str| Range::parse(t, "--altitude-m").unwrap();
        let grid = |h: &str, m: &str| Grid::new(r(h), r(m));
        assert!(grid("-500:0:500", "0.5")
            .unwrap_err()
            .contains("atmosphere"));
        assert!(grid("0:90000:1000", "0.5")
            .unwrap_err()
            .contains("atmosphere"));
        assert!(grid("0:2000:1", "0.1:1:0.0001")
            .unwrap_err()
            .contains("points"));
        assert!(grid("0", "0:1:0.5").unwrap_err().contains("Mach"));
        assert_eq!(grid("0:1000:500", "0.5:0.6:0.1").unwrap().points().len(), 6);
        let speeds = |v: &str| Grid::over(r("0:1000:1000"), SpeedAxis::TrueAirspeed, r(v));
        let e = speeds("0:100:50").unwrap_err();
        assert!(
            e.starts_with("--speed: 0 is not a positive true airspeed"),
            "{e}"
        );
        let e = speeds("1:600000:1").unwrap_err();
        assert!(e.contains("true airspeeds"), "{e}");
        let points = speeds("100:150:50").unwrap().points();
        assert_eq!(points[1], (0.0, Speed::True(150.0)));
        assert_eq!(points.len(), 4);
        let e = grid("1e300", "0.5").unwrap_err();
        assert!(e.contains("1e300 m"), "{e}");
    }
}
