//! Rewrites of the user's function bodies that make the generated code cheaper without changing a
//! single value it computes. They run before [`crate::lift`], over all the bodies that one generated
//! function evaluates:
//!
//! 1. **Parameter-only subexpressions are evaluated in `f64`.** A maximal subexpression that names
//!    parameters and literals only (`alpha.sin()`, `l1 * l2`, `0.5 * m`) has zero derivative; it
//!    becomes `let __param_k: __D = <__D>::from({ let alpha: f64 = self.alpha; alpha.sin() });`
//!    once, before the bodies, instead of being evaluated on dual numbers.
//! 2. **`sin` and `cos` of the same coordinate share one `sin_cos`.** When the bodies call both
//!    `theta.sin()` and `theta.cos()` on a coordinate (or `t`), they become the halves of one
//!    `let (__sin_theta, __cos_theta) = theta.sin_cos();` — on hyper-dual numbers each of `sin` and
//!    `cos` costs a libm `sincos` of its own.
//!
//! A name bound anywhere inside the bodies (a `let`, a closure argument) is left alone, so shadowing
//! never changes meaning. Nested items are not touched.

use proc_macro2::{Ident, Span, TokenStream};
use quote::{format_ident, quote, ToTokens};
use std::collections::{BTreeMap, BTreeSet};
use syn::visit::{self, Visit};
use syn::visit_mut::{self, VisitMut};
use syn::{BinOp, Expr, ExprLit, Lit, UnOp};

/// `f64 → f64` methods (with `f64` or `i32` arguments) that mean the same on `f64` and on a dual
/// number, so a call on parameters may be evaluated in `f64`.
const PURE_METHODS: &[&str] = &[
    "sin", "cos", "tan", "asin", "acos", "atan", "atan2", "sinh", "cosh", "tanh", "asinh", "acosh",
    "atanh", "exp", "exp2", "exp_m1", "ln", "ln_1p", "log", "log10", "log2", "sqrt", "cbrt",
    "powi", "powf", "recip", "abs", "hypot",
];

/// What the rewrites need to know about the names in scope.
pub struct Scope<'a> {
    /// Parameter names (bound as `<__D>::from(self.p)` in the generated function).
    pub params: &'a BTreeSet<String>,
    /// Names whose `sin`/`cos` may share one `sin_cos` (coordinates, `t`), bound before the
    /// generated `let`s.
    pub trig: &'a BTreeSet<String>,
    /// Array coordinates: `theta[k].sin()` and `theta[k].cos()` share one `sin_cos` per element.
    pub arrays: &'a BTreeSet<String>,
}

/// Rewrites `blocks` in place; returns the `let`s to place after the inputs are bound and before
/// the bodies.
pub fn optimize(blocks: &mut [syn::Block], scope: &Scope, scalar: &TokenStream) -> TokenStream {
    let mut bound = Bound::default();
    for block in blocks.iter() {
        bound.visit_block(block);
    }
    let params: BTreeSet<String> = scope.params.difference(&bound.0).cloned().collect();
    let trig: BTreeSet<String> = scope.trig.difference(&bound.0).cloned().collect();
    let arrays: BTreeSet<String> = scope.arrays.difference(&bound.0).cloned().collect();

    let mut hoister = Hoister {
        params: &params,
        hoisted: Vec::new(),
        by_text: BTreeMap::new(),
    };
    for block in blocks.iter_mut() {
        hoister.visit_block_mut(block);
    }

    let mut calls = TrigCalls {
        names: &trig,
        arrays: &arrays,
        seen: BTreeMap::new(),
    };
    for block in blocks.iter() {
        calls.visit_block(block);
    }
    let shared: BTreeSet<String> = calls
        .seen
        .into_iter()
        .filter(|(_, (sin, cos))| *sin && *cos)
        .map(|(name, _)| name)
        .collect();
    // Only the arrays whose elements' `sin` and `cos` are both called get a table: an array with
    // `theta[i].cos()` alone keeps its calls.
    let shared_arrays: BTreeSet<String> = arrays.intersection(&shared).cloned().collect();
    let mut sharer = TrigShare {
        names: &shared,
        arrays: &shared_arrays,
    };
    for block in blocks.iter_mut() {
        sharer.visit_block_mut(block);
    }

    let hoisted = hoister.hoisted.iter().map(|(name, expr, used)| {
        let used = used.iter().map(|n| ident(n));
        quote!(let #name: #scalar = <#scalar>::from({ #( let #used: f64 = self.#used; )* #expr });)
    });
    let sincos = shared.iter().map(|name| {
        let name = ident(name);
        if arrays.contains(&name.to_string()) {
            let table = format_ident!("__sin_cos_{}", name);
            return quote!(let #table = #name.map(|__x| __x.sin_cos()););
        }
        let (s, c) = (
            format_ident!("__sin_{}", name),
            format_ident!("__cos_{}", name),
        );
        quote!(let (#s, #c) = #name.sin_cos();)
    });
    quote!(#(#hoisted)* #(#sincos)*)
}

/// The identifier a name was read from: `r#type` (a raw identifier, as `Ident::to_string` writes
/// it) becomes a raw identifier again. `format_ident!` drops the `r#` of an `Ident` argument, so
/// `__sin_{}` of it is `__sin_type`.
fn ident(name: &str) -> Ident {
    match name.strip_prefix("r#") {
        Some(raw) => Ident::new_raw(raw, Span::call_site()),
        None => Ident::new(name, Span::call_site()),
    }
}

/// Names bound by patterns inside the bodies.
#[derive(Default)]
struct Bound(BTreeSet<String>);

impl<'ast> Visit<'ast> for Bound {
    fn visit_pat_ident(&mut self, p: &'ast syn::PatIdent) {
        self.0.insert(p.ident.to_string());
        visit::visit_pat_ident(self, p);
    }
    fn visit_item(&mut self, _: &'ast syn::Item) {}
}

/// A single-segment path's identifier.
fn single_ident(expr: &Expr) -> Option<&Ident> {
    match crate::ast::ungroup(expr) {
        Expr::Path(p) if p.qself.is_none() && p.attrs.is_empty() => p.path.get_ident(),
        _ => None,
    }
}

/// Whether `expr` is made of parameters, literals, arithmetic and [`PURE_METHODS`] only; collects
/// the parameters it names.
fn parameter_only(expr: &Expr, params: &BTreeSet<String>, used: &mut BTreeSet<String>) -> bool {
    match expr {
        Expr::Lit(ExprLit {
            lit: Lit::Float(_) | Lit::Int(_),
            ..
        }) => true,
        Expr::Path(_) => match single_ident(expr) {
            Some(ident) if params.contains(&ident.to_string()) => {
                used.insert(ident.to_string());
                true
            }
            _ => false,
        },
        Expr::Paren(p) => parameter_only(&p.expr, params, used),
        Expr::Group(g) => parameter_only(&g.expr, params, used),
        Expr::Unary(u) if matches!(u.op, UnOp::Neg(_)) => parameter_only(&u.expr, params, used),
        Expr::Binary(b)
            if matches!(
                b.op,
                BinOp::Add(_) | BinOp::Sub(_) | BinOp::Mul(_) | BinOp::Div(_)
            ) =>
        {
            parameter_only(&b.left, params, used) && parameter_only(&b.right, params, used)
        }
        Expr::MethodCall(m)
            if m.turbofish.is_none() && PURE_METHODS.contains(&m.method.to_string().as_str()) =>
        {
            parameter_only(&m.receiver, params, used)
                && m.args.iter().all(|a| parameter_only(a, params, used))
        }
        _ => false,
    }
}

/// Replaces maximal parameter-only subexpressions that name a parameter and do some work by
/// `__param_k`.
struct Hoister<'a> {
    params: &'a BTreeSet<String>,
    hoisted: Vec<(Ident, Expr, BTreeSet<String>)>,
    by_text: BTreeMap<String, Ident>,
}

impl VisitMut for Hoister<'_> {
    fn visit_expr_mut(&mut self, expr: &mut Expr) {
        let mut used = BTreeSet::new();
        let works = matches!(expr, Expr::Binary(_) | Expr::MethodCall(_) | Expr::Unary(_));
        if works && parameter_only(expr, self.params, &mut used) && !used.is_empty() {
            let text = expr.to_token_stream().to_string();
            let ident = match self.by_text.get(&text) {
                Some(ident) => ident.clone(),
                None => {
                    let ident = format_ident!("__param_{}", self.hoisted.len());
                    self.hoisted.push((ident.clone(), expr.clone(), used));
                    self.by_text.insert(text, ident.clone());
                    ident
                }
            };
            *expr = syn::parse_quote!(#ident);
            return;
        }
        visit_mut::visit_expr_mut(self, expr);
    }
    fn visit_item_mut(&mut self, _: &mut syn::Item) {}
}

/// `name.sin()` / `name.cos()` (no arguments) with `name` in `names`, or `array[k].sin()` with
/// `array` in `arrays`: `(name, method, k)`.
fn trig_call<'e>(
    expr: &'e Expr,
    names: &BTreeSet<String>,
    arrays: &BTreeSet<String>,
) -> Option<(String, &'e Ident, Option<&'e Expr>)> {
    let Expr::MethodCall(m) = expr else {
        return None;
    };
    if !m.args.is_empty() || m.turbofish.is_some() || !(m.method == "sin" || m.method == "cos") {
        return None;
    }
    if let Expr::Index(index) = crate::ast::ungroup(&m.receiver) {
        let name = single_ident(&index.expr)?.to_string();
        return arrays
            .contains(&name)
            .then_some((name, &m.method, Some(&*index.index)));
    }
    let name = single_ident(&m.receiver)?.to_string();
    names.contains(&name).then_some((name, &m.method, None))
}

struct TrigCalls<'a> {
    names: &'a BTreeSet<String>,
    arrays: &'a BTreeSet<String>,
    /// Per name: whether `sin`, `cos` are called.
    seen: BTreeMap<String, (bool, bool)>,
}

impl<'ast> Visit<'ast> for TrigCalls<'_> {
    fn visit_expr(&mut self, expr: &'ast Expr) {
        if let Some((name, method, _)) = trig_call(expr, self.names, self.arrays) {
            let entry = self.seen.entry(name).or_default();
            if method == "sin" {
                entry.0 = true;
            } else {
                entry.1 = true;
            }
        }
        visit::visit_expr(self, expr);
    }
    fn visit_item(&mut self, _: &'ast syn::Item) {}
}

struct TrigShare<'a> {
    /// Names whose `sin` and `cos` are both called.
    names: &'a BTreeSet<String>,
    arrays: &'a BTreeSet<String>,
}

impl VisitMut for TrigShare<'_> {
    fn visit_expr_mut(&mut self, expr: &mut Expr) {
        let replacement = match trig_call(expr, self.names, self.arrays) {
            Some((name, method, Some(index))) => {
                let table = format_ident!("__sin_cos_{}", ident(&name));
                let half = if method == "sin" {
                    quote!(0)
                } else {
                    quote!(1)
                };
                let mut index = index.clone();
                self.visit_expr_mut(&mut index);
                Some(syn::parse_quote!(#table[#index].#half))
            }
            Some((name, method, None)) => {
                let ident = format_ident!("__{}_{}", method, ident(&name));
                Some(syn::parse_quote!(#ident))
            }
            None => None,
        };
        if let Some(replacement) = replacement {
            *expr = replacement;
            return;
        }
        visit_mut::visit_expr_mut(self, expr);
    }
    fn visit_item_mut(&mut self, _: &mut syn::Item) {}
}

#[cfg(test)]
mod tests {
    use super::*;

    fn names(list: &[&str]) -> BTreeSet<String> {
        list.iter().map(|s| s.to_string()).collect()
    }

    #[test]
    fn hoists_parameters_and_shares_sin_cos() {
        let params = names(&["alpha", "l1", "l2"]);
        let trig = names(&["theta", "phi"]);
        let mut blocks: Vec<syn::Block> = vec![
            syn::parse_quote!({ vec2(theta.sin(), -theta.cos()) * l1 }),
            syn::parse_quote!({ vec2(phi.sin() * alpha.cos(), l1 * l2 + alpha.cos()) }),
        ];
        let lets = optimize(
            &mut blocks,
            &Scope {
                params: &params,
                trig: &trig,
                arrays: &BTreeSet::new(),
            },
            &quote!(__D),
        );
        let text = |b: &syn::Block| b.to_token_stream().to_string();
        assert_eq!(
            text(&blocks[0]),
            "{ vec2 (__sin_theta , - __cos_theta) * l1 }"
        );
        assert_eq!(
            text(&blocks[1]),
            "{ vec2 (phi . sin () * __param_0 , __param_1) }"
        );
        assert_eq!(
            lets.to_string(),
            "let __param_0 : __D = < __D > :: from ({ let alpha : f64 = self . alpha ; alpha . cos () }) ; \
             let __param_1 : __D = < __D > :: from ({ let alpha : f64 = self . alpha ; let l1 : f64 = self . l1 ; let l2 : f64 = self . l2 ; l1 * l2 + alpha . cos () }) ; \
             let (__sin_theta , __cos_theta) = theta . sin_cos () ;"
        );
    }

    #[test]
    fn shadowed_names_are_left_alone() {
        let params = names(&["a"]);
        let trig = names(&["q"]);
        let mut blocks: Vec<syn::Block> = vec![syn::parse_quote!({
            let a = q * 2.0;
            let q = a;
            a.sin() + q.sin() * q.cos()
        })];
        let before = blocks[0].to_token_stream().to_string();
        let lets = optimize(
            &mut blocks,
            &Scope {
                params: &params,
                trig: &trig,
                arrays: &BTreeSet::new(),
            },
            &quote!(__D),
        );
        assert!(lets.is_empty());
        assert_eq!(blocks[0].to_token_stream().to_string(), before);
    }

    #[test]
    fn an_array_shares_only_when_both_sin_and_cos_are_called() {
        // `phi[i].cos()` alone keeps its call (a table bound for it alone was a name without a
        // binding: the rewrite took every array, the table only the shared ones); `theta`'s sin
        // and cos share one table.
        let arrays = names(&["theta", "phi"]);
        let mut blocks: Vec<syn::Block> = vec![syn::parse_quote!({
            vec2(theta[i].sin() * phi[i].cos(), -theta[i].cos())
        })];
        let lets = optimize(
            &mut blocks,
            &Scope {
                params: &BTreeSet::new(),
                trig: &BTreeSet::new(),
                arrays: &arrays,
            },
            &quote!(__D),
        );
        assert_eq!(
            blocks[0].to_token_stream().to_string(),
            "{ vec2 (__sin_cos_theta [i] . 0 * phi [i] . cos () , - __sin_cos_theta [i] . 1) }"
        );
        assert_eq!(
            lets.to_string(),
            "let __sin_cos_theta = theta . map (| __x | __x . sin_cos ()) ;"
        );
    }
}
