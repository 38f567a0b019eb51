//! A puck slides on a rough horizontal plane while a constant sideways push acts on it: friction in
//! the plane's two tangent directions (a `#[friction]` with a `Vec2` slip velocity, the Coulomb
//! cone) slows it along its slip direction, the path curves towards the push, and the puck stops and
//! sticks, because the push is below μₛ m g.
//!
//! ```text
//! cargo run --release --example rough_plane
//! ```
//!
//! The gallery's scene `lagrange_gallery::scenes::rough_plane` checks the stop time and point
//! against the closed form t_s = v₀ μₖg/((μₖg)² − a²), a = F/m.

use lagrange::prelude::*;
use lagrange_gallery::plot::{self, Series};

use lagrange_gallery::scenes::rough_plane::rough_plane;

fn main() -> Result<(), lagrange::Error> {
    use rough_plane::{Coords, RoughPlane, State};
    let sys = RoughPlane {
        m: 1.5,
        g: 9.81,
        mu_k: 0.5,
        mu_s: 0.6,
        push: 3.0,
    };
    let mut s = State::new(
        0.0,
        Coords {
            x: 0.0,
            y: 0.0,
            z: 0.0,
        },
        Coords {
            x: 3.0,
            y: 0.0,
            z: 0.0,
        },
    );
    // The solver locates the instant the slip stops, then decides stick or slide once.
    let mut stepper = Stepper::new(&sys, Rk4::with_step(1e-3), &s)?;
    let mut path = vec![(0.0, 0.0)];
    for _ in 0..1000 {
        stepper.step(f64::INFINITY)?;
        s = stepper.state();
        path.push((s.q.x, s.q.y));
    }
    for event in stepper.mode_changes() {
        println!(
            "t = {:.6} s: `{}` {:?} → {:?}",
            event.t, event.constraint, event.from, event.to
        );
    }
    println!("at rest at ({:.6}, {:.6}) m", s.q.x, s.q.y);
    let plots = lagrange_gallery::plots_dir();
    plot::lines(
        &plots.join("rough_plane_example.svg"),
        "Puck on a rough plane, pushed sideways",
        "x",
        "y",
        &[Series::new("path", path)],
    )
    .map_err(|e| eprintln!("{e}"))
    .ok();
    Ok(())
}
