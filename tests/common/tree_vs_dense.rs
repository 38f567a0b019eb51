//! Every evaluation of a mechanism that takes the rigid tree pass against the dense pass of the
//! same declaration (`lagrange::dynamics`, over its Cartesian model, which shares no code with the
//! recursions), at random states; shared by the test files of tree-shaped declarations. Where the
//! declaration's velocities are quasi-velocities (a free or ball joint's angular velocity, q̇ =
//! G(q) v), the dense pass runs at q̇ = G v and the tree's quantities are converted to the rates
//! (`lagrange::tree::rigid::free`: M_q̇ = Bᵀ M B, 𝓕_q̇ = Bᵀ 𝓕, q̈ = G (v̇ − Ḃ q̇), p_q̇ = Bᵀ p);
//! elsewhere every map is the identity.
//!
//! Tolerance: both passes are exact formulas evaluated in double precision; they differ by the
//! rounding of a few hundred operations on quantities of order one, so 1e-10 relative to the size
//! of the result leaves a margin of about 10⁴ over the observed differences (~1e-14) while
//! catching any wrong term.

// Each test file uses its own part of the helpers.
#![allow(dead_code)]

use lagrange::dynamics::{equations_of_motion, kinetic_energy, momenta};
use lagrange::evaluation::Dynamics;
use lagrange::model::Model;
use lagrange::prelude::*;
use lagrange::tree::rigid::free;
use nalgebra::{SMatrix, SVector};

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
    let joints = <H::Model as Dynamics<N>>::QUASI_VELOCITY_JOINTS;
    for &(q, v) in states {
        let s = State::new(
            0.0,
            Named::<H, N>::from_array(q),
            Named::<H, N>::from_array(v),
        );
        // The dense pass in the coordinates' rates; the tree's results made theirs.
        let rates = free::position_rates(joints, &q, &v);
        let to_rates = |x: [f64; N]| free::rate_forces(joints, &q, &x);
        let bias = free::velocity_bias(joints, &q, &rates);
        let dense = equations_of_motion::<M, f64, N, K>(declared, 0.0, &q, &rates);
        let m = congruent(joints, &q, &sys.mass_matrix(&s).unwrap());
        let scale = dense.mass_matrix.abs().max();
        for (a, b) in m.iter().zip(dense.mass_matrix.iter()) {
            close(*a, *b, scale, "M");
        }
        let f = to_rates(sys.generalized_forces(&s).unwrap().to_array());
        let rhs = dense.generalized_forces - dense.inertial_terms;
        let expected = dense.mass_matrix.cholesky().unwrap().solve(&rhs);
        let v_dot = sys.accelerations(&s).unwrap().to_array();
        let qdd = free::position_rates(joints, &q, &std::array::from_fn(|i| v_dot[i] - bias[i]));
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
        // Inverse dynamics of a q̈ that is not the free motion's: M q̈ + b − 𝓕 (v̇ = B q̈ + Ḃ q̇).
        let wanted = SVector::<f64, N>::from_fn(|j, _| 0.3 * j as f64 - 0.5);
        let b_wanted = free::velocities_from_rates(joints, &q, &wanted.into());
        let wanted_v: [f64; N] = std::array::from_fn(|i| b_wanted[i] + bias[i]);
        let tau = sys
            .inverse_dynamics(&s, &Named::<H, N>::from_array(wanted_v))
            .unwrap()
            .to_array();
        let tau = to_rates(tau);
        let expected = dense.mass_matrix * wanted + dense.inertial_terms - dense.generalized_forces;
        for j in 0..N {
            close(tau[j], expected[j], expected.abs().max(), "τ");
        }
        let t_dense = kinetic_energy::<M, f64, N, K>(declared, 0.0, &q, &rates);
        close(sys.kinetic_energy(&s).unwrap(), t_dense, t_dense, "T");
        let p_dense = momenta::<M, f64, N, K>(declared, 0.0, &q, &rates);
        let p = to_rates(sys.momenta(&s).unwrap().to_array());
        for j in 0..N {
            close(p[j], p_dense[j], 1.0, "p");
        }
    }
}

/// Bᵀ M B: a matrix on the velocities made one on the coordinates' rates (M itself where they are
/// the same).
fn congruent<const N: usize>(
    joints: &[lagrange::tree::rigid::Joint],
    q: &[f64; N],
    m: &SMatrix<f64, N, N>,
) -> SMatrix<f64, N, N> {
    SMatrix::from_fn(|i, j| {
        let unit = |k: usize| std::array::from_fn(|l| if l == k { 1.0 } else { 0.0 });
        let column = *m * SVector::from(free::velocities_from_rates(joints, q, &unit(j)));
        free::rate_forces(joints, q, &column.into())[i]
    })
}
