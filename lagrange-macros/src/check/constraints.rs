//! Constraint rows: their values, their number, and friction at a contact.

use super::masses::check_constant;
use super::model::Model;
use crate::ast::Decl;
use crate::attr::Kind;
use crate::ctxt::Ctxt;

/// A constraint's value is an expression that vanishes (or is ≥ 0), not a comparison.
pub(super) fn check_not_a_comparison(cx: &Ctxt, decl: &Decl) {
    let Some(syn::Stmt::Expr(last, None)) = decl.block.stmts.last() else {
        return;
    };
    let syn::Expr::Binary(binary) = crate::ast::ungroup(last) else {
        return;
    };
    use syn::BinOp::*;
    // `#[constraint] fn rod() -> f64 { bob.norm() == l }`: write `bob.norm() - l`.
    // `#[constraint] fn floor() -> f64 { y >= 0.0 }`: an inequality is a `#[unilateral]` row.
    if matches!(binary.op, Lt(_) | Le(_) | Gt(_) | Ge(_)) && decl.kind() != Kind::Unilateral {
        cx.error_spanned_by(
            binary.op,
            "an inequality is a `#[unilateral]` constraint, written as a value ≥ 0 where the \
             motion is admissible (`y`, not `y >= 0.0`)",
        );
        return;
    }
    if matches!(binary.op, Eq(_) | Ne(_) | Lt(_) | Le(_) | Gt(_) | Ge(_)) {
        let what = if decl.kind() == Kind::Unilateral {
            "≥ 0 where the motion is admissible"
        } else {
            "zero when satisfied"
        };
        cx.error_spanned_by(
            binary.op,
            format!("a constraint is a value, {what}: write `a - b`, not a comparison"),
        );
    }
}

/// Bilateral constraint rows beyond the number of coordinates cannot all be independent.
pub(super) fn check_constraint_count(cx: &Ctxt, model: &Model) {
    let bilateral = model
        .constraints
        .iter()
        .filter(|r| matches!(r.decl.kind(), Kind::Constraint | Kind::VelocityConstraint));
    // Two coordinates and three `#[constraint]`s: at most two of them can be independent.
    if let Some(extra) = bilateral.clone().nth(model.dof()) {
        let n = model.dof();
        cx.error_spanned_by(
            extra.decl.ident(),
            format!(
                "{} constraints on {n} coordinate{}: at most {n} can be independent",
                bilateral.count(),
                if n == 1 { "" } else { "s" }
            ),
        );
    }
}

/// A friction row: its contact row and its Coulomb coefficients.
pub(super) fn check_friction(cx: &Ctxt, model: &mut Model, decl: &Decl) {
    let args = &decl.args;
    if args.malformed {
        return;
    }
    // `#[friction(kinetic = mu)] fn slip() -> f64`: friction acts at a contact.
    let Some(on) = &args.on else {
        cx.error_spanned_by(
            &args.attr,
            "missing `on = ...`: the constraint whose force is the normal force",
        );
        return;
    };
    let normal = model
        .constraints
        .iter()
        .position(|c| c.decl.ident() == on && c.decl.kind() != Kind::Friction);
    match normal {
        // `#[friction(on = flor)]`: a typo in the contact.
        None => cx.error_spanned_by(on, format!("`{on}` is not a `#[constraint]`, `#[velocity_constraint]` or `#[unilateral]` of this mechanism")),
        Some(n) => {
            let row = model.constraints.iter().position(|c| std::ptr::eq(c.decl, decl)).unwrap();
            // `#[friction(on = floor)] fn slip() -> Vec2` and another friction on `floor`: the cone
            // already bounds the whole tangential force.
            let cone = model.constraints[row].cone;
            if let Some(other) = model
                .constraints
                .iter()
                .find(|c| c.normal == Some(n) && (cone || c.cone))
            {
                cx.error_spanned_by(
                    on,
                    format!(
                        "`{on}` already has friction `{}`: friction in the tangent plane (a `Vec2` \
                         slip velocity) is the whole friction law of its contact",
                        other.decl.ident()
                    ),
                );
            }
            model.constraints[row].normal = Some(n);
        }
    }
    // `#[friction(on = floor)]`: Coulomb's law needs a coefficient.
    match &args.kinetic {
        None => cx.error_spanned_by(
            &args.attr,
            "missing `kinetic = ...`: the coefficient of sliding friction",
        ),
        Some(kinetic) => check_constant(cx, model, kinetic),
    }
    if let Some(stiction) = &args.stiction {
        check_constant(cx, model, stiction);
    }
}
