//! The lecture's example 3, a rigid body made of particles: three point masses held at fixed
//! offsets from a pivot swing as a physical pendulum. The same body declared as one planar rigid
//! body — total mass M at the centre of mass c, moment of inertia I_c = Σ mᵢ|sᵢ − c|² about it —
//! must move identically (the kinetic energy of a rigid body depends only on M, c and I_c).
//!
//! The mechanism, the simulation and its checks against the closed forms are the gallery's scene
//! `lagrange_gallery::scenes::rigid_triangle` (`gallery/src/scenes/rigid_triangle.rs`); this runs it alone and prints its
//! table.

fn main() {
    lagrange_gallery::run_scene(lagrange_gallery::scenes::rigid_triangle::run)
}
