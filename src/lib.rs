#![doc = include_str!("../README.md")]
//!
//! ## The crate root
//!
//! The root exports, by name, what a user of a declared mechanism calls: the
//! [`mechanism`](macro@mechanism) attribute, the [`Mechanism`] trait with its [`State`] and
//! [`Coordinates`], [`Validated`], the errors, the integrators, the geometry a declaration is
//! written in, the analysis entry points with their options and results, and the constraint tools
//! ([`Constraints`], [`ContactRk4`], [`consistent_state`], [`consistent_state_holding`],
//! [`constraint_forces`]). Everything else — the low-level [`model::Model`]
//! trait that generated code implements, the dynamics kernels, the small dense solves — stays in its
//! module: [`model`], [`dynamics`], [`tree`], [`linalg`], [`integrate`], [`analysis`],
//! [`constraints`], [`geometry`], [`inertia`], [`scalar_ext`], [`error`], [`sensitivity`] (trajectory
//! sensitivities), [`declaration`], [`animation`] (a trajectory as an HTML animation), and [`ffi`]
//! with [`export_c!`] (C embedding).
//!
//! So `use lagrange::*;` brings one `validate` into scope, [`Mechanism::validate`]:
//!
//! ```
//! use lagrange::*;
//!
//! #[mechanism]
//! pub mod pendulum {
//!     pub struct Coords {
//!         pub theta: f64,
//!     }
//!     pub struct Pendulum {
//!         pub m: f64,
//!         pub l: f64,
//!         pub g: f64,
//!     }
//!     #[particle(mass = m)]
//!     fn bob() -> Vec2 {
//!         vec2(theta.sin(), -theta.cos()) * l
//!     }
//!     #[gravity]
//!     fn down() -> Vec2 {
//!         vec2(0.0, -g)
//!     }
//! }
//!
//! let p = pendulum::Pendulum { m: 1.0, l: 1.0, g: 9.81 };
//! assert!(p.validate().is_ok());
//! let bad = pendulum::Pendulum { m: f64::NAN, l: 1.0, g: 9.81 };
//! assert!(matches!(bad.validate(), Err(Error::NonFiniteParameter { name: "m", .. })));
//! ```

#![warn(missing_docs)]

pub use lagrange_macros::mechanism;

pub use lagrange_core::analysis::{
    constrained_equilibrium, continuation, equilibrium, linearize, normal_modes, stability, Branch,
    BranchPoint, ConstrainedEquilibrium, Equilibrium, EquilibriumOptions, Linearization,
    NormalModes, Stability, StabilityAnalysis,
};
pub use lagrange_core::constraints::{
    consistent_state, consistent_state_holding, constraint_forces, ConstraintForces, Constraints,
    ContactAdaptive, ContactDop853, ContactDopri5, ContactOptions, ContactRk4, ModeChange, RowMode,
};
pub use lagrange_core::error::{Error, Result};
/// The scalar every declaration function is evaluated on (`f64` or a dual number): the bound of a
/// helper function called from one, `fn arm<D: lagrange::Scalar>(angle: D) -> D`.
pub use lagrange_core::geometry::Scalar;
pub use lagrange_core::geometry::{
    planar, rot3, rot_axis, rot_x, rot_y, rot_z, rpy, spatial, vec2, vec3, Planar, Rot3, Spatial,
    SpatialVelocity, Vec2, Vec3,
};
pub use lagrange_core::integrate::{
    Dop853, Dop853Stepper, Dopri5, Dopri5Stepper, Event, FixedStepper, GaussLegendre2,
    ImplicitMidpoint, Integrator, Observation, Outcome, Rk4, Stats, Stepper, StopReason,
    StormerVerlet, Variational,
};
pub use lagrange_core::mechanism::Mechanism;
pub use lagrange_core::model::{Coordinates, State};
pub use lagrange_core::validated::Validated;

pub use lagrange_core::ensemble;
pub use lagrange_core::{
    analysis, animation, constraints, declaration, dynamics, error, geometry, inertia, integrate,
    linalg, mechanism, model, parameters, scalar_ext, sensitivity, tree, validated,
};
/// C embedding: [`export_c!`] and what it uses ([`ffi::Status`], [`ffi::Export`], …).
pub use lagrange_ffi as ffi;
pub use lagrange_ffi::export_c;

/// Everything a declaration and its user need: `use lagrange::prelude::*;`.
pub mod prelude {
    pub use lagrange_core::geometry::{
        planar, rot3, rot_axis, rot_x, rot_y, rot_z, rpy, spatial, vec2, vec3,
    };
    pub use lagrange_core::geometry::{Planar, Rot3, Spatial, SpatialVelocity, Vec2, Vec3};
    pub use lagrange_core::integrate::{
        Dop853, Dopri5, GaussLegendre2, ImplicitMidpoint, Integrator, Radau5, Rk4, Stepper,
        StormerVerlet, Variational,
    };
    pub use lagrange_core::{Coordinates, Error, Mechanism, State, Validated};
    pub use lagrange_macros::mechanism;
}

/// What generated code names. Not a public API: it may change in any release.
#[doc(hidden)]
pub mod __private {
    pub use core;
    pub use lagrange_core;
    pub use lagrange_core::dynamics;
    pub use lagrange_core::geometry;
    pub use lagrange_core::inertia;
    pub use lagrange_core::mechanism::{Dynamics, Prepare};
    pub use lagrange_core::model::{check_state, Coordinates, Model, State};
    pub use lagrange_core::parameters;
    pub use lagrange_core::scalar_ext::{call_helper, ScalarExt};
    pub use lagrange_core::tree;
    pub use lagrange_core::{Error, Mechanism, Result, Scalar};
    pub use nalgebra;
    pub use num_dual;
    pub use num_dual::DualNum;
    pub use std;
}
