//! A block rests on a rough incline and is pushed sideways, along the incline's level direction.
//! Static friction in the incline's plane (a `#[friction]` with a `Vec2` slip velocity, the Coulomb
//! cone) holds it while the resultant of the push and the downslope weight stays within μₛ N; a
//! harder push makes it slide along that resultant.
//!
//! ```text
//! cargo run --release --example pushed_block
//! ```
//!
//! The gallery's scene `lagrange_gallery::scenes::pushed_block` checks the outcome and the
//! acceleration a = (R − μₖ N)/m against the closed form.

use lagrange::prelude::*;
use lagrange_gallery::plot::{self, Series};

use lagrange_gallery::scenes::pushed_block::pushed_block;

fn main() -> Result<(), lagrange::Error> {
    use pushed_block::{Coords, PushedBlock, State};
    let gentle = PushedBlock {
        m: 2.0,
        g: 9.81,
        alpha: 0.3,
        mu_k: 0.4,
        mu_s: 0.5,
        push: 7.0,
    };
    let mut series = Vec::new();
    for sys in [
        gentle,
        PushedBlock {
            push: 9.5,
            ..gentle
        },
    ] {
        let mut s = State::at_rest(Coords {
            x: 0.0,
            y: 0.0,
            z: 0.0,
        });
        let mut stepper = Stepper::new(&sys, Rk4::with_step(1e-3), &s)?;
        let mut slid = vec![(0.0, 0.0)];
        for _ in 0..2000 {
            stepper.step(f64::INFINITY)?;
            s = stepper.state();
            slid.push((s.t, s.q.x.hypot(s.q.y).hypot(s.q.z)));
        }
        println!(
            "push {} N: friction {:?}, after {:.1} s at ({:.4}, {:.4}, {:.4}) m",
            sys.push,
            stepper.contacts().mode().rows[1],
            s.t,
            s.q.x,
            s.q.y,
            s.q.z
        );
        series.push(Series::new(format!("push {} N", sys.push), slid));
    }
    let plots = lagrange_gallery::plots_dir();
    plot::lines(
        &plots.join("pushed_block_example.svg"),
        "Block on a rough incline pushed sideways",
        "t",
        "distance slid",
        &series,
    )
    .map_err(|e| eprintln!("{e}"))
    .ok();
    Ok(())
}
