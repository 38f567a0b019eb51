//! [`Ldlt`]: the LDLᵀ factorisation on the hot path of `accelerations`, dense or with the
//! structural zeros of a declaration left out.

// `!(pivot > tol)` rather than `pivot <= tol`: the negated form also rejects NaN.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use super::{NotPositiveDefinite, SINGULAR_PIVOT};
use crate::geometry::Scalar;
use nalgebra::{SMatrix, SVector};

/// The factorisation M = L D Lᵀ of a symmetric positive definite M (L unit lower triangular, D
/// diagonal), stored with the reciprocals of D so a solve needs no division. Cheaper than Cholesky
/// for the tiny systems of mechanisms: no square roots, N divisions in all (Golub & Van Loan,
/// *Matrix Computations*, 4th ed., §4.1.2). This is the solve on the hot path of `accelerations`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ldlt<S: Scalar, const N: usize, P = Dense> {
    /// Strictly lower part: L (the unit diagonal is implicit).
    lower: SMatrix<S, N, N>,
    /// 1 / Dⱼⱼ.
    inverse_pivots: SVector<S, N>,
    /// Which entries of L may be nonzero; the others are exact zeros never formed.
    pattern: P,
}

/// Which entries of L an [`Ldlt`] forms: [`Dense`] (every one), or a pattern of structural zeros
/// (`[[bool; N]; N]`, `pattern[i][k]` for L_ik with i > k; see [`factor_pattern`](super::factor_pattern)), a constant
/// of the declaration for the compiler to fold.
///
/// ```
/// use lagrange_core::linalg::{Dense, FactorPattern};
/// assert!(FactorPattern::<2>::may_be_nonzero(&Dense, 1, 0));
/// let diagonal = [[false; 2]; 2];
/// assert!(!diagonal.may_be_nonzero(1, 0));
/// ```
pub trait FactorPattern<const N: usize>: Copy {
    /// Whether L_ik (i > k) may be nonzero.
    fn may_be_nonzero(&self, i: usize, k: usize) -> bool;
}

/// Every entry of L formed: the pattern of [`Ldlt::new`], at no cost.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Dense;

impl<const N: usize> FactorPattern<N> for Dense {
    #[inline(always)]
    fn may_be_nonzero(&self, _i: usize, _k: usize) -> bool {
        true
    }
}

impl<const N: usize> FactorPattern<N> for [[bool; N]; N] {
    #[inline(always)]
    fn may_be_nonzero(&self, i: usize, k: usize) -> bool {
        self[i][k]
    }
}

impl<S: Scalar, const N: usize> Ldlt<S, N> {
    /// Factorises M (only its lower triangle is read). Fails with the first pivot that is not
    /// clearly positive against its own diagonal entry (see [`SINGULAR_PIVOT`]); NaN never passes.
    #[inline]
    pub fn new(m: &SMatrix<S, N, N>) -> Result<Self, NotPositiveDefinite> {
        Self::with_pattern(m, Dense)
    }
}

impl<S: Scalar, const N: usize, P: FactorPattern<N>> Ldlt<S, N, P> {
    /// [`Ldlt::new`] for an M whose structural zeros are known: `pattern` is the pattern of L,
    /// [`factor_pattern`](super::factor_pattern) of M's; the entries outside it are never formed, in the factorisation
    /// and in the solves. M must be exactly zero wherever its pattern says so (as a mass matrix
    /// assembled from `Model::DEPENDS` is); the result then equals [`Ldlt::new`]'s, the terms left
    /// out being exact zeros.
    ///
    /// ```
    /// use lagrange_core::linalg::{factor_pattern, Ldlt};
    /// use nalgebra::{matrix, vector};
    /// // Coordinates 0 and 1 coupled, 2 on its own.
    /// const PATTERN: [[bool; 3]; 3] =
    ///     factor_pattern(&[[true, true, false], [true, true, false], [false, false, true]]);
    /// let m = matrix![4.0, 1.0, 0.0; 1.0, 3.0, 0.0; 0.0, 0.0, 2.0];
    /// let b = vector![1.0, 2.0, 3.0];
    /// let x = Ldlt::with_pattern(&m, PATTERN).unwrap().solve(&b);
    /// assert_eq!(x, Ldlt::new(&m).unwrap().solve(&b));
    /// ```
    #[inline(always)]
    pub fn with_pattern(m: &SMatrix<S, N, N>, pattern: P) -> Result<Self, NotPositiveDefinite> {
        Self::factor(m, pattern, |j| m[(j, j)].re().abs())
    }

    /// [`with_pattern`](Self::with_pattern) with pivot j tested against `scales[j]` instead of
    /// M's own diagonal entry Mⱼⱼ: for a block of a larger matrix, whose pivots are judged against
    /// the diagonal entries of the whole (the articulated-body recursion, `crate::tree`).
    ///
    /// ```
    /// use lagrange_core::linalg::{Dense, Ldlt};
    /// use nalgebra::matrix;
    /// // A pivot of 1e-14 is singular against a whole whose diagonal entry is 1, not on its own.
    /// let block = matrix![1e-14];
    /// assert!(Ldlt::with_scales(&block, Dense, &[1e-14]).is_ok());
    /// assert!(Ldlt::with_scales(&block, Dense, &[1.0]).is_err());
    /// ```
    #[inline(always)]
    pub fn with_scales(
        m: &SMatrix<S, N, N>,
        pattern: P,
        scales: &[f64; N],
    ) -> Result<Self, NotPositiveDefinite> {
        Self::factor(m, pattern, |j| scales[j])
    }

    /// The factorisation, pivot j failing when dⱼ ≤ [`SINGULAR_PIVOT`]·`scale(j)` (or NaN).
    #[inline(always)]
    fn factor(
        m: &SMatrix<S, N, N>,
        pattern: P,
        scale: impl Fn(usize) -> f64,
    ) -> Result<Self, NotPositiveDefinite> {
        let mut lower = SMatrix::<S, N, N>::zeros();
        let mut pivots = SVector::<S, N>::zeros();
        let mut inverse_pivots = SVector::<S, N>::zeros();
        for j in 0..N {
            // w_k = L_jk D_k, reused for the column below.
            let mut d = m[(j, j)];
            for k in 0..j {
                if pattern.may_be_nonzero(j, k) {
                    d -= lower[(j, k)] * lower[(j, k)] * pivots[k];
                }
            }
            if !(d.re() > SINGULAR_PIVOT * scale(j)) {
                return Err(NotPositiveDefinite {
                    index: j,
                    pivot: d.re(),
                });
            }
            let inv = d.recip();
            pivots[j] = d;
            inverse_pivots[j] = inv;
            for i in (j + 1)..N {
                if !pattern.may_be_nonzero(i, j) {
                    continue;
                }
                let mut s = m[(i, j)];
                for k in 0..j {
                    if pattern.may_be_nonzero(i, k) && pattern.may_be_nonzero(j, k) {
                        s -= lower[(i, k)] * lower[(j, k)] * pivots[k];
                    }
                }
                lower[(i, j)] = s * inv;
            }
        }
        Ok(Ldlt {
            lower,
            inverse_pivots,
            pattern,
        })
    }

    /// The factors of −M: L with the pivots negated. Their solve is −M⁻¹b, bit for bit the
    /// negation of [`solve`](Self::solve)'s (each step of the substitutions is a product or a
    /// difference, and rounding to nearest is symmetric under a change of sign), so a right-hand
    /// side that is a negation (M q̈ = −∇V) is solved without forming it.
    ///
    /// ```
    /// use lagrange_core::linalg::Ldlt;
    /// use nalgebra::{matrix, vector};
    /// let factors = Ldlt::new(&matrix![4.0, 1.0; 1.0, 3.0]).unwrap();
    /// let b = vector![0.3, -1.7];
    /// assert_eq!(factors.negated().solve(&b), factors.solve(&-b));
    /// ```
    #[inline]
    pub fn negated(&self) -> Self {
        Ldlt {
            lower: self.lower,
            inverse_pivots: -self.inverse_pivots,
            pattern: self.pattern,
        }
    }

    /// Solves M x = b, for a right-hand side of the factors' scalar or, when the factors are
    /// plain `f64` constants (a mass matrix factorised once), of any scalar.
    #[inline]
    pub fn solve<T>(&self, b: &SVector<T, N>) -> SVector<T, N>
    where
        T: Scalar + std::ops::Mul<S, Output = T>,
    {
        self.solve_in(b, self.pattern)
    }

    /// [`solve`](Self::solve), skipping the entries of L that `pattern` rules out: for factors
    /// stored once (dense) and solved with a pattern that is a constant where they are used.
    /// The pattern must hold every nonzero of L (true of the pattern the matrix's structural zeros
    /// imply, whose ruled-out entries a dense factorisation leaves exactly zero).
    #[inline]
    pub fn solve_in<T, Q: FactorPattern<N>>(&self, b: &SVector<T, N>, pattern: Q) -> SVector<T, N>
    where
        T: Scalar + std::ops::Mul<S, Output = T>,
    {
        let l = &self.lower;
        let mut x = *b;
        for i in 0..N {
            let mut s = x[i];
            for k in 0..i {
                if pattern.may_be_nonzero(i, k) {
                    s -= x[k] * l[(i, k)];
                }
            }
            x[i] = s;
        }
        for i in 0..N {
            x[i] = x[i] * self.inverse_pivots[i];
        }
        for i in (0..N).rev() {
            let mut s = x[i];
            for k in (i + 1)..N {
                if pattern.may_be_nonzero(k, i) {
                    s -= x[k] * l[(k, i)];
                }
            }
            x[i] = s;
        }
        x
    }
}
