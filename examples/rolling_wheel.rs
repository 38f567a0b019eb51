//! The lecture's vertical wheel rolling without slipping on a horizontal plane (Hand & Finch,
//! *Analytical Mechanics*, Appendix 1A; Goldstein, Poole & Safko, 3rd ed., §1.3, fig. 1.5). Four
//! configuration variables — the centre (x, y), the heading φ and the rolling angle θ — and two
//! velocity constraints that cannot be integrated into constraints on the configuration
//! (nonholonomic): the contact point does not slip,
//!   ẋ = R θ̇ cos φ,   ẏ = R θ̇ sin φ,
//! leaving 2 degrees of freedom of velocity. The wheel is a uniform disk held vertical (a spatial
//! rigid body whose rotation is rot_z(φ)·rot_y(θ)): moment ½mR² about the axle, ¼mR² about a
//! diameter.
//!
//! The mechanism, the simulation and its checks against the closed forms are the gallery's scene
//! `lagrange_gallery::scenes::rolling_wheel` (`gallery/src/scenes/rolling_wheel.rs`); this runs it alone and prints its
//! table.

fn main() {
    lagrange_gallery::run_scene(lagrange_gallery::scenes::rolling_wheel::run)
}
