//! Name resolution: what each free name of a function refers to, and whether it may be named there.

use super::model::Model;
use crate::ctxt::Ctxt;
use syn::ext::IdentExt;
use syn::Ident;

/// Functions of the geometry module, in scope in every function body.
pub const GEOMETRY_FUNCTIONS: &[&str] = &[
    "vec2", "vec3", "planar", "spatial", "rot_x", "rot_y", "rot_z",
];
/// Single-segment values of Rust's prelude.
const PRELUDE_VALUES: &[&str] = &["Some", "None", "Ok", "Err", "drop"];

/// Where a name is being resolved.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(super) enum Context {
    /// The position of the body with this index.
    Position(usize),
    /// A potential or gravity.
    Potential,
    /// A holonomic or unilateral constraint.
    Constraint,
    /// A force, torque or generalized force.
    Force,
    /// A mass or inertia.
    Mass,
}

/// What a free name refers to.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(super) enum Name {
    Coord,
    Param,
    Time,
    Body(usize),
    CoordVelocity,
    BodyVelocity,
    Item,
}

pub(super) struct Resolver<'m, 'a> {
    pub(super) model: &'m Model<'a>,
    pub(super) context: Context,
}

impl Resolver<'_, '_> {
    fn lookup(&self, ident: &Ident) -> Option<Name> {
        let model = self.model;
        let name = ident.to_string();
        let velocity_of = name.strip_suffix("_dot");
        if model.coords.iter().any(|c| c.ident == name) {
            Some(Name::Coord)
        } else if model.params.iter().any(|p| p.ident == name) {
            Some(Name::Param)
        } else if name == "t" {
            Some(Name::Time)
        } else if let Some(b) = model.bodies.iter().position(|b| b.decl.ident() == &name) {
            Some(Name::Body(b))
        // `r#type_dot` is not an identifier: the velocity of `r#type` is `type_dot`.
        } else if velocity_of.is_some_and(|v| model.coords.iter().any(|c| c.ident.unraw() == v)) {
            Some(Name::CoordVelocity)
        } else if velocity_of
            .is_some_and(|v| model.bodies.iter().any(|b| b.decl.ident().unraw() == v))
        {
            Some(Name::BodyVelocity)
        } else if model.mechanism.item_names.iter().any(|i| *i == name)
            || GEOMETRY_FUNCTIONS.contains(&name.as_str())
            || PRELUDE_VALUES.contains(&name.as_str())
        {
            Some(Name::Item)
        } else {
            None
        }
    }

    /// Resolves a free name, reporting one that is unknown or not allowed here.
    pub(super) fn resolve(&self, cx: &Ctxt, ident: &Ident) -> Option<Name> {
        let name = self.lookup(ident);
        match (self.context, name) {
            // `fn bob() -> Vec2 { vec2(self.l, 0.0) }`: parameters are named directly.
            (_, None) if ident == "self" => {
                cx.error_spanned_by(ident, "declaration functions have no `self`: name parameters directly (`l`, not `self.l`)")
            }
            // `vec2(theta.sin(), 0.0) * lenght`: a typo, or something not in scope (unless a glob
            // import may bring it in: then rustc decides).
            (_, None) if !self.model.mechanism.has_glob_import => {
                cx.error_spanned_by(ident, self.unknown_message(ident))
            }
            // `fn bob() -> Vec2 { vec2(theta_dot, 0.0) }`.
            (Context::Position(_), Some(Name::CoordVelocity | Name::BodyVelocity)) => cx.error_spanned_by(
                ident,
                format!("positions cannot depend on velocities: `{ident}` is in scope in forces only"),
            ),
            // `#[constraint] fn rod() -> f64 { x_dot }`.
            (Context::Constraint, Some(Name::CoordVelocity | Name::BodyVelocity)) => cx.error_spanned_by(
                ident,
                format!("a position constraint cannot depend on velocities: `{ident}` is in scope in `#[velocity_constraint]`s, `#[friction]` and forces"),
            ),
            // `#[potential] fn v() -> f64 { theta_dot * theta_dot }`.
            (Context::Potential, Some(Name::CoordVelocity | Name::BodyVelocity)) => cx.error_spanned_by(
                ident,
                format!("potentials cannot depend on velocities: `{ident}` is in scope in forces only (write a `#[force]` or `#[generalized_force]`)"),
            ),
            // `fn bob1() -> Vec2 { bob2 + ... }` where `bob2` comes later (or is `bob1` itself).
            // A family member names earlier members of its own family: `bob[i - 1]`.
            (Context::Position(me), Some(Name::Body(b)))
                if b == me && self.model.bodies[me].count.is_some() => {}
            (Context::Position(me), Some(Name::Body(b))) if b >= me => {
                let this = self.model.bodies[me].decl.ident();
                let message = if b == me {
                    format!("`{this}` cannot use its own position")
                } else {
                    format!("`{ident}` is declared after `{this}`: a position can only use bodies and points declared before it")
                };
                cx.error_spanned_by(ident, message);
            }
            // `#[particle(mass = m * theta)]`: masses are constants.
            (Context::Mass, Some(Name::Coord | Name::Time | Name::Body(_) | Name::CoordVelocity | Name::BodyVelocity)) => {
                cx.error_spanned_by(ident, format!("masses and inertias are constant: they cannot depend on `{ident}`"))
            }
            _ => {}
        }
        name
    }

    fn unknown_message(&self, ident: &Ident) -> String {
        let in_scope = match self.context {
            Context::Position(_) => "a coordinate, parameter, `t`, body or point declared earlier, or item of this module",
            Context::Potential | Context::Constraint => "a coordinate, parameter, `t`, body, point, or item of this module",
            Context::Force => "a coordinate, parameter, `t`, body, point, their `_dot` velocities, or item of this module",
            Context::Mass => "a parameter or an item of this module",
        };
        format!("unknown name `{ident}`: it is not {in_scope}")
    }
}
