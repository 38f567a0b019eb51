//! Gravity fields and the bodies they act on.

use super::model::{Dim, Model};
use crate::ast::Decl;
use crate::ctxt::Ctxt;

/// With gravity, every massive body moves in the dimension of some field: a `Vec3` particle under
/// a `Vec2` field alone would silently feel no gravity.
pub(super) fn check_gravity_covers_every_body(cx: &Ctxt, model: &Model) {
    let fields: Vec<(&Decl, Dim)> = model
        .gravities
        .iter()
        .chain(&model.uniform_gravities)
        .copied()
        .collect();
    // Fields that act on nothing were reported at the field.
    let acting: Vec<&(&Decl, Dim)> = fields
        .iter()
        .filter(|(_, dim)| {
            model
                .bodies
                .iter()
                .any(|b| b.shape.has_mass() && b.shape.dim() == *dim)
        })
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
