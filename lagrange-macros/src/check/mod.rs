//! The checks: every rule a declaration must satisfy, each reported at the offending tokens into
//! the error context. The result is the checked model the expansion works from.

mod constraints;
mod forces;
mod gravity;
mod helpers;
mod indices;
mod masses;
mod model;
mod resolve;
mod signatures;
mod structs;

use model::ConstraintRow;
pub use model::{family_index, Body, Dim, Model, Shape};

use crate::ast::{Decl, Mechanism};
use crate::attr::Kind;
use crate::ctxt::Ctxt;
use crate::names;
use resolve::{Context, Name, Resolver};
use std::collections::{BTreeSet, HashMap};
use syn::Ident;

/// Checks `mechanism`, reporting every problem into `cx`. Returns the model when the declaration
/// has its two structs (even if other errors were found, so that they are all reported).
pub fn check<'a>(cx: &Ctxt, mechanism: &'a Mechanism) -> Option<Model<'a>> {
    // `#[mechanism] mod m {}`: one message for both structs.
    if mechanism.coords.is_none() && mechanism.params.is_none() {
        cx.error_at(
            mechanism.span(),
            "a mechanism declares `pub struct Coords { ... }` (the generalized coordinates) and a parameter struct (`pub struct Name { pub m: f64, ... }`: its name is the mechanism's type)",
        );
        return None;
    }
    // `#[mechanism] mod m { struct Pendulum {..} ... }` without `struct Coords`.
    if mechanism.coords.is_none() {
        cx.error_at(
            mechanism.span(),
            "missing `pub struct Coords { ... }`: the generalized coordinates, one `f64` field each",
        );
    }
    // `#[mechanism] mod m { struct Coords {..} ... }` without a parameter struct.
    // `pub struct Pendulum(f64, f64);`: there is a parameter struct, but its fields have no names.
    let tuple = mechanism.other_items.iter().find_map(|item| match item {
        syn::Item::Struct(s) if matches!(&s.fields, syn::Fields::Unnamed(u) if !u.unnamed.is_empty()) => Some(s),
        _ => None,
    });
    if let (None, Some(s)) = (&mechanism.params, tuple) {
        cx.error_spanned_by(
            &s.fields,
            format!(
                "the parameter struct has named fields: `pub struct {} {{ pub m: f64, ... }}`",
                s.ident
            ),
        );
    } else if mechanism.params.is_none() {
        cx.error_at(
            mechanism.span(),
            "missing the parameter struct (`pub struct Name { pub m: f64, ... }`): its name is the mechanism's type",
        );
    }
    let (Some((_, coords)), Some((params_struct, params))) = (&mechanism.coords, &mechanism.params)
    else {
        return None;
    };
    // `struct Coords {}`: nothing moves. (`struct Coords(f64);` was reported as such.)
    let tuple = matches!(
        mechanism.coords.as_ref().map(|(s, _)| &s.fields),
        Some(syn::Fields::Unnamed(_))
    );
    if coords.is_empty() && !tuple {
        cx.error_spanned_by(
            &mechanism.coords.as_ref().unwrap().0.ident,
            "`Coords` needs at least one coordinate",
        );
    }
    structs::check_duplicates(cx, mechanism, coords, params);
    let bodies = model::lay_out_bodies(cx, mechanism);
    let mut model = Model {
        mechanism,
        params_ident: &params_struct.ident,
        coords,
        params,
        potentials: Vec::new(),
        gravities: Vec::new(),
        uniform_gravities: Vec::new(),
        forces: Vec::new(),
        constraints: mechanism
            .decls
            .iter()
            .filter(|d| d.kind().is_constraint())
            .map(|decl| ConstraintRow {
                decl,
                normal: None,
                cone: decl.kind() == Kind::Friction
                    && signatures::return_type_name(decl).as_deref() == Some("Vec2"),
            })
            .collect(),
        free_names: HashMap::new(),
        rheonomic: false,
        rows: bodies.iter().map(|b| b.rows()).sum(),
        inertial_rows: bodies
            .iter()
            .filter(|b| b.shape.has_mass())
            .map(|b| b.rows())
            .sum(),
        bodies,
    };
    for decl in &mechanism.decls {
        signatures::check_signature(cx, decl);
        check_function(cx, &mut model, decl);
    }
    gravity::check_gravity_covers_every_body(cx, &model);
    masses::check_masses(cx, &model);
    indices::check_indices(cx, &model);
    constraints::check_constraint_count(cx, &model);
    masses::check_coordinates_are_used(cx, &model);
    helpers::check_helper_calls(cx, &model);
    Some(model)
}

/// Checks the return type, target and names of one function and records what it uses.
fn check_function<'a>(cx: &Ctxt, model: &mut Model<'a>, decl: &'a Decl) {
    let mut gravity = None;
    let context = match decl.kind() {
        Kind::Particle | Kind::RigidBody | Kind::Point => {
            let index = model
                .bodies
                .iter()
                .position(|b| std::ptr::eq(b.decl, decl))
                .unwrap();
            Context::Position(index)
        }
        Kind::Potential => {
            // `#[potential] fn spring() -> Vec2`: a potential is an energy.
            signatures::expect_return_type(cx, decl, &["f64"], "the potential energy");
            model.potentials.push(decl);
            Context::Potential
        }
        Kind::Gravity => {
            // `#[gravity] fn down() -> f64`: gravity is a field vector.
            let name =
                signatures::expect_return_type(cx, decl, &["Vec2", "Vec3"], "the field vector g");
            let dim = signatures::vector_dim(name.clone());
            let acts_on_something = model
                .bodies
                .iter()
                .any(|b| b.shape.has_mass() && b.shape.dim() == dim);
            // `#[gravity] fn down() -> Vec3` when every body moves in the plane: it acts on nothing.
            if name.is_some() && !acts_on_something {
                let (field, bodies) = if dim == Dim::Two {
                    ("Vec2", "the plane")
                } else {
                    ("Vec3", "space")
                };
                cx.error_spanned_by(
                    decl.output(),
                    format!("a `{field}` field acts on bodies in {bodies}, and there are none"),
                );
            }
            gravity = Some(dim);
            Context::Potential
        }
        Kind::Force | Kind::Torque | Kind::GeneralizedForce => {
            if let Some(force) = forces::check_force_target(cx, model, decl) {
                model.forces.push(force);
            }
            Context::Force
        }
        Kind::Constraint | Kind::Unilateral => {
            // `#[constraint] fn rod() -> Vec2`: a constraint row is one scalar.
            signatures::expect_return_type(
                cx,
                decl,
                &["f64"],
                "the constraint function, zero when satisfied",
            );
            constraints::check_not_a_comparison(cx, decl);
            Context::Constraint
        }
        Kind::VelocityConstraint => {
            signatures::expect_return_type(
                cx,
                decl,
                &["f64"],
                "the constraint, zero when satisfied, affine in velocities",
            );
            constraints::check_not_a_comparison(cx, decl);
            Context::Force
        }
        Kind::Friction => {
            // `#[friction(..)] fn slip() -> Vec3`: a slip velocity lies in the tangent plane.
            signatures::expect_return_type(
                cx,
                decl,
                &["f64", "Vec2"],
                "the slip velocity: along one tangent direction (planar friction), or its \
                 components along two orthonormal tangent directions (friction in the tangent \
                 plane, the Coulomb cone)",
            );
            constraints::check_friction(cx, model, decl);
            Context::Force
        }
    };
    let index = family_index(decl);
    let free: Vec<Ident> = names::free_names(&decl.block)
        .into_iter()
        .filter(|i| Some(i) != index)
        .collect();
    let mut seen = BTreeSet::new();
    // Each name is resolved (and reported) once per function.
    let mut constant = true;
    let mut reads_velocity = false;
    for ident in free.iter().filter(|i| seen.insert(i.to_string())) {
        let name = Resolver { model, context }.resolve(cx, ident);
        reads_velocity |= matches!(name, Some(Name::CoordVelocity | Name::BodyVelocity));
        let is_force = matches!(
            decl.kind(),
            Kind::Force | Kind::Torque | Kind::GeneralizedForce
        );
        if name == Some(Name::Time) && !is_force {
            model.rheonomic = true;
        }
        constant &= matches!(name, Some(Name::Param | Name::Item));
    }
    // `#[velocity_constraint] fn on_line() -> f64 { y - x }`: without a velocity it constrains
    // positions, which is a `#[constraint]`.
    if decl.kind() == Kind::VelocityConstraint && !reads_velocity {
        cx.error_spanned_by(
            decl.ident(),
            "a `#[velocity_constraint]` is affine in velocities (`x_dot`, `body_dot`), and this one \
             names none: a condition on positions alone is a `#[constraint]`",
        );
    }
    match gravity {
        Some(dim) if constant => model.uniform_gravities.push((decl, dim)),
        Some(dim) => model.gravities.push((decl, dim)),
        None => {}
    }
    model.free_names.insert(decl.ident().to_string(), free);
}
