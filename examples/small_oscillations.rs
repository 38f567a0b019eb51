//! Small oscillations of the double pendulum (equal masses m and lengths l, the mechanism of
//! `double_pendulum.rs`) about its stable equilibrium: the normal modes from K v = ω² M v with M and
//! K from dual numbers. Closed form (Goldstein, 3rd ed., §6.4; Landau & Lifshitz §23, problem 1):
//! ω² = (2 ± √2) g/l, with mode shapes θ₂/θ₁ = ±√2 (in phase for the slow mode).
//!
//! The mechanism, the simulation and its checks against the closed forms are the gallery's scene
//! `lagrange_gallery::scenes::small_oscillations` (`gallery/src/scenes/small_oscillations.rs`); this runs it alone and prints its
//! table.

fn main() {
    lagrange_gallery::run_scene(lagrange_gallery::scenes::small_oscillations::run)
}
