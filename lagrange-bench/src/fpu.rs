//! The Fermi–Pasta–Ulam chain of Hairer, Lubich & Wanner, *Geometric Numerical Integration*,
//! §I.5.1: six unit masses between fixed walls, joined alternately by soft cubic springs (energy
//! (Δq)⁴) and stiff linear springs (energy ω²/4 (Δq)²):
//! V = ω²/4 Σᵢ (q₂ᵢ₊₁ − q₂ᵢ)² + Σᵢ (q₂ᵢ − q₂ᵢ₋₁)⁴ (0-based, q₋₁ = q₆ = 0), each spring declared
//! as a potential of its own (so each gradient is taken on its own two coordinates); and its
//! forces written by hand. The callgrind driver (`scripts/callgrind/`) compiles this file as well, so
//! the report and the instruction counts measure one declaration.

use lagrange::prelude::*;

#[mechanism]
pub mod fpu_chain {
    pub const MASSES: usize = 6;

    /// Positions of the masses along the line (from their rest positions).
    pub struct Coords {
        pub q: [f64; MASSES],
    }

    #[derive(Clone, Copy, Debug)]
    pub struct Fpu {
        /// Each mass.
        pub m: f64,
        /// The stiff springs' frequency.
        pub omega: f64,
    }

    #[particle(mass = m, count = MASSES)]
    fn mass(i: usize) -> Vec2 {
        vec2(q[i], 0.0)
    }

    /// The stiff springs, ω²/4 (Δq)².
    #[potential]
    fn stiff1() -> f64 {
        omega * omega / 4.0 * (q[1] - q[0]).powi(2)
    }
    #[potential]
    fn stiff2() -> f64 {
        omega * omega / 4.0 * (q[3] - q[2]).powi(2)
    }
    #[potential]
    fn stiff3() -> f64 {
        omega * omega / 4.0 * (q[5] - q[4]).powi(2)
    }

    /// The soft springs, (Δq)⁴, two of them to the walls.
    #[potential]
    fn wall_left() -> f64 {
        q[0].powi(4)
    }
    #[potential]
    fn soft1() -> f64 {
        (q[2] - q[1]).powi(4)
    }
    #[potential]
    fn soft2() -> f64 {
        (q[4] - q[3]).powi(4)
    }
    #[potential]
    fn wall_right() -> f64 {
        q[5].powi(4)
    }
}

/// −∂V/∂q of the chain, by hand; with unit masses, its accelerations q̈.
pub fn fpu_forces(omega: f64, q: &[f64; 6]) -> [f64; 6] {
    let w2 = omega * omega;
    let mut f = [0.0; 6];
    for i in 0..3 {
        // ω²/4 (q₂ᵢ₊₁ − q₂ᵢ)²: force ∓ ω²/2 (q₂ᵢ₊₁ − q₂ᵢ).
        let d = q[2 * i + 1] - q[2 * i];
        f[2 * i] += 0.5 * w2 * d;
        f[2 * i + 1] -= 0.5 * w2 * d;
    }
    // (Δ)⁴: force ∓ 4Δ³.
    f[0] -= 4.0 * q[0].powi(3);
    for (a, b) in [(1, 2), (3, 4)] {
        let d = q[b] - q[a];
        f[a] += 4.0 * d.powi(3);
        f[b] -= 4.0 * d.powi(3);
    }
    f[5] -= 4.0 * q[5].powi(3);
    f
}
