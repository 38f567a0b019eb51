//! A heavy symmetric top on a fixed point, its orientation a rotation vector about the pivot: the
//! rigid tree's ball joint (`lagrange::tree::rigid::JointKind::Ball`), stepped through the chart's
//! switches (the top spins at 20 rad/s, so the rotation vector passes π about every 0.3 s).
//!
//! Closed form: steady precession (Goldstein, Poole & Safko, *Classical Mechanics*, 3rd ed., §5.7;
//! Landau & Lifshitz, *Mechanics*, §35, problem 1). With A the moment about a horizontal axis
//! through the pivot, C about the symmetry axis, l the pivot's distance to the centre of mass and
//! z-x-z Euler angles (φ precession, θ nutation, ψ spin), L = ½A(θ̇² + φ̇² sin²θ) + ½C ω₃² − m g l
//! cos θ with ω₃ = ψ̇ + φ̇ cos θ; Lagrange's equation in θ at θ̇ = θ̈ = 0 is
//! m g l = C ω₃ Ω − A Ω² cos θ₀, so a top started at θ₀ with spin ω₃ and precession
//! Ω = (C ω₃ − √(C² ω₃² − 4 A m g l cos θ₀)) / (2 A cos θ₀) (the slow root) keeps θ = θ₀ and turns
//! its axis about the vertical at Ω.

use lagrange::geometry::{chart_rates, RotationChart};
use lagrange::prelude::*;
use lagrange::tree::rigid::{JointKind, RigidTree, Velocities};

#[mechanism]
pub mod top {
    pub struct Coords {
        /// The rotation vector of the top's frame: its symmetry axis is the frame's z.
        pub phi: [f64; 3],
    }
    pub struct Top {
        pub m: f64,
        /// Moments about the centre of mass: a about the transverse axes, c about the symmetry axis.
        pub a: f64,
        pub c: f64,
        /// The centre of mass's distance from the pivot, along the symmetry axis.
        pub l: f64,
        pub g: f64,
    }
    #[rigid_body(mass = m, inertia = [a, a, c])]
    fn body() -> Spatial {
        let r = rot_vector(vec3(phi[0], phi[1], phi[2]));
        spatial(vec3(0.0, 0.0, 0.0) + r * vec3(0.0, 0.0, l), r)
    }
    #[gravity]
    fn down() -> Vec3 {
        vec3(0.0, 0.0, -g)
    }
}

const TOP: top::Top = top::Top {
    m: 1.0,
    a: 0.02,
    c: 0.04,
    l: 0.1,
    g: 9.81,
};
const THETA0: f64 = 0.5;
const SPIN: f64 = 20.0;

/// The slow steady precession rate Ω at θ₀ and ω₃ (see the module docs); A about the pivot.
fn precession() -> f64 {
    let a = TOP.a + TOP.m * TOP.l * TOP.l;
    let (c, cos) = (TOP.c, THETA0.cos());
    let mgl = TOP.m * TOP.g * TOP.l;
    (c * SPIN - (c * c * SPIN * SPIN - 4.0 * a * mgl * cos).sqrt()) / (2.0 * a * cos)
}

/// The start: turned by θ₀ about x (φ = ψ = 0), body-frame ω = (θ̇, Ω sin θ₀, ω₃) with θ̇ = 0.
fn start() -> top::State {
    let phi = [THETA0, 0.0, 0.0];
    let omega = [0.0, precession() * THETA0.sin(), SPIN];
    let rates = chart_rates(RotationChart::Vector, phi, omega).unwrap();
    top::State::new(0.0, top::Coords { phi }, top::Coords { phi: rates })
}

/// The largest departures over `duration` of θ from θ₀ and of the axis's azimuth from Ω t,
/// sampled every 0.1 s, RK4 at step `h`.
fn departures(h: f64, duration: f64) -> (f64, f64) {
    let sys = TOP.validated().unwrap();
    let mut s = start();
    let omega = precession();
    let (mut theta_error, mut azimuth_error) = (0.0_f64, 0.0_f64);
    let per_sample = (0.1 / h).round() as usize;
    for step in 1..=(duration / h).round() as usize {
        sys.step::<Rk4>(&mut s, h).unwrap();
        if step % per_sample != 0 {
            continue;
        }
        // The symmetry axis R e_z = (sin θ sin φ, −sin θ cos φ, cos θ).
        let axis = sys.bodies(&s).body.rotation * vec3(0.0, 0.0, 1.0);
        theta_error = theta_error.max((axis.z.acos() - THETA0).abs());
        let azimuth = axis.x.atan2(-axis.y);
        // The difference taken to (−π, π]: the axis goes round more than once.
        let pi = std::f64::consts::PI;
        let difference = (azimuth - omega * s.t + pi).rem_euclid(2.0 * pi) - pi;
        azimuth_error = azimuth_error.max(difference.abs());
    }
    (theta_error, azimuth_error)
}

#[test]
fn the_top_is_a_ball_joint() {
    let joints = <top::Top as RigidTree<3, 1>>::JOINTS;
    assert_eq!(
        joints[0].kind,
        JointKind::Ball(RotationChart::Vector, Velocities::ChartRates)
    );
}

/// Over 5 s (Ω ≈ 1.28 rad/s: a turn of precession; ≈ 16 chart switches) the top keeps θ₀
/// and precesses at Ω with the error of a fourth-order method: halving the step divides the
/// departures by about 16 (12 to 20 allowed: at h = 2 ms, hω₃ = 0.04, the h⁵ term still shifts
/// the ratio). Their size: RK4's local error is of order (hω₃)⁵/5! ≈ 8.5·10⁻¹⁰ rad per step at
/// h = 2 ms, so 2 500 steps stay below ≈ 2·10⁻⁶ rad.
#[test]
fn a_top_in_steady_precession_keeps_its_angle_and_rate() {
    let omega = precession();
    assert!((1.2..1.3).contains(&omega), "Ω = {omega}");
    let coarse = departures(2e-3, 5.0);
    let fine = departures(1e-3, 5.0);
    assert!(coarse.0 < 2e-6 && coarse.1 < 2e-6, "{coarse:?}");
    let ratios = (coarse.0 / fine.0, coarse.1 / fine.1);
    assert!((12.0..20.0).contains(&ratios.0), "{ratios:?}");
    assert!((12.0..20.0).contains(&ratios.1), "{ratios:?}");
}
