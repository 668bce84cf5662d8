//! Small dense matrices of polynomials: determinant, adjugate, Cramer solve.
//!
//! The matrices of the derivation are at most 5x5 and sparse, so the determinant is a Laplace
//! expansion memoised over (first row, remaining column set), which skips zero entries and never
//! divides: it is exact in Z[parameters] without fraction-free tricks.

use super::poly::Poly;
use rustc_hash::FxHashMap;

/// A dense `rows x cols` matrix of polynomials, row-major.
#[derive(Clone, Debug, PartialEq)]
pub struct Matrix {
    rows: usize,
    cols: usize,
    data: Vec<Poly>,
}

impl Matrix {
    /// Builds a matrix from rows (all of equal length).
    pub fn from_rows(rows: Vec<Vec<Poly>>) -> Matrix {
        let r = rows.len();
        let c = rows.first().map_or(0, |row| row.len());
        assert!(rows.iter().all(|row| row.len() == c), "ragged matrix");
        Matrix {
            rows: r,
            cols: c,
            data: rows.into_iter().flatten().collect(),
        }
    }

    /// Number of rows.
    pub fn rows(&self) -> usize {
        self.rows
    }

    /// Number of columns.
    pub fn cols(&self) -> usize {
        self.cols
    }

    /// Entry (i, j).
    pub fn get(&self, i: usize, j: usize) -> &Poly {
        &self.data[i * self.cols + j]
    }

    /// The rows as vectors.
    pub fn to_rows(&self) -> Vec<Vec<Poly>> {
        (0..self.rows)
            .map(|i| (0..self.cols).map(|j| self.get(i, j).clone()).collect())
            .collect()
    }

    /// Applies `f` to every entry.
    pub fn map(&self, f: impl Fn(&Poly) -> Poly) -> Matrix {
        Matrix {
            rows: self.rows,
            cols: self.cols,
            data: self.data.iter().map(f).collect(),
        }
    }

    /// Determinant (square matrices only).
    pub fn det(&self) -> Poly {
        assert_eq!(self.rows, self.cols, "det of a non-square matrix");
        let rows: Vec<usize> = (0..self.rows).collect();
        let cols: Vec<usize> = (0..self.cols).collect();
        self.minor_det(&rows, &cols)
    }

    /// Determinant of the submatrix on the given rows and columns.
    pub fn minor_det(&self, rows: &[usize], cols: &[usize]) -> Poly {
        assert_eq!(rows.len(), cols.len());
        let mut memo: FxHashMap<(usize, u32), Poly> = FxHashMap::default();
        let mask = cols.iter().fold(0u32, |m, c| m | (1 << c));
        self.laplace(rows, 0, mask, &mut memo)
    }

    fn laplace(
        &self,
        rows: &[usize],
        k: usize,
        mask: u32,
        memo: &mut FxHashMap<(usize, u32), Poly>,
    ) -> Poly {
        if k == rows.len() {
            return Poly::int(1);
        }
        if let Some(p) = memo.get(&(k, mask)) {
            return p.clone();
        }
        let mut acc = Poly::zero();
        let mut sign_pos = true;
        for j in 0..self.cols {
            if mask & (1 << j) == 0 {
                continue;
            }
            let a = self.get(rows[k], j);
            if !a.is_zero() {
                let sub = self.laplace(rows, k + 1, mask & !(1 << j), memo);
                let t = a * &sub;
                acc = if sign_pos { &acc + &t } else { &acc - &t };
            }
            sign_pos = !sign_pos;
        }
        memo.insert((k, mask), acc.clone());
        acc
    }

    /// Adjugate (transposed cofactor matrix): `A adj(A) = det(A) I`.
    pub fn adjugate(&self) -> Matrix {
        let n = self.rows;
        assert_eq!(n, self.cols);
        let mut data = vec![Poly::zero(); n * n];
        for i in 0..n {
            for j in 0..n {
                let rows: Vec<usize> = (0..n).filter(|r| *r != i).collect();
                let cols: Vec<usize> = (0..n).filter(|c| *c != j).collect();
                let m = if n == 1 {
                    Poly::int(1)
                } else {
                    self.minor_det(&rows, &cols)
                };
                // adj(A)[j][i] = (-1)^(i+j) M_ij
                data[j * n + i] = if (i + j) % 2 == 0 { m } else { -m };
            }
        }
        Matrix {
            rows: n,
            cols: n,
            data,
        }
    }

    /// Matrix-vector product.
    pub fn mul_vec(&self, v: &[Poly]) -> Vec<Poly> {
        assert_eq!(v.len(), self.cols);
        (0..self.rows)
            .map(|i| (0..self.cols).fold(Poly::zero(), |acc, j| &acc + &(self.get(i, j) * &v[j])))
            .collect()
    }

    /// Solves `A x = b` by the adjugate: returns the numerators `adj(A) b` and the common
    /// denominator `det A`, unnormalised (`x_i = numerators[i] / det`).
    pub fn solve(&self, b: &[Poly]) -> (Vec<Poly>, Poly) {
        (self.adjugate().mul_vec(b), self.det())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::Sym;

    #[test]
    fn adjugate_times_matrix_is_det_times_identity() {
        let x = Poly::var(Sym::new("mx_x"));
        let y = Poly::var(Sym::new("mx_y"));
        let m = Matrix::from_rows(vec![
            vec![x.clone(), Poly::int(2), Poly::zero()],
            vec![y.clone(), &x * &y, Poly::int(-1)],
            vec![Poly::int(3), Poly::zero(), &x + &y],
        ]);
        let d = m.det();
        let adj = m.adjugate();
        for i in 0..3 {
            for j in 0..3 {
                let e = (0..3).fold(Poly::zero(), |acc, k| &acc + &(m.get(i, k) * adj.get(k, j)));
                let want = if i == j { d.clone() } else { Poly::zero() };
                assert_eq!(e, want, "entry ({i},{j})");
            }
        }
    }
}
