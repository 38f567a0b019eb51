//! A large-amplitude pendulum: released at rest from θ₀ = 3 rad (172°), it swings much more slowly
//! than the small-amplitude 2π√(L/g), because it lingers near the top. Its period is
//!   T = 4 K(k) √(L/g),  modulus k = sin(θ₀/2)
//! (Landau & Lifshitz, *Mechanics*, §11, problem 1), 2.6 times the small-amplitude period.
//!
//! The period is measured here with an event: `sys.integrate` with `Dopri5` locates the instant θ
//! next crosses zero upwards, three quarters of a period after the release.
//!
//! ```text
//! cargo run --release --example pendulum
//! ```
//!
//! The gallery's scene `lagrange_gallery::scenes::pendulum` checks the period (measured with RK4)
//! and the energy against the closed form.

use lagrange::integrate::{Direction, Event, Observation, StopReason};
use lagrange::prelude::*;
use lagrange_gallery::plot::{self, Series};

use lagrange_gallery::scenes::pendulum::pendulum;

fn main() -> Result<(), lagrange::Error> {
    use pendulum::{Coords, Pendulum, State};
    let sys = Pendulum {
        m: 1.0,
        l: 1.0,
        g: 9.81,
    };
    let theta0: f64 = 3.0;
    let mut s = State::at_rest(Coords { theta: theta0 });

    // Stop when θ crosses zero upwards: t = 3T/4.
    let theta = |s: &State| s.q.theta;
    let mut events = [Event::new(&theta).direction(Direction::Rising).terminal()];
    let mut swing = vec![(0.0, theta0)];
    let outcome = sys.integrate(Dopri5::new(1e-12, 1e-12), &mut s, 10.0, &mut events, |o| {
        if let Observation::Step { state, .. } = o {
            swing.push((state.t, state.q.theta));
        }
    })?;
    match outcome.reason {
        StopReason::Event(hit) => {
            let period = hit.state.t * 4.0 / 3.0;
            let closed_form =
                4.0 * lagrange_gallery::elliptic_k((theta0 / 2.0).sin()) * (sys.l / sys.g).sqrt();
            let small = 2.0 * std::f64::consts::PI * (sys.l / sys.g).sqrt();
            println!("period from the event: {period:.12} s");
            println!("4K(k)√(L/g):           {closed_form:.12} s");
            println!(
                "2π√(L/g):              {small:.12} s (ratio {:.3})",
                period / small
            );
            println!(
                "{} accepted steps, {} rejected",
                outcome.stats.accepted, outcome.stats.rejected
            );
        }
        _ => println!("θ did not cross zero upwards before t = {:.1} s", s.t),
    }
    let plots = lagrange_gallery::plots_dir();
    plot::lines(
        &plots.join("pendulum_example.svg"),
        "Pendulum released at 172°: three quarters of a period",
        "t",
        "θ",
        &[Series::new("θ(t), Dopri5 steps", swing)],
    )
    .map_err(|e| eprintln!("{e}"))
    .ok();
    Ok(())
}
