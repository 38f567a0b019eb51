//! A large-amplitude pendulum: released at rest from θ₀ = 3 rad (172°), its period is
//! T = 4 K(k) √(L/g) with modulus k = sin(θ₀/2) (Landau & Lifshitz, *Mechanics*, §11, problem 1),
//! 2.6 times the small-amplitude period. The period is measured from the simulation as the time of
//! the first upward zero crossing of θ (at 3T/4), located by cubic Hermite interpolation between
//! steps.
//!
//! The mechanism, the simulation and its checks against the closed forms are the gallery's scene
//! `lagrange_gallery::scenes::pendulum` (`gallery/src/scenes/pendulum.rs`); this runs it alone and prints its
//! table.

fn main() {
    lagrange_gallery::run_scene(lagrange_gallery::scenes::pendulum::run)
}
