//! Potentials whose gradient the macro derives on the expression tree as written
//! (`Model::potential_gradient` without dual numbers) against the gradient of the same potential
//! on dual numbers seeded on every coordinate (what `lagrange_core::dynamics` takes without it):
//! springs of a chain, Kepler's −μ m/|r| in Cartesian and in polar coordinates, a spring between two
//! bodies, a potential that exercises every elementary function read, and one the macro does not
//! read (which keeps its dual numbers beside a read one).

use lagrange::__private::num_dual::{Derivative, DualSVec};
use lagrange::__private::Model;
use lagrange::prelude::*;
use nalgebra::SVector;

/// The Fermi–Pasta–Ulam chain's springs (Hairer, Lubich & Wanner, *Geometric Numerical
/// Integration*, 2nd ed., 2006, §I.5.1): a stiff one ω²/4 (q₁ − q₀)², soft ones (Δq)⁴.
#[mechanism]
pub mod fpu {
    pub struct Coords {
        pub q: [f64; 4],
    }
    pub struct Fpu {
        pub m: f64,
        pub omega: f64,
    }
    #[particle(mass = m, count = 4)]
    fn mass(i: usize) -> Vec2 {
        vec2(q[i], 0.0)
    }
    #[potential]
    fn stiff() -> f64 {
        omega * omega / 4.0 * (q[1] - q[0]).powi(2)
    }
    #[potential]
    fn soft() -> f64 {
        q[0].powi(4) + (q[2] - q[1]).powi(4) + (q[3] - q[2]).powi(4)
    }
}

/// Kepler's problem in Cartesian coordinates, the potential through the body.
#[mechanism]
pub mod kepler_cartesian {
    pub struct Coords {
        pub x: f64,
        pub y: f64,
    }
    pub struct Kepler {
        pub m: f64,
        pub mu: f64,
    }
    #[particle(mass = m)]
    fn planet() -> Vec2 {
        vec2(x, y)
    }
    #[potential]
    fn gravitation() -> f64 {
        -mu * m / planet.norm()
    }
}

/// Kepler's problem in polar coordinates, the potential through the body: ∂V/∂φ = 0 by the chain
/// rule through J, ∂V/∂r = μ m/r².
#[mechanism]
pub mod kepler_polar {
    pub struct Coords {
        pub r: f64,
        pub phi: f64,
    }
    pub struct Kepler {
        pub m: f64,
        pub mu: f64,
    }
    #[particle(mass = m)]
    fn planet() -> Vec2 {
        vec2(phi.cos(), phi.sin()) * r
    }
    #[potential]
    fn gravitation() -> f64 {
        -mu * m / planet.norm()
    }
}

/// Two pucks on a plane tied by a spring of rest length l₀, ½ k (|a − b| − l₀)²; a planar body whose
/// angle is held by a torsion spring that moves in time, and a potential with every function read.
#[mechanism]
pub mod tied {
    pub struct Coords {
        pub ax: f64,
        pub ay: f64,
        pub bx: f64,
        pub by: f64,
        pub theta: f64,
    }
    pub struct Tied {
        pub m: f64,
        pub k: f64,
        pub rest: f64,
        pub c: f64,
        pub e: f64,
        pub alpha: f64,
    }
    #[particle(mass = m)]
    fn a() -> Vec2 {
        vec2(ax, ay)
    }
    #[particle(mass = m)]
    fn b() -> Vec2 {
        vec2(bx, by)
    }
    #[rigid_body(mass = m, inertia = 0.1)]
    fn plate() -> Planar {
        planar(b + vec2(theta.cos(), theta.sin()) * 0.5, theta)
    }
    #[potential]
    fn spring() -> f64 {
        let stretch = (a - b).norm() - rest;
        0.5 * k * stretch * stretch
    }
    #[potential]
    fn torsion() -> f64 {
        c * (plate.angle - 0.3 * (2.0 * t).sin()).powi(2) / 2
    }
    #[potential]
    fn everything() -> f64 {
        let (d, r2) = (a - plate.position, (a - b).norm_squared());
        e * (1.0 + d.dot(&d)).ln() + alpha.cos() * (0.1 * ay).exp() / (1.0 + r2)
            - e * theta.cos().recip().sqrt() * std::f64::consts::FRAC_1_SQRT_2
            + e * (1.0 + r2).powi(-2)
    }
}

/// A potential the tree reader does not read (`abs`, `powf`) beside one it reads: the first keeps
/// its dual numbers, narrow, the second is derived.
#[mechanism]
pub mod mixed {
    pub struct Coords {
        pub x: [f64; 3],
    }
    pub struct Mixed {
        pub m: f64,
        pub k: f64,
    }
    #[particle(mass = m, count = 3)]
    fn bead(i: usize) -> Vec2 {
        vec2(x[i], 0.0)
    }
    #[potential]
    fn unread() -> f64 {
        k * (x[1] - x[0]).abs().powf(3.5)
    }
    #[potential]
    fn read() -> f64 {
        k * (bead[2].x - bead[1].x).powi(2)
    }
}

/// Two particles of different masses, each moved by one coordinate with a factor (rows of x that
/// are not coordinates, so the spring between them is derived by the rows and added through J),
/// and a pin on one coordinate: affine positions, diagonal M.
#[mechanism]
pub mod stretched {
    pub struct Coords {
        pub a: f64,
        pub b: f64,
    }
    pub struct Stretched {
        pub m1: f64,
        pub m2: f64,
        pub k: f64,
    }
    #[particle(mass = m1)]
    fn p() -> Vec2 {
        vec2(2.0 * a + 0.3, 0.0)
    }
    #[particle(mass = m2)]
    fn r() -> Vec2 {
        vec2(0.0, 3.0 * b)
    }
    #[potential]
    fn spring() -> f64 {
        k * ((p - r).norm() - 1.0).powi(2)
    }
    #[potential]
    fn pin() -> f64 {
        k * a.powi(2) / 3.0
    }
}

/// Eighteen masses, each on its own spring to a wall: eighteen constant factors sⱼ k (one per
/// slot), more than a handle prepares; the others are computed where they are used.
#[mechanism]
pub mod many {
    pub struct Coords {
        pub q: [f64; 18],
    }
    pub struct Many {
        pub m: f64,
        pub k: f64,
    }
    #[particle(mass = m, count = 18)]
    fn bead(i: usize) -> Vec2 {
        vec2(q[i], 0.0)
    }
    #[potential]
    fn walls() -> f64 {
        k * (q[0].powi(2)
            + q[1].powi(2)
            + q[2].powi(2)
            + q[3].powi(2)
            + q[4].powi(2)
            + q[5].powi(2)
            + q[6].powi(2)
            + q[7].powi(2)
            + q[8].powi(2)
            + q[9].powi(2)
            + q[10].powi(2)
            + q[11].powi(2)
            + q[12].powi(2)
            + q[13].powi(2)
            + q[14].powi(2)
            + q[15].powi(2)
            + q[16].powi(2)
            + q[17].powi(2))
    }
}

/// x and its Jacobian rows at (t, q), from `cartesian` on dual numbers.
#[allow(clippy::type_complexity)]
fn positions<M: Model<N, K>, const N: usize, const K: usize>(
    sys: &M,
    t: f64,
    q: [f64; N],
) -> ([f64; K], [Option<SVector<f64, N>>; K]) {
    let qd: [DualSVec<f64, N>; N] = std::array::from_fn(|j| DualSVec::from_re(q[j]).derivative(j));
    let xd = sys.cartesian(DualSVec::from_re(t), &qd);
    (
        std::array::from_fn(|i| xd[i].re),
        std::array::from_fn(|i| xd[i].eps.0),
    )
}

/// (`scaled_potential_gradient` with `scale` and its coefficients, `scale` ⊙
/// `potential_gradient`) at (t, q); `None` where the macro writes no scaled gradient.
fn scaled_gradients<M: Model<N, K>, const N: usize, const K: usize>(
    sys: &M,
    t: f64,
    q: [f64; N],
    scale: [f64; N],
) -> Option<(SVector<f64, N>, SVector<f64, N>)> {
    let (x, rows) = positions(sys, t, q);
    let prepared = sys.gradient_coefficients(&scale);
    let scaled = sys.scaled_potential_gradient(t, &q, &x, &rows, &scale, &prepared)?;
    let plain = sys.potential_gradient(t, &q, &x, &rows).unwrap();
    Some((scaled, plain.component_mul(&SVector::from(scale))))
}

/// (symbolic ∇V, dual-number ∇V) at (t, q): x and J from `cartesian` on dual numbers, then
/// `potential_gradient` and V on dual numbers seeded on every coordinate, x carrying J.
fn gradients<M: Model<N, K>, const N: usize, const K: usize>(
    sys: &M,
    t: f64,
    q: [f64; N],
) -> (SVector<f64, N>, SVector<f64, N>) {
    let qd: [DualSVec<f64, N>; N] = std::array::from_fn(|j| DualSVec::from_re(q[j]).derivative(j));
    let (x, rows) = positions(sys, t, q);
    let symbolic = sys
        .potential_gradient(t, &q, &x, &rows)
        .expect("the macro writes potential_gradient");
    let xr: [DualSVec<f64, N>; K] =
        std::array::from_fn(|i| DualSVec::new(x[i], Derivative::new(rows[i])));
    let v = sys.potential(DualSVec::from_re(t), &qd, &xr);
    (symbolic, v.eps.0.unwrap_or_else(SVector::zeros))
}

/// The two gradients agree to round-off. Both evaluate the same elementary operations on the same
/// differences (neither expands a power), each rounding to ½ ulp, in a few tens of operations and
/// in a different order for the chain rule's sums: their difference is a few tens of ulps of the
/// largest term, so 1e-13 (≈ 450 ulps) of the largest entry bounds it with room.
fn assert_agree<const N: usize>(symbolic: SVector<f64, N>, dual: SVector<f64, N>, what: &str) {
    let scale = symbolic
        .iter()
        .chain(&dual)
        .fold(1e-300f64, |m, g| m.max(g.abs()));
    for (s, d) in symbolic.iter().zip(&dual) {
        assert!(
            (s - d).abs() <= 1e-13 * scale,
            "{what}: {symbolic:?} vs {dual:?}"
        );
    }
}

/// A point of a smooth curve through the state space, i = 0, 1, …
fn wiggle(i: usize, j: usize) -> f64 {
    let (f, g) = (i as f64, j as f64);
    (0.7 * f + 1.3 * g).sin() * 0.8 + 0.1 * g
}

#[test]
fn chain_springs_agree_with_dual_numbers() {
    let sys = fpu::Fpu {
        m: 1.0,
        omega: 50.0,
    };
    for i in 0..20 {
        let q = std::array::from_fn(|j| wiggle(i, j));
        let (s, d) = gradients(&sys, 0.0, q);
        assert_agree(s, d, "FPU");
        // By hand: ∂/∂q₀ of ω²/4 (q₁ − q₀)² + q₀⁴ + (q₂ − q₁)⁴ + (q₃ − q₂)⁴.
        let w2 = 2500.0;
        let by_hand = -w2 / 2.0 * (q[1] - q[0]) + 4.0 * q[0].powi(3);
        assert!((s[0] - by_hand).abs() <= 1e-13 * s.abs().max(), "{s:?}");
    }
}

#[test]
fn kepler_agrees_in_cartesian_and_polar_coordinates() {
    let cartesian = kepler_cartesian::Kepler { m: 2.0, mu: 1.5 };
    let polar = kepler_polar::Kepler { m: 2.0, mu: 1.5 };
    for i in 0..20 {
        let (r, phi) = (0.4 + 0.06 * i as f64, 0.9 * i as f64 - 3.0);
        let (s, d) = gradients(&cartesian, 0.0, [r * phi.cos(), r * phi.sin()]);
        assert_agree(s, d, "Kepler, Cartesian");
        // ∇(−μ m/|x|) = μ m x/|x|³.
        assert!((s[0] - 3.0 * phi.cos() / (r * r)).abs() <= 1e-13 * s.abs().max());
        let (s, d) = gradients(&polar, 0.0, [r, phi]);
        assert_agree(s, d, "Kepler, polar");
        assert!((s[0] - 3.0 / (r * r)).abs() <= 1e-13 * s[0].abs(), "{s:?}");
        // ∂V/∂φ cancels in Jᵀ ∂V/∂x to rounding of the terms μ m/r².
        assert!(s[1].abs() <= 1e-13 * s[0].abs(), "{s:?}");
    }
}

#[test]
fn a_spring_between_bodies_and_every_function_read_agree() {
    let sys = tied::Tied {
        m: 1.0,
        k: 40.0,
        rest: 0.5,
        c: 3.0,
        e: 0.25,
        alpha: 0.4,
    };
    for i in 0..20 {
        let q: [f64; 5] = std::array::from_fn(|j| wiggle(i, j));
        // θ = wiggle ∈ [−0.4, 1.2], within (−π/2, π/2) where √(1/cos θ) is defined.
        let q = [q[0], q[1], q[2] + 1.0, q[3], q[4]];
        let (s, d) = gradients(&sys, 0.1 * i as f64, q);
        assert_agree(s, d, "tied pucks");
    }
}

#[test]
fn an_unread_potential_keeps_its_dual_numbers_beside_a_read_one() {
    let sys = mixed::Mixed { m: 1.0, k: 2.0 };
    for i in 0..20 {
        let q = std::array::from_fn(|j| wiggle(i, j));
        let (s, d) = gradients(&sys, 0.0, q);
        assert_agree(s, d, "mixed");
    }
}

#[test]
fn accelerations_agree_with_the_closed_form() {
    // Kepler in polar coordinates: r̈ = r φ̇² − μ/r², φ̈ = −2 ṙ φ̇/r.
    let sys = kepler_polar::Kepler { m: 2.0, mu: 1.5 };
    let s = kepler_polar::State::new(
        0.0,
        kepler_polar::Coords { r: 0.8, phi: 0.3 },
        kepler_polar::Coords { r: 0.2, phi: 1.1 },
    );
    let a = sys.accelerations(&s).unwrap();
    // Entries of size 2; a few roundings of each term: 1e-13 is a few hundred ulps.
    let (r, rd, pd) = (0.8, 0.2, 1.1);
    assert!((a.r - (r * pd * pd - 1.5 / (r * r))).abs() < 1e-13);
    assert!((a.phi - (-2.0 * rd * pd / r)).abs() < 1e-13);
}

#[test]
fn scaled_gradients_agree_with_the_gradient_times_the_scales() {
    // Written for affine positions with every potential read: each slot's scale joins the
    // constant factors of its derivatives (for the coordinates) or its row of J (for the rows).
    // The products are the same factors in another order; `assert_agree`'s bound holds.
    let (fpu, kepler) = (
        fpu::Fpu {
            m: 1.0,
            omega: 50.0,
        },
        kepler_cartesian::Kepler { m: 2.0, mu: 1.5 },
    );
    let stretched = stretched::Stretched {
        m1: 1.0,
        m2: 2.5,
        k: 7.0,
    };
    for i in 0..20 {
        let q: [f64; 4] = std::array::from_fn(|j| wiggle(i, j));
        let (s, d) = scaled_gradients(&fpu, 0.0, q, [-0.7, 1.3, -2.0 / 3.0, 0.1]).unwrap();
        assert_agree(s, d, "FPU, scaled");
        let (r, phi) = (0.4 + 0.06 * i as f64, 0.9 * i as f64 - 3.0);
        let q = [r * phi.cos(), r * phi.sin()];
        let (s, d) = scaled_gradients(&kepler, 0.0, q, [-1.0 / 3.0, 0.6]).unwrap();
        assert_agree(s, d, "Kepler, scaled");
        let q = [wiggle(i, 0), wiggle(i, 1)];
        let (s, d) = scaled_gradients(&stretched, 0.0, q, [-0.3, -1.0 / 7.0]).unwrap();
        assert_agree(s, d, "stretched, scaled");
        let (s, d) = gradients(&stretched, 0.0, q);
        assert_agree(s, d, "stretched");
    }
    // More constant factors than are prepared.
    let many = many::Many { m: 1.0, k: 3.0 };
    for i in 0..5 {
        let q: [f64; 18] = std::array::from_fn(|j| wiggle(i, j));
        let scale = std::array::from_fn(|j| -1.0 / (1.0 + j as f64));
        let (s, d) = scaled_gradients(&many, 0.0, q, scale).unwrap();
        assert_agree(s, d, "many, scaled");
    }
    // Not written where the positions are not affine (the handle has no constant M to scale by).
    let polar = kepler_polar::Kepler { m: 2.0, mu: 1.5 };
    assert!(scaled_gradients(&polar, 0.0, [0.8, 0.3], [1.0, 1.0]).is_none());
    // Nor where a potential keeps its dual numbers.
    let mixed = mixed::Mixed { m: 1.0, k: 2.0 };
    assert!(scaled_gradients(&mixed, 0.0, [0.1, 0.2, 0.3], [1.0; 3]).is_none());
}

#[test]
fn the_handle_of_a_diagonal_mass_matrix_agrees_with_the_checked_path() {
    // Through the handle q̈ⱼ = sⱼ ∂V/∂qⱼ with sⱼ = −1/Mⱼⱼ joined to the derivative's constants;
    // the checked path assembles M at the state and solves. Each entry is the same real product
    // (μ m x / (r² √r²)) (1/Mⱼⱼ), or the same sum of such products, rounded in another order: a
    // few roundings apart, relative to the largest term (1e-13 ≈ 450 ulps bounds it with room).
    let sys = || stretched::Stretched {
        m1: 1.0,
        m2: 2.5,
        k: 7.0,
    };
    let (handle, sys) = (sys().validated().unwrap(), sys());
    for i in 0..20 {
        let q = stretched::Coords {
            a: wiggle(i, 0),
            b: wiggle(i, 1),
        };
        let s = stretched::State::at_rest(q);
        let (a, b) = (
            handle.accelerations(&s).unwrap(),
            sys.accelerations(&s).unwrap(),
        );
        let scale = a.a.abs().max(a.b.abs()).max(1.0);
        assert!((a.a - b.a).abs() <= 1e-13 * scale, "{a:?} vs {b:?}");
        assert!((a.b - b.b).abs() <= 1e-13 * scale, "{a:?} vs {b:?}");
    }
}
