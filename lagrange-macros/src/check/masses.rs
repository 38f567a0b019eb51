//! What the mass matrix needs: constant masses and inertias, and every coordinate moving a body.

use super::model::Model;
use super::resolve::{Context, Resolver};
use crate::attr::{Inertia, Kind};
use crate::ctxt::Ctxt;
use crate::names;
use std::collections::BTreeSet;

/// Masses and inertias: present where needed, constant.
pub(super) fn check_masses(cx: &Ctxt, model: &Model) {
    for body in &model.bodies {
        let args = &body.decl.args;
        let name = body.decl.ident();
        if args.kind == Kind::Point || args.malformed {
            continue;
        }
        // `#[particle] fn bob() -> Vec2`: a body without a mass.
        match &args.mass {
            None => cx.error_spanned_by(
                &args.attr,
                format!(
                    "`{name}` has no mass: write `#[{}(mass = ...)]`",
                    args.kind.name()
                ),
            ),
            Some(mass) => check_constant(cx, model, mass),
        }
        if args.kind != Kind::RigidBody {
            continue;
        }
        match &args.inertia {
            // `#[rigid_body(mass = m)] fn bar() -> Planar`: a rigid body also needs its inertia.
            None => cx.error_spanned_by(
                &args.attr,
                format!("rigid body `{name}` has no inertia: add `inertia = ...` (one moment, or `[I1, I2, I3]`)"),
            ),
            Some(Inertia::Moment(e)) => check_constant(cx, model, e),
            Some(Inertia::Principal(array)) => {
                // `inertia = [a, b]`: three principal moments.
                if array.elems.len() != 3 {
                    cx.error_spanned_by(array, "principal moments are three: `[I1, I2, I3]`");
                }
                array.elems.iter().for_each(|e| check_constant(cx, model, e));
            }
        }
    }
}

/// A mass or inertia names only parameters and module items.
pub(super) fn check_constant(cx: &Ctxt, model: &Model, expr: &syn::Expr) {
    let mut seen = BTreeSet::new();
    for ident in names::free_names_of_expr(expr)
        .iter()
        .filter(|i| seen.insert(i.to_string()))
    {
        Resolver {
            model,
            context: Context::Mass,
        }
        .resolve(cx, ident);
    }
}

/// A coordinate that no position depends on leaves the mass matrix singular.
pub(super) fn check_coordinates_are_used(cx: &Ctxt, model: &Model) {
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
    let used: BTreeSet<usize> = depends.into_iter().flatten().collect();
    for (j, coord) in model.coords.iter().enumerate() {
        let repeated = model.coords[..j].iter().any(|c| c.ident == coord.ident);
        // An array whose length was reported has no elements to depend on.
        let unread = matches!(coord.array, Some((_, 0)));
        // `Coords { x, y }` where no body's position names `y`: its mass-matrix row is zero.
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
