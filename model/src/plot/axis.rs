//! Axis coordinates for plotters with our own ticks: "nice" linear ticks (1, 2, 5 x 10^k) and
//! the asinh scale of the det K plots (Figs 7, 8, 11), ticks at 0 and +-unit x 10^k.

use super::spec::{Axis, Scale};
use plotters::coord::ranged1d::{KeyPointHint, NoDefaultFormatting, Ranged, ValueFormatter};
use std::ops::Range;

/// A plotters coordinate for one [`Axis`].
#[derive(Clone, Debug)]
pub(crate) struct Coord {
    lo: f64,
    hi: f64,
    scale: Scale,
}

impl Coord {
    pub(crate) fn new(axis: &Axis) -> Coord {
        Coord {
            lo: axis.lo,
            hi: axis.hi,
            scale: axis.scale,
        }
    }
}

impl Ranged for Coord {
    type FormatOption = NoDefaultFormatting;
    type ValueType = f64;

    fn map(&self, v: &f64, limit: (i32, i32)) -> i32 {
        let (a, b) = (self.scale.forward(self.lo), self.scale.forward(self.hi));
        let t = (self.scale.forward(*v) - a) / (b - a);
        let px = f64::from(limit.0) + t * f64::from(limit.1 - limit.0);
        px.round().clamp(-1e7, 1e7) as i32
    }

    fn key_points<Hint: KeyPointHint>(&self, hint: Hint) -> Vec<f64> {
        ticks(self.lo, self.hi, self.scale, hint.max_num_points().max(2))
    }

    fn range(&self) -> Range<f64> {
        self.lo..self.hi
    }
}

impl ValueFormatter<f64> for Coord {
    fn format(v: &f64) -> String {
        format!("{v}")
    }
}

/// Tick positions: for a linear axis multiples of a 1-2-5 step giving at most `max` ticks; for
/// an asinh axis 0 and +-unit * 10^k (every other decade when there are too many).
pub fn ticks(lo: f64, hi: f64, scale: Scale, max: usize) -> Vec<f64> {
    let (lo, hi) = (lo.min(hi), lo.max(hi));
    match scale {
        Scale::Linear => {
            let step = nice_step(hi - lo, max);
            if !(step > 0.0 && step.is_finite()) {
                return vec![lo, hi];
            }
            let first = (lo / step).ceil() as i64;
            let last = (hi / step).floor() as i64;
            (first..=last).map(|k| clean(k as f64 * step)).collect()
        }
        Scale::Asinh { unit } => {
            let mut decades: Vec<f64> = Vec::new();
            let mut v = unit;
            while v <= hi.abs().max(lo.abs()) && decades.len() < 40 {
                decades.push(v);
                v *= 10.0;
            }
            let mut stride = 1;
            while 2 * decades.len().div_ceil(stride) + 1 > max.max(3) {
                stride += 1;
            }
            let mut out: Vec<f64> = Vec::new();
            for d in decades.iter().step_by(stride).rev() {
                if -d >= lo {
                    out.push(-d);
                }
            }
            if lo <= 0.0 && hi >= 0.0 {
                out.push(0.0);
            }
            for d in decades.iter().step_by(stride) {
                if *d <= hi {
                    out.push(*d);
                }
            }
            out
        }
    }
}

/// The 1-2-5 x 10^k step giving at most `max` intervals over `span`.
pub fn nice_step(span: f64, max: usize) -> f64 {
    if !(span > 0.0 && span.is_finite()) {
        return 0.0;
    }
    let raw = span / max.max(1) as f64;
    let mag = 10f64.powf(raw.log10().floor());
    for m in [1.0, 2.0, 2.5, 5.0, 10.0] {
        if m * mag >= raw {
            return m * mag;
        }
    }
    10.0 * mag
}

/// Rounds away the floating-point noise of `k * step` (e.g. 0.30000000000000004).
fn clean(v: f64) -> f64 {
    if v == 0.0 {
        return 0.0;
    }
    let digits = 12 - v.abs().log10().floor() as i32;
    let f = 10f64.powi(digits.clamp(-300, 300));
    (v * f).round() / f
}

/// Tick label for ticks from [`ticks`] with at most `max` ticks: as few decimals as the tick
/// spacing needs; large and small magnitudes of an asinh axis as `1e4`, `-1e-2`.
pub fn label(v: f64, axis: &Axis, max: usize) -> String {
    if v == 0.0 {
        return "0".into();
    }
    match axis.scale {
        Scale::Asinh { .. } => {
            let e = v.abs().log10().round() as i32;
            let m = v.abs() / 10f64.powi(e);
            let sign = if v < 0.0 { "\u{2212}" } else { "" };
            if (m - 1.0).abs() < 1e-9 && !(-1..=3).contains(&e) {
                format!("{sign}1e{e}")
            } else {
                format!("{sign}{}", clean(v.abs()))
            }
        }
        Scale::Linear => {
            let step = nice_step((axis.hi - axis.lo).abs(), max);
            let mut decimals = 0;
            while decimals < 12
                && (step * 10f64.powi(decimals) - (step * 10f64.powi(decimals)).round()).abs()
                    > 1e-6
            {
                decimals += 1;
            }
            let s = format!("{:.*}", decimals as usize, v);
            // A typographic minus sign.
            match s.strip_prefix('-') {
                Some(rest) => format!("\u{2212}{rest}"),
                None => s,
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn linear_ticks_are_round_numbers() {
        assert_eq!(
            ticks(-4.3, 8.1, Scale::Linear, 10),
            vec![-4.0, -2.0, 0.0, 2.0, 4.0, 6.0, 8.0]
        );
        assert_eq!(
            ticks(0.0, 1.0, Scale::Linear, 5),
            vec![0.0, 0.2, 0.4, 0.6, 0.8, 1.0]
        );
        let a = Axis::linear("x", 0.0, 1.0);
        assert_eq!(label(0.6000000000000001, &a, 5), "0.6");
        assert_eq!(label(-2.0, &Axis::linear("x", -5.0, 5.0), 10), "\u{2212}2");
        assert_eq!(label(0.25, &Axis::linear("x", 0.0, 1.0), 4), "0.25");
    }

    #[test]
    fn asinh_ticks_are_decades() {
        let s = Scale::Asinh { unit: 10.0 };
        assert_eq!(
            ticks(-1e4, 1e4, s, 20),
            vec![-1e4, -1e3, -100.0, -10.0, 0.0, 10.0, 100.0, 1e3, 1e4]
        );
        assert_eq!(ticks(-1e4, 1e4, s, 5), vec![-1e3, -10.0, 0.0, 10.0, 1e3]);
        assert!((s.inverse(s.forward(123.0)) - 123.0).abs() < 1e-12);
        let a = Axis {
            label: "y".into(),
            lo: -1e5,
            hi: 1e5,
            scale: s,
        };
        assert_eq!(label(1e4, &a, 10), "1e4");
        assert_eq!(label(-100.0, &a, 10), "\u{2212}100");
    }
}
