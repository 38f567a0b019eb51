//! Name resolution: what each free name of a function refers to, and whether it may be named there.

use super::model::{family_index, Model};
use crate::ast::Decl;
use crate::ctxt::Ctxt;
use crate::names;
use std::collections::BTreeSet;
use syn::ext::IdentExt;
use syn::Ident;

/// Functions of the geometry module, in scope in every function body.
pub(crate) const GEOMETRY_FUNCTIONS: &[&str] = &[
    "vec2",
    "vec3",
    "planar",
    "spatial",
    "rot_x",
    "rot_y",
    "rot_z",
    "rpy",
    "rot_axis",
    "rot3",
    "rot_vector",
    "rot_mrp",
];
/// Single-segment values of Rust's prelude.
const PRELUDE_VALUES: &[&str] = &["Some", "None", "Ok", "Err", "drop"];

/// The free names of a function's body, less a family member's own index.
pub(super) fn free_names(decl: &Decl) -> Vec<Ident> {
    let index = family_index(decl);
    names::free_names(&decl.block)
        .into_iter()
        .filter(|i| Some(i) != index)
        .collect()
}

/// What a function's free names include, for the rules and records that depend on it.
pub(super) struct Uses {
    /// Time, `t`.
    pub(super) time: bool,
    /// A velocity, `x_dot` or `body_dot`.
    pub(super) velocity: bool,
    /// Only parameters and items: the function is a constant.
    pub(super) constant: bool,
}

/// Resolves each of `free` in `context`, once per name, reporting those unknown or out of place.
pub(super) fn resolve_free_names(
    cx: &Ctxt,
    model: &Model,
    context: Context,
    free: &[Ident],
) -> Uses {
    let resolver = Resolver { model, context };
    let mut uses = Uses {
        time: false,
        velocity: false,
        constant: true,
    };
    let mut seen = BTreeSet::new();
    for ident in free.iter().filter(|i| seen.insert(i.to_string())) {
        let name = resolver.resolve(cx, ident);
        uses.time |= name == Some(Name::Time);
        uses.velocity |= matches!(name, Some(Name::CoordVelocity | Name::BodyVelocity));
        uses.constant &= matches!(name, Some(Name::Param | Name::Item));
    }
    uses
}

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
    /// A velocity constraint or a friction row: velocities in scope, inputs not.
    VelocityRow,
    /// A mass, inertia or friction coefficient: a constant.
    Mass,
    /// A rigid body's centre of mass in its frame (`com = ..`): a constant.
    CentreOfMass,
}

/// What a free name refers to.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Name {
    Coord,
    Param,
    Time,
    Body(usize),
    CoordVelocity,
    BodyVelocity,
    Input,
    Item,
}

/// Resolves names in one context.
struct Resolver<'m, 'a> {
    model: &'m Model<'a>,
    context: Context,
}

impl Resolver<'_, '_> {
    /// What `ident` refers to, if anything.
    fn lookup(&self, ident: &Ident) -> Option<Name> {
        let model = self.model;
        let name = ident.to_string();
        let velocity_of = name.strip_suffix("_dot");
        if model.coords.iter().any(|c| c.ident == name) {
            Some(Name::Coord)
        } else if model.params.iter().any(|p| p.ident == name) {
            Some(Name::Param)
        } else if model.inputs.iter().any(|u| u.ident == name) {
            Some(Name::Input)
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
    fn resolve(&self, cx: &Ctxt, ident: &Ident) -> Option<Name> {
        let name = self.lookup(ident);
        let problem = match name {
            None => self.unknown(ident),
            Some(name) => self.out_of_place(ident, name),
        };
        if let Some(message) = problem {
            cx.error_spanned_by(ident, message);
        }
        name
    }

    /// A name that refers to nothing in scope: a typo, or `self` (there is none). Unless a glob
    /// import may bring it in: then rustc decides.
    fn unknown(&self, ident: &Ident) -> Option<String> {
        // `fn bob() -> Vec2 { vec2(self.l, 0.0) }`: parameters are named directly.
        if ident == "self" {
            return Some("declaration functions have no `self`: name parameters directly (`l`, not `self.l`)".to_string());
        }
        if self.model.mechanism.has_glob_import {
            return None;
        }
        // `vec2(theta.sin(), 0.0) * lenght`: a typo, or something not in scope.
        let in_scope = match self.context {
            Context::Position(_) => "a coordinate, parameter, `t`, body or point declared earlier, or item of this module",
            Context::Potential | Context::Constraint => "a coordinate, parameter, `t`, body, point, or item of this module",
            Context::Force if !self.model.inputs.is_empty() => "a coordinate, parameter, input, `t`, body, point, their `_dot` velocities, or item of this module",
            Context::Force | Context::VelocityRow => "a coordinate, parameter, `t`, body, point, their `_dot` velocities, or item of this module",
            Context::Mass | Context::CentreOfMass => "a parameter or an item of this module",
        };
        Some(format!("unknown name `{ident}`: it is not {in_scope}"))
    }

    /// A name that exists but may not be named in this context.
    fn out_of_place(&self, ident: &Ident, name: Name) -> Option<String> {
        match (self.context, name) {
            // `#[particle(mass = m * theta)]`: masses are constants.
            (
                Context::Mass,
                Name::Coord | Name::Time | Name::Body(_) | Name::CoordVelocity | Name::BodyVelocity,
            ) => Some(format!(
                "masses and inertias are constant: they cannot depend on `{ident}`"
            )),
            // `#[rigid_body(.., com = vec3(0.0, 0.0, theta))]`: the body's own geometry.
            (
                Context::CentreOfMass,
                Name::Coord | Name::Time | Name::Body(_) | Name::CoordVelocity | Name::BodyVelocity,
            ) => Some(format!(
                "a centre of mass `com` is a constant point of the body's frame: it cannot depend on `{ident}` (write the motion in the body's function)"
            )),
            (_, Name::CoordVelocity | Name::BodyVelocity) => self.velocity_out_of_place(ident),
            // `#[particle(mass = m + tau)]`, `fn bob() -> Vec2 { vec2(tau, 0.0) }`: what a
            // program sets between steps acts on the mechanism as a force.
            (Context::Force, Name::Input) => None,
            (_, Name::Input) => Some(format!(
                "`{ident}` is an input: inputs act through forces, read in `#[force]`, `#[torque]` and `#[generalized_force]` functions only"
            )),
            (Context::Position(me), Name::Body(b)) => self.body_out_of_order(ident, me, b),
            _ => None,
        }
    }

    /// Velocities are in scope where the equations take them as given: forces, velocity
    /// constraints and friction. Positions, position constraints and potentials are functions of
    /// the configuration alone (their derivatives are taken with respect to coordinates).
    fn velocity_out_of_place(&self, ident: &Ident) -> Option<String> {
        match self.context {
            // `fn bob() -> Vec2 { vec2(theta_dot, 0.0) }`.
            Context::Position(_) => Some(format!("positions cannot depend on velocities: `{ident}` is in scope in forces only")),
            // `#[constraint] fn rod() -> f64 { x_dot }`.
            Context::Constraint => Some(format!("a position constraint cannot depend on velocities: `{ident}` is in scope in `#[velocity_constraint]`s, `#[friction]` and forces")),
            // `#[potential] fn v() -> f64 { theta_dot * theta_dot }`.
            Context::Potential => Some(format!("potentials cannot depend on velocities: `{ident}` is in scope in forces only (write a `#[force]` or `#[generalized_force]`)")),
            Context::Force | Context::VelocityRow | Context::Mass | Context::CentreOfMass => None,
        }
    }

    /// A position is built from the bodies and points declared before it, so positions are
    /// computed in declaration order without a cycle: `fn bob1() -> Vec2 { bob2 + ... }` where
    /// `bob2` comes later, or is `bob1` itself. A family member names earlier members of its own
    /// family: `bob[i - 1]`.
    fn body_out_of_order(&self, ident: &Ident, me: usize, b: usize) -> Option<String> {
        if b < me || (b == me && self.model.bodies[me].count.is_some()) {
            return None;
        }
        let this = self.model.bodies[me].decl.ident();
        Some(if b == me {
            format!("`{this}` cannot use its own position")
        } else {
            format!("`{ident}` is declared after `{this}`: a position can only use bodies and points declared before it")
        })
    }
}
