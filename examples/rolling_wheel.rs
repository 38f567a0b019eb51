//! The lecture's vertical wheel rolling without slipping on a horizontal plane (Hand & Finch,
//! *Analytical Mechanics*, Appendix 1A; Goldstein, Poole & Safko, 3rd ed., §1.3, fig. 1.5). Four
//! configuration variables — the centre (x, y), the heading φ and the rolling angle θ — and two
//! velocity constraints that cannot be integrated into constraints on the configuration
//! (nonholonomic): the contact point does not slip, ẋ = R θ̇ cos φ, ẏ = R θ̇ sin φ.
//!
//! Closed form (Greenwood, *Advanced Dynamics*, 2003, §3.4, the rolling disk, vertical case): the
//! multipliers give (I_a + mR²) θ̈ = 0 and φ̈ = 0, so φ = φ₀ + ωt, θ̇ = Ω is constant, and the
//! centre moves on a straight line (ω = 0) or on a circle of radius RΩ/ω, at constant kinetic
//! energy.
//!
//! ```text
//! cargo run --release --example rolling_wheel
//! ```
//!
//! The gallery's scene `lagrange_gallery::scenes::rolling_wheel` checks the no-slip residual, the
//! configuration against the closed form and the kinetic energy over 10⁵ steps.

use lagrange::prelude::*;
use lagrange_gallery::plot::{self, Series};

use lagrange_gallery::scenes::rolling_wheel::rolling_wheel;

fn main() -> Result<(), lagrange::Error> {
    use rolling_wheel::{Coords, RollingWheel, State};
    let w = RollingWheel { m: 2.0, r: 0.3 };
    // Rolling at Ω = 5 rad/s and turning at ω = 0.7 rad/s: a circle of radius RΩ/ω.
    let (big_omega, omega, phi0) = (5.0, 0.7, 0.4f64);
    let q0 = Coords {
        x: 0.1,
        y: -0.2,
        phi: phi0,
        theta: 0.0,
    };
    let v0 = Coords {
        x: w.r * big_omega * phi0.cos(),
        y: w.r * big_omega * phi0.sin(),
        phi: omega,
        theta: big_omega,
    };
    let mut s = State::new(0.0, q0, v0);
    let rho = w.r * big_omega / omega;
    let centre = (q0.x - rho * phi0.sin(), q0.y + rho * phi0.cos());
    println!(
        "circle of radius RΩ/ω = {rho:.6} m about ({:.6}, {:.6})",
        centre.0, centre.1
    );
    let t0 = w.energy(&s)?;
    println!("   t (s)   distance from the centre (m)   φ − ωt (rad)   T − T₀ (J)");
    let mut path = Vec::new();
    for _ in 0..5 {
        // RK4, the velocities projected back onto the no-slip rows after every step.
        w.simulate::<Rk4>(&mut s, 1e-3, 2000, |s| path.push((s.q.x, s.q.y)))?;
        println!(
            "{:8.2} {:30.12} {:14.2e} {:12.2e}",
            s.t,
            (s.q.x - centre.0).hypot(s.q.y - centre.1),
            s.q.phi - phi0 - omega * s.t,
            w.energy(&s)? - t0
        );
    }
    let plots = lagrange_gallery::plots_dir();
    plot::lines(
        &plots.join("rolling_wheel_example.svg"),
        "Rolling wheel turning at a constant rate: the centre's path over 10 s",
        "x",
        "y",
        &[Series::new("centre", path)],
    )
    .map_err(|e| eprintln!("{e}"))
    .ok();
    Ok(())
}
