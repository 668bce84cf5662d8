//! [`clear`]: the clearance of a box, from the candidates for the worst case (which set `hi`)
//! through the branch and bound (which proves `lo`: no aircraft of the box has a critical jump
//! below it) to the bounds, the note on what limited them, and the check that no worst case
//! lies where the proof found no jump.

use super::bound::{BoxPolys, Failure};
use super::coordinates::split_box;
use super::on_pool::on_pool;
use super::tree::{Leaf, Walk, BATCH, MAX_ROLL_RATE};
use super::verdict::{decide, AileronBounds, Tightening};
use super::worst_case::{search_candidates, Worst};
use super::{Bounds, CaseAircraft, ClearError, Clearance, Settings, Verdict};
use crate::aircraft::{Aircraft, Uncertain};
use crate::interval::I;
use rayon::prelude::*;
use std::time::Instant;

/// Runs the clearance of `aircraft`'s `[uncertainty]` box; `progress` gets a fraction in [0, 1].
/// The proof runs on a thread of rayon's pool, where each of its thousands of rounds forks its
/// steps; `progress` is called on the calling thread.
pub fn clear(
    aircraft: &Aircraft,
    settings: &Settings,
    progress: &mut dyn FnMut(f64),
) -> Result<Clearance, ClearError> {
    on_pool(progress, |progress| {
        clear_in_pool(aircraft, settings, progress)
    })
}

/// [`clear`] on a thread of rayon's pool.
fn clear_in_pool(
    aircraft: &Aircraft,
    settings: &Settings,
    progress: &mut dyn FnMut(f64),
) -> Result<Clearance, ClearError> {
    let start = Instant::now();
    let de = settings.delta_e_rad;
    let (base, params) = split_box(aircraft);
    let mut worst = Worst::new(&base, &params, aircraft.limits.aileron_deg, de);
    let answer = Answer {
        aircraft,
        settings,
        params: &params,
        start,
    };
    if params.is_empty() {
        // A point: the exact analysis is the proof.
        let (lo, da) = match worst.exact_at(&[])? {
            Some((p, d)) => (p, d),
            None => (f64::INFINITY, f64::INFINITY),
        };
        let note = "zero-width box: the exact analysis of its one aircraft".to_string();
        return Ok(answer.finish(worst, (lo, da), note, (0, 0), None));
    }
    search_candidates(&mut worst, settings, progress)?;
    progress(0.1);

    let polys = BoxPolys::of_box(&base, &params, de);
    let mut search = Search::new(&polys, aircraft, &params, &worst, settings);
    let note = search
        .run(&mut worst, start, progress, Goal::Tolerance)
        .note;
    let tightening = search.tighten(&mut worst, start, progress);
    let (lo, lo_da, note) = search.bounds(&worst, note);
    progress(1.0);
    let work = (search.boxes, search.slabs);
    let lo = (lo, lo_da.to_degrees());
    Ok(answer.finish(worst, lo, note, work, tightening.as_ref()))
}

/// What the branch and bound works towards: both gaps within the tolerance, or the proven
/// lower bound of |delta_a| above the aileron limit (deg) unless an aircraft of the box is
/// found within it.
#[derive(Clone, Copy)]
enum Goal {
    Tolerance,
    Limit(f64),
}

/// Why the branch and bound stopped, and whether a budget of work (or the wall-clock guard)
/// stopped it.
struct Stopped {
    note: String,
    by_budget: bool,
}

/// What the answer of a run is about: the aircraft, the settings, the box and when it started.
struct Answer<'a> {
    aircraft: &'a Aircraft,
    settings: &'a Settings,
    params: &'a [Uncertain],
    start: Instant,
}

impl Answer<'_> {
    /// The clearance with the proven lower bounds `p0_lo` (rad/s) and `da_lo_deg`, the worst
    /// cases of `worst`, why the proof stopped (`note`), its work (boxes, slabs) and the
    /// tightening past the tolerance, if it ran.
    fn finish(
        &self,
        worst: Worst,
        (p0_lo, da_lo_deg): (f64, f64),
        note: String,
        (boxes, slabs): (usize, usize),
        tightening: Option<&Tightening>,
    ) -> Clearance {
        let settings = self.settings;
        // No critical jump anywhere in the box (proven): the minimum over an empty set, lo =
        // infinity (null in JSON), exact.
        let none = p0_lo == f64::INFINITY && worst.p0.is_none();
        let bounds = |lo: f64, hi: Option<f64>, tol: f64| {
            let gap = hi.map(|h| (h - lo).max(0.0));
            Bounds {
                lo,
                hi,
                gap,
                converged: gap.is_some_and(|g| g <= tol) || none,
            }
        };
        let hi_p0 = worst.p0.as_ref().map(|(p, _)| *p);
        let hi_da = worst.da.as_ref().map(|(d, _)| *d);
        let (verdict, verdict_reason, gap_to_limit) = decide(
            worst.limit_deg,
            worst.limit_hit.as_ref().map(|c| c.delta_a_deg.abs()),
            &AileronBounds {
                lo: da_lo_deg,
                hi: hi_da,
            },
            tightening,
        );
        let cleared = match verdict {
            Some(Verdict::Cleared) => Some(true),
            Some(Verdict::NotCleared) => Some(false),
            _ => None,
        };
        let box_ = self
            .params
            .iter()
            .map(|u| {
                let b = I::from_q_pair(&u.lo, &u.hi);
                (u.key().to_string(), b.lo, b.hi)
            })
            .collect();
        Clearance {
            aircraft: self.aircraft.name.clone(),
            delta_e_rad: settings.delta_e_rad,
            box_,
            critical_p0: bounds(p0_lo, hi_p0, settings.tolerance_p0),
            critical_delta_a_deg: bounds(da_lo_deg, hi_da, settings.tolerance_deg),
            worst_case: worst.p0.map(|(_, c)| c),
            worst_case_aileron: worst.da.map(|(_, c)| c),
            cleared,
            verdict,
            verdict_reason,
            gap_to_limit,
            no_critical_jump: none,
            counterexample: worst.limit_hit,
            note,
            boxes,
            slabs,
            seconds: self.start.elapsed().as_secs_f64(),
        }
    }
}

/// How far the proof must go, from the worst case found so far: the roll rate every sub-box
/// must be certified to and the aileron bound (rad) |delta_a| must reach.
struct Targets {
    /// The worst case's critical roll rate, rad/s (infinite without one).
    hi_p0: f64,
    /// `hi_p0` less the tolerance, or the cap without a worst case.
    reach: f64,
    /// The worst case's |delta_a|, rad (infinite without one).
    hi_da_rad: f64,
    /// The bound |delta_a| must reach, rad: `hi_da_rad` less the tolerance, or the aileron
    /// limit when tightening past the tolerance.
    da_target: f64,
}

impl Targets {
    /// How deep every sub-box must be certified: to the worst case found (less the
    /// tolerance), or, when no aircraft tried has a critical jump, until every sub-box is
    /// finished (its branch leaves the aileron range first) or reaches the cap. The worst
    /// case found only ever goes down (`Worst::probe`). The aileron bound's target is set by
    /// `goal`.
    fn of(worst: &Worst, settings: &Settings, goal: Goal) -> Targets {
        let hi_p0 = worst.p0.as_ref().map_or(f64::INFINITY, |(p, _)| *p);
        let reach = if hi_p0.is_finite() {
            hi_p0 - settings.tolerance_p0
        } else {
            MAX_ROLL_RATE
        };
        let hi_da_rad = worst
            .da
            .as_ref()
            .map_or(f64::INFINITY, |(d, _)| d.to_radians());
        let da_target = match goal {
            Goal::Tolerance => hi_da_rad - settings.tolerance_deg.to_radians(),
            Goal::Limit(limit_deg) => limit_deg.to_radians(),
        };
        Targets {
            hi_p0,
            reach,
            hi_da_rad,
            da_target,
        }
    }
}

/// The branch and bound over the box: its leaves, the work done, and what every step needs.
struct Search<'a> {
    polys: &'a BoxPolys,
    settings: &'a Settings,
    theta0: Vec<I>,
    first_step: f64,
    min_step: f64,
    /// The aileron range `analyze` follows the primary branch to, rad (infinite when the trim
    /// at P0 = 0 needs aileron for some aircraft).
    range: f64,
    /// The aileron limit, rad (infinite without one).
    limit_rad: f64,
    leaves: Vec<Leaf>,
    boxes: usize,
    slabs: usize,
}

impl<'a> Search<'a> {
    /// One leaf, the whole box `params` of `aircraft`, its first slab sized from the worst
    /// case found.
    fn new(
        polys: &'a BoxPolys,
        aircraft: &Aircraft,
        params: &[Uncertain],
        worst: &Worst,
        settings: &'a Settings,
    ) -> Search<'a> {
        let theta0: Vec<I> = params
            .iter()
            .map(|u| I::from_q_pair(&u.lo, &u.hi))
            .collect();
        let hi_p0 = worst.p0.as_ref().map_or(f64::INFINITY, |(p, _)| *p);
        let first_step = if hi_p0.is_finite() {
            hi_p0 / 32.0
        } else {
            0.05
        };
        let leaves = vec![Leaf::new(polys, &theta0, first_step)];
        let range = if polys.symmetric {
            aircraft.aileron_range()
        } else {
            f64::INFINITY
        };
        Search {
            polys,
            settings,
            theta0,
            first_step,
            min_step: settings.tolerance_p0 / 8.0,
            range,
            limit_rad: aircraft
                .limits
                .aileron_deg
                .map_or(f64::INFINITY, f64::to_radians),
            leaves,
            boxes: 1,
            slabs: 0,
        }
    }

    /// Steps the lowest leaves, probing the lowest for the worst case, until the `goal` is
    /// reached or a budget stops the proof; returns why it stopped.
    fn run(
        &mut self,
        worst: &mut Worst,
        start: Instant,
        progress: &mut dyn FnMut(f64),
        goal: Goal,
    ) -> Stopped {
        let stop = |note: String, by_budget: bool| Stopped { note, by_budget };
        loop {
            let t = Targets::of(worst, self.settings, goal);
            let (lo, lo_da) = Leaf::minima(&self.leaves);
            progress(0.1 + 0.9 * (lo / t.reach).clamp(0.0, 1.0));
            // Work on the roll rate while it is short of its target, else on |delta_a|.
            let by_p0 = match goal {
                Goal::Tolerance => {
                    let done_p0 = lo >= t.reach;
                    // Without a worst case (hi), the aileron bound rides on the roll-rate walk.
                    let done_da =
                        !self.polys.symmetric || lo_da >= t.da_target || !t.hi_p0.is_finite();
                    if done_p0 && done_da {
                        return stop(converged_note(lo, t.hi_p0), false);
                    }
                    !done_p0
                }
                Goal::Limit(limit_deg) => {
                    if worst.limit_hit.is_some() || lo_da.min(t.hi_da_rad).to_degrees() > limit_deg
                    {
                        return stop("decided".to_string(), false);
                    }
                    false
                }
            };
            if let Some(note) = self.budget_note(start) {
                return stop(note, true);
            }
            let batch = match self.batch(by_p0, &t) {
                Ok(batch) => batch,
                Err(note) => return stop(note, false),
            };
            // The probe of the lowest leaf runs beside the batch's steps: they were set by the
            // targets before it, so it changes nothing they do, and the worst case it may find
            // counts from the next batch on, as it would after them.
            let first = batch[0];
            let probe = (!self.leaves[first].probed).then(|| {
                self.leaves[first].probed = true;
                self.leaves[first].theta.clone()
            });
            rayon::join(
                || {
                    if let Some(theta) = probe {
                        worst.probe(&theta, by_p0);
                    }
                },
                || self.step(batch, by_p0, &t),
            );
        }
    }

    /// When the aileron limit falls between the bounds the tolerance left (no aircraft found
    /// within it, the proven bound at or below it), goes on refining the sub-boxes whose bound
    /// lies below the limit, probing the lowest for an aircraft within it, until the verdict is
    /// decided or the budget runs out; returns how that went (nothing when it was not needed).
    /// Where |delta_a|'s bound is held at 0 (the trim at P0 = 0 needs aileron), refining
    /// cannot raise it, and says so.
    fn tighten(
        &mut self,
        worst: &mut Worst,
        start: Instant,
        progress: &mut dyn FnMut(f64),
    ) -> Option<Tightening> {
        let limit_deg = worst.limit_deg?;
        let hi_da = worst
            .da
            .as_ref()
            .map_or(f64::INFINITY, |(d, _)| d.to_radians());
        let from_lo_deg = Leaf::minima(&self.leaves).1.min(hi_da).to_degrees();
        if worst.limit_hit.is_some() || from_lo_deg > limit_deg {
            return None;
        }
        if !self.polys.symmetric {
            return Some(Tightening {
                from_lo_deg: 0.0,
                note: "cannot raise |delta_a|'s lower bound above 0 (the trim at P0 = 0 needs                        aileron for some aircraft of the box)"
                    .to_string(),
                by_budget: false,
            });
        }
        let stopped = self.run(worst, start, progress, Goal::Limit(limit_deg));
        Some(Tightening {
            from_lo_deg,
            note: stopped.note,
            by_budget: stopped.by_budget,
        })
    }

    /// Why the proof stops at a budget of work (boxes, slabs) or at the wall-clock guard, if it
    /// does.
    fn budget_note(&self, start: Instant) -> Option<String> {
        let settings = self.settings;
        if self.leaves.len() >= settings.max_boxes {
            return Some(format!(
                "stopped at the budget of {} boxes",
                settings.max_boxes
            ));
        }
        if self.slabs >= settings.max_slabs {
            return Some(format!(
                "stopped at the budget of {} slabs",
                settings.max_slabs
            ));
        }
        if start.elapsed().as_secs_f64() > settings.wall_clock_guard_s {
            return Some(format!(
                "stopped by the wall-clock guard of {} s with {} boxes and {} slabs, not \
                 by a budget of work: this answer depends on the machine's speed and load",
                settings.wall_clock_guard_s,
                self.leaves.len(),
                self.slabs
            ));
        }
        None
    }

    /// The leaves to step next, the lowest by the roll rate (`by_p0`) or else by |delta_a|
    /// first: the lowest few still short of the target, one step each, in parallel. A fixed
    /// number of them, so that the answer does not depend on the number of cores; every leaf
    /// has to reach the target anyway, so taking the next-lowest ones along adds little work.
    /// Without a leaf left to step, why the proof stops.
    fn batch(&self, by_p0: bool, t: &Targets) -> Result<Vec<usize>, String> {
        let leaves = &self.leaves;
        let key = |l: &Leaf| if by_p0 { l.p0_key() } else { l.da_key() };
        let target = if by_p0 { t.reach } else { t.da_target };
        let mut batch: Vec<usize> = (0..leaves.len())
            .filter(|i| {
                let l = &leaves[*i];
                l.stuck.is_none() && !l.finished() && l.depth < MAX_ROLL_RATE
            })
            .collect();
        let lowest =
            |a: &usize, b: &usize| key(&leaves[*a]).total_cmp(&key(&leaves[*b])).then(a.cmp(b));
        if batch.len() > BATCH {
            batch.select_nth_unstable_by(BATCH - 1, lowest);
            batch.truncate(BATCH);
        }
        batch.sort_by(lowest);
        let Some(first) = batch.first().copied() else {
            return Err(if leaves.iter().any(|l| l.stuck.is_some()) {
                "every remaining box is stuck at a point where the proof cannot continue"
                    .to_string()
            } else {
                format!(
                    "every remaining box reached the cap of the proof, P0 = {MAX_ROLL_RATE} rad/s"
                )
            });
        };
        batch.retain(|i| *i == first || key(&leaves[*i]) < target);
        Ok(batch)
    }

    /// One step of each leaf of `batch` (in parallel), the halves of a split added as leaves.
    fn step(&mut self, batch: Vec<usize>, by_p0: bool, t: &Targets) {
        let limit = if by_p0 { t.hi_p0 } else { f64::INFINITY }.min(MAX_ROLL_RATE);
        let walk = Walk {
            polys: self.polys,
            theta0: &self.theta0,
            limit,
            min_step: self.min_step,
            first_step: self.first_step,
            range: self.range,
            limit_rad: self.limit_rad,
        };
        let leaves = &self.leaves;
        let steps: Vec<(Leaf, Option<Leaf>)> =
            batch.par_iter().map(|i| walk.step(&leaves[*i])).collect();
        // Sub-boxes done with drop their lifted data (the targets are those this batch
        // worked to; they only go down while a worst case is known).
        let da_target = if self.polys.symmetric && t.hi_p0.is_finite() {
            t.da_target
        } else {
            f64::NEG_INFINITY
        };
        let reach = t.reach;
        let keep = |mut leaf: Leaf| {
            if leaf.retired(reach, da_target) {
                leaf.drop_lifted();
            }
            leaf
        };
        for (i, (leaf, other)) in batch.into_iter().zip(steps) {
            self.slabs += 1;
            self.leaves[i] = keep(leaf);
            if let Some(other) = other {
                self.leaves.push(keep(other));
                self.boxes += 1;
            }
        }
    }

    /// The proven lower bounds over the leaves, of the critical jump roll rate (rad/s) and of
    /// |delta_a| at it (rad), each at most what the worst case attains, and `note` with what
    /// holds them.
    fn bounds(&self, worst: &Worst, note: String) -> (f64, f64, String) {
        let leaves = &self.leaves;
        let (mut lo, mut lo_da) = Leaf::minima(leaves);
        let mut note = note;
        if !self.polys.symmetric {
            lo_da = 0.0;
            note += "; the trim at P0 = 0 needs aileron for some aircraft of the box, so \
                     |delta_a| is not monotone from 0 along the branch and its lower bound is 0";
        }
        note += &self.turn_notes(lo);
        let cases: Vec<&CaseAircraft> = [&worst.p0, &worst.da]
            .into_iter()
            .filter_map(|c| c.as_ref().map(|(_, c)| c))
            .collect();
        if let Some(c) = contradiction(leaves, &cases) {
            // Never expected: the exact path found a critical jump where the proof says there
            // is none, so an assumption of the proof (docs/clearance.md: that `analyze`'s walk
            // follows the exact curve) fails for this box, and nothing below is proven.
            lo = 0.0;
            lo_da = 0.0;
            note += &format!(
                "; INCONSISTENT: an aircraft of the box has a critical jump (exact path, P0 = \
                 {:.6} rad/s) inside a sub-box the proof found free of them, so no bound is \
                 proven (lo = 0)",
                c.p0
            );
        }
        if let Some(hi) = worst.p0.as_ref().map(|(p, _)| *p) {
            lo = lo.min(hi);
        }
        if let Some(hi) = worst.da.as_ref().map(|(d, _)| d.to_radians()) {
            lo_da = lo_da.min(hi);
        }
        (lo, lo_da, note)
    }

    /// What the note adds on branches that turn in P0 (docs/clearance.md, step 6) and on a
    /// possible jump of the other trim that holds the bound `lo`.
    fn turn_notes(&self, lo: f64) -> String {
        let leaves = &self.leaves;
        let mut note = String::new();
        // A sub-box held up where its branch may turn (its latest slab failed so, stuck there
        // or not) keeps its bound: past the turn the branch comes back on its other trim, and
        // every slab below the bound has that trim certified free of jumps within the aileron
        // range.
        if let Some(l) = leaves
            .iter()
            .filter(|l| !l.finished() && l.turned.is_none())
            .find(|l| l.stuck == Some(Failure::Turn) || l.last == Some(Failure::Turn))
        {
            note += &format!(
                "; the primary branch may turn in P0 near {:.4} rad/s for part of the box: lo \
                 also bounds the jumps met after the turn, on the other trim",
                l.depth
            );
        }
        // Sub-boxes whose branch turns back in P0 (certified zones).
        let zones = leaves
            .iter()
            .filter_map(|l| l.turned.map(|top| (l.depth, top)))
            .fold(None, |z: Option<(f64, f64)>, (a, b)| {
                Some(z.map_or((a, b), |(lo, hi)| (lo.min(a), hi.max(b))))
            });
        if let Some((from, to)) = zones {
            let whose = if leaves.iter().all(|l| l.turned.is_some()) {
                "for every aircraft of the box"
            } else {
                "for part of the box"
            };
            note += &format!(
                "; {whose} the primary branch turns back in P0 between {from:.4} and {to:.4} \
                 rad/s (proven, with no jump there) and comes back down on its other trim, whose \
                 jumps within the aileron range, if any, bound lo"
            );
        }
        if let Some(d) = leaves
            .iter()
            .filter(|l| !l.finished())
            .filter_map(Leaf::doubt)
            .min_by(|a, b| a.lo.total_cmp(&b.lo))
            .filter(|d| d.lo <= lo)
        {
            note += &format!(
                "; lo is held at {:.6} rad/s by a possible jump on the other trim of the trim \
                 condition (P0 in [{:.6}, {:.6}]), which a branch turning in P0 beyond its \
                 certified depth could come back to",
                d.lo, d.lo, d.hi
            );
        }
        note
    }
}

/// Why the proof stops with both minima within the tolerance: the lowest bound `lo` over the
/// leaves and the worst case's roll rate `hi_p0` tell which way.
fn converged_note(lo: f64, hi_p0: f64) -> String {
    if lo == f64::INFINITY {
        "converged: no box's primary branch meets a jump before it leaves the aileron range"
            .to_string()
    } else if !hi_p0.is_finite() {
        // No worst case, and some sub-box stopped at the cap unfinished.
        format!(
            "stopped: no aircraft tried has a critical jump, and a box reached the cap of the \
             proof, P0 = {MAX_ROLL_RATE} rad/s, without leaving the aileron range"
        )
    } else {
        "converged: both gaps within the tolerance".to_string()
    }
}

/// The first of `cases` (aircraft the exact path found a critical jump for) that lies in a
/// finished sub-box of `leaves`, one the proof found free of critical jumps: a contradiction.
fn contradiction<'a>(leaves: &[Leaf], cases: &[&'a CaseAircraft]) -> Option<&'a CaseAircraft> {
    use num_traits::ToPrimitive;
    cases.iter().copied().find(|c| {
        let x: Vec<f64> = c
            .coordinates
            .iter()
            .map(|v| v.to_f64().unwrap_or(f64::NAN))
            .collect();
        leaves.iter().filter(|l| l.finished()).any(|l| {
            l.theta.len() == x.len()
                && l.theta
                    .iter()
                    .zip(&x)
                    .all(|(t, v)| t.lo <= *v && *v <= t.hi)
        })
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::aircraft::Param;
    use crate::clearance::tests::a_uncertain;
    use num_rational::BigRational;

    /// An aircraft the exact path finds a critical jump for, inside a sub-box the proof calls
    /// free of them (here one turned without doubts), is a contradiction; outside every such
    /// sub-box, or inside an unfinished one, it is not.
    #[test]
    fn a_jump_inside_a_box_proven_free_of_jumps_is_a_contradiction() {
        let a = Aircraft::a();
        let polys = BoxPolys::new(&a, &[Param::Lp], 0.0);
        let mut finished = Leaf::new(&polys, &[I::new(-22.0, -21.0)], 0.1);
        finished.turned = Some(1.5);
        let unfinished = Leaf::new(&polys, &[I::new(-21.0, -20.0)], 0.1);
        let case = |l_p: f64| CaseAircraft {
            parameters: Default::default(),
            p0: 1.7,
            delta_a_deg: 10.0,
            aircraft: a.clone(),
            coordinates: vec![BigRational::from_float(l_p).expect("finite")],
        };
        let leaves = [finished, unfinished];
        let (inside, outside, unproven) = (case(-21.5), case(-23.0), case(-20.5));
        assert_eq!(contradiction(&leaves, &[&outside, &inside]), Some(&inside));
        assert_eq!(contradiction(&leaves, &[&outside, &unproven]), None);
    }

    /// The branch and bound steps a fixed number of leaves at a time, so its answer (bounds,
    /// worst cases, boxes, slabs) does not depend on how many threads run them.
    #[test]
    fn the_proof_does_not_depend_on_the_threads() {
        let a = a_uncertain();
        let settings = Settings::default();
        let run = |threads: usize| {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .expect("a thread pool");
            let mut c = pool
                .install(|| clear(&a, &settings, &mut |_| {}))
                .expect("a proof");
            c.seconds = 0.0;
            c
        };
        let one = run(1);
        assert!(one.critical_p0.converged, "{one:?}");
        assert!(one.boxes > 1, "the box is split: {one:?}");
        assert_eq!(run(2), one);
        assert_eq!(run(3), one);
    }

    /// Aircraft A with n_delta_a in [20, 40] at delta_e = -4 deg and an aileron limit: its
    /// |delta_a| minimum lies inside the box, at a cusp near n_delta_a = 24.49.
    fn cusp_box(limit_deg: f64) -> Aircraft {
        let q = |n: i64| BigRational::from_integer(n.into());
        let mut a = Aircraft::a().with(Param::NDeltaA, q(30));
        a.uncertainty = vec![crate::aircraft::Uncertain::param(
            Param::NDeltaA,
            q(20),
            q(40),
        )];
        a.limits.aileron_deg = Some(limit_deg);
        a
    }

    /// The shipped box with its aileron limit moved between the bounds the default tolerance
    /// leaves (|delta_a| in [3.1020, 3.1095] deg): undecided there, the bounds are tightened
    /// past the tolerance until the proven bound clears the limit.
    #[test]
    fn a_limit_between_the_bounds_is_decided_by_tightening() {
        let mut a = a_uncertain();
        let at_tolerance = clear(&a, &Settings::default(), &mut |_| {}).expect("a proof");
        let b = &at_tolerance.critical_delta_a_deg;
        let hi = b.hi.expect("a worst case");
        assert!(b.converged && hi - b.lo > 0.005, "{b:?}");
        let limit = b.lo + 0.6 * (hi - b.lo);
        a.limits.aileron_deg = Some(limit);
        let c = clear(&a, &Settings::default(), &mut |_| {}).expect("a proof");
        assert_eq!(c.verdict, Some(Verdict::Cleared), "{}", c.verdict_reason);
        assert_eq!(c.cleared, Some(true));
        assert!(
            c.critical_delta_a_deg.lo > limit,
            "{:?}",
            c.critical_delta_a_deg
        );
        assert!(
            c.verdict_reason.contains("tightening"),
            "{}",
            c.verdict_reason
        );
        assert!(
            c.gap_to_limit.is_none() && c.counterexample.is_none(),
            "{c:?}"
        );
        assert!(c.slabs > at_tolerance.slabs, "{} slabs", c.slabs);
        // The verdict at the shipped limit needs no tightening.
        assert_eq!(at_tolerance.verdict, Some(Verdict::Cleared));
        assert!(!at_tolerance.verdict_reason.contains("tightening"));
    }

    /// A limit a hair below the worst case found leaves nothing a proof within a tiny budget
    /// of work can decide: undecided at the budget, with the gap reached on each side.
    #[test]
    fn a_limit_no_proof_reaches_within_the_budget_is_undecided_with_the_gap() {
        let mut a = a_uncertain();
        let at_tolerance = clear(&a, &Settings::default(), &mut |_| {}).expect("a proof");
        let hi = at_tolerance.critical_delta_a_deg.hi.expect("a worst case");
        a.limits.aileron_deg = Some(hi - 1e-9);
        let settings = Settings {
            max_slabs: at_tolerance.slabs + 16,
            ..Settings::default()
        };
        let c = clear(&a, &settings, &mut |_| {}).expect("a proof");
        assert_eq!(
            c.verdict,
            Some(Verdict::UndecidedBudget),
            "{}",
            c.verdict_reason
        );
        assert_eq!(c.cleared, None);
        let gap = c.gap_to_limit.as_ref().expect("the gap reached");
        assert!(gap.limit_minus_lo_deg > 0.0, "{gap:?}");
        assert!((gap.hi_minus_limit_deg - 1e-9).abs() < 1e-10, "{gap:?}");
        assert!(
            c.verdict_reason.contains("budget of") && c.verdict_reason.contains("limit - lo"),
            "{}",
            c.verdict_reason
        );
    }

    /// With a coarse tolerance the worst case found stops above the limit while the box's
    /// minimum lies below it: tightening probes the lowest sub-boxes and finds an aircraft
    /// within the limit, whose exact analysis (`analyze`, independently) jumps within it.
    #[test]
    fn tightening_finds_a_counterexample_that_analyze_confirms() {
        let limit = 4.7;
        let a = cusp_box(limit);
        let settings = Settings {
            delta_e_rad: (-4f64).to_radians(),
            tolerance_p0: 0.3,
            tolerance_deg: 3.0,
            ..Settings::default()
        };
        let c = clear(&a, &settings, &mut |_| {}).expect("a proof");
        assert_eq!(c.verdict, Some(Verdict::NotCleared), "{}", c.verdict_reason);
        assert!(
            c.verdict_reason.contains("tightening"),
            "{}",
            c.verdict_reason
        );
        let x = c.counterexample.expect("a counterexample");
        let r = crate::analysis::analyze(&x.aircraft, settings.delta_e_rad).expect("analysed");
        let j = r.critical.expect("a critical jump");
        assert!(j.delta_a_deg.abs() <= limit, "{j:?}");
        assert_eq!(j.delta_a_deg, x.delta_a_deg);
        let n = x.aircraft.value(Param::NDeltaA);
        assert!((20.0..=40.0).contains(&n), "{n}");
    }

    /// A budget of work stops the proof at the same place on every run, and says which budget
    /// it was; the wall-clock guard, when it stops a proof, says that the answer depends on
    /// the machine.
    #[test]
    fn the_budgets_are_of_work_and_the_wall_clock_guard_says_so() {
        let a = a_uncertain();
        let run = |settings: &Settings| {
            let mut c = clear(&a, settings, &mut |_| {}).expect("a proof");
            c.seconds = 0.0;
            c
        };
        let few_slabs = Settings {
            max_slabs: 3,
            ..Settings::default()
        };
        let stopped = run(&few_slabs);
        assert!(!stopped.critical_p0.converged, "{stopped:?}");
        assert_eq!(stopped.note, "stopped at the budget of 3 slabs");
        assert!(stopped.slabs >= 3 && stopped.slabs < 3 + 64, "{stopped:?}");
        assert_eq!(run(&few_slabs), stopped);
        let guarded = run(&Settings {
            wall_clock_guard_s: 0.0,
            ..Settings::default()
        });
        assert!(
            guarded.note.contains("wall-clock guard") && guarded.note.contains("depends on"),
            "{}",
            guarded.note
        );
    }
}
