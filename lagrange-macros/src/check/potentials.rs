//! Potentials and gravity fields, and the bodies gravity acts on.

use super::model::{Dim, Model};
use super::signatures::{expect_return_type, vector_dim};
use crate::ast::Decl;
use crate::ctxt::Ctxt;

/// A potential is an energy, one scalar: `#[potential] fn spring() -> Vec2` is not one.
pub(super) fn check_potential(cx: &Ctxt, decl: &Decl) {
    expect_return_type(cx, decl, &["f64"], "the potential energy");
}

/// A gravity field is a vector, `Vec2` or `Vec3` (`#[gravity] fn down() -> f64` is not one), and
/// acts on some body with mass. Returns its dimension (the plane's when the return type is wrong).
pub(super) fn check_gravity_field(cx: &Ctxt, model: &Model, decl: &Decl) -> Dim {
    let name = expect_return_type(cx, decl, &["Vec2", "Vec3"], "the field vector g");
    let dim = vector_dim(name.clone());
    if name.is_some() {
        check_field_acts_on_a_body(cx, model, decl, dim);
    }
    dim
}

/// A field acts on the bodies with mass of its dimension: `#[gravity] fn down() -> Vec3` when every
/// body moves in the plane acts on nothing.
fn check_field_acts_on_a_body(cx: &Ctxt, model: &Model, decl: &Decl, dim: Dim) {
    if model.has_massive_body_in(dim) {
        return;
    }
    let (field, bodies) = match dim {
        Dim::Two => ("Vec2", "the plane"),
        Dim::Three => ("Vec3", "space"),
    };
    cx.error_spanned_by(
        decl.output(),
        format!("a `{field}` field acts on bodies in {bodies}, and there are none"),
    );
}

/// With gravity, every massive body moves in the dimension of some field: a `Vec3` particle under
/// a `Vec2` field alone would silently feel no gravity.
pub(super) fn check_gravity_covers_every_body(cx: &Ctxt, model: &Model) {
    // Fields that act on nothing were reported at the field.
    let acting: Vec<&(&Decl, Dim)> = model
        .gravities
        .iter()
        .chain(&model.uniform_gravities)
        .filter(|(_, dim)| model.has_massive_body_in(*dim))
        .collect();
    let Some((field, dim)) = acting.first() else {
        return;
    };
    for body in &model.bodies {
        if !body.shape.has_mass() || acting.iter().any(|(_, d)| *d == body.shape.dim()) {
            continue;
        }
        // `#[gravity] fn down() -> Vec2` and `#[particle(..)] fn bead() -> Vec3`.
        let (moves, field_type, other) = match dim {
            Dim::Two => ("space", "Vec2", "Vec3"),
            Dim::Three => ("the plane", "Vec3", "Vec2"),
        };
        cx.error_spanned_by(
            body.decl.output(),
            format!(
                "`{}` moves in {moves}, but the gravity `{}` is a `{field_type}` field and would not act on it: declare a `#[gravity] fn ..() -> {other}` field for it too, or give it the field's dimension",
                body.decl.ident(),
                field.ident()
            ),
        );
    }
}
