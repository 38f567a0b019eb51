//! One Dormand–Prince 5(4) step: the stages (on any scalar), the trial step with its error norm,
//! and the order-4 continuous extension of an accepted step.

// Stage loops index several arrays.
#![allow(clippy::needless_range_loop)]

use super::settings::Dopri5;
use super::tableau::*;
use crate::error::{Error, Result};
use crate::geometry::Scalar;
use crate::integrate::control::ratio;
use crate::integrate::dense::{hermite_rows, DenseOutput};
use crate::integrate::Stats;
use crate::model::{check_state, Coordinates};

/// y + h Σⱼ coefⱼ kⱼ, componentwise, on any scalar (the f64 operations in the same order).
#[inline(always)]
pub(crate) fn combo<T: Scalar, const N: usize, const S: usize>(
    y: &[T; N],
    h: f64,
    coef: [f64; S],
    k: [&[T; N]; S],
) -> [T; N] {
    std::array::from_fn(|i| {
        let mut s = T::zero();
        for j in 0..S {
            s += k[j][i] * coef[j];
        }
        y[i] + s * h
    })
}

/// The stages of one Dormand–Prince step of size h from (t, q, v) with v̇ = `a1` there: the new
/// (q₁, v₁) and the stage position rates kq (`rates`, q̇ = G(q) v) and accelerations ka of stages
/// 1…6 (stage 7, FSAL, is v̇ at the new point). On any scalar: the f64 step, and the trajectory
/// sensitivities on dual numbers.
#[allow(clippy::type_complexity)]
#[inline(always)]
pub(crate) fn stages<T: Scalar, const N: usize>(
    t: f64,
    (q, v): (&[T; N], &[T; N]),
    a1: [T; N],
    h: f64,
    rates: impl Fn(&[T; N], &[T; N]) -> [T; N],
    mut acc: impl FnMut(f64, &[T; N], &[T; N]) -> Result<[T; N]>,
) -> Result<([T; N], [T; N], [[T; N]; 6], [[T; N]; 6])> {
    let (kq1, ka1) = (rates(q, v), a1);
    // Stage i: position increments use the stage position rates kqⱼ, velocity increments the
    // stage accelerations kaⱼ.
    let (q2, v2) = (combo(q, h, [A21], [&kq1]), combo(v, h, [A21], [&ka1]));
    let ka2 = acc(t + C2 * h, &q2, &v2)?;
    let kq2 = rates(&q2, &v2);
    let (q3, v3) = (
        combo(q, h, [A31, A32], [&kq1, &kq2]),
        combo(v, h, [A31, A32], [&ka1, &ka2]),
    );
    let ka3 = acc(t + C3 * h, &q3, &v3)?;
    let kq3 = rates(&q3, &v3);
    let (q4, v4) = (
        combo(q, h, [A41, A42, A43], [&kq1, &kq2, &kq3]),
        combo(v, h, [A41, A42, A43], [&ka1, &ka2, &ka3]),
    );
    let ka4 = acc(t + C4 * h, &q4, &v4)?;
    let kq4 = rates(&q4, &v4);
    let (q5, v5) = (
        combo(q, h, [A51, A52, A53, A54], [&kq1, &kq2, &kq3, &kq4]),
        combo(v, h, [A51, A52, A53, A54], [&ka1, &ka2, &ka3, &ka4]),
    );
    let ka5 = acc(t + C5 * h, &q5, &v5)?;
    let kq5 = rates(&q5, &v5);
    let (q6, v6) = (
        combo(
            q,
            h,
            [A61, A62, A63, A64, A65],
            [&kq1, &kq2, &kq3, &kq4, &kq5],
        ),
        combo(
            v,
            h,
            [A61, A62, A63, A64, A65],
            [&ka1, &ka2, &ka3, &ka4, &ka5],
        ),
    );
    let ka6 = acc(t + h, &q6, &v6)?;
    let kq6 = rates(&q6, &v6);
    let q1 = combo(
        q,
        h,
        [A71, A73, A74, A75, A76],
        [&kq1, &kq3, &kq4, &kq5, &kq6],
    );
    let v1 = combo(
        v,
        h,
        [A71, A73, A74, A75, A76],
        [&ka1, &ka3, &ka4, &ka5, &ka6],
    );
    Ok((
        q1,
        v1,
        [kq1, kq2, kq3, kq4, kq5, kq6],
        [ka1, ka2, ka3, ka4, ka5, ka6],
    ))
}

/// One trial step of Dormand–Prince 5(4) of size h from (t, q, v) with q̈ = `a` there, on the
/// accelerations `acc`: (q₁, v₁, err), with q̈₁ and the stage data for [`dense_output`] written into
/// `stages` (in place: the step's completion reads them there): what every Dopri5 step attempts, on
/// a mechanism's accelerations or those of a held contact mode. Adds its evaluations of `acc` to
/// `stats`.
#[allow(clippy::type_complexity)]
#[inline(always)]
pub(crate) fn trial<C: Coordinates<N>, const N: usize>(
    st: &Dopri5,
    (t, q, v, a): (f64, &[f64; N], &[f64; N], &[f64; N]),
    h: f64,
    (a_end, k): &mut Stages<N>,
    stats: &mut Stats,
    rates: impl Fn(&[f64; N], &[f64; N]) -> [f64; N],
    mut acc: impl FnMut(f64, &[f64; N], &[f64; N]) -> Result<[f64; N]>,
) -> Result<([f64; N], [f64; N], f64)> {
    let (q1, v1, kq, ka) = stages(t, (q, v), *a, h, &rates, |t, q, v| {
        stats.evaluations += 1;
        acc(t, q, v)
    })?;
    let [kq1, _, kq3, kq4, kq5, kq6] = kq;
    let [ka1, _, ka3, ka4, ka5, ka6] = ka;
    check_state(&C::NAMES, t + h, &q1, &v1)?;
    stats.evaluations += 1;
    let ka7 = acc(t + h, &q1, &v1)?;
    let kq7 = rates(&q1, &v1);
    let mut sum = 0.0;
    for i in 0..N {
        let eq =
            h * (E1 * kq1[i] + E3 * kq3[i] + E4 * kq4[i] + E5 * kq5[i] + E6 * kq6[i] + E7 * kq7[i]);
        let ev =
            h * (E1 * ka1[i] + E3 * ka3[i] + E4 * ka4[i] + E5 * ka5[i] + E6 * ka6[i] + E7 * ka7[i]);
        let sq = st.atol + st.rtol * q[i].abs().max(q1[i].abs());
        let sv = st.atol + st.rtol * v[i].abs().max(v1[i].abs());
        sum += ratio(eq, sq).powi(2) + ratio(ev, sv).powi(2);
    }
    // Every stage is finite here (checked above), so an infinite error norm is an error far
    // above a tolerance near the bottom of the floating-point range (rtol = atol = 1e-300):
    // a rejection like any other, which ends in a step-size underflow if it persists.
    let err = (sum / (2 * N) as f64).sqrt();
    if err.is_nan() {
        return Err(Error::NonFiniteDynamics {
            t: t + h,
            configuration: crate::error::describe_configuration(&C::NAMES, &q1),
        });
    }
    // The dense output needs d-weighted sums of the stages for q and v.
    let dq = combo(
        &[0.0; N],
        1.0,
        [D1, D3, D4, D5, D6, D7],
        [&kq1, &kq3, &kq4, &kq5, &kq6, &kq7],
    );
    let dv = combo(
        &[0.0; N],
        1.0,
        [D1, D3, D4, D5, D6, D7],
        [&ka1, &ka3, &ka4, &ka5, &ka6, &ka7],
    );
    *a_end = ka7;
    *k = [kq1, ka1, kq7, ka7, dq, dv];
    Ok((q1, v1, err))
}

/// The stages of a Dopri5 step its completion reads: q̈₁ (FSAL) and the dense output's data
/// (stages 1 and 7 and the d-weighted sums, for q and v).
pub(crate) type Stages<const N: usize> = ([f64; N], [[f64; N]; 6]);

/// The dense output of an accepted [`trial`] of size h from (t₀, q₀, v₀) to
/// (q₁, v₁): Hairer's CONTD5 (HNW I §II.6), order 4, no extra evaluation. Inlined, so that the
/// output is built where it is stored.
#[inline(always)]
pub(crate) fn dense_output<const N: usize>(
    t0: f64,
    h: f64,
    (q0, v0): (&[f64; N], &[f64; N]),
    (q1, v1): (&[f64; N], &[f64; N]),
    k: &[[f64; N]; 6],
) -> DenseOutput<N> {
    // Stage 1 is (q̇₀, v̇₀) and stage 7 (FSAL) is (q̇₁, v̇₁): the derivatives of (q, v) at the ends.
    let [kq1, ka1, kq7, ka7, dq, dv] = k;
    let make = |y0: &[f64; N],
                y1: &[f64; N],
                k1: &[f64; N],
                k7: &[f64; N],
                d: &[f64; N]|
     -> [[f64; N]; 8] {
        let mut r = [[0.0; N]; 8];
        hermite_rows(&mut r, h, y0, y1, k1, k7);
        for i in 0..N {
            r[4][i] = h * d[i];
        }
        r
    };
    DenseOutput::from_five(
        t0,
        h,
        make(q0, q1, kq1, kq7, dq),
        make(v0, v1, ka1, ka7, dv),
    )
}
