//! Indexing array coordinates and families.

use super::model::{family_index, Model};
use crate::ctxt::Ctxt;
use std::collections::HashMap;
use syn::Ident;

/// Indexing an array coordinate, an array of parameters or a family: a literal index must be in range, and a family's own
/// index must not run past an array shorter than the family. Either would index out of bounds at
/// run time; here it is reported at the index.
pub(super) fn check_indices(cx: &Ctxt, model: &Model) {
    let lengths = indexable_lengths(model);
    if lengths.is_empty() {
        return;
    }
    for decl in &model.mechanism.decls {
        let members = decl
            .args
            .count
            .as_ref()
            .and_then(|c| model.mechanism.constant_length(c));
        let mut visitor = Indices {
            cx,
            lengths: &lengths,
            family: family_index(decl).zip(members),
            family_name: decl.ident(),
        };
        syn::visit::Visit::visit_block(&mut visitor, &decl.block);
        // A family's mass, inertia and centre of mass may index by its index (`mass = m[i]`).
        let args = &decl.args;
        let attributes = args.mass.iter().chain(&args.com).cloned();
        for expr in attributes.chain(args.inertia.as_ref().map(|i| i.expr())) {
            syn::visit::Visit::visit_expr(&mut visitor, &expr);
        }
    }
}

/// An array of parameters is read by element: standing alone in arithmetic (`vec2(..) * l` with
/// `l: [f64; 2]`) it is a mistake that rustc would report twice, in terms of the generated scalar;
/// here it is one message at the name. (Passed whole to a helper or a method, it is rustc's.)
pub(super) fn check_arrays_read_by_element(cx: &Ctxt, model: &Model) {
    let arrays: Vec<String> = model
        .params
        .iter()
        .filter(|p| p.array.is_some())
        .map(|p| p.ident.to_string())
        .collect();
    if arrays.is_empty() {
        return;
    }
    for decl in &model.mechanism.decls {
        let args = &decl.args;
        let attributes = args.mass.iter().chain(&args.com).cloned();
        let attributes = attributes.chain(args.inertia.as_ref().map(|i| i.expr()));
        let mut operands = crate::names::free_operands(&decl.block);
        operands.extend(attributes.flat_map(|e| crate::names::free_operands_of_expr(&e)));
        for name in operands.iter().filter(|n| arrays.contains(&n.to_string())) {
            cx.error_spanned_by(
                name,
                format!("`{name}` is an array of parameters: name one element, `{name}[0]` (or `{name}[i]` in a family)"),
            );
        }
    }
}

/// The length of everything a function may index, by name: array coordinates and families of
/// bodies, and their velocities.
fn indexable_lengths(model: &Model) -> HashMap<String, usize> {
    let mut lengths: HashMap<String, usize> = HashMap::new();
    for c in model.coords {
        // A length the macro could not read (0) was reported: nothing to check against.
        if let Some((_, n)) = c.array.as_ref().filter(|(_, n)| *n > 0) {
            let n = *n;
            lengths.insert(c.ident.to_string(), n);
            lengths.insert(format!("{}_dot", c.ident), n);
        }
    }
    for p in model.params {
        if let Some((_, n)) = p.array.as_ref().filter(|(_, n)| *n > 0) {
            lengths.insert(p.ident.to_string(), *n);
        }
    }
    for b in &model.bodies {
        if let Some(n) = b.count {
            lengths.insert(b.decl.ident().to_string(), n);
            lengths.insert(format!("{}_dot", b.decl.ident()), n);
        }
    }
    lengths
}

/// Visits one function's body for indexing expressions.
struct Indices<'c, 'l> {
    cx: &'c Ctxt,
    lengths: &'l HashMap<String, usize>,
    /// This function's family index and member count.
    family: Option<(&'l Ident, usize)>,
    family_name: &'l Ident,
}

impl Indices<'_, '_> {
    /// A literal index is below the length: `theta[8]` with `theta: [f64; 8]` is not.
    fn check_literal_index(&self, index: &syn::LitInt, name: &str, len: usize) {
        if let Ok(k) = index.base10_parse::<usize>() {
            if k >= len {
                self.cx.error_spanned_by(
                    index,
                    format!("index {k} is out of range: `{name}` has {len} elements"),
                );
            }
        }
    }

    /// A family's own index stays below the length: `theta[i]` in a family of 9 with
    /// `theta: [f64; 8]` does not.
    fn check_family_index(&self, index: &syn::Expr, path: &syn::Path, name: &str, len: usize) {
        let Some((family_index, members)) = self.family else {
            return;
        };
        if path.is_ident(family_index) && members > len {
            self.cx.error_spanned_by(
                index,
                format!(
                    "mismatched family length: `{}` has {members} members but `{name}` has {len} elements, so `{name}[{family_index}]` is out of range",
                    self.family_name
                ),
            );
        }
    }
}

impl<'ast> syn::visit::Visit<'ast> for Indices<'_, '_> {
    fn visit_expr_index(&mut self, e: &'ast syn::ExprIndex) {
        let base = match crate::ast::ungroup(&e.expr) {
            syn::Expr::Path(p) => p.path.get_ident(),
            _ => None,
        };
        if let Some((name, &len)) = base.and_then(|b| self.lengths.get_key_value(&b.to_string())) {
            match crate::ast::ungroup(&e.index) {
                syn::Expr::Lit(syn::ExprLit {
                    lit: syn::Lit::Int(i),
                    ..
                }) => self.check_literal_index(i, name, len),
                syn::Expr::Path(p) => self.check_family_index(&e.index, &p.path, name, len),
                _ => {}
            }
        }
        syn::visit::visit_expr_index(self, e);
    }
    fn visit_item(&mut self, _: &'ast syn::Item) {}
}
