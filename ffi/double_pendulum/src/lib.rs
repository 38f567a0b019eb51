//! The double pendulum as a C library: `#[mechanism]` declares it, `lagrange::export_c!` writes
//! its C functions (`dp_create`, `dp_step`, …). The header `double_pendulum.h` next to this crate
//! is `dp::header()`, checked by `tests/c_program.rs`, which also compiles
//! and runs `main.c` against the library.
//!
//! ```
//! use double_pendulum_ffi::dp;
//! use lagrange::ffi::Export;
//! assert!(dp::header().contains("#define DP_DOF 2"));
//! ```

use lagrange::prelude::*;

/// Two point masses on massless rods, in the plane, under gravity, a motor at each joint.
#[mechanism]
pub mod double_pendulum {
    /// The angles of the rods from the downward vertical.
    pub struct Coords {
        pub theta1: f64,
        pub theta2: f64,
    }

    /// Masses, rod lengths, gravity.
    pub struct DoublePendulum {
        pub m1: f64,
        pub m2: f64,
        pub l1: f64,
        pub l2: f64,
        pub g: f64,
    }

    /// The motors' torques: the shoulder's turns rod 1 against the ground, the elbow's rod 2
    /// against rod 1.
    #[inputs]
    pub struct Torques {
        pub tau1: f64,
        pub tau2: f64,
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

    /// The angles are absolute, so the elbow's torque, which turns θ₂ − θ₁, acts on θ₂ and
    /// reacts on θ₁: its virtual work is τ₂ δ(θ₂ − θ₁).
    #[generalized_force(on = theta1)]
    fn shoulder() -> f64 {
        tau1 - tau2
    }

    #[generalized_force(on = theta2)]
    fn elbow() -> f64 {
        tau2
    }
}

lagrange::export_c!(double_pendulum::DoublePendulum, prefix = dp);
