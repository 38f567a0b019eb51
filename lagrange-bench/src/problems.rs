//! The report's problems: the wedge as a hand-written [`Model`] (what `#[mechanism]` generates),
//! every problem's hand-written right-hand side for the peer solvers, and their exact or reference
//! solutions. Kepler is declared in [`crate::kepler`], the pendulums in [`crate::pendulums`], the
//! chains and the constrained pendulum in [`crate::stiff`].

use lagrange_core::{Model, Scalar, State};
use std::f64::consts::{FRAC_1_SQRT_2, PI, SQRT_2};

// ---------------------------------------------------------------------------------------------
// Jacobi elliptic functions.

/// K(k) = π / (2 AGM(1, √(1 − k²))) (Abramowitz & Stegun 17.6).
pub fn elliptic_k(k: f64) -> f64 {
    let (mut a, mut b) = (1.0f64, (1.0 - k * k).sqrt());
    for _ in 0..60 {
        let (a1, b1) = (0.5 * (a + b), (a * b).sqrt());
        a = a1;
        b = b1;
    }
    PI / (2.0 * a)
}

/// (sn, cn)(u, k) by the descending AGM (Abramowitz & Stegun 16.4).
pub fn jacobi_sn_cn(u: f64, k: f64) -> (f64, f64) {
    let mut a = [0.0f64; 32];
    let mut c = [0.0f64; 32];
    a[0] = 1.0;
    let mut b = (1.0 - k * k).sqrt();
    c[0] = k;
    let mut n = 0;
    while c[n].abs() > 1e-16 && n < 30 {
        a[n + 1] = 0.5 * (a[n] + b);
        c[n + 1] = 0.5 * (a[n] - b);
        b = (a[n] * b).sqrt();
        n += 1;
    }
    let mut phi = 2f64.powi(n as i32) * a[n] * u;
    for j in (1..=n).rev() {
        phi = 0.5 * (phi + (c[j] / a[j] * phi.sin()).asin());
    }
    (phi.sin(), phi.cos())
}

// ---------------------------------------------------------------------------------------------
// 1. Large-amplitude pendulum.

// The mechanism: `crate::pendulums::PENDULUM`, q̈ = −sin q.

/// Modulus of the pendulum problem.
pub const PENDULUM_K: f64 = 0.999;

/// q(0) = 0, q̇(0) = 2k: q = 2 arcsin(k sn(t, k)), q̇ = 2k cn(t, k).
pub fn pendulum_exact(t: f64) -> ([f64; 1], [f64; 1]) {
    let (sn, cn) = jacobi_sn_cn(t, PENDULUM_K);
    ([2.0 * (PENDULUM_K * sn).asin()], [2.0 * PENDULUM_K * cn])
}

pub fn pendulum_rhs(_t: f64, q: &[f64; 1], _v: &[f64; 1]) -> [f64; 1] {
    [-q[0].sin()]
}

// ---------------------------------------------------------------------------------------------
// 2. Kepler.

// The mechanism: `crate::kepler::KEPLER`, V = −1/r.

pub const KEPLER_E: f64 = 0.6;

/// a = 1, GM = 1 from periapsis: position and velocity at t from Kepler's equation E − e sin E = t.
pub fn kepler_exact(t: f64) -> ([f64; 2], [f64; 2]) {
    let e = KEPLER_E;
    let m = t.rem_euclid(2.0 * PI);
    let mut big_e = m;
    for _ in 0..60 {
        let d = (big_e - e * big_e.sin() - m) / (1.0 - e * big_e.cos());
        big_e -= d;
        if d.abs() < 1e-16 {
            break;
        }
    }
    let (s, c) = big_e.sin_cos();
    let b = (1.0 - e * e).sqrt();
    let den = 1.0 - e * c;
    ([c - e, b * s], [-s / den, b * c / den])
}

pub fn kepler_start() -> State<[f64; 2]> {
    let e = KEPLER_E;
    State::new(0.0, [1.0 - e, 0.0], [0.0, ((1.0 + e) / (1.0 - e)).sqrt()])
}

pub use crate::kepler::kepler_rhs;

// ---------------------------------------------------------------------------------------------
// 3. Double pendulum.

// The mechanism: `crate::pendulums::DOUBLE_PENDULUM`.

/// Closed form of the double pendulum with m₁ = m₂ = l₁ = l₂ = g = 1 (the standard derivation, as
/// in `lagrange-core/tests/hand_written_model.rs`).
pub fn double_pendulum_rhs(_t: f64, q: &[f64; 2], v: &[f64; 2]) -> [f64; 2] {
    let (m1, m2, l1, l2, g) = (1.0, 1.0, 1.0, 1.0, 1.0);
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

// ---------------------------------------------------------------------------------------------
// 4. Fermi–Pasta–Ulam chain.

/// Stiff-spring frequency. The chain itself is declared with `#[mechanism]` in [`crate::fpu`]
/// ([`crate::stiff::FPU`]), each spring a potential of its own.
pub const FPU_OMEGA: f64 = 50.0;

/// HLW's initial values x₀,₁ = 1, ẋ₀,₁ = 1, x₁,₁ = ω⁻¹, ẋ₁,₁ = 1 (centre and elongation of the first
/// stiff spring, x₀ = (q₂ + q₁)/√2, x₁ = (q₂ − q₁)/√2 in their 1-based numbering), all else zero.
pub fn fpu_start() -> State<[f64; 6]> {
    let w = FPU_OMEGA;
    State::new(
        0.0,
        [
            (1.0 - 1.0 / w) * FRAC_1_SQRT_2,
            (1.0 + 1.0 / w) * FRAC_1_SQRT_2,
            0.0,
            0.0,
            0.0,
            0.0,
        ],
        [0.0, SQRT_2, 0.0, 0.0, 0.0, 0.0],
    )
}

/// q̈ of the chain (unit masses), by hand: [`crate::fpu::fpu_forces`].
pub fn fpu_rhs(_t: f64, q: &[f64; 6], _v: &[f64; 6]) -> [f64; 6] {
    crate::fpu::fpu_forces(FPU_OMEGA, q)
}

// ---------------------------------------------------------------------------------------------
// 5. Wedge and block.

pub const WEDGE_MASS: f64 = 3.0;
pub const BLOCK_MASS: f64 = 1.0;
pub const WEDGE_ALPHA: f64 = 0.5;
pub const WEDGE_HEIGHT: f64 = 1.0;
pub const WEDGE_G: f64 = 9.81;

/// A wedge of mass M sliding on a frictionless floor (coordinate x) and a block of mass m sliding
/// down its frictionless face of angle α (coordinate d along the face), from height h.
pub struct WedgeBlock;

impl Model<2, 4> for WedgeBlock {
    type Coords = [f64; 2];
    const RHEONOMIC: bool = false;
    const HAS_POTENTIAL: bool = true;
    const HAS_FORCES: bool = false;
    fn validate(&self) -> lagrange_core::Result<()> {
        Ok(())
    }
    fn masses(&self) -> [f64; 4] {
        [WEDGE_MASS, WEDGE_MASS, BLOCK_MASS, BLOCK_MASS]
    }
    fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 2]) -> [D; 4] {
        let (s, c) = WEDGE_ALPHA.sin_cos();
        [q[0], D::zero(), q[0] + q[1] * c, -(q[1] * s) + WEDGE_HEIGHT]
    }
    fn potential<D: Scalar>(&self, _t: D, _q: &[D; 2], x: &[D; 4]) -> D {
        x[3] * (BLOCK_MASS * WEDGE_G)
    }
}
// x is affine in q: its validated handle prepares J and the factors of M once.
lagrange_core::impl_mechanism!(WedgeBlock, 2, 4, affine);

/// The constant accelerations (ẍ, d̈): [[M + m, m cos α], [m cos α, m]] q̈ = (0, m g sin α).
pub fn wedge_accelerations() -> [f64; 2] {
    let (s, c) = WEDGE_ALPHA.sin_cos();
    let (big, m, g) = (WEDGE_MASS, BLOCK_MASS, WEDGE_G);
    let den = big + m * s * s;
    [-m * g * s * c / den, (big + m) * g * s / den]
}

/// Time at which the block reaches the floor (d = h / sin α) from rest.
pub fn wedge_floor_time() -> f64 {
    (2.0 * WEDGE_HEIGHT / WEDGE_ALPHA.sin() / wedge_accelerations()[1]).sqrt()
}

pub fn wedge_exact(t: f64) -> ([f64; 2], [f64; 2]) {
    let a = wedge_accelerations();
    (
        [0.5 * a[0] * t * t, 0.5 * a[1] * t * t],
        [a[0] * t, a[1] * t],
    )
}

pub fn wedge_rhs(_t: f64, _q: &[f64; 2], _v: &[f64; 2]) -> [f64; 2] {
    wedge_accelerations()
}

#[cfg(test)]
mod tests {
    use super::*;
    use lagrange_core::evaluation::Evaluate as _;

    #[test]
    fn hand_written_right_hand_sides_match_the_models() {
        let check = |a: &[f64], b: &[f64]| {
            for (x, y) in a.iter().zip(b) {
                assert!((x - y).abs() <= 1e-10 * (1.0 + y.abs()), "{a:?} vs {b:?}");
            }
        };
        check(
            &crate::pendulums::PENDULUM
                .accelerations_at(0.0, &[0.7], &[0.3])
                .unwrap(),
            &pendulum_rhs(0.0, &[0.7], &[0.3]),
        );
        check(
            &crate::kepler::KEPLER
                .accelerations_at(0.0, &[0.7, -0.2], &[0.3, 1.0])
                .unwrap(),
            &kepler_rhs(0.0, &[0.7, -0.2], &[0.0; 2]),
        );
        let (q, v) = ([1.1, -0.4], [0.5, 2.0]);
        check(
            &crate::pendulums::DOUBLE_PENDULUM
                .accelerations_at(0.0, &q, &v)
                .unwrap(),
            &double_pendulum_rhs(0.0, &q, &v),
        );
        let q6 = [0.1, 0.3, -0.2, 0.05, 0.4, -0.1];
        check(
            &crate::stiff::FPU
                .accelerations_at(0.0, &q6, &[0.0; 6])
                .unwrap(),
            &fpu_rhs(0.0, &q6, &[0.0; 6]),
        );
        check(
            &WedgeBlock
                .accelerations_at(0.0, &[0.2, 0.3], &[0.1, 0.4])
                .unwrap(),
            &wedge_rhs(0.0, &[0.0; 2], &[0.0; 2]),
        );
    }

    #[test]
    fn exact_solutions_start_where_the_problems_start() {
        let (q, v) = pendulum_exact(0.0);
        assert!(q[0].abs() < 1e-15 && (v[0] - 2.0 * PENDULUM_K).abs() < 1e-15);
        // sn has quarter period K: q(K) is the turning point 2 arcsin k.
        let (q, v) = pendulum_exact(elliptic_k(PENDULUM_K));
        assert!(
            (q[0] - 2.0 * PENDULUM_K.asin()).abs() < 1e-9 && v[0].abs() < 1e-7,
            "{q:?} {v:?}"
        );
        let (q, v) = kepler_exact(0.0);
        let s = kepler_start();
        assert!((q[0] - s.q[0]).abs() < 1e-15 && (v[1] - s.v[1]).abs() < 1e-14);
    }
}
