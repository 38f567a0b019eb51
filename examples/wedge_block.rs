//! The lecture's frictionless wedge and block: a block of mass m slides down the incline (angle α)
//! of a wedge of mass M that is itself free to slide on a frictionless floor. Generalized
//! coordinates: the wedge's position X and the block's distance d down the incline.
//!
//! Closed form (solve the two Lagrange equations; e.g. Kleppner & Kolenkow, problem 2.x, or the
//! lecture's generalized forces 𝓕_X = 0, 𝓕_d = m g sin α):
//!   Ẍ = −m g sin α cos α / (M + m sin²α),   d̈ = (M + m) g sin α / (M + m sin²α),
//! both constant. 𝓕_X = 0 does not mean Ẍ = 0: the momentum conjugate to X is conserved instead,
//! and it is zero when starting from rest.
//!
//! ```text
//! cargo run --release --example wedge_block
//! ```
//!
//! The gallery's scene `lagrange_gallery::scenes::wedge_block` checks both accelerations, X(t), d(t)
//! and p_X = 0 against the closed form.

use lagrange::prelude::*;
use lagrange_gallery::plot::{self, Series};

use lagrange_gallery::scenes::wedge_block::wedge_block;

fn main() -> Result<(), lagrange::Error> {
    use wedge_block::{Coords, State, WedgeBlock};
    let sys = WedgeBlock {
        wedge_mass: 3.0,
        block_mass: 1.0,
        alpha: 0.5,
        h: 1.0,
        g: 9.81,
    };
    let (big_m, m, a, g) = (sys.wedge_mass, sys.block_mass, sys.alpha, sys.g);
    let den = big_m + m * a.sin().powi(2);
    let (x_acc, d_acc) = (
        -m * g * a.sin() * a.cos() / den,
        (big_m + m) * g * a.sin() / den,
    );

    let mut s = State::at_rest(Coords { x: 0.0, d: 0.0 });
    let qdd = sys.accelerations(&s)?;
    println!("Ẍ = {:.12} m/s², closed form {x_acc:.12}", qdd.x);
    println!("d̈ = {:.12} m/s², closed form {d_acc:.12}", qdd.d);
    println!("   t (s)     X (m)         ½Ẍt²          d (m)        ½d̈t²         p_X (kg m/s)");
    let (mut wedge, mut block) = (Vec::new(), Vec::new());
    for _ in 0..4 {
        sys.simulate::<Rk4>(&mut s, 1e-3, 100, |s| {
            let bodies = sys.bodies(s);
            wedge.push((bodies.wedge.x, bodies.wedge.y));
            block.push((bodies.block.x, bodies.block.y));
        })?;
        let t = s.t;
        println!(
            "{t:8.2} {:12.9} {:12.9} {:12.9} {:12.9} {:12.1e}",
            s.q.x,
            0.5 * x_acc * t * t,
            s.q.d,
            0.5 * d_acc * t * t,
            sys.momenta(&s)?.x
        );
    }
    let plots = lagrange_gallery::plots_dir();
    plot::lines(
        &plots.join("wedge_block_example.svg"),
        "Wedge and block: paths from rest",
        "x",
        "y",
        &[Series::new("wedge", wedge), Series::new("block", block)],
    )
    .map_err(|e| eprintln!("{e}"))
    .ok();
    Ok(())
}
