//! The constraint mode read from a state by complementarity: [`infer_mode`] and the helpers that
//! decide which unilateral and friction rows are enforced.

use super::cone;
use super::kinds::always_active;
use super::quasi;
use super::rows::{real, rows_and_scales};
use super::solve::accelerations_in_mode_in_rates;
use super::{ConstraintKind, Constraints, Mode, RowMode, CONSISTENCY_TOLERANCE};
use crate::error::Result;
use crate::geometry::Scalar;

/// The mode at a state, by complementarity: a unilateral row with c ≤ tol and ċ ≤ tol is a
/// candidate contact, kept if its λ ≥ 0; a friction row with |s| ≤ tol (tol =
/// [`CONSISTENCY_TOLERANCE`]) on an enforced contact is a candidate stick, kept if
/// |λₜ| ≤ μₛ|λₙ|, otherwise it slides against the force static friction would have had to supply.
/// Candidates are dropped one at a time, the most violated first, until the mode is consistent.
pub fn infer_mode<M: Constraints<N, K, C>, const N: usize, const K: usize, const C: usize>(
    model: &M,
    t: f64,
    q: &[f64; N],
    v: &[f64; N],
) -> Result<Mode<C>> {
    infer_mode_in_rates(model, t, q, &quasi::rates::<M, f64, N, K, C>(q, v))
}

/// [`infer_mode`] at (q, q̇), the coordinates' rates.
pub(crate) fn infer_mode_in_rates<
    M: Constraints<N, K, C>,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    model: &M,
    t: f64,
    q: &[f64; N],
    v: &[f64; N],
) -> Result<Mode<C>> {
    let mut mode = Mode::all_active::<M, N, K>();
    if always_active::<M, N, K, C>() {
        return Ok(mode);
    }
    let (cr, scales) = rows_and_scales(model, t, q, v);
    let tol = CONSISTENCY_TOLERANCE;
    for i in 0..C {
        if let ConstraintKind::Unilateral = M::KINDS[i] {
            if !(cr.value[i] <= tol * scales.position[i] && cr.rate[i] <= tol * scales.velocity[i])
            {
                mode.rows[i] = RowMode::Inactive;
            }
        }
    }
    friction_rows_follow(&M::KINDS, &mut mode, &cr.value, None, &scales.stick());
    for _ in 0..=2 * C {
        if always_active::<M, N, K, C>() {
            break;
        }
        let sol = accelerations_in_mode_in_rates(model, t, q, v, &mode)?;
        match worst_violation(model, &mode, &sol.multipliers) {
            None => break,
            Some((i, new)) => apply_fix::<M, N, K, C>(&mut mode, i, new, &sol.multipliers),
        }
    }
    Ok(mode)
}

/// Switches row `i` to `new` as [`worst_violation`] asks: a separated contact carries no friction;
/// a friction cone's stick breaks for both its rows, sliding against the stick force `lambda`.
pub(crate) fn apply_fix<M: Constraints<N, K, C>, const N: usize, const K: usize, const C: usize>(
    mode: &mut Mode<C>,
    i: usize,
    new: RowMode,
    lambda: &[f64; C],
) {
    if let (Some((k, _)), RowMode::Sliding) = (cone::first_of_pair(M::KINDS[i], i), new) {
        cone::break_stick(mode, i, k, lambda);
        return;
    }
    mode.rows[i] = new;
    if new == RowMode::Inactive {
        for j in 0..C {
            if M::KINDS[j].friction_normal() == Some(i) {
                mode.rows[j] = RowMode::Inactive;
                mode.reference[j] = 0.0;
                mode.stopping[j] = false;
                mode.stopping[j] = false;
            }
        }
    }
}

/// Friction rows follow their contact (helper with the model type in scope): rows of a separated
/// contact are inactive; the others stick where the slip is within `stick` of zero (per row,
/// [`CONSISTENCY_TOLERANCE`] of its size: [`RowScales::stick`](super::consistency::RowScales::stick))
/// and slide with it elsewhere. `only_normal` restricts the update to the friction of one contact.
pub(super) fn friction_rows_follow<const C: usize>(
    kinds: &[ConstraintKind; C],
    mode: &mut Mode<C>,
    slip: &[f64; C],
    only_normal: Option<usize>,
    stick: &[f64; C],
) {
    for j in 0..C {
        let Some(normal) = kinds[j].friction_normal() else {
            continue;
        };
        if only_normal.is_some_and(|n| n != normal) && mode.enforced(normal) {
            continue;
        }
        if !mode.enforced(normal) {
            mode.rows[j] = RowMode::Inactive;
            mode.reference[j] = 0.0;
            mode.stopping[j] = false;
            continue;
        }
        match kinds[j] {
            ConstraintKind::FrictionCone { partner, .. } => {
                if j < partner {
                    cone::follow_slip(mode, j, partner, slip, stick[j].max(stick[partner]));
                }
            }
            _ => {
                mode.rows[j] = if slip[j].abs() <= stick[j] {
                    RowMode::Stick
                } else if slip[j] > 0.0 {
                    RowMode::SlipPositive
                } else {
                    RowMode::SlipNegative
                };
            }
        }
    }
}

/// The most violated complementarity condition of a solved mode, and the row mode that fixes it:
/// a contact pulling (λ < 0) separates; a stick needing more than μₛ|λₙ| slides against it (for a
/// friction cone, the pair's first row reports |(λⱼ, λₖ)| > μₛ|λₙ| and the fix
/// [`RowMode::Sliding`], applied to both rows by [`apply_fix`]).
pub(crate) fn worst_violation<
    M: Constraints<N, K, C>,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    model: &M,
    mode: &Mode<C>,
    lambda: &[f64; C],
) -> Option<(usize, RowMode)> {
    let mut worst: Option<(usize, RowMode, f64)> = None;
    for i in 0..C {
        let (excess, fix) = match (M::KINDS[i], mode.rows[i]) {
            (ConstraintKind::Unilateral, RowMode::Active) => (-lambda[i], RowMode::Inactive),
            (ConstraintKind::Friction { normal }, RowMode::Stick) => {
                let bound = model.friction_coefficients(i).stiction * lambda[normal].abs();
                let fix = if lambda[i] > 0.0 {
                    RowMode::SlipNegative
                } else {
                    RowMode::SlipPositive
                };
                (lambda[i].abs() - bound, fix)
            }
            (ConstraintKind::FrictionCone { normal, partner }, RowMode::Stick) if i < partner => (
                cone::stick_excess(model, i, partner, normal, lambda),
                RowMode::Sliding,
            ),
            _ => continue,
        };
        if excess > 0.0 && worst.is_none_or(|w| excess > w.2) {
            worst = Some((i, fix, excess));
        }
    }
    worst.map(|(i, m, _)| (i, m))
}

/// q̈ at (t, q, q̇) with the mode read from the state ([`infer_mode`]); with only holonomic and
/// velocity rows, every row is enforced and no inference runs. What a constrained mechanism's
/// `Dynamics::accelerations_at` forwards to.
pub fn accelerations<
    M: Constraints<N, K, C>,
    S: Scalar,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    model: &M,
    t: S,
    q: &[S; N],
    v: &[S; N],
) -> Result<[S; N]> {
    let rates = quasi::rates::<M, S, N, K, C>(q, v);
    let mode = if always_active::<M, N, K, C>() {
        Mode::all_active::<M, N, K>()
    } else {
        infer_mode_in_rates(model, t.re(), &real(q), &real(&rates))?
    };
    let qdd = accelerations_in_mode_in_rates(model, t, q, &rates, &mode)?.accelerations;
    Ok(quasi::accelerations::<M, S, N, K, C>(q, &rates, &qdd))
}
