//! Steps of the gallery's block pushed along a rough incline (a unilateral contact and a friction
//! cone, the contact mode held over the step), one per call, through a validated handle.

use lagrange::prelude::*;
use lagrange_gallery::scenes::pushed_block::pushed_block::{Coords, PushedBlock};
use std::hint::black_box;

/// The block (m = 2, α = 0.3, μ_k = 0.4, μ_s = 0.5, push 12) at rest at the origin.
fn pushed_block() -> (Validated<PushedBlock>, State<Coords>) {
    let sys = PushedBlock {
        m: 2.0,
        g: 9.81,
        alpha: 0.3,
        mu_k: 0.4,
        mu_s: 0.5,
        push: 12.0,
    }
    .validated()
    .unwrap();
    let s = State::at_rest(Coords {
        x: 0.0,
        y: 0.0,
        z: 0.0,
    });
    (sys, s)
}

/// `sys.step::<Rk4>` (h = 10⁻³): the contact mode inferred at every call.
pub fn rk4_pushed_block(n: usize) -> f64 {
    let (sys, mut s) = pushed_block();
    for _ in 0..n {
        black_box(&sys).step::<Rk4>(&mut s, 1e-3).unwrap();
    }
    s.q.x
}

/// An accepted step of a Dopri5 `Stepper` (the mode held across steps) up to the next 10⁻² of time.
pub fn dopri5_pushed_block(n: usize) -> f64 {
    let (sys, s) = pushed_block();
    let mut stepper = Stepper::new(&sys, Dopri5::default(), &s).unwrap();
    for i in 0..n {
        stepper.step(1e-2 * (i + 1) as f64).unwrap();
    }
    stepper.state().q.x
}
