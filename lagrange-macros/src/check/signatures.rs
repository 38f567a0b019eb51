//! A declaration function's signature: its arguments, generics, qualifiers and return type.

use super::model::Dim;
use crate::ast::Decl;
use crate::ctxt::Ctxt;
use crate::names;
use syn::{Signature, Type};

/// A marked function takes no arguments (or a family member's index), no generics, no `return`, and
/// is a plain `fn`: its body is spliced into generated code, generic over the scalar.
pub(super) fn check_signature(cx: &Ctxt, decl: &Decl) {
    if decl.args.count.is_some() {
        check_family_takes_its_index(cx, &decl.sig);
    } else {
        check_no_arguments(cx, &decl.sig);
    }
    check_not_generic(cx, &decl.sig);
    check_no_return(cx, decl);
    check_plain_fn(cx, &decl.sig);
}

/// A family member is a function of its index: `#[particle(mass = m, count = N)] fn bob() -> Vec2`
/// has none, and takes nothing else.
fn check_family_takes_its_index(cx: &Ctxt, sig: &Signature) {
    let is_index = |arg: &syn::FnArg| {
        matches!(arg, syn::FnArg::Typed(t)
            if matches!(&*t.pat, syn::Pat::Ident(p) if p.by_ref.is_none() && p.mutability.is_none() && p.subpat.is_none())
            && matches!(crate::ast::ungroup_type(&t.ty), Type::Path(p) if p.qself.is_none() && p.path.is_ident("usize")))
    };
    if sig.inputs.len() != 1 || !sig.inputs.first().is_some_and(is_index) {
        let message = "a family's function takes its member's index: `fn name(i: usize)`";
        if sig.inputs.is_empty() {
            cx.error_spanned_by(&sig.ident, message);
        } else {
            cx.error_spanned_by(&sig.inputs, message);
        }
    }
}

/// Coordinates, parameters and `t` are in scope by name, so a function takes no arguments:
/// `fn bob(theta: f64) -> Vec2` would have no caller to pass `theta`.
fn check_no_arguments(cx: &Ctxt, sig: &Signature) {
    if !sig.inputs.is_empty() {
        cx.error_spanned_by(
            &sig.inputs,
            "declaration functions take no arguments: coordinates, parameters and `t` are in scope by name",
        );
    }
}

/// The macro makes each function generic over the scalar (to differentiate it), so it declares no
/// generics of its own: `fn bob<T>() -> Vec2`.
fn check_not_generic(cx: &Ctxt, sig: &Signature) {
    if !sig.generics.params.is_empty() || sig.generics.where_clause.is_some() {
        cx.error_spanned_by(
            &sig.generics,
            "declaration functions are not generic: the macro makes them generic over the scalar",
        );
    }
}

/// The body is spliced into generated code, where a `return` would leave the generated function:
/// `fn bob() -> Vec2 { return vec2(x, y); }` writes the value last instead.
fn check_no_return(cx: &Ctxt, decl: &Decl) {
    if let Some(token) = names::first_return(&decl.block) {
        cx.error_spanned_by(
            token,
            "write the value as the function's last expression: `return` is not supported here",
        );
    }
}

/// The body is spliced into a plain function: `async fn`, `const fn` and `unsafe fn` qualifiers
/// would be lost or wrong there.
fn check_plain_fn(cx: &Ctxt, sig: &Signature) {
    if let Some(token) = sig
        .asyncness
        .as_ref()
        .map(|t| t.span)
        .or(sig.constness.map(|t| t.span))
        .or(sig.unsafety.map(|t| t.span))
    {
        cx.error_at(token, "declaration functions are plain `fn`s");
    }
}

/// The last segment of a return type, if it is a plain name (`Vec2`, `lagrange::Vec2`).
pub(super) fn return_type_name(decl: &Decl) -> Option<String> {
    match crate::ast::ungroup_type(decl.output()?) {
        Type::Path(p) if p.qself.is_none() => {
            let last = p.path.segments.last()?;
            last.arguments.is_none().then(|| last.ident.to_string())
        }
        _ => None,
    }
}

/// The return type is one of `expected` (the types the expansion generates code for), else it is
/// reported at the return type, or at the signature if there is none. Returns it when it is.
pub(super) fn expect_return_type(
    cx: &Ctxt,
    decl: &Decl,
    expected: &[&str],
    why: &str,
) -> Option<String> {
    let name = return_type_name(decl).filter(|n| expected.contains(&n.as_str()));
    if name.is_none() {
        let list = expected
            .iter()
            .map(|e| format!("`{e}`"))
            .collect::<Vec<_>>()
            .join(" or ");
        let message = format!("`#[{}]` returns {why}: {list}", decl.kind().name());
        match decl.output() {
            Some(ty) => cx.error_spanned_by(ty, message),
            None => cx.error_spanned_by(&decl.sig, format!("missing return type; {message}")),
        }
    }
    name
}

/// The dimension of a vector type checked by [`expect_return_type`]: the plane's unless `Vec3`.
pub(super) fn vector_dim(name: Option<String>) -> Dim {
    if name.as_deref() == Some("Vec3") {
        Dim::Three
    } else {
        Dim::Two
    }
}
