//! The two rows of a friction cone (Coulomb friction in a tangent plane): the sliding direction, the
//! stick test and the mode switches of the pair. See the [module docs](super) for the law.

use super::{ConstraintKind, Constraints, Mode, RowMode};
use crate::geometry::Scalar;

/// The unit vector along (a, b), `None` for a zero or non-finite vector.
pub(super) fn unit(a: f64, b: f64) -> Option<(f64, f64)> {
    let norm = a.hypot(b);
    (norm > 0.0 && norm.is_finite()).then(|| (a / norm, b / norm))
}

/// The component along row j of the slip direction a sliding cone's force opposes, from the slip
/// velocity (sⱼ, sₖ) and the mode's reference (rⱼ, rₖ): ŝ·sign(ŝ·r) (Stewart 2000's
/// F_t = −μN v_t/|v_t|, continued smoothly past a stop within a step), or r itself where s = 0.
pub(super) fn sliding_direction<S: Scalar>(s_j: S, s_k: S, r_j: f64, r_k: f64) -> S {
    let norm = (s_j * s_j + s_k * s_k).sqrt();
    if !(norm.re() > 0.0 && norm.re().is_finite()) {
        return S::from(r_j);
    }
    let along = s_j.re() * r_j + s_k.re() * r_k;
    let sign = if along < 0.0 { -1.0 } else { 1.0 };
    s_j / norm * S::from(sign)
}

/// Sets the pair (j, k) from its slip velocity: stuck when |s| ≤ `stick` ([`CONSISTENCY_TOLERANCE`](super::CONSISTENCY_TOLERANCE)
/// of the rows' size), else sliding along ŝ (the reference).
pub(super) fn follow_slip<const C: usize>(
    mode: &mut Mode<C>,
    j: usize,
    k: usize,
    s: &[f64; C],
    stick: f64,
) {
    match unit(s[j], s[k]).filter(|_| s[j].hypot(s[k]) > stick) {
        Some((a, b)) => slide(mode, j, k, (a, b)),
        None => {
            mode.rows[j] = RowMode::Stick;
            mode.rows[k] = RowMode::Stick;
            mode.stopping[j] = false;
            mode.stopping[k] = false;
            mode.reference[j] = 0.0;
            mode.reference[k] = 0.0;
        }
    }
}

/// Both rows of the pair (j, k) sliding along `direction`.
pub(super) fn slide<const C: usize>(mode: &mut Mode<C>, j: usize, k: usize, direction: (f64, f64)) {
    mode.rows[j] = RowMode::Sliding;
    mode.rows[k] = RowMode::Sliding;
    mode.stopping[j] = false;
    mode.stopping[k] = false;
    mode.reference[j] = direction.0;
    mode.reference[k] = direction.1;
}

/// Static friction exceeded at the stuck pair (j, k) with multipliers (λⱼ, λₖ): slide opposite to the
/// force static friction would have had to supply, ŝ = −λ/|λ|.
pub(super) fn break_stick<const C: usize>(
    mode: &mut Mode<C>,
    j: usize,
    k: usize,
    lambda: &[f64; C],
) {
    let direction = unit(-lambda[j], -lambda[k]).unwrap_or((1.0, 0.0));
    slide(mode, j, k, direction);
}

/// How far the stuck pair (j, k) needs more than static friction holds: |(λⱼ, λₖ)| − μₛ|λₙ|.
pub(super) fn stick_excess<
    M: Constraints<N, K, C>,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    model: &M,
    j: usize,
    k: usize,
    normal: usize,
    lambda: &[f64; C],
) -> f64 {
    lambda[j].hypot(lambda[k]) - model.friction_coefficients(j).stiction * lambda[normal].abs()
}

/// The partner of row j when j is the first row of a friction cone pair (the row that carries the
/// pair's event and stick test), `None` otherwise.
pub(super) fn first_of_pair(kind: ConstraintKind, j: usize) -> Option<(usize, usize)> {
    match kind {
        ConstraintKind::FrictionCone { normal, partner } if j < partner => Some((partner, normal)),
        _ => None,
    }
}

/// Before a (sub)step of length `span` from (t, q, q̇): refreshes the reference of every sliding cone
/// pair to its current slip direction (kept where the slip is within [`CONSISTENCY_TOLERANCE`](super::CONSISTENCY_TOLERANCE) of
/// zero, just after sliding starts), and marks the pairs whose slip, extrapolated linearly with
/// ṡ = S q̈ + β, stops within 2·span as [`Mode::stopping`].
pub(super) fn refresh_references<
    M: Constraints<N, K, C>,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    model: &M,
    t: f64,
    q: &[f64; N],
    v: &[f64; N],
    span: f64,
    mode: &mut Mode<C>,
) -> crate::Result<()> {
    mode.stopping = [false; C];
    if !(0..C).any(|j| mode.rows[j] == RowMode::Sliding) {
        return Ok(());
    }
    let (cr, scales) = super::rows::rows_and_scales(model, t, q, v);
    let (s, stick) = (cr.value, scales.stick());
    for j in 0..C {
        if let Some((k, _)) = first_of_pair(M::KINDS[j], j) {
            if mode.rows[j] == RowMode::Sliding && s[j].hypot(s[k]) > stick[j].max(stick[k]) {
                if let Some(d) = unit(s[j], s[k]) {
                    slide(mode, j, k, d);
                }
            }
        }
    }
    let qdd = nalgebra::SVector::from(
        super::solve::accelerations_in_mode_in_rates(model, t, q, v, mode)?.accelerations,
    );
    for j in 0..C {
        if let Some((k, _)) = first_of_pair(M::KINDS[j], j) {
            if mode.rows[j] != RowMode::Sliding {
                continue;
            }
            let rate = |i: usize| cr.rows[i].dot(&qdd) + cr.bias[i];
            // s(t + τ) ≈ s + τ ṡ stops along ŝ at τ = |s|² / (−s·ṡ).
            let closing = -(s[j] * rate(j) + s[k] * rate(k));
            let speed2 = s[j] * s[j] + s[k] * s[k];
            if closing > 0.0 && speed2 <= 2.0 * span * closing {
                mode.stopping[j] = true;
                mode.stopping[k] = true;
            }
        }
    }
    Ok(())
}
