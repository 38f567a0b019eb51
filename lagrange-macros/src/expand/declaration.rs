//! The `Declaration` impl: the parameters' names and flat values, the degrees of freedom and the
//! constraint rows, for code generic over declarations (the C export).

use super::{lit, private};
use crate::check::Model;
use proc_macro2::TokenStream;
use quote::quote;
use syn::ext::IdentExt;

/// `impl Declaration for Params`: names in declaration order; constraint forces through
/// `flat_constraint_forces` when constraints are declared.
pub(super) fn declaration_impl(model: &Model) -> TokenStream {
    let p = private();
    let declaration = quote!(#p::lagrange_core::declaration);
    let (params, n) = (model.params_ident, lit(model.dof()));
    let fields: Vec<_> = model.params.iter().map(|f| &f.ident).collect();
    let names = fields.iter().map(|f| f.unraw().to_string());
    let slots = (0..fields.len()).map(lit);
    let constraints = (!model.constraints.is_empty()).then(|| {
        let (k, c) = (lit(model.rows), lit(model.constraint_row_count()));
        let rows = model.constraints.iter().map(|r| r.decl.ident().unraw().to_string());
        quote! {
            const CONSTRAINT_ROWS: &'static [&'static str] = &[#(#rows),*];
            fn constraint_forces(&self, t: f64, q: &[f64], v: &[f64]) -> #p::Result<#declaration::FlatConstraintForces> {
                #declaration::flat_constraint_forces::<Self, #n, #k, #c>(self, t, q, v)
            }
        }
    });
    quote! {
        impl #declaration::Declaration for #params {
            const DOF: usize = #n;
            const PARAMETERS: &'static [&'static str] = &[#(#names),*];
            fn from_parameters(values: &[f64]) -> #p::core::option::Option<Self> {
                if values.len() != Self::PARAMETERS.len() {
                    return #p::core::option::Option::None;
                }
                #p::core::option::Option::Some(#params { #(#fields: values[#slots]),* })
            }
            fn parameters(&self) -> #p::std::vec::Vec<f64> {
                #p::std::vec![#(self.#fields),*]
            }
            #constraints
        }
    }
}
