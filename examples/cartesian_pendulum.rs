//! The planar pendulum written in Cartesian coordinates: the bob's (x, y) are the coordinates and a
//! holonomic constraint |r| − L = 0 keeps it on the circle. The rod is no longer absorbed by the
//! choice of coordinates, so its force comes out as a Lagrange multiplier λ.
//!
//! The mechanism, the simulation and its checks against the closed forms are the gallery's scene
//! `lagrange_gallery::scenes::cartesian_pendulum` (`gallery/src/scenes/cartesian_pendulum.rs`); this runs it alone and prints its
//! table.

fn main() {
    lagrange_gallery::run_scene(lagrange_gallery::scenes::cartesian_pendulum::run)
}
