//! Statics of the bead on a spinning hoop (the mechanism of `spinning_hoop.rs`): equilibria by the
//! principle of virtual work (all generalized forces zero at rest, the lecture's eq. 5), their
//! stability and small-oscillation frequencies, traced over the spin rate ω.
//!
//! The mechanism, the simulation and its checks against the closed forms are the gallery's scene
//! `lagrange_gallery::scenes::hoop_bifurcation` (`gallery/src/scenes/hoop_bifurcation.rs`); this runs it alone and prints its
//! table.

fn main() {
    lagrange_gallery::run_scene(lagrange_gallery::scenes::hoop_bifurcation::run)
}
