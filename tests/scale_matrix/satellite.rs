//! A satellite in polar coordinates about a fixed centre: M = diag(m, m r²), the declaration a
//! pivot test comparing the two diagonal entries refused in SI units.

use lagrange::prelude::*;

#[mechanism]
pub mod kepler_polar {
    pub struct Coords {
        pub r: f64,
        pub phi: f64,
    }

    pub struct KeplerPolar {
        pub m: f64,
        /// The centre's gravitational parameter GM.
        pub gm: f64,
    }

    #[particle(mass = m)]
    fn planet() -> Vec2 {
        vec2(phi.cos(), phi.sin()) * r
    }

    #[potential]
    fn gravitation() -> f64 {
        -gm * m / r
    }
}
