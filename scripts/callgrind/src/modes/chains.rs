//! The N-link planar chains of the chain benchmark (N = 1, 2, 4, …, 64): generated, declared link
//! by link (`chainN_links`, along the prefix's path), against the closed form (`hw_chainN`); and
//! the 32-link chain declared as a family (`chain32`).

use crate::calls::{calls, Via};
use crate::mechanisms::{chain32, chains};
use lagrange::prelude::*;
use std::hint::black_box;

/// θⱼ and θ̇ⱼ spread over the links, as in the chain benchmark.
fn chain_state<const N: usize>() -> ([f64; N], [f64; N]) {
    (
        std::array::from_fn(|j| 0.3 + 0.7 * ((j as f64) * 0.9).sin()),
        std::array::from_fn(|j| 0.5 * ((j as f64) * 1.3).cos()),
    )
}

/// `chainN_links`: `n` calls of the link-by-link chain of N links (see `calls`), m = 1, l = 0.5,
/// g = 9.81.
macro_rules! chain_links {
    ($($mode:ident: $module:ident, $ty:ident, $links:literal;)*) => {$(
        pub fn $mode(n: usize, via: Via) -> f64 {
            use chains::$module::*;
            let sys = $ty {
                m: 1.0,
                l: 0.5,
                g: 9.81,
            };
            let (q, v) = chain_state::<$links>();
            let s = State::new(0.0, Coords::from_array(q), Coords::from_array(v));
            calls(sys, &s, n, via)
        }
    )*};
}

chain_links! {
    chain1_links: chain1, Chain1, 1;
    chain2_links: chain2, Chain2, 2;
    chain4_links: chain4, Chain4, 4;
    chain8_links: chain8, Chain8, 8;
    chain16_links: chain16, Chain16, 16;
    chain32_links: chain32, Chain32, 32;
    chain64_links: chain64, Chain64, 64;
}

/// The N-link chain's closed form, as in the chain benchmark: M_jk = m l² (N − max(j,k))
/// cos(θⱼ − θₖ), one sin_cos per link, the same LDLᵀ.
fn chain_accelerations<const N: usize>(
    m: f64,
    l: f64,
    g: f64,
    q: &[f64; N],
    v: &[f64; N],
) -> [f64; N] {
    let sc: [(f64, f64); N] = std::array::from_fn(|j| q[j].sin_cos());
    let mut mass = nalgebra::SMatrix::<f64, N, N>::zeros();
    let mut force = nalgebra::SVector::<f64, N>::zeros();
    for j in 0..N {
        let (sj, cj) = sc[j];
        force[j] = -m * g * l * (N - j) as f64 * sj;
        for k in 0..N {
            let (sk, ck) = sc[k];
            let w = m * l * l * (N - j.max(k)) as f64;
            mass[(j, k)] = w * (cj * ck + sj * sk);
            force[j] -= w * (sj * ck - cj * sk) * v[k] * v[k];
        }
    }
    lagrange::linalg::Ldlt::new(&mass)
        .expect("positive definite")
        .solve(&force)
        .into()
}

/// `hw_chainN`: `n` calls of the closed form of the chain of N links.
pub fn hw_chain<const N: usize>(n: usize) -> f64 {
    let (q, v) = chain_state::<N>();
    let mut acc = 0.0;
    for _ in 0..n {
        // Parameters opaque, as the generated side's (`black_box(&sys)`).
        let (m, l, g) = black_box((1.0, 0.5, 9.81));
        acc += chain_accelerations::<N>(m, l, g, black_box(&q), black_box(&v))[0];
    }
    acc
}

/// `n` calls of `accelerations` on the 32-link family, on the parameters (the prefix not read).
pub fn chain32(n: usize) -> f64 {
    use chain32::*;
    let sys = Chain {
        m: 1.0,
        l: 0.5,
        g: 9.81,
    };
    let (theta, theta_dot) = chain_state::<LINKS>();
    let s = State::new(0.0, Coords { theta }, Coords { theta: theta_dot });
    let mut acc = 0.0;
    for _ in 0..n {
        acc += black_box(&sys).accelerations(black_box(&s)).unwrap().theta[0];
    }
    acc
}
