//! A block (a point mass) sent up a rough ramp fixed at angle α, with Coulomb friction: kinetic μₖ
//! while it slides, static μₛ ≥ μₖ while it sticks. The block is free in the plane, (x, y); the
//! ramp is a unilateral contact (it pushes along its normal and cannot pull), and friction acts on
//! that contact against the slip velocity along the ramp.
//!
//! Closed form (Kleppner & Kolenkow, 2nd ed., §3.x, the block on a rough incline): the normal force
//! is N = m g cos α; sent up with speed u, the block decelerates at g (sin α + μₖ cos α), stops at
//!   t_s = u / (g (sin α + μₖ cos α))  after  d_s = u² / (2 g (sin α + μₖ cos α)),
//! and then sticks if tan α ≤ μₛ, or slides back with a = g (sin α − μₖ cos α).
//! The solver holds the contact mode over each step, locates the stop and decides stick or slide
//! once: one mode change, no chattering.
//!
//! ```text
//! cargo run --release --example rough_ramp
//! ```
//!
//! The gallery's scene `lagrange_gallery::scenes::rough_ramp` checks the stop time, the motion, the
//! normal and friction forces and the mode changes against the closed form.

use lagrange::prelude::*;
use lagrange_gallery::plot::{self, Series};

use lagrange_gallery::scenes::rough_ramp::rough_ramp;

fn main() -> Result<(), lagrange::Error> {
    use rough_ramp::{Coords, RoughRamp, State};
    let (g, alpha, u) = (9.81, 0.5f64, 2.0); // tan α = 0.546
    let (sn, cs) = alpha.sin_cos();
    let mut series = Vec::new();
    // μₛ above tan α: it sticks where it stops; below: it slides back.
    for (mu_k, mu_s) in [(0.5, 0.6), (0.2, 0.3)] {
        let sys = RoughRamp {
            m: 2.0,
            alpha,
            g,
            mu_k,
            mu_s,
        };
        let mut s = State::new(
            0.0,
            Coords { x: 0.0, y: 0.0 },
            Coords {
                x: u * cs,
                y: u * sn,
            },
        );
        let mut stepper = Stepper::new(&sys, Rk4::with_step(1e-3), &s)?;
        let mut climb = vec![(0.0, 0.0)];
        for _ in 0..3000 {
            stepper.step(f64::INFINITY)?;
            s = stepper.state();
            climb.push((s.t, s.q.x * cs + s.q.y * sn));
        }
        let up = g * (sn + mu_k * cs);
        println!("μₖ = {mu_k}, μₛ = {mu_s}:");
        for event in stepper.mode_changes() {
            println!(
                "  t = {:.12} s: `{}` {:?} → {:?}  (closed-form stop u/(g(sin α + μₖ cos α)) = {:.12} s)",
                event.t, event.constraint, event.from, event.to, u / up
            );
        }
        let d_stop = u * u / (2.0 * up);
        let t_back = s.t - u / up;
        let closed_form = if mu_s >= alpha.tan() {
            d_stop
        } else {
            d_stop - 0.5 * g * (sn - mu_k * cs) * t_back * t_back
        };
        println!(
            "  at t = {:.1} s: {:.12} m up the ramp (closed form {closed_form:.12} m)",
            s.t,
            s.q.x * cs + s.q.y * sn
        );
        series.push(Series::new(format!("μₛ = {mu_s}"), climb));
    }
    let plots = lagrange_gallery::plots_dir();
    plot::lines(
        &plots.join("rough_ramp_example.svg"),
        "Block sent up a rough ramp (tan α = 0.55): stops, then sticks or slides back",
        "t",
        "distance up the ramp",
        &series,
    )
    .map_err(|e| eprintln!("{e}"))
    .ok();
    Ok(())
}
