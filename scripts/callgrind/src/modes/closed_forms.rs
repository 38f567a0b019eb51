//! The hand-written closed forms (`hw_*`) the generated `accelerations` are counted against: each
//! q̈ written out in f64, no checks, its parameters and state through `black_box` as the generated
//! side's; and `check`, which prints the cart pendulum's q̈ both ways.

use crate::mechanisms::{
    cart_pendulum, double_pendulum, fpu_forces, kepler_rhs, pendulum, wedge_block, CART_PENDULUM,
    DOUBLE_PENDULUM, PENDULUM, WEDGE_BLOCK,
};
use lagrange::prelude::*;
use std::hint::black_box;

/// θ̈ = −(g/l) sin θ.
fn pendulum_accelerations(p: &pendulum::Pendulum, q: [f64; 1], _v: [f64; 1]) -> [f64; 1] {
    [-p.g / p.l * q[0].sin()]
}

/// The double pendulum's q̈ solved in closed form (d = θ₁ − θ₂).
pub fn double_pendulum_accelerations(
    p: &double_pendulum::DoublePendulum,
    q: [f64; 2],
    v: [f64; 2],
) -> [f64; 2] {
    let double_pendulum::DoublePendulum { m1, m2, l1, l2, g } = *p;
    let d = q[0] - q[1];
    let den = m1 + m2 * d.sin().powi(2);
    let a1 = (m2 * g * q[1].sin() * d.cos()
        - m2 * d.sin() * (l1 * v[0] * v[0] * d.cos() + l2 * v[1] * v[1])
        - (m1 + m2) * g * q[0].sin())
        / (l1 * den);
    let a2 = ((m1 + m2) * (l1 * v[0] * v[0] * d.sin() - g * q[1].sin() + g * q[0].sin() * d.cos())
        + m2 * l2 * v[1] * v[1] * d.sin() * d.cos())
        / (l2 * den);
    [a1, a2]
}

/// The wedge's and the block's constant accelerations (ẍ, d̈) in closed form.
fn wedge_block_accelerations(p: &wedge_block::WedgeBlock) -> [f64; 2] {
    let (s, c) = p.alpha.sin_cos();
    let den = p.wedge_mass + p.block_mass * s * s;
    [
        -p.block_mass * p.g * s * c / den,
        (p.wedge_mass + p.block_mass) * p.g * s / den,
    ]
}

/// The wedge by the generated code's method, written out by hand in f64 (rows [1, 0], [1, c],
/// [0, −s]; M = JᵀμJ; 𝓕 = Jᵀw; 2×2 solve; no checks): see benches/accelerations.rs.
fn wedge_block_assembled(p: &wedge_block::WedgeBlock) -> [f64; 2] {
    let (s, c) = p.alpha.sin_cos();
    let (big_m, m) = (p.wedge_mass, p.block_mass);
    let (m00, m10, m11) = (big_m + m, m * c, m * (c * c + s * s));
    let (f0, f1) = (0.0, m * p.g * s);
    let inv_det = 1.0 / (m00 * m11 - m10 * m10);
    [
        (m11 * f0 - m10 * f1) * inv_det,
        (m00 * f1 - m10 * f0) * inv_det,
    ]
}

/// The cart pendulum's (ẍ, θ̈) in closed form.
fn cart_pendulum_accelerations(
    p: &cart_pendulum::CartPendulum,
    q: [f64; 2],
    v: [f64; 2],
) -> [f64; 2] {
    let (s, c) = q[1].sin_cos();
    let (mc, m, l, g) = (p.cart_mass, p.m, p.l, p.g);
    let den = mc + m * s * s;
    let xdd = (m * s * (l * v[1] * v[1] + g * c)) / den;
    let tdd = -(m * l * v[1] * v[1] * s * c + (mc + m) * g * s) / (l * den);
    [xdd, tdd]
}

pub fn hw_pendulum(n: usize) -> f64 {
    let sys = PENDULUM;
    let mut acc = 0.0;
    for _ in 0..n {
        acc += pendulum_accelerations(black_box(&sys), black_box([0.7]), black_box([1.1]))[0];
    }
    acc
}

pub fn hw_double_pendulum(n: usize) -> f64 {
    let sys = DOUBLE_PENDULUM;
    let mut acc = 0.0;
    for _ in 0..n {
        acc += double_pendulum_accelerations(
            black_box(&sys),
            black_box([0.7, -1.2]),
            black_box([1.1, -0.4]),
        )[0];
    }
    acc
}

// The wedge's two hand-written forms in two loops, not behind a function pointer: each inlined
// into its loop, as in the bench.

pub fn hw_wedge_block(n: usize) -> f64 {
    let sys = WEDGE_BLOCK;
    let mut acc = 0.0;
    for _ in 0..n {
        acc += wedge_block_accelerations(black_box(&sys))[0];
    }
    acc
}

pub fn assembled_wedge_block(n: usize) -> f64 {
    let sys = WEDGE_BLOCK;
    let mut acc = 0.0;
    for _ in 0..n {
        acc += wedge_block_assembled(black_box(&sys))[0];
    }
    acc
}

pub fn hw_cart_pendulum(n: usize) -> f64 {
    let sys = CART_PENDULUM;
    let mut acc = 0.0;
    for _ in 0..n {
        acc += cart_pendulum_accelerations(
            black_box(&sys),
            black_box([0.1, 0.7]),
            black_box([-0.3, 1.1]),
        )[0];
    }
    acc
}

/// Kepler's q̈ as the peers write it (`kepler_report::kepler_rhs`).
pub fn hw_kepler(n: usize) -> f64 {
    let (q, v) = ([0.4, 0.3], [-0.2, 1.7]);
    let mut acc = 0.0;
    // Both components consumed: with q̈₀ alone the compiler drops the second division.
    for _ in 0..n {
        let a = kepler_rhs(0.0, black_box(&q), black_box(&v));
        acc += a[0] + a[1];
    }
    acc
}

/// The FPU chain's forces as the peers write them (`fpu_report::fpu_forces`).
pub fn hw_fpu(n: usize) -> f64 {
    let q = [0.1, 0.2, -0.3, 0.05, 0.4, -0.1];
    let mut acc = 0.0;
    for _ in 0..n {
        acc += fpu_forces(black_box(50.0), black_box(&q))
            .iter()
            .sum::<f64>();
    }
    acc
}

/// Prints the cart pendulum's q̈, generated and by hand, once (`n` unused).
pub fn check(_n: usize) -> f64 {
    use cart_pendulum::*;
    let sys = CART_PENDULUM;
    let s = State::new(
        0.0,
        Coords { x: 0.1, theta: 0.7 },
        Coords {
            x: -0.3,
            theta: 1.1,
        },
    );
    let a = sys.accelerations(&s).unwrap();
    println!(
        "{:?} {:?}",
        a,
        cart_pendulum_accelerations(&sys, [0.1, 0.7], [-0.3, 1.1])
    );
    0.0
}
