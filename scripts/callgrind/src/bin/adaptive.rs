//! Driver for callgrind: `adaptive MODE CALLS` integrates the work-precision report's double
//! pendulum (unit masses and lengths, g = 1, both arms horizontal at rest, to t = 10) CALLS times
//! with one adaptive method at one tolerance: lagrange's `Dopri5` / `Dop853` on the gallery
//! declaration through a validated handle, or the `ode_solvers` peer on the hand-written
//! equations, with the settings the report gives each side. Modes: `METHOD_E` with METHOD one of
//! `dopri5`, `dop853`, `peer_dopri5`, `peer_dop853` and tolerance 10^-E. The accepted steps and
//! evaluations of one run go to stderr, so that count.sh's instructions per call (`BIN=adaptive`)
//! divide into instructions per step.

use lagrange::integrate::{Dop853, Dopri5};
use lagrange::prelude::*;
use std::hint::black_box;

// The report's problems (the FPU chain's forces are in `fpu`).
#[path = "../../../../lagrange-bench/src/fpu.rs"]
#[allow(dead_code)]
mod fpu;
#[path = "../../../../lagrange-bench/src/pendulums.rs"]
#[allow(dead_code)]
mod pendulums;
#[path = "../../../../lagrange-bench/src/kepler.rs"]
#[allow(dead_code)]
mod kepler;
#[path = "../../../../lagrange-bench/src/problems.rs"]
#[allow(dead_code, unused_imports)]
mod problems;
use pendulums::{double_pendulum, DOUBLE_PENDULUM};
use problems::double_pendulum_rhs;

const T_END: f64 = 10.0;
const START: [f64; 2] = [std::f64::consts::FRAC_PI_2; 2];

/// The peer's right-hand side on y = (q, q̇), as in the report.
struct Peer;

impl ode_solvers::System<f64, ode_solvers::SVector<f64, 4>> for Peer {
    fn system(
        &self,
        t: f64,
        y: &ode_solvers::SVector<f64, 4>,
        dy: &mut ode_solvers::SVector<f64, 4>,
    ) {
        let a = double_pendulum_rhs(t, &[y[0], y[1]], &[y[2], y[3]]);
        (dy[0], dy[1], dy[2], dy[3]) = (y[2], y[3], a[0], a[1]);
    }
}

/// One run: (θ₁ at the end, accepted steps, evaluations).
fn run(method: &str, tol: f64) -> (f64, usize, usize) {
    let sys = DOUBLE_PENDULUM.validated().unwrap();
    let mut s = State::new(
        0.0,
        double_pendulum::Coords::from_array(START),
        double_pendulum::Coords::from_array([0.0; 2]),
    );
    // The report's settings: Dop853 without its dense output, the peer's own controller constants
    // (Dopri5 β = 0.04, factors 0.2…10; Dop853 β = 0, factors 0.333…6), sparse output.
    let peer = |dop853: bool| {
        let y0 = ode_solvers::SVector::<f64, 4>::new(START[0], START[1], 0.0, 0.0);
        macro_rules! go {
            ($solver:ident, $beta:expr, $fac_min:expr, $fac_max:expr) => {{
                let mut solver = ode_solvers::$solver::from_param(
                    Peer,
                    0.0,
                    T_END,
                    T_END,
                    y0,
                    tol,
                    tol,
                    0.9,
                    $beta,
                    $fac_min,
                    $fac_max,
                    T_END,
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
    };
    let out = match method {
        "dopri5" => Dopri5::new(tol, tol).integrate(&sys, &mut s, T_END, &mut [], |_| {}),
        "dop853" => Dop853 {
            dense: false,
            ..Dop853::new(tol, tol)
        }
        .integrate(&sys, &mut s, T_END, &mut [], |_| {}),
        "peer_dopri5" => return peer(false),
        "peer_dop853" => return peer(true),
        other => panic!("no adaptive method {other}"),
    }
    .unwrap();
    (s.q.theta1, out.stats.accepted, out.stats.evaluations)
}

fn main() {
    let mode = std::env::args().nth(1).expect("METHOD_E");
    let n: usize = std::env::args()
        .nth(2)
        .map(|s| s.parse().unwrap())
        .unwrap_or(1000);
    let (method, exponent) = mode.rsplit_once('_').expect("METHOD_E");
    let tol = 10f64.powi(-exponent.parse::<i32>().expect("tolerance exponent"));
    let mut acc = 0.0;
    for i in 0..n {
        let (theta, steps, evaluations) = run(black_box(method), black_box(tol));
        if i == 0 {
            eprintln!("{mode}: {steps} accepted steps, {evaluations} evaluations per run");
        }
        acc += theta;
    }
    println!("{acc}");
}
