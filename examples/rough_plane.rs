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

use lagrange::constraints::{ContactOptions, ContactRk4};
use lagrange::prelude::*;
use lagrange_gallery::plot::{self, Series};

#[mechanism]
pub mod rough_plane {
    pub struct Coords {
        pub x: f64,
        pub y: f64,
        pub z: f64,
    }

    pub struct RoughPlane {
        pub m: f64,
        pub g: f64,
        pub mu_k: f64,
        pub mu_s: f64,
        pub push: f64,
    }

    #[particle(mass = m)]
    fn puck() -> Vec3 {
        vec3(x, y, z)
    }

    #[gravity]
    fn down() -> Vec3 {
        vec3(0.0, 0.0, -g)
    }

    #[force(on = puck)]
    fn sideways() -> Vec3 {
        vec3(0.0, push, 0.0)
    }

    /// The plane z = 0 pushes up and cannot pull.
    #[unilateral]
    fn plane() -> f64 {
        puck.z
    }

    /// Friction in the plane: the slip velocity's components along x and y.
    #[friction(on = plane, kinetic = mu_k, stiction = mu_s)]
    fn rub() -> Vec2 {
        vec2(puck_dot.x, puck_dot.y)
    }
}

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
    // ContactRk4 locates the instant the slip stops, then decides stick or slide once.
    let mut stepper = ContactRk4::new(&sys, &s, ContactOptions::default())?;
    let mut path = vec![(0.0, 0.0)];
    for _ in 0..1000 {
        stepper.step(&sys, &mut s, 1e-3)?;
        path.push((s.q.x, s.q.y));
    }
    for event in &stepper.events {
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
