//! Continuation and bifurcation analysis of the PSS equilibria: what the paper does
//! with AUTO2000 for Figs 1-4 (section II.B) and Fig. 9 (section V.B), so that every special
//! point can be set against the analytical criterion of section IV (`model::analysis`).
//!
//! * Equilibria of the PSS model of Appendix A.2, `f(x, u) = 0` with `x = [alpha, beta, p, q,
//!   r]`, are continued in one control ([`ContinuationParam`]: delta_a by default) by
//!   pseudo-arclength continuation with an adaptive step and a Newton corrector on the bordered
//!   system, using the model's symbolic Jacobian ([`crate::pss_model::PssModel`]); no finite
//!   differences anywhere.
//! * Stability of every point from the eigenvalues of J5. Folds (saddle-nodes: the jump points of
//!   section IV, Figs 1, 2, 7, 8), Hopf points (with their frequency; the filled squares of
//!   Fig. 2) and branch points are detected by test functions and located along the branch
//!   (folds and Hopf points to `locate_tol` in arclength; branch points, where the corrector is
//!   singular, from a cubic through nearby regular points, to about 1e-12 in practice); at each
//!   branch point the crossing branch is traced too.
//! * Every branch in the range is traced, not only the primary one: start points are the
//!   equilibria on a grid of roll rates, which the PSS equations give in closed form (section
//!   II.A; see `seeds` for the general case), so that the separate pieces of aircraft B's
//!   diagram (Fig. 2) are found without hand-picked starts. Traced branches claim the grid points
//!   they pass, so nothing is traced twice.
//! * A branch ends cleanly where the parameter leaves `[min, max]`, where a state reaches
//!   `max_state` in absolute value (near the divergence roll rates of Eq. 5 the trims blow up),
//!   or where it closes on itself; its last point then lies exactly on the bound.
//! * Zero sideslip (section V.B, the extended bifurcation analysis): step 1 continues
//!   `f = 0, beta = 0` with the rudder freed (Eq. 36) from the level trim, giving the rudder
//!   schedule delta_r(delta_a) up to its first turning point; step 2 continues the unconstrained
//!   model with the schedule substituted (Eq. 37). The schedule used in step 2 is the exact
//!   closed-form zero-sideslip trim (Eqs 32-35), parametrised by its roll rate; the
//!   zero-sideslip branch loses stability at a transcritical (branch) point, the departure of
//!   Fig. 9, where the crossing branch is traced by branch switching.
//!
//! ```
//! use model::aircraft::Aircraft;
//! use model::continuation::{continue_equilibria, Settings, SpecialKind};
//!
//! // Aircraft A for delta_a in [-0.1, 0.1] rad (the paper's range is +-0.8), roll rates up to
//! // 5 rad/s: the primary branch folds at its first jump on either side (Fig. 1).
//! let settings = Settings { min: -0.1, max: 0.1, max_state: 5.0, ..Settings::default() };
//! let d = continue_equilibria(&Aircraft::a(), &settings, &mut |_| {}).unwrap();
//! let folds: Vec<_> = d.special(SpecialKind::Fold).collect();
//! assert_eq!(folds.len(), 2);
//! // Mirror images: P0 -> -P0 with delta_a -> -delta_a; negative aileron rolls to positive p.
//! assert!((folds[0].p + folds[1].p).abs() < 1e-8 && folds.iter().all(|f| f.p * f.param < 0.0));
//! ```

// The files: what is asked (`settings.rs`), the pseudo-arclength engine (`engine.rs`), the
// systems continued (`systems.rs`), start points (`seeds.rs`), tracing every branch (`trace.rs`),
// the zero-sideslip analysis (`zero_sideslip.rs`), collecting what is found (`collect.rs`) and the
// result (`diagram.rs`, `json.rs`).
mod collect;
mod diagram;
mod engine;
mod json;
mod seeds;
mod settings;
mod systems;
mod trace;
mod zero_sideslip;

use crate::aircraft::Aircraft;
use crate::pss_model::PssModel;
use collect::Collect;
pub use diagram::{Branch, Diagram, Point, SchedulePoint, SpecialKind, SpecialPoint};
use settings::{check, limits};
pub use settings::{ContinuationError, ContinuationParam, Settings};
use trace::unconstrained;
use zero_sideslip::zero_sideslip;

/// Computes the bifurcation diagram of the PSS equilibria of `ac` (see the module docs).
///
/// `progress` is called with the fraction done, from 0 to 1, a few hundred times at most.
pub fn continue_equilibria(
    ac: &Aircraft,
    settings: &Settings,
    progress: &mut dyn FnMut(f64),
) -> Result<Diagram, ContinuationError> {
    check(settings)?;
    let model = PssModel::new(ac);
    let mut out = Collect::default();
    let rudder_schedule = if settings.zero_sideslip {
        zero_sideslip(&model, settings, &mut out, progress)?
    } else {
        unconstrained(&model, settings, &mut out, progress)?;
        Vec::new()
    };
    progress(1.0);
    let mut diagram = out.finish(
        ac.name.clone(),
        settings.param.name().to_string(),
        rudder_schedule,
    );
    mark(ac, settings, &mut diagram);
    Ok(diagram)
}

/// Marks every special point with the aircraft's limits and validity range. The controls there
/// are the settings' with the continuation parameter at the point's value; on a zero-sideslip
/// diagram the rudder is the schedule's at the point's aileron (linear between its points).
fn mark(ac: &Aircraft, settings: &Settings, d: &mut Diagram) {
    let schedule = &d.rudder_schedule;
    let rudder_at = |da: f64| -> Option<f64> {
        let w = schedule
            .windows(2)
            .find(|w| (w[0].delta_a - da) * (w[1].delta_a - da) <= 0.0)?;
        let (a, b) = (&w[0], &w[1]);
        let t = if b.delta_a == a.delta_a {
            0.0
        } else {
            (da - a.delta_a) / (b.delta_a - a.delta_a)
        };
        Some(a.delta_r + t * (b.delta_r - a.delta_r))
    };
    for sp in &mut d.special_points {
        let (mut da, mut de, mut dr) = (settings.delta_a, settings.delta_e, Some(settings.delta_r));
        match settings.param {
            ContinuationParam::DeltaA => da = sp.param,
            ContinuationParam::DeltaE => de = sp.param,
            ContinuationParam::DeltaR => dr = Some(sp.param),
        }
        if settings.zero_sideslip {
            dr = rudder_at(da);
        }
        sp.within_limits = ac.within_limits(da, de, dr);
        sp.valid = ac.valid(sp.alpha, sp.beta);
    }
}
