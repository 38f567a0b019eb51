//! The lecture's wedge and block (Cross, Caltech Ph106, Lecture 4, eqs. (27)–(32); the frictionless
//! version is the `wedge_block` example), now with Coulomb friction between block and wedge; the
//! wedge (mass M) still slides freely on a frictionless floor. Coordinates: the wedge's position X
//! and the block's position (bₓ, b_y). The block touches the wedge's face through a unilateral
//! contact, with friction on that contact against the slip along the face.
//!
//! Closed form while the block slides down (Newton's laws for the two bodies, as in Kleppner &
//! Kolenkow, 2nd ed., problem 3.x for the frictionless case), with k = sin α − μₖ cos α:
//!   A = −m g cos α · k / (M + m sin α · k),   N = m (g cos α + A sin α),
//!   a_r = g k − A (cos α + μₖ sin α),
//! for the wedge's acceleration A, the normal force N and the block's acceleration a_r down the face
//! relative to the wedge. Friction is internal, so M Ẋ + m ḃₓ stays 0 from rest, while the energy
//! falls by the work of friction, μₖ N times the distance slid, ½ a_r t².
//!
//! ```text
//! cargo run --release --example rough_wedge
//! ```
//!
//! The gallery's scene `lagrange_gallery::scenes::rough_wedge` checks the motion, the forces, the
//! momentum, the energy lost, the frictionless limit and the stuck case against the closed form.

use lagrange::constraints::constraint_forces;
use lagrange::prelude::*;
use lagrange_gallery::plot::{self, Series};

use lagrange_gallery::scenes::rough_wedge::rough_wedge;

fn main() -> Result<(), lagrange::Error> {
    use rough_wedge::{Coords, RoughWedge, State};
    let sys = RoughWedge {
        wedge_mass: 3.0,
        block_mass: 1.0,
        alpha: 0.5,
        h: 1.0,
        g: 9.81,
        mu_k: 0.2,
        mu_s: 0.3,
    };
    let (m, big_m, mu, g) = (sys.block_mass, sys.wedge_mass, sys.mu_k, sys.g);
    let (sn, cs) = sys.alpha.sin_cos();
    let k = sn - mu * cs;
    let big_a = -m * g * cs * k / (big_m + m * sn * k);
    let normal = m * (g * cs + big_a * sn);
    let a_r = g * k - big_a * (cs + mu * sn);

    // The block at rest 0.3 m down the face.
    let mut s = State::at_rest(Coords {
        x: 0.0,
        bx: 0.3 * cs,
        by: sys.h - 0.3 * sn,
    });
    let e0 = sys.energy(&s)?;
    let mut stepper = Stepper::new(&sys, Rk4::with_step(1e-3), &s)?;
    let (mut wedge, mut block) = (Vec::new(), Vec::new());
    for _ in 0..1000 {
        stepper.step(f64::INFINITY)?;
        s = stepper.state();
        wedge.push((s.q.x, 0.0));
        block.push((s.q.bx, s.q.by));
    }
    let f = constraint_forces(&sys, &s)?;
    let t = s.t;
    let p = sys.momenta(&s)?;
    println!(
        "after {t:.1} s, {} mode changes",
        stepper.mode_changes().len()
    );
    println!(
        "{:30} {:>18} {:>18}",
        "quantity", "simulated", "closed form"
    );
    for (what, simulated, closed_form) in [
        ("wedge acceleration A (m/s²)", f.accelerations[0], big_a),
        ("normal force N (N)", f.multipliers[0], normal),
        ("friction −μₖN (N)", f.multipliers[1], -mu * normal),
        ("wedge position ½At² (m)", s.q.x, 0.5 * big_a * t * t),
        ("momentum M Ẋ + m ḃₓ (kg m/s)", p.x + p.bx, 0.0),
        (
            "energy lost μₖN·½a_r t² (J)",
            e0 - sys.energy(&s)?,
            mu * normal * 0.5 * a_r * t * t,
        ),
    ] {
        println!("{what:30} {simulated:18.12} {closed_form:18.12}");
    }
    let plots = lagrange_gallery::plots_dir();
    plot::lines(
        &plots.join("rough_wedge_example.svg"),
        "Wedge and block with friction (μₖ = 0.2): paths over 1 s from rest",
        "x",
        "y",
        &[Series::new("wedge", wedge), Series::new("block", block)],
    )
    .map_err(|e| eprintln!("{e}"))
    .ok();
    Ok(())
}
