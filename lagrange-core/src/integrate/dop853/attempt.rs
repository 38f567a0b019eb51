//! One Dormand–Prince 8(5,3) trial step: the stages, computed in place, the 8th-order solution and
//! the combined error estimate.

use super::tableau::{A, B, BHH, C, E};
use super::Dop853;
use crate::error::{Error, Result};
use crate::integrate::control::ratio;
use crate::integrate::pair::AccelerationField;
use crate::integrate::Stats;
use crate::model::{check_state, Coordinates};

/// The stages of one [`Dop853`] step, position parts kq (the stage position rates) and velocity parts
/// ka (the stage accelerations): stages 1…12 of the trial, 13 the FSAL evaluation at the new point,
/// 14…16 those of the dense output. A step computes them in place, without copying them around.
#[derive(Clone, Copy, Debug)]
pub struct Stages<const N: usize> {
    pub(crate) kq: [[f64; N]; 16],
    pub(crate) ka: [[f64; N]; 16],
}

impl<const N: usize> Stages<N> {
    /// All stages zero, to be filled by [`attempt`] and [`accept`].
    pub(crate) fn new() -> Self {
        Stages {
            kq: [[0.0; N]; 16],
            ka: [[0.0; N]; 16],
        }
    }
}

/// Evaluates stage I (0-based) of a step of size h from (t, q, v) into kq[I], ka[I]: the stage
/// point (q, v) + h Σ_{j<I} a_Ij (kqⱼ, kaⱼ), its position rates and v̇ there. The stage is a constant,
/// so the sum is unrolled over its nonzero aᵢⱼ alone.
#[inline(always)]
pub(super) fn evaluate_stage<const I: usize, const N: usize>(
    (t, q, v): (f64, &[f64; N], &[f64; N]),
    h: f64,
    k: &mut Stages<N>,
    stats: &mut Stats,
    field: &impl AccelerationField<N>,
) -> Result<()> {
    let (mut qi, mut vi) = (*q, *v);
    for j in 0..I {
        let a = A[I][j];
        if a != 0.0 {
            for n in 0..N {
                qi[n] += h * a * k.kq[j][n];
                vi[n] += h * a * k.ka[j][n];
            }
        }
    }
    stats.evaluations += 1;
    k.ka[I] = field.accelerations(t + C[I] * h, &qi, &vi)?;
    k.kq[I] = field.position_rates(&qi, &vi);
    Ok(())
}

/// Σⱼ wⱼ kⱼ over stages 1…12 (0-based 0…11), componentwise, the zero weights skipped (the weights
/// are constants: the loop unrolls over the nonzero ones, each a sweep over the N components).
#[inline(always)]
fn weighted<const N: usize>(w: &[f64; 12], k: &[[f64; N]; 16]) -> [f64; N] {
    let mut s = [0.0; N];
    for j in 0..12 {
        if w[j] != 0.0 {
            for n in 0..N {
                s[n] += w[j] * k[j][n];
            }
        }
    }
    s
}

/// One trial step of size h from (t, q, v) with v̇ = `a` there, on `field`: stages
/// 1…12 into `k`, the 8th-order solution (q₁, q̇₁) and the error norm. What every Dop853 step
/// attempts, on a mechanism's accelerations or those of a held contact mode.
pub(crate) fn attempt<Q: Coordinates<N>, const N: usize>(
    st: &Dop853,
    (t, q, v, a): (f64, &[f64; N], &[f64; N], &[f64; N]),
    h: f64,
    k: &mut Stages<N>,
    stats: &mut Stats,
    field: &impl AccelerationField<N>,
) -> Result<([f64; N], [f64; N], f64)> {
    k.kq[0] = field.position_rates(q, v);
    k.ka[0] = *a;
    let y = (t, q, v);
    evaluate_stage::<1, N>(y, h, k, stats, field)?;
    evaluate_stage::<2, N>(y, h, k, stats, field)?;
    evaluate_stage::<3, N>(y, h, k, stats, field)?;
    evaluate_stage::<4, N>(y, h, k, stats, field)?;
    evaluate_stage::<5, N>(y, h, k, stats, field)?;
    evaluate_stage::<6, N>(y, h, k, stats, field)?;
    evaluate_stage::<7, N>(y, h, k, stats, field)?;
    evaluate_stage::<8, N>(y, h, k, stats, field)?;
    evaluate_stage::<9, N>(y, h, k, stats, field)?;
    evaluate_stage::<10, N>(y, h, k, stats, field)?;
    evaluate_stage::<11, N>(y, h, k, stats, field)?;
    // dop853.f: k₄ = Σⱼ bⱼ kⱼ and y₁ = y₀ + h·k₄; the 5th-order error h·Σⱼ eⱼ kⱼ and the 3rd-order
    // one h·(k₄ − bhh₁k₁ − bhh₂k₉ − bhh₃k₁₂) (the factor h is applied to the norm below).
    // The sums of squares run over y = (q, q̇) in this order, as over dop853.f's y.
    let (mut q1, mut v1) = ([0.0; N], [0.0; N]);
    let (mut err5, mut err3) = (0.0, 0.0);
    for (kx, y0, y1) in [(&k.kq, q, &mut q1), (&k.ka, v, &mut v1)] {
        let (bsum, e5) = (weighted(&B, kx), weighted(&E, kx));
        for n in 0..N {
            y1[n] = y0[n] + h * bsum[n];
            let e3 = bsum[n] - BHH[0] * kx[0][n] - BHH[1] * kx[8][n] - BHH[2] * kx[11][n];
            let sc = st.atol + st.rtol * y0[n].abs().max(y1[n].abs());
            err5 += ratio(e5[n], sc).powi(2);
            err3 += ratio(e3, sc).powi(2);
        }
    }
    check_state(&Q::NAMES, t + h, &q1, &v1)?;
    // dop853.f: err = |h|·err₅² / √(n·(err₅² + 0.01·err₃²)), with sums of squares.
    let mut deno = err5 + 0.01 * err3;
    if !(deno > 0.0) {
        deno = 1.0;
    }
    let err = h.abs() * err5 * (1.0 / (deno * (2 * N) as f64)).sqrt();
    if err.is_nan() {
        return Err(Error::NonFiniteDynamics {
            t: t + h,
            configuration: crate::error::describe_configuration(&Q::NAMES, &q1),
        });
    }
    Ok((q1, v1, err))
}
