//! The bifurcation diagram: branches of equilibria with their stability, the special points
//! found on them (folds, Hopf and branch points), and the zero-sideslip rudder schedule; its CSV
//! form.

use serde::Serialize;

/// One point of a branch: an equilibrium, the parameter that holds it and its stability (also
/// the point of a figure's branch, `plot::BranchPoint`).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Point {
    /// The parameter value, rad.
    pub param: f64,
    /// Angle of attack, rad.
    pub alpha: f64,
    /// Sideslip, rad.
    pub beta: f64,
    /// Roll rate, rad/s.
    pub p: f64,
    /// Pitch rate, rad/s.
    pub q: f64,
    /// Yaw rate, rad/s.
    pub r: f64,
    /// Every eigenvalue of J5 has a negative real part.
    pub stable: bool,
}

/// A connected piece of the equilibrium curve, its points in order along it (also a figure's
/// branch, `plot::Branch`).
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct Branch {
    /// The points, in order of arclength.
    pub points: Vec<Point>,
}

/// The kind of a special point.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum SpecialKind {
    /// Saddle-node (turning point in the parameter): a jump point of section IV.
    Fold,
    /// A complex pair of eigenvalues crosses the imaginary axis.
    Hopf,
    /// Two branches cross (transcritical or pitchfork), e.g. the zero-sideslip departure.
    Branch,
}

impl SpecialKind {
    /// `fold`, `hopf` or `branch`.
    pub fn name(self) -> &'static str {
        match self {
            SpecialKind::Fold => "fold",
            SpecialKind::Hopf => "hopf",
            SpecialKind::Branch => "branch",
        }
    }
}

/// A located special point.
#[derive(Clone, Debug, PartialEq)]
pub struct SpecialPoint {
    /// What it is.
    pub kind: SpecialKind,
    /// The parameter value, rad.
    pub param: f64,
    /// Angle of attack, rad.
    pub alpha: f64,
    /// Sideslip, rad.
    pub beta: f64,
    /// Roll rate P0, rad/s.
    pub p: f64,
    /// Pitch rate, rad/s.
    pub q: f64,
    /// Yaw rate, rad/s.
    pub r: f64,
    /// Hopf points: the imaginary part of the critical pair, rad/s.
    pub frequency: Option<f64>,
    /// Index into [`Diagram::branches`] of the branch it was found on.
    pub branch: usize,
    /// Whether the controls there are within the aircraft's `[limits]` (None: no limit given).
    pub within_limits: Option<bool>,
    /// Whether alpha and beta are within the aircraft's `[validity]` range.
    pub valid: bool,
}

/// A point of the zero-sideslip rudder schedule (EBA step 1).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct SchedulePoint {
    /// Aileron deflection, rad.
    pub delta_a: f64,
    /// Rudder deflection holding beta = 0, rad.
    pub delta_r: f64,
    /// Roll rate, rad/s.
    pub p: f64,
}

/// The bifurcation diagram. Serialises as
/// `{"aircraft", "parameter", "branches": [{"points": [{<parameter>, alpha, beta, p, q, r,
/// stable}]}], "special_points": [{kind, <parameter>, p, alpha, beta, q, r, [frequency]}]}`
/// plus `"rudder_schedule"` for a zero-sideslip diagram; `<parameter>` is the parameter's name.
#[derive(Clone, Debug, PartialEq)]
pub struct Diagram {
    /// Aircraft name.
    pub aircraft: String,
    /// The parameter's name: `delta_a`, `delta_e` or `delta_r`.
    pub parameter: String,
    /// Every branch found, in the order found (deterministic).
    pub branches: Vec<Branch>,
    /// Folds, then Hopf points, then branch points, each ascending in the parameter.
    pub special_points: Vec<SpecialPoint>,
    /// Zero-sideslip diagrams: the rudder schedule of EBA step 1, along the branch; else empty.
    pub rudder_schedule: Vec<SchedulePoint>,
}

impl Diagram {
    /// One row per point under the header
    /// `branch,<parameter>_rad,alpha_rad,beta_rad,p_rad_s,q_rad_s,r_rad_s,stable` (units in
    /// the names; shortest round-trip decimals, `stable` as 1 or 0).
    pub fn to_csv(&self) -> String {
        let mut s = format!(
            "branch,{}_rad,alpha_rad,beta_rad,p_rad_s,q_rad_s,r_rad_s,stable\n",
            self.parameter
        );
        for (i, b) in self.branches.iter().enumerate() {
            for p in &b.points {
                s += &format!(
                    "{i},{},{},{},{},{},{},{}\n",
                    p.param,
                    p.alpha,
                    p.beta,
                    p.p,
                    p.q,
                    p.r,
                    u8::from(p.stable)
                );
            }
        }
        s
    }

    /// The special points of one kind, in the order of [`Diagram::special_points`].
    pub fn special(&self, kind: SpecialKind) -> impl Iterator<Item = &SpecialPoint> {
        self.special_points.iter().filter(move |p| p.kind == kind)
    }
}
