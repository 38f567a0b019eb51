//! `#[angular_velocity]` on a coordinate field: the field's three coordinates are a free or ball
//! joint's rotation chart and the state's velocities for them are the body's angular velocity ω_b
//! (in the body's frame), not the chart's rates — quasi-velocities, q̇ = G(q) v
//! (`lagrange_core::tree::rigid::Velocities::AngularVelocity`). The rigid tree's recursions take
//! them as they are; everything else that reads velocities as rates converts, and the generated
//! code says so (`Dynamics::QUASI_VELOCITIES`).

use super::model::Model;
use crate::ast::Field;
use crate::attr::Kind;
use crate::ctxt::Ctxt;
use crate::structure::rigid::{rigid_tree, Joint};

/// The charts whose velocities are angular velocities, as their three flat slots. Reported: a
/// marked field on a declaration whose bodies the rigid tree pass does not take; a marked coordinate outside every free or ball joint's chart; a generalized force on
/// a marked coordinate; a chart marked in part.
pub(super) fn check_angular_velocities(cx: &Ctxt, model: &Model) -> Vec<[usize; 3]> {
    let marked = marked_fields(model.coords);
    let Some((first, _)) = marked.first() else {
        return Vec::new();
    };
    let marker = |f: &Field| f.angular_velocity.clone().expect("a marked field");
    let Some(tree) = rigid_tree(model) else {
        cx.error_spanned_by(
            marker(first),
            "`#[angular_velocity]` marks the rotation chart of a free or ball joint, which the \
             rigid tree pass takes: a root body placed by `spatial(vec3(..), rot_mrp(vec3(..)))` \
             or turned by a chart about a fixed point; this declaration's bodies are not such a \
             tree",
        );
        return Vec::new();
    };
    let charts: Vec<[usize; 3]> = tree
        .nodes
        .iter()
        .filter_map(|n| chart_slots(&n.joint))
        .collect();
    let is_marked = |slot: usize| marked.iter().any(|(_, slots)| slots.contains(&slot));
    for (field, slots) in &marked {
        if let Some(stray) = slots
            .clone()
            .find(|s| !charts.iter().any(|c| c.contains(s)))
        {
            let message = format!(
                "`{}` (slot {stray}) is not a coordinate of a free or ball joint's rotation chart: \
                 `#[angular_velocity]` marks the three coordinates a root body's `rot_mrp` or \
                 `rot_vector` reads",
                field.ident
            );
            cx.error_spanned_by(marker(field), message);
        }
    }
    for force in &model.forces {
        if force.kind == Kind::GeneralizedForce && is_marked(force.target) {
            // At the coordinate `on =` names (the function's name where it names none).
            let at = force.decl.args.on.as_ref().unwrap_or(force.decl.ident());
            cx.error_spanned_by(
                at,
                "a generalized force on a coordinate whose velocity is an angular velocity \
                 (`#[angular_velocity]`) would be dual to the chart's rate, not to the velocity: \
                 turn the body with `#[torque(on = body)]`",
            );
        }
    }
    for chart in &charts {
        let count = chart.iter().filter(|s| is_marked(**s)).count();
        if count != 0 && count != 3 {
            let (field, _) = marked
                .iter()
                .find(|(_, slots)| chart.iter().any(|s| slots.contains(s)))
                .expect("a marked slot of the chart");
            cx.error_spanned_by(
                marker(field),
                "`#[angular_velocity]` marks all three coordinates of a rotation chart or none: \
                 the angular velocity has three components",
            );
        }
    }
    charts
        .into_iter()
        .filter(|c| c.iter().all(|s| is_marked(*s)))
        .collect()
}

/// The fields with `#[angular_velocity]` and their flat slots.
fn marked_fields(coords: &[Field]) -> Vec<(&Field, std::ops::Range<usize>)> {
    let mut start = 0;
    let mut marked = Vec::new();
    for field in coords {
        let slots = start..start + field.slots();
        start = slots.end;
        if field.angular_velocity.is_some() {
            marked.push((field, slots));
        }
    }
    marked
}

/// The three slots of a free or ball joint's chart.
fn chart_slots(joint: &Joint) -> Option<[usize; 3]> {
    match *joint {
        Joint::Free(_, first) => Some([first + 3, first + 4, first + 5]),
        Joint::Ball(_, first) => Some([first, first + 1, first + 2]),
        _ => None,
    }
}
