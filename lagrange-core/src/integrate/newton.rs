//! Shared pieces of the implicit methods: exact Jacobians of the accelerations by dual numbers and
//! the convergence test of the Newton iterations.

use crate::error::Result;
use crate::mechanism::Mechanism;
use nalgebra::{SMatrix, SVector};
use num_dual::DualSVec;

/// Most Newton iterations an implicit step may take before it reports
/// [`Error::NewtonDiverged`](crate::Error::NewtonDiverged). With exact Jacobians the iteration
/// converges quadratically from the explicit predictor, so a well-posed step needs 3–6.
pub const MAX_NEWTON_ITERATIONS: usize = 20;

/// q̈ and its exact Jacobians ∂q̈/∂q and ∂q̈/∂q̇ at (t, q, q̇): two passes of the accelerations with
/// gradient dual numbers, seeded on q and then on q̇.
#[allow(clippy::type_complexity)]
pub fn acceleration_jacobians<M: Mechanism<N>, const N: usize>(
    mechanism: &M,
    t: f64,
    q: &[f64; N],
    v: &[f64; N],
) -> Result<([f64; N], SMatrix<f64, N, N>, SMatrix<f64, N, N>)> {
    let td = DualSVec::<f64, N>::from_re(t);
    let seeded: [DualSVec<f64, N>; N] =
        std::array::from_fn(|j| DualSVec::from_re(q[j]).derivative(j));
    let plain: [DualSVec<f64, N>; N] = std::array::from_fn(|j| DualSVec::from_re(v[j]));
    let by_q = mechanism.accelerations_at(td, &seeded, &plain)?;
    let plain_q: [DualSVec<f64, N>; N] = std::array::from_fn(|j| DualSVec::from_re(q[j]));
    let seeded_v: [DualSVec<f64, N>; N] =
        std::array::from_fn(|j| DualSVec::from_re(v[j]).derivative(j));
    let by_v = mechanism.accelerations_at(td, &plain_q, &seeded_v)?;
    let value = std::array::from_fn(|i| by_q[i].re);
    Ok((value, jacobian_rows(&by_q), jacobian_rows(&by_v)))
}

/// The matrix whose row i is the gradient carried by `f[i]`.
pub fn jacobian_rows<const N: usize, const R: usize>(
    f: &[DualSVec<f64, N>; R],
) -> SMatrix<f64, R, N> {
    let mut m = SMatrix::<f64, R, N>::zeros();
    for (i, fi) in f.iter().enumerate() {
        if let Some(g) = &fi.eps.0 {
            for j in 0..N {
                m[(i, j)] = g[j];
            }
        }
    }
    m
}

/// ‖x‖∞.
pub fn max_norm<const N: usize>(x: &SVector<f64, N>) -> f64 {
    x.iter().fold(0.0f64, |m, v| m.max(v.abs()))
}

/// Convergence test of a Newton iteration on its increments. Converged when the increment is at
/// the level of round-off of the unknowns (≤ 4ε·scale), or when it has become small (≤ 1e-10·scale)
/// and stopped shrinking (no longer decreasing by half: quadratic convergence has reached the
/// round-off floor of the residual evaluation, so further iterations only add noise).
#[derive(Debug)]
pub struct Convergence {
    previous: f64,
}

impl Convergence {
    pub fn new() -> Self {
        Convergence {
            previous: f64::INFINITY,
        }
    }

    /// `increment` and `scale` are ∞-norms of the Newton increment and of the unknowns.
    pub fn converged(&mut self, increment: f64, scale: f64) -> bool {
        let s = scale.max(1.0);
        let done = increment <= 4.0 * f64::EPSILON * s
            || (increment <= 1e-10 * s && increment > 0.5 * self.previous);
        self.previous = increment;
        done
    }
}

/// Whether constraint forces act at (t, q, v): compares `accelerations` (from
/// [`Mechanism::accelerations_at`]) with the solve of M q̈ = 𝓕 − b from
/// [`Mechanism::equations_of_motion_at`] at the same state. Identical for an unconstrained mechanism
/// (up to 1e-10 relative, for hand-optimized `accelerations_at`), different wherever a constraint
/// force acts (its accelerations solve the KKT system).
pub(crate) fn constraint_forces_act<M: Mechanism<N>, const N: usize>(
    mechanism: &M,
    t: f64,
    q: &[f64; N],
    v: &[f64; N],
    accelerations: &[f64; N],
) -> Result<bool> {
    let eom = mechanism.equations_of_motion_at(t, q, v);
    let free = crate::dynamics::solve_accelerations::<M::Coords, f64, N>(&eom, t, q)?;
    let scale = accelerations
        .iter()
        .chain(&free)
        .fold(1.0f64, |m, a| m.max(a.abs()));
    Ok(accelerations
        .iter()
        .zip(&free)
        .any(|(a, b)| (a - b).is_nan() || (a - b).abs() > 1e-10 * scale))
}

/// Refuses a mechanism whose accelerations are not those of its Lagrangian and generalized forces
/// alone — one with constraints, whose `accelerations_at` adds constraint forces (KKT system) —
/// for methods built on the Lagrangian itself (the variational integrator) or on the unconstrained
/// mass matrix (Störmer–Verlet). The test compares `accelerations` (from
/// [`Mechanism::accelerations_at`]) with the solve of M q̈ = 𝓕 − b from
/// [`Mechanism::equations_of_motion_at`] at the same state: identical for an unconstrained mechanism
/// (up to 1e-10 relative, for hand-optimized `accelerations_at`), different wherever a constraint
/// force acts.
pub fn refuse_constrained<M: Mechanism<N>, const N: usize>(
    mechanism: &M,
    method: &'static str,
    t: f64,
    q: &[f64; N],
    v: &[f64; N],
    accelerations: &[f64; N],
) -> Result<()> {
    if constraint_forces_act(mechanism, t, q, v, accelerations)? {
        return Err(crate::error::Error::UnsuitableMethod {
            method,
            reason: "the mechanism has constraints (its accelerations include constraint forces that its \
                     Lagrangian does not carry); use RK4, Dopri5, implicit midpoint or Gauss-Legendre, which \
                     integrate the constrained accelerations and project"
                .to_string(),
        });
    }
    Ok(())
}
