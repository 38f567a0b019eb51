//! The symmetric positive definite solve for three or four coordinates by 2×2 blocks: the
//! leading 2×2 block A is eliminated in closed form, leaving its Schur complement, itself 1×1 or
//! 2×2 (Golub & Van Loan, *Matrix Computations*, 4th ed., §4.2.8 and §3.2.11 on block
//! factorisations). With
//!
//! ```text
//! M = [A  Bᵀ]     adj(A) = [ a₁₁  −a₁₀]     det A = a₀₀a₁₁ − a₁₀²,
//!     [B  C ],             [−a₁₀   a₀₀],
//!
//! S = C − B A⁻¹ Bᵀ,   S x₂ = b₂ − B A⁻¹ b₁,   x₁ = A⁻¹ (b₁ − Bᵀ x₂),   A⁻¹ = adj(A) / det A,
//! ```
//!
//! the pivots are those of the LDLᵀ factorisation in exact arithmetic: d₀ = a₀₀, d₁ = det A / a₀₀,
//! d₂ = S₀₀ and, for four coordinates, d₃ = det S / S₀₀. Two divisions stand in series where the
//! factorisation has one per pivot, and the tests dⱼ > tol·|Mⱼⱼ| (each pivot against its own
//! diagonal entry, as in `Ldlt`) are taken without dividing (d₁ > tol·|a₁₁| ⇔ det A > tol·|a₁₁|·d₀
//! once d₀ > 0), off the chain of dependent operations and folded into one flag with `&`.

// `!(pivot > tol)` rather than `pivot <= tol`: the negated form also rejects NaN.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use super::SINGULAR_PIVOT;
use crate::geometry::Scalar;
use nalgebra::{SMatrix, SVector};

/// The solve of M x = b for N = 3 or 4 (see the module's documentation): x, and whether every pivot
/// passed its test (x is meaningless when one did not).
#[inline(always)]
pub(super) fn solve<S: Scalar, const N: usize>(
    m: &SMatrix<S, N, N>,
    b: &SVector<S, N>,
) -> (SVector<S, N>, bool) {
    debug_assert!(N == 3 || N == 4);
    let (a00, a10, a11) = (m[(0, 0)], m[(1, 0)], m[(1, 1)]);
    let det_a = a00 * a11 - a10 * a10;
    let inv_det_a = det_a.recip();
    // adj(A) times row i of B and times b₁: no division, beside det A's.
    let adj = |x0: S, x1: S| (a11 * x0 - a10 * x1, a00 * x1 - a10 * x0);
    let w2 = adj(m[(2, 0)], m[(2, 1)]);
    let top = adj(b[0], b[1]);
    // (B A⁻¹ y) for row i of B, from adj(A) times that row.
    let along = |w: (S, S), y0: S, y1: S| (w.0 * y0 + w.1 * y1) * inv_det_a;
    let s00 = m[(2, 2)] - along(w2, m[(2, 0)], m[(2, 1)]);
    let rhs2 = b[2] - along(w2, b[0], b[1]);
    // Each pivot against its own diagonal entry (see `SINGULAR_PIVOT`).
    let tol = |j: usize| SINGULAR_PIVOT * m[(j, j)].re().abs();
    let leading = (a00.re() > tol(0)) & (det_a.re() > tol(1) * a00.re());
    let mut x = *b;
    if N == 3 {
        x[2] = rhs2 / s00;
        x[0] = (top.0 - w2.0 * x[2]) * inv_det_a;
        x[1] = (top.1 - w2.1 * x[2]) * inv_det_a;
        // `&`, not `&&`: the tests are cheap, and one branch is what the caller wants.
        return (x, leading & (s00.re() > tol(2)));
    }
    let w3 = adj(m[(3, 0)], m[(3, 1)]);
    let s10 = m[(3, 2)] - along(w3, m[(2, 0)], m[(2, 1)]);
    let s11 = m[(3, 3)] - along(w3, m[(3, 0)], m[(3, 1)]);
    let rhs3 = b[3] - along(w3, b[0], b[1]);
    let det_s = s00 * s11 - s10 * s10;
    let inv_det_s = det_s.recip();
    x[2] = (s11 * rhs2 - s10 * rhs3) * inv_det_s;
    x[3] = (s00 * rhs3 - s10 * rhs2) * inv_det_s;
    x[0] = (top.0 - w2.0 * x[2] - w3.0 * x[3]) * inv_det_a;
    x[1] = (top.1 - w2.1 * x[2] - w3.1 * x[3]) * inv_det_a;
    let trailing = (s00.re() > tol(2)) & (det_s.re() > tol(3) * s00.re());
    (x, leading & trailing)
}

#[cfg(test)]
mod tests {
    use super::super::Ldlt;
    use super::*;
    use nalgebra::{matrix, vector, Matrix4};
    use num_dual::Dual64;

    /// A well-conditioned SPD 4×4: AᵀA + I for a fixed A.
    fn spd4() -> Matrix4<f64> {
        let a = matrix![
            1.0, 0.3, -0.2, 0.5;
            0.1, 2.0, 0.4, -0.3;
            -0.6, 0.2, 1.5, 0.1;
            0.4, -0.5, 0.3, 1.2
        ];
        a.transpose() * a + Matrix4::identity()
    }

    #[test]
    fn agrees_with_the_factorisation() {
        // Both solves are backward stable for SPD M, so they agree to about κ(M)·ε relative;
        // κ of this M is below 10, and 1e-14 leaves a margin of ~40 ulps.
        let m4 = spd4();
        let b4 = vector![1.0, -2.0, 0.5, 3.0];
        let (x, ok) = solve(&m4, &b4);
        let y = Ldlt::new(&m4).unwrap().solve(&b4);
        assert!(ok && (x - y).norm() < 1e-14 * y.norm(), "{x} vs {y}");
        let m3 = m4.fixed_view::<3, 3>(0, 0).into_owned();
        let b3 = vector![1.0, -2.0, 0.5];
        let (x, ok) = solve(&m3, &b3);
        let y = Ldlt::new(&m3).unwrap().solve(&b3);
        assert!(ok && (x - y).norm() < 1e-14 * y.norm(), "{x} vs {y}");
    }

    #[test]
    fn fails_where_the_factorisation_does() {
        // Each pivot made singular in turn (a row a copy of a row above, or a zero or negative or
        // NaN diagonal), in both sizes: the flag fails wherever the factorisation does.
        let base = spd4();
        let mut cases: Vec<Matrix4<f64>> = Vec::new();
        for k in 0..4 {
            let mut zero = base;
            zero[(k, k)] = if k == 0 { 0.0 } else { -50.0 };
            cases.push(zero);
            let mut nan = base;
            nan[(k, k)] = f64::NAN;
            cases.push(nan);
        }
        // Row and column 3 a copy of row and column 1: d₃ = 0 in exact arithmetic.
        let mut dependent = base;
        for j in 0..4 {
            dependent[(3, j)] = base[(1, j)];
            dependent[(j, 3)] = base[(j, 1)];
        }
        dependent[(3, 3)] = base[(1, 1)];
        cases.push(dependent);
        for m in cases {
            assert!(Ldlt::new(&m).is_err(), "{m}");
            assert!(!solve(&m, &vector![1.0, 1.0, 1.0, 1.0]).1, "{m}");
            let m3 = m.fixed_view::<3, 3>(0, 0).into_owned();
            if Ldlt::new(&m3).is_err() {
                assert!(!solve(&m3, &vector![1.0, 1.0, 1.0]).1, "{m3}");
            }
        }
    }

    #[test]
    fn differentiates_like_the_factorisation() {
        // d/ds of M(s)⁻¹ b through dual numbers: the derivative of the same rational function,
        // so it agrees with the factorisation's to round-off as the values do.
        let s = Dual64::from_re(0.5).derivative();
        let m = spd4().map(Dual64::from) + Matrix4::<f64>::identity().map(|e: f64| s * e);
        let b = vector![1.0, -2.0, 0.5, 3.0].map(Dual64::from);
        let (x, ok) = solve(&m, &b);
        let y = Ldlt::new(&m).unwrap().solve(&b);
        assert!(ok);
        for k in 0..4 {
            assert!((x[k].re - y[k].re).abs() < 1e-14 && (x[k].eps - y[k].eps).abs() < 1e-13);
        }
    }
}
