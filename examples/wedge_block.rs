//! The lecture's frictionless wedge and block: a block of mass m slides down the incline (angle α)
//! of a wedge of mass M that is itself free to slide on a frictionless floor. Generalized
//! coordinates: the wedge's position X and the block's distance d down the incline.
//!
//! The mechanism, the simulation and its checks against the closed forms are the gallery's scene
//! `lagrange_gallery::scenes::wedge_block` (`gallery/src/scenes/wedge_block.rs`); this runs it alone and prints its
//! table.

fn main() {
    lagrange_gallery::run_scene(lagrange_gallery::scenes::wedge_block::run)
}
