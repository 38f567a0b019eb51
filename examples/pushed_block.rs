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

use lagrange::constraints::{ContactOptions, ContactRk4};
use lagrange::prelude::*;
use lagrange_gallery::plot::{self, Series};

#[mechanism]
pub mod pushed_block {
    pub struct Coords {
        pub x: f64,
        pub y: f64,
        pub z: f64,
    }

    #[derive(Clone, Copy)]
    pub struct PushedBlock {
        pub m: f64,
        pub g: f64,
        /// The incline rises along y at angle α; x is level.
        pub alpha: f64,
        pub mu_k: f64,
        pub mu_s: f64,
        pub push: f64,
    }

    #[particle(mass = m)]
    fn block() -> Vec3 {
        vec3(x, y, z)
    }

    #[gravity]
    fn down() -> Vec3 {
        vec3(0.0, 0.0, -g)
    }

    #[force(on = block)]
    fn sideways() -> Vec3 {
        vec3(push, 0.0, 0.0)
    }

    /// The incline pushes along its normal (0, −sin α, cos α) and cannot pull.
    #[unilateral]
    fn incline() -> f64 {
        block.z * alpha.cos() - block.y * alpha.sin()
    }

    /// Friction in the incline's plane: slip along the level direction and up the slope.
    #[friction(on = incline, kinetic = mu_k, stiction = mu_s)]
    fn rub() -> Vec2 {
        vec2(
            block_dot.x,
            block_dot.y * alpha.cos() + block_dot.z * alpha.sin(),
        )
    }
}

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
        let mut stepper = ContactRk4::new(&sys, &s, ContactOptions::default())?;
        let mut slid = vec![(0.0, 0.0)];
        for _ in 0..2000 {
            stepper.step(&sys, &mut s, 1e-3)?;
            slid.push((s.t, s.q.x.hypot(s.q.y).hypot(s.q.z)));
        }
        println!(
            "push {} N: friction {:?}, after {:.1} s at ({:.4}, {:.4}, {:.4}) m",
            sys.push,
            stepper.mode().rows[1],
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
