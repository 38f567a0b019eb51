//! The structure a declaration states: which body each body is translated from, and which
//! coordinates its own part depends on. When every body is a point written as
//!
//! ```text
//! #[particle(mass = m2)]
//! fn bob2() -> Vec2 { bob1 + vec2(theta2.sin(), -theta2.cos()) * l2 }
//!
//! #[particle(mass = m, count = LINKS)]
//! fn bob(i: usize) -> Vec2 {
//!     let link = vec2(theta[i].sin(), -theta[i].cos()) * l;
//!     if i == 0 { link } else { bob[i - 1] + link }
//! }
//! ```
//!
//! — an earlier body (or family member) plus a displacement that names no body, or a position that
//! names no body at all — the mechanism is a tree of translations, and its equations of motion are
//! assembled by `lagrange_core::tree` with dual numbers seeded only on each body's own coordinates.
//! A family is read member by member: the family index is known for each, so `if i == 0` picks a
//! branch and `theta[i]`, `theta[i - 1]`, `theta[3]` name single coordinates. Anything else (rigid
//! bodies, constraints, a body named inside a product, an array coordinate used other than by such
//! an index), and a tree whose widest body needs every coordinate anyway, keeps the dense assembly.

use crate::check::{family_index, Body, Model, Shape};
use crate::names;
use proc_macro2::Span;
use quote::ToTokens;
use std::collections::BTreeSet;
use syn::visit_mut::{self, VisitMut};
use syn::{BinOp, Block, Expr, Ident, Lit, Stmt};

pub mod rigid;

/// A body of the tree: one point, or one member of a family of points.
pub struct TreeBody {
    /// Index into `Model::bodies`.
    pub body: usize,
    /// The member's index, for a member of a family.
    pub member: Option<usize>,
    /// Index into `Tree::bodies` of the body this one is translated from.
    pub parent: Option<usize>,
    /// Which of [`Tree::functions`] evaluates its displacement.
    pub function: usize,
    /// Its seeds: the slot of each of the function's coordinate arguments, in their order.
    pub slots: Vec<usize>,
    /// Whether the displacement names `t` (then seeded after the coordinates).
    pub names_time: bool,
}

impl Tree {
    /// Whether each of the `dof` coordinates is a seed of exactly one body
    /// (`lagrange_core::tree::Tree::JOINTS`): then q̈ comes from the articulated-body recursion.
    pub fn moves_each_coordinate_once(&self, dof: usize) -> bool {
        (0..dof).all(|c| {
            let owners = self.bodies.iter().flat_map(|b| &b.slots);
            owners.filter(|&&slot| slot == c).count() == 1
        })
    }
}

impl TreeBody {
    /// Seeds this body uses: its coordinates and, if it names `t`, time.
    pub fn seeds(&self) -> usize {
        self.slots.len() + usize::from(self.names_time)
    }
}

/// A displacement function: the part of a body's position after its parent, with the elements of
/// array coordinates it reads replaced by scalar arguments.
pub struct Displacement {
    /// Index into `Model::bodies`.
    pub body: usize,
    pub block: Block,
    /// The coordinate arguments, in order: a scalar coordinate's own name, or a local standing for
    /// an array element (`__theta_at_i_minus_1` for `theta[i - 1]`).
    pub arguments: Vec<Ident>,
}

/// The whole tree: its bodies (parents first), the displacement functions they share, and the
/// widest body's seed count.
pub struct Tree {
    pub bodies: Vec<TreeBody>,
    pub functions: Vec<Displacement>,
    pub width: usize,
}

/// Which coordinates each row of x can depend on (the generated `Model::DEPENDS`):
/// [`crate::components::dependencies`] (body by body, component by component), narrowed member by member where
/// the declaration is a tree of translations — a family member's rows depend on the elements it
/// names (`q[i]` for member i, not the whole array) and on its parent's. `None` when every row may
/// depend on every coordinate.
pub fn rows_depend_on(model: &Model) -> Option<Vec<Vec<bool>>> {
    let (mut rows, _) = crate::components::dependencies(model);
    if let Some(tree) = tree(model) {
        let mut body_deps: Vec<Vec<bool>> = Vec::with_capacity(tree.bodies.len());
        for member in &tree.bodies {
            let mut deps = member
                .parent
                .map_or_else(|| vec![false; model.dof()], |p| body_deps[p].clone());
            member.slots.iter().for_each(|&s| deps[s] = true);
            let body = &model.bodies[member.body];
            let first = body.row + member.member.unwrap_or(0) * body.shape.rows();
            for row in &mut rows[first..first + body.shape.rows()] {
                row.iter_mut().zip(&deps).for_each(|(r, &d)| *r &= d);
            }
            body_deps.push(deps);
        }
    }
    rows.iter().any(|r| r.contains(&false)).then_some(rows)
}

/// The tree of translations the declaration states, if it states one.
pub fn tree(model: &Model) -> Option<Tree> {
    if !model.constraints.is_empty() {
        return None;
    }
    let mut tree = Tree {
        bodies: Vec::new(),
        functions: Vec::new(),
        width: 0,
    };
    for (index, body) in model.bodies.iter().enumerate() {
        if !matches!(body.shape, Shape::Particle(_) | Shape::Point(_)) {
            return None;
        }
        for member in 0..body.members() {
            let member = body.count.map(|_| member);
            let own = tree_body(model, &mut tree, index, body, member)?;
            tree.bodies.push(own);
        }
    }
    tree.width = tree
        .bodies
        .iter()
        .map(TreeBody::seeds)
        .max()
        .unwrap_or(0)
        .max(1);
    // Seeds as wide as the dense pass's save nothing, and the dense pass is the shorter code
    // (BENCHMARKS.md §1: a pendulum, a wedge).
    (tree.width < model.dof()).then_some(tree)
}

/// One body or member: its parent, its displacement (shared with the members that have the same
/// one) and its seeds.
fn tree_body(
    model: &Model,
    tree: &mut Tree,
    index: usize,
    body: &Body,
    member: Option<usize>,
) -> Option<TreeBody> {
    let block = &body.decl.block;
    // `return` would leave the final expression with the parent still in it.
    if names::first_return(block).is_some() {
        return None;
    }
    let family = member.and_then(|k| family_index(body.decl).map(|i| (i, k)));
    let (parent, displacement) = split_block(model, tree, index, body, family, block)?;
    if names_a_body(model, &displacement) {
        return None;
    }
    let (displacement, elements) = seed_elements(model, family, displacement)?;
    let free: BTreeSet<String> = names::free_names(&displacement)
        .iter()
        .map(Ident::to_string)
        .collect();
    // Scalar coordinates by name, then array elements by the local standing for them.
    let mut arguments = Vec::new();
    let mut slots = Vec::new();
    let mut slot = 0;
    for field in model.coords {
        if field.array.is_none() && free.contains(&field.ident.to_string()) {
            arguments.push(field.ident.clone());
            slots.push(slot);
        }
        slot += field.slots();
    }
    for (local, element) in elements {
        arguments.push(local);
        slots.push(element);
    }
    let text = displacement.to_token_stream().to_string();
    let function = match tree.functions.iter().position(|f| {
        f.body == index && f.block.to_token_stream().to_string() == text && f.arguments == arguments
    }) {
        Some(f) => f,
        None => {
            tree.functions.push(Displacement {
                body: index,
                block: displacement,
                arguments,
            });
            tree.functions.len() - 1
        }
    };
    Some(TreeBody {
        body: index,
        member,
        parent,
        function,
        slots,
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

/// The family index and the member it stands for.
pub(crate) type Family<'a> = Option<(&'a Ident, usize)>;

/// The block with the parent taken out of its final expression (`None` for a root), following
/// `if`s on the family index and nested blocks to the expression that is the position.
fn split_block(
    model: &Model,
    tree: &Tree,
    index: usize,
    body: &Body,
    family: Family,
    block: &Block,
) -> Option<(Option<usize>, Block)> {
    let Some(Stmt::Expr(tail, None)) = block.stmts.last() else {
        // No final expression: nothing to split (a block that names no body is a root).
        return (!names_a_body(model, block)).then(|| (None, block.clone()));
    };
    let (parent, rest) = split_expr(model, tree, index, body, family, tail)?;
    let mut split = block.clone();
    *split.stmts.last_mut()? = Stmt::Expr(rest, None);
    // The name taken as the parent is the body, not a local of the block that shadows it.
    if parent.is_some() && shadows_a_body(model, block) {
        return None;
    }
    Some((parent, split))
}

fn split_expr(
    model: &Model,
    tree: &Tree,
    index: usize,
    body: &Body,
    family: Family,
    expr: &Expr,
) -> Option<(Option<usize>, Expr)> {
    match expr {
        Expr::Paren(p) => split_expr(model, tree, index, body, family, &p.expr),
        Expr::Group(g) => split_expr(model, tree, index, body, family, &g.expr),
        Expr::Block(b) if b.label.is_none() => {
            let (parent, block) = split_block(model, tree, index, body, family, &b.block)?;
            Some((parent, Expr::Block(syn::ExprBlock { block, ..b.clone() })))
        }
        // `if i == 0 { .. } else { .. }`: the member decides the branch.
        Expr::If(e) => {
            let taken = condition(&e.cond, family?)?;
            let branch = match (taken, &e.else_branch) {
                (true, _) => &e.then_branch,
                (false, Some((_, other))) => match &**other {
                    Expr::Block(b) => &b.block,
                    other => return split_expr(model, tree, index, body, family, other),
                },
                (false, None) => return None,
            };
            let (parent, block) = split_block(model, tree, index, body, family, branch)?;
            // A branch that is one expression is that expression: braces around it, kept with the
            // spans of the user's `if`, would be `unused_braces` in the user's crate.
            let expr = match &block.stmts[..] {
                [Stmt::Expr(tail, None)] => tail.clone(),
                _ => Expr::Block(syn::ExprBlock {
                    attrs: Vec::new(),
                    label: None,
                    block,
                }),
            };
            Some((parent, expr))
        }
        Expr::Binary(sum) if matches!(sum.op, BinOp::Add(_)) => {
            let (left, right) = (&*sum.left, &*sum.right);
            match (
                parent_of(model, tree, index, body, family, left),
                parent_of(model, tree, index, body, family, right),
            ) {
                (Some(p), _) => Some((Some(p), right.clone())),
                (None, Some(p)) => Some((Some(p), left.clone())),
                (None, None) => Some((None, expr.clone())),
            }
        }
        _ => Some((None, expr.clone())),
    }
}

/// The tree body `expr` names as a parent: an earlier point (`bob1`) or an earlier member of a
/// family (`bob[i - 1]`, `links[2]`) of the same dimension laid out before this body's rows.
fn parent_of(
    model: &Model,
    tree: &Tree,
    index: usize,
    body: &Body,
    family: Family,
    expr: &Expr,
) -> Option<usize> {
    let (name, member) = match strip(expr) {
        Expr::Path(path) => (path.path.get_ident()?, None),
        Expr::Index(e) => match strip(&e.expr) {
            Expr::Path(path) => (path.path.get_ident()?, Some(evaluate(&e.index, family)?)),
            _ => return None,
        },
        _ => return None,
    };
    let parent = model.bodies[..=index]
        .iter()
        .position(|b| b.decl.ident() == name)?;
    let parent_body = &model.bodies[parent];
    if parent_body.count.is_some() != member.is_some()
        || parent_body.shape.dim() != body.shape.dim()
        || !matches!(parent_body.shape, Shape::Particle(_) | Shape::Point(_))
    {
        return None;
    }
    // Rows: the parent's member must come before this body's in x.
    let member_rows = |b: &Body, k: usize| b.row + k * b.shape.rows();
    let this_row = member_rows(body, family.map_or(0, |(_, k)| k));
    if member_rows(parent_body, member.unwrap_or(0)) >= this_row {
        return None;
    }
    tree.bodies
        .iter()
        .position(|t| t.body == parent && t.member == member)
}

/// Whether the block binds the name of a body anywhere (a local that could shadow it).
fn shadows_a_body(model: &Model, block: &Block) -> bool {
    let free: BTreeSet<String> = names::free_names(block)
        .iter()
        .map(Ident::to_string)
        .collect();
    let text = block.to_token_stream().to_string();
    model.bodies.iter().any(|b| {
        let name = b.decl.ident().to_string();
        text.contains(&format!("let {name}"))
            || text.contains(&format!("let mut {name}"))
            || (!free.contains(&name) && text.split_whitespace().any(|w| w == name))
    })
}

/// The value of a condition on the family index for this member: `i == 0`, `i > 0`, `0 < i`, …
pub(crate) fn condition(cond: &Expr, family: (&Ident, usize)) -> Option<bool> {
    let Expr::Binary(c) = strip(cond) else {
        return None;
    };
    let (left, right) = (
        evaluate(&c.left, Some(family))?,
        evaluate(&c.right, Some(family))?,
    );
    Some(match c.op {
        BinOp::Eq(_) => left == right,
        BinOp::Ne(_) => left != right,
        BinOp::Lt(_) => left < right,
        BinOp::Le(_) => left <= right,
        BinOp::Gt(_) => left > right,
        BinOp::Ge(_) => left >= right,
        _ => return None,
    })
}

/// The value of an index written with integer literals and the family index (`i`, `i - 1`, `3`,
/// `i % 2`).
pub(crate) fn evaluate(expr: &Expr, family: Family) -> Option<usize> {
    match strip(expr) {
        Expr::Lit(syn::ExprLit {
            lit: Lit::Int(i), ..
        }) => i.base10_parse().ok(),
        Expr::Path(p) => {
            let (index, k) = family?;
            (p.path.get_ident()? == index).then_some(k)
        }
        Expr::Binary(b) => {
            let (l, r) = (evaluate(&b.left, family)?, evaluate(&b.right, family)?);
            match b.op {
                BinOp::Add(_) => l.checked_add(r),
                BinOp::Sub(_) => l.checked_sub(r),
                BinOp::Mul(_) => l.checked_mul(r),
                BinOp::Rem(_) => l.checked_rem(r),
                BinOp::Div(_) => l.checked_div(r),
                _ => None,
            }
        }
        _ => None,
    }
}

/// The displacement with each element of an array coordinate it reads (`theta[i]`) replaced by a
/// local argument, and those arguments with their slots. `None` when an array coordinate is used
/// other than by an index this member can evaluate.
fn seed_elements(
    model: &Model,
    family: Family,
    mut block: Block,
) -> Option<(Block, Vec<(Ident, usize)>)> {
    let mut offset = 0;
    let mut arrays = Vec::new();
    for field in model.coords {
        if let Some((_, len)) = &field.array {
            arrays.push((field.ident.to_string(), offset, *len));
        }
        offset += field.slots();
    }
    let mut rewrite = Elements {
        arrays: &arrays,
        family,
        found: Vec::new(),
        failed: false,
    };
    rewrite.visit_block_mut(&mut block);
    if rewrite.failed {
        return None;
    }
    // An array coordinate still named (passed whole, iterated): not one element.
    let free: BTreeSet<String> = names::free_names(&block)
        .iter()
        .map(Ident::to_string)
        .collect();
    if arrays.iter().any(|(name, _, _)| free.contains(name)) {
        return None;
    }
    Some((block, rewrite.found))
}

struct Elements<'a> {
    arrays: &'a [(String, usize, usize)],
    family: Family<'a>,
    found: Vec<(Ident, usize)>,
    failed: bool,
}

impl VisitMut for Elements<'_> {
    fn visit_expr_mut(&mut self, expr: &mut Expr) {
        if let Expr::Index(e) = expr {
            if let Expr::Path(p) = strip(&e.expr) {
                if let Some(name) = p.path.get_ident() {
                    if let Some((_, offset, len)) =
                        self.arrays.iter().find(|(a, _, _)| name == a.as_str())
                    {
                        match evaluate(&e.index, self.family) {
                            Some(k) if k < *len => {
                                let local = element_local(name, &e.index);
                                if !self.found.iter().any(|(l, _)| *l == local) {
                                    self.found.push((local.clone(), offset + k));
                                }
                                *expr = syn::parse_quote!(#local);
                            }
                            _ => self.failed = true,
                        }
                        return;
                    }
                }
            }
        }
        visit_mut::visit_expr_mut(self, expr);
    }
    fn visit_item_mut(&mut self, _: &mut syn::Item) {}
}

/// `__theta_at_i_minus_1` for `theta[i - 1]`: one name per index as written.
fn element_local(array: &Ident, index: &Expr) -> Ident {
    let written: String = index
        .to_token_stream()
        .to_string()
        .chars()
        .map(|c| match c {
            '-' => 'm',
            '+' => 'p',
            c if c.is_ascii_alphanumeric() => c,
            _ => '_',
        })
        .collect();
    let array = array.to_string();
    let array = array.trim_start_matches("r#");
    Ident::new(&format!("__{array}_at_{written}"), Span::call_site())
}

/// The expression inside parentheses and invisible groups.
pub(crate) fn strip(expr: &Expr) -> &Expr {
    match expr {
        Expr::Paren(p) => strip(&p.expr),
        Expr::Group(g) => strip(&g.expr),
        e => e,
    }
}
