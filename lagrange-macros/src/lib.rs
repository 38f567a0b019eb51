//! The `#[mechanism]` attribute of `lagrange`. Use it through the `lagrange` crate, which documents
//! the declaration; this crate only turns a declaration into code:
//!
//! parse ([`ast`], [`attr`]) → check, collecting every error ([`check`], [`ctxt`]) → expand
//! ([`expand`]). On error the user's items are still emitted, with stubs for what the rest of their
//! code names, so one mistake gives one message.

mod ast;
mod attr;
mod check;
mod ctxt;
mod expand;
mod lift;
mod names;
mod optimize;

#[cfg(test)]
mod expand_tests;

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
/// `#[gravity]` (`Vec2`/`Vec3`), `#[force(on = body)]` (`Vec2`/`Vec3`), `#[torque(on = planar_body)]`
/// and `#[generalized_force(on = coordinate)]` (`f64`); constraint rows `#[constraint]` (g = 0),
/// `#[unilateral]` (c ≥ 0), `#[velocity_constraint]` (h = 0, affine in velocities) and
/// `#[friction(on = contact, kinetic = μₖ, stiction = μₛ)]` (the slip velocity), all `f64`. Bodies
/// name coordinates, parameters, `t` and earlier bodies; potentials and position constraints every
/// body; forces, velocity constraints and friction also `<coordinate>_dot` and `<body>_dot`. Other
/// items of the module are kept as written.
///
/// Generated in the module: `Coords<T = f64>`, `DOF`, `State`, `Bodies<T = f64>` and
/// `BodyVelocities<T = f64>` with `bodies(&state)` and `body_velocities(&state)` on the parameter
/// struct, and `Model` and `Mechanism` impls for it (plus `Constraints` when constraints are declared). See the `lagrange` crate's README, "The
/// declaration"; mistakes are compile errors at the offending tokens, all reported at once.
#[proc_macro_attribute]
pub fn mechanism(attr: TokenStream, item: TokenStream) -> TokenStream {
    expand::expand(attr.into(), item.into()).into()
}
