//! A declaration's `#[inputs]`: the struct (with what it derives), its `Inputs` impl (names and
//! flat values, zero by default), the mechanism's `Actuated` impl naming it, and the
//! `ActuatedModel` impl whose applied forces read the inputs (see `lagrange_core::inputs`).

use super::model::{applied_forces_fn, Forces};
use super::{lit, private};
use crate::check::Model;
use proc_macro2::TokenStream;
use quote::quote;

/// Every item of the inputs, or nothing for a declaration without `#[inputs]`.
pub(super) fn inputs_items(model: &Model) -> TokenStream {
    let (Some((inputs_struct, fields)), Some(count)) =
        (&model.mechanism.inputs, model.input_count())
    else {
        return TokenStream::new();
    };
    let p = private();
    let (ident, params) = (&inputs_struct.ident, model.params_ident);
    let (n, k, nu) = (lit(model.dof()), lit(model.rows), lit(count));
    // The user's attributes but their derives: the struct derives what `Inputs` needs itself.
    let mut declared = inputs_struct.clone();
    declared.attrs.retain(|a| !a.path().is_ident("derive"));
    let mut names = Vec::new();
    let mut values = Vec::new();
    let mut fields_from = Vec::new();
    let mut slot = 0;
    for f in fields {
        let field = &f.ident;
        match &f.array {
            Some((_, len)) => {
                let slots: Vec<_> = (slot..slot + len).map(lit).collect();
                names.extend((0..*len).map(|i| format!("{field}[{i}]")));
                values.extend((0..*len).map(|i| {
                    let i = lit(i);
                    quote!(self.#field[#i])
                }));
                fields_from.push(quote!(#field: [#(__values[#slots]),*]));
                slot += len;
            }
            None => {
                let i = lit(slot);
                names.push(field.to_string());
                values.push(quote!(self.#field));
                fields_from.push(quote!(#field: __values[#i]));
                slot += 1;
            }
        }
    }
    let forces = applied_forces_fn(model, Forces::WithInputs);
    quote! {
        #[derive(#p::core::clone::Clone, #p::core::marker::Copy, #p::core::fmt::Debug, #p::core::cmp::PartialEq)]
        #declared
        impl #p::core::default::Default for #ident {
            /// Every input zero.
            fn default() -> Self {
                <Self as #p::lagrange_core::inputs::Inputs<#nu>>::from_array([0.0; #nu])
            }
        }
        impl #p::lagrange_core::inputs::Inputs<#nu> for #ident {
            const NAMES: [&'static str; #nu] = [#(#names),*];
            #[inline]
            fn to_array(&self) -> [f64; #nu] {
                [#(#values),*]
            }
            #[inline]
            fn from_array(__values: [f64; #nu]) -> Self {
                #ident { #(#fields_from),* }
            }
        }
        impl #p::lagrange_core::inputs::Actuated<#nu> for #params {
            type Inputs = #ident;
        }
        impl #p::lagrange_core::inputs::ActuatedModel<#n, #k, #nu> for #params {
            #forces
        }
    }
}
