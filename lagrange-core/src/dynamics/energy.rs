//! Quantities along a motion besides q̈: Cartesian velocities, the energies T and V, the generalized
//! momenta p = ∂L/∂q̇, the canonical field (p, ṗ) and ∂L/∂t.

#[cfg(doc)]
use super::MotionPass;
use super::{cartesian_with_jacobian, equations_of_motion_from_pass, gradient, motion_pass};
use crate::geometry::Scalar;
use crate::model::Model;
use nalgebra::SVector;
use num_dual::Dual;

/// ẋ = J q̇ + ∂x/∂t: the Cartesian coordinates and their velocities, by one forward-mode pass.
pub fn cartesian_velocities<M: Model<N, K>, S: Scalar, const N: usize, const K: usize>(
    model: &M,
    t: S,
    q: &[S; N],
    v: &[S; N],
) -> ([S; K], [S; K]) {
    let qd: [Dual<S>; N] = std::array::from_fn(|j| Dual::new(q[j], v[j]));
    let td = if M::RHEONOMIC {
        Dual::new(t, S::one())
    } else {
        Dual::from_re(t)
    };
    let x = model.cartesian(td, &qd);
    (
        std::array::from_fn(|i| x[i].re),
        std::array::from_fn(|i| x[i].eps),
    )
}

/// T = ½ Σ μᵢ ẋᵢ².
pub fn kinetic_energy<M: Model<N, K>, S: Scalar, const N: usize, const K: usize>(
    model: &M,
    t: S,
    q: &[S; N],
    v: &[S; N],
) -> S {
    let masses = model.masses();
    let (_, x_dot) = cartesian_velocities(model, t, q, v);
    let mut twice_t = S::zero();
    for i in 0..M::INERTIAL {
        twice_t += x_dot[i] * x_dot[i] * masses[i];
    }
    twice_t * 0.5
}

/// V(q, t).
pub fn potential_energy<M: Model<N, K>, S: Scalar, const N: usize, const K: usize>(
    model: &M,
    t: S,
    q: &[S; N],
) -> S {
    if !M::HAS_POTENTIAL && !M::HAS_GRAVITY {
        return S::zero();
    }
    let x = model.cartesian(t, q);
    let mut v = if M::HAS_POTENTIAL {
        model.potential(t, q, &x)
    } else {
        S::zero()
    };
    if M::HAS_GRAVITY {
        let weights = model.weights();
        for i in 0..K {
            v -= x[i] * weights[i];
        }
    }
    v
}

/// Generalized momenta pₖ = ∂L/∂q̇ₖ = Σᵢ μᵢ ẋᵢ ∂xᵢ/∂qₖ = (Jᵀ diag(μ) ẋ)ₖ.
pub fn momenta<M: Model<N, K>, S: Scalar, const N: usize, const K: usize>(
    model: &M,
    t: S,
    q: &[S; N],
    v: &[S; N],
) -> [S; N] {
    let masses = model.masses();
    let (x1, _, _) = cartesian_with_jacobian(model, t, q);
    let (_, x_dot) = cartesian_velocities(model, t, q, v);
    let mut p = SVector::<S, N>::zeros();
    for i in 0..M::INERTIAL {
        if masses[i] != 0.0 {
            p += gradient(&x1[i]) * (x_dot[i] * masses[i]);
        }
    }
    p.into()
}

/// The canonical field of a scleronomic mechanism, (p, ṗ) = (∂T/∂q̇, ∂T/∂q + 𝓕) at (t, q, q̇), from
/// one hyper-dual pass ([`MotionPass`]): with T = ½ Σᵢ μᵢ ẋᵢ² and ẋ = J q̇,
///
/// ```text
/// p = Jᵀ diag(μ) ẋ,     ∂T/∂q = (∂ẋ/∂q)ᵀ diag(μ) ẋ,
/// ```
///
/// J, ẋ and ∂ẋ/∂q being the pass's ε₁, ε₂ and ε₁ε₂ parts, and 𝓕 (which holds −∇V and the applied
/// forces) that of the equations of motion on the same pass. What the methods on (q, p) evaluate
/// at every Newton iteration (see `integrate::canonical`); the momenta and the gradient of T by
/// passes of their own would evaluate x several times over.
#[doc(hidden)]
#[inline]
pub fn canonical_field<M: Model<N, K>, S: Scalar, const N: usize, const K: usize>(
    model: &M,
    t: S,
    q: &[S; N],
    v: &[S; N],
) -> ([S; N], [S; N]) {
    debug_assert!(!M::RHEONOMIC, "one pass carries no ∂x/∂t");
    let pass = motion_pass(model, t, q, v);
    let forces = equations_of_motion_from_pass(model, &pass, t, q, v).generalized_forces;
    let masses = model.masses();
    let mut p = SVector::<S, N>::zeros();
    let mut kinetic_gradient = SVector::<S, N>::zeros();
    for (x, &mass) in pass.x.iter().zip(&masses).take(M::INERTIAL) {
        if mass == 0.0 {
            continue;
        }
        let weighted_velocity = x.eps2.0.map_or(S::zero(), |e| e[0]) * mass;
        if let Some(row) = &x.eps1.0 {
            p += row * weighted_velocity;
        }
        if let Some(mixed) = &x.eps1eps2.0 {
            kinetic_gradient += mixed * weighted_velocity;
        }
    }
    (p.into(), (kinetic_gradient + forces).into())
}

/// ∂L/∂t = ∂T/∂t − ∂V/∂t at fixed (q, q̇): the rate of change of the energy function
/// h = Σ pₖq̇ₖ − L along a motion without non-conservative forces (dh/dt = −∂L/∂t).
pub fn lagrangian_time_derivative<M: Model<N, K>, const N: usize, const K: usize>(
    model: &M,
    t: f64,
    q: &[f64; N],
    v: &[f64; N],
) -> f64 {
    if !M::RHEONOMIC {
        return 0.0;
    }
    let td = Dual::new(t, 1.0);
    let qd: [Dual<f64>; N] = std::array::from_fn(|j| Dual::from_re(q[j]));
    let vd: [Dual<f64>; N] = std::array::from_fn(|j| Dual::from_re(v[j]));
    let lagrangian = kinetic_energy(model, td, &qd, &vd) - potential_energy(model, td, &qd);
    lagrangian.eps
}
