//! Eigenvalues of J5 in a bounded number of steps, and the stability they decide.
//!
//! Stability of a trim (landings, the first departure, the figures' solid and dashed lines,
//! the continuation's test functions) is read from the eigenvalues of the 5x5 Jacobian J5.
//! nalgebra's real Schur decomposition deflates a 2x2 block when its subdiagonal entry falls
//! below `eps` times the neighbouring diagonal entries, so a matrix whose diagonal entries are
//! exactly zero (an aircraft with `y_beta = n_r = 0`, say) can iterate forever without a cap.
//! Here every decomposition is capped; one that does not converge is retried on `J5 + s I`
//! with `s` the matrix's largest absolute row sum (eigenvalues `lambda + s`, the same
//! rounding errors of order `eps |J5|` as the direct decomposition, and no zero diagonal
//! unless the matrix is zero), and what still does not converge is reported as undecided,
//! never waited for.

use nalgebra::{Complex, Matrix5};

/// The QR iterations allowed to one Schur decomposition (a 5x5 matrix converges in tens).
pub const MAX_QR_ITERATIONS: usize = 2000;

/// The eigenvalues of `m`, or `None` when `m` is not finite or neither `m` nor its shift
/// converges within [`MAX_QR_ITERATIONS`].
pub fn eigenvalues(m: &Matrix5<f64>) -> Option<[Complex<f64>; 5]> {
    if !m.iter().all(|v| v.is_finite()) {
        return None;
    }
    if let Some(e) = schur_eigenvalues(m) {
        return Some(e);
    }
    let s = (0..5)
        .map(|i| m.row(i).iter().map(|v| v.abs()).sum::<f64>())
        .fold(0.0, f64::max);
    let shifted = m + Matrix5::from_diagonal_element(s);
    schur_eigenvalues(&shifted).map(|e| e.map(|l| l - s))
}

fn schur_eigenvalues(m: &Matrix5<f64>) -> Option<[Complex<f64>; 5]> {
    let schur = nalgebra::linalg::Schur::try_new(*m, f64::EPSILON, MAX_QR_ITERATIONS)?;
    let e = schur.complex_eigenvalues();
    Some(std::array::from_fn(|i| e[i]))
}

/// Whether every eigenvalue of `m` lies in the open left half-plane; `None` when the
/// eigenvalues cannot be computed (see [`eigenvalues`]).
pub fn stable(m: &Matrix5<f64>) -> Option<bool> {
    eigenvalues(m).map(|e| e.iter().all(|l| l.re < 0.0))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A companion matrix with exactly zero diagonal entries and known eigenvalues: the
    /// decomposition ends (capped), and the eigenvalues are the polynomial's roots.
    #[test]
    fn a_zero_diagonal_ends_with_the_eigenvalues() {
        // (x + 1)(x + 2)(x^2 + 1)(x - 3) = x^5 - 6x^3 - 6x^2 - 7x - 6: roots -1, -2, +-i, 3.
        let c = [-6.0, -7.0, -6.0, -6.0, 0.0];
        let mut m = Matrix5::zeros();
        for i in 0..4 {
            m[(i + 1, i)] = 1.0;
        }
        for (i, ci) in c.iter().enumerate() {
            m[(i, 4)] = -ci;
        }
        let mut e = eigenvalues(&m).expect("converges").to_vec();
        e.sort_by(|a, b| (a.re, a.im).partial_cmp(&(b.re, b.im)).unwrap());
        let want = [
            (-2.0, 0.0),
            (-1.0, 0.0),
            (0.0, -1.0),
            (0.0, 1.0),
            (3.0, 0.0),
        ];
        for (got, (re, im)) in e.iter().zip(want) {
            assert!(
                (got.re - re).abs() < 1e-9 && (got.im - im).abs() < 1e-9,
                "{e:?}"
            );
        }
        assert_eq!(stable(&m), Some(false));
        assert_eq!(
            stable(&(m - Matrix5::from_diagonal_element(4.0))),
            Some(true)
        );
    }

    #[test]
    fn a_matrix_that_is_not_finite_is_undecided() {
        let mut m = Matrix5::<f64>::identity();
        m[(2, 3)] = f64::NAN;
        assert_eq!(eigenvalues(&m), None);
        assert_eq!(stable(&m), None);
    }
}
