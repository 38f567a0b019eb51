//! Which bodies and points each position and constraint function names, member by member: the
//! lines a drawing of the mechanism shows between a body and the bodies its declaration is written
//! from (`Drawable::LINKS`), and where each constraint acts (`Drawable::CONSTRAINT_BODIES`).
//!
//! A family member is read as [`crate::structure`] reads it: the family index is known for each
//! member, so `if i == 0 { .. } else { .. }` takes one branch and `bob[i - 1]` names one member.

use crate::check::{family_index, Model};
use crate::structure::{condition, evaluate, strip, Family};
use std::collections::BTreeSet;
use syn::visit::{self, Visit};
use syn::{Block, Expr, Ident};

/// A body (index into `Model::bodies`) and its member (0 for a single body).
pub type Member = (usize, usize);

/// Every (body member, earlier body member its position function names), in declaration order.
/// A family named whole, or at an index that cannot be evaluated for the member, is not linked:
/// which member is meant is not written down.
pub fn links(model: &Model) -> Vec<(Member, Member)> {
    let mut links = Vec::new();
    for (index, body) in model.bodies.iter().enumerate() {
        for member in 0..body.members() {
            let family = body
                .count
                .and_then(|_| family_index(body.decl))
                .map(|i| (i, member));
            let named = named_in(model, body.decl.ident(), &body.decl.block, family, false);
            for to in named {
                let link = ((index, member), to);
                if to != (index, member) && !links.contains(&link) {
                    links.push(link);
                }
            }
        }
    }
    links
}

/// For each constraint row, in declaration order, the body members its function names; a family
/// named whole, or at an index that is not a constant, counts with every member.
pub fn constraint_bodies(model: &Model) -> Vec<Vec<Member>> {
    model
        .constraints
        .iter()
        .map(|row| {
            let mut named = Vec::new();
            for m in named_in(model, row.decl.ident(), &row.decl.block, None, true) {
                if !named.contains(&m) {
                    named.push(m);
                }
            }
            named
        })
        .collect()
}

/// The body members `block` (the function `name`) names, in order of appearance (with repeats).
fn named_in(
    model: &Model,
    name: &Ident,
    block: &Block,
    family: Family,
    whole_families: bool,
) -> Vec<Member> {
    let free: BTreeSet<String> = model
        .free_names
        .get(&name.to_string())
        .into_iter()
        .flatten()
        .map(Ident::to_string)
        .collect();
    let mut visitor = Named {
        model,
        free,
        family,
        whole_families,
        found: Vec::new(),
    };
    visitor.visit_block(block);
    visitor.found
}

struct Named<'m, 'a> {
    model: &'m Model<'a>,
    /// The function's free names: a body's name bound by a local is not the body.
    free: BTreeSet<String>,
    family: Family<'a>,
    whole_families: bool,
    found: Vec<Member>,
}

impl Named<'_, '_> {
    /// The body `expr` is the bare name of, with its family count.
    fn body(&self, expr: &Expr) -> Option<(usize, Option<usize>)> {
        let Expr::Path(path) = strip(expr) else {
            return None;
        };
        let ident = path.path.get_ident()?.to_string();
        if !self.free.contains(&ident) {
            return None;
        }
        let index = self
            .model
            .bodies
            .iter()
            .position(|b| *b.decl.ident() == ident)?;
        Some((index, self.model.bodies[index].count))
    }

    fn every_member(&mut self, body: usize, count: usize) {
        if self.whole_families {
            self.found.extend((0..count).map(|k| (body, k)));
        }
    }
}

impl<'ast> Visit<'ast> for Named<'_, '_> {
    fn visit_expr(&mut self, expr: &'ast Expr) {
        match expr {
            // `if i == 0 { link } else { bob[i - 1] + link }`: the member decides the branch.
            Expr::If(e) => {
                if let Some(taken) = self.family.and_then(|f| condition(&e.cond, f)) {
                    match (taken, &e.else_branch) {
                        (true, _) => self.visit_block(&e.then_branch),
                        (false, Some((_, other))) => self.visit_expr(other),
                        (false, None) => {}
                    }
                    return;
                }
            }
            // `bob[i - 1]`: one member when the index can be evaluated.
            Expr::Index(e) => {
                if let Some((body, Some(count))) = self.body(&e.expr) {
                    match evaluate(&e.index, self.family) {
                        Some(k) if k < count => self.found.push((body, k)),
                        _ => self.every_member(body, count),
                    }
                    self.visit_expr(&e.index);
                    return;
                }
            }
            Expr::Path(_) => match self.body(expr) {
                Some((body, None)) => self.found.push((body, 0)),
                Some((body, Some(count))) => self.every_member(body, count),
                None => {}
            },
            _ => {}
        }
        visit::visit_expr(self, expr);
    }

    // Items nested in a function (a helper `fn`) are not part of its value.
    fn visit_item(&mut self, _: &'ast syn::Item) {}
}
