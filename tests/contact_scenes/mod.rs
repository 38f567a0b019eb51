//! Contact mechanisms several contact tests share (the unilateral sphere is the gallery's
//! `sphere_release`), with the sphere's parameters, its starts, and its release located on the
//! bilateral declaration's multiplier.
#![allow(dead_code)]

use lagrange::constraints::constraint_forces;
use lagrange::integrate::{Direction, Event, Outcome, Stats, StopReason};
use lagrange::prelude::*;
use lagrange_gallery::scenes::sphere_release::Release;

/// The particle's mass on the sphere.
pub const M: f64 = 0.7;
/// The sphere's radius.
pub const R: f64 = 1.5;
/// Gravity, in every contact scene.
pub const G: f64 = 9.81;

/// Where the particle starts (at angle θ₀ from the top, with speed v₀ along the sphere), with the
/// closed form of its release: the gallery's `sphere_release::Release`.
pub type Start = Release;

/// A start on this sphere (radius R, gravity G).
pub const fn on_sphere(theta0: f64, v0: f64) -> Start {
    Release {
        r: R,
        g: G,
        theta0,
        v0,
    }
}

/// Released at rest near the top (cos θ* = ⅔ cos θ₀), and from the top at two speeds.
pub const STARTS: [Start; 3] = [
    on_sphere(0.1, 0.0),
    on_sphere(0.0, 0.5),
    on_sphere(0.0, 1.2),
];

/// The bilateral sphere from `start`, integrated by `integrate` (an adaptive method to t = 10 with
/// the events given) and stopped where its multiplier falls through 0: the release time and the
/// cost.
pub fn bilateral_release_in(
    start: Start,
    integrate: impl FnOnce(
        &bilateral::Sphere,
        &mut bilateral::State,
        &mut [Event<'_, bilateral::Coords>],
    ) -> lagrange::Result<Outcome<bilateral::Coords>>,
) -> (f64, Stats) {
    use bilateral::{Coords, Sphere, State};
    let sys = Sphere { m: M, r: R, g: G };
    let ([x, y], [vx, vy]) = start.state();
    let mut s = State::new(0.0, Coords { x, y }, Coords { x: vx, y: vy });
    let normal = |s: &State| constraint_forces(&sys, s).expect("forces").multipliers[0];
    let mut events = [Event::new(&normal).direction(Direction::Falling).terminal()];
    let outcome = integrate(&sys, &mut s, &mut events).expect("integration");
    let StopReason::Event(hit) = outcome.reason else {
        panic!("the particle did not leave: {:?}", outcome.reason)
    };
    (hit.state.t, outcome.stats)
}

/// The sphere of the gallery's `sphere_release` as a bilateral constraint: its multiplier is the
/// normal force it would need.
#[mechanism]
pub mod bilateral {
    pub struct Coords {
        pub x: f64,
        pub y: f64,
    }

    pub struct Sphere {
        pub m: f64,
        pub r: f64,
        pub g: f64,
    }

    #[particle(mass = m)]
    fn particle() -> Vec2 {
        vec2(x, y)
    }

    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }

    #[constraint]
    fn surface() -> f64 {
        particle.norm() - r
    }
}

/// A ball above a floor y ≥ 0.
#[mechanism]
pub mod ball {
    pub struct Coords {
        pub x: f64,
        pub y: f64,
    }

    pub struct Ball {
        pub m: f64,
        pub g: f64,
    }

    #[particle(mass = m)]
    fn ball() -> Vec2 {
        vec2(x, y)
    }

    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }

    #[unilateral]
    fn floor() -> f64 {
        y
    }
}
