//! A gyroscope driven by a torque: a symmetric rigid body (moments A, A, C) pivoted at its centre,
//! spinning about its symmetry axis a, with a torque τ = k (e_z × a) — horizontal, perpendicular to
//! the axis, the torque gravity exerts on a top whose centre is a distance l above the pivot
//! (k = m g l). Euler angles z-x-z: precession φ, nutation θ, spin ψ.
//!
//! Closed form (steady precession; Goldstein, Poole & Safko, *Classical Mechanics*, 3rd ed., §5.7):
//! with the spin ω₃ = ψ̇ + φ̇ cos θ about the axis, θ stays at θ₀ and φ turns at the constant rate Ω
//! when k = Ω (C ω₃ − A Ω cos θ₀), i.e. the slow root Ω = 2k / (C ω₃ + √(C²ω₃² − 4 A k cos θ₀))
//! — so θ(t) = θ₀, φ(t) = Ω t, and ω₃ is conserved. For a fast spin Ω ≈ k / (C ω₃), the
//! textbook gyroscopic precession.

use crate::Check;
use lagrange::animation::Recorder;
use lagrange::prelude::*;
use std::path::Path;

#[mechanism]
pub mod gyroscope {
    /// Euler angles z-x-z: precession, nutation, spin.
    pub struct Coords {
        pub phi: f64,
        pub theta: f64,
        pub psi: f64,
    }

    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct Gyroscope {
        pub m: f64,
        /// Moment of inertia about any axis through the pivot perpendicular to the symmetry axis.
        pub a: f64,
        /// Moment of inertia about the symmetry axis.
        pub c: f64,
        /// The torque's magnitude per unit sin θ.
        pub k: f64,
    }

    #[rigid_body(mass = m, inertia = [a, a, c])]
    fn rotor() -> Spatial {
        spatial(vec3(0.0, 0.0, 0.0), rot_z(phi) * rot_x(theta) * rot_z(psi))
    }

    /// τ = k (e_z × a), a the symmetry axis (the rotation's third column), in the world frame.
    #[torque(on = rotor)]
    fn drive() -> Vec3 {
        vec3(0.0, 0.0, k).cross(&rotor.rotation.column(2))
    }
}

const SCENE: &str = "gyroscope driven by a torque";

pub fn run(plots: &Path) -> Vec<Check> {
    use gyroscope::{Coords, Gyroscope, State};
    let sys = Gyroscope {
        m: 1.0,
        a: 0.5,
        c: 0.8,
        k: 2.0,
    };
    let (theta0, spin) = (1.0f64, 40.0);
    let cos = theta0.cos();
    // The slow root, written without the cancellation of C ω₃ − √(…) (the two are close).
    let precession = 2.0 * sys.k
        / (sys.c * spin + (sys.c * sys.c * spin * spin - 4.0 * sys.a * sys.k * cos).sqrt());
    let mut s = State::new(
        0.0,
        Coords {
            phi: 0.0,
            theta: theta0,
            psi: 0.0,
        },
        Coords {
            phi: precession,
            theta: 0.0,
            psi: spin - precession * cos,
        },
    );
    let start = sys.accelerations(&s).expect("accelerations");
    let h = 1e-4;
    // The symmetry axis's tip traces the precession cone; the rotor's frame shows the spin.
    let mut film = Recorder::new(&sys)
        .title(SCENE)
        .frame_rate(60.0)
        .expect("60 frames per second");
    film.mark("axis tip", "rotor", &[0.0, 0.0, 1.0])
        .and_then(|f| f.trail("axis tip"))
        .expect("the symmetry axis");
    film.push(&sys, &s).expect("a finite state");
    sys.simulate::<Rk4>(&mut s, h, 20_000, film.observer(&sys))
        .expect("simulation");
    let _ = film.write_html(plots.join("gyroscope.html"));
    let t = s.t;
    let spin_now = s.v.psi + s.v.phi * s.q.theta.cos();
    vec![
        // Steady precession is an equilibrium of the nutation: θ̈ = 0 at the start, up to the
        // round-off of terms of size C ω₃ Ω ≈ 3.
        Check::new(SCENE, "θ̈(0) at steady precession", start.theta, 0.0, 1e-12),
        // RK4 at h = 10⁻⁴ with the spin ω₃ = 40 the fastest rate: global error of order
        // (ω₃ h)⁴ ω₃ t ≈ 2·10⁻⁸ at most over 2 s, far less on this smooth steady motion.
        Check::new(
            SCENE,
            format!("θ(t = {t:.0}) = θ₀"),
            s.q.theta,
            theta0,
            5e-8,
        ),
        Check::new(
            SCENE,
            format!(
                "φ(t = {t:.0}) = Ω t, Ω = {precession:.4} (k/(C ω₃) = {:.4})",
                sys.k / (sys.c * spin)
            ),
            s.q.phi,
            precession * t,
            5e-8,
        ),
        Check::new(SCENE, "spin ω₃ conserved", spin_now, spin, 5e-8),
    ]
}
