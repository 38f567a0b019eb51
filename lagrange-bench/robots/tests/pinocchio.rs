//! The five declarations against Pinocchio 4.1.0 (the `pin` wheel), which reads the same robots
//! from their URDF files (`scripts/peers/robots/`) with its own parser: q̈ by the articulated-body
//! algorithm (τ = 0), τ by the recursive Newton–Euler algorithm at a given q̈, M by the
//! composite-rigid-body algorithm, at two random states per robot. `pinocchio.tsv` holds
//! Pinocchio's values, written by `scripts/peers/robots.py reference` (rows `robot, k, quantity,
//! values`, in the declaration's coordinate order; `state` is q, q̇, q̈).
//!
//! Tolerance: both sides evaluate the same rigid-body dynamics in double precision by recursions
//! of a few thousand operations on quantities of order one to a hundred; MuJoCo and Pinocchio
//! differ on these robots by at most 2e-14 of the result's size (`scripts/peers/robots.sh
//! check`). 1e-10 of the largest entry leaves a margin of 10⁴ and still catches any wrong term
//! (a wrong inertia, offset or rotation changes the result at the 1e-3 level or more).

use lagrange::evaluation::Dynamics;
use lagrange::prelude::*;
use lagrange::tree::rigid::RigidTree;
use lagrange_robots::quadruped::Quadruped;
use lagrange_robots::{arm14::Arm14, arm3::Arm3, arm7::Arm7, humanoid::Humanoid};

mod common;

const REFERENCE: &str = include_str!("pinocchio.tsv");
const TOLERANCE: f64 = 1e-10;

/// Pinocchio's `quantity` for `robot` at state `k`.
fn reference(robot: &str, k: usize, quantity: &str) -> Vec<f64> {
    let key = [robot.to_owned(), k.to_string(), quantity.to_owned()];
    REFERENCE
        .lines()
        .filter(|line| !line.starts_with('#'))
        .map(|line| line.split('\t').collect::<Vec<_>>())
        .find(|fields| fields[..3] == key)
        .unwrap_or_else(|| panic!("no {quantity} of {robot} at state {k} in pinocchio.tsv"))[3..]
        .iter()
        .map(|x| x.parse().expect("a number"))
        .collect()
}

/// Within TOLERANCE of Pinocchio's value, relative to its size.
fn assert_close(what: &str, x: &[f64], expected: &[f64]) {
    common::assert_close(
        &format!("{what} (against Pinocchio)"),
        x,
        expected,
        TOLERANCE,
    );
}

/// Generic over the declaration (`Dynamics`, what `validated` takes), every call through its
/// validated handle.
fn agrees_with_pinocchio<M: Dynamics<N>, const N: usize>(sys: M, robot: &str) {
    let sys = sys.validated().expect("valid parameters");
    for k in 0..2 {
        let s = reference(robot, k, "state");
        let part = |i: usize| M::Coords::from_array(std::array::from_fn(|j| s[i * N + j]));
        let state = State {
            t: 0.0,
            q: part(0),
            v: part(1),
        };
        let qdd = sys.accelerations(&state).expect("accelerations");
        assert_close(
            &format!("{robot} q̈ at state {k}"),
            &qdd.to_array(),
            &reference(robot, k, "qdd"),
        );
        let tau = sys
            .inverse_dynamics(&state, &part(2))
            .expect("inverse dynamics");
        assert_close(
            &format!("{robot} τ at state {k}"),
            &tau.to_array(),
            &reference(robot, k, "tau"),
        );
        let m = sys.mass_matrix(&state).expect("mass matrix");
        let rows: Vec<f64> = (0..N)
            .flat_map(|i| (0..N).map(move |j| m[(i, j)]))
            .collect();
        assert_close(
            &format!("{robot} M at state {k}"),
            &rows,
            &reference(robot, k, "M"),
        );
    }
}

#[test]
fn arm3_agrees_with_pinocchio() {
    // The generated `RigidTree` impl is the proof the recursive pass is taken.
    assert_eq!(<Arm3 as RigidTree<3, 3>>::JOINTS.len(), 3);
    agrees_with_pinocchio(Arm3 { g: 9.81 }, "arm3");
}

#[test]
fn arm7_agrees_with_pinocchio() {
    // The generated `RigidTree` impl is the proof the recursive pass is taken.
    assert_eq!(<Arm7 as RigidTree<7, 7>>::JOINTS.len(), 7);
    agrees_with_pinocchio(Arm7 { g: 9.81 }, "arm7");
}

#[test]
fn arm14_agrees_with_pinocchio() {
    // The generated `RigidTree` impl is the proof the recursive pass is taken.
    assert_eq!(<Arm14 as RigidTree<14, 14>>::JOINTS.len(), 14);
    agrees_with_pinocchio(Arm14 { g: 9.81 }, "arm14");
}

#[test]
fn quadruped_agrees_with_pinocchio() {
    // The generated `RigidTree` impl is the proof the recursive pass is taken.
    assert_eq!(<Quadruped as RigidTree<12, 12>>::JOINTS.len(), 12);
    agrees_with_pinocchio(Quadruped { g: 9.81 }, "quadruped");
}

#[test]
fn humanoid_agrees_with_pinocchio() {
    // The generated `RigidTree` impl is the proof the recursive pass is taken.
    assert_eq!(<Humanoid as RigidTree<30, 30>>::JOINTS.len(), 30);
    agrees_with_pinocchio(Humanoid { g: 9.81 }, "humanoid");
}
