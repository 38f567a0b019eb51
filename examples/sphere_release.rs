//! A particle slides on the outside of a frictionless sphere of radius R, started at the top with
//! speed v₀ > 0. It moves on a great circle, so two Cartesian coordinates (x, y) suffice; the sphere
//! is a unilateral constraint |r| − R ≥ 0 whose force can only push.
//!
//! Closed form (Goldstein, Poole & Safko, *Classical Mechanics*, 3rd ed., §2.4, the particle on a
//! hemisphere; Kleppner & Kolenkow, 2nd ed., problem 5.x): with θ the angle from the top, energy
//! gives v² = v₀² + 2gR(1 − cos θ) and the radial component of Newton's law gives the normal force
//!   N(θ) = m g (3 cos θ − 2) − m v₀²/R,
//! which vanishes at cos θ* = (2 + v₀²/(gR))/3: there the particle leaves, at the time
//! t* = ∫₀^θ* R dθ / v(θ).
//!
//! The simulation knows none of this: the solver keeps the contact while its multiplier λ = N is
//! positive and locates the instant λ reaches 0.
//!
//! ```text
//! cargo run --release --example sphere_release
//! ```
//!
//! The gallery's scene `lagrange_gallery::scenes::sphere_release` checks the release time and angle,
//! λ against N(θ) and the parabola after release.

use lagrange::constraints::constraint_forces;
use lagrange::prelude::*;
use lagrange_gallery::plot::{self, Series};
use lagrange_gallery::scenes::sphere_release::gauss_legendre;

use lagrange_gallery::scenes::sphere_release::sphere_release;

fn main() -> Result<(), lagrange::Error> {
    use sphere_release::{Coords, SphereRelease, State};
    let sys = SphereRelease {
        m: 0.7,
        r: 1.5,
        g: 9.81,
    };
    let (m, r, g, v0) = (sys.m, sys.r, sys.g, 1.2f64);
    let mut s = State::new(0.0, Coords { x: 0.0, y: r }, Coords { x: v0, y: 0.0 });
    let mut stepper = Stepper::new(&sys, Rk4::with_step(1e-3), &s)?;
    println!("θ (rad)    λ (N)        N(θ) = mg(3cos θ − 2) − mv₀²/R");
    let mut path = vec![(s.q.x, s.q.y)];
    let mut step = 0;
    while stepper.mode_changes().is_empty() {
        stepper.step(f64::INFINITY)?;
        s = stepper.state();
        path.push((s.q.x, s.q.y));
        step += 1;
        if step % 100 == 0 && stepper.mode_changes().is_empty() {
            let cos = s.q.y / r;
            let lambda = constraint_forces(&sys, &s)?.multipliers[0];
            println!(
                "{:.4}     {lambda:.9}  {:.9}",
                s.q.x.atan2(s.q.y),
                m * g * (3.0 * cos - 2.0) - m * v0 * v0 / r
            );
        }
    }
    let release = stepper.mode_changes()[0];
    let theta_star = ((2.0 + v0 * v0 / (g * r)) / 3.0).acos();
    let speed = |th: f64| (v0 * v0 + 2.0 * g * r * (1.0 - th.cos())).sqrt();
    let t_star = gauss_legendre(|th| r / speed(th), 0.0, theta_star, 400);
    println!(
        "`{}` {:?} → {:?} at t = {:.12} s",
        release.constraint, release.from, release.to, release.t
    );
    println!("closed form t* = ∫ R dθ / v = {t_star:.12} s, at θ* = {theta_star:.6} rad");

    // Free flight: a parabola away from the sphere.
    while s.t < release.t + 0.4 {
        stepper.step(f64::INFINITY)?;
        s = stepper.state();
        path.push((s.q.x, s.q.y));
    }
    let circle = (0..=90)
        .map(|k| (1.0 - k as f64 / 45.0) * std::f64::consts::FRAC_PI_2)
        .map(|a| (r * a.cos(), r * a.sin()))
        .collect();
    let plots = lagrange_gallery::plots_dir();
    plot::lines(
        &plots.join("sphere_release_example.svg"),
        "Particle on a sphere: slides, leaves at cos θ* = (2 + v₀²/gR)/3, then flies",
        "x",
        "y",
        &[Series::new("sphere", circle), Series::new("path", path)],
    )
    .map_err(|e| eprintln!("{e}"))
    .ok();
    Ok(())
}
