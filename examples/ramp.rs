//! A block on a fixed frictionless ramp (the lecture's example 1): one coordinate, the distance s
//! down the ramp. The ramp's constraint force is normal to it, does no virtual work, and drops out
//! of the Lagrangian; only gravity's component along the ramp is left. Closed form:
//!   s̈ = g sin α,  so s(t) = v₀ t + ½ g sin α t², with T + V conserved.
//!
//! ```text
//! cargo run --release --example ramp
//! ```
//!
//! The gallery's scene `lagrange_gallery::scenes::ramp` checks s̈, s(t) and the energy against the
//! closed form.

use lagrange::prelude::*;
use lagrange_gallery::plot::{self, Series};

use lagrange_gallery::scenes::ramp::ramp;

fn main() -> Result<(), lagrange::Error> {
    use ramp::{Coords, Ramp, State};
    let sys = Ramp {
        m: 2.0,
        alpha: 0.6,
        g: 9.81,
    };
    // Pushed up the ramp at 1.5 m/s: it rises, stops and slides back.
    let v0 = -1.5;
    let mut s = State::new(0.0, Coords { s: 0.0 }, Coords { s: v0 });
    let e0 = sys.energy(&s)?;
    let closed_form = |t: f64| v0 * t + 0.5 * sys.g * sys.alpha.sin() * t * t;
    println!(
        "s̈ = {:.12} m/s²; g sin α = {:.12} m/s²",
        sys.accelerations(&s)?.s,
        sys.g * sys.alpha.sin()
    );
    println!("   t (s)        s (m)   closed form (m)   T + V − E₀ (J)");
    let mut path = vec![(0.0, 0.0)];
    for _ in 0..5 {
        sys.simulate::<Rk4>(&mut s, 1e-3, 200, |s| path.push((s.t, s.q.s)))?;
        println!(
            "{:8.2} {:12.9} {:17.9} {:16.2e}",
            s.t,
            s.q.s,
            closed_form(s.t),
            sys.energy(&s)? - e0
        );
    }
    let plots = lagrange_gallery::plots_dir();
    plot::lines(
        &plots.join("ramp_example.svg"),
        "Block pushed up a frictionless ramp",
        "t",
        "distance down the ramp",
        &[Series::new("s(t)", path)],
    )
    .map_err(|e| eprintln!("{e}"))
    .ok();
    Ok(())
}
