//! The jump part of the exact path (`analyze --exact` without departures): the criterion
//! polynomials specialised in big rationals, their roots, and the jump analysis they give; shared
//! by [`super::analyze_with`] and the first departure's fallback in [`super::fast`].

use super::primary::Walk;
use super::{
    cancel, eval_trim, in_aileron, in_aileron_all, parametric, positive_roots, strip, univariate,
    Analysis, AnalysisError, CriterionPolys, Found,
};
use crate::aircraft::Aircraft;
use crate::algebra::{Poly, Sym};
use crate::equations::symbols;
use crate::roots::RealRoot;

/// The jump part of the exact path: the exact criterion polynomials, what their roots give, and
/// the jump analysis with the index of its critical jump (as [`Found::assemble`]).
pub(crate) struct ExactJumpPart {
    /// The exact criterion polynomials.
    pub d: CriterionPolys,
    /// Their roots and the f64 polynomials evaluated at them.
    pub found: Found,
    /// The f64 walk of the primary branch on them ([`Found::walk`]).
    pub walk: Walk,
    /// The jump part of the analysis (no Hopf points, landings or first departure).
    pub analysis: Analysis,
    /// The index of the critical jump in `analysis.jump`.
    pub critical: Option<usize>,
}

/// [`ExactJumpPart`] of `aircraft` at elevator `delta_e_rad` (already checked), or why the
/// exact path refuses the data.
pub(crate) fn exact_jump_part(
    aircraft: &Aircraft,
    delta_e_rad: f64,
) -> Result<ExactJumpPart, AnalysisError> {
    let s = symbols();
    let d = CriterionPolys::new(parametric(), aircraft, delta_e_rad);
    let u = |p: &Poly| univariate(p, s.p0);

    let det_a = u(&d.det_a);
    if det_a.is_zero() {
        return Err(AnalysisError::Degenerate("det A"));
    }
    if d.jump.is_zero() {
        return Err(AnalysisError::Degenerate("det J5"));
    }
    let values = |roots: Vec<RealRoot>| roots.iter().map(|r| r.value).collect::<Vec<f64>>();
    // Every root shared with det A is a trim at infinity (divergence), not a pole on the curve;
    // a root shared with det A after cancellation has no finite trim: not a jump point.
    let zs_det = u(&d.zs_det);
    let zs_num = strip(&cancel(&u(&d.zs_jump), &u(&d.zs_d_det)).0, &zs_det);
    // det A's roots are taken out of the jump and pole polynomials before their common factors
    // are cancelled: with aileron yaw both hold det A to a high power, which the cancellation's
    // gcd (a pseudo-remainder sequence on large coefficients) would otherwise carry. The jump
    // roots are the same: every factor left is coprime to det A, so cancelling it is unchanged,
    // and what cancelling the det A factors would leave is stripped afterwards anyway.
    let poles = strip(&d.poles, &det_a);
    let found = Found {
        divergence: values(positive_roots(&det_a)),
        jump_roots: values(positive_roots(&cancel(&strip(&d.jump, &det_a), &poles).0)),
        pole_roots: values(positive_roots(&poles)),
        zs_roots: values(positive_roots(&zs_num)),
        g: in_aileron(&d.trim_condition),
        // The trim numerators share det A's scale, so that their ratios are the trim.
        trims: in_aileron_all(&[&d.det_a, &d.trim[0], &d.trim[1], &d.trim[2], &d.trim[3]]),
        jump_at: in_aileron(&d.jump_at),
        d_at: in_aileron(&d.d_at),
        // Numerators share the determinant's scale (see `in_aileron_all`).
        zs_trims: in_aileron_all(&[&d.zs_det, &d.zs_trim[0], &d.zs_trim[1], &d.zs_trim[2]]),
        // Without lateral control authority (l_delta_a n_delta_r = l_delta_r n_delta_a) no
        // zero-sideslip trim exists: there is nothing to report.
        lateral_authority: !d.zs_delta_a.den.is_zero(),
    };
    let zs_controls =
        |at: &[(Sym, f64)]| (eval_trim(&d.zs_delta_a, at), eval_trim(&d.zs_delta_r, at));
    let walk = found.walk(aircraft);
    let (analysis, critical) = found.assemble(aircraft, delta_e_rad, &zs_controls, &walk);
    Ok(ExactJumpPart {
        d,
        found,
        walk,
        analysis,
        critical,
    })
}
