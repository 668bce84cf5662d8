//! Principal moments of inertia that break the triangle inequalities: analysed as given, with a
//! warning naming the violation.
//!
//! Every rigid body's principal moments satisfy ix <= iy + iz and its two cyclic companions
//! (each is an integral of a sum of two squares, and the third square is non-negative). Data
//! from established models do not always: several of JSBSim's catalogue aircraft carry estimated
//! moments that break one. The equations of motion (Eqs 1-3) need only the inertia coefficients
//! C = (iz - ix)/iy, D = (iy - ix)/iz, E = (iz - iy)/ix, which exist for any positive moments
//! (a violation puts one of them outside [-1, 1]), so such a file is analysed and its result
//! carries the warning; only a moment <= 0, for which a coefficient is undefined or the inertia
//! matrix is not positive definite, is refused.

use super::{AircraftError, Cx, Table};
use crate::aircraft::rational_to_f64;
use num_rational::BigRational;

/// A moment of inertia to four significant digits as a plain decimal (`7834`, `35116`,
/// `0.1250`), in exponent form only beyond the magnitudes an aircraft file gives (below 1e-3 or
/// from 1e9 on).
pub(super) fn moment_text(x: f64) -> String {
    let magnitude = if x == 0.0 {
        0
    } else {
        x.abs().log10().floor() as i32
    };
    if !(-3..9).contains(&magnitude) {
        return format!("{x:e}");
    }
    let digits = (3 - magnitude).max(0) as usize;
    format!("{x:.digits$}")
}

/// The warning for principal moments `[ix, iy, iz]` (named by `names`, in kg m^2 or any one
/// unit) that break a triangle inequality, or `None` when they satisfy all three.
pub(super) fn triangle_violation(
    names: [&str; 3],
    [ix, iy, iz]: [&BigRational; 3],
) -> Option<String> {
    let [nx, ny, nz] = names;
    let broken: Vec<String> = [
        (ix, iy, iz, nx, ny, nz),
        (ix, iz, iy, nx, nz, ny),
        (iy, iz, ix, ny, nz, nx),
    ]
    .iter()
    .filter(|(a, b, c, ..)| *a + *b < **c)
    .map(|(_, _, _, a, b, c)| format!("{a} + {b} < {c}"))
    .collect();
    if broken.is_empty() {
        return None;
    }
    let f = rational_to_f64;
    Some(format!(
        "the principal moments of inertia {nx} = {}, {ny} = {}, {nz} = {} break the \
         triangle inequality {} (no rigid body has them: each principal moment is at most the \
         sum of the other two); analysed as given, with inertia coefficients C, D, E = {}",
        moment_text(f(ix)),
        moment_text(f(iy)),
        moment_text(f(iz)),
        broken.join(" and "),
        super::inertia_coefficients(ix, iy, iz)
            .iter()
            .map(|c| format!("{:.4}", f(c)))
            .collect::<Vec<_>>()
            .join(", ")
    ))
}

impl Cx<'_> {
    /// C, D, E of principal moments ix, iy, iz (each > 0, read before), refused when one
    /// leaves f64 (a moment tiny beside the others, which only a broken triangle inequality
    /// allows: within them every coefficient lies in [-1, 1]).
    pub(super) fn coefficients_in_f64(
        &self,
        table: &Table<'_>,
        [ix, iy, iz]: [&BigRational; 3],
    ) -> Result<Vec<BigRational>, AircraftError> {
        let coefficients = super::inertia_coefficients(ix, iy, iz);
        for (name, c) in ["C", "D", "E"].iter().zip(&coefficients) {
            let x = rational_to_f64(c);
            if !x.is_finite() {
                return Err(AircraftError::UnphysicalInertia {
                    at: self.at(table.span.as_ref()),
                    problem: format!(
                        "the moments ix = {:e}, iy = {:e}, iz = {:e} give the inertia \
                         coefficient {name} = {x:e}, beyond f64",
                        rational_to_f64(ix),
                        rational_to_f64(iy),
                        rational_to_f64(iz)
                    ),
                });
            }
        }
        Ok(coefficients.to_vec())
    }

    /// The warnings of a dimensional `[inertia]` given as moments `ix`, `iy`, `iz` (each read
    /// and checked positive before): none for coefficients `C`, `D`, `E`, whose own checks
    /// stand (`load/inertia.rs`).
    pub(super) fn moment_warnings(&self, table: &Table<'_>) -> Vec<String> {
        let moment = |k: &str| {
            let (key, value) = table.get(k)?;
            self.number(table.name, key, value).ok().map(|n| n.exact)
        };
        let (Some(ix), Some(iy), Some(iz)) = (moment("ix"), moment("iy"), moment("iz")) else {
            return Vec::new();
        };
        triangle_violation(["ix", "iy", "iz"], [&ix, &iy, &iz])
            .into_iter()
            .map(|w| format!("{}: table `[inertia]`: {w}", self.at(table.span.as_ref())))
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(s: &str) -> BigRational {
        crate::aircraft::decimal_to_rational(s).unwrap()
    }

    #[test]
    fn moments_of_a_rigid_body_give_no_warning() {
        let names = ["ix", "iy", "iz"];
        assert_eq!(triangle_violation(names, [&q("2"), &q("5"), &q("6")]), None);
        // A lamina: iz = ix + iy exactly is a rigid body's.
        assert_eq!(triangle_violation(names, [&q("2"), &q("5"), &q("7")]), None);
    }

    #[test]
    fn a_broken_inequality_is_named_with_the_coefficients() {
        // The A-4 of JSBSim's catalogue: ix + iz < iy.
        let w = triangle_violation(
            ["ix'", "iy", "iz'"],
            [&q("7833.9"), &q("35115.7"), &q("27227.5")],
        )
        .unwrap();
        assert!(w.contains("ix' + iz' < iy"), "{w}");
        assert!(!w.contains("ix' + iy < iz'"), "{w}");
        // C = (27227.5 - 7833.9)/35115.7, D = (35115.7 - 7833.9)/27227.5 > 1.
        assert!(w.contains("C, D, E = 0.5523, 1.0020, -1.0069"), "{w}");
    }
}
