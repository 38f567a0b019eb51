//! Contact mechanisms several contact tests share (the unilateral sphere is the gallery's
//! `sphere_release`).
#![allow(dead_code)]

use lagrange::prelude::*;

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
