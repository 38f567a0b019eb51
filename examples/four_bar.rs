//! A four-bar linkage swinging under gravity: a closed kinematic loop, which no choice of three
//! independent angles can describe without constraints. The crank (length l₁) is pivoted at
//! O = (0, 0), the rocker (l₃) at D = (d, 0), and the coupler (l₂) joins their tips; the coordinates
//! are the three bars' absolute angles (θ₁, θ₂, θ₃), each bar a uniform rod (I = m l²/12 about its
//! centre). Closing the loop — the coupler's far end B on the rocker's tip — is two holonomic
//! constraints, written on the bodies, which leave one degree of freedom.
//!
//! The mechanism, the simulation and its checks against the closed forms are the gallery's scene
//! `lagrange_gallery::scenes::four_bar` (`gallery/src/scenes/four_bar.rs`); this runs it alone and prints its
//! table.

fn main() {
    lagrange_gallery::run_scene(lagrange_gallery::scenes::four_bar::run)
}
