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
/// inertia = ..)]` (`Planar`, or `Spatial` with `inertia = [I1, I2, I3]`), `#[potential]` (`f64`),
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
