//! The grid of an envelope: a range `START:STOP:STEP` (or one value) of altitudes and one of
//! Mach numbers, checked before any work starts (reversed, zero step, too many points, altitudes
//! outside the standard atmosphere of the import).

use crate::jsbsim::atmosphere::standard;

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
        let values = (0..=steps as usize)
            .map(|i| start + i as f64 * step)
            .collect();
        Ok(Range { values })
    }
}

/// Altitudes (m) by Mach numbers: the points of an envelope.
#[derive(Clone, Debug, PartialEq)]
pub struct Grid {
    /// Geometric altitudes, m.
    pub altitudes_m: Range,
    /// Mach numbers.
    pub machs: Range,
}

impl Grid {
    /// The grid of the two ranges, or why it cannot be flown: more than [`MAX_POINTS`] points,
    /// an altitude outside the standard atmosphere, a Mach number not positive.
    pub fn new(altitudes_m: Range, machs: Range) -> Result<Grid, String> {
        let n = altitudes_m.values.len().saturating_mul(machs.values.len());
        if n > MAX_POINTS {
            return Err(format!(
                "{} altitudes by {} Mach numbers is {n} points, more than the {MAX_POINTS} an \
                 envelope computes (take larger steps)",
                altitudes_m.values.len(),
                machs.values.len()
            ));
        }
        let (lo, hi) = (
            altitudes_m.values[0],
            *altitudes_m.values.last().unwrap_or(&0.0),
        );
        if let Some(h) = [lo, hi].into_iter().find(|h| standard(*h).is_none()) {
            return Err(format!(
                "--altitude-m: {h} m is outside the standard atmosphere of the import (0 to \
                 86,000 m)"
            ));
        }
        if machs.values[0] <= 0.0 {
            return Err(format!(
                "--mach: {} is not a positive Mach number",
                machs.values[0]
            ));
        }
        Ok(Grid { altitudes_m, machs })
    }

    /// Every point (altitude m, Mach), altitude by altitude, Mach ascending within each.
    pub fn points(&self) -> Vec<(f64, f64)> {
        self.altitudes_m
            .values
            .iter()
            .flat_map(|h| self.machs.values.iter().map(move |m| (*h, *m)))
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
    }
}
