//! A root body that turns freely: placed from the ground by a rotation chart (`rot_mrp` or
//! `rot_vector`) of three consecutive coordinates c, and either by three more consecutive
//! coordinates p just before them, as a floating base is written,
//!
//! ```text
//! #[rigid_body(mass = m, inertia = [..])]
//! fn base() -> Spatial {
//!     spatial(vec3(p[0], p[1], p[2]), rot_mrp(vec3(s[0], s[1], s[2])))
//! }
//! ```
//!
//! which reads as the runtime's free joint (`lagrange_core::tree::rigid::JointKind::Free`:
//! R_b = R(c), o_b = p, E the identity and r zero) on the coordinates from p's first; or by
//! constants only, `spatial(vec3(0.0, 0.0, 0.5), rot_vector(vec3(a, b, c)))`, a body turning about
//! a fixed point, which reads as the runtime's ball joint (`JointKind::Ball`: R_b = R(c), o_b = r,
//! the constant). As for a revolute joint, constant rotations after the chart's are the body's C_b
//! and offsets turned by it its s_b; anything else — a parent, a constant rotation before it, a
//! position term in the world frame beside p, coordinates out of that order — is not read.

use super::value::{Factor, Piece, Term, Value};
use super::{blank, constants, offsets, Joint, Node};
use crate::check::ChartKind;

/// `vec3(a, b, c)` of three consecutive coordinates, in order.
pub(super) fn coordinates(components: &[&Value]) -> Option<Value> {
    let [Value::Coordinate(a), Value::Coordinate(b), Value::Coordinate(c)] = components else {
        return None;
    };
    (*b == a + 1 && *c == a + 2).then(|| {
        Value::Vector(vec![Term {
            rotation: Vec::new(),
            piece: Piece::Coordinates(*a),
        }])
    })
}

/// `rot_mrp(vec3(a, b, c))` or `rot_vector(..)` of three consecutive coordinates (the checks admit
/// no other argument).
pub(super) fn chart(kind: ChartKind, coordinates: &Value) -> Option<Value> {
    let Value::Vector(terms) = coordinates else {
        return None;
    };
    match terms.as_slice() {
        [Term {
            rotation,
            piece: Piece::Coordinates(slot),
        }] if rotation.is_empty() => Some(Value::Rotation(vec![Factor::Chart(kind, *slot)])),
        _ => None,
    }
}

/// The free or ball joint of a body whose rotation `R(c) C` starts with a chart's and whose
/// position is p plus terms turned by R(c) (s_b; a free joint), or constants plus such terms (a
/// ball joint). Whether the body is a root is left to the caller.
pub(super) fn free(rotation: &[Factor], terms: Vec<(Vec<Factor>, Piece)>) -> Option<Node> {
    let Some(&Factor::Chart(kind, sigma)) = rotation.first() else {
        return None;
    };
    let (turned, world): (Vec<_>, Vec<_>) = terms
        .into_iter()
        .partition(|(f, _)| matches!(f.first(), Some(&Factor::Chart(..))));
    let mut node = match world.as_slice() {
        [(turn, Piece::Coordinates(first))] if turn.is_empty() && first + 3 == sigma => {
            blank(Joint::Free(kind, *first))
        }
        _ if world
            .iter()
            .any(|(_, p)| matches!(p, Piece::Coordinates(_))) =>
        {
            return None
        }
        _ => {
            let mut node = blank(Joint::Ball(kind, sigma));
            node.offset = offsets(world)?;
            node
        }
    };
    node.after = constants(&rotation[1..])?;
    let own = turned
        .into_iter()
        .map(|(f, p)| match f.first() {
            Some(&Factor::Chart(k, s)) if k == kind && s == sigma => Some((f[1..].to_vec(), p)),
            _ => None,
        })
        .collect::<Option<Vec<_>>>()?;
    node.own = offsets(own)?;
    Some(node)
}
