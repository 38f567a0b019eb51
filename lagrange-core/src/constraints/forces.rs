//! The forces each constraint applies at a state: [`ConstraintForces`] and [`constraint_forces`].

use super::consistency::check_consistent_in_rates;
use super::kinds::{has_position, has_velocity};
use super::mode::infer_mode_in_rates;
use super::quasi;
use super::rows::{constraint_rows_in_rates, gradient};
use super::solve::accelerations_in_mode_in_rates;
#[cfg(doc)]
use super::{infer_mode, ConstrainedAccelerations};
use super::{Constraints, Mode, CONSISTENCY_TOLERANCE};
use crate::dynamics;
use crate::error::{Error, Result};
use crate::model::{Coordinates, State};
use num_dual::DualSVec;

/// What each constraint does at a state: multipliers, generalized and Cartesian forces.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ConstraintForces<const N: usize, const K: usize, const C: usize> {
    /// The mode the forces were computed in ([`infer_mode`]).
    pub mode: Mode<C>,
    /// q̈.
    pub accelerations: [f64; N],
    /// λᵢ (see [`ConstrainedAccelerations::multipliers`]).
    pub multipliers: [f64; C],
    /// λᵢ·rᵢ: the generalized force of each row.
    pub generalized: [[f64; N]; C],
    /// λᵢ·∂fᵢ/∂xₖ (position rows) or λᵢ·∂fᵢ/∂ẋₖ (velocity and friction rows): the force row i applies
    /// to Cartesian coordinate k, with x treated as independent of q. This is the physical force on a
    /// body when the constraint is written on the bodies' Cartesian coordinates (as the declaration
    /// syntax encourages); parts written directly on q appear only in `generalized`.
    pub cartesian: [[f64; K]; C],
}

/// Multipliers, generalized and Cartesian forces of every constraint at a state (mode by
/// [`infer_mode`]). With quasi-velocities ([`Constraints::QUASI_VELOCITY_JOINTS`]) the
/// accelerations are v̇ and the generalized forces are dual to v (Gᵀ rᵢ λᵢ).
pub fn constraint_forces<
    M: Constraints<N, K, C>,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    model: &M,
    state: &State<M::Coords>,
) -> Result<ConstraintForces<N, K, C>> {
    model.validate()?;
    let (q, v) = (state.q.to_array(), state.v.to_array());
    crate::model::check_state(&<M::Coords as Coordinates<N>>::NAMES, state.t, &q, &v)?;
    let t = state.t;
    // Refuse what the integrators refuse about the declaration (friction coefficients, velocity
    // rows not linear in q̇), but compute forces at states off the constraints too.
    let rates = quasi::rates::<M, f64, N, K, C>(&q, &v);
    match check_consistent_in_rates(model, t, &q, &rates, CONSISTENCY_TOLERANCE) {
        Ok(()) | Err(Error::ConstraintViolation { .. }) => {}
        Err(e) => return Err(e),
    }
    let mode = infer_mode_in_rates(model, t, &q, &rates)?;
    let mut forces = forces_in_mode(model, t, &q, &rates, &mode)?;
    if quasi::quasi::<M, N, K, C>() {
        forces.accelerations =
            quasi::accelerations::<M, f64, N, K, C>(&q, &rates, &forces.accelerations);
        for row in &mut forces.generalized {
            *row = quasi::forces::<M, f64, N, K, C>(&q, row);
        }
    }
    Ok(forces)
}

/// [`constraint_forces`] in a given mode, at (q, q̇), the coordinates' rates.
pub(crate) fn forces_in_mode<
    M: Constraints<N, K, C>,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    model: &M,
    t: f64,
    q: &[f64; N],
    v: &[f64; N],
    mode: &Mode<C>,
) -> Result<ConstraintForces<N, K, C>> {
    let sol = accelerations_in_mode_in_rates(model, t, q, v, mode)?;
    let cr = constraint_rows_in_rates(model, t, q, v);
    let generalized: [[f64; N]; C] =
        std::array::from_fn(|i| std::array::from_fn(|j| sol.multipliers[i] * cr.rows[i][j]));
    // ∂f/∂x (position rows) and ∂f/∂ẋ (velocity rows), x and ẋ seeded as independent gradient duals.
    let (x, x_dot) = dynamics::cartesian_velocities(model, t, q, v);
    let mut cartesian = [[0.0; K]; C];
    let qs: [DualSVec<f64, K>; N] = std::array::from_fn(|j| DualSVec::from_re(q[j]));
    let ts = DualSVec::<f64, K>::from_re(t);
    if has_position::<M, N, K, C>() {
        let xs: [DualSVec<f64, K>; K] =
            std::array::from_fn(|i| DualSVec::from_re(x[i]).derivative(i));
        let g = model.position_constraints(ts, &qs, &xs);
        for i in 0..C {
            if M::KINDS[i].is_position() {
                let d = gradient(&g[i]);
                cartesian[i] = std::array::from_fn(|k| sol.multipliers[i] * d[k]);
            }
        }
    }
    if has_velocity::<M, N, K, C>() {
        let vk: [DualSVec<f64, K>; N] = std::array::from_fn(|j| DualSVec::from_re(v[j]));
        let xs: [DualSVec<f64, K>; K] = std::array::from_fn(|i| DualSVec::from_re(x[i]));
        let xds: [DualSVec<f64, K>; K] =
            std::array::from_fn(|i| DualSVec::from_re(x_dot[i]).derivative(i));
        let h = model.velocity_constraints(ts, &qs, &vk, &xs, &xds);
        for i in 0..C {
            if M::KINDS[i].is_velocity() {
                let d = gradient(&h[i]);
                cartesian[i] = std::array::from_fn(|k| sol.multipliers[i] * d[k]);
            }
        }
    }
    // A row without force (not enforced, or λ = 0 exactly) applies none, even where its gradient is
    // not finite (a separated contact at an overflowing or degenerate configuration): 0, not 0·NaN.
    let mut generalized = generalized;
    for i in 0..C {
        if sol.multipliers[i] == 0.0 {
            generalized[i] = [0.0; N];
            cartesian[i] = [0.0; K];
        }
    }
    if !generalized
        .iter()
        .flatten()
        .chain(cartesian.iter().flatten())
        .all(|x| x.is_finite())
    {
        return Err(dynamics::non_finite_dynamics::<M::Coords, f64, N>(t, q));
    }
    Ok(ConstraintForces {
        mode: *mode,
        accelerations: sol.accelerations,
        multipliers: sol.multipliers,
        generalized,
        cartesian,
    })
}
