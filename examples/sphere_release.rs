//! A particle slides on the outside of a frictionless sphere of radius R, started at the top with
//! speed v₀ > 0. It moves on a great circle (a vertical plane), so two Cartesian coordinates (x, y)
//! suffice; the sphere is a unilateral constraint |r| − R ≥ 0 whose force can only push.
//!
//! The mechanism, the simulation and its checks against the closed forms are the gallery's scene
//! `lagrange_gallery::scenes::sphere_release` (`gallery/src/scenes/sphere_release.rs`); this runs it alone and prints its
//! table.

fn main() {
    lagrange_gallery::run_scene(lagrange_gallery::scenes::sphere_release::run)
}
