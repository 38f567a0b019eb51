//! A gyroscope driven by a torque: a symmetric rigid body (moments A, A, C) pivoted at its centre,
//! spinning about its symmetry axis a, with a torque τ = k (e_z × a) — horizontal, perpendicular to
//! the axis, the torque gravity exerts on a top whose centre is a distance l above the pivot
//! (k = m g l). Euler angles z-x-z: precession φ, nutation θ, spin ψ.
//!
//! The mechanism, the simulation and its checks against the closed forms are the gallery's scene
//! `lagrange_gallery::scenes::gyroscope` (`gallery/src/scenes/gyroscope.rs`); this runs it alone and prints its
//! table.

fn main() {
    lagrange_gallery::run_scene(lagrange_gallery::scenes::gyroscope::run)
}
