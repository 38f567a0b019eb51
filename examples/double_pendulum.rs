//! A double pendulum released with both arms horizontal: the motion is chaotic, so the trajectory
//! has no closed form, but the accelerations do (the standard result, e.g. as written out in
//! myphysicslab's double pendulum) and the energy T + V is conserved. RK4 does not conserve it
//! exactly: its energy error shrinks as h⁴, so halving the step divides it by 2⁴ = 16.
//!
//! ```text
//! cargo run --release --example double_pendulum
//! ```
//!
//! The gallery's scene `lagrange_gallery::scenes::double_pendulum` checks θ̈₁, θ̈₂ against the
//! closed form, the energy drift over 10⁵ steps and the order 4 of the drift.

use lagrange::prelude::*;
use lagrange_gallery::plot::{self, Series};

use lagrange_gallery::scenes::double_pendulum::double_pendulum;

use double_pendulum::{Coords, DoublePendulum, State};

/// Both arms horizontal, at rest.
fn horizontal() -> State {
    let half_pi = std::f64::consts::FRAC_PI_2;
    State::at_rest(Coords {
        theta1: half_pi,
        theta2: half_pi,
    })
}

fn main() -> Result<(), lagrange::Error> {
    let sys = DoublePendulum {
        m1: 1.0,
        m2: 1.0,
        l1: 1.0,
        l2: 1.0,
        g: 9.81,
    };
    // |V| with both bobs at the bottom: the scale of the energy error.
    let scale = sys.g * (sys.m1 * sys.l1 + sys.m2 * (sys.l1 + sys.l2));

    // The largest energy error over the first second, at three step sizes.
    println!("   h       max |ΔE|/|V₀| over 1 s   ratio to the step before");
    let mut previous: Option<f64> = None;
    for h in [4e-3, 2e-3, 1e-3] {
        let mut s = horizontal();
        let e0 = sys.energy(&s)?;
        let mut worst = 0.0f64;
        sys.simulate::<Rk4>(&mut s, h, (1.0 / h) as usize, |s| {
            let e = sys.energy(s).unwrap_or(f64::NAN);
            worst = worst.max((e - e0).abs() / scale);
        })?;
        let ratio = previous.map_or(String::new(), |p| format!("{:.2}", p / worst));
        println!("{h:8.0e}  {worst:22.3e}  {ratio:>14}");
        previous = Some(worst);
    }

    // Twenty seconds of chaos: the path of the outer bob.
    let mut s = horizontal();
    let mut path = Vec::new();
    sys.simulate::<Rk4>(&mut s, 1e-3, 20_000, |s| {
        let bob = sys.bodies(s).bob2;
        path.push((bob.x, bob.y));
    })?;
    println!(
        "after {:.0} s: θ₁ = {:.4} rad, θ₂ = {:.4} rad",
        s.t, s.q.theta1, s.q.theta2
    );
    let plots = lagrange_gallery::plots_dir();
    plot::lines(
        &plots.join("double_pendulum_example.svg"),
        "Double pendulum from horizontal: path of the outer bob over 20 s",
        "x",
        "y",
        &[Series::new("outer bob", path)],
    )
    .map_err(|e| eprintln!("{e}"))
    .ok();
    Ok(())
}
