//! The lecture's example 2: a bead of mass m slides without friction on a vertical elliptical wire
//! whose semi-axes a(t) = a₀(1 + ε sin Ωt), b(t) = b₀(1 + ε cos Ωt) are prescribed. The wire does work
//! on the bead (the actual displacement is not along the wire), so T + V is not conserved. What holds
//! instead is the energy-function theorem: h = Σ pₖq̇ₖ − L obeys dh/dt = −∂L/∂t along the motion
//! (Goldstein, *Classical Mechanics*, 3rd ed., eq. 2.55). The scene integrates −∂L/∂t alongside the
//! motion (composite Simpson rule on the step samples) and compares it with h(t) − h(0).
//!
//! The mechanism, the simulation and its checks against the closed forms are the gallery's scene
//! `lagrange_gallery::scenes::breathing_ellipse` (`gallery/src/scenes/breathing_ellipse.rs`); this runs it alone and prints its
//! table.

fn main() {
    lagrange_gallery::run_scene(lagrange_gallery::scenes::breathing_ellipse::run)
}
