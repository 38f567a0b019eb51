//! Every evaluation of a mechanism that takes the rigid tree pass against the dense pass of the
//! same declaration (`lagrange::dynamics`, over its Cartesian model, which shares no code with the
//! recursions), at random states; shared by the test files of tree-shaped declarations.
//!
//! Tolerance: both passes are exact formulas evaluated in double precision; they differ by the
//! rounding of a few hundred operations on quantities of order one, so 1e-10 relative to the size
//! of the result leaves a margin of about 10⁴ over the observed differences (~1e-14) while
//! catching any wrong term.

// Each test file uses its own part of the helpers.
#![allow(dead_code)]

use lagrange::dynamics::{equations_of_motion, kinetic_energy, momenta};
use lagrange::model::Model;
use lagrange::prelude::*;
use nalgebra::SVector;

/// Random states, the same every run (a linear congruential sequence in [−1, 1)).
pub fn states<const N: usize>(count: usize) -> Vec<([f64; N], [f64; N])> {
    let mut seed: u64 = 0x2545_f491_4f6c_dd1d;
    let mut next = move || {
        seed = seed
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (seed >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    };
    (0..count)
        .map(|_| {
            let q = std::array::from_fn(|_| 1.5 * next());
            let v = std::array::from_fn(|_| 2.0 * next());
            (q, v)
        })
        .collect()
}

/// The tolerance of the module docs, relative to the result's size (at least 1).
pub const TOLERANCE: f64 = 1e-10;

pub fn close(a: f64, b: f64, scale: f64, what: &str) {
    close_within(a, b, scale, TOLERANCE, what);
}

pub fn close_within(a: f64, b: f64, scale: f64, tolerance: f64, what: &str) {
    assert!(
        (a - b).abs() <= tolerance * scale.max(1.0),
        "{what}: tree {a}, dense {b}"
    );
}

pub type Named<H, const N: usize> = <H as lagrange::evaluation::Evaluate<N>>::Coords;

/// Every evaluation of `sys` (the declaration `declared` or its validated handle) through the tree
/// pass against the dense pass of the same declaration.
pub fn agrees_with_dense<M, H, const N: usize, const K: usize>(declared: &M, sys: &H)
where
    M: Model<N, K>,
    H: Mechanism<N>,
{
    agrees_with_dense_at::<M, H, N, K>(declared, sys, &states::<N>(6), TOLERANCE);
}

/// [`agrees_with_dense`] at the given states (q, q̇), within `tolerance` relative.
pub fn agrees_with_dense_at<M, H, const N: usize, const K: usize>(
    declared: &M,
    sys: &H,
    states: &[([f64; N], [f64; N])],
    tolerance: f64,
) where
    M: Model<N, K>,
    H: Mechanism<N>,
{
    let close = |a: f64, b: f64, scale: f64, what: &str| close_within(a, b, scale, tolerance, what);
    for &(q, v) in states {
        let s = State::new(
            0.0,
            Named::<H, N>::from_array(q),
            Named::<H, N>::from_array(v),
        );
        let dense = equations_of_motion::<M, f64, N, K>(declared, 0.0, &q, &v);
        let m = sys.mass_matrix(&s).unwrap();
        let scale = dense.mass_matrix.abs().max();
        for (a, b) in m.iter().zip(dense.mass_matrix.iter()) {
            close(*a, *b, scale, "M");
        }
        let f = sys.generalized_forces(&s).unwrap().to_array();
        let rhs = dense.generalized_forces - dense.inertial_terms;
        let expected = dense.mass_matrix.cholesky().unwrap().solve(&rhs);
        let qdd = sys.accelerations(&s).unwrap().to_array();
        let scale = expected.abs().max();
        for j in 0..N {
            close(
                f[j],
                dense.generalized_forces[j],
                dense.generalized_forces.abs().max(),
                "𝓕",
            );
            close(qdd[j], expected[j], scale, "q̈");
        }
        // Inverse dynamics of a q̈ that is not the free motion's: M q̈ + b − 𝓕.
        let wanted = SVector::<f64, N>::from_fn(|j, _| 0.3 * j as f64 - 0.5);
        let tau = sys
            .inverse_dynamics(&s, &Named::<H, N>::from_array(wanted.into()))
            .unwrap()
            .to_array();
        let expected = dense.mass_matrix * wanted + dense.inertial_terms - dense.generalized_forces;
        for j in 0..N {
            close(tau[j], expected[j], expected.abs().max(), "τ");
        }
        let t_dense = kinetic_energy::<M, f64, N, K>(declared, 0.0, &q, &v);
        close(sys.kinetic_energy(&s).unwrap(), t_dense, t_dense, "T");
        let p_dense = momenta::<M, f64, N, K>(declared, 0.0, &q, &v);
        let p = sys.momenta(&s).unwrap().to_array();
        for j in 0..N {
            close(p[j], p_dense[j], 1.0, "p");
        }
    }
}
