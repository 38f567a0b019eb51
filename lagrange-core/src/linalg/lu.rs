//! [`BlockLu`]: LU with scaled partial pivoting for the general (not symmetric) systems of the
//! implicit methods' Newton iterations, and [`lu_solve`](super::lu_solve) and
//! [`lu_solve_blocks`](super::lu_solve_blocks) on top of it.
//!
//! The rows and columns of those systems carry the units of the unknowns and of the equations —
//! momenta and velocities of coordinates that may be angles or lengths, constraint rows in metres
//! or radians — so a pivot compared with the largest entry of the whole matrix would compare
//! kilograms with kilogram-square-metres. Instead the pivots are chosen and tested on the
//! equilibrated matrix R A C (column scales cⱼ = 1/maxᵢ|aᵢⱼ|, then row scales
//! rᵢ = 1/maxⱼ|aᵢⱼ|cⱼ, so every row of R A C has largest entry 1): implicit scaling, the matrix
//! itself is left as it is (Golub & Van Loan, *Matrix Computations*, 4th ed., §3.5.2, row scaling
//! and the choice of pivots). Rescaling an unknown multiplies a column by a constant, which the
//! column scales undo exactly; rescaling an equation multiplies a row, which the row scales undo.

// `!(pivot > tol)` rather than `pivot <= tol`: the negated form also rejects NaN.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use super::SINGULAR_PIVOT;
use nalgebra::{SMatrix, SVector};

/// An LU factorisation with scaled partial pivoting of a matrix of S×S blocks of size N×N (an
/// (S·N)-square matrix; stable Rust cannot name S·N as an array length, so the blocks are
/// indexed through r ↦ (r / N, r % N)): factorised once, solved many times — the simplified Newton
/// iteration's matrix (see the [module docs](self) for the pivots).
///
/// ```
/// use lagrange_core::linalg::BlockLu;
/// use nalgebra::{matrix, vector};
/// // A 2×2 system as one block; the second unknown in units 10⁶ times smaller than the first.
/// let a = matrix![2.0, 1e6; 1.0, 3e6];
/// let lu = BlockLu::factor(&[[a]]).unwrap();
/// let [x] = lu.solve(&[vector![3.0, 4.0]]);
/// assert!((a * x - vector![3.0, 4.0]).norm() < 1e-14 * 5.0);
/// ```
#[derive(Clone, Copy, Debug)]
pub struct BlockLu<const N: usize, const S: usize> {
    lu: [[SMatrix<f64, N, N>; S]; S],
    pivots: [[usize; N]; S],
}

impl<const N: usize, const S: usize> BlockLu<N, S> {
    #[inline(always)]
    fn get(&self, r: usize, c: usize) -> f64 {
        self.lu[r / N][c / N][(r % N, c % N)]
    }

    #[inline(always)]
    fn set(&mut self, r: usize, c: usize, x: f64) {
        self.lu[r / N][c / N][(r % N, c % N)] = x;
    }

    /// Factorises `a`; `None` when an entry is not finite, a row or column is zero, or a pivot of
    /// the equilibrated matrix is below [`SINGULAR_PIVOT`] (its rows' largest entries are 1).
    #[inline]
    pub fn factor(a: &[[SMatrix<f64, N, N>; S]; S]) -> Option<Self> {
        let mut f = BlockLu {
            lu: *a,
            pivots: [[0; N]; S],
        };
        let dim = N * S;
        let (rows, columns) = f.equilibration()?;
        let mut row_scale = rows;
        let at = |x: &[[f64; N]; S], r: usize| x[r / N][r % N];
        for c in 0..dim {
            // The pivot: the largest entry of column c of the equilibrated matrix, at or below c.
            let mut p = c;
            let mut best = f.get(c, c).abs() * at(&row_scale, c);
            for r in (c + 1)..dim {
                let candidate = f.get(r, c).abs() * at(&row_scale, r);
                if candidate > best {
                    p = r;
                    best = candidate;
                }
            }
            if !(best * at(&columns, c) > SINGULAR_PIVOT) {
                return None;
            }
            let pivot = f.get(p, c);
            f.pivots[c / N][c % N] = p;
            // Rows are swapped from column c on only (LINPACK's convention): the multipliers of
            // the earlier columns stay where they were made, in the order in which `solve`
            // applies the interchanges, interleaved with the elimination.
            if p != c {
                for k in c..dim {
                    let (u, w) = (f.get(p, k), f.get(c, k));
                    f.set(p, k, w);
                    f.set(c, k, u);
                }
                let (u, w) = (at(&row_scale, p), at(&row_scale, c));
                row_scale[p / N][p % N] = w;
                row_scale[c / N][c % N] = u;
            }
            let inv = 1.0 / pivot;
            for r in (c + 1)..dim {
                let m = f.get(r, c) * inv;
                f.set(r, c, m);
                if m != 0.0 {
                    for k in (c + 1)..dim {
                        let x = f.get(r, k) - m * f.get(c, k);
                        f.set(r, k, x);
                    }
                }
            }
        }
        Some(f)
    }

    /// The row and column scales of the equilibrated matrix (see the [module docs](self)), or
    /// `None` when an entry is not finite or a row or column is zero.
    #[inline(always)]
    #[allow(clippy::type_complexity)]
    fn equilibration(&self) -> Option<([[f64; N]; S], [[f64; N]; S])> {
        let dim = N * S;
        let mut columns = [[0.0f64; N]; S];
        // x·0 is 0 exactly when x is finite: one test for every entry; a zero column makes its
        // scale infinite (and then every row's), a zero row its own.
        let mut zero = 0.0f64;
        let mut finite = true;
        for c in 0..dim {
            let mut largest = 0.0f64;
            for r in 0..dim {
                let x = self.get(r, c);
                zero += x * 0.0;
                largest = largest.max(x.abs());
            }
            let scale = 1.0 / largest;
            finite &= scale.is_finite();
            columns[c / N][c % N] = scale;
        }
        let mut rows = [[0.0f64; N]; S];
        for r in 0..dim {
            let mut largest = 0.0f64;
            for c in 0..dim {
                largest = largest.max(self.get(r, c).abs() * columns[c / N][c % N]);
            }
            let scale = 1.0 / largest;
            finite &= scale.is_finite();
            rows[r / N][r % N] = scale;
        }
        (zero == 0.0 && finite).then_some((rows, columns))
    }

    /// Solves A x = b with the factorisation.
    pub fn solve(&self, b: &[SVector<f64, N>; S]) -> [SVector<f64, N>; S] {
        let dim = N * S;
        let mut x = *b;
        for c in 0..dim {
            let p = self.pivots[c / N][c % N];
            if p != c {
                let (u, w) = (x[p / N][p % N], x[c / N][c % N]);
                x[p / N][p % N] = w;
                x[c / N][c % N] = u;
            }
            let xc = x[c / N][c % N];
            if xc != 0.0 {
                for r in (c + 1)..dim {
                    x[r / N][r % N] -= self.get(r, c) * xc;
                }
            }
        }
        for r in (0..dim).rev() {
            let mut s = x[r / N][r % N];
            for k in (r + 1)..dim {
                s -= self.get(r, k) * x[k / N][k % N];
            }
            x[r / N][r % N] = s / self.get(r, r);
        }
        x
    }
}

#[cfg(test)]
mod tests {
    use super::BlockLu;
    use nalgebra::{SMatrix, SVector};

    #[test]
    fn block_lu_solves_with_interchanges_in_several_columns() {
        // A 4×4 matrix (2×2 blocks of 2×2) whose partial pivoting swaps rows at columns 0 and 1
        // (pivots 1, 3, 2, 3): the solve must apply the interchanges in the order the
        // factorisation made them. Checked against nalgebra's dense LU.
        let a = [
            [
                SMatrix::<f64, 2, 2>::new(992660.25, -1000031.54, -999952.69, 992611.94),
                SMatrix::<f64, 2, 2>::new(-56580.37, 35.89, -53.83, -56526.54),
            ],
            [
                SMatrix::<f64, 2, 2>::new(56580.37, -35.89, 53.83, 56526.54),
                SMatrix::<f64, 2, 2>::new(992660.25, -1000031.54, -999952.69, 992611.94),
            ],
        ];
        let mut dense = SMatrix::<f64, 4, 4>::zeros();
        for r in 0..4 {
            for c in 0..4 {
                dense[(r, c)] = a[r / 2][c / 2][(r % 2, c % 2)];
            }
        }
        let b = [SVector::from([1.0, 2.0]), SVector::from([3.0, 4.0])];
        let x = BlockLu::factor(&a).unwrap().solve(&b);
        let expected = dense
            .lu()
            .solve(&SVector::<f64, 4>::from([1.0, 2.0, 3.0, 4.0]))
            .unwrap();
        for r in 0..4 {
            // The matrix's condition number is about 40: both solves agree to ~1e-14 relative.
            let got = x[r / 2][r % 2];
            assert!(
                (got - expected[r]).abs() < 1e-12 * expected.amax(),
                "{got} vs {}",
                expected[r]
            );
        }
    }
}
