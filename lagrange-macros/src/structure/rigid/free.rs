//! A free root body: one placed from the ground by six consecutive coordinates, its origin p and
//! its orientation's three coordinates c in a rotation chart (`rot_mrp` or `rot_vector`), as a
//! floating base is written:
//!
//! ```text
//! #[rigid_body(mass = m, inertia = [..])]
//! fn base() -> Spatial {
//!     spatial(vec3(p[0], p[1], p[2]), rot_mrp(vec3(s[0], s[1], s[2])))
//! }
//! ```
//!
//! reads as the runtime's free joint (`lagrange_core::tree::rigid::JointKind::Free`: R_b = R(c),
//! o_b = p, E the identity and r zero) on the coordinates from p's first, c's three following
//! p's. As for a revolute joint, constant rotations after the chart's are the body's C_b and
//! offsets turned by it its s_b; anything else — a parent, a constant rotation before it, a
//! position term in the world frame other than p, coordinates out of that order — is not read.

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

/// The free joint of a body whose rotation `R(c) C` starts with a chart's and whose position is
/// p plus terms turned by R(c) (s_b). Whether the body is a root is left to the caller.
pub(super) fn free(rotation: &[Factor], terms: Vec<(Vec<Factor>, Piece)>) -> Option<Node> {
    let Some(&Factor::Chart(kind, sigma)) = rotation.first() else {
        return None;
    };
    let (origin, other): (Vec<_>, Vec<_>) = terms
        .into_iter()
        .partition(|(_, p)| matches!(p, Piece::Coordinates(_)));
    let [(turn, Piece::Coordinates(first))] = origin.as_slice() else {
        return None;
    };
    if !turn.is_empty() || first + 3 != sigma {
        return None;
    }
    let mut node = blank(Joint::Free(kind, *first));
    node.after = constants(&rotation[1..])?;
    let own = other
        .into_iter()
        .map(|(f, p)| match f.first() {
            Some(&Factor::Chart(k, s)) if k == kind && s == sigma => Some((f[1..].to_vec(), p)),
            _ => None,
        })
        .collect::<Option<Vec<_>>>()?;
    node.own = offsets(own)?;
    Some(node)
}
