//! Small dense linear algebra for the equations of motion, generic over the scalar so the same
//! solve runs on `f64` and on dual numbers (for exact Jacobians of the accelerations).
//!
//! The mass matrix is symmetric positive definite wherever the coordinates are independent, so the
//! solve is a Cholesky factorisation M = L Lᵀ (Golub & Van Loan, *Matrix Computations*, 4th ed.,
//! Alg. 4.2.1), written out for fixed N so the compiler unrolls it for the tiny systems mechanisms
//! usually are. A pivot that is not clearly positive relative to its own diagonal entry means the
//! coordinates are locally dependent: that is reported, never turned into NaN.
//!
//! Every singularity test here is invariant under rescaling each unknown (a coordinate written in
//! millimetres instead of metres, a mass in tonnes): an SPD pivot is compared with its own diagonal
//! entry, which a change of the unknown's unit multiplies by the same factor, and the general
//! (LU) factorisations choose and test their pivots on the row- and column-equilibrated matrix.

// `!(pivot > tol)` rather than `pivot <= tol` throughout: the negated form also rejects NaN.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use crate::geometry::Scalar;
use nalgebra::{SMatrix, SVector};

mod blocks;
mod ldlt;
mod lu;
mod pattern;
pub use ldlt::{Dense, FactorPattern, Ldlt};
pub use lu::BlockLu;
pub use pattern::{factor_pattern, mass_pattern};

/// Relative size under which a pivot counts as zero: an LDLᵀ pivot dⱼ (a squared Cholesky pivot)
/// against its own diagonal entry Mⱼⱼ, an LU pivot against the largest entry of the equilibrated
/// matrix (1). For symmetric positive definite M, dⱼ/Mⱼⱼ = 1/(Mⱼⱼ (M₀..ⱼ⁻¹)ⱼⱼ) is the squared sine of
/// the angle, in the metric M, between coordinate j's direction and those of the coordinates before
/// it; it is a ratio of two quantities of the same unit, unchanged when any coordinate is rescaled.
/// Below 1e3·ε the rounding error of the elimination (about ε·Mⱼⱼ) is within three orders of the
/// pivot itself: the coordinates are dependent to working precision, and a configuration this close
/// to singular is reported rather than trusted. The diagonally scaled matrix D⁻¹MD⁻¹ (D² = diag M),
/// whose condition number bounds every solve's error up to a factor N (van der Sluis, Numer. Math.
/// 14 (1969); Higham, *Accuracy and Stability of Numerical Algorithms*, 2nd ed., §7.3), then has
/// κ ≳ 1/(1e3·ε) ≈ 4.5e12.
pub const SINGULAR_PIVOT: f64 = 1e3 * f64::EPSILON;

/// Why a Cholesky factorisation failed: the index of the first pivot that is not positive, and its
/// (real part's) value.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NotPositiveDefinite {
    /// The row (and column) of the first pivot that is not positive, counting from 0.
    pub index: usize,
    /// That pivot's value (its real part, for dual numbers).
    pub pivot: f64,
}

/// Solves M x = b for symmetric positive definite M by Cholesky, in place of nothing: returns x.
///
/// ```
/// use lagrange_core::linalg::cholesky_solve;
/// use nalgebra::{matrix, vector};
/// let m = matrix![4.0, 2.0; 2.0, 3.0];
/// let x = cholesky_solve(&m, &vector![2.0, 1.0]).unwrap();
/// assert!(((m * x) - vector![2.0, 1.0]).norm() < 1e-15);
/// ```
#[inline]
pub fn cholesky_solve<S: Scalar, const N: usize>(
    m: &SMatrix<S, N, N>,
    b: &SVector<S, N>,
) -> Result<SVector<S, N>, NotPositiveDefinite> {
    let l = cholesky(m)?;
    Ok(cholesky_substitute(&l, b))
}

/// The lower Cholesky factor L of M = L Lᵀ (only the lower triangle of M is read).
#[inline]
pub fn cholesky<S: Scalar, const N: usize>(
    m: &SMatrix<S, N, N>,
) -> Result<SMatrix<S, N, N>, NotPositiveDefinite> {
    let mut l = SMatrix::<S, N, N>::zeros();
    for j in 0..N {
        let mut d = m[(j, j)];
        for k in 0..j {
            d -= l[(j, k)] * l[(j, k)];
        }
        // Against its own diagonal entry (see `SINGULAR_PIVOT`); `!(d > tol)` also catches NaN.
        if !(d.re() > SINGULAR_PIVOT * m[(j, j)].re().abs()) {
            return Err(NotPositiveDefinite {
                index: j,
                pivot: d.re(),
            });
        }
        let ljj = d.sqrt();
        l[(j, j)] = ljj;
        let inv = ljj.recip();
        for i in (j + 1)..N {
            let mut s = m[(i, j)];
            for k in 0..j {
                s -= l[(i, k)] * l[(j, k)];
            }
            l[(i, j)] = s * inv;
        }
    }
    Ok(l)
}

/// Solves L Lᵀ x = b given the lower Cholesky factor L.
#[inline]
pub fn cholesky_substitute<S: Scalar, const N: usize>(
    l: &SMatrix<S, N, N>,
    b: &SVector<S, N>,
) -> SVector<S, N> {
    // forward: L y = b
    let mut y = *b;
    for i in 0..N {
        let mut s = y[i];
        for k in 0..i {
            s -= l[(i, k)] * y[k];
        }
        y[i] = s / l[(i, i)];
    }
    // backward: Lᵀ x = y
    for i in (0..N).rev() {
        let mut s = y[i];
        for k in (i + 1)..N {
            s -= l[(k, i)] * y[k];
        }
        y[i] = s / l[(i, i)];
    }
    y
}

/// Solves M x = b for symmetric positive definite M: the solve on the hot path of `accelerations`.
///
/// The same pivots and the same test as [`Ldlt`] (the first pivot that is not clearly positive is
/// reported), but one or two coordinates — most mechanisms people write down — take the closed
/// form with a single division instead of a factorisation with one division per pivot in series:
///
/// ```text
/// N = 2:  d₀ = M₀₀,  det = M₀₀M₁₁ − M₁₀²,  d₁ = det / d₀,   x = [M₁₁b₀ − M₁₀b₁, M₀₀b₁ − M₁₀b₀] / det
/// ```
///
/// (d₁ > tol·M₁₁ ⇔ det > tol·M₁₁·d₀ since d₀ > 0, so the second test needs no division either), and three
/// or four eliminate the leading 2×2 block the same way and solve its Schur complement in closed
/// form: two divisions in series instead of three or four.
///
/// ```
/// use lagrange_core::linalg::solve_spd;
/// use nalgebra::{matrix, vector};
/// let m = matrix![4.0, 2.0; 2.0, 3.0];
/// let x = solve_spd(&m, &vector![2.0, 1.0]).unwrap();
/// assert!(((m * x) - vector![2.0, 1.0]).norm() < 1e-15);
/// assert_eq!(solve_spd(&matrix![1.0, 2.0; 2.0, 4.0], &vector![1.0, 1.0]).unwrap_err().index, 1);
/// ```
#[inline(always)]
pub fn solve_spd<S: Scalar, const N: usize>(
    m: &SMatrix<S, N, N>,
    b: &SVector<S, N>,
) -> Result<SVector<S, N>, NotPositiveDefinite> {
    match solve_spd_flagged(m, b) {
        (x, true) => Ok(x),
        (_, false) => factorised_solve(m, b),
    }
}

/// [`solve_spd`] without a branch for up to four coordinates: x, and whether every pivot passed
/// (x is meaningless when one did not). For a caller that folds the test into one branch with
/// others (`dynamics::regular_accelerations`).
///
/// ```
/// use lagrange_core::linalg::solve_spd_flagged;
/// use nalgebra::{matrix, vector};
/// let (x, regular) = solve_spd_flagged(&matrix![4.0, 2.0; 2.0, 3.0], &vector![2.0, 1.0]);
/// assert!(regular && (x - vector![0.5, 0.0]).norm() < 1e-15);
/// assert!(!solve_spd_flagged(&matrix![1.0, 2.0; 2.0, 4.0], &vector![1.0, 1.0]).1);
/// ```
#[inline(always)]
pub fn solve_spd_flagged<S: Scalar, const N: usize>(
    m: &SMatrix<S, N, N>,
    b: &SVector<S, N>,
) -> (SVector<S, N>, bool) {
    let mut x = *b;
    if N == 1 {
        let d0 = m[(0, 0)];
        x[0] = b[0] / d0;
        return (x, first_pivot_passes(d0.re(), d0.re().abs()));
    }
    if N == 2 {
        let (m00, m10, m11) = (m[(0, 0)], m[(1, 0)], m[(1, 1)]);
        let det = m00 * m11 - m10 * m10;
        let inv_det = det.recip();
        x[0] = (m11 * b[0] - m10 * b[1]) * inv_det;
        x[1] = (m00 * b[1] - m10 * b[0]) * inv_det;
        let (first, second) = pivots_2x2_pass(m00.re(), m11.re(), det.re());
        // `&`, not `&&`: both tests are cheap, and one branch is what the caller wants.
        return (x, first & second);
    }
    if N == 3 || N == 4 {
        return blocks::solve(m, b);
    }
    match Ldlt::new(m) {
        Ok(factors) => (factors.solve(b), true),
        Err(_) => (x, false),
    }
}

/// The first pivot's test: `!(d₀ > tol)` rejects NaN too.
#[inline(always)]
fn first_pivot_passes(d0: f64, scale: f64) -> bool {
    d0 > SINGULAR_PIVOT * scale
}

/// The two pivot tests of a 2×2 M (see [`solve_spd`]), each against its own diagonal entry as in
/// [`Ldlt`]: d₀ = M₀₀ > tol·|M₀₀|, and d₁ = det/d₀ > tol·|M₁₁| written as det > tol·|M₁₁|·d₀.
#[inline(always)]
fn pivots_2x2_pass(m00: f64, m11: f64, det: f64) -> (bool, bool) {
    (
        first_pivot_passes(m00, m00.abs()),
        det > SINGULAR_PIVOT * m11.abs() * m00,
    )
}

/// [`solve_spd`] when the closed forms' tests fail: the factorisation decides, and names the
/// pivot that fails. It can succeed where they did not — a determinant that overflows although
/// the pivots do not (masses near `f64::MAX`), or a pivot at the tolerance rounded to either side.
#[cold]
#[inline(never)]
fn factorised_solve<S: Scalar, const N: usize>(
    m: &SMatrix<S, N, N>,
    b: &SVector<S, N>,
) -> Result<SVector<S, N>, NotPositiveDefinite> {
    Ldlt::new(m).map(|factors| factors.solve(b))
}

/// Solves A x = b for a general square A by LU with scaled partial pivoting ([`BlockLu`] with one
/// block); `None` when an entry of A is not finite or a pivot of the equilibrated matrix vanishes
/// (≤ [`SINGULAR_PIVOT`], see [`BlockLu::factor`]): a test no rescaling of the unknowns or of the
/// equations changes. Used by Newton iterations of implicit methods, whose Jacobians are not
/// symmetric.
pub fn lu_solve<const N: usize>(
    a: &SMatrix<f64, N, N>,
    b: &SVector<f64, N>,
) -> Option<SVector<f64, N>> {
    BlockLu::factor(&[[*a]]).map(|lu| lu.solve(&[*b])[0])
}

/// Solves a block system Σₖ Aᵢₖ xₖ = bᵢ (i, k = 0..B) with N×N blocks, that is the (B·N)×(B·N)
/// system of the stage equations of a B-stage implicit Runge–Kutta method, by LU with scaled
/// partial pivoting over the whole system ([`BlockLu`]; Golub & Van Loan, *Matrix Computations*,
/// 4th ed., Alg. 3.4.1 and §3.5.2). A pivot may come from any block. `None` when a pivot of the
/// equilibrated matrix vanishes or an entry is not finite. No allocation: the work copy lives on
/// the stack.
pub fn lu_solve_blocks<const N: usize, const B: usize>(
    a: &[[SMatrix<f64, N, N>; B]; B],
    b: &[SVector<f64, N>; B],
) -> Option<[SVector<f64, N>; B]> {
    if b.iter().any(|v| !v.iter().all(|e| e.is_finite())) {
        return None;
    }
    BlockLu::factor(a).map(|lu| lu.solve(b))
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{matrix, vector, Matrix4, Vector4};
    use num_dual::Dual64;

    #[test]
    fn cholesky_solves_spd_system() {
        let m = matrix![4.0, 1.0, 0.5; 1.0, 3.0, 0.2; 0.5, 0.2, 2.0];
        let b = vector![1.0, -2.0, 0.5];
        let x = cholesky_solve(&m, &b).unwrap();
        assert!((m * x - b).norm() < 1e-14);
    }

    #[test]
    fn cholesky_reports_singular_pivot() {
        // Rank one: second pivot is exactly zero.
        let m = matrix![1.0, 2.0; 2.0, 4.0];
        let e = cholesky(&m).unwrap_err();
        assert_eq!(e.index, 1);
        let nan = matrix![f64::NAN, 0.0; 0.0, 1.0];
        assert_eq!(cholesky(&nan).unwrap_err().index, 0);
    }

    #[test]
    fn cholesky_differentiates_through_dual_numbers() {
        // x(s) = M(s)⁻¹ b with M(s) = [[2+s, 1],[1, 3]]: dx/ds = −M⁻¹ (dM/ds) x.
        let s = Dual64::from_re(0.5).derivative();
        let m = matrix![s + 2.0, Dual64::from(1.0); Dual64::from(1.0), Dual64::from(3.0)];
        let b = vector![Dual64::from(1.0), Dual64::from(2.0)];
        let x = cholesky_solve(&m, &b).unwrap();
        let m0 = matrix![2.5, 1.0; 1.0, 3.0];
        let x0 = cholesky_solve(&m0, &vector![1.0, 2.0]).unwrap();
        let dx = -cholesky_solve(&m0, &vector![x0[0], 0.0]).unwrap();
        assert!((x[0].re - x0[0]).abs() < 1e-15 && (x[1].re - x0[1]).abs() < 1e-15);
        assert!((x[0].eps - dx[0]).abs() < 1e-14 && (x[1].eps - dx[1]).abs() < 1e-14);
    }

    #[test]
    fn ldlt_agrees_with_cholesky_and_reports_singular() {
        let m = matrix![4.0, 1.0, 0.5; 1.0, 3.0, 0.2; 0.5, 0.2, 2.0];
        let b = vector![1.0, -2.0, 0.5];
        let x = Ldlt::new(&m).unwrap().solve(&b);
        assert!((m * x - b).norm() < 1e-14);
        assert!((x - cholesky_solve(&m, &b).unwrap()).norm() < 1e-15);
        assert_eq!(
            Ldlt::new(&matrix![1.0, 2.0; 2.0, 4.0]).unwrap_err().index,
            1
        );
        assert_eq!(
            Ldlt::new(&matrix![f64::NAN, 0.0; 0.0, 1.0])
                .unwrap_err()
                .index,
            0
        );
    }

    #[test]
    fn closed_form_small_solves_agree_with_ldlt() {
        // The closed forms for N ≤ 2 against the factorisation: same solution to round-off (both
        // backward stable for SPD 2×2; the condition number here is 5.9 / 0.1 = 59, so ≈ 59·ε ≈ 1.3e-14
        // relative), same failing pivot.
        let m2 = matrix![3.0, 2.9; 2.9, 3.0];
        let b2 = vector![1.0, -2.0];
        let x2 = solve_spd(&m2, &b2).unwrap();
        assert!((x2 - Ldlt::new(&m2).unwrap().solve(&b2)).norm() < 1e-13 * x2.norm());
        let m1 = matrix![0.25];
        assert_eq!(solve_spd(&m1, &vector![1.0]).unwrap()[0], 4.0);
        for bad in [
            matrix![1.0, 2.0; 2.0, 4.0],
            matrix![f64::NAN, 0.0; 0.0, 1.0],
            matrix![1.0, 0.0; 0.0, f64::NAN],
            matrix![-1.0, 0.0; 0.0, 1.0],
            // Nearly parallel coordinates: d₁/M₁₁ = 1 − (1 − 1e-14)² ≈ 2e-14 < 1e3·ε.
            matrix![1.0, 1.0 - 1e-14; 1.0 - 1e-14, 1.0],
        ] {
            let ours = solve_spd(&bad, &b2).unwrap_err();
            let reference = Ldlt::new(&bad).unwrap_err();
            assert_eq!(ours.index, reference.index, "{bad}");
        }
        assert_eq!(
            solve_spd(&matrix![0.0], &vector![1.0]).unwrap_err().index,
            0
        );
        assert_eq!(
            solve_spd(&matrix![f64::NAN], &vector![1.0])
                .unwrap_err()
                .index,
            0
        );
        // Through dual numbers: d/ds of M(s)⁻¹ b agrees with the factorisation.
        let s = Dual64::from_re(0.5).derivative();
        let m = matrix![s + 2.0, Dual64::from(1.0); Dual64::from(1.0), s * 3.0];
        let b = vector![Dual64::from(1.0), Dual64::from(2.0)];
        let (x, y) = (solve_spd(&m, &b).unwrap(), Ldlt::new(&m).unwrap().solve(&b));
        for k in 0..2 {
            assert!((x[k].re - y[k].re).abs() < 1e-15 && (x[k].eps - y[k].eps).abs() < 1e-14);
        }
    }

    #[test]
    fn closed_forms_that_overflow_fall_back_to_the_factorisation() {
        // Entries near 1e160: the determinants the closed forms form (≈ 1e320) overflow, the
        // pivots do not. The flag fails, and `solve_spd` returns the factorisation's solution.
        for n in [2, 3, 4] {
            let mut m = nalgebra::Matrix4::<f64>::identity() * 3.0;
            m[(1, 0)] = 1.0;
            m[(0, 1)] = 1.0;
            let big = m * 1e160;
            let b = vector![1.0, 2.0, -1.0, 0.5];
            let (x, y) = match n {
                2 => {
                    let (m, b) = (
                        big.fixed_view::<2, 2>(0, 0).into_owned(),
                        b.fixed_rows::<2>(0).into_owned(),
                    );
                    assert!(!solve_spd_flagged(&m, &b).1);
                    (
                        solve_spd(&m, &b).unwrap().as_slice().to_vec(),
                        Ldlt::new(&m).unwrap().solve(&b).as_slice().to_vec(),
                    )
                }
                3 => {
                    let (m, b) = (
                        big.fixed_view::<3, 3>(0, 0).into_owned(),
                        b.fixed_rows::<3>(0).into_owned(),
                    );
                    assert!(!solve_spd_flagged(&m, &b).1);
                    (
                        solve_spd(&m, &b).unwrap().as_slice().to_vec(),
                        Ldlt::new(&m).unwrap().solve(&b).as_slice().to_vec(),
                    )
                }
                _ => {
                    assert!(!solve_spd_flagged(&big, &b).1);
                    (
                        solve_spd(&big, &b).unwrap().as_slice().to_vec(),
                        Ldlt::new(&big).unwrap().solve(&b).as_slice().to_vec(),
                    )
                }
            };
            assert_eq!(x, y, "N = {n}");
        }
    }

    #[test]
    fn lu_solves_general_system_and_detects_singular() {
        let a = matrix![0.0, 2.0, 1.0; 1.0, 1.0, 0.0; 3.0, 0.0, 1.0];
        let b = vector![1.0, 2.0, 3.0];
        let x = lu_solve(&a, &b).unwrap();
        assert!((a * x - b).norm() < 1e-14);
        assert!(lu_solve(&matrix![1.0, 2.0; 2.0, 4.0], &vector![1.0, 1.0]).is_none());
    }

    #[test]
    fn block_lu_matches_dense_solve() {
        // A 4×4 system as 2×2 blocks of 2×2, with a zero leading block so pivoting must cross blocks.
        let a = [
            [matrix![0.0, 0.0; 0.0, 0.0], matrix![1.0, 2.0; 3.0, 1.0]],
            [matrix![2.0, 1.0; 1.0, 3.0], matrix![0.5, 0.0; 0.0, 0.5]],
        ];
        let b = [vector![1.0, 2.0], vector![3.0, 4.0]];
        let x = lu_solve_blocks(&a, &b).unwrap();
        for i in 0..2 {
            let r = a[i][0] * x[0] + a[i][1] * x[1] - b[i];
            assert!(r.norm() < 1e-14, "{r}");
        }
        let singular = [[matrix![1.0], matrix![2.0]], [matrix![2.0], matrix![4.0]]];
        assert!(lu_solve_blocks(&singular, &[vector![1.0], vector![1.0]]).is_none());
    }

    /// Well-conditioned SPD matrices of sizes 1 to 6 (AᵀA + I for a fixed A), and BᵀB for a B
    /// whose last column is a combination of the others (zero for N = 1): a coordinate that depends
    /// on the others.
    fn spd<const N: usize>() -> (SMatrix<f64, N, N>, SMatrix<f64, N, N>) {
        let a = SMatrix::<f64, N, N>::from_fn(|i, j| ((3 * i + 7 * j + 1) % 5) as f64 * 0.3 - 0.5);
        let m = a.transpose() * a + SMatrix::<f64, N, N>::identity();
        let mut b = a + SMatrix::<f64, N, N>::identity() * 2.0;
        let last = N - 1;
        for i in 0..N {
            b[(i, last)] = match last {
                0 => 0.0,
                1 => 0.6 * b[(i, 0)],
                _ => 0.6 * b[(i, 0)] - 0.8 * b[(i, 1)],
            };
        }
        (m, b.transpose() * b)
    }

    /// D M D for coordinate scales dᵢ from 1e-9 to 1e9.
    fn rescaled<const N: usize>(m: &SMatrix<f64, N, N>, k: usize) -> SMatrix<f64, N, N> {
        let d = SVector::<f64, N>::from_fn(|i, _| 10f64.powi(((i * 7 + k * 5) % 19) as i32 - 9));
        SMatrix::from_fn(|i, j| d[i] * m[(i, j)] * d[j])
    }

    fn spd_solves_accept<const N: usize>(m: &SMatrix<f64, N, N>) -> [bool; 4] {
        let b = SVector::<f64, N>::from_fn(|i, _| 1.0 + i as f64);
        [
            solve_spd(m, &b).is_ok(),
            solve_spd_flagged(m, &b).1,
            Ldlt::new(m).is_ok(),
            cholesky(m).is_ok(),
        ]
    }

    fn spd_tests_are_scale_invariant<const N: usize>() {
        let (m, dependent) = spd::<N>();
        for k in 0..6 {
            assert_eq!(
                spd_solves_accept(&rescaled(&m, k)),
                [true; 4],
                "N = {N}, k = {k}"
            );
            let refused = spd_solves_accept(&rescaled(&dependent, k));
            assert_eq!(refused, [false; 4], "N = {N}, k = {k}");
        }
    }

    #[test]
    fn spd_pivot_tests_do_not_depend_on_the_coordinates_units() {
        // Every SPD factorisation (the closed forms for N ≤ 2, the 2×2 blocks for N = 3 and 4, the
        // LDLᵀ and Cholesky factorisations for any N) accepts a well-conditioned M however its
        // coordinates are scaled (D M D, dᵢ from 1e-9 to 1e9: the largest diagonal entry 1e36
        // times the smallest), and refuses one with a dependent coordinate however scaled.
        spd_tests_are_scale_invariant::<1>();
        spd_tests_are_scale_invariant::<2>();
        spd_tests_are_scale_invariant::<3>();
        spd_tests_are_scale_invariant::<4>();
        spd_tests_are_scale_invariant::<5>();
        spd_tests_are_scale_invariant::<6>();
        // Kepler in polar coordinates in SI units: M = diag(m, m r²) with m = 1000 kg, r = 7e6 m.
        let kepler = matrix![1e3, 0.0; 0.0, 1e3 * 7e6 * 7e6];
        assert_eq!(spd_solves_accept(&kepler), [true; 4]);
        // The pattern-aware factorisation and a block of the tree recursion judged against the
        // whole's diagonal entries.
        let (m, _) = spd::<3>();
        let scaled = rescaled(&m, 1);
        let pattern = [[true; 3]; 3];
        assert!(Ldlt::with_pattern(&scaled, pattern).is_ok());
        let diagonal: [f64; 3] = std::array::from_fn(|i| scaled[(i, i)]);
        assert!(Ldlt::with_scales(&scaled, Dense, &diagonal).is_ok());
    }

    #[test]
    fn lu_pivot_tests_do_not_depend_on_the_units() {
        // A general (unsymmetric, well-conditioned) 4×4 matrix under the rescalings the Newton
        // matrices see — D A D (momenta against velocities), S A S⁻¹ (Radau's σ²I − σJᵥ − J_q),
        // D₁ A D₂ (equations and unknowns in unrelated units) — is factorised and solved to
        // round-off; a singular one is refused however scaled.
        let a = matrix![
            4.0, 1.0, -0.5, 0.3;
            0.7, 3.0, 0.2, -1.0;
            -0.4, 0.6, 5.0, 0.8;
            1.1, -0.3, 0.9, 2.5
        ];
        let mut singular = a;
        for j in 0..4 {
            singular[(3, j)] = 0.5 * a[(0, j)] - 2.0 * a[(2, j)];
        }
        let b = vector![1.0, -2.0, 0.5, 3.0];
        let x = lu_solve(&a, &b).unwrap();
        for k in 0..8 {
            let d1 = Matrix4::from_diagonal(&Vector4::from_fn(|i, _| {
                10f64.powi(((i * 7 + k * 5) % 19) as i32 - 9)
            }));
            let d2 = Matrix4::from_diagonal(&Vector4::from_fn(|i, _| {
                10f64.powi(((i * 3 + k * 11) % 19) as i32 - 9)
            }));
            let d1_inv = d1.try_inverse().unwrap();
            let d2_inv = d2.try_inverse().unwrap();
            for (scaled, left, right_inv) in [
                (d1 * a * d1, d1, d1_inv),
                (d1 * a * d1_inv, d1, d1),
                (d1 * a * d2, d1, d2_inv),
            ] {
                // (L A R) y = L b  ⇔  y = R⁻¹ x.
                let y = lu_solve(&scaled, &(left * b)).expect("scaled matrix refused");
                let back = right_inv.try_inverse().unwrap() * y;
                // κ(A) ≈ 5: the unscaled solution to ~1e-15; the scaled one, whose pivots are
                // chosen on the equilibrated matrix, to the same relative accuracy.
                assert!(
                    (back - x).norm() < 1e-13 * x.norm(),
                    "k = {k}: {back} vs {x}"
                );
                let blocks = [
                    [
                        scaled.fixed_view::<2, 2>(0, 0).into_owned(),
                        scaled.fixed_view::<2, 2>(0, 2).into_owned(),
                    ],
                    [
                        scaled.fixed_view::<2, 2>(2, 0).into_owned(),
                        scaled.fixed_view::<2, 2>(2, 2).into_owned(),
                    ],
                ];
                assert!(BlockLu::factor(&blocks).is_some());
            }
            for scaled in [
                d1 * singular * d1,
                d1 * singular * d1_inv,
                d1 * singular * d2,
            ] {
                assert!(
                    lu_solve(&scaled, &b).is_none(),
                    "k = {k}: singular accepted"
                );
            }
        }
    }
}
