//! A four-bar linkage swinging under gravity: a closed kinematic loop, which no choice of three
//! independent angles can describe without constraints. The crank (length l₁) is pivoted at
//! O = (0, 0), the rocker (l₃) at D = (d, 0), and the coupler (l₂) joins their tips; the coordinates
//! are the three bars' absolute angles, each bar a uniform rod (I = m l²/12 about its centre).
//! Closing the loop — the coupler's far end B on the rocker's tip — is two holonomic constraints,
//! which leave one degree of freedom. The bars are Grashof's crank–rocker (Norton, *Design of
//! Machinery*, 5th ed., §2.12): the crank turns fully and the linkage never reaches a toggle.
//!
//! What has a closed form over a long run: the joint forces do no work, so E = T + V is conserved
//! (Goldstein, Poole & Safko, 3rd ed., §2.4 and §2.7), and the loop stays closed, g = ġ = 0.
//!
//! ```text
//! cargo run --release --example four_bar
//! ```
//!
//! The gallery's scene `lagrange_gallery::scenes::four_bar` checks the loop closure, the energy over
//! 10⁵ steps and Newton's third law at the joint B.

use lagrange::constraints::{consistent_state, constraint_forces, constraint_rows};
use lagrange::prelude::*;
use lagrange_gallery::plot::{self, Series};

use lagrange_gallery::scenes::four_bar::four_bar;

fn main() -> Result<(), lagrange::Error> {
    use four_bar::{Coords, FourBar, State};
    let sys = FourBar {
        l1: 1.0,
        l2: 3.0,
        l3: 2.0,
        m1: 1.0,
        m2: 2.0,
        m3: 1.5,
        d: 3.0,
        g: 9.81,
    };
    // A rough guess with the crank turning at 3 rad/s: consistent_state closes the loop and removes
    // the velocity components that would open it.
    let guess = State::new(
        0.0,
        Coords {
            theta1: 1.0,
            theta2: 0.2,
            theta3: 1.6,
        },
        Coords {
            theta1: 3.0,
            theta2: 0.0,
            theta3: 0.0,
        },
    );
    let mut s = consistent_state(&sys, &guess)?;
    let e0 = sys.energy(&s)?;
    println!("   t (s)   crank θ₁ (rad)   (E − E₀)/|E₀|   |g| (m)    joint force λ (N)");
    let mut coupler_curve = Vec::new();
    for step in 1..=20_000 {
        // RK4, projected back onto g = 0 and ġ = 0 after every step.
        sys.step::<Rk4>(&mut s, 1e-3)?;
        if step % 10 == 0 {
            let c = sys.bodies(&s).coupler.position;
            coupler_curve.push((c.x, c.y));
        }
        if step % 4000 == 0 {
            let rows = constraint_rows(&sys, s.t, &s.q.to_array(), &s.v.to_array());
            let closure = rows.value[0].abs().max(rows.value[1].abs());
            let lambda = constraint_forces(&sys, &s)?.multipliers;
            println!(
                "{:8.2} {:14.6} {:16.2e} {:10.1e}   ({:.4}, {:.4})",
                s.t,
                s.q.theta1,
                (sys.energy(&s)? - e0) / e0.abs(),
                closure,
                lambda[0],
                lambda[1]
            );
        }
    }
    let plots = lagrange_gallery::plots_dir();
    plot::lines(
        &plots.join("four_bar_example.svg"),
        "Four-bar linkage: path of the coupler's midpoint over 20 s",
        "x",
        "y",
        &[Series::new("coupler midpoint", coupler_curve)],
    )
    .map_err(|e| eprintln!("{e}"))
    .ok();
    Ok(())
}
