//! A gyroscope driven by a torque: a symmetric rigid body (moments A, A, C) pivoted at its centre,
//! spinning about its symmetry axis a, with a torque τ = k (e_z × a) — horizontal, perpendicular to
//! the axis, the torque gravity exerts on a top whose centre is a distance l above the pivot
//! (k = m g l). Euler angles z-x-z: precession φ, nutation θ, spin ψ.
//!
//! Closed form (steady precession; Goldstein, Poole & Safko, *Classical Mechanics*, 3rd ed., §5.7):
//! with the spin ω₃ = ψ̇ + φ̇ cos θ, θ stays at θ₀ and φ turns at the constant rate
//!   Ω = 2k / (C ω₃ + √(C²ω₃² − 4 A k cos θ₀))  (the slow root; Ω ≈ k / (C ω₃) for a fast spin),
//! so θ(t) = θ₀, φ(t) = Ω t, and ω₃ is conserved.
//!
//! ```text
//! cargo run --release --example gyroscope
//! ```
//!
//! The gallery's scene `lagrange_gallery::scenes::gyroscope` checks θ̈(0) = 0, θ(t), φ(t) and ω₃
//! against the closed form.

use lagrange::prelude::*;

use lagrange_gallery::scenes::gyroscope::gyroscope;

fn main() -> Result<(), lagrange::Error> {
    use gyroscope::{Coords, Gyroscope, State};
    let sys = Gyroscope {
        m: 1.0,
        a: 0.5,
        c: 0.8,
        k: 2.0,
    };
    let (theta0, spin) = (1.0f64, 40.0);
    let cos = theta0.cos();
    let precession = 2.0 * sys.k
        / (sys.c * spin + (sys.c * sys.c * spin * spin - 4.0 * sys.a * sys.k * cos).sqrt());
    println!(
        "steady precession Ω = {precession:.10} rad/s (fast-spin estimate k/(C ω₃) = {:.10})",
        sys.k / (sys.c * spin)
    );
    // Started on the steady precession: φ̇ = Ω, θ̇ = 0, ψ̇ = ω₃ − Ω cos θ₀.
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
    println!(
        "θ̈ at the start: {:.1e} rad/s²",
        sys.accelerations(&s)?.theta
    );
    println!("   t (s)   θ (rad)         φ (rad)         Ω t (rad)       ω₃ (rad/s)");
    for _ in 0..4 {
        // RK4 at h = 1e-4: the spin, 40 rad/s, is the fastest rate.
        sys.simulate::<Rk4>(&mut s, 1e-4, 5000, |_| {})?;
        println!(
            "{:8.2}  {:.12}  {:.12}  {:.12}  {:.10}",
            s.t,
            s.q.theta,
            s.q.phi,
            precession * s.t,
            s.v.psi + s.v.phi * s.q.theta.cos()
        );
    }
    Ok(())
}
