//! An Atwood machine with a massive pulley: masses m₁ and m₂ hang from an inextensible rope over a
//! pulley of radius r and moment of inertia I that turns without the rope slipping. One coordinate,
//! the descent y of m₁; the pulley turns by −y/r. Closed form (Kleppner & Kolenkow, 2nd ed., §7.x):
//!   ÿ = (m₁ − m₂) g / (m₁ + m₂ + I/r²).

use crate::Check;
use lagrange::animation::Recorder;
use lagrange::prelude::*;
use std::path::Path;

#[mechanism]
pub mod atwood {
    /// Descent of the first mass.
    pub struct Coords {
        pub y: f64,
    }

    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct Atwood {
        pub m1: f64,
        pub m2: f64,
        pub pulley_mass: f64,
        pub pulley_inertia: f64,
        pub r: f64,
        pub g: f64,
    }

    #[particle(mass = m1)]
    fn left() -> Vec2 {
        vec2(-r, -1.0 - y)
    }

    #[particle(mass = m2)]
    fn right() -> Vec2 {
        vec2(r, -1.0 + y)
    }

    #[rigid_body(mass = pulley_mass, inertia = pulley_inertia)]
    fn pulley() -> Planar {
        planar(vec2(0.0, 0.0), -y / r)
    }

    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
}

const SCENE: &str = "Atwood machine, massive pulley";

pub fn run(plots: &Path) -> Vec<Check> {
    use atwood::{Atwood, Coords, State};
    let sys = Atwood {
        m1: 3.0,
        m2: 2.0,
        pulley_mass: 1.5,
        pulley_inertia: 0.5 * 1.5 * 0.2 * 0.2,
        r: 0.2,
        g: 9.81,
    };
    let exact =
        (sys.m1 - sys.m2) * sys.g / (sys.m1 + sys.m2 + sys.pulley_inertia / (sys.r * sys.r));
    let mut s = State::at_rest(Coords { y: 0.0 });
    let acc = sys.accelerations(&s).expect("accelerations").y;
    // The rope leaves the pulley at (±r, 0); a mark on the rim shows the pulley turn.
    let mut film = Recorder::new(&sys).title(SCENE);
    film.fixed_point("rope left", &[-sys.r, 0.0])
        .and_then(|f| {
            f.fixed_point("rope right", &[sys.r, 0.0])?
                .link("rope left", "left")
        })
        .and_then(|f| {
            f.link("rope right", "right")?
                .mark("rim", "pulley", &[sys.r, 0.0])
        })
        .expect("the rope");
    film.push(&sys, &s).expect("a finite state");
    sys.simulate::<Rk4>(&mut s, 1e-3, 1000, film.observer(&sys))
        .expect("simulation");
    let _ = film.write_html(plots.join("atwood.html"));
    let t = s.t;
    vec![
        Check::new(
            SCENE,
            "ÿ = (m₁ − m₂)g / (m₁ + m₂ + I/r²)",
            acc,
            exact,
            1e-14,
        ),
        // Constant acceleration: RK4 is exact up to round-off over 1000 steps.
        Check::new(
            SCENE,
            format!("y(t = {t:.0})"),
            s.q.y,
            0.5 * exact * t * t,
            1e-12,
        ),
    ]
}
