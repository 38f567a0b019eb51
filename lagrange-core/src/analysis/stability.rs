//! Stability of an equilibrium from the stiffness matrix relative to the mass matrix, or from the
//! eigenvalues of the linearized first-order system.

use super::{
    check_configuration, describe, mass_cholesky, mass_normalized, max_abs, rest_terms,
    rest_velocity_matrix, to_dmatrix, RestTerms,
};
use crate::error::{Error, Result};
use crate::mechanism::Mechanism;
use nalgebra::{Complex, DMatrix, SMatrix};

/// Relative size under which an eigenvalue counts as zero in [`stability`]: |λ| ≤ 1e-8·s² for the
/// eigenvalues λ of K relative to M, |Re μ| ≤ 1e-8·s for those of the linearized system, with
/// s = √(‖M⁻¹K_𝓕‖ + ‖M⁻¹K_b‖) + ‖M⁻¹D_𝓕‖ + ‖M⁻¹D_b‖ the system's own rate scale (Frobenius norms of
/// the mass-normalized parts of K and D that come from the forces 𝓕 and from the inertial terms b,
/// before they cancel). The eigenvalues come from exact derivatives and backward-stable
/// eigen-solvers, so a simple eigenvalue is
/// accurate to a few ε·s²; the margin leaves room for near-multiple eigenvalues and for parameters
/// that put the mechanism on a bifurcation only up to rounding (ω² = g/R for the hoop).
///
/// ```
/// use lagrange_core::analysis::{stability, Stability, MARGINAL_TOLERANCE};
/// # use lagrange_core::analysis::doc_models::SpinningHoop;
/// // Exactly at the critical spin ω² = g/R (up to rounding) the bottom is neutral at linear order.
/// let hoop = SpinningHoop { m: 0.1, r: 0.5, g: 9.81, omega: (9.81f64 / 0.5).sqrt() };
/// let s = stability(&hoop, 0.0, &[0.0])?;
/// assert_eq!(s.stability, Stability::Marginal);
/// assert!(s.stiffness_eigenvalues[0].abs() < MARGINAL_TOLERANCE);
/// # Ok::<(), lagrange_core::Error>(())
/// ```
pub const MARGINAL_TOLERANCE: f64 = 1e-8;

/// A configuration counts as an equilibrium when ‖𝓕 − b‖∞ ≤ 1e-8·(‖𝓕‖∞ + ‖b‖∞ + (‖∂𝓕/∂q‖∞ +
/// ‖∂b/∂q‖∞)·max(1, ‖q‖∞)), i.e. when it is within about 1e-8 (relative) of a regular root.
const EQUILIBRIUM_TOLERANCE: f64 = 1e-8;

/// What small disturbances of an equilibrium do.
///
/// ```
/// use lagrange_core::analysis::{stability, Stability};
/// # use lagrange_core::analysis::doc_models::SpinningHoop;
/// let hoop = |omega| SpinningHoop { m: 0.1, r: 0.5, g: 9.81, omega };
/// let describe = |s: Stability| match s {
///     Stability::Stable => "stays",
///     Stability::Unstable => "leaves",
///     Stability::Marginal => "undecided",
/// };
/// assert_eq!(describe(stability(&hoop(3.0), 0.0, &[0.0])?.stability), "stays");
/// assert_eq!(describe(stability(&hoop(6.0), 0.0, &[0.0])?.stability), "leaves");
/// # Ok::<(), lagrange_core::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Stability {
    /// Small disturbances stay small (a strict minimum of the potential, possibly with damping or
    /// gyroscopic forces; or all eigenvalues of the linearized system in the open left half-plane).
    Stable,
    /// Some small disturbance grows exponentially (an eigenvalue with positive real part).
    Unstable,
    /// The linear analysis cannot decide: a zero eigenvalue of K relative to M (a neutral
    /// direction, a bifurcation point) or eigenvalues of the linearized system on the imaginary
    /// axis with non-conservative forces. Higher-order terms decide.
    Marginal,
}

/// Which criterion [`stability`] used.
///
/// ```
/// use lagrange_core::analysis::{stability, StabilityMethod};
/// # use lagrange_core::analysis::doc_models::Pendulum;
/// // A conservative mechanism is decided from K relative to M.
/// let s = stability(&Pendulum { m: 1.0, l: 1.0, g: 9.81 }, 0.0, &[0.0])?;
/// assert_eq!(s.method, StabilityMethod::Potential);
/// # Ok::<(), lagrange_core::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum StabilityMethod {
    /// The eigenvalues of K relative to M (K symmetric, no circulatory forces; the velocity terms
    /// at most gyroscopic or dissipative): Lagrange–Dirichlet and Kelvin–Tait–Chetaev.
    Potential,
    /// The eigenvalues of the linearized first-order system ẋ = A x.
    Linearized,
}

/// The stability of an equilibrium and everything it was decided from.
///
/// ```
/// use lagrange_core::analysis::stability;
/// # use lagrange_core::analysis::doc_models::Pendulum;
/// // Pendulum at the bottom: K = m g l, M = m l², so λ = g/l and μ = ±i√(g/l).
/// let s = stability(&Pendulum { m: 2.0, l: 0.5, g: 9.81 }, 0.0, &[0.0])?;
/// assert!((s.stiffness[(0, 0)] - 2.0 * 9.81 * 0.5).abs() < 1e-12);
/// assert!((s.stiffness_eigenvalues[0] - 9.81 / 0.5).abs() < 1e-12);
/// assert!(s.system_eigenvalues.iter().all(|mu| mu.re.abs() < 1e-12));
/// assert!((s.system_eigenvalues[0].im.abs() - (9.81f64 / 0.5).sqrt()).abs() < 1e-12);
/// # Ok::<(), lagrange_core::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct StabilityAnalysis<const N: usize> {
    /// The verdict.
    pub stability: Stability,
    /// The criterion it came from.
    pub method: StabilityMethod,
    /// K = ∂(b − 𝓕)/∂q at rest.
    pub stiffness: SMatrix<f64, N, N>,
    /// D = ∂(b − 𝓕)/∂q̇ at rest: damping (symmetric part) and gyroscopic terms (antisymmetric part).
    pub velocity_matrix: SMatrix<f64, N, N>,
    /// M at the equilibrium.
    pub mass_matrix: SMatrix<f64, N, N>,
    /// Eigenvalues λ of the symmetric part of K relative to M (K v = λ M v), ascending. For a
    /// conservative mechanism these are the squared small-oscillation frequencies ω² when positive.
    pub stiffness_eigenvalues: [f64; N],
    /// The 2N eigenvalues μ of the linearized system A = [0 I; −M⁻¹K −M⁻¹D], largest real part
    /// first. Disturbances grow or decay like e^{μt}.
    pub system_eigenvalues: Vec<Complex<f64>>,
}

/// Classifies the equilibrium q at time t as [`Stability::Stable`], [`Unstable`](Stability::Unstable)
/// or [`Marginal`](Stability::Marginal).
///
/// With K = ∂(b − 𝓕)/∂q and D = ∂(b − 𝓕)/∂q̇ at rest (exact, from dual numbers) the linearized
/// equations are M δq̈ + D δq̇ + K δq = 0. Working in mass-normalized coordinates (M = L Lᵀ,
/// K̃ = L⁻¹ K L⁻ᵀ, D̃ = L⁻¹ D L⁻ᵀ):
///
/// - **no circulatory forces** (K symmetric) and velocity terms at most dissipative and gyroscopic
///   (symmetric part of D positive semidefinite) — in particular conservative forces, where K is the
///   Hessian of V (or of the effective potential of a steadily moving frame): the eigenvalues λ of K
///   relative to M decide. All λ > 0: a strict minimum, stable (Lagrange–Dirichlet; damping and
///   gyroscopic forces do not change that, Kelvin–Tait–Chetaev: D. R. Merkin, *Introduction to the
///   Theory of Stability*, Springer, 1997). Some λ < 0 and D = 0: unstable (the linearized system has
///   the root +√(−λ); Lyapunov's indirect method). Smallest λ ≈ 0: marginal.
/// - otherwise (velocity-independent non-conservative "circulatory" forces, negative damping, or a
///   maximum of V with gyroscopic terms that might stabilize it): the eigenvalues μ of
///   A = [0 I; −M⁻¹K −M⁻¹D] decide (Lyapunov's indirect method: all Re μ < 0 stable, some Re μ > 0
///   unstable, otherwise marginal).
///
/// "≈ 0" is relative, see [`MARGINAL_TOLERANCE`]. For a rheonomic mechanism this treats the
/// linearization at time t as time-independent, which is right for a steadily moving frame (a hoop
/// spinning at constant rate) and meaningless for a periodically forced one.
///
/// Errors: non-finite input, [`Error::NotAnEquilibrium`] when the generalized forces at rest are not
/// balanced at q (relative tolerance 1e-8, see [`unbalanced_forces`](super::unbalanced_forces)),
/// a singular mass matrix, [`Error::EigenvalueFailure`] if an eigen-solver does not converge.
///
/// ```
/// use lagrange_core::analysis::{stability, Stability};
/// # use lagrange_core::analysis::doc_models::Pendulum;
/// let p = Pendulum { m: 1.0, l: 1.0, g: 9.81 };
/// assert_eq!(stability(&p, 0.0, &[0.0])?.stability, Stability::Stable);
/// let top = stability(&p, 0.0, &[std::f64::consts::PI])?;
/// assert_eq!(top.stability, Stability::Unstable);
/// assert!((top.stiffness_eigenvalues[0] + 9.81).abs() < 1e-12); // λ = −g/l
/// assert!(stability(&p, 0.0, &[0.5]).is_err()); // not an equilibrium
/// # Ok::<(), lagrange_core::Error>(())
/// ```
pub fn stability<M: Mechanism<N>, const N: usize>(
    mechanism: &M,
    t: f64,
    q: &M::Coords,
) -> Result<StabilityAnalysis<N>> {
    let q = check_configuration(mechanism, t, q)?;
    let (terms, velocity_matrix, velocity_parts) = balanced_rest_terms(mechanism, t, &q)?;

    let l = mass_cholesky::<M, N>(&terms.mass_matrix, t, &q)?;
    let k = mass_normalized(&l, &terms.stiffness);
    let d = mass_normalized(&l, &velocity_matrix);
    let eigen_failure = || Error::EigenvalueFailure {
        t,
        configuration: describe::<M, N>(&q),
    };

    let k_sym = (k + k.transpose()) * 0.5;
    let k_skew = (k - k.transpose()) * 0.5;
    let d_sym = (d + d.transpose()) * 0.5;
    let lambda = symmetric_eigenvalues(&k_sym).ok_or_else(eigen_failure)?;
    let d_eigen = symmetric_eigenvalues(&d_sym).ok_or_else(eigen_failure)?;
    let mu = system_eigenvalues(&k, &d).ok_or_else(eigen_failure)?;

    // The system's own rate scale s (1/time), see MARGINAL_TOLERANCE: from the parts of K and D
    // before they cancel (forces and inertial terms), so that K = 0 at a bifurcation point is
    // measured against the stiffness of the forces that balance there.
    let part_norm = |parts: &[SMatrix<f64, N, N>; 2]| {
        parts
            .iter()
            .map(|p| mass_normalized(&l, p).norm())
            .sum::<f64>()
    };
    let s = part_norm(&terms.stiffness_parts).sqrt() + part_norm(&velocity_parts);
    let tol = MARGINAL_TOLERANCE;
    let lambda_min = lambda.first().copied().unwrap_or(0.0);
    let circulatory = k_skew.norm() > tol * s * s;
    let has_velocity_terms = d.norm() > tol * s;
    let dissipative_or_gyroscopic = d_eigen.first().is_none_or(|&e| e >= -tol * s);

    let (stability, method) = verdict(
        s,
        lambda_min,
        circulatory,
        has_velocity_terms,
        dissipative_or_gyroscopic,
        &mu,
    );
    let mut stiffness_eigenvalues = [0.0; N];
    stiffness_eigenvalues.copy_from_slice(&lambda);
    Ok(StabilityAnalysis {
        stability,
        method,
        stiffness: terms.stiffness,
        velocity_matrix,
        mass_matrix: terms.mass_matrix,
        stiffness_eigenvalues,
        system_eigenvalues: mu,
    })
}

/// The terms at rest at q (see [`RestTerms`]) and the velocity matrix D with its parts, once all
/// are finite and the generalized forces balance at q (relative tolerance
/// [`EQUILIBRIUM_TOLERANCE`]).
#[allow(clippy::type_complexity)]
fn balanced_rest_terms<M: Mechanism<N>, const N: usize>(
    mechanism: &M,
    t: f64,
    q: &[f64; N],
) -> Result<(RestTerms<N>, SMatrix<f64, N, N>, [SMatrix<f64, N, N>; 2])> {
    let terms = rest_terms(mechanism, t, q);
    let (velocity_matrix, velocity_parts) = rest_velocity_matrix(mechanism, t, q);
    let finite = terms
        .residual
        .iter()
        .chain(terms.stiffness.iter())
        .chain(velocity_matrix.iter())
        .chain(terms.mass_matrix.iter())
        .all(|x| x.is_finite());
    if !finite {
        return Err(Error::NonFiniteDynamics {
            t,
            configuration: describe::<M, N>(q),
        });
    }
    let residual = max_abs(terms.residual.iter());
    if residual > EQUILIBRIUM_TOLERANCE * terms.residual_scale {
        return Err(Error::NotAnEquilibrium {
            t,
            configuration: describe::<M, N>(q),
            residual,
        });
    }
    Ok((terms, velocity_matrix, velocity_parts))
}

/// The verdict of [`stability`] and the criterion it came from, at the rate scale `s`: the
/// stiffness eigenvalues (smallest `lambda_min`) where the potential criterion applies (no
/// circulatory forces, velocity terms at most dissipative and gyroscopic), otherwise the largest
/// real part of the system eigenvalues `mu` (largest first).
fn verdict(
    s: f64,
    lambda_min: f64,
    circulatory: bool,
    has_velocity_terms: bool,
    dissipative_or_gyroscopic: bool,
    mu: &[Complex<f64>],
) -> (Stability, StabilityMethod) {
    let tol = MARGINAL_TOLERANCE;
    let potential = if s == 0.0 {
        // Nothing acts at all (a free particle): every direction is neutral.
        Some(Stability::Marginal)
    } else if !circulatory && dissipative_or_gyroscopic {
        if lambda_min > tol * s * s {
            Some(Stability::Stable)
        } else if lambda_min >= -tol * s * s {
            Some(Stability::Marginal)
        } else if !has_velocity_terms {
            Some(Stability::Unstable)
        } else {
            None
        }
    } else {
        None
    };
    match potential {
        Some(verdict) => (verdict, StabilityMethod::Potential),
        None => {
            let re_max = mu.first().map_or(0.0, |z| z.re);
            let verdict = if re_max > tol * s {
                Stability::Unstable
            } else if re_max < -tol * s {
                Stability::Stable
            } else {
                Stability::Marginal
            };
            (verdict, StabilityMethod::Linearized)
        }
    }
}

/// Iteration cap handed to nalgebra's eigen-solvers (they loop forever with 0); far more than the
/// few sweeps per eigenvalue the implicit QR iteration needs.
const EIGEN_ITERATIONS: usize = 100_000;

/// Eigenvalues of a symmetric matrix, ascending; `None` if the iteration does not converge.
pub(crate) fn symmetric_eigenvalues<const N: usize>(m: &SMatrix<f64, N, N>) -> Option<Vec<f64>> {
    let eig = nalgebra::SymmetricEigen::try_new(to_dmatrix(m), f64::EPSILON, EIGEN_ITERATIONS)?;
    let mut values: Vec<f64> = eig.eigenvalues.iter().copied().collect();
    values.sort_by(f64::total_cmp);
    Some(values)
}

/// Symmetric eigen-decomposition: eigenvalues ascending with their orthonormal eigenvectors.
pub(crate) fn symmetric_eigen<const N: usize>(
    m: &SMatrix<f64, N, N>,
) -> Option<(Vec<f64>, DMatrix<f64>)> {
    symmetric_eigen_dynamic(to_dmatrix(m))
}

/// [`symmetric_eigen`] of a matrix whose size is not a type.
pub(crate) fn symmetric_eigen_dynamic(m: DMatrix<f64>) -> Option<(Vec<f64>, DMatrix<f64>)> {
    let n = m.nrows();
    let eig = nalgebra::SymmetricEigen::try_new(m, f64::EPSILON, EIGEN_ITERATIONS)?;
    let mut order: Vec<usize> = (0..n).collect();
    order.sort_by(|&a, &b| eig.eigenvalues[a].total_cmp(&eig.eigenvalues[b]));
    let values = order.iter().map(|&i| eig.eigenvalues[i]).collect();
    let vectors = DMatrix::from_fn(n, n, |r, c| eig.eigenvectors[(r, order[c])]);
    Some((values, vectors))
}

/// Eigenvalues of [0 I; −K −D], largest real part first (then largest imaginary part).
fn system_eigenvalues<const N: usize>(
    k: &SMatrix<f64, N, N>,
    d: &SMatrix<f64, N, N>,
) -> Option<Vec<Complex<f64>>> {
    let mut a = DMatrix::<f64>::zeros(2 * N, 2 * N);
    for i in 0..N {
        a[(i, N + i)] = 1.0;
        for j in 0..N {
            a[(N + i, j)] = -k[(i, j)];
            a[(N + i, N + j)] = -d[(i, j)];
        }
    }
    let schur = nalgebra::Schur::try_new(a, f64::EPSILON, EIGEN_ITERATIONS)?;
    let mut mu: Vec<Complex<f64>> = schur.complex_eigenvalues().iter().copied().collect();
    mu.sort_by(|x, y| y.re.total_cmp(&x.re).then(y.im.total_cmp(&x.im)));
    Some(mu)
}
