//! The mechanisms the modes evaluate: the models shared with the benches, the tests and the
//! work-precision report (their files re-declared here), and those declared in this file. The
//! constrained ones of the gallery's scenes are taken from `lagrange_gallery::scenes`.

use lagrange::prelude::*;

// The constrained mechanisms' KKT systems written out by hand, as in the accelerations benchmark.
#[path = "../../../benches/common/constrained.rs"]
#[allow(dead_code)]
pub mod constrained;
// The N-link chains declared link by link, as in the chain benchmark.
#[path = "../../../benches/chains/mod.rs"]
#[allow(dead_code)]
pub mod chains;
// The FPU chain of the work-precision report, each spring a potential of its own, and its forces
// written by hand.
#[path = "../../../lagrange-bench/src/fpu.rs"]
pub mod fpu_report;
pub use fpu_report::{fpu_chain, fpu_forces};
// Andrews' squeezer (seven bodies, six closure rows), the tests' reference problem.
#[path = "../../../tests/common/squeezer.rs"]
#[allow(dead_code)]
pub mod squeezer_model;
// Kepler's problem of the work-precision report, and its accelerations written by hand.
#[path = "../../../lagrange-bench/src/kepler.rs"]
pub mod kepler_report;
pub use kepler_report::{kepler, kepler_rhs, KEPLER};
// A three-link spatial arm declared by its joint frames (centres of mass, full inertia tensors)
// and by its principal axes, as in tests/body_frames.rs.
#[path = "../../../tests/common/framed_arms.rs"]
#[allow(dead_code)]
pub mod framed_arms;

#[mechanism]
pub mod pendulum {
    pub struct Coords {
        pub theta: f64,
    }
    pub struct Pendulum {
        pub m: f64,
        pub l: f64,
        pub g: f64,
    }
    #[particle(mass = m)]
    fn bob() -> Vec2 {
        vec2(theta.sin(), -theta.cos()) * l
    }
    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
}

/// The pendulum the modes on it take.
pub const PENDULUM: pendulum::Pendulum = pendulum::Pendulum {
    m: 1.0,
    l: 0.8,
    g: 9.81,
};

#[mechanism]
pub mod double_pendulum {
    pub struct Coords {
        pub theta1: f64,
        pub theta2: f64,
    }
    pub struct DoublePendulum {
        pub m1: f64,
        pub m2: f64,
        pub l1: f64,
        pub l2: f64,
        pub g: f64,
    }
    #[particle(mass = m1)]
    fn bob1() -> Vec2 {
        vec2(theta1.sin(), -theta1.cos()) * l1
    }
    #[particle(mass = m2)]
    fn bob2() -> Vec2 {
        bob1 + vec2(theta2.sin(), -theta2.cos()) * l2
    }
    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
}

/// The double pendulum every mode that evaluates it takes: its parameters and its start.
pub const DOUBLE_PENDULUM: double_pendulum::DoublePendulum = double_pendulum::DoublePendulum {
    m1: 1.0,
    m2: 1.3,
    l1: 1.0,
    l2: 0.8,
    g: 9.81,
};

pub fn double_pendulum_start() -> double_pendulum::State {
    use double_pendulum::{Coords, State};
    State::new(
        0.0,
        Coords {
            theta1: 0.7,
            theta2: -1.2,
        },
        Coords {
            theta1: 1.1,
            theta2: -0.4,
        },
    )
}

#[mechanism]
pub mod wedge_block {
    pub struct Coords {
        pub x: f64,
        pub d: f64,
    }
    pub struct WedgeBlock {
        pub wedge_mass: f64,
        pub block_mass: f64,
        pub alpha: f64,
        pub h: f64,
        pub g: f64,
    }
    #[particle(mass = wedge_mass)]
    fn wedge() -> Vec2 {
        vec2(x, 0.0)
    }
    #[particle(mass = block_mass)]
    fn block() -> Vec2 {
        vec2(x + d * alpha.cos(), h - d * alpha.sin())
    }
    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
}

/// The wedge and block the modes on it take.
pub const WEDGE_BLOCK: wedge_block::WedgeBlock = wedge_block::WedgeBlock {
    wedge_mass: 3.0,
    block_mass: 1.0,
    alpha: 0.5,
    h: 1.0,
    g: 9.81,
};

/// The FPU chain of the work-precision report (`fpu_report`) with its potential written as one sum
/// instead of spring by spring: the mode `fpu` counts the macro's term-by-term reading of a sum
/// against the declaration of the report (`fpu_springs`).
#[mechanism]
pub mod fpu {
    pub const MASSES: usize = 6;
    pub struct Coords {
        pub q: [f64; MASSES],
    }
    pub struct Fpu {
        pub m: f64,
        pub omega: f64,
    }
    #[particle(mass = m, count = MASSES)]
    fn mass(i: usize) -> Vec2 {
        vec2(q[i], 0.0)
    }
    #[potential]
    fn springs() -> f64 {
        let (s1, s2, s3) = (q[1] - q[0], q[3] - q[2], q[5] - q[4]);
        let (w1, w2) = (q[2] - q[1], q[4] - q[3]);
        omega * omega / 4.0 * (s1 * s1 + s2 * s2 + s3 * s3)
            + q[0].powi(4)
            + w1.powi(4)
            + w2.powi(4)
            + q[5].powi(4)
    }
}

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

/// The cart pendulum the modes on it take.
pub const CART_PENDULUM: cart_pendulum::CartPendulum = cart_pendulum::CartPendulum {
    cart_mass: 2.0,
    m: 1.0,
    l: 0.8,
    g: 9.81,
};

/// The 32-link chain as a family (`count = LINKS`, each bob on the one before), against
/// `chains::chain32` declared link by link.
#[mechanism]
pub mod chain32 {
    pub const LINKS: usize = 32;
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
}

/// The pendulum with linear drag on the bob: a velocity-dependent force.
#[mechanism]
pub mod drag {
    pub struct Coords {
        pub theta: f64,
    }
    pub struct Drag {
        pub m: f64,
        pub l: f64,
        pub g: f64,
        pub c: f64,
    }
    #[particle(mass = m)]
    fn bob() -> Vec2 {
        vec2(theta.sin(), -theta.cos()) * l
    }
    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
    #[force(on = bob)]
    fn air() -> Vec2 {
        bob_dot * (-c)
    }
}

/// The pendulum on a support oscillating horizontally, a cos(w t): a rheonomic position.
#[mechanism]
pub mod driven {
    pub struct Coords {
        pub theta: f64,
    }
    pub struct Driven {
        pub m: f64,
        pub l: f64,
        pub g: f64,
        pub a: f64,
        pub w: f64,
    }
    #[particle(mass = m)]
    fn bob() -> Vec2 {
        vec2(a * (w * t).cos() + l * theta.sin(), -l * theta.cos())
    }
    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
}
