//! The three-link spatial arm declared by its joint frames (full inertia tensors, diagonalised
//! when evaluated) and by its principal axes, and the eigen-decomposition of one tensor alone.

use crate::calls::{calls, Via};
use crate::mechanisms::framed_arms::{self, framed_arm as fa, principal_arm as pa};
use lagrange::prelude::*;
use std::hint::black_box;

/// The arm's (q, q̇), one for both declarations.
const ARM_STATE: ([f64; 3], [f64; 3]) = ([0.3, 1.2, -0.8], [1.0, -0.5, 2.0]);

pub fn framed_arm(n: usize, via: Via) -> f64 {
    let (q, v) = ARM_STATE;
    let s = fa::State::new(0.0, fa::Coords::from_array(q), fa::Coords::from_array(v));
    calls(framed_arms::framed(), &s, n, via)
}

pub fn principal_arm(n: usize, via: Via) -> f64 {
    let (q, v) = ARM_STATE;
    let s = pa::State::new(0.0, pa::Coords::from_array(q), pa::Coords::from_array(v));
    calls(framed_arms::principal(), &s, n, via)
}

/// `lagrange::inertia::principal_axes` of one symmetric 3×3 tensor: the eigen-decomposition
/// `framed_arm` does for each body wherever its mass frame is needed.
pub fn principal_axes(n: usize) -> f64 {
    let tensor = [
        [0.02, 0.001, -0.002],
        [0.001, 0.03, 0.0005],
        [-0.002, 0.0005, 0.04],
    ];
    let mut acc = 0.0;
    for _ in 0..n {
        acc += lagrange::inertia::principal_axes(black_box(&tensor)).0[0];
    }
    acc
}
