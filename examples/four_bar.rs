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

#[mechanism]
pub mod four_bar {
    /// Absolute angles of the crank, the coupler and the rocker, from the x axis.
    pub struct Coords {
        pub theta1: f64,
        pub theta2: f64,
        pub theta3: f64,
    }

    /// Lengths and masses of crank, coupler and rocker.
    pub struct FourBar {
        pub l1: f64,
        pub l2: f64,
        pub l3: f64,
        pub m1: f64,
        pub m2: f64,
        pub m3: f64,
        /// Distance between the two fixed pivots.
        pub d: f64,
        pub g: f64,
    }

    #[rigid_body(mass = m1, inertia = m1 * l1 * l1 / 12.0)]
    fn crank() -> Planar {
        planar(vec2(theta1.cos(), theta1.sin()) * (0.5 * l1), theta1)
    }

    #[rigid_body(mass = m2, inertia = m2 * l2 * l2 / 12.0)]
    fn coupler() -> Planar {
        let tip = vec2(theta1.cos(), theta1.sin()) * l1;
        planar(tip + vec2(theta2.cos(), theta2.sin()) * (0.5 * l2), theta2)
    }

    #[rigid_body(mass = m3, inertia = m3 * l3 * l3 / 12.0)]
    fn rocker() -> Planar {
        planar(
            vec2(d, 0.0) + vec2(theta3.cos(), theta3.sin()) * (0.5 * l3),
            theta3,
        )
    }

    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }

    /// Joint B, x: the coupler's far end on the rocker's tip.
    #[constraint]
    fn joint_b_x() -> f64 {
        coupler.point(vec2(0.5 * l2, 0.0)).x - rocker.point(vec2(0.5 * l3, 0.0)).x
    }

    /// Joint B, y.
    #[constraint]
    fn joint_b_y() -> f64 {
        coupler.point(vec2(0.5 * l2, 0.0)).y - rocker.point(vec2(0.5 * l3, 0.0)).y
    }
}

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
