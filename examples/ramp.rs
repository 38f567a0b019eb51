//! A block on a fixed frictionless ramp (the lecture's example 1): one coordinate, the distance s
//! down the ramp; the constraint force is normal to the ramp, does no virtual work, and drops out.
//! Closed form: s̈ = g sin α, so s(t) = v₀ t + ½ g sin α t².
//!
//! The mechanism, the simulation and its checks against the closed forms are the gallery's scene
//! `lagrange_gallery::scenes::ramp` (`gallery/src/scenes/ramp.rs`); this runs it alone and prints its
//! table.

fn main() {
    lagrange_gallery::run_scene(lagrange_gallery::scenes::ramp::run)
}
