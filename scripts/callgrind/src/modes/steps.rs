//! Steps of the integrators on the double pendulum (h = 10⁻³), one per call: RK4 on the
//! parameters, through a validated handle, with an animation recorder, with sensitivities, and by
//! hand on the closed form; the implicit midpoint rule and Gauss–Legendre 2 as a solver takes them
//! (memory kept) and through `sys.step` (fresh memory); accepted steps of Radau5 from a solver.

use crate::mechanisms::{double_pendulum_start, DOUBLE_PENDULUM};
use crate::modes::closed_forms::double_pendulum_accelerations;
use lagrange::evaluation::Evaluate;
use lagrange::integrate::NewtonMemory;
use lagrange::prelude::*;
use lagrange::sensitivity::Seed;
use lagrange::{GaussLegendre2, ImplicitMidpoint};
use std::hint::black_box;

/// `sys.step::<Rk4>` on the parameters.
pub fn rk4_double_pendulum(n: usize) -> f64 {
    let params = DOUBLE_PENDULUM;
    let mut s = double_pendulum_start();
    for _ in 0..n {
        black_box(&params).step::<Rk4>(&mut s, 1e-3).unwrap();
    }
    s.q.theta1
}

/// `sys.step::<Rk4>` through a validated handle.
pub fn rk4_validated_double_pendulum(n: usize) -> f64 {
    let params = DOUBLE_PENDULUM;
    let mut s = double_pendulum_start();
    let sys = params.validated().unwrap();
    for _ in 0..n {
        black_box(&sys).step::<Rk4>(&mut s, 1e-3).unwrap();
    }
    s.q.theta1
}

/// An RK4 step and one `Recorder::push` per call, at 30 frames per second of simulated time (a
/// frame kept every 34 steps), against `rk4_validated_double_pendulum`.
pub fn rk4_recorded_double_pendulum(n: usize) -> f64 {
    let sys = DOUBLE_PENDULUM.validated().unwrap();
    let mut s = double_pendulum_start();
    let mut recorder = lagrange::animation::Recorder::new(&sys);
    for _ in 0..n {
        black_box(&sys).step::<Rk4>(&mut s, 1e-3).unwrap();
        recorder.push(&sys, &s).unwrap();
    }
    s.q.theta1 + recorder.frames() as f64
}

/// RK4 written out on the closed form (`double_pendulum_accelerations`).
pub fn hw_rk4_double_pendulum(n: usize) -> f64 {
    let sys = DOUBLE_PENDULUM;
    let (mut q, mut v) = ([0.7, -1.2], [1.1, -0.4]);
    let h = 1e-3;
    let axpy = |x: [f64; 2], a: f64, y: [f64; 2]| [x[0] + a * y[0], x[1] + a * y[1]];
    for _ in 0..n {
        let f = |q, v| double_pendulum_accelerations(black_box(&sys), q, v);
        let a1 = f(q, v);
        let (q2, v2) = (axpy(q, 0.5 * h, v), axpy(v, 0.5 * h, a1));
        let a2 = f(q2, v2);
        let (q3, v3) = (axpy(q, 0.5 * h, v2), axpy(v, 0.5 * h, a2));
        let a3 = f(q3, v3);
        let (q4, v4) = (axpy(q, h, v3), axpy(v, h, a3));
        let a4 = f(q4, v4);
        for j in 0..2 {
            q[j] += h / 6.0 * (v[j] + 2.0 * v2[j] + 2.0 * v3[j] + v4[j]);
            v[j] += h / 6.0 * (a1[j] + 2.0 * a2[j] + 2.0 * a3[j] + a4[j]);
        }
    }
    q[0]
}

/// An RK4 step per call on dual numbers seeded on `seeds` (a `Stepper` with sensitivities, through
/// a validated handle), against `rk4_validated_double_pendulum`: ∂θ₁/∂(first seed) at the end.
fn sensitivity_steps<const P: usize>(n: usize, seeds: [Seed; P]) -> f64 {
    let sys = DOUBLE_PENDULUM.validated().unwrap();
    let s = double_pendulum_start();
    let mut run = Stepper::new(&sys, Rk4::with_step(1e-3), &s)
        .unwrap()
        .with_sensitivities(seeds)
        .unwrap();
    for _ in 0..n {
        black_box(&mut run).step(f64::INFINITY).unwrap();
    }
    run.sensitivities().dq[0].theta1
}

// Seeded on 1, 2 or 4 initial values.
const THETA1: Seed = Seed::Coordinate("theta1");
const THETA2: Seed = Seed::Coordinate("theta2");

pub fn sensitivity_double_pendulum_1(n: usize) -> f64 {
    sensitivity_steps(n, [THETA1])
}

pub fn sensitivity_double_pendulum_2(n: usize) -> f64 {
    sensitivity_steps(n, [THETA1, THETA2])
}

pub fn sensitivity_double_pendulum_4(n: usize) -> f64 {
    let (v1, v2) = (Seed::Velocity("theta1"), Seed::Velocity("theta2"));
    sensitivity_steps(n, [THETA1, THETA2, v1, v2])
}

// Seeded on parameters, the lengths (and both with two initial values): the accelerations of the
// lifted model.
const L1: Seed = Seed::Parameter("l1");
const L2: Seed = Seed::Parameter("l2");

pub fn sensitivity_double_pendulum_l1(n: usize) -> f64 {
    sensitivity_steps(n, [L1])
}

pub fn sensitivity_double_pendulum_l1_l2(n: usize) -> f64 {
    sensitivity_steps(n, [L1, L2])
}

pub fn sensitivity_double_pendulum_l1_l2_4(n: usize) -> f64 {
    sensitivity_steps(n, [L1, L2, THETA1, THETA2])
}

/// `n` implicit midpoint steps as a solver takes them: the Newton matrix and the stage predictor
/// kept from step to step (`step_with_memory`).
fn midpoint_steps<M: Evaluate<2>>(sys: &M, s: &mut State<M::Coords>, n: usize) {
    let mut memory = NewtonMemory::<2, 1>::default();
    for _ in 0..n {
        ImplicitMidpoint::step_with_memory(black_box(sys), &mut memory, s, 1e-3).unwrap();
    }
}

/// `n` Gauss–Legendre 2 steps as a solver takes them (see `midpoint_steps`).
fn gl2_steps<M: Evaluate<2>>(sys: &M, s: &mut State<M::Coords>, n: usize) {
    let mut memory = NewtonMemory::<2, 2>::default();
    for _ in 0..n {
        GaussLegendre2::step_with_memory(black_box(sys), &mut memory, s, 1e-3).unwrap();
    }
}

pub fn midpoint_double_pendulum(n: usize) -> f64 {
    let params = DOUBLE_PENDULUM;
    let mut s = double_pendulum_start();
    midpoint_steps(&params, &mut s, n);
    s.q.theta1
}

pub fn gl2_double_pendulum(n: usize) -> f64 {
    let params = DOUBLE_PENDULUM;
    let mut s = double_pendulum_start();
    gl2_steps(&params, &mut s, n);
    s.q.theta1
}

/// Through a validated handle (the closed form's prepared coefficients).
pub fn midpoint_validated_double_pendulum(n: usize) -> f64 {
    let sys = DOUBLE_PENDULUM.validated().unwrap();
    let mut s = double_pendulum_start();
    midpoint_steps(&sys, &mut s, n);
    s.q.theta1
}

/// Through a validated handle (the closed form's prepared coefficients).
pub fn gl2_validated_double_pendulum(n: usize) -> f64 {
    let sys = DOUBLE_PENDULUM.validated().unwrap();
    let mut s = double_pendulum_start();
    gl2_steps(&sys, &mut s, n);
    s.q.theta1
}

// One implicit step per call through `sys.step` (fresh memory: the field's Jacobians by gradient
// duals and a factorisation at every step).

pub fn midpoint_fresh_double_pendulum(n: usize) -> f64 {
    let params = DOUBLE_PENDULUM;
    let mut s = double_pendulum_start();
    for _ in 0..n {
        black_box(&params)
            .step::<ImplicitMidpoint>(&mut s, 1e-3)
            .unwrap();
    }
    s.q.theta1
}

pub fn gl2_fresh_double_pendulum(n: usize) -> f64 {
    let params = DOUBLE_PENDULUM;
    let mut s = double_pendulum_start();
    for _ in 0..n {
        black_box(&params)
            .step::<GaussLegendre2>(&mut s, 1e-3)
            .unwrap();
    }
    s.q.theta1
}

/// One accepted Radau5 step (tolerance 1e-8) per call, from a solver that keeps its memory.
pub fn radau5_double_pendulum(n: usize) -> f64 {
    let sys = DOUBLE_PENDULUM;
    let mut solver = Stepper::new(&sys, Radau5::new(1e-8, 1e-8), &double_pendulum_start()).unwrap();
    for _ in 0..n {
        black_box(&mut solver).step(f64::INFINITY).unwrap();
    }
    solver.state().q.theta1
}
