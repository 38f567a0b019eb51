//! Step-size control of the embedded pairs: the starting step, the PI controller and its step
//! loop (the explicit pairs), and the scaled error component.

use super::dopri5::settings::Dopri5;
use super::Stats;
use crate::error::{Error, Result};

/// The starting step of an embedded pair of order `order` on the accelerations `acc` (HNW I
/// §II.4, "Starting step size"; Hairer's HINIT), with q̇ = `rates` at the start: one extra
/// evaluation of v̇.
pub(crate) fn initial_step_on<const N: usize>(
    acc: impl FnOnce(f64, &[f64; N], &[f64; N]) -> Result<[f64; N]>,
    st: &Dopri5,
    (t, q, v, a): (f64, &[f64; N], &[f64; N], &[f64; N]),
    rates: &[f64; N],
    order: i32,
    stats: &mut Stats,
) -> f64 {
    let (mut dnf, mut dny) = (0.0, 0.0);
    for i in 0..N {
        let sq = st.atol + st.rtol * q[i].abs();
        let sv = st.atol + st.rtol * v[i].abs();
        dnf += (rates[i] / sq).powi(2) + (a[i] / sv).powi(2);
        dny += (q[i] / sq).powi(2) + (v[i] / sv).powi(2);
    }
    let mut h = if dnf <= 1e-10 || dny <= 1e-10 {
        1e-6
    } else {
        (dny / dnf).sqrt() * 0.01
    };
    h = h.min(st.h_max);
    let q1: [f64; N] = std::array::from_fn(|i| q[i] + h * rates[i]);
    let v1: [f64; N] = std::array::from_fn(|i| v[i] + h * a[i]);
    stats.evaluations += 1;
    let Ok(a1) = acc(t + h, &q1, &v1) else {
        return h;
    };
    let mut der2 = 0.0;
    for i in 0..N {
        let sq = st.atol + st.rtol * q[i].abs();
        let sv = st.atol + st.rtol * v[i].abs();
        der2 += ((v1[i] - v[i]) / sq).powi(2) + ((a1[i] - a[i]) / sv).powi(2);
    }
    let der2 = der2.sqrt() / h;
    let der12 = der2.max(dnf.sqrt());
    let h1 = if der12 <= 1e-15 {
        (h * 1e-3).max(1e-6)
    } else {
        (0.01 / der12).powf(1.0 / order as f64)
    };
    let h = (100.0 * h).min(h1).min(st.h_max);
    if h.is_finite() && h > 0.0 {
        h
    } else {
        1e-6
    }
}

/// The step size and the previous error of an explicit embedded pair's controller: the memory
/// ([`EmbeddedPair::Memory`](crate::integrate::EmbeddedPair::Memory)) of [`Dopri5`] and
/// [`Dop853`](crate::integrate::Dop853) from one step to the next.
#[derive(Clone, Copy, Debug)]
pub struct Controller {
    pub(crate) h: f64,
    pub(crate) fac_old: f64,
}

/// The step loop and PI step-size controller shared by the embedded pairs (Dopri5, Dop853):
/// attempts steps of the controller's size (the last one shortened to land on `t_limit`, and
/// steps within 1 % of it stretched to it), rejecting and shrinking until `attempt` reports an
/// error norm ≤ 1, and returns the accepted trial, its h and its end time. The controller is
/// h_new = h·min(1/fac_min, max(1/fac_max, safety⁻¹·err^(p − β·w)·err_old^(−β)))⁻¹ with
/// (p, w) = `exponents` = (1/5, 0.75) for Dopri5 and (1/8, 0.2) for Dop853 (HNW I §II.4;
/// Hairer & Wanner, *Solving ODEs II*, §IV.2; the forms of Hairer's DOPRI5 and DOP853); after a
/// rejection the step does not grow. A failing attempt (singular mass matrix, non-finite
/// dynamics) counts as a rejection with the step cut by `fac_min`; when the step can no longer
/// shrink (0.1·h below round-off of t) the last failure is returned
/// ([`Error::StepSizeUnderflow`] if steps were rejected only for accuracy).
// `!(a > b)` is deliberate: it also refuses NaN.
#[allow(clippy::too_many_arguments, clippy::neg_cmp_op_on_partial_ord)]
#[inline(always)]
pub(crate) fn adaptive_step<T>(
    method: &'static str,
    st: &Dopri5,
    (exponent, weight): (f64, f64),
    t: f64,
    t_limit: f64,
    control: &mut Controller,
    stats: &mut Stats,
    mut attempt: impl FnMut(f64, &mut Stats) -> Result<(T, f64)>,
) -> Result<(T, f64, f64)> {
    check_limit(t, t_limit)?;
    let expo1 = exponent - st.beta * weight;
    let mut last_rejected = false;
    let mut last_error: Option<Error> = None;
    loop {
        let (h, last) = next_attempt(method, (t, t_limit), control.h, st.h_max, &mut last_error)?;
        match attempt(h, stats) {
            Ok((trial, err)) => {
                // err^(1/8) (Dop853's classical controller) as three square roots, a few
                // instructions where `powf` takes about a hundred; they agree to an ulp or two, a
                // relative change of the next step far below anything that could flip a decision.
                let fac11 = if expo1 == 0.125 {
                    err.sqrt().sqrt().sqrt()
                } else {
                    err.powf(expo1)
                };
                if err <= 1.0 {
                    // err_old^β, exactly 1 for the classical controller (β = 0): no `powf`.
                    let pi = if st.beta == 0.0 {
                        1.0
                    } else {
                        control.fac_old.powf(st.beta)
                    };
                    let fac = (fac11 / pi / st.safety).clamp(1.0 / st.fac_max, 1.0 / st.fac_min);
                    let mut h_new = h / fac;
                    if last_rejected {
                        h_new = h_new.min(h);
                    }
                    control.fac_old = err.max(1e-4);
                    control.h = h_new;
                    stats.accepted += 1;
                    let t_new = if last { t_limit } else { t + h };
                    return Ok((trial, h, t_new));
                }
                control.h = h / (1.0 / st.fac_min).min(fac11 / st.safety);
            }
            Err(e) => {
                control.h = h * st.fac_min;
                last_error = Some(e);
            }
        }
        last_rejected = true;
        stats.rejected += 1;
    }
}

/// Refuses a step limit not after t ([`Error::InvalidEndTime`]; written so that a NaN limit is
/// refused too).
// `!(a > b)` is deliberate: it also refuses NaN.
#[allow(clippy::neg_cmp_op_on_partial_ord)]
#[inline(always)]
pub(crate) fn check_limit(t: f64, t_limit: f64) -> Result<()> {
    if !(t_limit > t) {
        return Err(Error::InvalidEndTime { t, t_end: t_limit });
    }
    Ok(())
}

/// The size of the next attempt of an adaptive step from t towards `t_limit`: the `proposed` step
/// bounded by `h_max`, and shortened to land on `t_limit` when it would end within 1 % of it or
/// past it (then `true`: the last step before the limit). When the step can no longer shrink
/// (0.1·h below round-off of t) the last failure is returned, [`Error::StepSizeUnderflow`] if
/// there was none.
#[allow(clippy::neg_cmp_op_on_partial_ord)]
#[inline(always)]
pub(crate) fn next_attempt(
    method: &'static str,
    (t, t_limit): (f64, f64),
    proposed: f64,
    h_max: f64,
    last_error: &mut Option<Error>,
) -> Result<(f64, bool)> {
    let mut h = proposed.min(h_max);
    let last = t + 1.01 * h >= t_limit;
    if last {
        h = t_limit - t;
    }
    if !(t + 0.1 * h > t) {
        return Err(last_error
            .take()
            .unwrap_or(Error::StepSizeUnderflow { method, t, h }));
    }
    Ok((h, last))
}

/// e/sc of the error norm, with 0/0 = 0 (an exact component with a zero scale, possible when
/// atol = 0) and e/0 = ∞ otherwise.
#[inline(always)]
pub(crate) fn ratio(e: f64, scale: f64) -> f64 {
    if e == 0.0 {
        0.0
    } else {
        e / scale
    }
}
