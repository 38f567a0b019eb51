//! The classical fourth-order Runge–Kutta method (Hairer, Nørsett & Wanner, *Solving Ordinary
//! Differential Equations I*, §II.1, Table 1.2) on the first-order system (q, v)' = (v, q̈(t, q, v)).

use super::Integrator;
use crate::error::Result;
use crate::mechanism::{check_step_at, diagnose, Mechanism};
use crate::model::{Coordinates, State};

/// Fixed-step classical Runge–Kutta of order 4: four evaluations of the accelerations per step,
/// global error O(h⁴), no energy conservation (energy drifts slowly in long runs).
#[derive(Clone, Copy, Debug, Default)]
pub struct Rk4;

#[inline(always)]
fn axpy<const N: usize>(y: &[f64; N], a: f64, x: &[f64; N]) -> [f64; N] {
    std::array::from_fn(|i| y[i] + a * x[i])
}

impl Rk4 {
    /// One RK4 step on raw arrays: returns (q, v) at t + h. No validation. A stage whose mass
    /// matrix overflowed (a step that blew up) is [`Error::NonFiniteDynamics`](crate::Error::NonFiniteDynamics)
    /// at that stage, not a singular mass matrix (see [`diagnose`]).
    #[inline]
    pub fn step_arrays<M: Mechanism<N>, const N: usize>(
        mechanism: &M,
        t: f64,
        q: &[f64; N],
        v: &[f64; N],
        h: f64,
    ) -> Result<([f64; N], [f64; N])> {
        let half = 0.5 * h;
        let a1 = mechanism
            .accelerations_at(t, q, v)
            .map_err(|e| diagnose(mechanism, t, q, v, e))?;
        let (q2, v2) = (axpy(q, half, v), axpy(v, half, &a1));
        let a2 = mechanism
            .accelerations_at(t + half, &q2, &v2)
            .map_err(|e| diagnose(mechanism, t + half, &q2, &v2, e))?;
        let (q3, v3) = (axpy(q, half, &v2), axpy(v, half, &a2));
        let a3 = mechanism
            .accelerations_at(t + half, &q3, &v3)
            .map_err(|e| diagnose(mechanism, t + half, &q3, &v3, e))?;
        let (q4, v4) = (axpy(q, h, &v3), axpy(v, h, &a3));
        let a4 = mechanism
            .accelerations_at(t + h, &q4, &v4)
            .map_err(|e| diagnose(mechanism, t + h, &q4, &v4, e))?;
        let w = h / 6.0;
        let q_new = std::array::from_fn(|i| q[i] + w * (v[i] + 2.0 * (v2[i] + v3[i]) + v4[i]));
        let v_new = std::array::from_fn(|i| v[i] + w * (a1[i] + 2.0 * (a2[i] + a3[i]) + a4[i]));
        Ok((q_new, v_new))
    }
}

impl Integrator for Rk4 {
    const NAME: &'static str = "RK4";

    fn step<M: Mechanism<N>, const N: usize>(
        mechanism: &M,
        state: &mut State<M::Coords>,
        h: f64,
    ) -> Result<()> {
        check_step_at(state.t, h)?;
        let (q, v) = mechanism.check(state)?;
        mechanism.check_constraints(state.t, &q, &v)?;
        let (mut q_new, mut v_new) = Self::step_arrays(mechanism, state.t, &q, &v, h)?;
        mechanism.project(state.t + h, &mut q_new, &mut v_new)?;
        crate::model::check_state(&M::Coords::NAMES, state.t + h, &q_new, &v_new)?;
        state.t += h;
        state.q = M::Coords::from_array(q_new);
        state.v = M::Coords::from_array(v_new);
        Ok(())
    }
}
