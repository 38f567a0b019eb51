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
/// iteration's matrix: its pivots are chosen and tested on scaled rows, so the test does not depend
/// on the units of the unknowns.
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
        if dim == 2 {
            return f.factor_2x2();
        }
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

    /// [`factor`](Self::factor) for a 2×2 matrix [a b; c d], without equilibrating it: the pivot
    /// row is row 0 unless |b·c| > |a·d|, and the matrix is singular when its determinant cancels
    /// to [`SINGULAR_PIVOT`] of its terms, |a·d − b·c| ≤ tol·(|a·d| + |b·c|). Scaling row i by rᵢ
    /// and column j by cⱼ multiplies a·d, b·c and the determinant alike by r₀r₁c₀c₁, so neither
    /// the choice nor the test depends on the units of the unknowns or of the equations. The
    /// choice bounds the elimination's growth by 1: with row 0 the second pivot is d − b·c/a with
    /// |b·c/a| ≤ |d|, and the test is that pivot against the entries it is computed from
    /// ((|a·d| + |b·c|)/|a| ≤ 2|d|). It is the row the equilibrated choice takes, ties apart: in the
    /// equilibrated matrix E each row's largest entry is 1, so e₀₀ > e₁₀ forces e₁₁ = 1 and
    /// |e₀₁·e₁₀| ≤ e₁₀ < e₀₀ = |e₀₀·e₁₁|, and symmetrically. A chosen pivot that is 0 makes the determinant 0 (a·d = 0
    /// then forces b·c = 0), and an entry that is not finite an infinite or NaN term: both are
    /// refused by the one test. So is a matrix whose terms over- or underflow (entries beyond
    /// 10^±150), which the Newton matrices of mechanisms in any practical units are not.
    #[inline(always)]
    fn factor_2x2(mut self) -> Option<Self> {
        let (a, b, c, d) = (
            self.get(0, 0),
            self.get(0, 1),
            self.get(1, 0),
            self.get(1, 1),
        );
        let (ad, bc) = (a * d, b * c);
        if !((ad - bc).abs() > SINGULAR_PIVOT * (ad.abs() + bc.abs())) {
            return None;
        }
        // The elimination of `factor` with the pivot chosen: multiplier, then the second pivot.
        let (p, (a, b, c, d)) = if bc.abs() > ad.abs() {
            (1, (c, d, a, b))
        } else {
            (0, (a, b, c, d))
        };
        let m = c * (1.0 / a);
        self.set(0, 0, a);
        self.set(0, 1, b);
        self.set(1, 0, m);
        self.set(1, 1, d - m * b);
        self.pivots[0][0] = p;
        self.pivots[(1 / N).min(S - 1)][1 % N] = 1;
        Some(self)
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
    use nalgebra::{matrix, vector, SMatrix, SVector};

    #[test]
    fn two_by_two_pivots_do_not_depend_on_the_units() {
        // [a b; c d] with rows and columns scaled by 10⁻⁹…10⁹: the pivot row is the one the
        // unscaled matrix takes (row 1 here, |b·c| > |a·d| although |a| > |c|), the solution is
        // the unscaled one rescaled, and a singular matrix is refused however scaled, as is one
        // with an entry that is not finite.
        let a = matrix![3.0, 2.0; 1.0, 0.5];
        let b = vector![1.0, -2.0];
        let [x] = BlockLu::factor(&[[a]]).unwrap().solve(&[b]);
        // det = −0.5 against terms 1.5 and 2: κ ≈ 30, the solve good to ~1e-14.
        assert!((a * x - b).norm() < 1e-14, "{x}");
        let singular = matrix![3.0, 2.0; 1.5, 1.0];
        for k in -9..=9 {
            let (r, c) = (10f64.powi(k), 10f64.powi(-2 * k / 3));
            let scaled = matrix![a[(0, 0)] * c, a[(0, 1)] / r; a[(1, 0)] * r * c, a[(1, 1)]];
            // (R A C) y = R b with R = diag(1, r), C = diag(c, 1/r): x = C y.
            let lu = BlockLu::factor(&[[scaled]]).expect("scaled matrix refused");
            assert_eq!(lu.pivots[0], [1, 1], "k = {k}");
            let [y] = lu.solve(&[vector![b[0], b[1] * r]]);
            let back = vector![y[0] * c, y[1] / r];
            assert!(
                (back - x).norm() < 1e-14 * x.norm(),
                "k = {k}: {back} vs {x}"
            );
            let refused = matrix![
                singular[(0, 0)] * c, singular[(0, 1)] / r;
                singular[(1, 0)] * r * c, singular[(1, 1)]
            ];
            assert!(BlockLu::factor(&[[refused]]).is_none(), "k = {k}");
        }
        for bad in [f64::NAN, f64::INFINITY] {
            for i in 0..4 {
                let mut m = a;
                m[(i / 2, i % 2)] = bad;
                assert!(BlockLu::factor(&[[m]]).is_none(), "{m}");
            }
        }
        assert!(BlockLu::factor(&[[SMatrix::<f64, 2, 2>::zeros()]]).is_none());
        // Two blocks of one unknown each take the same path.
        let blocks = [[matrix![3.0], matrix![2.0]], [matrix![1.0], matrix![0.5]]];
        let [y0, y1] = BlockLu::factor(&blocks)
            .unwrap()
            .solve(&[vector![1.0], vector![-2.0]]);
        assert_eq!([y0[0], y1[0]], [x[0], x[1]]);
    }

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
