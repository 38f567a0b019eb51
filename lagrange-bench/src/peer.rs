//! The first peer: the `ode_solvers` crate's Dopri5 and Dop853 on y = (q, v) with the
//! hand-written accelerations.

use crate::runs::RunResult;
use crate::setup::{in_coordinates, split_qv, Rhs, Setup};
use lagrange_core::{Mechanism, State};
use ode_solvers::dop_shared::Stats;
use ode_solvers::SVector;

/// The first-order system y' = (v, q̈(t, q, v)), y = (q, v).
struct FirstOrder<const N: usize, const N2: usize> {
    rhs: Rhs<N>,
}

impl<const N: usize, const N2: usize> ode_solvers::System<f64, SVector<f64, N2>>
    for FirstOrder<N, N2>
{
    fn system(&self, t: f64, y: &SVector<f64, N2>, dy: &mut SVector<f64, N2>) {
        let (q, v) = split_qv::<N>(y.as_slice());
        let a = (self.rhs)(t, &q, &v);
        for i in 0..N {
            dy[i] = v[i];
            dy[N + i] = a[i];
        }
    }
}

/// Which of the peer's methods.
#[derive(Clone, Copy, Debug)]
pub enum PeerMethod {
    Dopri5,
    Dop853,
}

impl PeerMethod {
    pub fn name(self) -> &'static str {
        match self {
            PeerMethod::Dopri5 => "ode_solvers Dopri5",
            PeerMethod::Dop853 => "ode_solvers Dop853",
        }
    }
}

/// The peer's `method` on `rhs` from `start` to `t_end` at rtol = atol = `tol`: its statistics and
/// its output, the state at every accepted step with `keep_all`, else the last one only.
///
/// The peer's own default controller constants (those of its `new`, Hairer's: Dopri5 safety 0.9,
/// β = 0.04, factors 0.2…10; Dop853 safety 0.9, β = 0, factors 0.333…6), automatic initial step,
/// step limit raised to 10⁷. Sparse output: the solution at every accepted step, so the end point
/// is the solver's own last step (its dense output was measured to be less accurate than its steps
/// at tight tolerances: with dense output at t_end alone its Dopri5 stalls near 1e-7).
pub fn solve<const N: usize, const N2: usize>(
    rhs: Rhs<N>,
    start: &State<[f64; N]>,
    t_end: f64,
    tol: f64,
    method: PeerMethod,
    keep_all: bool,
) -> Result<(Stats, Vec<SVector<f64, N2>>), String> {
    assert_eq!(N2, 2 * N);
    let y0 = SVector::<f64, N2>::from_fn(|i, _| if i < N { start.q[i] } else { start.v[i - N] });
    let (t0, t1) = (start.t, t_end);
    macro_rules! integrate {
        ($solver:ident, $beta:expr, $fac_min:expr, $fac_max:expr) => {{
            let mut solver = ode_solvers::$solver::from_param(
                FirstOrder::<N, N2> { rhs },
                t0,
                t1,
                t1 - t0,
                y0,
                tol,
                tol,
                0.9,
                $beta,
                $fac_min,
                $fac_max,
                t1 - t0,
                0.0,
                10_000_000,
                1000,
                ode_solvers::OutputType::Sparse,
            );
            let stats = solver.integrate().map_err(|e| e.to_string())?;
            let ys = solver.y_out();
            let kept = if keep_all {
                ys.clone()
            } else {
                ys.last().cloned().into_iter().collect()
            };
            (stats, kept)
        }};
    }
    Ok(match method {
        PeerMethod::Dop853 => integrate!(Dop853, 0.0, 0.333, 6.0),
        PeerMethod::Dopri5 => integrate!(Dopri5, 0.04, 0.2, 10.0),
    })
}

/// One run of the peer's `method` at `tol`; with `track`, the maximum energy error over its
/// accepted steps.
pub fn run_peer<M: Mechanism<N>, const N: usize, const N2: usize>(
    setup: &Setup<M, N, N2>,
    method: PeerMethod,
    tol: f64,
    track: bool,
) -> RunResult<N> {
    let (stats, ys) = solve::<N, N2>(setup.rhs, &setup.start, setup.t_end, tol, method, track)?;
    let (q, v) = split_qv(ys.last().ok_or("no output")?.as_slice());
    let max_de = if track {
        max_energy_error(&setup.mechanism, &setup.start, &ys)?
    } else {
        f64::NAN
    };
    Ok((
        q,
        v,
        stats.num_eval as usize,
        0,
        max_de,
        stats.accepted_steps as usize,
    ))
}

/// max |E(y) − E(start)| over the states `ys`, by the mechanism's energy.
fn max_energy_error<M: Mechanism<N>, const N: usize, const N2: usize>(
    mechanism: &M,
    start: &State<[f64; N]>,
    ys: &[SVector<f64, N2>],
) -> Result<f64, String> {
    let e0 = mechanism
        .energy(&in_coordinates::<M, N>(start))
        .map_err(|e| e.to_string())?;
    let mut max_de = 0.0f64;
    for y in ys {
        let (q, v) = split_qv::<N>(y.as_slice());
        if let Ok(e) = mechanism.energy(&in_coordinates::<M, N>(&State::new(0.0, q, v))) {
            max_de = max_de.max((e - e0).abs());
        }
    }
    Ok(max_de)
}
