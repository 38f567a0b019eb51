//! Kepler's problem, a planet in the plane about a fixed centre, V = −μ m/|r|, declared with
//! `#[mechanism]` (the macro derives the potential's gradient on its expression tree); with
//! GM = μ = 1 and m = 1 its accelerations are those of [`kepler_rhs`], written by hand for the
//! peer solvers. The callgrind driver (`scripts/callgrind/`) compiles this file as
//! well, so the report and the instruction counts measure one declaration.

use lagrange::prelude::*;

#[mechanism]
pub mod kepler {
    /// The planet's Cartesian position.
    pub struct Coords {
        pub x: f64,
        pub y: f64,
    }

    #[derive(Clone, Copy, Debug)]
    pub struct Kepler {
        /// The planet's mass.
        pub m: f64,
        /// The centre's gravitational parameter GM.
        pub mu: f64,
    }

    #[particle(mass = m)]
    fn planet() -> Vec2 {
        vec2(x, y)
    }

    /// Newton's gravitation, −μ m/|r|.
    #[potential]
    fn gravitation() -> f64 {
        -mu * m / planet.norm()
    }
}

/// GM = 1, unit mass.
pub const KEPLER: kepler::Kepler = kepler::Kepler { m: 1.0, mu: 1.0 };

/// q̈ = −q/|q|³ (GM = 1), by hand: the peers' right-hand side.
pub fn kepler_rhs(_t: f64, q: &[f64; 2], _v: &[f64; 2]) -> [f64; 2] {
    let r2 = q[0] * q[0] + q[1] * q[1];
    let r3 = r2 * r2.sqrt();
    [-q[0] / r3, -q[1] / r3]
}
