//! The canonical field (p, ṗ) that implicit midpoint, Gauss–Legendre and the variational integrator
//! evaluate at every Newton iteration: `#[mechanism]` computes a scleronomic mechanism's from one
//! hyper-dual pass (`lagrange::dynamics::canonical_field`). It must equal the definition — the
//! momenta ∂L/∂q̇ and ∂T/∂q + 𝓕 by passes of their own, what the trait's default computes — for
//! points, rigid bodies, potentials, applied forces and constraints alike, and on dual numbers
//! (the implicit methods differentiate it for their Newton matrix).

use lagrange::evaluation::Evaluate as _;
use lagrange::integrate::momentum_rate;
use lagrange::prelude::*;
use nalgebra::SVector;
use num_dual::DualSVec;

#[mechanism]
pub mod sprung_pendulum {
    pub struct Coords {
        pub theta1: f64,
        pub theta2: f64,
        pub r: f64,
    }
    pub struct Params {
        pub m1: f64,
        pub m2: f64,
        pub l1: f64,
        pub k: f64,
        pub c: f64,
        pub g: f64,
    }
    #[particle(mass = m1)]
    fn bob1() -> Vec2 {
        vec2(theta1.sin(), -theta1.cos()) * l1
    }
    #[particle(mass = m2)]
    fn bob2() -> Vec2 {
        bob1 + vec2(theta2.sin(), -theta2.cos()) * r
    }
    #[potential]
    fn spring() -> f64 {
        (r - 1.0) * (r - 1.0) * (0.5 * k)
    }
    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
    #[force(on = bob2)]
    fn drag() -> Vec2 {
        bob2_dot * (-c)
    }
}

#[mechanism]
pub mod crank {
    pub struct Coords {
        pub theta: f64,
        pub s: f64,
    }
    pub struct Params {
        pub m: f64,
        pub l: f64,
        pub slider: f64,
        pub g: f64,
    }
    #[rigid_body(mass = m, inertia = m * l * l / 12.0)]
    fn bar() -> Planar {
        planar(vec2(theta.cos(), theta.sin()) * (0.5 * l), theta)
    }
    #[particle(mass = slider)]
    fn block() -> Vec2 {
        vec2(s, 0.0)
    }
    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
    /// The bar's tip slides on the block.
    #[constraint]
    fn pinned() -> f64 {
        bar.point(vec2(0.5 * l, 0.0)).x - block.x
    }
}

/// The field by the one-pass override and by its definition agree to round-off: both sum the same
/// products, in a different order (a few ulps of the largest term, |ṗ| ≲ 30 here).
fn assert_same_field<M: Mechanism<N>, const N: usize>(sys: &M, q: [f64; N], v: [f64; N]) {
    let (p, rate) = sys.canonical_field_at(0.3, &q, &v);
    let (p_def, rate_def) = (sys.momenta_at(0.3, &q, &v), momentum_rate(sys, 0.3, &q, &v));
    for k in 0..N {
        assert!(
            (p[k] - p_def[k]).abs() < 1e-12,
            "p[{k}]: {p:?} vs {p_def:?}"
        );
        assert!(
            (rate[k] - rate_def[k]).abs() < 1e-12,
            "ṗ[{k}]: {rate:?} vs {rate_def:?}"
        );
    }
    // On gradient duals seeded on q (the Newton matrix's ∂/∂q): the derivatives agree as well.
    let qd: [DualSVec<f64, N>; N] = std::array::from_fn(|j| DualSVec::from_re(q[j]).derivative(j));
    let vd: [DualSVec<f64, N>; N] = std::array::from_fn(|j| DualSVec::from_re(v[j]));
    let t = DualSVec::from_re(0.3);
    let (pd, rated) = sys.canonical_field_at(t, &qd, &vd);
    let (pd_def, rated_def) = (sys.momenta_at(t, &qd, &vd), momentum_rate(sys, t, &qd, &vd));
    for k in 0..N {
        let d = |x: &DualSVec<f64, N>| x.eps.0.unwrap_or_else(SVector::zeros);
        assert!((d(&pd[k]) - d(&pd_def[k])).norm() < 1e-11, "∂p[{k}]/∂q");
        assert!(
            (d(&rated[k]) - d(&rated_def[k])).norm() < 1e-10,
            "∂ṗ[{k}]/∂q"
        );
        assert!((rated[k].re - rated_def[k].re).abs() < 1e-12);
    }
}

#[test]
fn one_pass_field_is_the_definition_for_points_potentials_and_forces() {
    let sys = sprung_pendulum::Params {
        m1: 1.0,
        m2: 1.3,
        l1: 0.9,
        k: 40.0,
        c: 0.2,
        g: 9.81,
    };
    assert_same_field(&sys, [0.7, -1.2, 1.1], [1.1, -0.4, 0.3]);
    assert_same_field(
        &sys.validated().unwrap(),
        [0.1, 2.0, 0.9],
        [-2.0, 0.5, -0.1],
    );
}

#[test]
fn one_pass_field_is_the_definition_for_rigid_bodies_and_constraints() {
    let sys = crank::Params {
        m: 2.0,
        l: 1.5,
        slider: 0.5,
        g: 9.81,
    };
    assert_same_field(&sys, [0.4, 0.75 * 0.4f64.cos()], [0.8, -0.3]);
}

/// A scleronomic mechanism's velocities from its momenta are one solve with M (p = M q̇): the
/// velocities that give back the momenta, to the solve's round-off (cond(M) ε ≈ 1e-15 here).
#[test]
fn velocities_from_momenta_invert_the_momenta() {
    use lagrange::Variational;
    let sys = sprung_pendulum::Params {
        m1: 1.0,
        m2: 1.3,
        l1: 0.9,
        k: 40.0,
        c: 0.2,
        g: 9.81,
    };
    let (q, v) = ([0.7, -1.2, 1.1], [1.1, -0.4, 0.3]);
    let p = sys.momenta_at(0.0, &q, &v);
    let (back, iterations) =
        Variational::velocities_from_momenta(&sys, 0.0, &q, &p, &[0.0; 3]).unwrap();
    assert_eq!(iterations, 1);
    for k in 0..3 {
        assert!((back[k] - v[k]).abs() < 1e-13, "{back:?} vs {v:?}");
    }
}
