//! Mechanisms in closed form declared once for the test files that check the closed form and its
//! canonical field, and the states both sample.

use lagrange::prelude::*;

/// A pendulum hanging from a cart on a rail.
#[mechanism]
pub mod cart_pendulum {
    pub struct Coords {
        pub x: f64,
        pub theta: f64,
    }
    pub struct CartPendulum {
        pub cart_mass: f64,
        pub m: f64,
        pub l: f64,
        pub g: f64,
    }
    #[particle(mass = cart_mass)]
    fn cart() -> Vec2 {
        vec2(x, 0.0)
    }
    #[particle(mass = m)]
    fn bob() -> Vec2 {
        cart + vec2(theta.sin(), -theta.cos()) * l
    }
    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
}

/// A spherical pendulum in polar and azimuthal angles, and a particle in polar coordinates in the
/// plane z = 0 of the same space: products of a coordinate with sines and cosines, and
/// sin² θ (cos² φ + sin² φ) + cos² θ to simplify; M depends on sin² θ and on r², so ∂T/∂q has both
/// trigonometric and polynomial derivatives.
#[mechanism]
pub mod spherical {
    pub struct Coords {
        pub theta: f64,
        pub phi: f64,
        pub r: f64,
        pub psi: f64,
    }
    pub struct Spherical {
        pub m: f64,
        pub m2: f64,
        pub l: f64,
        pub g: f64,
    }
    #[particle(mass = m)]
    fn bob() -> Vec3 {
        vec3(
            theta.sin() * phi.cos(),
            theta.sin() * phi.sin(),
            -theta.cos(),
        ) * l
    }
    #[particle(mass = m2)]
    fn orbiter() -> Vec3 {
        vec3(r * psi.cos(), r * psi.sin(), 0.0)
    }
    #[gravity]
    fn down() -> Vec3 {
        vec3(0.0, 0.0, -g)
    }
}

/// States spread over the configuration space: angles over several turns, velocities of both
/// signs. The spherical declaration's r = q₂ spans [0.4 − 4, 0.4 + 4]; no sample lands on r = 0,
/// where its M is singular.
pub fn states<const N: usize>() -> impl Iterator<Item = ([f64; N], [f64; N])> {
    (0..25).map(|i| {
        let f = i as f64;
        (
            std::array::from_fn(|j| 0.4 + (0.9 * f + 1.7 * j as f64).sin() * 4.0),
            std::array::from_fn(|j| (1.3 * f - 0.6 * j as f64).cos() * 3.0),
        )
    })
}
