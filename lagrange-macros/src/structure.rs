//! The structure a declaration states: which body each body is translated from, and which
//! coordinates its own part depends on. When every body is a point written as
//!
//! ```text
//! #[particle(mass = m2)]
//! fn bob2() -> Vec2 { bob1 + vec2(theta2.sin(), -theta2.cos()) * l2 }
//! ```
//!
//! — an earlier body plus a displacement that names no body, or a position that names no body at all
//! — the mechanism is a tree of translations, and its equations of motion are assembled by
//! `lagrange_core::tree` with dual numbers seeded only on each body's own coordinates. Anything else
//! (rigid bodies, families, constraints, a body named inside a product) keeps the dense assembly.

use crate::check::{Body, Model, Shape};
use crate::names;
use std::collections::BTreeSet;
use syn::{BinOp, Block, Expr, Ident, Stmt};

/// A body of a tree: what it is translated from and its own displacement.
pub struct TreeBody {
    /// Index into `Model::bodies` of the body this one is translated from.
    pub parent: Option<usize>,
    /// The body's function with the parent removed from its final expression.
    pub displacement: Block,
    /// The coordinates the displacement names, in declaration order: its seeds, slot by slot.
    pub coordinates: Vec<(Ident, usize)>,
    /// Whether the displacement names `t` (then seeded after the coordinates).
    pub names_time: bool,
}

impl TreeBody {
    /// Seeds this body uses: its coordinates and, if it names `t`, time.
    pub fn seeds(&self) -> usize {
        self.coordinates.len() + usize::from(self.names_time)
    }
}

/// The whole tree: one entry per body of `Model::bodies`, and the widest body's seed count.
pub struct Tree {
    pub bodies: Vec<TreeBody>,
    pub width: usize,
}

/// The tree of translations the declaration states, if it states one.
pub fn tree(model: &Model) -> Option<Tree> {
    if !model.constraints.is_empty() {
        return None;
    }
    let bodies = model
        .bodies
        .iter()
        .enumerate()
        .map(|(index, body)| tree_body(model, index, body))
        .collect::<Option<Vec<_>>>()?;
    let width = bodies.iter().map(TreeBody::seeds).max().unwrap_or(0).max(1);
    Some(Tree { bodies, width })
}

/// One body: a point or particle, not a family, whose function is `parent + displacement` or names
/// no body.
fn tree_body(model: &Model, index: usize, body: &Body) -> Option<TreeBody> {
    if body.count.is_some() || !matches!(body.shape, Shape::Particle(_) | Shape::Point(_)) {
        return None;
    }
    let block = &body.decl.block;
    // `return` would leave the final expression with the parent still in it.
    if names::first_return(block).is_some() {
        return None;
    }
    let (parent, displacement) = if names_a_body(model, block) {
        split_parent(model, index, body, block)?
    } else {
        (None, block.clone())
    };
    let free: BTreeSet<String> = names::free_names(&displacement)
        .iter()
        .map(Ident::to_string)
        .collect();
    let mut coordinates = Vec::new();
    let mut slot = 0;
    for field in model.coords {
        if free.contains(&field.ident.to_string()) {
            // An array coordinate would need its elements seeded one by one: not yet.
            if field.array.is_some() {
                return None;
            }
            coordinates.push((field.ident.clone(), slot));
        }
        slot += field.slots();
    }
    Some(TreeBody {
        parent,
        displacement,
        coordinates,
        names_time: free.contains("t"),
    })
}

fn names_a_body(model: &Model, block: &Block) -> bool {
    let bodies: BTreeSet<String> = model
        .bodies
        .iter()
        .map(|b| b.decl.ident().to_string())
        .collect();
    names::free_names(block)
        .iter()
        .any(|name| bodies.contains(&name.to_string()))
}

/// `bob1 + d` or `d + bob1` as the final expression, with `bob1` an earlier point of the same
/// dimension laid out before this body, and nothing else naming a body.
fn split_parent(
    model: &Model,
    index: usize,
    body: &Body,
    block: &Block,
) -> Option<(Option<usize>, Block)> {
    let Some(Stmt::Expr(tail, None)) = block.stmts.last() else {
        return None;
    };
    let Expr::Binary(sum) = strip(tail) else {
        return None;
    };
    if !matches!(sum.op, BinOp::Add(_)) {
        return None;
    }
    let (left, right) = (&*sum.left, &*sum.right);
    let (parent, parent_name, rest) = match (
        earlier_body(model, index, left),
        earlier_body(model, index, right),
    ) {
        (Some(p), _) => (p, left, right),
        (None, Some(p)) => (p, right, left),
        (None, None) => return None,
    };
    let parent_body = &model.bodies[parent];
    if parent_body.shape.dim() != body.shape.dim() || parent_body.row >= body.row {
        return None;
    }
    // The name in the final expression is the body, not a local of the block that shadows it.
    let mut probe = block.clone();
    *probe.stmts.last_mut()? = Stmt::Expr(parent_name.clone(), None);
    if !names::free_names(&probe).iter().any(|n| n == parent_body.decl.ident()) {
        return None;
    }
    let mut displacement = block.clone();
    *displacement.stmts.last_mut()? = Stmt::Expr(rest.clone(), None);
    (!names_a_body(model, &displacement)).then_some((Some(parent), displacement))
}

/// The index of the earlier point or particle `expr` names, if it is just that name.
fn earlier_body(model: &Model, index: usize, expr: &Expr) -> Option<usize> {
    let Expr::Path(path) = strip(expr) else {
        return None;
    };
    let ident = path.path.get_ident()?;
    model.bodies[..index].iter().position(|b| {
        b.decl.ident() == ident
            && b.count.is_none()
            && matches!(b.shape, Shape::Particle(_) | Shape::Point(_))
    })
}

/// The expression inside parentheses and invisible groups.
fn strip(expr: &Expr) -> &Expr {
    match expr {
        Expr::Paren(p) => strip(&p.expr),
        Expr::Group(g) => strip(&g.expr),
        e => e,
    }
}
