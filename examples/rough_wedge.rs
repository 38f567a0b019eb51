//! The lecture's wedge and block (Cross, Caltech Ph106, Lecture 4, eqs. (27)–(32); the frictionless
//! version is the `wedge_block` scene), now with Coulomb friction between block and wedge; the wedge
//! (mass M) still slides freely on a frictionless floor. Coordinates: the wedge's position X and the
//! block's position (bₓ, b_y). The wedge's face passes through (X, h) and slopes down at angle α; the
//! block touches it through a unilateral contact c = n·(b − (X, h)) ≥ 0, n = (sin α, cos α), with
//! friction on that contact, slip velocity s = t̂·(ḃ − (Ẋ, 0)), t̂ = (cos α, −sin α) (positive when
//! the block slides down the face).
//!
//! The mechanism, the simulation and its checks against the closed forms are the gallery's scene
//! `lagrange_gallery::scenes::rough_wedge` (`gallery/src/scenes/rough_wedge.rs`); this runs it alone and prints its
//! table.

fn main() {
    lagrange_gallery::run_scene(lagrange_gallery::scenes::rough_wedge::run)
}
