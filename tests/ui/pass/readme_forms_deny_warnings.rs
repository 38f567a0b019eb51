//! Every declaration form of the README in a crate that denies warnings: the code the macro
//! generates must not warn in its users' crates (an `unused_braces` in a family's `if`, say).
#![deny(warnings)]

use lagrange::prelude::*;

/// A helper outside the module, generic over the scalar, called as `super::sag(..)`.
pub fn sag<D: lagrange::Scalar>(x: D) -> D {
    x * x * 0.01
}

/// Array coordinates, a family of particles written with its index (the README's form), a family
/// of forces, a uniform field, a potential that names time, and helpers inside and outside the
/// module.
#[mechanism]
pub mod chain {
    pub const LINKS: usize = 3;

    pub struct Coords {
        pub theta: [f64; LINKS],
    }

    pub struct Chain {
        pub m: f64,
        pub l: f64,
        pub g: f64,
        pub k: f64,
        pub c: f64,
    }

    fn arm<D: lagrange::Scalar>(angle: D) -> D {
        angle.sin()
    }

    #[particle(mass = m, count = LINKS)]
    fn bob(i: usize) -> Vec2 {
        let link = vec2(arm(theta[i]), -theta[i].cos()) * l;
        if i == 0 {
            link
        } else {
            bob[i - 1] + link
        }
    }

    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }

    /// A spring at the first joint whose stiffness breathes in time.
    #[potential]
    fn spring() -> f64 {
        0.5 * k * (1.0 + super::sag(t)) * theta[0].powi(2)
    }

    /// Drag on every bob.
    #[force(on = bob, count = LINKS)]
    fn drag(i: usize) -> Vec2 {
        -c * bob_dot[i]
    }

}

/// The README's N-link pendulum at a length where its accelerations come from the articulated-body
/// recursion of the tree (each link's displacement a function of its own), with the family's `if`
/// on the index; and a family written without a `let`.
#[mechanism]
pub mod long_chain {
    pub const LINKS: usize = 16;

    pub struct Coords {
        pub theta: [f64; LINKS],
    }

    pub struct Chain {
        pub m: f64,
        pub l: f64,
        pub g: f64,
    }

    #[particle(mass = m, count = LINKS)]
    fn bob(i: usize) -> Vec2 {
        let link = vec2(theta[i].sin(), -theta[i].cos()) * l;
        // On one line, as the README writes it (a branch's braces over several lines are never
        // linted).
        if i == 0 { link } else { bob[i - 1] + link }
    }

    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
}

#[mechanism]
pub mod inline_chain {
    pub const LINKS: usize = 16;

    pub struct Coords {
        pub theta: [f64; LINKS],
    }

    pub struct Chain {
        pub m: f64,
        pub l: f64,
        pub g: f64,
    }

    #[particle(mass = m, count = LINKS)]
    fn bob(i: usize) -> Vec2 {
        if i == 0 { vec2(theta[i].sin(), -theta[i].cos()) * l } else { bob[i - 1] + vec2(theta[i].sin(), -theta[i].cos()) * l }
    }

    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
}

/// Scalar coordinates, a planar rigid body with a torque, a particle and a point, a force on a
/// point and on a body's centre of mass, a generalized force that reads a velocity, a holonomic
/// constraint and a velocity constraint.
#[mechanism]
pub mod disc {
    pub struct Coords {
        pub x: f64,
        pub y: f64,
        pub phi: f64,
    }

    pub struct Disc {
        pub m: f64,
        pub r: f64,
        pub tau: f64,
        pub g: f64,
    }

    #[rigid_body(mass = m, inertia = 0.5 * m * r * r)]
    fn disc() -> Planar {
        planar(vec2(x, y), phi)
    }

    #[particle(mass = 0.5 * m)]
    fn bead() -> Vec2 {
        disc.position + r * vec2(phi.cos(), phi.sin())
    }

    #[point]
    fn rim() -> Vec2 {
        disc.point(vec2(0.0, r))
    }

    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }

    #[torque(on = disc)]
    fn motor() -> f64 {
        tau
    }

    #[force(on = rim)]
    fn pull() -> Vec2 {
        vec2(tau, 0.0) - rim_dot * 0.1
    }

    #[force(on = disc)]
    fn wind() -> Vec2 {
        vec2(0.1 * g, 0.0) - disc_dot.position * 0.2
    }

    /// A brake on the disc's turning.
    #[generalized_force(on = phi)]
    fn brake() -> f64 {
        -0.1 * tau * phi_dot
    }

    /// The disc's centre on the circle of radius 2r.
    #[constraint]
    fn circle() -> f64 {
        disc.position.norm() - 2.0 * r
    }

    /// The disc turns with its centre's speed along x.
    #[velocity_constraint]
    fn turning() -> f64 {
        disc_dot.position.x - r * disc_dot.angle
    }
}

/// A spatial rigid body with principal moments and a world-frame torque, a particle and a point in
/// space, a uniform field in space.
#[mechanism]
pub mod top {
    pub struct Coords {
        pub phi: f64,
        pub theta: f64,
        pub psi: f64,
    }

    pub struct Top {
        pub m: f64,
        pub a: f64,
        pub c: f64,
        pub d: f64,
        pub g: f64,
    }

    #[rigid_body(mass = m, inertia = [a, a, c])]
    fn rotor() -> Spatial {
        let rotation = rot_z(phi) * rot_x(theta) * rot_z(psi);
        spatial(rotation * vec3(0.0, 0.0, d), rotation)
    }

    #[particle(mass = 0.1 * m)]
    fn tip() -> Vec3 {
        rotor.point(vec3(0.0, 0.0, 2.0 * d))
    }

    #[point]
    fn peg() -> Vec3 {
        rotor.point(vec3(d, 0.0, 0.0))
    }

    #[gravity]
    fn down() -> Vec3 {
        vec3(0.0, 0.0, -g)
    }

    #[torque(on = rotor)]
    fn spin_damping() -> Vec3 {
        -rotor_dot.angular * 0.01
    }

    #[force(on = peg)]
    fn nudge() -> Vec3 {
        vec3(0.0, 0.1 * m * g, 0.0) - peg_dot * 0.05
    }
}

/// A unilateral contact with Coulomb friction along one slip velocity.
#[mechanism]
pub mod block {
    pub struct Coords {
        pub x: f64,
        pub y: f64,
    }

    pub struct Block {
        pub m: f64,
        pub g: f64,
        pub mu_k: f64,
        pub mu_s: f64,
    }

    #[particle(mass = m)]
    fn body() -> Vec2 {
        vec2(x, y)
    }

    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }

    #[unilateral]
    fn floor() -> f64 {
        body.y
    }

    #[friction(on = floor, kinetic = mu_k, stiction = mu_s)]
    fn rub() -> f64 {
        body_dot.x
    }
}

/// Friction in a contact's tangent plane (the friction cone).
#[mechanism]
pub mod puck {
    pub struct Coords {
        pub x: f64,
        pub y: f64,
        pub z: f64,
    }

    pub struct Puck {
        pub m: f64,
        pub g: f64,
        pub mu: f64,
    }

    #[particle(mass = m)]
    fn body() -> Vec3 {
        vec3(x, y, z)
    }

    #[gravity]
    fn down() -> Vec3 {
        vec3(0.0, 0.0, -g)
    }

    #[unilateral]
    fn plane() -> f64 {
        body.z
    }

    #[friction(on = plane, kinetic = mu, stiction = mu)]
    fn rub() -> Vec2 {
        vec2(body_dot.x, body_dot.y)
    }
}

fn main() -> Result<(), lagrange::Error> {
    let chain = chain::Chain {
        m: 1.0,
        l: 1.0,
        g: 9.81,
        k: 2.0,
        c: 0.1,
    };
    let s = chain::State::new(
        0.0,
        chain::Coords {
            theta: [0.1, 0.2, 0.3],
        },
        chain::Coords {
            theta: [0.0, 0.1, 0.0],
        },
    );
    chain.accelerations(&s)?;
    let s = long_chain::State::at_rest(long_chain::Coords { theta: [0.1; 16] });
    long_chain::Chain { m: 1.0, l: 0.5, g: 9.81 }.accelerations(&s)?;
    let s = inline_chain::State::at_rest(inline_chain::Coords { theta: [0.1; 16] });
    inline_chain::Chain { m: 1.0, l: 0.5, g: 9.81 }.accelerations(&s)?;
    let disc = disc::Disc {
        m: 1.0,
        r: 0.5,
        tau: 0.2,
        g: 9.81,
    };
    let s = disc::State::new(
        0.0,
        disc::Coords {
            x: 1.0,
            y: 0.0,
            phi: 0.0,
        },
        disc::Coords {
            x: 0.0,
            y: 0.0,
            phi: 0.0,
        },
    );
    disc.accelerations(&s)?;
    let top = top::Top {
        m: 1.0,
        a: 0.02,
        c: 0.04,
        d: 0.1,
        g: 9.81,
    };
    let s = top::State::new(
        0.0,
        top::Coords {
            phi: 0.0,
            theta: 0.3,
            psi: 0.0,
        },
        top::Coords {
            phi: 0.1,
            theta: 0.0,
            psi: 20.0,
        },
    );
    top.accelerations(&s)?;
    let block = block::Block {
        m: 1.0,
        g: 9.81,
        mu_k: 0.3,
        mu_s: 0.4,
    };
    block.accelerations(&block::State::at_rest(block::Coords { x: 0.0, y: 0.0 }))?;
    let puck = puck::Puck {
        m: 1.0,
        g: 9.81,
        mu: 0.3,
    };
    let s = puck::State::new(
        0.0,
        puck::Coords {
            x: 0.0,
            y: 0.0,
            z: 0.0,
        },
        puck::Coords {
            x: 1.0,
            y: 0.5,
            z: 0.0,
        },
    );
    puck.accelerations(&s)?;
    Ok(())
}
