//! The checks: every rule a declaration must satisfy, each reported at the offending tokens into
//! the error context. The result is the checked model the expansion works from.
//!
//! [`check`] builds the model ([`model`]) and runs the rules in order; each module holds the rules
//! of one concern, each rule a function that says what it forbids and why.

mod charts;
mod constraints;
mod forces;
mod helpers;
mod indices;
mod masses;
mod model;
mod potentials;
mod resolve;
mod signatures;
mod structs;
mod velocities;

pub use charts::{Chart, ChartKind};
pub use model::{attribute_sets, family_index, Body, Dim, Force, Model, Shape};
pub(crate) use resolve::GEOMETRY_FUNCTIONS;

use crate::ast::{Decl, Mechanism};
use crate::attr::Kind;
use crate::ctxt::Ctxt;
use resolve::Context;

/// Checks `mechanism`, reporting every problem into `cx`. Returns the model when the declaration
/// has its two structs (even if other errors were found, so that they are all reported).
pub fn check<'a>(cx: &Ctxt, mechanism: &'a Mechanism) -> Option<Model<'a>> {
    let (params_ident, coords, params) = structs::check_structs(cx, mechanism)?;
    structs::check_duplicates(cx, mechanism, coords, params);
    let mut model = Model::new(cx, mechanism, params_ident, coords, params);
    for decl in &mechanism.decls {
        signatures::check_signature(cx, decl);
        check_function(cx, &mut model, decl);
    }
    potentials::check_gravity_covers_every_body(cx, &model);
    masses::check_masses(cx, &model);
    indices::check_indices(cx, &model);
    indices::check_arrays_read_by_element(cx, &model);
    constraints::check_constraint_count(cx, &model);
    masses::check_coordinates_are_used(cx, &model);
    helpers::check_helper_calls(cx, &model);
    model.charts = charts::rotation_charts(cx, &model);
    model.angular_velocities = velocities::check_angular_velocities(cx, &model);
    Some(model)
}

/// One function: the rules of its kind, then its free names, each resolved once. Records what it
/// adds to the model: its free names, a dependence on time, a gravity field.
fn check_function<'a>(cx: &Ctxt, model: &mut Model<'a>, decl: &'a Decl) {
    let (context, field) = check_kind(cx, model, decl);
    let free = resolve::free_names(decl);
    let uses = resolve::resolve_free_names(cx, model, context, &free);
    let is_force = matches!(
        decl.kind(),
        Kind::Force | Kind::Torque | Kind::GeneralizedForce
    );
    model.rheonomic |= uses.time && !is_force;
    if decl.kind() == Kind::VelocityConstraint {
        constraints::check_velocity_constraint_names_a_velocity(cx, decl, uses.velocity);
    }
    match field {
        Some(dim) if uses.constant => model.uniform_gravities.push((decl, dim)),
        Some(dim) => model.gravities.push((decl, dim)),
        None => {}
    }
    model.free_names.insert(decl.ident().to_string(), free);
}

/// The rules of a function's kind (its return type, target or contact), recording potentials,
/// forces and friction contacts. Returns where its names are resolved and, for a gravity field,
/// the field's dimension.
fn check_kind<'a>(cx: &Ctxt, model: &mut Model<'a>, decl: &'a Decl) -> (Context, Option<Dim>) {
    let context = match decl.kind() {
        Kind::Particle | Kind::RigidBody | Kind::Point => Context::Position(model.body_index(decl)),
        Kind::Potential => {
            potentials::check_potential(cx, decl);
            model.potentials.push(decl);
            Context::Potential
        }
        Kind::Gravity => {
            let dim = potentials::check_gravity_field(cx, model, decl);
            return (Context::Potential, Some(dim));
        }
        Kind::Force | Kind::Torque | Kind::GeneralizedForce => {
            let force = forces::check_force(cx, model, decl);
            model.forces.extend(force);
            Context::Force
        }
        Kind::Constraint | Kind::Unilateral => {
            constraints::check_position_constraint(cx, decl);
            Context::Constraint
        }
        Kind::VelocityConstraint => {
            constraints::check_velocity_constraint(cx, decl);
            Context::VelocityRow
        }
        Kind::Friction => {
            constraints::check_friction(cx, model, decl);
            Context::VelocityRow
        }
    };
    (context, None)
}
