//! Forces, torques and generalized forces: their targets, dimensions and families.

use super::model::{family_count, Dim, Force, Model, Shape};
use super::signatures::{expect_return_type, vector_dim};
use crate::ast::Decl;
use crate::attr::Kind;
use crate::ctxt::Ctxt;

/// The body or coordinate a force acts on, checked against its kind and return type.
pub(super) fn check_force_target<'a>(
    cx: &Ctxt,
    model: &Model<'a>,
    decl: &'a Decl,
) -> Option<Force<'a>> {
    let kind = decl.kind();
    let dim = match kind {
        // `#[force(on = bob)] fn push() -> f64`: a Cartesian force is a vector.
        Kind::Force => Some(vector_dim(expect_return_type(
            cx,
            decl,
            &["Vec2", "Vec3"],
            "the force vector",
        ))),
        // `#[torque(on = bar)] fn motor() -> Vec2`: a planar torque is a scalar, a spatial one a
        // vector; which one the body decides, below.
        Kind::Torque => None,
        _ => expect_return_type(cx, decl, &["f64"], "its magnitude").map(|_| Dim::Two),
    };
    // `#[force] fn drag() -> Vec2`: what does it act on?
    let Some(on) = decl.args.on.as_ref().filter(|_| !decl.args.malformed) else {
        if decl.args.malformed {
            return None;
        }
        cx.error_spanned_by(
            &decl.args.attr,
            format!("missing `on = ...`: `#[{}(on = name)]`", kind.name()),
        );
        return None;
    };
    let target = match kind {
        Kind::GeneralizedForce => {
            let field = model.coords.iter().position(|c| c.ident == *on);
            // `#[generalized_force(on = theta)]` with `theta: [f64; N]`: one element is meant.
            if let Some(f) = field.filter(|&f| model.coords[f].array.is_some()) {
                cx.error_spanned_by(
                    on,
                    format!("`{on}` is an array of coordinates: a generalized force acts on a scalar coordinate"),
                );
                let _ = f;
                return None;
            }
            field.map(|f| crate::ast::slot_count(&model.coords[..f]))
        }
        _ => model.bodies.iter().position(|b| b.decl.ident() == on),
    };
    let Some(target) = target else {
        // `#[force(on = bobb)]`: a typo in the target.
        let what = if kind == Kind::GeneralizedForce {
            "coordinate"
        } else {
            "body or point"
        };
        cx.error_spanned_by(on, format!("`{on}` is not a {what} of this mechanism"));
        return None;
    };
    if kind == Kind::Torque {
        match model.bodies[target].shape {
            // `#[torque(on = bar)] fn motor() -> Vec2` on a planar body: the torque about the plane's
            // normal is a scalar.
            Shape::Planar => {
                expect_return_type(cx, decl, &["f64"], "its magnitude about the plane's normal");
            }
            // `#[torque(on = top)] fn drive() -> f64` on a spatial body: the torque is a vector.
            Shape::Spatial => {
                expect_return_type(cx, decl, &["Vec3"], "the torque vector, in the world frame");
            }
            // `#[torque(on = bob)]` on a particle: only a rigid body has an orientation to twist.
            _ => cx.error_spanned_by(
                on,
                format!(
                    "`{on}` is not a rigid body: a torque acts on a `Planar` or `Spatial` body"
                ),
            ),
        }
    }
    if kind == Kind::Force && dim != Some(model.bodies[target].shape.dim()) {
        // `#[force(on = bob3d)] fn push() -> Vec2`: the force has the dimension of its body.
        let want = if model.bodies[target].shape.dim() == Dim::Two {
            "Vec2"
        } else {
            "Vec3"
        };
        cx.error_spanned_by(
            decl.output(),
            format!(
                "`{on}` moves in {}: the force on it is a `{want}`",
                if want == "Vec2" { "the plane" } else { "space" }
            ),
        );
    }
    let count = family_count(cx, model.mechanism, decl);
    if kind != Kind::GeneralizedForce {
        let members = model.bodies[target].count;
        match (members, count) {
            (Some(n), Some(m)) if n != m => {
                // `#[force(on = bob, count = 4)]` on a family of 8: one force per member.
                cx.error_spanned_by(
                    decl.args.count.as_ref(),
                    format!("mismatched family length: `{on}` has {n} members, this family of forces has {m}"),
                );
            }
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
    Some(Force {
        decl,
        target,
        kind,
        count,
    })
}
