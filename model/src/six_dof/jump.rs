//! The rule that calls a jump in a sweep of aileron steps, the same for every model it judges
//! (the 7th-order model and the 6-DOF in `model validate`, JSBSim's runs in the oracle
//! `tests/oracle/jsbsim_six_dof.py`, whose rule this is): of the rises of the settled roll rate
//! between neighbouring steps, the steepest is a jump when its slope exceeds [`RATIO`] times
//! the median slope of the sweep and [`MIN_SLOPE`] rad/s per deg of aileron. A smooth plateau
//! rises at about its median slope everywhere; a fold makes one step of the sweep rise by the
//! gap between the branches.

/// How many times steeper than the sweep's median rise a jump is.
pub const RATIO: f64 = 3.0;

/// The smallest slope of a jump, rad/s per deg of aileron.
pub const MIN_SLOPE: f64 = 0.3;

/// A jump found in a sweep.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Jump {
    /// The two neighbouring steps it lies between, deg.
    pub between_deg: (f64, f64),
    /// Its slope, rad/s per deg.
    pub slope: f64,
    /// The sweep's median |slope|, rad/s per deg.
    pub median: f64,
}

/// The jump of the sweep `(aileron_deg, settled |p|)` in increasing aileron, if the rule calls
/// one; `None` with fewer than three steps.
pub fn find_jump(aileron_deg: &[f64], p: &[f64]) -> Option<Jump> {
    if aileron_deg.len() < 3 || p.len() != aileron_deg.len() {
        return None;
    }
    let slopes: Vec<(f64, usize)> = (1..p.len())
        .map(|k| ((p[k] - p[k - 1]) / (aileron_deg[k] - aileron_deg[k - 1]), k))
        .collect();
    let mut mags: Vec<f64> = slopes.iter().map(|(s, _)| s.abs()).collect();
    mags.sort_by(f64::total_cmp);
    let median = mags[mags.len() / 2];
    let &(slope, k) = slopes
        .iter()
        .max_by(|a, b| a.0.abs().total_cmp(&b.0.abs()))?;
    (slope.abs() > (RATIO * median).max(MIN_SLOPE)).then_some(Jump {
        between_deg: (aileron_deg[k - 1], aileron_deg[k]),
        slope,
        median,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_smooth_plateau_has_no_jump_and_a_step_has_one() {
        let deg: Vec<f64> = (0..10).map(f64::from).collect();
        let smooth: Vec<f64> = deg.iter().map(|d| 0.1 * d + 0.002 * d * d).collect();
        assert_eq!(find_jump(&deg, &smooth), None);
        let mut step = smooth.clone();
        step.iter_mut().skip(6).for_each(|p| *p += 2.0);
        let j = find_jump(&deg, &step).unwrap();
        assert_eq!(j.between_deg, (5.0, 6.0));
        assert_eq!(find_jump(&deg[..2], &step[..2]), None);
    }
}

/// The rule on the 7th-order model of the paper's aircraft A, whose fold the analysis gives
/// exactly: a sweep that stops 1 deg before the critical aileron has no jump; one that goes
/// 3 deg past it has one, between steps around or just past the fold (the step's transient
/// must carry the roll past the fold, so the jump lies at or beyond it).
#[cfg(test)]
mod known_answers {
    use super::find_jump;
    use crate::aircraft::Aircraft;
    use crate::analysis::analyze;
    use crate::simulation::{simulate, Model, SimSettings};

    fn plateau(ac: &Aircraft, delta_e: f64, sign: f64, degs: &[f64]) -> Vec<f64> {
        degs.iter()
            .map(|d| {
                let s = SimSettings::step(Model::SeventhOrder, delta_e, sign * d.to_radians());
                simulate(ac, &s).unwrap().steady(2.0).p_mean.abs()
            })
            .collect()
    }

    #[test]
    fn the_rule_finds_no_jump_before_the_fold_of_aircraft_a_and_one_past_it() {
        let ac = Aircraft::a();
        let delta_e = 2f64.to_radians();
        let critical = analyze(&ac, delta_e).unwrap().critical.unwrap().delta_a_deg;
        let (sign, c) = (critical.signum(), critical.abs());
        let before: Vec<f64> = (0..)
            .map(|k| 1.0 + 0.5 * f64::from(k))
            .take_while(|d| *d <= c - 1.0)
            .collect();
        assert!(before.len() >= 3, "{c}");
        assert_eq!(
            find_jump(&before, &plateau(&ac, delta_e, sign, &before)),
            None
        );
        let past: Vec<f64> = (0..)
            .map(|k| 1.0 + 0.5 * f64::from(k))
            .take_while(|d| *d <= c + 3.0)
            .collect();
        let j =
            find_jump(&past, &plateau(&ac, delta_e, sign, &past)).expect("a jump past the fold");
        assert!(
            j.between_deg.1 >= c && j.between_deg.0 <= c + 2.5,
            "{j:?} vs fold {c}"
        );
    }
}
