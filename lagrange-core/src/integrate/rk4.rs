//! The classical fourth-order Runge–Kutta method (Hairer, Nørsett & Wanner, *Solving Ordinary
//! Differential Equations I*, §II.1, Table 1.2) on the first-order system (q, v)' = (v, q̈(t, q, v)).

use super::{Integrator, Stats};
use crate::error::Result;
use crate::evaluation::{diagnose, Evaluate};
use crate::geometry::Scalar;

/// Fixed-step classical Runge–Kutta of order 4: four evaluations of the accelerations per step,
/// global error O(h⁴), no energy conservation (energy drifts slowly in long runs).
///
/// ```
/// use lagrange_core::{Mechanism, Rk4, State};
/// # use lagrange_core::{vec2, Model, Scalar};
/// # struct Pendulum;
/// # impl Model<1, 2> for Pendulum {
/// #     type Coords = [f64; 1];
/// #     const RHEONOMIC: bool = false;
/// #     const HAS_POTENTIAL: bool = true;
/// #     const HAS_FORCES: bool = false;
/// #     fn validate(&self) -> lagrange_core::Result<()> { Ok(()) }
/// #     fn masses(&self) -> [f64; 2] { [1.0, 1.0] }
/// #     fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 1]) -> [D; 2] {
/// #         vec2(q[0].sin(), -q[0].cos()).to_array()
/// #     }
/// #     fn potential<D: Scalar>(&self, _t: D, _q: &[D; 1], x: &[D; 2]) -> D { x[1] * 9.81 }
/// # }
/// # lagrange_core::impl_mechanism!(Pendulum, 1, 2);
/// let mut s = State::new(0.0, [0.5], [0.0]);
/// let e0 = Pendulum.energy(&s)?;
/// for _ in 0..1000 {
///     Pendulum.step::<Rk4>(&mut s, 1e-3)?;
/// }
/// // Local error O(h⁵) per step with constants of order ω⁵|θ| ≈ 150: ≈ 1e-13 per step.
/// assert!((Pendulum.energy(&s)? - e0).abs() < 1e-9);
/// # Ok::<(), lagrange_core::Error>(())
/// ```
#[derive(Clone, Copy, Debug, Default)]
pub struct Rk4;

#[inline(always)]
fn axpy<S: Scalar, const N: usize>(y: &[S; N], a: f64, x: &[S; N]) -> [S; N] {
    std::array::from_fn(|i| y[i] + x[i] * a)
}

/// One classical RK4 step of (q, v)' = (`rates`(q, v), `acc`(t, q, v)) from (t, q, v): (q, v) at
/// t + h, with `rates` q̇ = G(q) v ([`Evaluate::position_rates_at`]: v itself unless the mechanism
/// has quasi-velocities). The one implementation of the method, on `f64` ([`Rk4`]'s step, also
/// with a contact mode held) and on dual numbers `S` (trajectory sensitivities: the same
/// operations in the same order, so the real parts are the f64 run bit for bit).
#[inline(always)]
pub(crate) fn rk4_step<S: Scalar, const N: usize>(
    t: f64,
    (q, v): (&[S; N], &[S; N]),
    h: f64,
    rates: impl Fn(&[S; N], &[S; N]) -> [S; N],
    mut acc: impl FnMut(f64, &[S; N], &[S; N]) -> Result<[S; N]>,
) -> Result<([S; N], [S; N])> {
    let half = 0.5 * h;
    let (r1, a1) = (rates(q, v), acc(t, q, v)?);
    let (q2, v2) = (axpy(q, half, &r1), axpy(v, half, &a1));
    let (r2, a2) = (rates(&q2, &v2), acc(t + half, &q2, &v2)?);
    let (q3, v3) = (axpy(q, half, &r2), axpy(v, half, &a2));
    let (r3, a3) = (rates(&q3, &v3), acc(t + half, &q3, &v3)?);
    let (q4, v4) = (axpy(q, h, &r3), axpy(v, h, &a3));
    let (r4, a4) = (rates(&q4, &v4), acc(t + h, &q4, &v4)?);
    let w = h / 6.0;
    let q_new = std::array::from_fn(|i| q[i] + (r1[i] + (r2[i] + r3[i]) * 2.0 + r4[i]) * w);
    let v_new = std::array::from_fn(|i| v[i] + (a1[i] + (a2[i] + a3[i]) * 2.0 + a4[i]) * w);
    Ok((q_new, v_new))
}

impl Rk4 {
    /// One RK4 step on raw arrays: returns (q, v) at t + h. No validation. A stage whose mass
    /// matrix overflowed (a step that blew up) is [`Error::NonFiniteDynamics`](crate::Error::NonFiniteDynamics)
    /// at that stage, not a singular mass matrix (see [`diagnose`]).
    #[inline]
    pub fn step_arrays<M: Evaluate<N>, const N: usize>(
        mechanism: &M,
        t: f64,
        q: &[f64; N],
        v: &[f64; N],
        h: f64,
    ) -> Result<([f64; N], [f64; N])> {
        let rates = |q: &[f64; N], v: &[f64; N]| mechanism.position_rates_at(q, v);
        rk4_step(t, (q, v), h, rates, |t, q, v| {
            mechanism
                .accelerations_at(t, q, v)
                .map_err(|e| diagnose(mechanism, t, q, v, e))
        })
    }
}

impl Integrator for Rk4 {
    const NAME: &'static str = "RK4";
    type Memory<const N: usize> = ();
    const STEPS_ON_DUALS: bool = true;

    /// `rk4_step` on any scalar: four evaluations of `acc`.
    #[inline]
    fn advance_on_duals<S: Scalar, const N: usize>(
        t: f64,
        y: (&[S; N], &[S; N]),
        h: f64,
        rates: impl Fn(&[S; N], &[S; N]) -> [S; N],
        acc: impl FnMut(f64, &[S; N], &[S; N]) -> Result<[S; N]>,
        stats: &mut Stats,
    ) -> Result<([S; N], [S; N])> {
        stats.evaluations += 4;
        rk4_step(t, y, h, rates, acc)
    }

    #[inline]
    fn advance<M: Evaluate<N>, const N: usize>(
        mechanism: &M,
        _memory: &mut (),
        t: f64,
        q: &[f64; N],
        v: &[f64; N],
        h: f64,
        stats: &mut Stats,
    ) -> Result<([f64; N], [f64; N])> {
        stats.evaluations += 4;
        Self::step_arrays(mechanism, t, q, v, h)
    }
}
