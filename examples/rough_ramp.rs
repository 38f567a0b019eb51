//! A block (a point mass) on a rough ramp fixed at angle α, with Coulomb friction: kinetic μₖ while
//! it slides, static μₛ ≥ μₖ while it sticks. The block is free in the plane, (x, y); the ramp is a
//! unilateral contact c = n·r ≥ 0 with n = (−sin α, cos α), and friction acts on that contact with
//! the slip velocity s = t̂·ṙ, t̂ = (cos α, sin α) (positive up the ramp). As in the lecture, the
//! friction force is part of the contact's constraint force and does virtual work.
//!
//! The mechanism, the simulation and its checks against the closed forms are the gallery's scene
//! `lagrange_gallery::scenes::rough_ramp` (`gallery/src/scenes/rough_ramp.rs`); this runs it alone and prints its
//! table.

fn main() {
    lagrange_gallery::run_scene(lagrange_gallery::scenes::rough_ramp::run)
}
