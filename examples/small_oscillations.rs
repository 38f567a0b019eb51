//! Small oscillations of a double pendulum (equal masses m, equal lengths l) about its stable
//! equilibrium: `equilibrium` finds the rest configuration by virtual work (every generalized force
//! zero), and `normal_modes` solves K v = ω² M v with the mass matrix M and the stiffness K taken
//! from dual numbers. Closed form (Goldstein, 3rd ed., §6.4; Landau & Lifshitz §23, problem 1):
//!   ω² = (2 ∓ √2) g/l,  mode shapes θ₂/θ₁ = ±√2 (in phase for the slow mode).
//!
//! ```text
//! cargo run --release --example small_oscillations
//! ```
//!
//! The gallery's scene `lagrange_gallery::scenes::small_oscillations` checks the equilibrium, both
//! frequencies and both shapes against the closed form.

use lagrange::analysis::{equilibrium, normal_modes, EquilibriumOptions};

use lagrange_gallery::scenes::double_pendulum::double_pendulum;

fn main() -> Result<(), lagrange::Error> {
    use double_pendulum::{Coords, DoublePendulum};
    let (m, l, g) = (0.7, 1.3, 9.81);
    let sys = DoublePendulum {
        m1: m,
        m2: m,
        l1: l,
        l2: l,
        g,
    };
    // Newton from a guess off the equilibrium.
    let guess = Coords {
        theta1: 0.3,
        theta2: -0.2,
    };
    let rest = equilibrium(&sys, 0.0, &guess, &EquilibriumOptions::default())?;
    println!(
        "equilibrium θ₁ = {:.1e}, θ₂ = {:.1e} after {} Newton iterations",
        rest.q.theta1, rest.q.theta2, rest.iterations
    );

    let modes = normal_modes(&sys, 0.0, &rest.q)?;
    let root2 = std::f64::consts::SQRT_2;
    println!("mode   ω (rad/s)       √((2 ∓ √2) g/l)   θ₂/θ₁           closed form");
    for (j, (name, sign)) in [("slow", -1.0), ("fast", 1.0)].into_iter().enumerate() {
        println!(
            "{name}  {:.12}  {:.12}    {:+.12}  {:+.12}",
            modes.frequencies[j],
            ((2.0 + sign * root2) * g / l).sqrt(),
            modes.shapes[(1, j)] / modes.shapes[(0, j)],
            -sign * root2
        );
    }
    Ok(())
}
