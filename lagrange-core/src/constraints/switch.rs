//! The switch of a contact mode at a located event: the impact law, release, slip stop or stick
//! break of the row whose event fired, then complementarity of the whole mode and the projection
//! onto it (see the table at [`ContactModel`](super::ContactModel) and the [module docs](super)).

use super::cone;
use super::mode::{apply_fix, friction_rows_follow, worst_violation};
use super::projection::project_in_rates;
use super::rows::constraint_rows_in_rates;
use super::rows::rows_and_scales;
use super::solve::accelerations_in_mode_in_rates;
use super::CONSISTENCY_TOLERANCE;
use super::{ConstraintKind, Constraints, Mode, RowMode};
use crate::error::{describe_configuration, Error, Result};
use crate::model::Coordinates;

/// Switches row `row` after its event at (t, q, v): impact (Newton's restitution law with
/// coefficient `restitution`), release, slip stop or stick break, then restores complementarity
/// of the whole mode and projects onto it.
pub(crate) fn transition<
    M: Constraints<N, K, C>,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    model: &M,
    restitution: f64,
    t: f64,
    (q, v): (&mut [f64; N], &mut [f64; N]),
    mode: &mut Mode<C>,
    row: usize,
) -> Result<()> {
    let follow = |mode: &mut Mode<C>, slip: &[f64; C], stick: &[f64; C]| {
        friction_rows_follow(&M::KINDS, mode, slip, Some(row), stick);
    };
    match (M::KINDS[row], mode.rows[row]) {
        (ConstraintKind::Unilateral, RowMode::Inactive) => {
            impact(model, restitution, t, q, v, mode, row)?;
            let (after, scales) = rows_and_scales(model, t, q, v);
            follow(mode, &after.value, &scales.stick());
        }
        (ConstraintKind::Unilateral, RowMode::Active) => {
            mode.rows[row] = RowMode::Inactive;
            follow(mode, &[0.0; C], &[0.0; C]);
        }
        (ConstraintKind::Friction { .. }, RowMode::SlipPositive | RowMode::SlipNegative) => {
            // The slip velocity reached zero: make it exactly zero, then test static friction.
            mode.rows[row] = RowMode::Stick;
            project_in_rates(model, t, q, v, mode)?;
        }
        (ConstraintKind::Friction { .. }, RowMode::Stick) => {
            let lambda = accelerations_in_mode_in_rates(model, t, q, v, mode)?.multipliers;
            mode.rows[row] = if lambda[row] > 0.0 {
                RowMode::SlipNegative
            } else {
                RowMode::SlipPositive
            };
        }
        (ConstraintKind::FrictionCone { partner, .. }, RowMode::Sliding) => {
            // The slip stopped: both tangent slips set to zero, then the stick test below.
            for i in [row, partner] {
                mode.rows[i] = RowMode::Stick;
                mode.reference[i] = 0.0;
                mode.stopping[i] = false;
            }
            project_in_rates(model, t, q, v, mode)?;
        }
        (ConstraintKind::FrictionCone { partner, .. }, RowMode::Stick) => {
            let lambda = accelerations_in_mode_in_rates(model, t, q, v, mode)?.multipliers;
            cone::break_stick(mode, row, partner, &lambda);
        }
        _ => {}
    }
    restore_complementarity(model, t, q, v, mode)
}

/// A separated contact `row` closes at (t, q, v): a frictionless impulse along it (and the rows
/// already enforced, which stay satisfied) takes its rate from ċ⁻ to −e ċ⁻ (Newton's law); the
/// contact stays closed unless it bounces off (e ċ⁻ beyond [`CONSISTENCY_TOLERANCE`] of the row's
/// velocity size).
fn impact<M: Constraints<N, K, C>, const N: usize, const K: usize, const C: usize>(
    model: &M,
    restitution: f64,
    t: f64,
    q: &[f64; N],
    v: &mut [f64; N],
    mode: &mut Mode<C>,
    row: usize,
) -> Result<()> {
    let (cr, scales) = rows_and_scales(model, t, q, v);
    let approach = cr.rate[row];
    mode.rows[row] = RowMode::Active;
    if approach < 0.0 {
        // Lower the contact's rate from ċ⁻ to −e ċ⁻, the others' to 0.
        let decrease: [f64; C] = std::array::from_fn(|i| {
            if i == row {
                cr.rate[i] + restitution * approach
            } else {
                cr.rate[i]
            }
        });
        let mut velocity_only = *mode;
        for i in 0..C {
            if !(mode.enforced(i) && M::KINDS[i].friction_normal().is_none()) {
                velocity_only.rows[i] = RowMode::Inactive;
            }
        }
        impulse(model, t, q, v, &velocity_only, &decrease)?;
        if restitution * -approach > CONSISTENCY_TOLERANCE * scales.velocity[row] {
            mode.rows[row] = RowMode::Inactive; // bounces off
        }
    }
    Ok(())
}

/// Complementarity of a new mode (a closed contact that pulls opens, a stick that needs more than
/// μₛ|λₙ| slides), most violated first, then the projection onto it.
fn restore_complementarity<
    M: Constraints<N, K, C>,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    model: &M,
    t: f64,
    q: &mut [f64; N],
    v: &mut [f64; N],
    mode: &mut Mode<C>,
) -> Result<()> {
    for _ in 0..=2 * C {
        let lambda = accelerations_in_mode_in_rates(model, t, q, v, mode)?.multipliers;
        match worst_violation(model, mode, &lambda) {
            None => break,
            Some((i, new)) => apply_fix::<M, N, K, C>(mode, i, new, &lambda),
        }
    }
    project_in_rates(model, t, q, v, mode)
}

/// Velocity jump v ← v − M⁻¹Rᵀ(RM⁻¹Rᵀ)⁻¹d over the rows enforced in `mode`: an impulse along those
/// rows that lowers each row's rate r·v + r_t by exactly dᵢ.
fn impulse<M: Constraints<N, K, C>, const N: usize, const K: usize, const C: usize>(
    model: &M,
    t: f64,
    q: &[f64; N],
    v: &mut [f64; N],
    mode: &Mode<C>,
    decrease: &[f64; C],
) -> Result<()> {
    let names = &<M::Coords as Coordinates<N>>::NAMES;
    let cr = constraint_rows_in_rates(model, t, q, v);
    let mass = crate::dynamics::mass_matrix(model, t, q);
    let l = crate::linalg::cholesky(&mass).map_err(|e| Error::SingularMassMatrix {
        t,
        configuration: describe_configuration(names, q),
        coordinate: names[e.index],
        pivot: e.pivot,
    })?;
    let enforced: [bool; C] = std::array::from_fn(|i| mode.enforced(i));
    let y: [nalgebra::SVector<f64, N>; C] = std::array::from_fn(|i| {
        if enforced[i] {
            crate::linalg::cholesky_substitute(&l, &cr.rows[i])
        } else {
            nalgebra::SVector::zeros()
        }
    });
    let mut s = nalgebra::SMatrix::<f64, C, C>::identity();
    let mut rhs = nalgebra::SVector::<f64, C>::zeros();
    for i in (0..C).filter(|&i| enforced[i]) {
        for k in (0..C).filter(|&k| enforced[k]) {
            s[(i, k)] = cr.rows[i].dot(&y[k]);
        }
        rhs[i] = decrease[i];
    }
    let mu = crate::linalg::cholesky_solve(&s, &rhs).map_err(|e| Error::SingularConstraints {
        t,
        configuration: describe_configuration(names, q),
        constraints: format!("`{}`", M::NAMES[e.index.min(C - 1)]),
        pivot: e.pivot,
    })?;
    for k in (0..C).filter(|&k| enforced[k]) {
        for j in 0..N {
            v[j] -= y[k][j] * mu[k];
        }
    }
    Ok(())
}
