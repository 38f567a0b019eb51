//! The gallery's constrained mechanisms, the pendulum in Cartesian coordinates (its length a
//! constraint) and the four-bar linkage: `accelerations` along the prefix's path (see `calls`),
//! against their KKT systems written out by hand (`hw_*`, as in the accelerations benchmark); and
//! the projection onto the constraints after a step.

use crate::calls::{calls, Via};
use crate::mechanisms::constrained;
use lagrange::prelude::*;
use lagrange_gallery::scenes::cartesian_pendulum::cartesian_pendulum::{CartesianPendulum, Coords};
use lagrange_gallery::scenes::four_bar as four_bar_scene;
use std::hint::black_box;

/// The Cartesian pendulum the modes on it take, m = 1, l = 0.8, g = 9.81.
const CARTESIAN_PENDULUM: CartesianPendulum = CartesianPendulum {
    m: 1.0,
    l: 0.8,
    g: 9.81,
};

/// Its bob at θ = 0.7 on the circle moving at θ̇ = 1.1: (x, y) and (ẋ, ẏ).
fn cartesian_start() -> ([f64; 2], [f64; 2]) {
    let (th, w) = (0.7f64, 1.1f64);
    let q = [0.8 * th.sin(), -0.8 * th.cos()];
    let v = [0.8 * w * th.cos(), 0.8 * w * th.sin()];
    (q, v)
}

pub fn cartesian_pendulum(n: usize, via: Via) -> f64 {
    let sys = CARTESIAN_PENDULUM;
    let (q, v) = cartesian_start();
    let s = State::new(
        0.0,
        Coords { x: q[0], y: q[1] },
        Coords { x: v[0], y: v[1] },
    );
    calls(sys, &s, n, via)
}

pub fn hw_cartesian_pendulum(n: usize) -> f64 {
    let hand = constrained::CartesianPendulum {
        m: 1.0,
        l: 0.8,
        g: 9.81,
    };
    let (q, v) = cartesian_start();
    let mut acc = 0.0;
    for _ in 0..n {
        acc += constrained::cartesian_pendulum(black_box(&hand), black_box(q), black_box(v))[0];
    }
    acc
}

/// `n` projections (`project`) of the Cartesian pendulum from a state off the circle and its
/// tangent by 1e-10, as an accepted step leaves it: on the parameters, or (either prefix) through
/// a validated handle.
pub fn project_cartesian_pendulum(n: usize, via: Via) -> f64 {
    let sys = CARTESIAN_PENDULUM;
    let (th, w, drift) = (0.7f64, 1.1f64, 1.0 + 1e-10);
    let q = [0.8 * drift * th.sin(), -0.8 * drift * th.cos()];
    let v = [0.8 * w * th.cos() + 1e-10, 0.8 * w * th.sin()];
    fn project<M: Mechanism<2>>(sys: &M, q: [f64; 2], v: [f64; 2], n: usize) -> f64 {
        let mut acc = 0.0;
        for _ in 0..n {
            let (mut q, mut v) = (black_box(q), black_box(v));
            black_box(sys).project(0.0, &mut q, &mut v).unwrap();
            acc += q[0] + v[0];
        }
        acc
    }
    match via {
        Via::Parameters => project(&sys, q, v, n),
        _ => project(&sys.validated().unwrap(), q, v, n),
    }
}

pub fn four_bar(n: usize, via: Via) -> f64 {
    let (sys, s) = four_bar_scene::linkage();
    calls(sys, &s, n, via)
}

pub fn hw_four_bar(n: usize) -> f64 {
    let (sys, s) = four_bar_scene::linkage();
    let hand = constrained::FourBar {
        l: [sys.l1, sys.l2, sys.l3],
        m: [sys.m1, sys.m2, sys.m3],
        d: sys.d,
        g: sys.g,
    };
    let (q, v) = (s.q.to_array(), s.v.to_array());
    let mut acc = 0.0;
    for _ in 0..n {
        acc += constrained::four_bar(black_box(&hand), black_box(q), black_box(v))[0];
    }
    acc
}
