//! A block on a fixed frictionless ramp (the lecture's example 1): one coordinate, the distance s
//! down the ramp; the constraint force is normal to the ramp, does no virtual work, and drops out.
//! Closed form: s̈ = g sin α, so s(t) = v₀ t + ½ g sin α t².

use crate::page::outline;
use crate::Check;
use lagrange::animation::Recorder;
use lagrange::prelude::*;
use std::path::Path;

#[mechanism]
pub mod ramp {
    /// Distance down the ramp.
    pub struct Coords {
        pub s: f64,
    }

    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct Ramp {
        pub m: f64,
        pub alpha: f64,
        pub g: f64,
    }

    #[particle(mass = m)]
    fn block() -> Vec2 {
        vec2(alpha.cos(), -alpha.sin()) * s
    }

    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
}

const SCENE: &str = "block on a ramp";

pub fn run(plots: &Path) -> Vec<Check> {
    use ramp::{Coords, Ramp, State};
    let sys = Ramp {
        m: 2.0,
        alpha: 0.6,
        g: 9.81,
    };
    let v0 = -1.5; // pushed up the ramp
    let mut s = State::new(0.0, Coords { s: 0.0 }, Coords { s: v0 });
    let acc = sys.accelerations(&s).expect("accelerations").s;
    let e0 = sys.energy(&s).expect("energy");
    let mut film = Recorder::new(&sys).title(SCENE);
    let (cos, sin) = (sys.alpha.cos(), sys.alpha.sin());
    outline(
        &mut film,
        "ramp",
        &[&[-0.5 * cos, 0.5 * sin], &[1.5 * cos, -1.5 * sin]],
        false,
    )
    .expect("the ramp");
    film.push(&sys, &s).expect("a finite state");
    sys.simulate::<Rk4>(&mut s, 1e-3, 1000, film.observer(&sys))
        .expect("simulation");
    let _ = film.write_html(plots.join("ramp.html"));
    let t = s.t;
    let exact = v0 * t + 0.5 * sys.g * sys.alpha.sin() * t * t;
    // Quadratic motion: RK4 is exact up to round-off accumulated over 1000 steps (≲ 1e-13).
    vec![
        Check::new(
            SCENE,
            "acceleration s̈ = g sin α",
            acc,
            sys.g * sys.alpha.sin(),
            1e-14,
        ),
        Check::new(
            SCENE,
            format!("s(t = {t:.0}) pushed up at {v0} m/s"),
            s.q.s,
            exact,
            1e-12,
        ),
        Check::new(
            SCENE,
            "energy T + V at the end (conserved)",
            sys.energy(&s).expect("energy"),
            e0,
            1e-12,
        ),
    ]
}
