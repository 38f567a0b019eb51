//! Statics and small oscillations of any [`Mechanism`]: equilibria by the principle of virtual
//! work, their stability, linearization about any state, normal modes, and equilibrium branches over
//! a parameter.
//!
//! # The principle behind it
//!
//! A configuration q* is an **equilibrium** when a mechanism placed there at rest stays there:
//! q̈ = 0 at q̇ = 0. With M(q, t) q̈ = 𝓕 − b (see [`crate::dynamics`]) and M positive definite, that is
//!
//! ```text
//! r(q) = 𝓕(q, q̇ = 0, t) − b(q, q̇ = 0, t) = 0,
//! ```
//!
//! the principle of virtual work for equilibria, Σᵢ Fᵢ·δrᵢ = 0 for every virtual displacement, i.e.
//! every generalized force 𝓕ₖ = Σᵢ Fᵢ·∂rᵢ/∂qₖ vanishes (the lecture's eq. (5) and (7)). The term b
//! at rest is non-zero only for a rheonomic mechanism: it is the generalized inertial
//! ("centrifugal") force of a moving frame, e.g. the spinning hoop of a bead — so the same r covers
//! relative equilibria in a steadily moving frame.
//!
//! Everything is computed from the mechanism's own `Dynamics::equations_of_motion_at` and
//! `Dynamics::accelerations_at` evaluated on dual numbers (`num_dual::DualSVec`), so every
//! Jacobian below is exact to rounding — no finite differences:
//!
//! - the **stiffness matrix** K = ∂(b − 𝓕)/∂q at rest (the Hessian of V when the forces are
//!   conservative and the mechanism scleronomic);
//! - the **velocity matrix** D = ∂(b − 𝓕)/∂q̇ at rest (damping and gyroscopic terms);
//! - the blocks ∂q̈/∂q, ∂q̈/∂q̇ of the linearized first-order system.
//!
//! # What is here
//!
//! | function | result |
//! |---|---|
//! | [`equilibrium`] | q* with r(q*) = 0, by Newton's method with a backtracking line search |
//! | [`unbalanced_forces`] | r(q) itself: the generalized forces left over at rest |
//! | [`stability`] | [`Stability::Stable`] / [`Unstable`](Stability::Unstable) / [`Marginal`](Stability::Marginal) with the eigenvalues behind it |
//! | [`linearize`] | ẋ ≈ ẋ₀ + A δx (+ B u) about any state |
//! | [`normal_modes`] | frequencies and M-normalized shapes from K v = ω² M v |
//! | [`continuation`] | an equilibrium branch over a parameter |
//! | [`constrained_equilibrium`] | q* and the constraint forces λ of a mechanism with [`Constraints`](crate::constraints::Constraints), with its stability on the tangent space |
//!
//! ```
//! use lagrange_core::analysis::{equilibrium, normal_modes, stability, EquilibriumOptions, Stability};
//! # use lagrange_core::analysis::doc_models::Pendulum;
//! // A pendulum (length 2, g = 9.81) released near the bottom.
//! let pendulum = Pendulum { m: 1.0, l: 2.0, g: 9.81 };
//! let eq = equilibrium(&pendulum, 0.0, &[0.4], &EquilibriumOptions::default())?;
//! assert!(eq.q[0].abs() < 1e-12);
//! assert_eq!(stability(&pendulum, 0.0, &eq.q)?.stability, Stability::Stable);
//! let modes = normal_modes(&pendulum, 0.0, &eq.q)?;
//! assert!((modes.frequencies[0] - (9.81f64 / 2.0).sqrt()).abs() < 1e-12);
//! # Ok::<(), lagrange_core::Error>(())
//! ```

mod constrained;
mod continuation;
#[doc(hidden)]
pub mod doc_models;
mod equilibrium;
mod line_search;
mod linearize;
mod modes;
mod stability;

pub use constrained::{constrained_equilibrium, ConstrainedEquilibrium};
pub use continuation::{continuation, Branch, BranchPoint};
pub use equilibrium::{equilibrium, unbalanced_forces, Equilibrium, EquilibriumOptions};
pub use linearize::{linearize, linearize_driven, DrivenLinearization, Linearization};
pub use modes::{normal_modes, NormalModes};
pub use stability::{stability, Stability, StabilityAnalysis, StabilityMethod, MARGINAL_TOLERANCE};

use crate::error::{describe_configuration, Error, Result};
use crate::evaluation::rates::InRates;
use crate::evaluation::Evaluate;
use crate::mechanism::Mechanism;
use crate::model::Coordinates;
use nalgebra::{DMatrix, SMatrix, SVector};
use num_dual::DualSVec;

/// The gradient part of a gradient dual (zero when the value does not depend on the seeds).
#[inline]
fn gradient<const N: usize>(x: &DualSVec<f64, N>) -> SVector<f64, N> {
    x.eps.0.unwrap_or_else(SVector::zeros)
}

/// The Jacobian of a vector of gradient duals: row i = ∂yᵢ/∂(seeds).
fn jacobian<const N: usize>(y: &SVector<DualSVec<f64, N>, N>) -> SMatrix<f64, N, N> {
    let mut j = SMatrix::<f64, N, N>::zeros();
    for i in 0..N {
        j.set_row(i, &gradient(&y[i]).transpose());
    }
    j
}

/// The terms of the equations of motion at rest, with their exact derivatives.
#[derive(Clone, Copy, Debug)]
pub(crate) struct RestTerms<const N: usize> {
    /// r = 𝓕 − b at q̇ = 0.
    pub residual: SVector<f64, N>,
    /// The size r is measured against: ‖𝓕‖∞ + ‖b‖∞ + (‖∂𝓕/∂q‖∞ + ‖∂b/∂q‖∞)·max(1, ‖q‖∞) — the terms
    /// that cancel in r and the force a displacement of the size of q would bring.
    pub residual_scale: f64,
    /// K = −∂r/∂q.
    pub stiffness: SMatrix<f64, N, N>,
    /// The two parts of K before they cancel, −∂𝓕/∂q and ∂b/∂q: their size is the scale K is
    /// compared against (K itself vanishes at a bifurcation point).
    pub stiffness_parts: [SMatrix<f64, N, N>; 2],
    /// M(q, t).
    pub mass_matrix: SMatrix<f64, N, N>,
}

/// r, K and M at rest at (t, q), by one pass of gradient duals seeded on q. Of a mechanism with
/// quasi-velocities (q̇ = G(q) v), in the coordinates' rates ([`InRates`]): there the linearized
/// motion is M δq̈ + K δq = 0 in the coordinates themselves, as for every other mechanism (in the
/// velocities it would be M_v G⁻¹ δq̈ + K_v δq = 0).
pub(crate) fn rest_terms<M: Mechanism<N>, const N: usize>(
    mechanism: &M,
    t: f64,
    q: &[f64; N],
) -> RestTerms<N> {
    match M::QUASI_VELOCITIES {
        true => rest_terms_of(&InRates(mechanism), t, q),
        false => rest_terms_of(mechanism, t, q),
    }
}

/// [`rest_terms`] of an evaluation whose velocities are the coordinates' rates.
fn rest_terms_of<E: Evaluate<N>, const N: usize>(
    mechanism: &E,
    t: f64,
    q: &[f64; N],
) -> RestTerms<N> {
    let qd: [DualSVec<f64, N>; N] = std::array::from_fn(|j| DualSVec::from_re(q[j]).derivative(j));
    let zero: [DualSVec<f64, N>; N] = [DualSVec::from_re(0.0); N];
    let eom = mechanism.equations_of_motion_at(DualSVec::from_re(t), &qd, &zero);
    let r = eom.generalized_forces - eom.inertial_terms;
    let stiffness_parts = [
        -jacobian(&eom.generalized_forces),
        jacobian(&eom.inertial_terms),
    ];
    let row_sum_norm =
        |k: &SMatrix<f64, N, N>| (0..N).map(|i| k.row(i).abs().sum()).fold(0.0f64, f64::max);
    let residual_scale = max_abs(eom.generalized_forces.iter().map(|x| &x.re))
        + max_abs(eom.inertial_terms.iter().map(|x| &x.re))
        + (row_sum_norm(&stiffness_parts[0]) + row_sum_norm(&stiffness_parts[1]))
            * max_abs(q.iter()).max(1.0);
    RestTerms {
        residual: r.map(|x| x.re),
        residual_scale,
        stiffness: -jacobian(&r),
        stiffness_parts,
        mass_matrix: eom.mass_matrix.map(|x| x.re),
    }
}

/// D = ∂(b − 𝓕)/∂q̇ at rest at (t, q), and its parts −∂𝓕/∂q̇ and ∂b/∂q̇, by one pass of gradient
/// duals seeded on q̇ (in the coordinates' rates, as [`rest_terms`]).
pub(crate) fn rest_velocity_matrix<M: Mechanism<N>, const N: usize>(
    mechanism: &M,
    t: f64,
    q: &[f64; N],
) -> (SMatrix<f64, N, N>, [SMatrix<f64, N, N>; 2]) {
    match M::QUASI_VELOCITIES {
        true => rest_velocity_matrix_of(&InRates(mechanism), t, q),
        false => rest_velocity_matrix_of(mechanism, t, q),
    }
}

/// [`rest_velocity_matrix`] of an evaluation whose velocities are the coordinates' rates.
#[allow(clippy::type_complexity)]
fn rest_velocity_matrix_of<E: Evaluate<N>, const N: usize>(
    mechanism: &E,
    t: f64,
    q: &[f64; N],
) -> (SMatrix<f64, N, N>, [SMatrix<f64, N, N>; 2]) {
    let qd: [DualSVec<f64, N>; N] = std::array::from_fn(|j| DualSVec::from_re(q[j]));
    let vd: [DualSVec<f64, N>; N] = std::array::from_fn(|j| DualSVec::from_re(0.0).derivative(j));
    let eom = mechanism.equations_of_motion_at(DualSVec::from_re(t), &qd, &vd);
    (
        -jacobian(&(eom.generalized_forces - eom.inertial_terms)),
        [
            -jacobian(&eom.generalized_forces),
            jacobian(&eom.inertial_terms),
        ],
    )
}

/// r = 𝓕 − b at rest, values only (the cheap evaluation of a line search; in the coordinates'
/// rates, as [`rest_terms`]).
pub(crate) fn rest_residual<M: Mechanism<N>, const N: usize>(
    mechanism: &M,
    t: f64,
    q: &[f64; N],
) -> SVector<f64, N> {
    let eom = match M::QUASI_VELOCITIES {
        true => InRates(mechanism).equations_of_motion_at(t, q, &[0.0; N]),
        false => mechanism.equations_of_motion_at(t, q, &[0.0; N]),
    };
    eom.generalized_forces - eom.inertial_terms
}

/// Validates parameters, t and q (every public entry point does this first).
pub(crate) fn check_configuration<M: Mechanism<N>, const N: usize>(
    mechanism: &M,
    t: f64,
    q: &M::Coords,
) -> Result<[f64; N]> {
    mechanism.validate()?;
    let q = q.to_array();
    crate::model::check_state(&M::Coords::NAMES, t, &q, &[0.0; N])?;
    Ok(q)
}

/// Names a configuration for error messages.
pub(crate) fn describe<M: Mechanism<N>, const N: usize>(q: &[f64; N]) -> String {
    describe_configuration(&M::Coords::NAMES, q)
}

/// The lower Cholesky factor of M, or the mass-matrix error naming the configuration.
pub(crate) fn mass_cholesky<M: Mechanism<N>, const N: usize>(
    mass_matrix: &SMatrix<f64, N, N>,
    t: f64,
    q: &[f64; N],
) -> Result<SMatrix<f64, N, N>> {
    crate::linalg::cholesky(mass_matrix).map_err(|e| Error::SingularMassMatrix {
        t,
        configuration: describe::<M, N>(q),
        coordinate: M::Coords::NAMES[e.index],
        pivot: e.pivot,
    })
}

/// L⁻¹ X L⁻ᵀ for the lower Cholesky factor L of M: X in coordinates where M is the identity
/// (eigenvalues of the result are those of the pencil (X, M); Golub & Van Loan, *Matrix
/// Computations*, 4th ed., §8.7.2, the Cholesky reduction of the symmetric-definite problem).
pub(crate) fn mass_normalized<const N: usize>(
    l: &SMatrix<f64, N, N>,
    x: &SMatrix<f64, N, N>,
) -> SMatrix<f64, N, N> {
    let linv = l
        .solve_lower_triangular(&SMatrix::<f64, N, N>::identity())
        .unwrap_or_else(SMatrix::zeros);
    linv * x * linv.transpose()
}

/// A fixed-size matrix as a dynamically sized one (nalgebra's eigen-solvers need `DimSub`, which
/// a generic const `N` does not provide).
pub(crate) fn to_dmatrix<const R: usize, const C: usize>(m: &SMatrix<f64, R, C>) -> DMatrix<f64> {
    DMatrix::from_column_slice(R, C, m.as_slice())
}

/// Largest absolute value.
pub(crate) fn max_abs<'a>(x: impl IntoIterator<Item = &'a f64>) -> f64 {
    x.into_iter().fold(0.0f64, |m, v| m.max(v.abs()))
}
