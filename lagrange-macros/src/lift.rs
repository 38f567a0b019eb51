//! Lifting a function body to the scalar it is evaluated on: every float literal `1.5` becomes
//! `<__D>::from(1.5)`, keeping its span, except a literal passed directly to a method
//! (`x.powf(1.5)`: num-dual's `powf` takes an `f64`). Integer literals are untouched (`powi(2)`).

use proc_macro2::TokenStream;
use quote::quote_spanned;
use syn::spanned::Spanned;
use syn::visit_mut::{self, VisitMut};
use syn::{Expr, ExprLit, Lit};

/// `block` with its float literals lifted to `scalar`.
pub fn lift_block(block: &syn::Block, scalar: &TokenStream) -> syn::Block {
    let mut block = block.clone();
    Lifter { scalar }.visit_block_mut(&mut block);
    block
}

struct Lifter<'s> {
    scalar: &'s TokenStream,
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

impl VisitMut for Lifter<'_> {
    fn visit_expr_mut(&mut self, expr: &mut Expr) {
        match expr {
            Expr::Lit(ExprLit {
                lit: Lit::Float(lit),
                ..
            }) => {
                let scalar = self.scalar;
                let lifted: TokenStream = quote_spanned!(lit.span()=> <#scalar>::from(#lit));
                *expr = syn::parse2(lifted).expect("a lifted literal is an expression");
            }
            Expr::MethodCall(call) => {
                self.visit_expr_mut(&mut call.receiver);
                for arg in call.args.iter_mut().filter(|a| !is_float_literal(a)) {
                    self.visit_expr_mut(arg);
                }
            }
            _ => visit_mut::visit_expr_mut(self, expr),
        }
    }

    // Nested items are ordinary Rust, not evaluated on the scalar.
    fn visit_item_mut(&mut self, _: &mut syn::Item) {}
}

#[cfg(test)]
mod tests {
    use super::*;
    use quote::{quote, ToTokens};

    #[test]
    fn floats_lift_except_direct_method_arguments() {
        let block: syn::Block = syn::parse_quote!({ x.powf(1.5) * 2.0 + y.powi(2) - x.max(-0.5) });
        let lifted = lift_block(&block, &quote!(__D))
            .into_token_stream()
            .to_string();
        assert_eq!(
            lifted,
            "{ x . powf (1.5) * < __D > :: from (2.0) + y . powi (2) - x . max (- 0.5) }"
        );
    }
}
