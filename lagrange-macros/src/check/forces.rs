//! Forces, torques and generalized forces: their targets, dimensions and families.

use super::model::{family_count, Dim, Force, Model, Shape};
use super::signatures::{expect_return_type, vector_dim};
use crate::ast::Decl;
use crate::attr::Kind;
use crate::ctxt::Ctxt;
use syn::Ident;

/// A force, torque or generalized force, checked against its return type and its target. Returns
/// the force to record when its target is known.
pub(super) fn check_force<'a>(cx: &Ctxt, model: &Model<'a>, decl: &'a Decl) -> Option<Force<'a>> {
    let dim = check_force_return_type(cx, decl);
    let on = check_names_a_target(cx, decl)?;
    let target = check_target(cx, model, decl, on)?;
    match decl.kind() {
        Kind::Torque => check_torque_on_rigid_body(cx, model.bodies[target].shape, decl, on),
        Kind::Force => check_force_dimension(cx, model.bodies[target].shape.dim(), decl, on, dim),
        _ => {}
    }
    let count = family_count(cx, model.mechanism, decl);
    if decl.kind() != Kind::GeneralizedForce {
        check_families_match(cx, model.bodies[target].count, count, decl, on);
    }
    Some(Force {
        decl,
        target,
        kind: decl.kind(),
        count,
    })
}

/// A Cartesian force is a vector (`#[force(on = bob)] fn push() -> f64` is not one), a generalized
/// force a scalar. Returns a force's dimension. (A torque's type depends on its body: checked with
/// the body.)
fn check_force_return_type(cx: &Ctxt, decl: &Decl) -> Option<Dim> {
    match decl.kind() {
        Kind::Force => Some(vector_dim(expect_return_type(
            cx,
            decl,
            &["Vec2", "Vec3"],
            "the force vector",
        ))),
        Kind::Torque => None,
        _ => expect_return_type(cx, decl, &["f64"], "its magnitude").map(|_| Dim::Two),
    }
}

/// A force acts on something: `#[force] fn drag() -> Vec2` names no target. Returns the target's
/// name. (Malformed arguments were reported while parsing.)
fn check_names_a_target<'d>(cx: &Ctxt, decl: &'d Decl) -> Option<&'d Ident> {
    if decl.args.malformed {
        return None;
    }
    let on = decl.args.on.as_ref();
    if on.is_none() {
        cx.error_spanned_by(
            &decl.args.attr,
            format!("missing `on = ...`: `#[{}(on = name)]`", decl.kind().name()),
        );
    }
    on
}

/// The target exists: a body or point of the mechanism, or for a generalized force a scalar
/// coordinate (an array's elements are not named one by one). Returns the body's index, or the
/// coordinate's slot.
fn check_target(cx: &Ctxt, model: &Model, decl: &Decl, on: &Ident) -> Option<usize> {
    let generalized = decl.kind() == Kind::GeneralizedForce;
    let target = if generalized {
        let field = model.coords.iter().position(|c| c.ident == *on);
        // `#[generalized_force(on = theta)]` with `theta: [f64; N]`: one element is meant.
        if field.is_some_and(|f| model.coords[f].array.is_some()) {
            cx.error_spanned_by(
                on,
                format!("`{on}` is an array of coordinates: a generalized force acts on a scalar coordinate"),
            );
            return None;
        }
        field.map(|f| crate::ast::slot_count(&model.coords[..f]))
    } else {
        model.bodies.iter().position(|b| b.decl.ident() == on)
    };
    if target.is_none() {
        // `#[force(on = bobb)]`: a typo in the target.
        let what = if generalized {
            "coordinate"
        } else {
            "body or point"
        };
        cx.error_spanned_by(on, format!("`{on}` is not a {what} of this mechanism"));
    }
    target
}

/// A torque twists an orientation, so it acts on a rigid body: a scalar about the plane's normal
/// on a `Planar` body, a vector on a `Spatial` one.
fn check_torque_on_rigid_body(cx: &Ctxt, shape: Shape, decl: &Decl, on: &Ident) {
    match shape {
        // `#[torque(on = bar)] fn motor() -> Vec2` on a planar body.
        Shape::Planar => {
            expect_return_type(cx, decl, &["f64"], "its magnitude about the plane's normal");
        }
        // `#[torque(on = top)] fn drive() -> f64` on a spatial body.
        Shape::Spatial => {
            expect_return_type(cx, decl, &["Vec3"], "the torque vector, in the world frame");
        }
        // `#[torque(on = bob)]` on a particle: it has no orientation to twist.
        _ => cx.error_spanned_by(
            on,
            format!("`{on}` is not a rigid body: a torque acts on a `Planar` or `Spatial` body"),
        ),
    }
}

/// A force has the dimension of the body it pushes: `#[force(on = bob3d)] fn push() -> Vec2` is
/// not a force in space.
fn check_force_dimension(cx: &Ctxt, body: Dim, decl: &Decl, on: &Ident, force: Option<Dim>) {
    if force == Some(body) {
        return;
    }
    let (want, moves) = match body {
        Dim::Two => ("Vec2", "the plane"),
        Dim::Three => ("Vec3", "space"),
    };
    cx.error_spanned_by(
        decl.output(),
        format!("`{on}` moves in {moves}: the force on it is a `{want}`"),
    );
}

/// A family of forces acts on a family of bodies of the same length, one force per member; a
/// force on a family is a family too; torques on families are not supported.
fn check_families_match(
    cx: &Ctxt,
    members: Option<usize>,
    count: Option<usize>,
    decl: &Decl,
    on: &Ident,
) {
    let kind = decl.kind();
    match (members, count) {
        // `#[force(on = bob, count = 4)]` on a family of 8.
        (Some(n), Some(m)) if n != m => cx.error_spanned_by(
            decl.args.count.as_ref(),
            format!("mismatched family length: `{on}` has {n} members, this family of forces has {m}"),
        ),
        (Some(n), None) if kind == Kind::Force && !decl.args.malformed => cx.error_spanned_by(
            on,
            format!("`{on}` is a family of {n}: the force on it is a family too, `#[force(on = {on}, count = {n})] fn {}(i: usize)`", decl.ident()),
        ),
        (Some(_), _) if kind == Kind::Torque => cx.error_spanned_by(
            on,
            format!("`{on}` is a family: torques on families are not supported"),
        ),
        (None, Some(_)) => cx.error_spanned_by(
            decl.args.count.as_ref(),
            format!("`{on}` is a single body: a family of forces acts on a family of bodies"),
        ),
        _ => {}
    }
}
