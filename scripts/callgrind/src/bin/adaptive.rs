//! Driver for callgrind: `adaptive MODE CALLS` integrates one problem of the work-precision report
//! CALLS times with one adaptive method at one tolerance. MODE is `[PROBLEM.]METHOD_E`:
//!
//! - PROBLEM: `dp` (the default: the double pendulum, unit masses and lengths, g = 1, both arms
//!   horizontal at rest, to t = 10), `kepler` (e = 0.6 from periapsis over five periods, t = 10π) or
//!   `fpu` (the FPU chain, ω = 50, to t = 10) or `cart` (the pendulum in Cartesian coordinates
//!   with its length as a constraint, k = 0.999, over one period 4K(k));
//! - METHOD: `dopri5`, `dop853` (lagrange's, on the `#[mechanism]` declaration through a validated
//!   handle, `integrate` as the report runs it), `hw_dopri5`, `hw_dop853` (lagrange's, stepped
//!   through `EmbeddedPair` on the hand-written equations of the peer: the integrator's own work
//!   against the peer's on the same right-hand side), `field_dop853` (lagrange's, stepped the same
//!   way on the declaration's accelerations: the cost of `integrate` around the steps),
//!   `peer_dopri5`, `peer_dop853` (`ode_solvers` on the hand-written equations);
//! - E: the tolerance 10^-E (rtol = atol; E may be fractional, `9.5` for the report's 3.2e-10).
//!
//! Each side has the report's settings (Dop853 without dense output; the peer's own controller
//! constants, sparse output). The accepted steps and evaluations of one run go to stderr, so that
//! count.sh's instructions per call (`BIN=adaptive`) divide into instructions per step.

use lagrange::integrate::{AccelerationField, Dop853, Dopri5, EmbeddedPair, Stats};
use lagrange::prelude::*;
use nalgebra::SMatrix;
use std::hint::black_box;

// The report's problems (the FPU chain's forces are in `fpu`).
#[path = "../../../../lagrange-bench/src/fpu.rs"]
#[allow(dead_code)]
mod fpu;
#[path = "../../../../lagrange-bench/src/kepler.rs"]
#[allow(dead_code)]
mod kepler;
#[path = "../../../../lagrange-bench/src/pendulums.rs"]
#[allow(dead_code)]
mod pendulums;
// The report's stiff and constrained problems.
#[path = "../../../../lagrange-bench/src/problems.rs"]
#[allow(dead_code, unused_imports)]
mod problems;
#[path = "../../../../lagrange-bench/src/stiff.rs"]
#[allow(dead_code, unused_imports)]
mod stiff;

/// A problem: its start (q, q̇), end time and hand-written accelerations.
struct Problem<const N: usize> {
    q: [f64; N],
    v: [f64; N],
    t_end: f64,
    rhs: fn(f64, &[f64; N], &[f64; N]) -> [f64; N],
}

/// The peer's right-hand side on y = (q, q̇), as in the report.
struct Peer<const N: usize> {
    rhs: fn(f64, &[f64; N], &[f64; N]) -> [f64; N],
}

impl<const N: usize, const N2: usize> ode_solvers::System<f64, ode_solvers::SVector<f64, N2>>
    for Peer<N>
{
    fn system(
        &self,
        t: f64,
        y: &ode_solvers::SVector<f64, N2>,
        dy: &mut ode_solvers::SVector<f64, N2>,
    ) {
        let q: [f64; N] = std::array::from_fn(|i| y[i]);
        let v: [f64; N] = std::array::from_fn(|i| y[N + i]);
        let a = (self.rhs)(t, &q, &v);
        for i in 0..N {
            dy[i] = v[i];
            dy[N + i] = a[i];
        }
    }
}

/// The hand-written accelerations as lagrange's right-hand side.
struct HandWritten<const N: usize> {
    rhs: fn(f64, &[f64; N], &[f64; N]) -> [f64; N],
}

impl<const N: usize> AccelerationField<N> for HandWritten<N> {
    #[inline]
    fn accelerations(&self, t: f64, q: &[f64; N], v: &[f64; N]) -> lagrange::Result<[f64; N]> {
        Ok((self.rhs)(t, q, v))
    }

    fn jacobians(
        &self,
        _t: f64,
        _q: &[f64; N],
        _v: &[f64; N],
    ) -> lagrange::Result<(SMatrix<f64, N, N>, SMatrix<f64, N, N>)> {
        unreachable!("the explicit pairs take no Jacobian")
    }
}

/// One run of the peer: (q₀ at the end, accepted steps, evaluations).
fn peer<const N: usize, const N2: usize>(
    p: &Problem<N>,
    dop853: bool,
    tol: f64,
) -> (f64, usize, usize) {
    let y0 =
        ode_solvers::SVector::<f64, N2>::from_fn(|i, _| if i < N { p.q[i] } else { p.v[i - N] });
    macro_rules! go {
        ($solver:ident, $beta:expr, $fac_min:expr, $fac_max:expr) => {{
            let mut solver = ode_solvers::$solver::from_param(
                Peer { rhs: p.rhs },
                0.0,
                p.t_end,
                p.t_end,
                y0,
                tol,
                tol,
                0.9,
                $beta,
                $fac_min,
                $fac_max,
                p.t_end,
                0.0,
                10_000_000,
                1000,
                ode_solvers::OutputType::Sparse,
            );
            let stats = solver.integrate().unwrap();
            let y = solver.y_out().last().unwrap()[0];
            (y, stats.accepted_steps as usize, stats.num_eval as usize)
        }};
    }
    if dop853 {
        go!(Dop853, 0.0, 0.333, 6.0)
    } else {
        go!(Dopri5, 0.04, 0.2, 10.0)
    }
}

/// The declaration's accelerations as a right-hand side of its own, stepped outside `integrate`.
struct Declared<'m, M>(&'m M);

impl<M: Mechanism<N>, const N: usize> AccelerationField<N> for Declared<'_, M> {
    #[inline]
    fn accelerations(&self, t: f64, q: &[f64; N], v: &[f64; N]) -> lagrange::Result<[f64; N]> {
        self.0.accelerations_at(t, q, v)
    }

    fn jacobians(
        &self,
        _t: f64,
        _q: &[f64; N],
        _v: &[f64; N],
    ) -> lagrange::Result<(SMatrix<f64, N, N>, SMatrix<f64, N, N>)> {
        unreachable!("the explicit pairs take no Jacobian")
    }
}

/// One run of lagrange's `method` stepped through [`EmbeddedPair`] on `field`.
fn on_field<P: EmbeddedPair, C: Coordinates<N>, const N: usize>(
    p: &Problem<N>,
    field: &impl AccelerationField<N>,
    method: P,
) -> (f64, usize, usize) {
    let mut stats = Stats::default();
    let (mut t, mut q, mut v) = (0.0, p.q, p.v);
    let mut a = field.accelerations(t, &q, &v).unwrap();
    stats.evaluations += 1;
    let mut memory = method.start(field, (t, &q, &v, &a), &mut stats);
    let mut scratch = P::scratch::<N>();
    let mut dense = lagrange::integrate::DenseOutput::constant(t, &q, &v);
    while t < p.t_end {
        let step = method
            .step::<C, N>(
                &mut memory,
                &mut scratch,
                field,
                (t, &q, &v, &a),
                p.t_end,
                &mut stats,
                &mut dense,
            )
            .unwrap();
        (t, q, v, a) = (step.t, step.q, step.v, step.a.unwrap());
    }
    (q[0], stats.accepted, stats.evaluations)
}

/// One run of lagrange's Dopri5 / Dop853 on `sys` (a validated handle), as the report runs it.
fn generated<M: Mechanism<N>, const N: usize>(
    sys: &M,
    p: &Problem<N>,
    dop853: bool,
    tol: f64,
) -> (f64, usize, usize) {
    let mut s = State::new(0.0, M::Coords::from_array(p.q), M::Coords::from_array(p.v));
    let out = if dop853 {
        let method = Dop853 {
            dense: false,
            ..Dop853::new(tol, tol)
        };
        sys.integrate(method, &mut s, p.t_end, &mut [], |_| {})
    } else {
        sys.integrate(Dopri5::new(tol, tol), &mut s, p.t_end, &mut [], |_| {})
    }
    .unwrap();
    (s.q.to_array()[0], out.stats.accepted, out.stats.evaluations)
}

/// One run of `method` on `problem` with its declaration `sys`.
fn run<M: Mechanism<N>, const N: usize, const N2: usize>(
    sys: &M,
    p: &Problem<N>,
    method: &str,
    tol: f64,
) -> (f64, usize, usize) {
    // lagrange's settings on the hand-written side: those `integrate` takes (the largest step
    // the integration interval, as in dop853.f), without the dense output.
    let dop853 = Dop853 {
        dense: false,
        h_max: p.t_end,
        ..Dop853::new(tol, tol)
    };
    let hw = HandWritten { rhs: p.rhs };
    match method {
        "dopri5" => generated(sys, p, false, tol),
        "dop853" => generated(sys, p, true, tol),
        "hw_dopri5" => on_field::<_, M::Coords, N>(p, &hw, Dopri5::new(tol, tol)),
        "hw_dop853" => on_field::<_, M::Coords, N>(p, &hw, dop853),
        "field_dop853" => on_field::<_, M::Coords, N>(p, &Declared(sys), dop853),
        "peer_dopri5" => peer::<N, N2>(p, false, tol),
        "peer_dop853" => peer::<N, N2>(p, true, tol),
        other => panic!("no adaptive method {other}"),
    }
}

fn main() {
    let mode = std::env::args().nth(1).expect("[PROBLEM.]METHOD_E");
    let n: usize = std::env::args()
        .nth(2)
        .map(|s| s.parse().unwrap())
        .unwrap_or(1000);
    let (problem, rest) = mode.split_once('.').unwrap_or(("dp", &mode));
    let (method, exponent) = rest.rsplit_once('_').expect("METHOD_E");
    let tol = 10f64.powf(-exponent.parse::<f64>().expect("tolerance exponent"));
    let mut acc = 0.0;
    for i in 0..n {
        let (method, tol) = (black_box(method), black_box(tol));
        let (end, steps, evaluations) = match problem {
            "dp" => {
                let p = Problem {
                    q: [std::f64::consts::FRAC_PI_2; 2],
                    v: [0.0; 2],
                    t_end: 10.0,
                    rhs: problems::double_pendulum_rhs,
                };
                let sys = pendulums::DOUBLE_PENDULUM.validated().unwrap();
                run::<_, 2, 4>(&sys, &p, method, tol)
            }
            "kepler" => {
                let s = problems::kepler_start();
                let p = Problem {
                    q: s.q,
                    v: s.v,
                    t_end: 10.0 * std::f64::consts::PI,
                    rhs: problems::kepler_rhs,
                };
                let sys = kepler::KEPLER.validated().unwrap();
                run::<_, 2, 4>(&sys, &p, method, tol)
            }
            "fpu" => {
                let s = problems::fpu_start();
                let p = Problem {
                    q: s.q,
                    v: s.v,
                    t_end: 10.0,
                    rhs: problems::fpu_rhs,
                };
                let chain = fpu::fpu_chain::Fpu {
                    m: 1.0,
                    omega: problems::FPU_OMEGA,
                };
                let sys = chain.validated().unwrap();
                run::<_, 6, 12>(&sys, &p, method, tol)
            }
            "cart" => {
                let s = stiff::cartesian_start();
                let p = Problem {
                    q: s.q,
                    v: s.v,
                    t_end: 4.0 * problems::elliptic_k(problems::PENDULUM_K),
                    rhs: stiff::cartesian_rhs,
                };
                let sys = stiff::ROD.validated().unwrap();
                run::<_, 2, 4>(&sys, &p, method, tol)
            }
            other => panic!("no problem {other}"),
        };
        if i == 0 {
            eprintln!("{mode}: {steps} accepted steps, {evaluations} evaluations per run");
        }
        acc += end;
    }
    println!("{acc}");
}
