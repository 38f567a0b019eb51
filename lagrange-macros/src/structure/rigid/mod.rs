//! The kinematic tree of rigid bodies a declaration states (see `lagrange_core::tree::rigid`):
//! each body placed from an earlier one (or the ground) by constant rotations and offsets and at
//! most one joint — a rotation about a coordinate axis by one coordinate, or a slide along one — or,
//! for a root, a free joint of six coordinates or a ball joint of three (see [`free`]).
//!
//! ```text
//! #[rigid_body(mass = m2, inertia = [ix2, iy2, iz2])]
//! fn link2() -> Spatial {
//!     let r = link1.rotation * rot_y(q2);
//!     let joint = link1.point(vec3(-e, 0.0, 0.5 * d1));
//!     spatial(joint + r * vec3(e, 0.0, 0.5 * d2), r)
//! }
//! ```
//!
//! reads as: parent `link1`; joint frame at link1's point (−e, 0, d1/2), turned by nothing constant,
//! then by q2 about its y axis; the body's position at (e, 0, d2/2) in the joint's frame. A body's
//! frame as its function returns it is (R_b, p_b) = (F_b C_b, o_b + F_b s_b), with (F_b, o_b) the
//! joint frame of the runtime's recursion, C_b the constant rotations written after the joint and
//! s_b the offsets written in the turned frame. A child's joint frame follows from its parent's
//! (R_p, p_p): E_b = C_p A_b, r_b = s_p + C_p Σ X c for the offsets X c written in the parent's frame.
//!
//! Which declarations this reads is listed in the facade's README ("How it works"); anything else
//! keeps the dense pass, which is what the tree is tested against.

mod free;
mod value;

use crate::check::{family_index, ChartKind, Model, Shape};
use proc_macro2::TokenStream;
use quote::quote;
pub use value::Axis;
use value::{Factor, Piece, Reader, Term, Value};

/// How a node moves relative to its joint frame's place in its parent.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Joint {
    /// About an axis of the joint frame, by coordinate `slot`.
    Revolute(Axis, usize),
    /// Along an axis of the joint frame, by coordinate `slot`.
    Prismatic(Axis, usize),
    Fixed,
    /// A root moved by coordinates `slot..slot + 6`: its origin, then its orientation in the
    /// chart (see [`free`]).
    Free(ChartKind, usize),
    /// A root turned by coordinates `slot..slot + 3` in the chart about its origin, held at a
    /// constant offset (see [`free`]).
    Ball(ChartKind, usize),
}

/// A constant vector turned by constant rotation factors (`Rot3<f64>` and `Vec3<f64>`
/// expressions, factors left to right).
pub struct Offset {
    pub factors: Vec<TokenStream>,
    pub vector: TokenStream,
    /// The vector's components that are literal zeros.
    pub zeros: [bool; 3],
}

/// A body (or family member, or a point that bodies are placed from) of the tree.
pub struct Node {
    /// Index into `Model::bodies`.
    pub body: usize,
    pub member: Option<usize>,
    /// The node it is placed from.
    pub parent: Option<usize>,
    pub joint: Joint,
    /// The joint frame's axes in the parent's frame as written: E_b = C_p Π joint_frame.
    pub joint_frame: Vec<TokenStream>,
    /// Whether the joint frame's origin is measured from the parent's position (s_p added).
    pub anchored: bool,
    /// Offsets in the parent's frame as written: r_b = s_p + C_p Σ X c.
    pub offset: Vec<Offset>,
    /// C_b: the body's frame as written, in the joint frame.
    pub after: Vec<TokenStream>,
    /// s_b = Σ Y c: the body's position as written, in the joint frame.
    pub own: Vec<Offset>,
    /// Components of r_b that are structurally zero.
    pub offset_zeros: [bool; 3],
}

impl Node {
    /// Whether E_b can differ from the identity.
    pub fn rotated(&self, nodes: &[Node]) -> bool {
        !self.joint_frame.is_empty() || self.parent.is_some_and(|p| !nodes[p].after.is_empty())
    }
}

/// The tree, parents first.
pub struct RigidTree {
    pub nodes: Vec<Node>,
}

/// The kinematic tree of rigid bodies the declaration states, if it states one: every body with
/// mass a node, every coordinate the joint of exactly one node. Declarations of point masses only
/// are left to the tree of translations (`crate::structure::tree`), their own specialisation.
/// Constraints do not change the tree: a closed loop is a tree whose M and b the recursions give,
/// with the constraint rows solved on top of them.
pub fn rigid_tree(model: &Model) -> Option<RigidTree> {
    let rigid = |s: Shape| matches!(s, Shape::Planar | Shape::Spatial);
    if !model.bodies.iter().any(|b| rigid(b.shape)) {
        return None;
    }
    let mut nodes: Vec<Node> = Vec::new();
    let mut keys: Vec<(usize, Option<usize>)> = Vec::new();
    for (index, body) in model.bodies.iter().enumerate() {
        if crate::names::first_return(&body.decl.block).is_some() || names_time(model, index) {
            return None;
        }
        for member in 0..body.members() {
            let member = body.count.map(|_| member);
            let family = member.and_then(|k| family_index(body.decl).map(|i| (i, k)));
            let value = Reader::new(model, &keys, family).block(&body.decl.block);
            let node = value.and_then(|v| node(&nodes, index, member, v));
            match node {
                Some(node) => {
                    nodes.push(node);
                    keys.push((index, member));
                }
                // A point nothing is placed from does not take part in the dynamics.
                None if !body.shape.has_mass() => {}
                None => return None,
            }
        }
    }
    let nodes = without_massless_leaves(model, nodes);
    each_coordinate_moves_one_node(model, &nodes).then_some(RigidTree { nodes })
}

/// Whether body `index`'s function names time (a driven joint: not read).
fn names_time(model: &Model, index: usize) -> bool {
    let name = model.bodies[index].decl.ident().to_string();
    model
        .free_names
        .get(&name)
        .is_some_and(|names| names.iter().any(|n| n == "t"))
}

/// The nodes without the points below which nothing carries mass, parents renumbered.
fn without_massless_leaves(model: &Model, nodes: Vec<Node>) -> Vec<Node> {
    let mut keep: Vec<bool> = nodes
        .iter()
        .map(|n| model.bodies[n.body].shape.has_mass())
        .collect();
    for b in (0..nodes.len()).rev() {
        if let (true, Some(p)) = (keep[b], nodes[b].parent) {
            keep[p] = true;
        }
    }
    let mut index = vec![None; nodes.len()];
    let mut kept = Vec::new();
    for (b, mut node) in nodes.into_iter().enumerate() {
        if keep[b] {
            node.parent = node.parent.and_then(|p| index[p]);
            index[b] = Some(kept.len());
            kept.push(node);
        }
    }
    kept
}

fn each_coordinate_moves_one_node(model: &Model, nodes: &[Node]) -> bool {
    let mut owners = vec![0; model.dof()];
    for node in nodes {
        let slots = match node.joint {
            Joint::Revolute(_, slot) | Joint::Prismatic(_, slot) => slot..slot + 1,
            Joint::Free(_, first) => first..first + 6,
            Joint::Ball(_, first) => first..first + 3,
            Joint::Fixed => continue,
        };
        for slot in slots {
            match owners.get_mut(slot) {
                Some(n) => *n += 1,
                None => return false,
            }
        }
    }
    owners.iter().all(|&n| n == 1)
}

/// The node a body's value describes (see the module docs), or `None` where it is not one.
fn node(nodes: &[Node], body: usize, member: Option<usize>, value: Value) -> Option<Node> {
    let (position, rotation) = match value {
        Value::Pose { position, rotation } => (position, Some(rotation)),
        Value::Vector(position) => (position, None),
        _ => return None,
    };
    let (origins, terms): (Vec<Term>, Vec<Term>) = position
        .into_iter()
        .partition(|t| matches!(t.piece, Piece::Origin(_)));
    let anchor = match origins.as_slice() {
        [] => None,
        [Term {
            piece: Piece::Origin(n),
            ..
        }] => Some(*n),
        _ => return None,
    };
    // The parent: the body whose rotation the frame starts from, which is also the one whose
    // position it is measured from; a particle takes the one its position starts from.
    let turned_from = match &rotation {
        Some(r) => leading_body(r)?,
        None => anchor,
    };
    let parent = match (turned_from, anchor) {
        (Some(a), Some(b)) if a == b => Some(a),
        (None, None) => None,
        _ => return None,
    };
    let strip = |factors: &[Factor]| -> Option<Vec<Factor>> {
        match (parent, factors.first()) {
            (Some(p), Some(Factor::Body(q))) if p == *q => Some(factors[1..].to_vec()),
            (None, _) => Some(factors.to_vec()),
            _ => None,
        }
    };
    let terms: Vec<(Vec<Factor>, Piece)> = terms
        .into_iter()
        .map(|t| Some((strip(&t.rotation)?, t.piece)))
        .collect::<Option<_>>()?;
    if terms
        .iter()
        .any(|(f, _)| f.iter().any(|f| matches!(f, Factor::Body(_))))
    {
        return None;
    }
    let rotation = match rotation {
        Some(r) => Some(strip(&r)?),
        None => None,
    };
    let mut node = place(rotation, terms)?;
    // The runtime's free and ball joints are a root's (E the identity, a free joint's r zero).
    if matches!(node.joint, Joint::Free(..) | Joint::Ball(..)) && parent.is_some() {
        return None;
    }
    node.body = body;
    node.member = member;
    node.parent = parent;
    node.anchored = anchor.is_some();
    node.offset_zeros = offset_zeros(nodes, &node);
    Some(node)
}

/// The body `Body(n)` a rotation starts from (`Some(None)` for none, `None` when a body's rotation
/// stands anywhere else in it).
fn leading_body(rotation: &[Factor]) -> Option<Option<usize>> {
    let later = rotation
        .iter()
        .skip(1)
        .any(|f| matches!(f, Factor::Body(_)));
    match rotation.first() {
        _ if later => None,
        Some(Factor::Body(n)) => Some(Some(*n)),
        _ => Some(None),
    }
}

/// The joint, joint frame and offsets from the rotation after the parent's (`None` for a particle
/// or point) and the position's terms, their factors after the parent's.
fn place(rotation: Option<Vec<Factor>>, terms: Vec<(Vec<Factor>, Piece)>) -> Option<Node> {
    let slides = terms
        .iter()
        .filter(|(_, p)| matches!(p, Piece::Slide(..)))
        .count();
    // A particle's joint frame is the one its turned terms share.
    let turned = match &rotation {
        Some(r) => r.clone(),
        None => shared_turn(&terms)?,
    };
    let joints: Vec<usize> = (0..turned.len())
        .filter(|&i| matches!(turned[i], Factor::Joint(..)))
        .collect();
    let free = turned.iter().any(|f| matches!(f, Factor::Chart(..)));
    match (joints.as_slice(), slides) {
        ([], 0) if free && rotation.is_some() => free::free(&turned, terms),
        _ if free => None,
        ([], 0) => fixed(&turned, terms),
        ([j], 0) => revolute(&turned, *j, terms, rotation.is_some()),
        ([], 1) => prismatic(&turned, terms),
        _ => None,
    }
}

/// For a particle: the factors up to and including the joint that its turned terms share (none
/// when no term turns).
fn shared_turn(terms: &[(Vec<Factor>, Piece)]) -> Option<Vec<Factor>> {
    let mut shared: Option<Vec<Factor>> = None;
    for (factors, _) in terms {
        let Some(j) = factors.iter().position(|f| matches!(f, Factor::Joint(..))) else {
            continue;
        };
        let head = factors[..=j].to_vec();
        match &shared {
            None => shared = Some(head),
            Some(s) if same(s, &head) => {}
            Some(_) => return None,
        }
    }
    Some(shared.unwrap_or_default())
}

fn blank(joint: Joint) -> Node {
    Node {
        body: 0,
        member: None,
        parent: None,
        joint,
        joint_frame: Vec::new(),
        anchored: false,
        offset: Vec::new(),
        after: Vec::new(),
        own: Vec::new(),
        offset_zeros: [false; 3],
    }
}

/// No joint: every term an offset in the parent's frame, the rotation the joint frame.
fn fixed(rotation: &[Factor], terms: Vec<(Vec<Factor>, Piece)>) -> Option<Node> {
    let mut node = blank(Joint::Fixed);
    node.joint_frame = constants(rotation)?;
    node.offset = offsets(terms)?;
    Some(node)
}

/// A rotation A · R_a(q) · C: terms turned by A · R_a(q) are the body's own, the others offsets in
/// the parent's frame.
fn revolute(
    rotation: &[Factor],
    j: usize,
    terms: Vec<(Vec<Factor>, Piece)>,
    rigid: bool,
) -> Option<Node> {
    let Factor::Joint(axis, slot) = rotation[j] else {
        return None;
    };
    let mut node = blank(Joint::Revolute(axis, slot));
    node.joint_frame = constants(&rotation[..j])?;
    node.after = match rigid {
        true => constants(&rotation[j + 1..])?,
        false => Vec::new(),
    };
    let head = &rotation[..=j];
    let (own, other): (Vec<_>, Vec<_>) = terms
        .into_iter()
        .partition(|(f, _)| f.len() > j && same(&f[..=j], head));
    node.own = offsets(
        own.into_iter()
            .map(|(f, p)| (f[j + 1..].to_vec(), p))
            .collect(),
    )?;
    node.offset = offsets(other)?;
    Some(node)
}

/// A slide along an axis of a constant frame X: the joint frame is X, the rotation as written
/// (constants A) is Xᵀ A in it, and every other term is an offset in the parent's frame.
fn prismatic(rotation: &[Factor], terms: Vec<(Vec<Factor>, Piece)>) -> Option<Node> {
    let (slide, other): (Vec<_>, Vec<_>) = terms
        .into_iter()
        .partition(|(_, p)| matches!(p, Piece::Slide(..)));
    let [(frame, Piece::Slide(constant, axis, slot, backwards))] = slide.as_slice() else {
        return None;
    };
    let mut node = blank(Joint::Prismatic(*axis, *slot));
    let mut frame = constants(frame)?;
    let constant_frame = frame.clone();
    // Backwards along the axis: forwards along the axis of a frame turned half around.
    if *backwards {
        frame.push(value::flip(*axis));
    }
    let product = product(&frame);
    node.after = std::iter::once(quote!(#product.transpose()))
        .chain(constants(rotation)?)
        .collect();
    node.offset = offsets(other)?;
    if let Some(c) = constant {
        node.offset.push(Offset {
            factors: constant_frame,
            vector: c.clone(),
            zeros: [false; 3],
        });
    }
    node.joint_frame = frame;
    Some(node)
}

/// The product of constant rotation factors (`Rot3::identity()` for none).
pub fn product(factors: &[TokenStream]) -> TokenStream {
    quote!((Rot3::<f64>::identity() #(* #factors)*))
}

/// Constant factors as expressions (`None` if one is not constant).
fn constants(factors: &[Factor]) -> Option<Vec<TokenStream>> {
    factors
        .iter()
        .map(|f| match f {
            Factor::Constant(c) => Some(c.clone()),
            _ => None,
        })
        .collect()
}

/// Terms that are constant vectors turned by constant factors.
fn offsets(terms: Vec<(Vec<Factor>, Piece)>) -> Option<Vec<Offset>> {
    terms
        .into_iter()
        .map(|(f, p)| match p {
            Piece::Constant(vector, zeros) => Some(Offset {
                factors: constants(&f)?,
                vector,
                zeros,
            }),
            _ => None,
        })
        .collect()
}

/// Whether two factor lists are the same product, factor by factor.
fn same(a: &[Factor], b: &[Factor]) -> bool {
    a.len() == b.len()
        && a.iter().zip(b).all(|(x, y)| match (x, y) {
            (Factor::Body(m), Factor::Body(n)) => m == n,
            (Factor::Joint(a, s), Factor::Joint(b, t)) => a == b && s == t,
            (Factor::Chart(a, s), Factor::Chart(b, t)) => a == b && s == t,
            (Factor::Constant(c), Factor::Constant(d)) => c.to_string() == d.to_string(),
            _ => false,
        })
}

/// The components of r_b the declaration shows to be zero: the parent's position adds nothing
/// (no own offsets), no constant rotation of the parent's turns the offsets, and each offset is an
/// unturned vector with that component a literal zero.
fn offset_zeros(nodes: &[Node], node: &Node) -> [bool; 3] {
    let parent = node.parent.map(|p| &nodes[p]);
    if parent.is_some_and(|p| !p.after.is_empty()) {
        return [false; 3];
    }
    let from_parent = match (node.anchored, parent) {
        (true, Some(p)) => zeros(&p.own),
        _ => [true; 3],
    };
    let own = zeros(&node.offset);
    std::array::from_fn(|k| from_parent[k] && own[k])
}

/// The components of Σ X c that are structurally zero: those every unturned vector has as a
/// literal zero (none when a vector is turned).
fn zeros(offsets: &[Offset]) -> [bool; 3] {
    std::array::from_fn(|k| offsets.iter().all(|o| o.factors.is_empty() && o.zeros[k]))
}
