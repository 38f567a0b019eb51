//! Lifting a function body to the scalar it is evaluated on, so that it reads as `f64` code:
//!
//! - every float literal `1.5` becomes `<__D>::from(1.5)`, keeping its span, except a literal passed
//!   directly to a method that takes an `f64` (`x.powf(1.5)`, `x.log(2.0)`);
//! - an integer literal in arithmetic or a comparison with a scalar (`x * 2`, `y > 0`) is lifted
//!   the same way; one among integers (`i - 1`, `theta[2 * k]`, `0..N`, `powi(2)`) is untouched. A
//!   name is an integer when it indexes (`theta[i]`), counts a loop over a range, or is bound by a
//!   `let` to an integer;
//! - `f64` written as a type (`|s: f64|`, `let k: f64`) is the scalar, and a cast `n as f64` is
//!   lifted;
//! - `f64` methods dual numbers lack (`max`, `min`, `clamp`, `hypot`, `floor`, …) come from
//!   `lagrange::__private::ScalarExt`, imported into the block when it calls one, and `powf`
//!   with an exponent that is not a literal becomes `pow_scalar` (a parameter is a scalar too).

use proc_macro2::TokenStream;
use quote::quote_spanned;
use std::collections::BTreeSet;
use syn::spanned::Spanned;
use syn::visit::{self, Visit};
use syn::visit_mut::{self, VisitMut};
use syn::{BinOp, Expr, ExprLit, Lit};

/// Methods whose arguments are `f64` on a dual number too: their literal arguments stay `f64`.
const F64_ARGUMENT_METHODS: &[&str] = &["powf", "powi", "log"];
/// `f64` methods provided by `ScalarExt` on the scalar.
const EXT_METHODS: &[&str] = &[
    "max",
    "min",
    "clamp",
    "hypot",
    "to_degrees",
    "to_radians",
    "floor",
    "ceil",
    "round",
    "trunc",
    "pow_scalar",
];

/// `block` with its literals, `f64` types and casts lifted to `scalar`.
pub fn lift_block(block: &syn::Block, scalar: &TokenStream) -> syn::Block {
    lift_block_with_integers(block, scalar, None)
}

/// [`lift_block`] with `integer` known to be an integer whatever the block does with it: a
/// family's index in a block rewritten so that it no longer indexes (a tree's displacement, whose
/// `theta[i]` became a local), where `i % 2 == 0` would otherwise compare an integer with a scalar.
pub fn lift_block_with_integers(
    block: &syn::Block,
    scalar: &TokenStream,
    integer: Option<&syn::Ident>,
) -> syn::Block {
    let mut block = block.clone();
    let mut integers = integer_names(&block);
    integers.extend(integer.map(|i| i.to_string()));
    let mut lifter = Lifter {
        scalar,
        integers: &integers,
        in_integer: false,
        uses_ext: false,
    };
    lifter.visit_block_mut(&mut block);
    if lifter.uses_ext {
        let import: syn::Stmt = syn::parse_quote!(
            #[allow(unused_imports)]
            use ::lagrange::__private::ScalarExt as _;
        );
        block.stmts.insert(0, import);
    }
    block
}

struct Lifter<'s> {
    scalar: &'s TokenStream,
    integers: &'s BTreeSet<String>,
    /// Inside an index, a range, a repeat length or an integer `let`: literals stay integers.
    in_integer: bool,
    uses_ext: bool,
}

fn is_float_literal(expr: &Expr) -> bool {
    match expr {
        Expr::Lit(ExprLit {
            lit: Lit::Float(_), ..
        }) => true,
        Expr::Unary(u) if matches!(u.op, syn::UnOp::Neg(_)) => is_float_literal(&u.expr),
        Expr::Paren(p) => is_float_literal(&p.expr),
        Expr::Group(g) => is_float_literal(&g.expr),
        _ => false,
    }
}

fn is_int_literal(expr: &Expr) -> bool {
    matches!(crate::ast::ungroup(expr), Expr::Lit(ExprLit { lit: Lit::Int(i), .. }) if i.suffix().is_empty())
}

/// Whether `expr` is an integer by its shape: integer literals, integer names, integer casts,
/// `.len()`, and arithmetic of those.
fn is_integer(expr: &Expr, integers: &BTreeSet<String>) -> bool {
    match crate::ast::ungroup(expr) {
        Expr::Lit(ExprLit {
            lit: Lit::Int(_), ..
        }) => true,
        Expr::Path(p) => p
            .path
            .get_ident()
            .is_some_and(|i| integers.contains(&i.to_string())),
        Expr::Cast(c) => {
            !matches!(&*c.ty, syn::Type::Path(p) if p.path.is_ident("f64") || p.path.is_ident("f32"))
        }
        Expr::MethodCall(m) => m.method == "len",
        Expr::Paren(p) => is_integer(&p.expr, integers),
        Expr::Unary(u) => is_integer(&u.expr, integers),
        Expr::Binary(b) => is_integer(&b.left, integers) && is_integer(&b.right, integers),
        _ => false,
    }
}

/// Whether `func` is a path that leaves the module (`super::f`, `crate::m::f`, `self::f`): a
/// function whose signature the macro does not see.
fn is_outside_path(func: &Expr) -> bool {
    match crate::ast::ungroup(func) {
        Expr::Path(p) if p.qself.is_none() && p.path.segments.len() > 1 => {
            let first = p.path.segments[0].ident.to_string();
            p.path.leading_colon.is_none() && ["super", "crate", "self"].contains(&first.as_str())
        }
        _ => false,
    }
}

/// `f(a, b)` as `{ let h: fn(_, _) -> _ = f; call_helper((a, b), h) }`, spanned at the call: the
/// function becomes a function pointer of its own signature (a coercion, decided on the spot), and
/// one that does not take the scalar the body runs on lacks the `ScalarHelper` implementation for
/// the arguments — one message at the call that says what to write
/// (`lagrange_core::scalar_ext::ScalarHelper`), instead of type mismatches naming the generated
/// scalar type. A generic helper's pointer takes its types from the arguments.
fn outside_call(call: &syn::ExprCall) -> Expr {
    let (func, args) = (&call.func, call.args.iter());
    let holes = call.args.iter().map(|_| quote::quote!(_));
    let lifted: TokenStream = quote_spanned!(call.span()=> {
        let __lagrange_helper: fn(#(#holes),*) -> _ = #func;
        ::lagrange::__private::call_helper((#(#args,)*), __lagrange_helper)
    });
    syn::parse2(lifted).expect("a helper call is an expression")
}

fn is_f64_type(ty: &syn::Type) -> bool {
    matches!(crate::ast::ungroup_type(ty), syn::Type::Path(p) if p.qself.is_none() && p.path.is_ident("f64"))
}

impl Lifter<'_> {
    fn lift(&self, expr: &Expr) -> Expr {
        let scalar = self.scalar;
        let lifted: TokenStream = quote_spanned!(expr.span()=> <#scalar>::from(#expr));
        syn::parse2(lifted).expect("a lifted expression is an expression")
    }

    /// An integer literal as the float literal it denotes (`2` → `2.0`), lifted when visited.
    fn lift_integer(&self, expr: &Expr) -> Expr {
        match crate::ast::ungroup(expr) {
            Expr::Lit(ExprLit {
                lit: Lit::Int(i), ..
            }) => {
                let float = syn::LitFloat::new(&format!("{}.0", i.base10_digits()), i.span());
                Expr::Lit(ExprLit {
                    attrs: Vec::new(),
                    lit: Lit::Float(float),
                })
            }
            other => other.clone(),
        }
    }

    fn integer_scope(&mut self, f: impl FnOnce(&mut Self)) {
        let outer = std::mem::replace(&mut self.in_integer, true);
        f(self);
        self.in_integer = outer;
    }
}

impl VisitMut for Lifter<'_> {
    fn visit_expr_mut(&mut self, expr: &mut Expr) {
        match expr {
            Expr::Lit(ExprLit {
                lit: Lit::Float(_), ..
            }) => *expr = self.lift(expr),
            // `n as f64`: an integer made a scalar.
            Expr::Cast(c) if is_f64_type(&c.ty) => {
                self.integer_scope(|v| v.visit_expr_mut(&mut c.expr));
                *expr = self.lift(expr);
            }
            // `super::helper(x)`: a function outside the module, through `ScalarHelper`, so a
            // helper that takes `f64` is one message at the call (see `outside_call`).
            Expr::Call(call) if is_outside_path(&call.func) => {
                for arg in call.args.iter_mut() {
                    self.visit_expr_mut(arg);
                }
                *expr = outside_call(call);
            }
            Expr::MethodCall(call) => {
                self.visit_expr_mut(&mut call.receiver);
                let method = call.method.to_string();
                // `x.powf(n)` with a parameter or coordinate exponent: a scalar exponent.
                if method == "powf" && call.args.len() == 1 && !is_float_literal(&call.args[0]) {
                    call.method = syn::Ident::new("pow_scalar", call.method.span());
                }
                let method = call.method.to_string();
                self.uses_ext |= EXT_METHODS.contains(&method.as_str());
                let keep_f64 = F64_ARGUMENT_METHODS.contains(&method.as_str());
                for arg in call.args.iter_mut() {
                    if keep_f64 && (is_float_literal(arg) || is_int_literal(arg)) {
                        continue;
                    }
                    self.visit_expr_mut(arg);
                }
            }
            Expr::Binary(b)
                if !self.in_integer
                    && matches!(
                        b.op,
                        BinOp::Add(_)
                            | BinOp::Sub(_)
                            | BinOp::Mul(_)
                            | BinOp::Div(_)
                            | BinOp::Lt(_)
                            | BinOp::Le(_)
                            | BinOp::Gt(_)
                            | BinOp::Ge(_)
                            | BinOp::Eq(_)
                            | BinOp::Ne(_)
                    ) =>
            {
                // `x * 2`: an integer literal beside a scalar is the scalar.
                let (left_int, right_int) = (is_int_literal(&b.left), is_int_literal(&b.right));
                if left_int && !is_integer(&b.right, self.integers) {
                    *b.left = self.lift_integer(&b.left);
                } else if right_int && !is_integer(&b.left, self.integers) {
                    *b.right = self.lift_integer(&b.right);
                }
                if is_integer(&b.left, self.integers) && is_integer(&b.right, self.integers) {
                    return;
                }
                self.visit_expr_mut(&mut b.left);
                self.visit_expr_mut(&mut b.right);
            }
            Expr::Index(index) => {
                self.visit_expr_mut(&mut index.expr);
                self.integer_scope(|v| v.visit_expr_mut(&mut index.index));
            }
            Expr::Range(_) | Expr::Repeat(_) => {
                self.integer_scope(|v| visit_mut::visit_expr_mut(v, expr))
            }
            _ => visit_mut::visit_expr_mut(self, expr),
        }
    }

    fn visit_local_mut(&mut self, local: &mut syn::Local) {
        let mut names = Names::default();
        names.visit_pat(&local.pat);
        let integer = names.0.iter().any(|n| self.integers.contains(n));
        self.visit_pat_mut(&mut local.pat);
        if let Some(init) = &mut local.init {
            if integer {
                self.integer_scope(|v| v.visit_expr_mut(&mut init.expr));
            } else {
                self.visit_expr_mut(&mut init.expr);
            }
            if let Some((_, diverge)) = &mut init.diverge {
                self.visit_expr_mut(diverge);
            }
        }
    }

    // `|s: f64|`, `let k: f64`: `f64` is the scalar.
    fn visit_type_mut(&mut self, ty: &mut syn::Type) {
        if is_f64_type(ty) {
            let scalar = self.scalar;
            *ty = syn::parse_quote_spanned!(ty.span()=> #scalar);
            return;
        }
        visit_mut::visit_type_mut(self, ty);
    }

    // Nested items are ordinary Rust, not evaluated on the scalar.
    fn visit_item_mut(&mut self, _: &mut syn::Item) {}
}

/// Names a pattern binds.
#[derive(Default)]
struct Names(Vec<String>);

impl<'ast> Visit<'ast> for Names {
    fn visit_pat_ident(&mut self, p: &'ast syn::PatIdent) {
        self.0.push(p.ident.to_string());
        visit::visit_pat_ident(self, p);
    }
}

/// Names that are integers by use: an index (`theta[i]`), a loop over a range, and, until nothing
/// changes, every name in the value of a `let` that binds an integer.
fn integer_names(block: &syn::Block) -> BTreeSet<String> {
    #[derive(Default)]
    struct Uses {
        integers: BTreeSet<String>,
        lets: Vec<(Vec<String>, Vec<String>)>,
    }
    fn idents(expr: &Expr) -> Vec<String> {
        struct Idents(Vec<String>);
        impl<'ast> Visit<'ast> for Idents {
            fn visit_expr_path(&mut self, p: &'ast syn::ExprPath) {
                if let Some(i) = p.path.get_ident() {
                    self.0.push(i.to_string());
                }
            }
            // `theta[i]` inside is an integer only as an index.
            fn visit_expr_index(&mut self, e: &'ast syn::ExprIndex) {
                self.visit_expr(&e.expr);
            }
            fn visit_expr_method_call(&mut self, m: &'ast syn::ExprMethodCall) {
                if m.method == "len" {
                    return;
                }
                visit::visit_expr_method_call(self, m);
            }
        }
        let mut v = Idents(Vec::new());
        v.visit_expr(expr);
        v.0
    }
    impl<'ast> Visit<'ast> for Uses {
        fn visit_expr_index(&mut self, e: &'ast syn::ExprIndex) {
            // The index's own names, not those of arrays indexed inside it.
            self.integers.extend(idents(&e.index));
            visit::visit_expr_index(self, e);
        }
        fn visit_expr_for_loop(&mut self, e: &'ast syn::ExprForLoop) {
            if matches!(crate::ast::ungroup(&e.expr), Expr::Range(_)) {
                let mut names = Names::default();
                names.visit_pat(&e.pat);
                self.integers.extend(names.0);
            }
            visit::visit_expr_for_loop(self, e);
        }
        fn visit_local(&mut self, local: &'ast syn::Local) {
            let mut names = Names::default();
            names.visit_pat(&local.pat);
            if let Some(init) = &local.init {
                self.lets.push((names.0, idents(&init.expr)));
            }
            visit::visit_local(self, local);
        }
        fn visit_item(&mut self, _: &'ast syn::Item) {}
    }
    let mut uses = Uses::default();
    uses.visit_block(block);
    loop {
        let before = uses.integers.len();
        for (bound, used) in &uses.lets {
            if bound.iter().any(|b| uses.integers.contains(b)) {
                uses.integers.extend(used.iter().cloned());
            }
        }
        if uses.integers.len() == before {
            return uses.integers;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use quote::{quote, ToTokens};

    fn lifted(block: syn::Block) -> String {
        lift_block(&block, &quote!(__D))
            .into_token_stream()
            .to_string()
    }

    #[test]
    fn floats_lift_except_direct_f64_method_arguments() {
        assert_eq!(
            lifted(syn::parse_quote!({ x.powf(1.5) * 2.0 + y.powi(2) - x.atan2(-0.5) })),
            "{ x . powf (1.5) * < __D > :: from (2.0) + y . powi (2) - x . atan2 (- < __D > :: from (0.5)) }"
        );
    }

    #[test]
    fn integers_lift_beside_scalars_only() {
        assert_eq!(
            lifted(syn::parse_quote!({ x * 2 + theta[i - 1] * (i as f64) })),
            "{ x * < __D > :: from (2.0) + theta [i - 1] * (< __D > :: from (i as f64)) }"
        );
        // `k` indexes, so `i * 2` that defines it stays an integer.
        assert_eq!(
            lifted(syn::parse_quote!({
                let k = i * 2;
                theta[k]
            })),
            "{ let k = i * 2 ; theta [k] }"
        );
        assert_eq!(
            lifted(syn::parse_quote!({
                if i == 0 {
                    x
                } else {
                    bob[i - 1]
                }
            })),
            "{ if i == 0 { x } else { bob [i - 1] } }"
        );
    }

    #[test]
    fn f64_types_are_the_scalar_and_ext_methods_are_imported() {
        let out = lifted(syn::parse_quote!({
            let f = |s: f64| s * 2.0;
            f(theta).max(0.0)
        }));
        assert!(
            out.starts_with(
                "{ # [allow (unused_imports)] use :: lagrange :: __private :: ScalarExt as _ ;"
            ),
            "{out}"
        );
        assert!(out.contains("| s : __D |"), "{out}");
        assert!(out.contains("max (< __D > :: from (0.0))"), "{out}");
        assert!(lifted(syn::parse_quote!({ x.powf(n) })).contains("pow_scalar"));
    }
}
