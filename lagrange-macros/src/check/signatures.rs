//! A declaration function's signature: its arguments, generics, qualifiers and return type.

use super::model::Dim;
use crate::ast::Decl;
use crate::ctxt::Ctxt;
use crate::names;
use syn::Type;

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

/// Reports a return type that is not one of `expected`, at the return type (or the name if none).
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

pub(super) fn vector_dim(name: Option<String>) -> Dim {
    if name.as_deref() == Some("Vec3") {
        Dim::Three
    } else {
        Dim::Two
    }
}

/// A marked function takes no arguments, no generics, and is a plain `fn`.
pub(super) fn check_signature(cx: &Ctxt, decl: &Decl) {
    let sig = &decl.sig;
    if decl.args.count.is_some() {
        // `#[particle(mass = m, count = N)] fn bob() -> Vec2`: a member is a function of its index.
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
    } else if !sig.inputs.is_empty() {
        // `fn bob(theta: f64) -> Vec2`: coordinates, parameters and `t` are in scope by name.
        cx.error_spanned_by(
            &sig.inputs,
            "declaration functions take no arguments: coordinates, parameters and `t` are in scope by name",
        );
    }
    // `fn bob<T>() -> Vec2`: the scalar type is chosen by the macro.
    if !sig.generics.params.is_empty() || sig.generics.where_clause.is_some() {
        cx.error_spanned_by(
            &sig.generics,
            "declaration functions are not generic: the macro makes them generic over the scalar",
        );
    }
    // `fn bob() -> Vec2 { return vec2(x, y); }`: the body is spliced into generated code.
    if let Some(token) = names::first_return(&decl.block) {
        cx.error_spanned_by(
            token,
            "write the value as the function's last expression: `return` is not supported here",
        );
    }
    // `async fn`, `const fn`, `unsafe fn`, `extern fn`: a plain function body is expected.
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
