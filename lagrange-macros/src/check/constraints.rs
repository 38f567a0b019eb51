//! Constraint rows: their values, their number, and friction at a contact.

use super::masses::check_constant;
use super::model::Model;
use super::signatures::expect_return_type;
use crate::ast::Decl;
use crate::attr::{Args, Kind};
use crate::ctxt::Ctxt;
use syn::Ident;

/// A holonomic or unilateral constraint row is one scalar function of the configuration
/// (`#[constraint] fn rod() -> Vec2` is not), and a value rather than a comparison.
pub(super) fn check_position_constraint(cx: &Ctxt, decl: &Decl) {
    expect_return_type(
        cx,
        decl,
        &["f64"],
        "the constraint function, zero when satisfied",
    );
    check_not_a_comparison(cx, decl);
}

/// A velocity constraint row is one scalar, affine in the velocities, and a value rather than a
/// comparison.
pub(super) fn check_velocity_constraint(cx: &Ctxt, decl: &Decl) {
    expect_return_type(
        cx,
        decl,
        &["f64"],
        "the constraint, zero when satisfied, affine in velocities",
    );
    check_not_a_comparison(cx, decl);
}

/// A `#[velocity_constraint]` names a velocity: `fn on_line() -> f64 { y - x }` names none, so it
/// constrains positions, which is a `#[constraint]`.
pub(super) fn check_velocity_constraint_names_a_velocity(
    cx: &Ctxt,
    decl: &Decl,
    names_velocity: bool,
) {
    if !names_velocity {
        cx.error_spanned_by(
            decl.ident(),
            "a `#[velocity_constraint]` is affine in velocities (`x_dot`, `body_dot`), and this one \
             names none: a condition on positions alone is a `#[constraint]`",
        );
    }
}

/// A constraint's value is an expression that vanishes (or is ≥ 0 where the motion is admissible),
/// not a comparison: the solver needs the value, and an inequality is a `#[unilateral]` row.
fn check_not_a_comparison(cx: &Ctxt, decl: &Decl) {
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

/// Bilateral constraint rows beyond the number of coordinates cannot all be independent: their
/// constraint matrix would be rank-deficient, and its multipliers undetermined.
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

/// A friction row: its slip velocity, its contact row and its Coulomb coefficients. Records the
/// contact.
pub(super) fn check_friction(cx: &Ctxt, model: &mut Model, decl: &Decl) {
    check_slip_velocity(cx, decl);
    if decl.args.malformed {
        return;
    }
    let Some(on) = check_names_a_contact(cx, &decl.args) else {
        return;
    };
    if let Some(normal) = check_contact(cx, model, on) {
        let row = model.constraint_index(decl);
        check_one_friction_law_per_contact(cx, model, row, normal, on);
        model.constraints[row].normal = Some(normal);
    }
    check_coulomb_coefficients(cx, model, &decl.args);
}

/// A slip velocity lies in the tangent plane: one component (planar friction) or two (the Coulomb
/// cone); `#[friction(..)] fn slip() -> Vec3` is neither.
fn check_slip_velocity(cx: &Ctxt, decl: &Decl) {
    expect_return_type(
        cx,
        decl,
        &["f64", "Vec2"],
        "the slip velocity: along one tangent direction (planar friction), or its \
         components along two orthonormal tangent directions (friction in the tangent \
         plane, the Coulomb cone)",
    );
}

/// Friction acts at a contact, whose force is the normal force: `#[friction(kinetic = mu)]` names
/// none. Returns the contact's name.
fn check_names_a_contact<'d>(cx: &Ctxt, args: &'d Args) -> Option<&'d Ident> {
    if args.on.is_none() {
        cx.error_spanned_by(
            &args.attr,
            "missing `on = ...`: the constraint whose force is the normal force",
        );
    }
    args.on.as_ref()
}

/// The contact is a constraint row other than friction: `#[friction(on = flor)]` is a typo.
/// Returns its index among the constraint items.
fn check_contact(cx: &Ctxt, model: &Model, on: &Ident) -> Option<usize> {
    let normal = model
        .constraints
        .iter()
        .position(|c| c.decl.ident() == on && c.decl.kind() != Kind::Friction);
    if normal.is_none() {
        cx.error_spanned_by(on, format!("`{on}` is not a `#[constraint]`, `#[velocity_constraint]` or `#[unilateral]` of this mechanism"));
    }
    normal
}

/// Friction in the tangent plane (a `Vec2` slip velocity, the cone) already bounds the whole
/// tangential force of its contact: no other friction row on the same contact.
fn check_one_friction_law_per_contact(
    cx: &Ctxt,
    model: &Model,
    row: usize,
    normal: usize,
    on: &Ident,
) {
    let cone = model.constraints[row].cone;
    // `#[friction(on = floor)] fn slip() -> Vec2` and another friction on `floor`.
    if let Some(other) = model
        .constraints
        .iter()
        .find(|c| c.normal == Some(normal) && (cone || c.cone))
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
}

/// Coulomb's law needs its kinetic coefficient (`#[friction(on = floor)]` has none); the
/// coefficients are constants.
fn check_coulomb_coefficients(cx: &Ctxt, model: &Model, args: &Args) {
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
