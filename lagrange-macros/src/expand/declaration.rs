//! The `Declaration` impl: the parameters' names and flat values, the degrees of freedom, the
//! inputs' names and the constraint rows, for code generic over declarations (the C export).

use super::{lit, private};
use crate::check::Model;
use proc_macro2::TokenStream;
use quote::quote;
use syn::ext::IdentExt;

/// `impl Declaration for Params`: names in declaration order (the inputs' are their `Inputs`
/// impl's); constraint forces through `flat_constraint_forces` when constraints are declared,
/// with the inputs held when inputs are declared too.
pub(super) fn declaration_impl(model: &Model) -> TokenStream {
    let p = private();
    let declaration = quote!(#p::lagrange_core::declaration);
    let (params, n) = (model.params_ident, lit(model.dof()));
    // Flat, one entry per value: an array of parameters by element (`m[0]`, `m[1]`, ...).
    let (mut names, mut values, mut inits) = (Vec::new(), Vec::new(), Vec::new());
    let mut slot = 0;
    for f in model.params {
        let ident = &f.ident;
        let name = ident.unraw().to_string();
        match &f.array {
            Some((_, len)) => {
                let elements = (slot..slot + len).map(lit);
                inits.push(quote!(#ident: [#(values[#elements]),*]));
                for k in 0..*len {
                    names.push(format!("{name}[{k}]"));
                    let k = lit(k);
                    values.push(quote!(self.#ident[#k]));
                }
            }
            None => {
                let at = lit(slot);
                inits.push(quote!(#ident: values[#at]));
                names.push(name);
                values.push(quote!(self.#ident));
            }
        }
        slot += f.slots();
    }
    let inputs = model
        .inputs_ident
        .zip(model.input_count())
        .map(|(ident, count)| (ident, lit(count)));
    let input_names = inputs.as_ref().map(|(ident, nu)| {
        quote! {
            const INPUTS: &'static [&'static str] = &<#ident as #p::lagrange_core::inputs::Inputs<#nu>>::NAMES;
        }
    });
    let constraints = (!model.constraints.is_empty()).then(|| {
        let (k, c) = (lit(model.rows), lit(model.constraint_row_count()));
        let rows = model.constraints.iter().map(|r| r.decl.ident().unraw().to_string());
        let forces = match &inputs {
            Some((_, nu)) => quote! {
                let __held = #p::lagrange_core::inputs::WithInputs::<'_, Self, f64, #nu>::held(self, inputs);
                #declaration::flat_constraint_forces::<_, #n, #k, #c>(&__held, t, q, v)
            },
            None => quote! {
                let _ = inputs;
                #declaration::flat_constraint_forces::<Self, #n, #k, #c>(self, t, q, v)
            },
        };
        quote! {
            const CONSTRAINT_ROWS: &'static [&'static str] = &[#(#rows),*];
            fn constraint_forces(&self, inputs: &[f64], t: f64, q: &[f64], v: &[f64]) -> #p::Result<#declaration::FlatConstraintForces> {
                #forces
            }
        }
    });
    quote! {
        impl #declaration::Declaration for #params {
            const DOF: usize = #n;
            const PARAMETERS: &'static [&'static str] = &[#(#names),*];
            #input_names
            fn from_parameters(values: &[f64]) -> #p::core::option::Option<Self> {
                if values.len() != Self::PARAMETERS.len() {
                    return #p::core::option::Option::None;
                }
                #p::core::option::Option::Some(#params { #(#inits),* })
            }
            fn parameters(&self) -> #p::std::vec::Vec<f64> {
                #p::std::vec![#(#values),*]
            }
            #constraints
        }
    }
}
