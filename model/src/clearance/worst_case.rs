//! The worst case of a box: the aircraft with the lowest critical jump roll rate and the lowest
//! |delta_a| at it found so far, each analysed by the exact path, which alone sets the upper
//! bounds `hi`. Candidates come from the centre, seeded random points, the Monte Carlo's lowest
//! samples and a greedy vertex search, and during the branch and bound from probes of its lowest
//! sub-box, every one screened by the certified route first: only those it cannot certify, or
//! whose certified critical jump would be kept, cost an exact analysis (3 to 12 ms with aileron
//! yaw, against a fraction of a millisecond).

use super::coordinates::{at, exact_coordinates, sample_coordinates, Rng};
use super::data_map::DataMap;
use super::{critical, CaseAircraft, ClearError, Settings};
use crate::aircraft::{Aircraft, Param, Uncertain};
use crate::analysis::JumpPoint;
use crate::interval::I;
use num_rational::BigRational;
use rayon::prelude::*;

/// The aircraft `a` at coordinates `x` of the box `params` with its critical jump `j`: every
/// parameter by its key, and each uncertain coefficient of a nondimensional file by its key.
fn case(a: &Aircraft, params: &[Uncertain], x: &[BigRational], j: &JumpPoint) -> CaseAircraft {
    let coefficients = params
        .iter()
        .zip(x)
        .filter(|(u, _)| u.coefficient.is_some())
        .map(|(u, v)| (u.key().to_string(), crate::aircraft::rational_to_f64(v)));
    CaseAircraft {
        parameters: Param::ALL
            .iter()
            .map(|p| (p.key().to_string(), a.value(*p)))
            .chain(coefficients)
            .collect(),
        p0: j.p0,
        delta_a_deg: j.delta_a_deg,
        aircraft: a.clone(),
        coordinates: x.to_vec(),
    }
}

/// The worst cases found so far, by the exact path.
pub(super) struct Worst<'a> {
    base: &'a Aircraft,
    params: &'a [Uncertain],
    /// The data of the box's aircraft at coordinates, for the probes' screens.
    map: DataMap,
    /// The lowest critical jump roll rate found, rad/s, and its aircraft.
    pub(super) p0: Option<(f64, CaseAircraft)>,
    /// The lowest |delta_a| at a critical jump found, deg, and its aircraft.
    pub(super) da: Option<(f64, CaseAircraft)>,
    /// The first aircraft found with a critical jump within the aileron limit.
    pub(super) limit_hit: Option<CaseAircraft>,
    /// The aileron limit, deg.
    pub(super) limit_deg: Option<f64>,
    delta_e_rad: f64,
}

impl<'a> Worst<'a> {
    /// None found yet in the box `params` around `base` (see [`super::split_box`]), with the
    /// aileron limit `limit_deg` (deg) at the elevator deflection `delta_e_rad` (rad).
    pub(super) fn new(
        base: &'a Aircraft,
        params: &'a [Uncertain],
        limit_deg: Option<f64>,
        delta_e_rad: f64,
    ) -> Worst<'a> {
        Worst {
            base,
            params,
            map: DataMap::new(base, params),
            p0: None,
            da: None,
            limit_hit: None,
            limit_deg,
            delta_e_rad,
        }
    }

    /// The critical (p0, |delta_a| deg) of the aircraft at coordinates `x`, if it has one:
    /// by the certified route where it answers and the aircraft would not be kept (no
    /// critical jump, or one that lowers neither minimum nor hits the limit), else by the
    /// exact path, whose answer is kept if it lowers a minimum (or hits the limit). So every
    /// aircraft that sets hi is the exact path's, as before, at a fraction of its cost for
    /// the others (the certified route's roll rate lies within 1e-9 relative of the exact one).
    pub(super) fn try_at(&mut self, x: &[BigRational]) -> Result<Option<(f64, f64)>, ClearError> {
        let screened = self.certified_data(self.data_at(x));
        self.settle(x, screened)
    }

    /// [`Worst::try_at`] of the aircraft at `x` whose certified answer is `screened`.
    fn settle(
        &mut self,
        x: &[BigRational],
        screened: Option<Option<(f64, f64)>>,
    ) -> Result<Option<(f64, f64)>, ClearError> {
        match screened {
            Some(None) => Ok(None),
            Some(Some((p0, da))) if !self.would_keep(p0, da) => Ok(Some((p0, da))),
            _ => self.exact_at(x),
        }
    }

    /// The enclosed data of the aircraft at coordinates `x`: by the map where it applies, else
    /// of the aircraft built.
    fn data_at(&self, x: &[BigRational]) -> [I; Param::COUNT] {
        self.map
            .data(x)
            .unwrap_or_else(|| crate::certified::Values::data(&at(self.base, self.params, x)))
    }

    /// The exact path's critical (p0, |delta_a| deg) of the aircraft at coordinates `x`, if
    /// it has one, kept if it lowers a minimum (or hits the limit).
    pub(super) fn exact_at(&mut self, x: &[BigRational]) -> Result<Option<(f64, f64)>, ClearError> {
        let a = at(self.base, self.params, x);
        let j = critical(&a, self.delta_e_rad)?;
        Ok(self.record(&a, x, j))
    }

    /// The critical (p0, |delta_a| deg) of the aircraft of the box whose enclosed data are
    /// `data` by the certified route ([`crate::analysis::fast::critical_of`], the Monte Carlo's
    /// lean route) without the exact path's fallback: `Some(None)` when it proves that the
    /// primary branch has no jump (it diverges or leaves the aileron range first), `None` when
    /// it cannot be certified. Every aircraft of the box has the base's aileron range: the box
    /// moves no limit.
    fn certified_data(&self, data: [I; Param::COUNT]) -> Option<Option<(f64, f64)>> {
        let lift = || crate::certified::Values::new(data, self.delta_e_rad, 0.0);
        let bound = self.base.aileron_range();
        let width = crate::analysis::fast::MAX_WIDTH;
        let found =
            crate::analysis::fast::critical_of(&data, self.delta_e_rad, &lift, bound, width)
                .ok()?;
        Some(found.map(|(p0, da)| (p0, da.to_degrees().abs())))
    }

    /// Whether a critical jump at `p0` (rad/s) with |delta_a| = `da` (deg) would be kept:
    /// it lowers either minimum or is the first within the aileron limit.
    fn would_keep(&self, p0: f64, da: f64) -> bool {
        self.lowers_p0(p0) || self.lowers_da(da) || self.first_within_limit(da)
    }

    /// Keeps `a` (at coordinates `x`) if its critical jump `j` lowers either minimum (or hits
    /// the limit).
    fn record(
        &mut self,
        a: &Aircraft,
        x: &[BigRational],
        j: Option<JumpPoint>,
    ) -> Option<(f64, f64)> {
        let j = j?;
        let da = j.delta_a_deg.abs();
        let case = |a: &Aircraft| case(a, self.params, x, &j);
        if self.lowers_p0(j.p0) {
            self.p0 = Some((j.p0, case(a)));
        }
        if self.lowers_da(da) {
            self.da = Some((da, case(a)));
        }
        if self.first_within_limit(da) {
            self.limit_hit = Some(case(a));
        }
        Some((j.p0, da))
    }

    /// Whether a critical roll rate `p0` is below the lowest so far.
    fn lowers_p0(&self, p0: f64) -> bool {
        self.p0.as_ref().is_none_or(|(p, _)| p0 < *p)
    }

    /// Whether an |delta_a| (deg) at a critical jump is below the lowest so far.
    fn lowers_da(&self, da: f64) -> bool {
        self.da.as_ref().is_none_or(|(d, _)| da < *d)
    }

    /// Whether an |delta_a| (deg) at a critical jump is within the aileron limit, and the first
    /// such.
    fn first_within_limit(&self, da: f64) -> bool {
        self.limit_hit.is_none() && self.limit_deg.is_some_and(|l| da <= l)
    }

    /// Tries the sub-box `theta` for the worst case of the minimum `by_p0` works on (the
    /// critical roll rate, else |delta_a|): the branch and bound's lowest sub-box is where that
    /// minimum lies, and hi, unlike lo, moves only when an aircraft attains a lower value. A
    /// minimum inside the box is out of reach of the candidates and the vertex search; so is
    /// one where the critical jump vanishes (a cusp, where the fold pair of the jump merges:
    /// |delta_a| at the jump tends to its infimum there, attained by no aircraft), which the
    /// lowest sub-box closes in on while its centre has no jump at all. So: the centre first;
    /// without a critical jump there, a bisection between the best aircraft so far and the
    /// centre towards where the jump vanishes, keeping the lowest aircraft with one it meets.
    ///
    /// Each point is screened by the certified route (about a hundredth of the exact path's
    /// time); the best one found, if it would lower either minimum or hit the limit, is
    /// analysed by the exact path, which alone sets hi. A probe is only ever a candidate: one
    /// the exact path refuses (e.g. two jump roots that round to the same double, next to a
    /// cusp) is dropped, and the proof goes on.
    pub(super) fn probe(&mut self, theta: &[I], by_p0: bool) {
        let key = |f: &Screened| if by_p0 { f.p0 } else { f.da_deg };
        let centre: Vec<f64> = theta.iter().map(|t| t.mid()).collect();
        if let Some(found) = self.screen(&centre) {
            return self.offer(found);
        }
        let best = if by_p0 { &self.p0 } else { &self.da };
        let Some((_, case)) = best else {
            return;
        };
        let mut yes: Vec<f64> = case
            .coordinates
            .iter()
            .map(|q| I::from_q(q).mid())
            .collect();
        let mut no = centre;
        let mut found: Option<Screened> = None;
        for _ in 0..PROBE_BISECTIONS {
            let m: Vec<f64> = yes
                .iter()
                .zip(&no)
                .map(|(a, b)| 0.5 * a + 0.5 * b)
                .collect();
            if m == yes || m == no {
                break;
            }
            match self.screen(&m) {
                Some(f) => {
                    if found.as_ref().is_none_or(|b| key(&f) < key(b)) {
                        found = Some(f);
                    }
                    yes = m;
                }
                None => no = m,
            }
        }
        if let Some(f) = found {
            self.offer(f);
        }
    }

    /// The aircraft at the f64 coordinates `x` (each clamped into the box as an exact value)
    /// if the certified route proves that it has a critical jump (the Monte Carlo's lean
    /// route, [`crate::analysis::fast::critical_of`], without the exact path's fallback: next to
    /// a cusp that fallback is the slow one, and an uncertified point only ends a bisection).
    fn screen(&self, x: &[f64]) -> Option<Screened> {
        let x = exact_coordinates(self.params, x);
        let (p0, da_deg) = self.certified_data(self.data_at(&x))??;
        Some(Screened { x, p0, da_deg })
    }

    /// Analyses a screened aircraft by the exact path if it would lower a minimum or hit the
    /// limit (its exact answer, not the screen's, is what is kept; nothing, if the exact path
    /// refuses it).
    fn offer(&mut self, f: Screened) {
        if self.would_keep(f.p0, f.da_deg) {
            // An aircraft the exact path refuses is no candidate (hi is only ever its answer).
            let _ = self.exact_at(&f.x);
        }
    }
}

/// An aircraft of the box with a critical jump, found by [`Worst::screen`]: its exact
/// coordinates, and its critical roll rate and |delta_a| (deg) by the certified route.
struct Screened {
    x: Vec<BigRational>,
    p0: f64,
    da_deg: f64,
}

/// Bisection steps of [`Worst::probe`] towards where the critical jump vanishes: 2^-40 of the
/// segment, far below any tolerance, at about 40 certified analyses.
const PROBE_BISECTIONS: usize = 40;

/// Greedy vertex search from `start`: each coordinate in turn moved to the end of its interval
/// that lowers `key` (the critical p0 or |delta_a|), repeated while it improves. A point the
/// exact path refuses is no candidate and is passed over (`start` itself must be analysed).
fn descend(
    worst: &mut Worst,
    params: &[Uncertain],
    start: Vec<BigRational>,
    key: fn(f64, f64) -> f64,
) -> Result<(), ClearError> {
    let mut x = start;
    let mut best = match worst.try_at(&x)? {
        Some((p, d)) => key(p, d),
        None => f64::INFINITY,
    };
    for _pass in 0..3 {
        let mut improved = false;
        for i in 0..params.len() {
            for end in [&params[i].lo, &params[i].hi] {
                if x[i] == *end {
                    continue;
                }
                let mut y = x.clone();
                y[i] = end.clone();
                if let Ok(Some((p, d))) = worst.try_at(&y) {
                    if key(p, d) < best {
                        best = key(p, d);
                        x = y;
                        improved = true;
                    }
                }
            }
        }
        if !improved {
            break;
        }
    }
    Ok(())
}

/// The candidates for the worst case before the branch and bound: the centre of the box,
/// seeded random points, the given ones (`settings.candidates_at`), and a greedy vertex search
/// from the best of them for each of the two minima. `progress` gets 0.05 once the candidates
/// are analysed, before the vertex search.
pub(super) fn search_candidates(
    worst: &mut Worst,
    settings: &Settings,
    progress: &mut dyn FnMut(f64),
) -> Result<(), ClearError> {
    let params = worst.params;
    let centre: Vec<BigRational> = params
        .iter()
        .map(|u| (&u.lo + &u.hi) / BigRational::from_integer(2.into()))
        .collect();
    worst.try_at(&centre)?;
    // The random candidates analysed on rayon's threads, kept in their seeded order.
    let mut rng = Rng::new(settings.seed);
    let candidates: Vec<Vec<BigRational>> = (0..settings.candidates)
        .map(|_| sample_coordinates(params, &mut rng))
        .collect();
    // Screened by the certified route on rayon's threads, settled in their seeded order.
    let screened: Vec<_> = candidates
        .par_iter()
        .map(|x| worst.certified_data(worst.data_at(x)))
        .collect();
    for (x, s) in candidates.iter().zip(screened) {
        worst.settle(x, s)?;
    }
    for x in settings
        .candidates_at
        .iter()
        .filter(|x| x.len() == params.len())
    {
        // An aircraft the exact path refuses is no candidate (hi is only ever its answer).
        let _ = worst.try_at(&exact_coordinates(params, x));
    }
    progress(0.05);
    let coords = |c: &Option<(f64, CaseAircraft)>| -> Vec<BigRational> {
        match c {
            Some((_, w)) => w.coordinates.clone(),
            None => centre.clone(),
        }
    };
    let from_p0 = coords(&worst.p0);
    descend(worst, params, from_p0, |p, _| p)?;
    let from_da = coords(&worst.da);
    descend(worst, params, from_da, |_, d| d)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::clearance::split_box;

    /// Though the certified route settles most candidates alone, the worst cases kept (which
    /// set hi) are the exact path's answers for their aircraft, as the full `analyze` gives
    /// them: aircraft A with n_delta_a in [20, 40] at delta_e = -4 deg, where every aircraft
    /// has a critical jump.
    #[test]
    fn the_worst_cases_kept_are_the_exact_paths_answers() {
        let q = |n: i64| BigRational::from_integer(n.into());
        let mut a = Aircraft::a().with(Param::NDeltaA, q(30));
        a.uncertainty = vec![Uncertain::param(Param::NDeltaA, q(20), q(40))];
        let de = (-4f64).to_radians();
        let (base, params) = split_box(&a);
        let mut worst = Worst::new(&base, &params, None, de);
        let settings = Settings {
            delta_e_rad: de,
            candidates: 16,
            ..Settings::default()
        };
        search_candidates(&mut worst, &settings, &mut |_| {}).expect("candidates");
        let (p0, by_p0) = worst.p0.as_ref().expect("a worst case");
        let (da, by_da) = worst.da.as_ref().expect("a worst case for the aileron");
        for case in [by_p0, by_da] {
            let j = crate::analysis::analyze(&case.aircraft, de)
                .expect("analysed")
                .critical
                .expect("a critical jump");
            assert_eq!((j.p0, j.delta_a_deg), (case.p0, case.delta_a_deg));
        }
        assert_eq!(*p0, by_p0.p0);
        assert_eq!(*da, by_da.delta_a_deg.abs());
    }
}
