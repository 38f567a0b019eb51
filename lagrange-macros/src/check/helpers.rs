//! Calls from a declaration's functions to helper functions of the module.

use super::model::Model;
use crate::ast::Mechanism;
use crate::ctxt::Ctxt;
use syn::{Ident, Type};

/// `fn helper(x: f64) -> f64` in the module, called from a declaration's function: those functions
/// are evaluated on dual numbers (to differentiate them) — coordinates, parameters and literals alike
/// — so an `f64` parameter cannot take the argument and rustc would report a mismatch on generated
/// types. One message at the call says what to write instead. (In an attribute, `mass = helper(m)`,
/// everything is `f64` and the call is fine.)
pub(super) fn check_helper_calls(cx: &Ctxt, model: &Model) {
    let helpers = f64_helpers(model.mechanism);
    if helpers.is_empty() {
        return;
    }
    for decl in &model.mechanism.decls {
        let mut calls = HelperCalls {
            helpers: &helpers,
            found: Vec::new(),
        };
        syn::visit::Visit::visit_block(&mut calls, &decl.block);
        for (call, name) in calls.found {
            cx.error_spanned_by(
                call,
                format!(
                    "`{name}` takes `f64`, but a mechanism's functions run on dual numbers (that is how they are differentiated): make it generic, `fn {name}<D: lagrange::Scalar>(x: D) -> D`, or write its expression inline"
                ),
            );
        }
    }
}

/// The module's non-generic functions that take an `f64` argument.
fn f64_helpers(mechanism: &Mechanism) -> Vec<&Ident> {
    mechanism
        .other_items
        .iter()
        .filter_map(|item| match item {
            syn::Item::Fn(f) if f.sig.generics.params.is_empty() => f
                .sig
                .inputs
                .iter()
                .any(|arg| matches!(arg, syn::FnArg::Typed(t) if is_f64_type(&t.ty)))
                .then_some(&f.sig.ident),
            _ => None,
        })
        .collect()
}

/// Whether `ty` is `f64`, looking through invisible groups and parentheses.
fn is_f64_type(ty: &Type) -> bool {
    match ty {
        Type::Path(p) => p.qself.is_none() && p.path.is_ident("f64"),
        Type::Group(g) => is_f64_type(&g.elem),
        Type::Paren(p) => is_f64_type(&p.elem),
        _ => false,
    }
}

/// Calls of helpers that take an `f64` argument.
struct HelperCalls<'a> {
    helpers: &'a [&'a Ident],
    found: Vec<(&'a syn::ExprCall, String)>,
}

impl<'ast: 'a, 'a> syn::visit::Visit<'ast> for HelperCalls<'a> {
    fn visit_expr_call(&mut self, call: &'ast syn::ExprCall) {
        if let syn::Expr::Path(p) = &*call.func {
            if let Some(name) = p.path.get_ident() {
                if self.helpers.contains(&name) {
                    self.found.push((call, name.to_string()));
                }
            }
        }
        syn::visit::visit_expr_call(self, call);
    }
    fn visit_item(&mut self, _: &'ast syn::Item) {}
}
