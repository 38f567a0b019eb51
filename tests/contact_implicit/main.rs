//! Unilateral contacts and friction inside the implicit Radau IIA method of order 5
//! ([`ContactRadau5`](lagrange::constraints::ContactRadau5)): the contact mode is held over each
//! step (the stages and the Newton iteration, with exact Jacobians by dual numbers, on that mode's
//! accelerations), mode changes are located on the collocation polynomial, and a step is cut there
//! and recomputed. `Radau5::integrate` (and `sys.step::<Radau5>`) take this solver for a
//! declaration with unilateral or friction rows.
//!
//! - `sphere`: a particle sliding off a sphere declared `#[unilateral]` (the gallery's
//!   `sphere_release`), against the same sphere declared `#[constraint]` (an event on its
//!   multiplier): release time against the closed form (Goldstein, Poole & Safko, *Classical
//!   Mechanics*, 3rd ed., §2.4: cos θ* = (2 cos θ₀ + v₀²/(gR))/3, t* = ∫_θ₀^θ* R dθ / v(θ)); steps,
//!   Newton iterations and evaluations in contact against the bilateral declaration's.
//! - `dropped_ball`: a ball dropped on a floor declared `#[unilateral]`: impact at √(2h/g),
//!   plastic (it stays) and with restitution (its landings at the closed-form times).
//! - `friction`: a block sent up a rough ramp (`#[friction]`, the gallery's `rough_ramp`): it
//!   stops at t_s = u/(g(sin α + μₖ cos α)) and sticks or slides back, as μₛ decides; a puck on a
//!   rough plane (the friction cone) stops at the closed-form time and point, straight and pushed
//!   sideways (its path curving, the errors falling with the tolerance).
//! - `stiff_lander`, a stiff case: a lander (a foot on a unilateral floor, a top mass on a stiff,
//!   overdamped spring above it) dropped on the floor, against a tight ContactDopri5 reference and
//!   its static equilibrium; Radau5 takes far fewer steps than Dopri5 at the same tolerance.
//! - `cost_table`: the cost tables of BENCHMARKS.md (an ignored test, run by hand).
//!
//! The fixed-step implicit methods with contacts: tests/contact_fixed_step.rs.

#[path = "../contact_scenes/mod.rs"]
mod contact_scenes;

mod cost_table;
mod dropped_ball;
mod friction;
mod sphere;
mod stiff_lander;
