//! What the mass matrix needs: constant masses and inertias, and every coordinate moving a body.

use super::model::{Body, Model, Shape};
use super::resolve::{resolve_free_names, Context};
use crate::attr::{Inertia, Kind};
use crate::ctxt::Ctxt;
use crate::names;
use std::collections::BTreeSet;

/// Masses and inertias: present where needed, constant. (Points have none; malformed arguments
/// were reported while parsing.)
pub(super) fn check_masses(cx: &Ctxt, model: &Model) {
    for body in &model.bodies {
        let args = &body.decl.args;
        if args.kind == Kind::Point || args.malformed {
            continue;
        }
        check_mass(cx, model, body);
        if args.kind == Kind::RigidBody {
            check_inertia(cx, model, body);
            check_centre_of_mass(cx, model, body);
        }
    }
}

/// A body has a mass, a constant: `#[particle] fn bob() -> Vec2` has none.
fn check_mass(cx: &Ctxt, model: &Model, body: &Body) {
    let args = &body.decl.args;
    match &args.mass {
        None => cx.error_spanned_by(
            &args.attr,
            format!(
                "`{}` has no mass: write `#[{}(mass = ...)]`",
                body.decl.ident(),
                args.kind.name()
            ),
        ),
        Some(mass) => check_attribute(cx, model, body, mass),
    }
}

/// A rigid body also has its inertia, constant: one moment about the centre of mass (planar) or
/// three principal moments (spatial). `#[rigid_body(mass = m)] fn bar() -> Planar` has none.
fn check_inertia(cx: &Ctxt, model: &Model, body: &Body) {
    let args = &body.decl.args;
    match &args.inertia {
        None => cx.error_spanned_by(
            &args.attr,
            format!("rigid body `{}` has no inertia: add `inertia = ...` (one moment, or `[I1, I2, I3]`)", body.decl.ident()),
        ),
        Some(Inertia::Moment(e)) => check_attribute(cx, model, body, e),
        Some(Inertia::Principal(array)) => {
            // `inertia = [a, b]`: three principal moments.
            if array.elems.len() != 3 {
                cx.error_spanned_by(array, "principal moments are three: `[I1, I2, I3]`");
            }
            array.elems.iter().for_each(|e| check_attribute(cx, model, body, e));
        }
        Some(Inertia::Tensor(rows)) => {
            // `inertia = [[a, 0.0], [0.0, b]]`: a tensor in space is 3×3.
            let square = rows.elems.len() == 3
                && rows.elems.iter().all(|row| {
                    matches!(crate::ast::ungroup(row), syn::Expr::Array(r) if r.elems.len() == 3)
                });
            if !square {
                cx.error_spanned_by(
                    rows,
                    "an inertia tensor is three rows of three: `[[ixx, ixy, ixz], [ixy, iyy, iyz], [ixz, iyz, izz]]`",
                );
            }
            check_attribute(cx, model, body, &syn::Expr::Array(rows.clone()));
        }
    }
}

/// A rigid body's `com`, if given, is a constant vector of the body's dimension: `vec2(..)` for a
/// `Planar` body, `vec3(..)` for a `Spatial` one. A constructor of the other dimension is reported
/// here; any other expression is typed by rustc, at its tokens, as a `Vec2<f64>` or `Vec3<f64>`.
fn check_centre_of_mass(cx: &Ctxt, model: &Model, body: &Body) {
    let Some(com) = &body.decl.args.com else {
        return;
    };
    resolve_free_names(
        cx,
        model,
        Context::CentreOfMass,
        &attribute_names(body, com),
    );
    let (expected, other) = match body.shape {
        Shape::Planar => ("vec2", "vec3"),
        _ => ("vec3", "vec2"),
    };
    // `#[rigid_body(mass = m, inertia = i, com = vec3(0.0, 0.0, l))] fn arm() -> Planar`.
    if let syn::Expr::Call(call) = crate::ast::ungroup(com) {
        if matches!(crate::ast::ungroup(&call.func), syn::Expr::Path(p) if p.path.is_ident(other)) {
            let shape = if body.shape == Shape::Planar {
                "Planar"
            } else {
                "Spatial"
            };
            cx.error_spanned_by(
                com,
                format!("the centre of mass of a `{shape}` body is a point of its frame: `com = {expected}(..)`"),
            );
        }
    }
}

/// A body's mass or inertia is a constant; a family's may name its index (`mass = m[i]`).
fn check_attribute(cx: &Ctxt, model: &Model, body: &Body, expr: &syn::Expr) {
    resolve_free_names(cx, model, Context::Mass, &attribute_names(body, expr));
}

/// The free names of a body's attribute, less a family's own index.
fn attribute_names(body: &Body, expr: &syn::Expr) -> Vec<syn::Ident> {
    let index = super::model::family_index(body.decl);
    let names = names::free_names_of_expr(expr).into_iter();
    names.filter(|name| Some(name) != index).collect()
}

/// A mass, inertia or friction coefficient is a constant: it names only parameters and module
/// items, never coordinates, time, bodies or velocities.
pub(super) fn check_constant(cx: &Ctxt, model: &Model, expr: &syn::Expr) {
    resolve_free_names(cx, model, Context::Mass, &names::free_names_of_expr(expr));
}

/// Every coordinate moves some body: a coordinate that no position depends on (`Coords { x, y }`
/// where no position names `y`) has a zero row in the mass matrix, which is then singular.
pub(super) fn check_coordinates_are_used(cx: &Ctxt, model: &Model) {
    let used = coordinates_moving_bodies(model);
    for (j, coord) in model.coords.iter().enumerate() {
        let repeated = model.coords[..j].iter().any(|c| c.ident == coord.ident);
        // An array whose length was reported has no elements to depend on.
        let unread = matches!(coord.array, Some((_, 0)));
        if !used.contains(&j) && !repeated && !unread {
            cx.error_spanned_by(
                &coord.ident,
                format!(
                    "no body or point position depends on coordinate `{}`: its row of the mass matrix would be zero",
                    coord.ident
                ),
            );
        }
    }
}

/// The indices of the coordinates some position depends on, directly or through the bodies it
/// names.
fn coordinates_moving_bodies(model: &Model) -> BTreeSet<usize> {
    let mut depends: Vec<BTreeSet<usize>> = Vec::new();
    for body in &model.bodies {
        let mut coords = BTreeSet::new();
        // What the position's value depends on: `let _unused = y;` does not move the body.
        for ident in &names::value_names(&body.decl.block) {
            if let Some(j) = model.coords.iter().position(|c| c.ident == *ident) {
                coords.insert(j);
            } else if let Some(b) = model.bodies.iter().position(|b| b.decl.ident() == ident) {
                coords.extend(depends.get(b).into_iter().flatten().copied());
            }
        }
        depends.push(coords);
    }
    depends.into_iter().flatten().collect()
}
