//! A bead on a circular hoop of radius R spun about its vertical diameter at a constant rate ω:
//! the hoop's azimuth ωt is written into the bead's position (a rheonomic constraint), leaving one
//! coordinate, the bead's angle θ from the bottom. For ω² > g/R the bottom is unstable and the bead
//! oscillates about cos θ* = g/(ω²R) (Goldstein, 3rd ed., §2.6 exercise; Taylor, *Classical
//! Mechanics*, §7.6). The motor does work, so T + V is not conserved; the Jacobi integral
//!   h = ½mR²θ̇² − ½mR²ω²sin²θ − mgR cos θ
//! is, because L has no explicit t dependence once written in θ.
//!
//! ```text
//! cargo run --release --example spinning_hoop
//! ```
//!
//! The gallery's scene `lagrange_gallery::scenes::spinning_hoop` checks the equilibrium θ* and the
//! Jacobi integral (its value against the formula above and its conservation over 10 s).

use lagrange::prelude::*;
use lagrange_gallery::plot::{self, Series};

use lagrange_gallery::scenes::spinning_hoop::spinning_hoop;

fn main() -> Result<(), lagrange::Error> {
    use spinning_hoop::{Coords, SpinningHoop, State};
    let sys = SpinningHoop {
        m: 0.2,
        r: 1.0,
        omega: 5.0,
        g: 9.81,
    };
    let (m, r, w, g) = (sys.m, sys.r, sys.omega, sys.g);
    let theta_star = (g / (w * w * r)).acos();
    let jacobi = |s: &State| {
        let (th, th_dot) = (s.q.theta, s.v.theta);
        0.5 * m * r * r * (th_dot * th_dot - w * w * th.sin().powi(2)) - m * g * r * th.cos()
    };
    // Released at rest 0.4 rad beyond θ*.
    let mut s = State::at_rest(Coords {
        theta: theta_star + 0.4,
    });
    println!(
        "θ* = arccos(g/ω²R) = {theta_star:.6} rad; θ̈ there: {:.1e}",
        {
            sys.accelerations(&State::at_rest(Coords { theta: theta_star }))?
                .theta
        }
    );
    println!("   t (s)    θ (rad)    T + V (J)      h (J)            closed-form h (J)");
    let mut swing = Vec::new();
    for _ in 0..5 {
        sys.simulate::<Rk4>(&mut s, 1e-3, 2000, |s| swing.push((s.t, s.q.theta)))?;
        println!(
            "{:8.2} {:10.6} {:10.6} {:16.12} {:16.12}",
            s.t,
            s.q.theta,
            sys.energy(&s)?,
            sys.energy_function(&s)?,
            jacobi(&s)
        );
    }
    let plots = lagrange_gallery::plots_dir();
    plot::lines(
        &plots.join("spinning_hoop_example.svg"),
        "Bead on a spinning hoop: oscillation about θ* = arccos(g/ω²R)",
        "t",
        "θ",
        &[
            Series::new("θ(t)", swing),
            Series::new("θ*", vec![(0.0, theta_star), (s.t, theta_star)]),
        ],
    )
    .map_err(|e| eprintln!("{e}"))
    .ok();
    Ok(())
}
