//! An Atwood machine with a massive pulley: masses m₁ and m₂ hang from an inextensible rope over a
//! pulley of radius r and moment of inertia I that turns without the rope slipping. One coordinate,
//! the descent y of m₁; the pulley turns by −y/r. Closed form (Kleppner & Kolenkow, 2nd ed., §7.x):
//!   ÿ = (m₁ − m₂) g / (m₁ + m₂ + I/r²).
//!
//! The mechanism, the simulation and its checks against the closed forms are the gallery's scene
//! `lagrange_gallery::scenes::atwood` (`gallery/src/scenes/atwood.rs`); this runs it alone and prints its
//! table.

fn main() {
    lagrange_gallery::run_scene(lagrange_gallery::scenes::atwood::run)
}
