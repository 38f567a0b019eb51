//! The runtime of `lagrange`: the numerical work behind every `#[mechanism]`.
//!
//! - [`model`]: what a declaration compiles to (Cartesian coordinates x(q, t) with masses) and the
//!   [`State`] a mechanism is simulated in;
//! - [`dynamics`]: M q̈ = 𝓕 − b by dual-number automatic differentiation;
//! - [`inertia`]: a rigid body declared by its frame (centre of mass offset, full inertia tensor)
//!   and the checks of the constants a declaration writes;
//! - [`tree`]: the same for bodies that form a tree of translations, seeded body by body;
//! - [`linalg`]: small dense solves generic over dual numbers;
//! - [`evaluation`]: the equations a declaration implements ([`evaluation::Dynamics`]) and what
//!   everything else evaluates through ([`evaluation::Evaluate`]);
//! - [`mechanism`]: the user-facing [`Mechanism`] trait, and [`Validated`] for parameters checked once;
//! - [`integrate`]: the integrators, generic over every mechanism, behind one solver
//!   ([`integrate::Stepper`]);
//! - [`analysis`]: equilibria, their stability, linearization, normal modes, continuation;
//! - [`declaration`]: a declaration's names and flat values, for code generic over declarations;
//! - [`sensitivity`]: trajectory sensitivities, a solver carrying its trajectory's tangent;
//! - [`parameters`]: a mechanism's parameters as values of any scalar (for sensitivities);
//! - [`ensemble`]: one computation over many parameters or initial states, on every core;
//! - [`animation`]: a trajectory of any declared mechanism as a self-contained HTML animation;
//! - [`error`]: typed errors; nothing here panics on user input.
//!
//! Users depend on the `lagrange` facade crate, which exports the user-facing items by name and
//! these modules as they are.

#![warn(missing_docs)]

pub mod affine;
pub mod analysis;
pub mod animation;
pub mod constraints;
pub mod declaration;
pub mod dynamics;
pub mod ensemble;
pub mod error;
pub mod evaluation;
pub mod geometry;
mod impl_mechanism;
pub mod inertia;
pub mod inputs;
pub mod integrate;
pub mod linalg;
pub mod mechanism;
pub mod model;
pub mod parameters;
pub mod scalar_ext;
pub mod sensitivity;
#[cfg(test)]
mod test_models;
pub mod tree;
pub mod validated;

pub use analysis::{
    constrained_equilibrium, continuation, equilibrium, linearize, normal_modes, stability,
    ConstrainedEquilibrium, Equilibrium, EquilibriumOptions, Linearization, NormalModes, Stability,
};
pub use constraints::Constraints;
pub use error::{Error, Result};
pub use geometry::{
    planar, rot3, rot_axis, rot_mrp, rot_vector, rot_x, rot_y, rot_z, rpy, spatial, vec2, vec3,
    Planar, Rot3, Scalar, Spatial, Vec2, Vec3,
};
pub use integrate::{
    Dop853, Dopri5, GaussLegendre2, ImplicitMidpoint, Integrator, Radau5, Rk4, Stepper,
    StormerVerlet, Variational,
};
pub use mechanism::Mechanism;
pub use model::{Coordinates, Model, State};
pub use validated::Validated;
