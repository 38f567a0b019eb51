//! The event function of every row in a contact mode, whose sign change is a mode change, and the
//! rows whose event fired over an interval (see the table at [`ContactModel`](super::ContactModel)).

use super::cone;
use super::solve::accelerations_in_mode_in_rates;
use super::{ConstraintKind, Constraints, Mode, RowMode, CONSISTENCY_TOLERANCE};
use crate::error::Result;

/// The event function of every row in `mode` (+∞ for rows without one).
pub(crate) fn event_values<
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
) -> Result<[f64; C]> {
    let needs_lambda = (0..C).any(|i| {
        matches!(
            (M::KINDS[i], mode.rows[i]),
            (ConstraintKind::Unilateral, RowMode::Active) | (_, RowMode::Stick)
        )
    });
    let lambda = if needs_lambda {
        accelerations_in_mode_in_rates(model, t, q, v, mode)?.multipliers
    } else {
        [0.0; C]
    };
    let x = model.cartesian(t, q);
    let c = model.position_constraints(t, q, &x);
    let needs_slip = (0..C).any(|i| {
        matches!(
            mode.rows[i],
            RowMode::SlipPositive | RowMode::SlipNegative | RowMode::Sliding
        )
    });
    let s = if needs_slip {
        let (x, x_dot) = crate::dynamics::cartesian_velocities(model, t, q, v);
        model.velocity_constraints(t, q, v, &x, &x_dot)
    } else {
        [0.0; C]
    };
    Ok(std::array::from_fn(|i| match (M::KINDS[i], mode.rows[i]) {
        (ConstraintKind::Unilateral, RowMode::Inactive) => c[i],
        (ConstraintKind::Unilateral, RowMode::Active) => lambda[i],
        (ConstraintKind::Friction { .. }, RowMode::SlipPositive) => s[i],
        (ConstraintKind::Friction { .. }, RowMode::SlipNegative) => -s[i],
        (ConstraintKind::Friction { normal }, RowMode::Stick) => {
            model.friction_coefficients(i).stiction * lambda[normal].abs() - lambda[i].abs()
        }
        // A cone's pair has one event, on its first row: the slip along the step's reference
        // direction, or the margin of static friction.
        (ConstraintKind::FrictionCone { partner, .. }, RowMode::Sliding) if i < partner => {
            s[i] * mode.reference[i] + s[partner] * mode.reference[partner]
        }
        (ConstraintKind::FrictionCone { normal, partner }, RowMode::Stick) if i < partner => {
            -cone::stick_excess(model, i, partner, normal, &lambda)
        }
        _ => f64::INFINITY,
    }))
}

/// The rows whose event fired over a (sub)step from (t, q, v) in `mode`, given the event functions
/// `phi_end` at its end: armed rows whose function is negative there, and also a contact that
/// bounced off (disarmed, separating at the start) and closes again within the same step.
pub(crate) fn triggered_rows<
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
    armed: &[bool; C],
    phi_end: &[f64; C],
) -> [bool; C] {
    let separated = |i: usize| {
        matches!(
            (M::KINDS[i], mode.rows[i]),
            (ConstraintKind::Unilateral, RowMode::Inactive)
        )
    };
    let separating: [bool; C] = if (0..C).any(|i| !armed[i] && phi_end[i] < 0.0 && separated(i)) {
        let (cr, scales) = super::rows::rows_and_scales(model, t, q, v);
        std::array::from_fn(|i| {
            separated(i) && cr.rate[i] > CONSISTENCY_TOLERANCE * scales.velocity[i]
        })
    } else {
        [false; C]
    };
    std::array::from_fn(|i| (armed[i] || separating[i]) && phi_end[i] < 0.0)
}
