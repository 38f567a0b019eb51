//! The five robots read from their URDF files by `#[lagrange::urdf]` against the declarations
//! written from the same tables (`src/`, checked against Pinocchio by `pinocchio.rs`): both take
//! the rigid tree pass (the generated `RigidTree` impls), and q̈, τ and M agree at random states.
//!
//! Tolerance: the two declarations hold the same literals and are expanded into the same
//! recursions, so they can differ only where the file's text is turned into numbers (the same
//! `f64` parsing on both sides) — observed equal to the last bit; 1e-12 of the result's size
//! allows for a different association of a few operations while catching any wrong term
//! (a wrong inertia, offset or axis changes the result at 1e-3 or more).

use lagrange::evaluation::Dynamics;
use lagrange::prelude::*;
use lagrange::tree::rigid::RigidTree;

#[lagrange::urdf("../../scripts/peers/robots/arm3.urdf")]
pub mod arm3 {}
#[lagrange::urdf("../../scripts/peers/robots/arm7.urdf")]
pub mod arm7 {}
#[lagrange::urdf("../../scripts/peers/robots/arm14.urdf")]
pub mod arm14 {}
#[lagrange::urdf("../../scripts/peers/robots/quadruped.urdf")]
pub mod quadruped {}
#[lagrange::urdf("../../scripts/peers/robots/humanoid.urdf")]
pub mod humanoid {}

mod common;

const TOLERANCE: f64 = 1e-12;

/// Random states, the same every run (a linear congruential sequence in [−1, 1)).
fn states<const N: usize>(count: usize) -> Vec<[[f64; N]; 3]> {
    let mut seed: u64 = 0x9e37_79b9_7f4a_7c15;
    let mut next = move || {
        seed = seed
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (seed >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    };
    (0..count)
        .map(|_| std::array::from_fn(|k| std::array::from_fn(|_| [3.0, 2.0, 5.0][k] * next())))
        .collect()
}

fn assert_close(what: &str, x: &[f64], expected: &[f64]) {
    common::assert_close(what, x, expected, TOLERANCE);
}

fn same_dynamics<A: Dynamics<N>, B: Dynamics<N>, const N: usize>(a: A, b: B, robot: &str) {
    let (a, b) = (a.validated().unwrap(), b.validated().unwrap());
    for [q, v, qdd] in states::<N>(3) {
        let sa = State::new(0.0, A::Coords::from_array(q), A::Coords::from_array(v));
        let sb = State::new(0.0, B::Coords::from_array(q), B::Coords::from_array(v));
        let (x, y) = (a.accelerations(&sa).unwrap(), b.accelerations(&sb).unwrap());
        assert_close(&format!("{robot} q̈"), &x.to_array(), &y.to_array());
        let x = a
            .inverse_dynamics(&sa, &A::Coords::from_array(qdd))
            .unwrap();
        let y = b
            .inverse_dynamics(&sb, &B::Coords::from_array(qdd))
            .unwrap();
        assert_close(&format!("{robot} τ"), &x.to_array(), &y.to_array());
        let (x, y) = (a.mass_matrix(&sa).unwrap(), b.mass_matrix(&sb).unwrap());
        assert_close(&format!("{robot} M"), x.as_slice(), y.as_slice());
    }
}

#[test]
fn arm3_from_its_file_equals_its_declaration() {
    assert_eq!(<arm3::Arm3 as RigidTree<3, 3>>::JOINTS.len(), 3);
    same_dynamics(
        arm3::Arm3::default(),
        lagrange_robots::arm3::Arm3 { g: 9.81 },
        "arm3",
    );
}

#[test]
fn arm7_from_its_file_equals_its_declaration() {
    assert_eq!(<arm7::Arm7 as RigidTree<7, 7>>::JOINTS.len(), 7);
    same_dynamics(
        arm7::Arm7::default(),
        lagrange_robots::arm7::Arm7 { g: 9.81 },
        "arm7",
    );
}

#[test]
fn arm14_from_its_file_equals_its_declaration() {
    assert_eq!(<arm14::Arm14 as RigidTree<14, 14>>::JOINTS.len(), 14);
    same_dynamics(
        arm14::Arm14::default(),
        lagrange_robots::arm14::Arm14 { g: 9.81 },
        "arm14",
    );
}

#[test]
fn quadruped_from_its_file_equals_its_declaration() {
    assert_eq!(
        <quadruped::Quadruped as RigidTree<12, 12>>::JOINTS.len(),
        12
    );
    let hand = lagrange_robots::quadruped::Quadruped { g: 9.81 };
    same_dynamics(quadruped::Quadruped::default(), hand, "quadruped");
}

#[test]
fn humanoid_from_its_file_equals_its_declaration() {
    assert_eq!(<humanoid::Humanoid as RigidTree<30, 30>>::JOINTS.len(), 30);
    let hand = lagrange_robots::humanoid::Humanoid { g: 9.81 };
    same_dynamics(humanoid::Humanoid::default(), hand, "humanoid");
}
