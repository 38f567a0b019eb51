#![doc = include_str!("../README.md")]
//!
//! ## The crate root
//!
//! The root exports, by name, what a user of a declared mechanism calls: the [`prelude`] (the
//! [`mechanism`](macro@mechanism) attribute and [`urdf`](macro@urdf), which writes a declaration from a
//! robot's file, the [`Mechanism`] trait with its [`State`] and
//! [`Coordinates`], [`Validated`], [`Error`], the integrators and the solver [`Stepper`], the
//! geometry a declaration is written in), and beside it the rest of the stepping interface
//! ([`Event`], [`Outcome`], [`Stats`], [`Fixed`], …), the analysis entry points with their options
//! and results, the constraint tools ([`Constraints`], [`ContactOptions`], [`consistent_state`],
//! [`consistent_state_holding`], [`constraint_forces`]) and the sensitivities' [`Seed`].
//! Everything else — the low-level [`model::Model`] trait that generated code implements, the
//! dynamics kernels, the small dense solves — stays in its module: [`model`], [`evaluation`],
//! [`dynamics`], [`tree`], [`linalg`], [`integrate`], [`analysis`], [`constraints`], [`geometry`],
//! [`inertia`], [`scalar_ext`], [`error`], [`sensitivity`], [`declaration`], [`animation`] (a
//! trajectory as an HTML animation), and [`ffi`] with [`export_c!`] (C embedding).
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

/// Everything a declaration and its user need: `use lagrange::prelude::*;`. The crate root
/// exports the same names (the root is this list and the rest of the user-facing API), and
/// `#[mechanism]` knows them by this list.
pub mod prelude {
    pub use lagrange_core::geometry::{
        planar, rot3, rot_axis, rot_mrp, rot_vector, rot_x, rot_y, rot_z, rpy, spatial, vec2, vec3,
    };
    pub use lagrange_core::geometry::{Planar, Rot3, Spatial, SpatialVelocity, Vec2, Vec3};
    pub use lagrange_core::integrate::{
        Dop853, Dopri5, GaussLegendre2, ImplicitMidpoint, Integrator, Radau5, Rk4, Stepper,
        StormerVerlet, Variational,
    };
    pub use lagrange_core::{Coordinates, Error, Mechanism, State, Validated};
    pub use lagrange_macros::{mechanism, urdf};
}

/// A robot's URDF file read at compile time into the declaration a user would write, expanded by
/// [`mechanism`](macro@mechanism).
///
/// ```
/// use lagrange::prelude::*;
///
/// // tests/urdf/two_link_arm.urdf: two links swinging in the x-z plane, damped joints.
/// #[lagrange::urdf("tests/urdf/two_link_arm.urdf")]
/// pub mod arm {
///     /// Items beside the file's: a spring holding the elbow straight.
///     #[generalized_force(on = elbow)]
///     fn elbow_spring() -> f64 {
///         -5.0 * elbow
///     }
/// }
///
/// use arm::{Arm, Coords, State};
/// let p = Arm::default(); // the file's values, and g = 9.81
/// assert_eq!((p.g, p.shoulder_damping, p.elbow_damping), (9.81, 0.3, 0.1));
/// let sys = p.validated()?;
/// let mut s = State::at_rest(Coords { shoulder: 0.3, elbow: -0.2 });
/// for _ in 0..100 {
///     sys.step::<Rk4>(&mut s, 1e-3)?;
/// }
/// println!("q(0.1) = {:?}", s.q);
/// # Ok::<(), lagrange::Error>(())
/// ```
///
/// **Form.** An attribute on a module, so that forces, torques, potentials and constraints of the
/// user's stand beside what the file gives, naming its joints and links, as in any declaration;
/// the module's name, in upper camel case, names the parameter struct (`arm` → `Arm`). The path
/// is relative to the calling crate's `CARGO_MANIFEST_DIR` (not to the source file, as for
/// `include_str!`: a procedural macro does not know its caller's file on stable Rust); the file is
/// included in the build (`include_bytes!`), so cargo rebuilds when it changes.
///
/// **What the file becomes.**
/// - `Coords`: one coordinate per revolute, continuous or prismatic joint, named after the joint
///   (lower case, characters other than letters, digits and `_` turned into `_`, a leading digit
///   prefixed with `joint_`, a keyword suffixed with `_`), in depth-first order from the root
///   link, siblings in the file's order.
/// - One `#[rigid_body]` per link moved by such a joint, named after the link (same rules, prefix
///   `link_`), declared by its frame: `parent.joint(offset, rpy(..) * rot_z(q))` (`rot_x`,
///   `rot_y`, `rot_z` for an axis along a coordinate axis, with `-q` for the opposite one,
///   `rot_axis(axis, q)` otherwise), a prismatic joint as a slide of the joint frame along its
///   axis; its `com` and full inertia tensor from `<inertial>` (the inertial frame's rotation
///   turned into the tensor). A link joined by a fixed joint moves with its parent: its mass is
///   merged into the parent's body (total mass, centre of mass, tensor by the parallel-axis
///   theorem), its children are placed through the fixed joint's origin; links fixed to the root
///   cannot move and are left out. So the declaration takes the rigid tree pass (articulated-body
///   algorithm; the generated `RigidTree` impl shows it).
/// - The parameter struct: `g`, gravity's magnitude along −z (URDF's z is up), and for each
///   joint whose `<dynamics>` gives them, `<joint>_damping` and `<joint>_friction`, with
///   `Default` holding the file's values and g = 9.81.
/// - Joint forces as `#[generalized_force]`s: viscous damping −c q̇, and `friction` as Coulomb
///   sliding friction of constant magnitude, −f sgn(q̇) (sgn(0) = 0): no sticking, and a force
///   that jumps where q̇ changes sign, which fixed-step methods step over with an O(h) error there.
/// - Not read: `<limit>` (limits are not enforced), `<visual>`, `<collision>`, `<transmission>`,
///   `<gazebo>`. Joint actuation is today a `#[generalized_force(on = joint)]` written in the
///   module; a declaration has no inputs yet, and when it does, one per actuated joint is what
///   this macro is to add beside the joint's damping.
///
/// **Refused**, as one compile error at the path: a file that cannot be read (naming the path
/// as resolved); malformed XML, a missing attribute or a value that is not a finite number (with
/// the file's `line:column`); a mimic, floating or planar joint, a link with two parents, joints
/// forming a loop, more than one root link, a moving link that carries no mass (naming the joint
/// or link); two joints or links whose identifiers coincide, or that collide with the
/// declaration's own names (`t`, `g`, `gravity`, `<name>_dot`).
pub use lagrange_macros::urdf;
pub use prelude::*;

pub use lagrange_core::analysis::{
    constrained_equilibrium, continuation, equilibrium, linearize, linearize_driven, normal_modes,
    stability, Branch, BranchPoint, ConstrainedEquilibrium, DrivenLinearization, Equilibrium,
    EquilibriumOptions, Linearization, NormalModes, Stability, StabilityAnalysis,
};
pub use lagrange_core::constraints::{
    consistent_state, consistent_state_holding, constraint_forces, ConstraintForces, Constraints,
    ContactOptions, ModeChange, RowMode,
};
pub use lagrange_core::error::Result;
/// The scalar every declaration function is evaluated on (`f64` or a dual number): the bound of a
/// helper function called from one, `fn arm<D: lagrange::Scalar>(angle: D) -> D`.
pub use lagrange_core::geometry::Scalar;
pub use lagrange_core::integrate::{
    Direction, Event, EventHit, Fixed, Observation, Outcome, Stats, StopReason,
};
pub use lagrange_core::sensitivity::{Seed, Sensitivities};

pub use lagrange_core::ensemble;
pub use lagrange_core::inputs::{self, Driven, Inputs};
pub use lagrange_core::{
    analysis, animation, constraints, declaration, dynamics, error, evaluation, geometry, inertia,
    integrate, linalg, mechanism, model, parameters, scalar_ext, sensitivity, tree, validated,
};
/// C embedding: [`export_c!`] and what it uses ([`ffi::Status`], [`ffi::Export`], …).
pub use lagrange_ffi as ffi;
pub use lagrange_ffi::export_c;

/// What generated code names. Not a public API: it may change in any release.
#[doc(hidden)]
pub mod __private {
    pub use core;
    pub use lagrange_core;
    pub use lagrange_core::dynamics;
    pub use lagrange_core::evaluation::{Dynamics, Prepare};
    pub use lagrange_core::geometry;
    pub use lagrange_core::inertia;
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
