//! A double pendulum released with both arms horizontal: chaotic, so the trajectory itself has no
//! closed form, but the accelerations do (the standard result, e.g. Goldstein-style derivation as
//! written out in myphysicslab's double pendulum), and the energy is conserved. The scene checks the
//! generated equations against the closed form and shows the energy behaviour of RK4 over a long
//! run: a slow drift that shrinks as h⁴.
//!
//! The mechanism, the simulation and its checks against the closed forms are the gallery's scene
//! `lagrange_gallery::scenes::double_pendulum` (`gallery/src/scenes/double_pendulum.rs`); this runs it alone and prints its
//! table.

fn main() {
    lagrange_gallery::run_scene(lagrange_gallery::scenes::double_pendulum::run)
}
