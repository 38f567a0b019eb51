//! One run of one method on one problem, from the start to the end time: lagrange's fixed-step
//! and adaptive methods, and diffsol's solvers (the `ode_solvers` peer is in [`crate::peer`]).

use crate::diffsol_peer;
use crate::setup::{in_coordinates, Setup};
use lagrange_core::integrate::{Dop853, ImplicitStepStats, NewtonMemory, Observation, Stepper};
use lagrange_core::{
    Coordinates, Dopri5, GaussLegendre2, ImplicitMidpoint, Integrator, Mechanism, Radau5, Rk4,
    StormerVerlet, Variational,
};

/// What one run returns: end state, evaluations, Jacobian evaluations, max energy error (NaN when
/// not tracked), steps, or an error message.
pub type RunResult<const N: usize> = Result<([f64; N], [f64; N], usize, usize, f64, usize), String>;

/// lagrange's fixed-step methods.
pub enum Fixed {
    Rk4,
    Midpoint,
    Gauss,
    Variational,
    Verlet,
}

impl Fixed {
    pub fn name(&self) -> &'static str {
        match self {
            Fixed::Rk4 => Rk4::NAME,
            Fixed::Midpoint => ImplicitMidpoint::NAME,
            Fixed::Gauss => GaussLegendre2::NAME,
            Fixed::Variational => Variational::NAME,
            Fixed::Verlet => StormerVerlet::NAME,
        }
    }
}

/// n steps of a fixed-step method from the start; returns the end state and costs.
pub fn run_fixed<M: Mechanism<N>, const N: usize, const N2: usize>(
    setup: &Setup<M, N, N2>,
    method: &Fixed,
    n: usize,
    track: bool,
) -> RunResult<N> {
    let m = &setup.mechanism;
    let mut s = in_coordinates::<M, N>(&setup.start);
    let h = (setup.t_end - s.t) / n as f64;
    let e0 = m.energy(&s).map_err(|e| e.to_string())?;
    let mut max_de = if track { 0.0f64 } else { f64::NAN };
    let (mut rhs, mut jac) = (0usize, 0usize);
    // The implicit methods run as a solver does: the Newton matrix and the stage predictor are
    // kept from step to step. Evaluations: plain evaluations of the canonical field plus the
    // velocity recovery's passes of the momenta plus the momenta and q̈ at the step's start.
    let add = |st: ImplicitStepStats, rhs: &mut usize, jac: &mut usize| {
        *rhs += st.field_evaluations + st.velocity_iterations + 2;
        *jac += st.jacobian_evaluations;
    };
    let mut memory1 = NewtonMemory::<N, 1>::default();
    let mut memory2 = NewtonMemory::<N, 2>::default();
    for _ in 0..n {
        let r = match method {
            Fixed::Rk4 => m.step::<Rk4>(&mut s, h).map(|_| rhs += 4),
            Fixed::Verlet => m.step::<StormerVerlet>(&mut s, h).map(|_| rhs += 3),
            Fixed::Midpoint => ImplicitMidpoint::step_with_memory(m, &mut memory1, &mut s, h)
                .map(|st| add(st, &mut rhs, &mut jac)),
            Fixed::Gauss => GaussLegendre2::step_with_memory(m, &mut memory2, &mut s, h)
                .map(|st| add(st, &mut rhs, &mut jac)),
            Fixed::Variational => Variational::step_with_stats(m, &mut s, h).map(|st| {
                // predictor, constraint test, final momentum rate, momenta; Newton iterations
                // evaluate with Jacobians.
                rhs += 4;
                jac += st.iterations + st.velocity_iterations;
            }),
        };
        r.map_err(|e| e.to_string())?;
        if track {
            let de = (m.energy(&s).map_err(|e| e.to_string())? - e0).abs();
            if de.is_nan() || de > setup.unstable_energy * (1.0 + e0.abs()) {
                return Err(format!(
                    "unstable (energy error {de:.2e} at t = {:.3})",
                    s.t
                ));
            }
            max_de = max_de.max(de);
        }
    }
    Ok((s.q.to_array(), s.v.to_array(), rhs, jac, max_de, n))
}

/// lagrange's adaptive methods.
#[derive(Clone, Copy, Debug)]
pub enum Adaptive {
    Dopri5,
    Dop853,
    Radau5,
}

impl Adaptive {
    pub fn name(self) -> &'static str {
        match self {
            Adaptive::Dopri5 => "Dopri5",
            Adaptive::Dop853 => "Dop853",
            Adaptive::Radau5 => "Radau5",
        }
    }
}

/// One run of an adaptive method at rtol = atol = `tol`; with `track`, the maximum energy error
/// over its accepted steps.
pub fn run_adaptive<M: Mechanism<N>, const N: usize, const N2: usize>(
    setup: &Setup<M, N, N2>,
    method: Adaptive,
    tol: f64,
    track: bool,
) -> RunResult<N> {
    let m = &setup.mechanism;
    let s = in_coordinates::<M, N>(&setup.start);
    let e0 = m.energy(&s).map_err(|e| e.to_string())?;
    let mut max_de = if track { 0.0f64 } else { f64::NAN };
    let observe = |o: Observation<'_, M::Coords, N>| {
        if track {
            if let Observation::Step { state, .. } = o {
                if let Ok(e) = m.energy(state) {
                    max_de = max_de.max((e - e0).abs());
                }
            }
        }
    };
    // Dop853 without its dense output (no events here; the peer's sparse output skips it too).
    let t_end = setup.t_end;
    let out = match method {
        Adaptive::Dop853 => {
            let settings = Dop853 {
                dense: false,
                ..Dop853::new(tol, tol)
            };
            Stepper::new(m, settings, &s).and_then(|mut r| r.integrate(t_end, &mut [], observe))
        }
        Adaptive::Dopri5 => Stepper::new(m, Dopri5::new(tol, tol), &s)
            .and_then(|mut r| r.integrate(t_end, &mut [], observe)),
        Adaptive::Radau5 => Stepper::new(m, Radau5::new(tol, tol), &s)
            .and_then(|mut r| r.integrate(t_end, &mut [], observe)),
    }
    .map_err(|e| e.to_string())?;
    let end = out.state;
    Ok((
        end.q.to_array(),
        end.v.to_array(),
        out.stats.evaluations,
        out.stats.jacobians,
        max_de,
        out.stats.accepted,
    ))
}

/// One run of diffsol's `method` at `tol`; the energy along the way is not tracked (NaN).
pub fn run_diffsol<M: Mechanism<N>, const N: usize, const N2: usize>(
    setup: &Setup<M, N, N2>,
    method: diffsol_peer::Method,
    tol: f64,
) -> RunResult<N> {
    let jac = setup.jacobian_times.ok_or("no Jacobian-vector product")?;
    let s = &setup.start;
    let (q, v, evals, products, steps) =
        diffsol_peer::run(method, setup.rhs, jac, s.t, s.q, s.v, setup.t_end, tol)?;
    Ok((q, v, evals, products, f64::NAN, steps))
}
