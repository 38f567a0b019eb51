//! A bead on a circular hoop of radius R spun about its vertical diameter at a constant rate ω
//! (a rheonomic constraint written into the position: the hoop's azimuth is ωt). One coordinate, the
//! bead's angle θ from the bottom.
//!
//! The mechanism, the simulation and its checks against the closed forms are the gallery's scene
//! `lagrange_gallery::scenes::spinning_hoop` (`gallery/src/scenes/spinning_hoop.rs`); this runs it alone and prints its
//! table.

fn main() {
    lagrange_gallery::run_scene(lagrange_gallery::scenes::spinning_hoop::run)
}
