//! An Atwood machine with a massive pulley: masses m₁ and m₂ hang from an inextensible rope over a
//! pulley of radius r and moment of inertia I that turns without the rope slipping. One coordinate,
//! the descent y of m₁; the pulley turns by −y/r, so its inertia adds I/r² to the masses the
//! weight difference has to accelerate. Closed form (Kleppner & Kolenkow, 2nd ed., §7.x):
//!   ÿ = (m₁ − m₂) g / (m₁ + m₂ + I/r²),  so y(t) = ½ ÿ t² from rest.
//!
//! ```text
//! cargo run --release --example atwood
//! ```
//!
//! The gallery's scene `lagrange_gallery::scenes::atwood` checks ÿ and y(t) against the closed form.

use lagrange::prelude::*;

use lagrange_gallery::scenes::atwood::atwood;

fn main() -> Result<(), lagrange::Error> {
    use atwood::{Atwood, Coords, State};
    // A uniform disk for the pulley: I = ½ M r².
    let sys = Atwood {
        m1: 3.0,
        m2: 2.0,
        pulley_mass: 1.5,
        pulley_inertia: 0.5 * 1.5 * 0.2 * 0.2,
        r: 0.2,
        g: 9.81,
    };
    let closed_form =
        (sys.m1 - sys.m2) * sys.g / (sys.m1 + sys.m2 + sys.pulley_inertia / (sys.r * sys.r));
    let mut s = State::at_rest(Coords { y: 0.0 });
    println!(
        "ÿ = {:.12} m/s²; (m₁ − m₂)g / (m₁ + m₂ + I/r²) = {closed_form:.12} m/s²",
        sys.accelerations(&s)?.y
    );
    println!("   t (s)        y (m)      ½ÿt² (m)");
    for _ in 0..5 {
        sys.simulate::<Rk4>(&mut s, 1e-3, 200, |_| {})?;
        println!(
            "{:8.2} {:12.9} {:12.9}",
            s.t,
            s.q.y,
            0.5 * closed_form * s.t * s.t
        );
    }
    Ok(())
}
