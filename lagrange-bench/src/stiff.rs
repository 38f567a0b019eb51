//! The report's problems declared with `#[mechanism]` (the Fermi–Pasta–Ulam chain, the stiff
//! and the constrained problem), with hand-written right-hand sides for the peers and their
//! closed-form solutions.
//!
//! - The Fermi–Pasta–Ulam chain of [`crate::fpu`], with ω = 50 ([`FPU`]).
//! - A stiff chain: four unit masses on a line, the first tied to a wall by a soft spring
//!   (k₀ = 1), neighbours joined by stiff springs (k = 2·10⁶). Its three stiff modes have
//!   ω ≈ 1082, 2000 and 2613, its slow mode ω ≈ 0.5 (the whole chain on the soft spring). Started
//!   along the slow normal mode, the motion is x(t) = φ (cos ωt + sin ωt) exactly: smooth, yet an
//!   explicit method's stability bound forces h ≲ 3/ω_max on it.
//! - The pendulum in Cartesian coordinates (x, y) with the constraint |r| = 1 (g = 1, unit mass):
//!   from the bottom with speed 2k, θ = 2 arcsin(k sn(t, k)) (the problems' large-amplitude
//!   pendulum, k = 0.999), so (x, y) = (sin θ, −cos θ), (ẋ, ẏ) = θ̇ (cos θ, sin θ).

use crate::problems::{pendulum_exact, FPU_OMEGA, PENDULUM_K};
use lagrange::prelude::*;
use nalgebra::{SMatrix, SymmetricEigen};

pub use crate::fpu::fpu_chain;

/// The chain of the report.
pub const FPU: fpu_chain::Fpu = fpu_chain::Fpu {
    m: 1.0,
    omega: FPU_OMEGA,
};

#[mechanism]
pub mod stiff_chain {
    pub const MASSES: usize = 4;

    /// Positions of the masses along the line (from their rest positions).
    pub struct Coords {
        pub x: [f64; MASSES],
    }

    #[derive(Clone, Copy, Debug)]
    pub struct StiffChain {
        /// Each mass.
        pub m: f64,
        /// The soft spring from the wall to the first mass.
        pub k_wall: f64,
        /// The stiff springs between neighbours.
        pub k: f64,
    }

    #[particle(mass = m, count = MASSES)]
    fn mass(i: usize) -> Vec2 {
        vec2(x[i], 0.0)
    }

    /// ½k₀x₀² + ½k Σ (xᵢ₊₁ − xᵢ)².
    #[potential]
    fn springs() -> f64 {
        let d1 = mass[1].x - mass[0].x;
        let d2 = mass[2].x - mass[1].x;
        let d3 = mass[3].x - mass[2].x;
        0.5 * k_wall * mass[0].x * mass[0].x + 0.5 * k * (d1 * d1 + d2 * d2 + d3 * d3)
    }
}

pub use stiff_chain::StiffChain;

/// The chain of the report.
pub const CHAIN: StiffChain = StiffChain {
    m: 1.0,
    k_wall: 1.0,
    k: 2e6,
};

/// The compliance matrix C = K⁻¹ (V = ½ xᵀKx): a unit force on mass i moves mass j by the
/// compliances of the springs both share on their way to the wall, C_ij = 1/k₀ + min(i, j)/k.
/// Formed this way it is exact to round-off relative to its largest entry, 1/k₀, so its largest
/// eigenvalue 1/ω²_slow is accurate to round-off — unlike the smallest eigenvalue of K itself,
/// whose absolute error ε‖K‖ ≈ 1e-9 would put a floor of about 1e-9 under every error.
fn chain_compliance() -> SMatrix<f64, 4, 4> {
    SMatrix::<f64, 4, 4>::from_fn(|i, j| 1.0 / CHAIN.k_wall + i.min(j) as f64 / CHAIN.k)
}

/// The chain's normal modes: angular frequencies ω (ascending) and mode shapes (columns), from
/// the eigenvalues μ of C/m⁻¹ = (K/m)⁻¹, ω = 1/√μ (the stiff ones only to ε‖C‖/μ relative).
pub fn chain_modes() -> ([f64; 4], SMatrix<f64, 4, 4>) {
    let eig = SymmetricEigen::new(chain_compliance() * CHAIN.m);
    let mut order: Vec<usize> = (0..4).collect();
    order.sort_by(|&a, &b| eig.eigenvalues[b].total_cmp(&eig.eigenvalues[a]));
    let omega = std::array::from_fn(|i| 1.0 / eig.eigenvalues[order[i]].sqrt());
    let shapes = SMatrix::<f64, 4, 4>::from_fn(|r, c| eig.eigenvectors[(r, order[c])]);
    (omega, shapes)
}

/// The slow mode shape φ, scaled so that φ₀ = 1.
fn slow_shape() -> ([f64; 4], f64) {
    let (omega, shapes) = chain_modes();
    let col = shapes.column(0);
    (std::array::from_fn(|i| col[i] / col[0]), omega[0])
}

/// Start: x = φ, ẋ = ωφ (so x(t) = φ (cos ωt + sin ωt)).
pub fn chain_start() -> lagrange_core::State<[f64; 4]> {
    let (phi, w) = slow_shape();
    lagrange_core::State::new(0.0, phi, phi.map(|p| w * p))
}

/// The closed form x(t) = φ (cos ωt + sin ωt) of the slow mode.
pub fn chain_exact(t: f64) -> ([f64; 4], [f64; 4]) {
    let (phi, w) = slow_shape();
    let (s, c) = (w * t).sin_cos();
    (phi.map(|p| p * (c + s)), phi.map(|p| p * w * (c - s)))
}

/// q̈ = −K x / m, by hand.
pub fn chain_rhs(_t: f64, q: &[f64; 4], _v: &[f64; 4]) -> [f64; 4] {
    let (k0, k, m) = (CHAIN.k_wall, CHAIN.k, CHAIN.m);
    [
        (-k0 * q[0] + k * (q[1] - q[0])) / m,
        (k * (q[0] - q[1]) + k * (q[2] - q[1])) / m,
        (k * (q[1] - q[2]) + k * (q[3] - q[2])) / m,
        (k * (q[2] - q[3])) / m,
    ]
}

/// The Jacobian of (q̇, q̈) applied to (dq, dv): (dv, −K dq / m) (the chain is linear).
pub fn chain_jacobian_times(
    _t: f64,
    _q: &[f64; 4],
    _v: &[f64; 4],
    dq: &[f64; 4],
    dv: &[f64; 4],
) -> ([f64; 4], [f64; 4]) {
    (*dv, chain_rhs(0.0, dq, &[0.0; 4]))
}

#[mechanism]
pub mod cartesian_pendulum {
    /// The bob's position, pivot at the origin.
    pub struct Coords {
        pub x: f64,
        pub y: f64,
    }

    #[derive(Clone, Copy, Debug)]
    pub struct CartesianPendulum {
        pub m: f64,
        pub l: f64,
        pub g: f64,
    }

    #[particle(mass = m)]
    fn bob() -> Vec2 {
        vec2(x, y)
    }

    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }

    /// The rod keeps the bob at distance l from the pivot.
    #[constraint]
    fn rod() -> f64 {
        bob.norm() - l
    }
}

pub use cartesian_pendulum::CartesianPendulum;

/// Unit mass, length and gravity: the angle obeys θ̈ = −sin θ, the problems' pendulum.
pub const ROD: CartesianPendulum = CartesianPendulum {
    m: 1.0,
    l: 1.0,
    g: 1.0,
};

/// From θ(t) of the angle form: (x, y) = (sin θ, −cos θ), (ẋ, ẏ) = θ̇ (cos θ, sin θ).
pub fn cartesian_exact(t: f64) -> ([f64; 2], [f64; 2]) {
    let ([th], [w]) = pendulum_exact(t);
    let (s, c) = th.sin_cos();
    ([s, -c], [w * c, w * s])
}

/// At the bottom moving at 2k.
pub fn cartesian_start() -> lagrange_core::State<[f64; 2]> {
    lagrange_core::State::new(0.0, [0.0, -1.0], [2.0 * PENDULUM_K, 0.0])
}

/// q̈ of the Cartesian pendulum from its KKT system, by hand: with n = r/|r|, the constraint's
/// Jacobian G = nᵀ and γ = (|ṙ|² − (n·ṙ)²)/|r| (so that G q̈ = −γ, the constraint differentiated
/// twice), M = mI gives λ = n·𝓕 + mγ and q̈ = (𝓕 − nλ)/m, 𝓕 = (0, −mg).
pub fn cartesian_rhs(_t: f64, q: &[f64; 2], v: &[f64; 2]) -> [f64; 2] {
    let (m, g) = (ROD.m, ROD.g);
    let r = (q[0] * q[0] + q[1] * q[1]).sqrt();
    let n = [q[0] / r, q[1] / r];
    let radial = n[0] * v[0] + n[1] * v[1];
    let gamma = (v[0] * v[0] + v[1] * v[1] - radial * radial) / r;
    let force = [0.0, -m * g];
    let lambda = n[0] * force[0] + n[1] * force[1] + m * gamma;
    [
        (force[0] - n[0] * lambda) / m,
        (force[1] - n[1] * lambda) / m,
    ]
}

#[cfg(test)]
mod tests {
    use super::*;
    use lagrange::evaluation::Evaluate as _;

    fn close(a: &[f64], b: &[f64], tol: f64) {
        for (x, y) in a.iter().zip(b) {
            assert!((x - y).abs() <= tol * (1.0 + y.abs()), "{a:?} vs {b:?}");
        }
    }

    #[test]
    fn hand_written_right_hand_sides_match_the_declarations() {
        let q = [0.1, -0.2, 0.05, 0.3];
        // Entries of K are 2e6: the generated assembly and the hand-written sum round differently
        // at ~1e-16·2e6·|q|.
        close(
            &CHAIN.accelerations_at(0.0, &q, &[0.0; 4]).unwrap(),
            &chain_rhs(0.0, &q, &[0.0; 4]),
            1e-9,
        );
        let (q, v) = ([0.6, -0.8], [0.4, 0.3]);
        close(
            &ROD.accelerations_at(0.0, &q, &v).unwrap(),
            &cartesian_rhs(0.0, &q, &v),
            1e-12,
        );
    }

    #[test]
    fn stiff_chain_has_one_slow_and_three_stiff_modes() {
        let (omega, _) = chain_modes();
        assert!(omega[0] < 0.6 && omega[1] > 1000.0, "{omega:?}");
        // The closed form solves q̈ = −Kq/m: its second derivative (by the mode's ω²) matches.
        let t = 0.7;
        let (q, _) = chain_exact(t);
        let a = chain_rhs(t, &q, &[0.0; 4]);
        close(&a, &q.map(|x| -omega[0] * omega[0] * x), 1e-8);
    }

    #[test]
    fn cartesian_closed_form_satisfies_the_constraint_and_the_equations() {
        let (q, v) = cartesian_exact(1.3);
        assert!(((q[0] * q[0] + q[1] * q[1]).sqrt() - 1.0).abs() < 1e-14);
        assert!((q[0] * v[0] + q[1] * v[1]).abs() < 1e-12);
        let s = cartesian_start();
        close(&cartesian_exact(0.0).0, &s.q, 1e-15);
        close(&cartesian_exact(0.0).1, &s.v, 1e-15);
    }
}
