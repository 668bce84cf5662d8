//! Numbers as the tool prints them: fixed decimals that never show `-0.0000`, lists with their
//! unit (or `none`), the cells of the jump, Hopf and departure rows of `analyze`'s tables and the
//! report's summary, and the text on the first loss of stability of the primary branch.
//!
//! ```
//! use model::present::numbers::{fixed, list};
//!
//! // Never "-0.0000", and "none" for an empty list.
//! assert_eq!(fixed(-0.00001, 4), "0.0000");
//! assert_eq!(list(&[1.23456, 2.5], 2, "rad/s"), "1.23, 2.50 rad/s");
//! assert_eq!(list(&[], 6, "rad/s"), "none");
//! ```

use crate::analysis::unstable_trim::{significant, UnstableTrim};
use crate::analysis::{Analysis, DeparturePoint, HopfPoint, JumpPoint};

/// `x` with `digits` decimals, never `-0.0000` (a value that rounds to zero prints as zero).
pub fn fixed(x: f64, digits: usize) -> String {
    let s = format!("{x:.digits$}");
    match s.strip_prefix('-') {
        Some(rest) if rest.chars().all(|c| c == '0' || c == '.') => rest.to_string(),
        _ => s,
    }
}

/// `v` with `digits` decimals, comma-separated and followed by `unit`, or `none`.
pub fn list(v: &[f64], digits: usize, unit: &str) -> String {
    if v.is_empty() {
        "none".into()
    } else {
        let v: Vec<String> = v.iter().map(|x| fixed(*x, digits)).collect();
        format!("{} {unit}", v.join(", "))
    }
}

/// Which instability the primary branch meets first (an unstable trim at its start with its
/// unstable modes, a jump, or a Hopf point with its frequency, first Lyapunov coefficient and
/// kind, marked where its trim lies outside the validity range) and where a jump lands, as
/// `analyze` prints it and the summary repeats it: lines ending in a blank line.
pub fn first_departure_text(a: &Analysis) -> String {
    let Some(f) = &a.first_departure else {
        return "First loss of stability on the primary branch: none within the aileron range.\n\n"
            .into();
    };
    if let Some(u) = &f.unstable_trim {
        return unstable_trim_text(u);
    }
    let mut s = format!(
        "First loss of stability on the primary branch: {} at P0 = {} rad/s, delta_a = {} deg",
        if f.kind == "jump" { "JUMP" } else { "HOPF" },
        fixed(f.p0, 6),
        fixed(f.delta_a_deg, 4)
    );
    if let (Some(w), Some(l1), Some(k)) = (f.omega, f.l1, f.hopf_kind) {
        s += &format!(
            " (oscillation omega = {} rad/s, l1 = {}, {k})",
            fixed(w, 4),
            significant(l1)
        );
    }
    if let (Some(alpha), Some(beta)) = (f.alpha, f.beta) {
        s += &validity_mark(alpha, beta, a);
    }
    s += "\n";
    if let Some(l) = &f.lands_at {
        if l.is_empty() {
            s += "  the jump lands on no stable equilibrium (divergence)\n";
        }
        for e in l {
            s += &format!(
                "  lands at P0 = {} rad/s (jump {} rad/s), alpha = {} deg, beta = {} deg{}\n",
                fixed(e.p0, 6),
                fixed(e.p0 - f.p0, 6),
                fixed(e.alpha.to_degrees(), 4),
                fixed(e.beta.to_degrees(), 4),
                validity_mark(e.alpha, e.beta, a)
            );
        }
    }
    s + "\n"
}

/// `  [outside validity range: ...]` naming the angle beyond the aircraft's validity range, or
/// nothing within it.
pub fn validity_mark(alpha: f64, beta: f64, a: &Analysis) -> String {
    let v = &a.validity;
    let beyond: Vec<String> = [
        ("alpha", alpha, v.alpha_max_deg),
        ("beta", beta, v.beta_max_deg),
    ]
    .into_iter()
    .filter(|(_, x, max)| x.to_degrees().abs() > *max)
    .map(|(name, x, max)| {
        format!(
            "|{name}| = {} deg > {max} deg",
            fixed(x.to_degrees().abs(), 1)
        )
    })
    .collect();
    if beyond.is_empty() {
        String::new()
    } else {
        format!("  [outside validity range: {}]", beyond.join(", "))
    }
}

/// The unstable start of the primary branch: the bare airframe cannot hold the trim, each
/// unstable mode with its eigenvalue, time to double (or frequency) and cause.
fn unstable_trim_text(u: &UnstableTrim) -> String {
    let mut s = format!(
        "First loss of stability on the primary branch: UNSTABLE TRIM at its start, P0 = 0, \
         delta_a = 0 (alpha = {} deg, q = {} rad/s)\n  the bare airframe is unstable at this \
         flight state and needs its stability augmentation: the jump and Hopf figures of this \
         analysis describe an airframe that cannot hold the trim unaided\n",
        fixed(u.alpha.to_degrees(), 4),
        fixed(u.q, 5)
    );
    for m in &u.modes {
        let eigenvalue = if m.eigenvalue_im == 0.0 {
            format!(
                "eigenvalue {} 1/s, time to double {} s",
                significant(m.eigenvalue_re),
                significant(std::f64::consts::LN_2 / m.eigenvalue_re)
            )
        } else {
            format!(
                "eigenvalues {} +- {} i 1/s, period {} s",
                significant(m.eigenvalue_re),
                significant(m.eigenvalue_im),
                significant(2.0 * std::f64::consts::PI / m.eigenvalue_im)
            )
        };
        s += &format!("  {} {}: {eigenvalue}", m.subsystem, m.motion);
        if let Some(c) = &m.cause {
            s += &format!("\n    {c}");
        }
        s += "\n";
    }
    s + "\n"
}

/// The cells of a reported point's row, as `analyze` and the summary print them: P0 (rad/s),
/// delta_a, alpha and beta (deg).
fn point_cells(j: &JumpPoint) -> [String; 4] {
    [
        fixed(j.p0, 6),
        fixed(j.delta_a_deg, 4),
        fixed(j.alpha.to_degrees(), 4),
        fixed(j.beta.to_degrees(), 4),
    ]
}

/// The cells of a jump point's row: P0 (rad/s), delta_a, alpha, beta (deg), q and r (rad/s).
pub fn jump_cells(j: &JumpPoint) -> [String; 6] {
    let [p0, da, alpha, beta] = point_cells(j);
    [p0, da, alpha, beta, fixed(j.q, 5), fixed(j.r, 5)]
}

/// The cells of a Hopf point's row: P0 (rad/s), delta_a, alpha, beta (deg), omega (rad/s),
/// period (s), l1 and its kind (supercritical or subcritical).
pub fn hopf_cells(h: &HopfPoint) -> [String; 8] {
    let [p0, da, alpha, beta] = point_cells(&h.point);
    [
        p0,
        da,
        alpha,
        beta,
        fixed(h.omega, 4),
        fixed(h.period, 4),
        significant(h.l1),
        h.kind.to_string(),
    ]
}

/// The cells of a zero-sideslip departure's row: P0 (rad/s), delta_a, delta_r, alpha (deg), q
/// and r (rad/s).
pub fn departure_cells(d: &DeparturePoint) -> [String; 6] {
    [
        fixed(d.p0, 6),
        fixed(d.delta_a_deg, 4),
        fixed(d.delta_r_deg, 4),
        fixed(d.alpha.to_degrees(), 4),
        fixed(d.q, 5),
        fixed(d.r, 5),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_never_print_as_negative_zero_and_empty_lists_carry_no_unit() {
        assert_eq!(fixed(-0.00001, 4), "0.0000");
        assert_eq!(fixed(-0.0, 2), "0.00");
        assert_eq!(fixed(-0.00006, 4), "-0.0001");
        assert_eq!(fixed(2.5, 1), "2.5");
        assert_eq!(list(&[], 6, "rad/s"), "none");
        assert_eq!(list(&[1.0, -0.0], 2, "rad/s"), "1.00, 0.00 rad/s");
    }

    #[test]
    fn a_first_departure_outside_the_validity_range_says_so_on_its_line() {
        let mut a = crate::analysis::analyze(&crate::aircraft::Aircraft::a(), 0.0349).unwrap();
        let mut f = a.first_departure.clone().unwrap();
        let line = |a: &Analysis| first_departure_text(a).lines().next().unwrap().to_string();
        assert!(!line(&a).contains("outside"), "{}", line(&a));
        // A trim 158.8 deg of alpha and 40 deg of sideslip from the analysed one: both beyond
        // aircraft A's default range of 30 deg.
        f.alpha = Some(158.8f64.to_radians());
        f.beta = Some(-40f64.to_radians());
        a.first_departure = Some(f);
        assert!(
            line(&a).ends_with(
                "  [outside validity range: |alpha| = 158.8 deg > 30 deg, |beta| = 40.0 deg > 30 deg]"
            ),
            "{}",
            line(&a)
        );
    }
}
