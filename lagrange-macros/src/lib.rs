//! The `#[mechanism]` attribute of `lagrange`. Use it through the `lagrange` crate, which documents
//! the declaration; this crate only turns a declaration into code:
//!
//! parse (modules `ast`, `attr`) → check, collecting every error (`check`, `ctxt`) → expand
//! (`expand`). On error (`expand::fallback`) the user's items are still emitted, with stubs for what the rest of their
//! code names, so one mistake gives one message.

mod affine;
mod ast;
mod attr;
mod check;
mod components;
mod ctxt;
mod expand;
mod lift;
mod named_bodies;
mod names;
mod optimize;
mod potentials;
mod structure;
mod symbolic;
mod urdf;

#[cfg(test)]
mod expand_tests;
#[cfg(test)]
mod robustness_tests;

use proc_macro::TokenStream;

/// Turns an inline module declaring a mechanism into typed equations of motion.
///
/// ```text
/// #[mechanism]
/// pub mod pendulum {
///     pub struct Coords { pub theta: f64 }              // generalized coordinates
///     pub struct Pendulum { pub m: f64, pub l: f64, pub g: f64 } // parameters: the mechanism's type
///
///     #[particle(mass = m)]
///     fn bob() -> Vec2 { vec2(theta.sin(), -theta.cos()) * l }
///
///     #[gravity]
///     fn down() -> Vec2 { vec2(0.0, -g) }
/// }
/// ```
///
/// Items: `#[particle(mass = ..)]` and `#[point]` (return `Vec2`/`Vec3`), `#[rigid_body(mass = ..,
/// inertia = ..)]` (`Planar`, or `Spatial` with `inertia = [I1, I2, I3]` or a full tensor
/// `[[ixx, ixy, ixz], [ixy, iyy, iyz], [ixz, iyz, izz]]`, optionally `com = ..`), `#[potential]` (`f64`),
/// `#[gravity]` (`Vec2`/`Vec3`), `#[force(on = body)]` (`Vec2`/`Vec3`), `#[torque(on = rigid_body)]`
/// (`f64` on a planar body, `Vec3` on a spatial one) and `#[generalized_force(on = coordinate)]`
/// (`f64`); constraint rows `#[constraint]` (g = 0),
/// `#[unilateral]` (c ≥ 0), `#[velocity_constraint]` (h = 0, affine in velocities) and
/// `#[friction(on = contact, kinetic = μₖ, stiction = μₛ)]` (the slip velocity), all `f64`; a
/// `#[friction]` returning `Vec2` is friction in the contact's tangent plane (the Coulomb cone, its
/// components the slip along two orthonormal tangent directions, runtime rows `name.x`, `name.y`). Bodies
/// name coordinates, parameters, `t` and earlier bodies; potentials and position constraints every
/// body; forces, velocity constraints and friction also `<coordinate>_dot` and `<body>_dot`. Other
/// items of the module are kept as written.
///
/// **Rigid bodies by their frames.** Without `com`, a rigid body's function returns its centre of
/// mass and its axes (`planar(centre, angle)`, `spatial(centre, rotation)`), and `inertia` is about
/// the centre of mass in those axes: one moment (planar), or the principal moments `[I1, I2, I3]`
/// (spatial: the axes are principal). With `com = EXPR` (`vec2(..)` for a `Planar` body, `vec3(..)`
/// for a `Spatial` one; parameters and literals only, like `mass`) the function returns the pose of
/// the body's *frame* — a joint frame, as a robot file gives it — and the centre of mass lies at
/// `com` in that frame (world position `pose.point(com)`). A spatial body's inertia may be the full
/// tensor about the centre of mass in the frame's axes, `inertia = [[ixx, ixy, ixz], [ixy, iyy,
/// iyz], [ixz, iyz, izz]]` (the tensor's entries: a robot file's products of inertia `ixy`, `ixz`,
/// `iyz` as they stand in the tensor), with or without `com`. Such a body is, everywhere a
/// declaration names it, what its function returns: `Bodies.<body>` and `<body>` in later bodies,
/// potentials and forces are the frame; `<body>_dot` its derivative (`linear`, or a planar body's
/// `position`, the velocity of the frame's origin; the angular velocity unchanged). Gravity and
/// `#[force(on = body)]` act at the centre of mass; `#[torque]` as for any body. `validate` refuses
/// a tensor that is not finite, symmetric (to 1e-12 of its size) and positive definite, or whose
/// principal moments violate the triangle inequality, and a `com` that is not finite
/// (`Error::InvalidInertia`). A link placed from its parent's joint reads like a row of a robot
/// file's table:
///
/// ```text
/// #[rigid_body(mass = m2, com = vec3(0.0, 0.02, 0.15),
///              inertia = [[ixx2, ixy2, 0.0], [ixy2, iyy2, 0.0], [0.0, 0.0, izz2]])]
/// fn link2() -> Spatial {
///     link1.joint(vec3(0.0, 0.0, 0.33), rpy(1.5707963267948966, 0.0, 0.0) * rot_z(q2))
/// }
/// ```
///
/// `Spatial::joint(origin, rotation)` is `spatial(self.point(origin), self.rotation * rotation)`,
/// `Planar::joint(origin, angle)` is `planar(self.point(origin), self.angle + angle)`. Constant
/// rotations are written `rpy(roll, pitch, yaw)` (Rz(yaw)·Ry(pitch)·Rx(roll), a robot file's
/// convention), `rot_axis(axis, angle)` (the axis normalised) or `rot3([[..], [..], [..]])` (rows);
/// a `rot3` matrix or a `rot_axis` axis written from parameters and literals is checked by
/// `validate` (`Error::InvalidRotation`: not orthonormal to 1e-9 with determinant +1, or an axis of
/// zero length).
///
/// **Arrays and families.** A coordinate may be an array, `pub theta: [f64; LINKS]`, its length an
/// integer literal or a `const LINKS: usize = 8;` of the module; in every function `theta` is then
/// an array (`theta[i]`, and `theta_dot[i]` in forces), and `Coords { theta: [..] }` holds it as
/// written (messages name elements `theta[3]`). A body or point written once for many members is a
/// *family*: `count = N` in its attribute and the member's index as the function's one argument.
/// The function is evaluated for `i = 0, 1, …, N − 1` in order, and may read earlier members of its
/// own family (`bob[i - 1]`); everywhere else the family is an array of positions (`bob[k]`,
/// `bob_dot[k]`), in `Bodies` too. A force on a family is a family of the same length, one force
/// per member:
///
/// ```text
/// #[mechanism]
/// pub mod chain {
///     pub const LINKS: usize = 8;
///     pub struct Coords { pub theta: [f64; LINKS] }
///     pub struct Chain { pub m: f64, pub l: f64, pub g: f64, pub c: f64 }
///
///     #[particle(mass = m, count = LINKS)]
///     fn bob(i: usize) -> Vec2 {
///         let link = vec2(theta[i].sin(), -theta[i].cos()) * l;
///         if i == 0 { link } else { bob[i - 1] + link }
///     }
///
///     #[force(on = bob, count = LINKS)]
///     fn drag(i: usize) -> Vec2 { bob_dot[i] * (-c) }
///
///     #[gravity]
///     fn down() -> Vec2 { vec2(0.0, -g) }
/// }
/// ```
///
/// Compile errors: a literal index past an array or family (`theta[8]` of 8), a family indexing an
/// array with its own index when it has more members than the array has elements, a family of
/// forces whose length differs from its bodies'. Torques and generalized forces act on single
/// bodies and scalar coordinates.
///
/// **What the expansion does for speed.** Subexpressions that name only parameters (`alpha.sin()`,
/// `l1 * l2`) are evaluated once in `f64` and lifted, since their derivatives vanish; `sin` and
/// `cos` of the same coordinate (or array element) share one `sin_cos`.
///
/// Generated in the module: `Coords<T = f64>`, `DOF`, `State`, `Bodies<T = f64>` and
/// `BodyVelocities<T = f64>` with `bodies(&state)` and `body_velocities(&state)` on the parameter
/// struct, and `Model` and `Mechanism` impls for it (plus `Constraints` when constraints are declared). See the `lagrange` crate's README, "The
/// declaration"; mistakes are compile errors at the offending tokens, all reported at once.
#[proc_macro_attribute]
pub fn mechanism(attr: TokenStream, item: TokenStream) -> TokenStream {
    expand::expand(attr.into(), item.into()).into()
}

/// A robot's URDF file read at compile time into the declaration `#[mechanism]` takes:
/// `#[urdf("robots/arm.urdf")] pub mod arm {}`, the path relative to the calling crate's
/// `CARGO_MANIFEST_DIR`. Documented, with an example, where the `lagrange` crate re-exports it
/// (`lagrange::urdf`).
#[proc_macro_attribute]
pub fn urdf(attr: TokenStream, item: TokenStream) -> TokenStream {
    urdf::expand(attr.into(), item.into()).into()
}
