//! The canonical (Hamiltonian) equations of a mechanism, written with the Lagrangian's own
//! functions, shared by the methods that live on (q, p): implicit midpoint, Gauss–Legendre and the
//! variational integrator.
//!
//! With p = ∂L/∂q̇(t, q, q̇) and v(t, q, p) its inverse (the velocities with ∂L/∂q̇(t, q, v) = p),
//! the equations of motion with non-conservative generalized forces F_nc are
//!
//! ```text
//! q̇ = v(t, q, p),     ṗ = G(t, q, v) := ∂L/∂q(t, q, v) + F_nc(t, q, v)     at v = v(t, q, p)
//! ```
//!
//! (the Euler–Lagrange equations d/dt ∂L/∂q̇ = ∂L/∂q + F_nc, first order in (q, p); without F_nc
//! this is Hamilton's system for H = p·v − L, Arnold, *Mathematical Methods of Classical
//! Mechanics*, §15). Because L = T − V and the generalized forces 𝓕 of the equations of motion
//! already contain −∇V, G = ∂T/∂q + 𝓕 = ∂(T − V)/∂q + (𝓕 + ∇V): the gradient of T by one gradient
//! dual pass over q at fixed q̇, plus 𝓕 — the potential and the non-conservative part need not be
//! separated ([`momentum_rate`]).

use super::newton::jacobian_rows;
use super::Stats;
use crate::error::{describe_configuration, Error, Result};
pub(crate) use crate::evaluation::momentum_rate;
use crate::evaluation::Evaluate;
use crate::geometry::Scalar;
use crate::model::Coordinates;
use nalgebra::{SMatrix, SVector};
use num_dual::DualSVec;

/// (p, ṗ) at (t, q, v), for any scalar: p = ∂L/∂q̇ and ṗ = [`momentum_rate`], plus, when
/// `constrained`, the generalized constraint force Jᵀλ = M q̈ − (𝓕 − b), with q̈ the mechanism's
/// (constrained) `accelerations` (`Dynamics::accelerations_at`): for a mechanism with constraints,
/// ṗ = d/dt ∂L/∂q̇ along its motion is ∂L/∂q + F_nc + Jᵀλ.
#[inline]
pub fn canonical_field<M: Evaluate<N>, S: Scalar, const N: usize>(
    mechanism: &M,
    t: S,
    q: &[S; N],
    v: &[S; N],
    constrained: bool,
) -> Result<([S; N], [S; N])> {
    let (p, mut rate) = mechanism.canonical_field_at(t, q, v);
    if constrained {
        let eom = mechanism.equations_of_motion_at(t, q, v);
        let a = mechanism.accelerations_at(t, q, v)?;
        for (i, r) in rate.iter_mut().enumerate() {
            let mut ma = S::zero();
            for (j, aj) in a.iter().enumerate() {
                ma += eom.mass_matrix[(i, j)] * *aj;
            }
            *r += ma - (eom.generalized_forces[i] - eom.inertial_terms[i]);
        }
    }
    Ok((p, rate))
}

/// [`canonical_field`] at a real point with its exact Jacobians, from two passes with gradient dual
/// numbers (seeded on q, then on v; ∂T/∂q inside ṗ nests them: exact second derivatives of T).
#[derive(Clone, Copy, Debug)]
pub struct FieldJacobians<const N: usize> {
    /// p = ∂L/∂q̇.
    pub p: SVector<f64, N>,
    /// ṗ.
    pub rate: SVector<f64, N>,
    /// ∂p/∂q.
    pub p_q: SMatrix<f64, N, N>,
    /// ∂p/∂v = M.
    pub p_v: SMatrix<f64, N, N>,
    /// ∂ṗ/∂q.
    pub rate_q: SMatrix<f64, N, N>,
    /// ∂ṗ/∂v.
    pub rate_v: SMatrix<f64, N, N>,
}

/// See [`FieldJacobians`].
pub fn field_jacobians<M: Evaluate<N>, const N: usize>(
    mechanism: &M,
    t: f64,
    q: &[f64; N],
    v: &[f64; N],
    constrained: bool,
) -> Result<FieldJacobians<N>> {
    let td = DualSVec::<f64, N>::from_re(t);
    let plain_q: [DualSVec<f64, N>; N] = std::array::from_fn(|j| DualSVec::from_re(q[j]));
    let plain_v: [DualSVec<f64, N>; N] = std::array::from_fn(|j| DualSVec::from_re(v[j]));
    let seeded_q: [DualSVec<f64, N>; N] =
        std::array::from_fn(|j| DualSVec::from_re(q[j]).derivative(j));
    let seeded_v: [DualSVec<f64, N>; N] =
        std::array::from_fn(|j| DualSVec::from_re(v[j]).derivative(j));
    let (p_by_q, rate_by_q) = canonical_field(mechanism, td, &seeded_q, &plain_v, constrained)?;
    let (p_by_v, rate_by_v) = canonical_field(mechanism, td, &plain_q, &seeded_v, constrained)?;
    Ok(FieldJacobians {
        p: SVector::from_fn(|i, _| p_by_q[i].re),
        rate: SVector::from_fn(|i, _| rate_by_q[i].re),
        p_q: jacobian_rows(&p_by_q),
        p_v: jacobian_rows(&p_by_v),
        rate_q: jacobian_rows(&rate_by_q),
        rate_v: jacobian_rows(&rate_by_v),
    })
}

/// The velocities v with ∂L/∂v(t, q, v) = p (inverse Legendre transform). T is quadratic in q̇
/// for every mechanism (T = ½ Σ μᵢ ẋᵢ² with ẋ = J q̇ + ∂x/∂t affine in q̇), so p = M(t, q) v +
/// p(t, q, 0) and v = M⁻¹(p − p(t, q, 0)) is one solve with the mass matrix (p(t, q, 0) = 0 for a
/// scleronomic mechanism): no iteration, whose stopping test on an already exact first step would
/// only decide on round-off. `guess` is where M is evaluated for a mechanism whose M depends on
/// q̇ (none does). Returns v and the solves taken (1).
pub fn velocities_from_momenta<M: Evaluate<N>, const N: usize>(
    mechanism: &M,
    t: f64,
    q: &[f64; N],
    p: &[f64; N],
    guess: &[f64; N],
    stats: &mut Stats,
) -> Result<([f64; N], usize)> {
    velocities_and_mass_from_momenta(mechanism, t, q, p, guess, stats).map(|(v, n, _)| (v, n))
}

/// [`velocities_from_momenta`], with the mass matrix M(q) it solved with when the mechanism is
/// scleronomic (`None` otherwise): the implicit methods' next step starts at this q, and its
/// Newton matrix takes M there (see `implicit`).
#[allow(clippy::type_complexity)]
pub(crate) fn velocities_and_mass_from_momenta<M: Evaluate<N>, const N: usize>(
    mechanism: &M,
    t: f64,
    q: &[f64; N],
    p: &[f64; N],
    guess: &[f64; N],
    stats: &mut Stats,
) -> Result<([f64; N], usize, Option<SMatrix<f64, N, N>>)> {
    stats.evaluations += 1;
    let mass = mechanism.equations_of_motion_at(t, q, guess).mass_matrix;
    let mut rhs = SVector::<f64, N>::from(*p);
    if !M::SCLERONOMIC {
        // The momenta at rest: the moving frame's part of p (p(t, q, 0) = Jᵀ diag(μ) ∂x/∂t).
        rhs -= SVector::from(mechanism.momenta_at(t, q, &[0.0; N]));
    }
    match crate::linalg::solve_spd(&mass, &rhs) {
        Ok(v) if v.iter().all(|x| x.is_finite()) => {
            Ok((v.into(), 1, M::SCLERONOMIC.then_some(mass)))
        }
        Ok(_) => Err(Error::NonFiniteDynamics {
            t,
            configuration: describe_configuration(&M::Coords::NAMES, q),
        }),
        Err(e) => Err(crate::dynamics::mass_matrix_failure::<M::Coords, f64, N>(
            &mass, e, t, q,
        )),
    }
}
