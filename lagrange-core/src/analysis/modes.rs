//! Normal modes of small oscillations about a stable equilibrium.

use super::stability::{stability, symmetric_eigen, Stability, MARGINAL_TOLERANCE};
use super::{check_configuration, describe, mass_cholesky, mass_normalized};
use crate::error::{Error, Result};
use crate::mechanism::Mechanism;
use nalgebra::SMatrix;

/// Small oscillations about a stable equilibrium: δq(t) = Σⱼ cⱼ shapeⱼ cos(ωⱼ t + φⱼ).
///
/// ```
/// use lagrange_core::analysis::normal_modes;
/// # use lagrange_core::analysis::doc_models::Pendulum;
/// let modes = normal_modes(&Pendulum { m: 1.0, l: 1.0, g: 9.81 }, 0.0, &[0.0])?;
/// assert!((modes.frequencies[0] - 9.81f64.sqrt()).abs() < 1e-12);
/// assert!((modes.shapes[(0, 0)] - 1.0).abs() < 1e-12); // m l² shape² = 1
/// # Ok::<(), lagrange_core::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NormalModes<const N: usize> {
    /// Angular frequencies ωⱼ (rad per unit time), ascending.
    pub frequencies: [f64; N],
    /// Mode shapes as columns: column j belongs to `frequencies[j]`. M-normalized
    /// (shapeⱼᵀ M shapeₖ = δⱼₖ), signed so that the entry of largest magnitude is positive.
    pub shapes: SMatrix<f64, N, N>,
}

/// The normal modes about the stable equilibrium q at time t: the generalized eigenproblem
/// K v = ω² M v with K = ∂(b − 𝓕)/∂q and M from dual numbers.
///
/// Solved as in Golub & Van Loan, *Matrix Computations*, 4th ed., §8.7.2: Cholesky M = L Lᵀ, the
/// symmetric eigen-decomposition of L⁻¹ K L⁻ᵀ = Y Λ Yᵀ (nalgebra's `SymmetricEigen`), ωⱼ = √λⱼ,
/// shapes L⁻ᵀ Y (M-orthonormal). Velocity-dependent terms (damping, gyroscopic coupling) are not
/// part of this eigenproblem: the frequencies are those of the undamped, non-gyroscopic system; use
/// [`linearize`](super::linearize()) and the eigenvalues of its A for the full picture.
///
/// Errors: everything [`stability`](super::stability()) reports (not an equilibrium, singular M,
/// …), and [`Error::NoNormalModes`] unless the equilibrium is [`Stability::Stable`] with a
/// symmetric K (no circulatory forces) that is positive definite relative to M.
///
/// ```
/// use lagrange_core::analysis::normal_modes;
/// # use lagrange_core::analysis::doc_models::SpinningHoop;
/// // Bead at the bottom of a hoop spinning slowly: ω₀² = g/R − ω².
/// let hoop = SpinningHoop { m: 0.1, r: 0.5, g: 9.81, omega: 2.0 };
/// let modes = normal_modes(&hoop, 0.0, &[0.0])?;
/// assert!((modes.frequencies[0].powi(2) - (9.81 / 0.5 - 4.0)).abs() < 1e-12);
/// // M-normalized: m R² shape² = 1.
/// assert!((0.1 * 0.25 * modes.shapes[(0, 0)].powi(2) - 1.0).abs() < 1e-12);
/// # Ok::<(), lagrange_core::Error>(())
/// ```
pub fn normal_modes<M: Mechanism<N>, const N: usize>(
    mechanism: &M,
    t: f64,
    q: &M::Coords,
) -> Result<NormalModes<N>> {
    let analysis = stability(mechanism, t, q)?;
    let q = check_configuration(mechanism, t, q)?;
    let no_modes = |reason: String| Error::NoNormalModes {
        t,
        configuration: describe::<M, N>(&q),
        reason,
    };
    if analysis.stability != Stability::Stable {
        return Err(no_modes(format!(
            "the equilibrium is not stable ({:?}; smallest eigenvalue of K relative to M {:e})",
            analysis.stability, analysis.stiffness_eigenvalues[0]
        )));
    }
    let l = mass_cholesky::<M, N>(&analysis.mass_matrix, t, &q)?;
    let k = mass_normalized(&l, &analysis.stiffness);
    let asymmetry = (k - k.transpose()).norm();
    if asymmetry > MARGINAL_TOLERANCE * k.norm() {
        return Err(no_modes(format!(
            "the stiffness matrix is not symmetric (circulatory forces; ‖K̃ − K̃ᵀ‖ = {asymmetry:e}): \
             use the eigenvalues of the linearized system instead"
        )));
    }
    let k_sym = (k + k.transpose()) * 0.5;
    let (lambda, y) = symmetric_eigen(&k_sym).ok_or_else(|| Error::EigenvalueFailure {
        t,
        configuration: describe::<M, N>(&q),
    })?;
    if lambda[0].is_nan() || lambda[0] <= 0.0 {
        return Err(no_modes(format!(
            "K is not positive definite relative to M (eigenvalue {:e})",
            lambda[0]
        )));
    }
    let mut frequencies = [0.0; N];
    let mut shapes = SMatrix::<f64, N, N>::zeros();
    let lt = l.transpose();
    for j in 0..N {
        frequencies[j] = lambda[j].sqrt();
        let yj = SMatrix::<f64, N, 1>::from_fn(|i, _| y[(i, j)]);
        // v = L⁻ᵀ y: then vᵀ M v = yᵀ L⁻¹ L Lᵀ L⁻ᵀ y = yᵀ y = 1.
        let mut v = lt
            .solve_upper_triangular(&yj)
            .ok_or_else(|| no_modes("singular Cholesky factor".into()))?;
        let largest = v
            .iter()
            .copied()
            .fold(0.0f64, |m, x| if x.abs() > m.abs() { x } else { m });
        if largest < 0.0 {
            v = -v;
        }
        shapes.set_column(j, &v);
    }
    Ok(NormalModes {
        frequencies,
        shapes,
    })
}
