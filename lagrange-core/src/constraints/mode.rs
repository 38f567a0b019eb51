//! The constraint mode read from a state by complementarity: [`infer_mode`] and the helpers that
//! decide which unilateral and friction rows are enforced.

use super::rows::{always_active, constraint_rows};
use super::{
    accelerations_in_mode, ConstraintKind, Constraints, Mode, RowMode, CONSISTENCY_TOLERANCE,
};
use crate::error::Result;

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
    let mut mode = Mode::all_active::<M, N, K>();
    if always_active::<M, N, K, C>() {
        return Ok(mode);
    }
    let cr = constraint_rows(model, t, q, v);
    let tol = CONSISTENCY_TOLERANCE;
    for i in 0..C {
        if let ConstraintKind::Unilateral = M::KINDS[i] {
            if !(cr.value[i] <= tol && cr.rate[i] <= tol) {
                mode.rows[i] = RowMode::Inactive;
            }
        }
    }
    friction_rows_follow(&M::KINDS, &mut mode, &cr.value);
    for _ in 0..=2 * C {
        if always_active::<M, N, K, C>() {
            break;
        }
        let sol = accelerations_in_mode(model, t, q, v, &mode)?;
        match worst_violation(model, &mode, &sol.multipliers) {
            None => break,
            Some((i, new)) => {
                mode.rows[i] = new;
                if new == RowMode::Inactive {
                    // A separated contact carries no friction.
                    for j in 0..C {
                        if M::KINDS[j] == (ConstraintKind::Friction { normal: i }) {
                            mode.rows[j] = RowMode::Inactive;
                        }
                    }
                }
            }
        }
    }
    Ok(mode)
}

/// Friction rows follow their contact (helper with the model type in scope).
pub(super) fn friction_rows_follow<const C: usize>(
    kinds: &[ConstraintKind; C],
    mode: &mut Mode<C>,
    slip: &[f64; C],
) {
    for j in 0..C {
        if let ConstraintKind::Friction { normal } = kinds[j] {
            mode.rows[j] = if !mode.enforced(normal) {
                RowMode::Inactive
            } else if slip[j].abs() <= CONSISTENCY_TOLERANCE {
                RowMode::Stick
            } else if slip[j] > 0.0 {
                RowMode::SlipPositive
            } else {
                RowMode::SlipNegative
            };
        }
    }
}

/// The most violated complementarity condition of a solved mode, and the row mode that fixes it:
/// a contact pulling (λ < 0) separates; a stick needing more than μₛ|λₙ| slides against it.
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
            _ => continue,
        };
        if excess > 0.0 && worst.is_none_or(|w| excess > w.2) {
            worst = Some((i, fix, excess));
        }
    }
    worst.map(|(i, m, _)| (i, m))
}
