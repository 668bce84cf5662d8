//! Branches and special points as they are found: each branch's points, special points
//! de-duplicated across the branches they lie on, and the finished diagram.

use super::engine::{self, Found, Half, Kind, Node, System, V6};
use super::{Branch, Diagram, Point, SchedulePoint, SpecialKind, SpecialPoint};

/// Branches and special points as they are found.
#[derive(Default)]
pub(super) struct Collect {
    pub(super) branches: Vec<Branch>,
    /// The continuation points of each branch.
    paths: Vec<Vec<V6>>,
    specials: Vec<SpecialPoint>,
    /// Located points (z) of each special point, for de-duplication, with the branches it was
    /// found on.
    seen: Vec<(SpecialKind, V6, Vec<usize>)>,
}

impl Collect {
    /// Adds a branch made of `minus` (reversed), `start` and `plus`; returns the branch points
    /// that are new (not yet seen) for branch switching.
    pub(super) fn add<S: System>(
        &mut self,
        sys: &S,
        start: &Node,
        plus: Half,
        minus: Option<Half>,
    ) -> Vec<Node> {
        let id = self.branches.len();
        let to_point = |n: &Node| {
            let (x, mu) = sys.physical(&n.z);
            Point {
                param: mu,
                alpha: x[0],
                beta: x[1],
                p: x[2],
                q: x[3],
                r: x[4],
                stable: n.stable,
            }
        };
        let mut nodes: Vec<&Node> = Vec::new();
        let mut found: Vec<Found> = Vec::new();
        if let Some(m) = &minus {
            nodes.extend(m.nodes.iter().rev());
        }
        nodes.push(start);
        nodes.extend(plus.nodes.iter());
        self.branches.push(Branch {
            points: nodes.iter().map(|n| to_point(n)).collect(),
        });
        self.paths.push(nodes.iter().map(|n| n.z).collect());
        if let Some(m) = minus {
            found.extend(m.found);
        }
        found.extend(plus.found);
        let mut new_bps = Vec::new();
        for f in found {
            let kind = match f.kind {
                Kind::Fold => SpecialKind::Fold,
                Kind::Hopf => SpecialKind::Hopf,
                Kind::Branch => SpecialKind::Branch,
            };
            let z = f.node.z;
            if let Some(i) = self.find(kind, &z) {
                if !self.seen[i].2.contains(&id) {
                    self.seen[i].2.push(id);
                }
                continue;
            }
            self.seen.push((kind, z, vec![id]));
            let (x, mu) = sys.physical(&z);
            self.specials.push(SpecialPoint {
                kind,
                param: mu,
                alpha: x[0],
                beta: x[1],
                p: x[2],
                q: x[3],
                r: x[4],
                frequency: f.frequency,
                branch: id,
                within_limits: None,
                valid: true,
            });
            if kind == SpecialKind::Branch {
                new_bps.push(f.node);
            }
        }
        new_bps
    }

    /// The index in `seen` of a special point of this kind at `z`.
    pub(super) fn find(&self, kind: SpecialKind, z: &V6) -> Option<usize> {
        self.seen
            .iter()
            .position(|(k, w, _)| *k == kind && (w - z).norm() <= 1e-6 * (1.0 + z.norm()))
    }

    /// Whether a traced branch passes through `z`.
    pub(super) fn on_a_branch(&self, z: &V6) -> bool {
        let tol = 1e-6 * (1.0 + z.norm());
        self.paths.iter().any(|p| {
            p.windows(2)
                .any(|w| engine::dist_to_segment(z, &w[0], &w[1]) <= tol)
        })
    }

    /// Whether both branches through a branch point have been traced.
    pub(super) fn crossed_twice(&self, z: &V6) -> bool {
        self.find(SpecialKind::Branch, z)
            .is_some_and(|i| self.seen[i].2.len() >= 2)
    }

    pub(super) fn finish(
        mut self,
        aircraft: String,
        parameter: String,
        rudder_schedule: Vec<SchedulePoint>,
    ) -> Diagram {
        // A turning point in the parameter exactly at a branch point (the rolling branch at a
        // pitchfork of the symmetric branch) is the branch point, not a saddle-node.
        let bps: Vec<V6> = self
            .seen
            .iter()
            .filter(|s| s.0 == SpecialKind::Branch)
            .map(|s| s.1)
            .collect();
        let mut keep = self.seen.iter().map(|(k, z, _)| {
            *k != SpecialKind::Fold
                || !bps
                    .iter()
                    .any(|b| (b - z).norm() <= 1e-5 * (1.0 + z.norm()))
        });
        self.specials.retain(|_| keep.next().unwrap_or(true));
        self.specials.sort_by(|a, b| {
            a.kind
                .cmp(&b.kind)
                .then(a.param.total_cmp(&b.param))
                .then(a.p.total_cmp(&b.p))
        });
        Diagram {
            aircraft,
            parameter,
            branches: self.branches,
            special_points: self.specials,
            rudder_schedule,
        }
    }
}
