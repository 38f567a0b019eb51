//! The planar pendulum written in Cartesian coordinates: the bob's (x, y) are the coordinates and a
//! holonomic constraint |r| − L = 0 keeps it on the circle. The rod is no longer absorbed by the
//! choice of coordinates, so its force comes out as a Lagrange multiplier λ; the constraint's
//! gradient is the outward unit vector, so λ is the outward force, minus the rod tension.
//!
//! Closed form: the radial component of Newton's law, m L θ̇² = T − m g cos θ, gives the tension
//!   T = m (g cos θ + L θ̇²)
//! (Taylor, *Classical Mechanics*, §7.10, example 7.9; Goldstein, Poole & Safko, 3rd ed., §2.4,
//! "Lagrange multipliers").
//!
//! ```text
//! cargo run --release --example cartesian_pendulum
//! ```
//!
//! The gallery's scene `lagrange_gallery::scenes::cartesian_pendulum` checks −λ against T, the
//! constraint residuals and the energy over 10⁵ steps, and the motion against the angle form.

use lagrange::constraints::constraint_forces;
use lagrange::prelude::*;
use lagrange_gallery::plot::{self, Series};

use lagrange_gallery::scenes::cartesian_pendulum::cartesian_pendulum;

fn main() -> Result<(), lagrange::Error> {
    use cartesian_pendulum::{CartesianPendulum, Coords, State};
    let (m, l, g) = (1.3, 0.8, 9.81);
    let sys = CartesianPendulum { m, l, g };
    // θ₀ = 1.2 rad from the vertical, swinging at θ̇₀ = 0.5 rad/s: a state on the circle.
    let (th0, w0) = (1.2f64, 0.5f64);
    let mut s = State::new(
        0.0,
        Coords {
            x: l * th0.sin(),
            y: -l * th0.cos(),
        },
        Coords {
            x: l * w0 * th0.cos(),
            y: l * w0 * th0.sin(),
        },
    );
    println!("   t (s)     −λ (N)   m(g cos θ + Lθ̇²) (N)   |r| − L (m)");
    let (mut multiplier, mut tension) = (Vec::new(), Vec::new());
    for step in 1..=5000 {
        // RK4 projected back onto |r| = L and r·ṙ = 0 after every step.
        sys.step::<Rk4>(&mut s, 1e-3)?;
        if step % 25 != 0 {
            continue;
        }
        let (x, y, vx, vy) = (s.q.x, s.q.y, s.v.x, s.v.y);
        let theta = x.atan2(-y);
        let theta_dot = (x * vy - y * vx) / (l * l);
        let closed_form = m * (g * theta.cos() + l * theta_dot * theta_dot);
        let lambda = constraint_forces(&sys, &s)?.multipliers[0];
        multiplier.push((s.t, -lambda));
        tension.push((s.t, closed_form));
        if step % 1000 == 0 {
            let off = x.hypot(y) - l;
            println!(
                "{:8.2} {:10.6} {:20.6} {:15.1e}",
                s.t, -lambda, closed_form, off
            );
        }
    }
    let plots = lagrange_gallery::plots_dir();
    plot::lines(
        &plots.join("cartesian_pendulum_example.svg"),
        "Cartesian pendulum: the multiplier is minus the rod tension",
        "t",
        "N",
        &[
            Series::new("−λ", multiplier),
            Series::new("m(g cos θ + Lθ̇²)", tension),
        ],
    )
    .map_err(|e| eprintln!("{e}"))
    .ok();
    Ok(())
}
