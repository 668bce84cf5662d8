//! The branch-and-bound tree of the proof: its leaves (sub-boxes certified from P0 = 0 to a
//! depth, with what bounds them: the depth, doubtful slabs of the other trim, barriers, turn
//! zones) and one step of a leaf (its next slab certified, or the step shrunk, or the sub-box
//! split in two). docs/clearance.md says what each certificate proves.

use super::bound::{BoxPolys, Failure, LiftedBox, OtherTrim};
use crate::analysis::primary::TURN_STEP;
use crate::interval::I;
use std::sync::Arc;

/// A leaf of the branch and bound: a sub-box certified from P0 = 0 to `depth`.
#[derive(Clone, Debug)]
pub(super) struct Leaf {
    pub(super) theta: Vec<I>,
    /// The box lifted once for all its slabs; dropped once the sub-box is retired
    /// ([`Leaf::retired`]: about 125 kB each with 17 uncertain parameters, which thousands of
    /// sub-boxes held to the end), and made again from `theta` and `side` should it be
    /// stepped after all.
    pub(super) lifted: Option<Arc<LiftedBox>>,
    /// The branch's side of the dropped lifted data ([`LiftedBox::side`]), to lift it again as
    /// it was.
    pub(super) side: Option<f64>,
    pub(super) depth: f64,
    pub(super) step: f64,
    /// Lower bound of |delta_a| (rad) of the primary branch at `depth` over the box.
    pub(super) da_lo: f64,
    /// The depth at which `da_lo` first exceeded the aileron range `analyze` follows the
    /// primary branch to (`None` while it has not, or when the trim at P0 = 0 needs aileron).
    pub(super) beyond_at: Option<f64>,
    /// Why its latest slab failed (`None` after a certified one).
    pub(super) last: Option<Failure>,
    pub(super) stuck: Option<Failure>,
    /// Certified slabs whose *other* trim may hold a jump within the aileron range
    /// ([`BoxPolys::other_trim`]), in increasing P0, above `barrier`: a branch that turns in
    /// P0 beyond the depth and comes back on that trim could meet it, so the sub-box's bound
    /// is the lowest.
    pub(super) doubts: Vec<I>,
    /// The top of the highest run of consecutive slabs, at least `TURN_STEP` long, whose other
    /// trim lies beyond the aileron range ([`OtherTrim::BeyondRange`]): a branch coming back
    /// down on that trim has a step end in it, checked against the range, so it ends there
    /// and never reaches the slabs below.
    pub(super) barrier: f64,
    /// Where the current run of such slabs (up to the depth) starts.
    pub(super) run_from: Option<f64>,
    /// The depth at which the search for a barrier above the lowest doubt
    /// ([`Walk::search_barrier`]) last failed (not tried again there).
    pub(super) searched_at: Option<f64>,
    /// The top of the certified turn zone above the depth ([`BoxPolys::turn_back`]): every
    /// aircraft's branch turns back in P0 below it with no jump, and comes back down through
    /// the depth on its other trim, so only the doubts bound the sub-box (and none: finished).
    pub(super) turned: Option<f64>,
    /// Whether the sub-box has been probed for the worst case ([`super::worst_case::Worst::probe`]), which is
    /// done once, the first time it is the lowest.
    pub(super) probed: bool,
}

/// How far past the roll rate where |delta_a| exceeds the aileron range a sub-box must be
/// certified before it is finished: two steps of the primary-branch walk of `analyze`, which
/// checks the range at steps at most [`MAX_STEP`](crate::analysis::primary::MAX_STEP) apart
/// (the second step in case the f64 value at the first rounds onto the range).
const BEYOND_MARGIN: f64 = 2.0 * crate::analysis::primary::MAX_STEP;

/// The largest roll rate the proof certifies to, rad/s. A sub-box is followed until its
/// branch leaves the aileron range, which for a box without jumps can lie far out (aircraft A
/// at delta_e = 0 reaches 90 deg of aileron near 80 rad/s); this cap keeps every enclosure
/// finite (the criterion polynomials have degree up to about 30 in P0) and the work bounded. A
/// sub-box that reaches it unfinished keeps it as its depth: no jump below it is proven.
pub const MAX_ROLL_RATE: f64 = 1000.0;

impl Leaf {
    /// The sub-box `theta` of `polys`, certified nowhere yet, its first slab `step` wide.
    pub(super) fn new(polys: &BoxPolys, theta: &[I], step: f64) -> Leaf {
        Leaf {
            lifted: Some(Arc::new(polys.lift(theta))),
            side: None,
            theta: theta.to_vec(),
            depth: 0.0,
            step,
            da_lo: 0.0,
            beyond_at: None,
            last: None,
            stuck: None,
            doubts: Vec::new(),
            searched_at: None,
            barrier: 0.0,
            run_from: None,
            turned: None,
            probed: false,
        }
    }

    /// The box lifted, made again from `theta` and `side` if it was dropped.
    fn lifted(&mut self, polys: &BoxPolys) -> Arc<LiftedBox> {
        let (theta, side) = (&self.theta, self.side);
        Arc::clone(
            self.lifted
                .get_or_insert_with(|| Arc::new(polys.lift_on_side(theta, side))),
        )
    }

    /// Drops the lifted data, keeping the branch's side to lift it again with.
    pub(super) fn drop_lifted(&mut self) {
        if let Some(l) = self.lifted.take() {
            self.side = l.side();
        }
    }

    /// Whether the sub-box is done with: finished or stuck, or at or past both targets, the
    /// roll rate `reach` and the aileron bound `da_target` (which only go down while a worst
    /// case is known, as hi does). It may still be stepped: as the lowest sub-box while a stuck
    /// one holds a bound below the target, or when a first worst case sets the aileron target;
    /// it is then lifted again (and the proof is the same, only slower).
    pub(super) fn retired(&self, reach: f64, da_target: f64) -> bool {
        self.finished()
            || self.stuck.is_some()
            || (self.p0_key() >= reach && self.da_key() >= da_target)
    }

    /// Whether the sub-box is proven to have no critical jump: along every aircraft's primary
    /// branch, |delta_a| (monotone before the first fold, Section 5 of docs/clearance.md)
    /// exceeds the aileron range at `beyond_at` with no jump, fold or divergence up to
    /// `beyond_at + BEYOND_MARGIN`, so `analyze`'s walk ends beyond the range (`Unbounded`)
    /// before it can meet a jump; or every branch turns back in P0 above the depth with no jump
    /// ([`Leaf::turned`]) and comes back down on an other trim that holds no jump within the
    /// range or ends at a barrier (no doubt left, docs/clearance.md step 6).
    pub(super) fn finished(&self) -> bool {
        self.beyond_at
            .is_some_and(|d| self.depth >= d + BEYOND_MARGIN)
            || (self.turned.is_some() && self.doubts.is_empty())
    }

    /// The proven lower bound of the critical jump roll rate on the sub-box: the certified
    /// depth or, below it, the lowest slab whose other trim may hold a jump; infinity for a
    /// finished sub-box (no critical jump at all: the minimum over an empty set).
    pub(super) fn p0_key(&self) -> f64 {
        if self.finished() {
            f64::INFINITY
        } else {
            self.doubt().map_or(self.depth, |d| d.lo.min(self.depth))
        }
    }

    /// The lowest doubtful slab, which bounds the sub-box.
    pub(super) fn doubt(&self) -> Option<I> {
        self.doubts.first().copied()
    }

    /// Records the other trim of the certified slab `slab`, the deepest so far.
    fn record_other_trim(&mut self, slab: I, other: OtherTrim) {
        match other {
            OtherTrim::BeyondRange => {
                let from = *self.run_from.get_or_insert(slab.lo);
                if slab.hi - from >= TURN_STEP {
                    self.raise_barrier(slab.hi);
                }
            }
            OtherTrim::NoJump => self.run_from = None,
            OtherTrim::MayJump => {
                self.run_from = None;
                self.doubts.push(slab);
            }
        }
    }

    /// The lower bound of |delta_a| at the critical jump, or infinity for a finished sub-box.
    pub(super) fn da_key(&self) -> f64 {
        if self.finished() {
            f64::INFINITY
        } else {
            self.da_lo
        }
    }

    /// Raises the barrier to `top` and drops what it shields of the doubts: those below it
    /// whole, and the part below it of one it cuts (a barrier found by
    /// [`Walk::search_barrier`] need not end on a slab's edge).
    fn raise_barrier(&mut self, top: f64) {
        self.barrier = self.barrier.max(top);
        let barrier = self.barrier;
        self.doubts.retain(|d| d.hi > barrier);
        for d in &mut self.doubts {
            *d = I::new(d.lo.max(barrier), d.hi);
        }
    }

    /// The proven minima over `leaves`: of the critical jump roll rate and of |delta_a| at it
    /// (each infinite when every sub-box is finished).
    pub(super) fn minima(leaves: &[Leaf]) -> (f64, f64) {
        let min = |key: fn(&Leaf) -> f64| leaves.iter().map(key).fold(f64::INFINITY, f64::min);
        (min(Leaf::p0_key), min(Leaf::da_key))
    }

    /// Raises `da_lo` to `lower` (a lower bound at `depth`) and records where it first exceeds
    /// `range`, the aileron range (infinite when |delta_a| is not monotone from 0).
    fn raise_aileron(&mut self, lower: f64, range: f64) {
        self.da_lo = self.da_lo.max(lower);
        if self.beyond_at.is_none() && self.da_lo > range * (1.0 + 1e-9) {
            self.beyond_at = Some(self.depth);
        }
    }
}

/// The widest turn zone tried above a sub-box held where its branch may turn
/// ([`BoxPolys::turn_back`]), rad/s.
const TURN_ZONE: f64 = 0.5;

/// Leaves of the branch and bound stepped at once (in parallel on rayon's threads).
pub(super) const BATCH: usize = 8;

/// What one step of a leaf needs: the box's polynomials, the initial box, the roll rate no
/// slab goes beyond, and the slab widths.
pub(super) struct Walk<'a> {
    pub(super) polys: &'a BoxPolys,
    pub(super) theta0: &'a [I],
    pub(super) limit: f64,
    pub(super) min_step: f64,
    pub(super) first_step: f64,
    /// The aileron range `analyze` follows the primary branch to, rad (infinite when the trim
    /// at P0 = 0 needs aileron for some aircraft: then |delta_a| is not bounded from 0).
    pub(super) range: f64,
    /// The aileron limit of the verdict, rad (infinite without one).
    pub(super) limit_rad: f64,
}

impl Walk<'_> {
    /// One step of `leaf`: its next slab certified (the leaf deeper, its step doubled), or
    /// not (the step quartered; at the smallest step the box split in two, or the leaf stuck
    /// when it cannot be). Returns the leaf and the other half of a split.
    pub(super) fn step(&self, leaf: &Leaf) -> (Leaf, Option<Leaf>) {
        let (polys, mut leaf) = (self.polys, leaf.clone());
        let lifted = leaf.lifted(polys);
        if let Some(doubt) = leaf.doubt() {
            // The doubt, not the depth, bounds this sub-box. Look for a barrier above it (once
            // per depth), else clear the doubt on halves of its slab while it is wider than the
            // smallest step. A doubt that neither clears stays, and the sub-box goes deeper as
            // usual: it may be finished (its branch leaves the range first), find a barrier
            // further up, reach a jump, or split (its halves check the doubt again).
            if leaf.searched_at != Some(leaf.depth) {
                leaf.searched_at = Some(leaf.depth);
                if self.search_barrier(&mut leaf, &lifted, doubt.hi) {
                    return (leaf, None);
                }
            }
            if doubt.width() > self.min_step {
                let m = doubt.mid();
                let halves = [I::new(doubt.lo, m), I::new(m, doubt.hi)];
                let left: Vec<I> = halves
                    .into_iter()
                    .filter(|h| !polys.other_trim(&lifted, *h, self.range).is_clear())
                    .collect();
                leaf.doubts.splice(0..1, left);
                return (leaf, None);
            }
            if leaf.turned.is_some() {
                // The branch turns back below the turn zone's top: going deeper proves nothing
                // more. The halves check the doubt again on their smaller boxes.
                return self.split(leaf, &lifted, doubt, Failure::Jump);
            }
        }
        let top = (leaf.depth + leaf.step).min(self.limit.max(leaf.depth + self.min_step));
        let slab = I::new(leaf.depth, top);
        let why = match polys.certify_with_other(&lifted, slab, self.range) {
            Ok((da, other)) => {
                leaf.record_other_trim(slab, other);
                leaf.last = None;
                leaf.depth = top;
                leaf.step *= 2.0;
                if let Some(lower) = polys.aileron_lower(&lifted, top) {
                    leaf.raise_aileron(lower, self.range);
                }
                self.raise_past_targets(&mut leaf, &lifted, da);
                return (leaf, None);
            }
            Err(why) => why,
        };
        leaf.last = Some(why);
        if leaf.step > self.min_step {
            leaf.step = (leaf.step / 4.0).max(self.min_step);
            return (leaf, None);
        }
        if why == Failure::Turn {
            // Before splitting: the branch may turn back, for every aircraft of the sub-box,
            // within a zone that holds no jump.
            let zone = polys.turn_back(&lifted, leaf.depth, self.min_step, TURN_ZONE);
            if let Some(top) = zone {
                leaf.turned = Some(top);
                return (leaf, None);
            }
        }
        self.split(leaf, &lifted, slab, why)
    }

    /// Raises `leaf`'s aileron bound past the aileron range, else past the aileron limit, when
    /// no aircraft of the sub-box has a trim within it at the depth
    /// ([`BoxPolys::no_trim_within`]), with a margin of 2e-9 relative (the range's test is 1e-9
    /// relative, the verdict's strict). Tried only where `da`, the enclosure of the branch's
    /// aileron over the slab just certified, reaches past the value: elsewhere the branch is
    /// within it and the test cannot succeed.
    fn raise_past_targets(&self, leaf: &mut Leaf, lifted: &LiftedBox, da: I) {
        if !self.range.is_finite() {
            return;
        }
        for target in [self.range, self.limit_rad] {
            let l = target * (1.0 + 2e-9);
            if !l.is_finite() || leaf.da_lo >= l || da.mag() <= l {
                continue;
            }
            if self.polys.no_trim_within(lifted, leaf.depth, l) {
                leaf.raise_aileron(l, self.range);
                return;
            }
        }
    }

    /// Looks, from the depth down to `from` (the top of the lowest doubt), for a slab of at
    /// least `TURN_STEP` whose other trim lies beyond the aileron range
    /// ([`BoxPolys::other_beyond_range`]; a sub-box's own slabs may not show one where its
    /// halves do), in 32 slabs at most; the highest one found becomes the barrier, and the doubts
    /// below it are dropped. Returns whether one was found.
    fn search_barrier(&self, leaf: &mut Leaf, lifted: &LiftedBox, from: f64) -> bool {
        let w = ((leaf.depth - from) / 32.0).max(TURN_STEP);
        let mut hi = leaf.depth;
        while hi - w >= from {
            let slab = I::new(hi - w, hi);
            if self.polys.other_beyond_range(lifted, slab, self.range) {
                leaf.raise_barrier(slab.hi);
                return true;
            }
            hi -= w;
        }
        false
    }

    /// Splits `leaf` (lifted: `parent`) in two because the slab `slab` failed with `why` at the
    /// smallest step (or the leaf stuck when it cannot be split); each half re-checks the other
    /// trim of its doubtful slabs on its smaller box.
    fn split(
        &self,
        mut leaf: Leaf,
        parent: &LiftedBox,
        slab: I,
        why: Failure,
    ) -> (Leaf, Option<Leaf>) {
        let polys = self.polys;
        // Split the coordinate that spreads the failing quantity most (its partial derivative
        // times the coordinate's width); the widest one (relative to the initial box) when that
        // cannot be told.
        let theta0 = self.theta0;
        let widest = (0..leaf.theta.len())
            .max_by(|a, b| {
                let r = |j: usize| leaf.theta[j].width() / theta0[j].width();
                r(*a).total_cmp(&r(*b))
            })
            .unwrap_or(0);
        let k = polys.split_coordinate(parent, slab, why).unwrap_or(widest);
        let t = leaf.theta[k];
        let m = t.mid();
        if m <= t.lo || m >= t.hi {
            leaf.stuck = Some(why);
            return (leaf, None);
        }
        let mut other = leaf.clone();
        leaf.theta[k] = I::new(t.lo, m);
        other.theta[k] = I::new(m, t.hi);
        leaf.step = self.first_step.max(self.min_step);
        other.step = leaf.step;
        (leaf.probed, other.probed) = (false, false);
        // The halves bound |delta_a| at their depth more tightly than the whole, and may clear
        // the other trim where the whole could not.
        for half in [&mut leaf, &mut other] {
            let lifted = Arc::new(polys.lift_part(&half.theta, parent));
            half.doubts
                .retain(|d| !polys.other_trim(&lifted, *d, self.range).is_clear());
            half.searched_at = None;
            if let Some(lower) = polys.aileron_lower(&lifted, half.depth) {
                half.raise_aileron(lower, self.range);
            }
            half.lifted = Some(lifted);
        }
        (leaf, Some(other))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::aircraft::{Aircraft, Param};

    /// A barrier shields only what lies below it: a doubt it cuts keeps its part above it, and
    /// one wholly below it goes.
    #[test]
    fn a_barrier_shields_only_what_lies_below_it() {
        let polys = BoxPolys::new(&Aircraft::a(), &[Param::Lp], 0.0);
        let mut leaf = Leaf::new(&polys, &[I::new(-22.0, -21.0)], 0.1);
        leaf.doubts = vec![I::new(1.0, 1.5), I::new(2.0, 2.4)];
        leaf.raise_barrier(2.375);
        assert_eq!(leaf.doubts, vec![I::new(2.375, 2.4)]);
        assert_eq!(leaf.doubt().map(|d| d.lo), Some(2.375));
        leaf.raise_barrier(2.4);
        assert!(leaf.doubts.is_empty());
    }

    /// A sub-box that dropped its lifted data (retired) and is stepped after all is lifted
    /// again from its box and its branch's side, and steps as it would have: the same depth,
    /// step, aileron bound and failure, slab after slab.
    #[test]
    fn a_retired_sub_box_stepped_again_steps_as_before() {
        let a = Aircraft::a();
        let polys = BoxPolys::new(&a, &[Param::Lp], 0.0);
        let theta0 = [I::new(-22.0, -21.0)];
        let walk = Walk {
            polys: &polys,
            theta0: &theta0,
            limit: 1.8,
            min_step: 1e-4,
            first_step: 0.05,
            range: a.aileron_range(),
            limit_rad: f64::INFINITY,
        };
        let (mut kept, mut dropped) = (Leaf::new(&polys, &theta0, 0.05), None);
        for slab in 0..12 {
            let mut again = dropped.unwrap_or_else(|| kept.clone());
            again.lifted = None;
            let (k, _) = walk.step(&kept);
            let (d, _) = walk.step(&again);
            let show = |l: &Leaf| (l.depth, l.step, l.da_lo, l.last, l.theta.clone());
            assert_eq!(show(&k), show(&d), "slab {slab}");
            assert!(d.lifted.is_some(), "slab {slab}: lifted again");
            (kept, dropped) = (k, Some(d));
        }
        assert!(kept.depth > 1.0, "the walk went on: {}", kept.depth);
        // Lifted again, a part keeps the branch's side it was given (by `lift_part`, its
        // parent's), not one computed afresh: a side the fresh lift would not give it.
        let fresh = polys.lift(&theta0).side().expect("a certain side");
        let mut part = Leaf::new(&polys, &theta0, 0.05);
        part.lifted = Some(Arc::new(polys.lift_on_side(&theta0, Some(-fresh))));
        part.drop_lifted();
        assert!(part.lifted.is_none());
        assert_eq!(part.lifted(&polys).side(), Some(-fresh));
    }
}
