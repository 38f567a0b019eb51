//! Steps (h = 10⁻⁵ s) of Andrews' squeezer, one per call, from the state 20 Gauss–Legendre 2 steps
//! after Hairer & Wanner's start: RK4 (the constrained accelerations and the projection after the
//! step), and Gauss–Legendre 2 as a solver takes it, through a `Stepper`, through `sys.simulate`
//! and through `sys.step`.

use crate::mechanisms::squeezer_model::{self, squeezer};
use lagrange::integrate::{NewtonMemory, Stepper};
use lagrange::prelude::*;
use lagrange::{GaussLegendre2, Integrator};
use std::hint::black_box;

const H: f64 = 1e-5;

/// The squeezer, its state after 20 steps from the start, and the Newton memory those steps left.
fn squeezer_after_20_steps() -> (squeezer::Squeezer, squeezer::State, NewtonMemory<7, 2>) {
    let sys = squeezer_model::ANDREWS;
    let mut s = squeezer_model::start();
    let mut memory = NewtonMemory::<7, 2>::default();
    for _ in 0..20 {
        GaussLegendre2::step_with_memory(&sys, &mut memory, &mut s, H).unwrap();
    }
    (sys, s, memory)
}

/// `sys.step::<Rk4>`.
pub fn rk4_squeezer(n: usize) -> f64 {
    let (sys, mut s, _) = squeezer_after_20_steps();
    for _ in 0..n {
        black_box(&sys).step::<Rk4>(&mut s, H).unwrap();
    }
    s.q.beta
}

/// `sys.simulate::<Rk4>`: n steps in one call.
pub fn rk4_simulate_squeezer(n: usize) -> f64 {
    let (sys, mut s, _) = squeezer_after_20_steps();
    black_box(&sys)
        .simulate::<Rk4>(&mut s, H, n, |_| {})
        .unwrap();
    s.q.beta
}

/// `step_with_memory`, as a solver takes the step: the Newton matrix and the stage predictor kept
/// from step to step (those of the 20 steps before).
pub fn gl2_squeezer(n: usize) -> f64 {
    let (sys, mut s, mut memory) = squeezer_after_20_steps();
    for _ in 0..n {
        GaussLegendre2::step_with_memory(black_box(&sys), &mut memory, &mut s, H).unwrap();
    }
    s.q.beta
}

/// `sys.step::<GaussLegendre2>`: a fresh Newton matrix every step.
pub fn gl2_fresh_squeezer(n: usize) -> f64 {
    let (sys, mut s, _) = squeezer_after_20_steps();
    for _ in 0..n {
        black_box(&sys).step::<GaussLegendre2>(&mut s, H).unwrap();
    }
    s.q.beta
}

/// The documented way to take repeated implicit steps: a `Stepper` (the Newton memory kept, the
/// projection and q̈ at the end of each step for dense output).
pub fn gl2_stepper_squeezer(n: usize) -> f64 {
    let (sys, s, _) = squeezer_after_20_steps();
    let mut solver = Stepper::new(&sys, GaussLegendre2::with_step(H), &s).unwrap();
    for _ in 0..n {
        black_box(&mut solver).step(f64::MAX).unwrap();
    }
    solver.state().q.beta
}

/// `sys.simulate::<GaussLegendre2>` (the memory kept within the call).
pub fn gl2_simulate_squeezer(n: usize) -> f64 {
    let (sys, mut s, _) = squeezer_after_20_steps();
    black_box(&sys)
        .simulate::<GaussLegendre2>(&mut s, H, n, |_| {})
        .unwrap();
    s.q.beta
}
