#![doc = include_str!("../README.md")]

pub use lagrange_core::*;
pub use lagrange_macros::mechanism;

/// Everything a declaration and its user need: `use lagrange::prelude::*;`.
pub mod prelude {
    pub use lagrange_core::geometry::{planar, rot_x, rot_y, rot_z, spatial, vec2, vec3};
    pub use lagrange_core::geometry::{Planar, Rot3, Spatial, Vec2, Vec3};
    pub use lagrange_core::{Coordinates, Error, Integrator, Mechanism, Rk4, State};
    pub use lagrange_macros::mechanism;
}

/// What generated code names. Not a public API: it may change in any release.
#[doc(hidden)]
pub mod __private {
    pub use core;
    pub use lagrange_core;
    pub use lagrange_core::dynamics;
    pub use lagrange_core::geometry;
    pub use lagrange_core::model::{check_state, Coordinates, Model, State};
    pub use lagrange_core::scalar_ext::ScalarExt;
    pub use lagrange_core::tree;
    pub use lagrange_core::{Error, Mechanism, Result, Scalar};
    pub use nalgebra;
    pub use num_dual;
    pub use num_dual::DualNum;
    pub use std;
}
