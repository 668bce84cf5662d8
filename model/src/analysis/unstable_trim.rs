//! The trim the primary branch starts from (P0 = 0, delta_a = 0), when it is unstable: the
//! eigenvalues of J5 there in the right half-plane, each with its motion (a real divergence or an
//! oscillation), its subsystem (pitch or lateral-directional, by its eigenvector) and, where the
//! decoupled subsystem's Routh-Hurwitz conditions say it, the derivatives that make it so.
//!
//! A bare airframe with a statically unstable pitch (Cm_alpha > 0, as flown behind a stability
//! augmentation system) starts the roll from an equilibrium it cannot hold: the jump and Hopf
//! points further along the branch then describe an airframe that needs its augmentation first.
//!
//! At P0 = 0 with delta_a = delta_r = 0 the trim has no sideslip and no yaw rate, and J5 falls
//! into the pitch block (alpha, q) and the lateral-directional block (beta, p, r). Each block's
//! conditions for stability are exact statements about its entries, which are the model's
//! derivatives at the trim (the ones a gyroscopic term at a trim pitch rate Q0 changes are named
//! with it):
//!
//! - pitch, `[[z_alpha, 1], [m_alpha, m_q]]`: stable if and only if its determinant
//!   `z_alpha m_q - m_alpha > 0` (else a real divergence: static pitch instability) and its trace
//!   `z_alpha + m_q < 0`;
//! - lateral-directional, with characteristic polynomial `s^3 + a1 s^2 + a2 s + a3`: stable if
//!   and only if `a1 > 0`, `a3 > 0` and `a1 a2 > a3`. `a3 = -det` and, expanded along the roll
//!   rate's column, the determinant is the sum of `l_p (n_beta + y_beta n_r)`,
//!   `n_p (l_beta + y_beta l_r)` negated and `(alpha0 + alpha_t) (l_beta n_r - l_r n_beta)`
//!   negated: roll damping times the directional subsystem (beta, r), the roll-yaw coupling
//!   through n_p, and the kinematic coupling of the principal axis' angle of attack with the
//!   spiral combination.
//!   A positive det is a real divergence, and the terms that make it positive are named.
//!
//! ```
//! use model::analysis::unstable_trim::{start, Start};
//! use nalgebra::Matrix5;
//!
//! // z_alpha = -1, m_q = -1, m_alpha = 5: the pitch block's characteristic polynomial is
//! // s^2 + 2 s - 4, with the root sqrt(5) - 1; the lateral block [[-1, 0, -1], [0, -2, 0],
//! // [1, 0, -1]] is stable (roots -2 and -1 +- i).
//! let mut j = Matrix5::zeros();
//! j[(0, 0)] = -1.0; j[(0, 3)] = 1.0; j[(3, 0)] = 5.0; j[(3, 3)] = -1.0;
//! j[(1, 1)] = -1.0; j[(1, 4)] = -1.0; j[(2, 2)] = -2.0; j[(4, 1)] = 1.0; j[(4, 4)] = -1.0;
//! let Start::Unstable(u) = start(&j, &[0.0; 5]) else { panic!("unstable") };
//! assert_eq!(u.modes.len(), 1);
//! let m = &u.modes[0];
//! assert!((m.eigenvalue_re - (5f64.sqrt() - 1.0)).abs() < 1e-12);
//! assert_eq!((m.motion, m.subsystem), ("divergence", "pitch"));
//! assert!(m.cause.as_deref().unwrap().starts_with("static pitch instability"));
//! ```

use super::departure::null_vector;
use nalgebra::{Complex, Matrix5};
use serde::Serialize;

/// The states of the pitch block, as indices of x = [alpha, beta, p, q, r].
const PITCH: [usize; 2] = [0, 3];
/// The states of the lateral-directional block.
const LATERAL: [usize; 3] = [1, 2, 4];

/// A real part within this fraction of J5's largest entry is zero within rounding (the
/// eigenvalues of a 5x5 matrix carry errors of order `eps |J5|`, more where it is nearly
/// defective); such an eigenvalue doubles no faster than in `1e9 / |J5|` seconds.
const NEUTRAL: f64 = 1e-9;

/// One unstable mode of the trim: an eigenvalue of J5 in the right half-plane (a complex pair
/// once, with its positive imaginary part).
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct UnstableMode {
    /// Real part of the eigenvalue, 1/s (positive: the time to double is ln 2 over it).
    pub eigenvalue_re: f64,
    /// Imaginary part, rad/s: zero for a divergence, the frequency of an oscillation.
    pub eigenvalue_im: f64,
    /// `"divergence"` (a real eigenvalue) or `"oscillation"` (a complex pair).
    pub motion: &'static str,
    /// `"pitch"` (its eigenvector lies in alpha and q), `"lateral-directional"` (in beta, p, r)
    /// or `"coupled"`.
    pub subsystem: &'static str,
    /// The derivatives that make it so, from the decoupled subsystem's stability conditions;
    /// absent where the blocks are coupled (or the mode lies on a condition's boundary).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub cause: Option<String>,
}

/// The unstable trim at P0 = 0, delta_a = 0: where it is and its unstable modes.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct UnstableTrim {
    /// Trim angle of attack, rad.
    pub alpha: f64,
    /// Trim sideslip, rad.
    pub beta: f64,
    /// Trim pitch rate, rad/s.
    pub q: f64,
    /// Trim yaw rate, rad/s.
    pub r: f64,
    /// The unstable modes, fastest first.
    pub modes: Vec<UnstableMode>,
}

/// Whether the primary branch's start holds.
#[derive(Clone, Debug, PartialEq)]
pub enum Start {
    /// Every eigenvalue of J5 in the open left half-plane.
    Stable,
    /// At least one eigenvalue clearly in the right half-plane.
    Unstable(UnstableTrim),
    /// Neither: an eigenvalue on the imaginary axis within rounding (and none beyond it), or
    /// eigenvalues that cannot be computed ([`crate::spectrum::eigenvalues`]).
    Undecided,
}

/// The stability of the trim `trim = [alpha0, beta0, P0, Q0, R0]` whose Jacobian is `j5`.
pub fn start(j5: &Matrix5<f64>, trim: &[f64; 5]) -> Start {
    let Some(eigenvalues) = crate::spectrum::eigenvalues(j5) else {
        return Start::Undecided;
    };
    if eigenvalues.iter().all(|l| l.re < 0.0) {
        return Start::Stable;
    }
    let scale = j5.iter().fold(0.0, |m: f64, v| m.max(v.abs()));
    let mut modes: Vec<UnstableMode> = eigenvalues
        .iter()
        .filter(|l| l.re > NEUTRAL * scale && l.im >= 0.0)
        .map(|l| mode(j5, *l, trim))
        .collect();
    if modes.is_empty() {
        return Start::Undecided;
    }
    modes.sort_by(|a, b| b.eigenvalue_re.total_cmp(&a.eigenvalue_re));
    // `+ 0.0` reports a trim that is zero as 0, not -0.
    Start::Unstable(UnstableTrim {
        alpha: trim[0] + 0.0,
        beta: trim[1] + 0.0,
        q: trim[3] + 0.0,
        r: trim[4] + 0.0,
        modes,
    })
}

/// The mode of the eigenvalue `l` of `j` at `trim`.
fn mode(j: &Matrix5<f64>, l: Complex<f64>, trim: &[f64; 5]) -> UnstableMode {
    // A 2x2 block with real roots can leave a rounding-sized imaginary part.
    let real = l.im.abs() <= 1e-12 * l.norm();
    let motion = if real { "divergence" } else { "oscillation" };
    let subsystem = subsystem(j, l);
    let cause = match subsystem {
        _ if !decoupled(j) => None,
        "pitch" => pitch_cause(j, real),
        "lateral-directional" => lateral_cause(j, real, trim),
        _ => None,
    };
    UnstableMode {
        eigenvalue_re: l.re,
        eigenvalue_im: if real { 0.0 } else { l.im },
        motion,
        subsystem,
        cause,
    }
}

/// The subsystem of the eigenvalue `l` of `j`: where its eigenvector lies (99 % of its squared
/// length in alpha and q: pitch; 1 % or less: lateral-directional; else coupled).
fn subsystem(j: &Matrix5<f64>, l: Complex<f64>) -> &'static str {
    let a = j.map(|v| Complex::new(v, 0.0)) - Matrix5::from_diagonal_element(l);
    let Some(v) = null_vector(&a) else {
        return "coupled";
    };
    let pitch: f64 = PITCH.iter().map(|&i| v[i].norm_sqr()).sum();
    let share = pitch / v.norm_squared();
    if share >= 0.99 {
        "pitch"
    } else if share <= 0.01 {
        "lateral-directional"
    } else {
        "coupled"
    }
}

/// Whether the pitch and lateral-directional blocks of `j` are decoupled (every entry between
/// them zero within rounding), so that each block's conditions are the whole story of its modes.
fn decoupled(j: &Matrix5<f64>) -> bool {
    let scale = j.iter().fold(0.0, |m: f64, v| m.max(v.abs()));
    PITCH.iter().all(|&p| {
        LATERAL
            .iter()
            .all(|&l| j[(p, l)].abs() <= 1e-12 * scale && j[(l, p)].abs() <= 1e-12 * scale)
    })
}

/// Why the pitch block `[[z_alpha, 1], [m_alpha, m_q]]` of `j` is unstable: a negative
/// determinant (one real root > 0, static instability) or a positive trace (both roots with
/// positive real part, too little damping).
fn pitch_cause(j: &Matrix5<f64>, real: bool) -> Option<String> {
    let (za, ma, mq) = (j[(0, 0)], j[(3, 0)], j[(3, 3)]);
    let det = za * mq - j[(0, 3)] * ma;
    let trace = za + mq;
    if det < 0.0 && real {
        Some(format!(
            "static pitch instability: m_alpha = {} 1/s^2 exceeds z_alpha m_q = {} 1/s^2 (the \
             pitch subsystem (alpha, q) has determinant z_alpha m_q - m_alpha = {} 1/s^2 < 0)",
            significant(ma),
            significant(za * mq),
            significant(det)
        ))
    } else if trace > 0.0 {
        Some(format!(
            "pitch damping: z_alpha + m_q = {} 1/s > 0 (the trace of the pitch subsystem \
             (alpha, q))",
            significant(trace)
        ))
    } else {
        None
    }
}

/// Why the lateral-directional block of `j` (beta, p, r) is unstable, by the Routh-Hurwitz
/// conditions of its characteristic polynomial `s^3 + a1 s^2 + a2 s + a3` (see the module's
/// doc): `det > 0` for a real divergence (its positive terms named), `a1 < 0` (too little
/// damping), else `a1 a2 <= a3` (an oscillation, or two real roots > 0).
fn lateral_cause(j: &Matrix5<f64>, real: bool, trim: &[f64; 5]) -> Option<String> {
    let [b, p, r] = LATERAL;
    let e = |i: usize, k: usize| j[(i, k)];
    let trace = e(b, b) + e(p, p) + e(r, r);
    let directional = e(b, b) * e(r, r) - e(b, r) * e(r, b);
    let terms = [
        (
            e(p, p) * directional,
            format!(
                "roll damping times the directional subsystem (beta, r), l_p (n_beta + y_beta \
                 n_r) = {} x {}",
                significant(e(p, p)),
                significant(directional)
            ),
        ),
        (
            -e(r, p) * (e(b, b) * e(p, r) - e(b, r) * e(p, b)),
            format!(
                "roll-yaw coupling, -{} (l_beta + y_beta {})",
                n_p(trim),
                l_r(trim)
            ),
        ),
        (
            -e(b, p) * (e(p, b) * e(r, r) - e(p, r) * e(r, b)),
            format!(
                "the kinematic coupling p (alpha0 + alpha_t) with the spiral combination, \
                 -(alpha0 + alpha_t) (l_beta n_r - {} n_beta)",
                l_r(trim)
            ),
        ),
    ];
    let det: f64 = terms.iter().map(|(v, _)| v).sum();
    let minors =
        e(b, b) * e(p, p) - e(b, p) * e(p, b) + directional + e(p, p) * e(r, r) - e(p, r) * e(r, p);
    let (a1, a2, a3) = (-trace, minors, -det);
    if real && det > 0.0 {
        let positive: Vec<String> = terms
            .iter()
            .filter(|(v, _)| *v > 0.0)
            .map(|(v, what)| format!("{what} = {}", significant(*v)))
            .collect();
        Some(format!(
            "lateral-directional divergence: the subsystem (beta, p, r) has determinant {} > 0 \
             (stable needs < 0), made positive by {}",
            significant(det),
            positive.join(" and by ")
        ))
    } else if a1 < 0.0 {
        Some(format!(
            "lateral-directional damping: y_beta + l_p + n_r = {} 1/s > 0 (the trace of the \
             subsystem (beta, p, r))",
            significant(trace)
        ))
    } else if a1 * a2 <= a3 {
        // With a1 > 0 and a3 > 0 (the cases above excluded) only this condition can fail.
        Some(format!(
            "lateral-directional {}: the subsystem (beta, p, r) has characteristic polynomial \
             s^3 + a1 s^2 + a2 s + a3 with a1 a2 - a3 = {} (a1 = {}, a2 = {}, a3 = {}; stable \
             needs a1 a2 > a3), its directional subsystem (beta, r) determinant n_beta + \
             y_beta n_r = {} and damping y_beta + n_r = {}",
            if real { "instability" } else { "oscillation" },
            significant(a1 * a2 - a3),
            significant(a1),
            significant(a2),
            significant(a3),
            significant(directional),
            significant(e(b, b) + e(r, r))
        ))
    } else {
        None
    }
}

/// The name of J5's entry `d r_dot / d p` at the trim: n_p, with the gyroscopic `-D Q0` when the
/// trim pitches.
fn n_p(trim: &[f64; 5]) -> &'static str {
    if trim[3] == 0.0 {
        "n_p"
    } else {
        "(n_p - D Q0)"
    }
}

/// The name of J5's entry `d p_dot / d r` at the trim: l_r, with `-E Q0` when the trim pitches.
fn l_r(trim: &[f64; 5]) -> &'static str {
    if trim[3] == 0.0 {
        "l_r"
    } else {
        "(l_r - E Q0)"
    }
}

/// `x` to four significant digits as a plain decimal (never in exponent form, so that it reads
/// beside the fixed decimals of the rest of the output; at most 12 decimals, so that a value
/// below 5e-13 prints as 0), never `-0`: how the causes, `analyze`'s text and the summary print
/// the numbers of an unstable trim and the first Lyapunov coefficients.
pub fn significant(x: f64) -> String {
    if x == 0.0 || !x.is_finite() {
        return if x == 0.0 { "0".into() } else { x.to_string() };
    }
    let magnitude = x.abs().log10().floor() as i32;
    let digits = (3 - magnitude).clamp(0, 12) as usize;
    let s = format!("{x:.digits$}");
    if s.chars().all(|c| matches!(c, '-' | '0' | '.')) {
        return "0".into();
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    /// J5 with the pitch block `pitch` and a stable lateral block (roots -2 and -1 +- i).
    fn with_pitch(pitch: [[f64; 2]; 2]) -> Matrix5<f64> {
        let mut j = Matrix5::zeros();
        for (r, row) in PITCH.iter().zip(pitch) {
            for (c, v) in PITCH.iter().zip(row) {
                j[(*r, *c)] = v;
            }
        }
        let lateral = [[-1.0, 0.0, -1.0], [0.0, -2.0, 0.0], [1.0, 0.0, -1.0]];
        for (r, row) in LATERAL.iter().zip(lateral) {
            for (c, v) in LATERAL.iter().zip(row) {
                j[(*r, *c)] = v;
            }
        }
        j
    }

    /// s^2 - s + 4.25 (trace 1, determinant 4.25): the pair 0.5 +- 2 i, a pitch oscillation
    /// from too little damping.
    #[test]
    fn a_positive_pitch_trace_is_an_oscillation_for_lack_of_damping() {
        let Start::Unstable(u) = start(&with_pitch([[0.5, 1.0], [-4.0, 0.5]]), &[0.0; 5]) else {
            panic!("unstable");
        };
        let [m] = u.modes.as_slice() else {
            panic!("{u:?}")
        };
        assert!((m.eigenvalue_re - 0.5).abs() < 1e-12 && (m.eigenvalue_im - 2.0).abs() < 1e-12);
        assert_eq!((m.motion, m.subsystem), ("oscillation", "pitch"));
        assert!(m
            .cause
            .as_deref()
            .unwrap()
            .starts_with("pitch damping: z_alpha + m_q = 1.000"));
    }

    /// A zero eigenvalue (m_alpha = 0, z_alpha = 0) and every other in the left half-plane:
    /// neutral, neither stable nor unstable; all in the left half-plane: stable.
    #[test]
    fn a_neutral_trim_is_undecided_and_a_stable_one_stable() {
        assert_eq!(
            start(&with_pitch([[0.0, 1.0], [0.0, -1.0]]), &[0.0; 5]),
            Start::Undecided
        );
        assert_eq!(
            start(&with_pitch([[-1.0, 1.0], [-5.0, -1.0]]), &[0.0; 5]),
            Start::Stable
        );
    }

    #[test]
    fn significant_digits_never_print_negative_zero() {
        assert_eq!(significant(0.2945123), "0.2945");
        assert_eq!(significant(-4.0), "-4.000");
        assert_eq!(significant(1234.5678), "1235");
        assert_eq!(significant(2.5e-7), "0.0000002500");
        assert_eq!(significant(-2.986e-8), "-0.00000002986");
        assert_eq!(significant(1.5e7), "15000000");
        assert_eq!(significant(-1e-14), "0");
        assert_eq!(significant(-0.0), "0");
    }
}
