//! Identifying a pendulum from a measurement: its length L and pivot friction c are fitted to
//! sampled angles by Gauss–Newton, the Jacobian ∂θ(tᵢ)/∂(L, c) coming from one sensitivity run per
//! iteration (`Seed::Parameter`).
//!
//! The mechanism, the fit and its checks are the gallery's scene
//! `lagrange_gallery::scenes::identify_pendulum` (`gallery/src/scenes/identify_pendulum.rs`); this
//! runs it alone and prints its table.

fn main() {
    lagrange_gallery::run_scene(lagrange_gallery::scenes::identify_pendulum::run)
}
