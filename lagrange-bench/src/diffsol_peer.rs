//! The second peer on the stiff problems: `diffsol`'s BDF (variable order 1–5, Newton with a
//! Jacobian it assembles from the Jacobian-vector product given) and ESDIRK3(4) solvers, on
//! y = (q, v) with the hand-written accelerations and Jacobian-vector product, dense nalgebra
//! matrices and LU.

use crate::setup::{split_qv, Rhs};
use diffsol::{NalgebraLU, NalgebraMat, OdeBuilder, OdeSolverMethod, OdeSolverStopReason};
use std::cell::Cell;

/// Hand-written Jacobian of (q̇, q̈) applied to (dq, dv).
pub type JacobianTimes<const N: usize> =
    fn(f64, &[f64; N], &[f64; N], &[f64; N], &[f64; N]) -> ([f64; N], [f64; N]);

/// Which diffsol method.
#[derive(Clone, Copy, Debug)]
pub enum Method {
    Bdf,
    Esdirk34,
}

impl Method {
    pub fn name(self) -> &'static str {
        match self {
            Method::Bdf => "diffsol BDF",
            Method::Esdirk34 => "diffsol ESDIRK34",
        }
    }
}

/// What a run returns: the end (q, v), right-hand-side evaluations, Jacobian-vector products,
/// steps.
pub type Outcome<const N: usize> = ([f64; N], [f64; N], usize, usize, usize);

/// Integrates from (t0, q0, v0) to t1 with rtol = atol = tol; stops exactly at t1.
#[allow(clippy::too_many_arguments)]
pub fn run<const N: usize>(
    method: Method,
    rhs: Rhs<N>,
    jac: JacobianTimes<N>,
    t0: f64,
    q0: [f64; N],
    v0: [f64; N],
    t1: f64,
    tol: f64,
) -> Result<Outcome<N>, String> {
    let evaluations = Cell::new(0usize);
    let products = Cell::new(0usize);
    let problem = OdeBuilder::<NalgebraMat<f64>>::new()
        .t0(t0)
        .rtol(tol)
        .atol([tol])
        .rhs_implicit(
            |y: &[f64], _p: &[f64], t: f64, dy: &mut [f64]| {
                evaluations.set(evaluations.get() + 1);
                let (q, v) = split_qv(y);
                let a = rhs(t, &q, &v);
                dy[..N].copy_from_slice(&v);
                dy[N..].copy_from_slice(&a);
            },
            |y: &[f64], _p: &[f64], t: f64, d: &[f64], out: &mut [f64]| {
                products.set(products.get() + 1);
                let (q, v) = split_qv(y);
                let (dq, dv) = split_qv(d);
                let (jq, jv) = jac(t, &q, &v, &dq, &dv);
                out[..N].copy_from_slice(&jq);
                out[N..].copy_from_slice(&jv);
            },
        )
        .init(
            |_p: &[f64], _t: f64, y: &mut [f64]| {
                y[..N].copy_from_slice(&q0);
                y[N..].copy_from_slice(&v0);
            },
            2 * N,
        )
        .build()
        .map_err(|e| e.to_string())?;
    macro_rules! go {
        ($solver:expr) => {{
            let mut solver = $solver.map_err(|e| e.to_string())?;
            solver.set_stop_time(t1).map_err(|e| e.to_string())?;
            loop {
                match solver.step().map_err(|e| e.to_string())? {
                    OdeSolverStopReason::TstopReached => break,
                    OdeSolverStopReason::InternalTimestep => {}
                    OdeSolverStopReason::RootFound(..) => return Err("unexpected root".into()),
                }
            }
            let y: Vec<f64> = (0..2 * N).map(|i| solver.state().y[i]).collect();
            let steps = solver.get_statistics().number_of_steps;
            (y, steps)
        }};
    }
    let (y, steps) = match method {
        Method::Bdf => go!(problem.bdf::<NalgebraLU<f64>>()),
        Method::Esdirk34 => go!(problem.esdirk34::<NalgebraLU<f64>>()),
    };
    let (q, v) = split_qv(&y);
    Ok((q, v, evaluations.get(), products.get(), steps))
}
