//! The expansion of a declaration that failed a check: the user's items, stubs for what the rest of
//! their code names, and every error. The stubs are what keeps one mistake at one message: without
//! them, each use of `Coords`, `State` or the parameter struct outside the module would add a rustc
//! error of its own.

use crate::ast::{Field, Mechanism};
use crate::check::Model;
use crate::ctxt;
use crate::expand::{bodies_structs, coords_items};
use proc_macro2::TokenStream;
use quote::quote;
use std::collections::BTreeSet;

/// An unsuffixed integer literal (`3`, not `3usize`).
fn lit(n: usize) -> proc_macro2::Literal {
    proc_macro2::Literal::usize_unsuffixed(n)
}

/// On error: the user's items, stubs for what the rest of their code names (`Coords`, the
/// parameter struct, `State`, a `Mechanism` impl that is never run), and every error. So one
/// mistake gives one message, not a cascade of rustc errors about missing items.
pub(crate) fn fallback(mechanism: &Mechanism, model: Option<&Model>, errors: Vec<syn::Error>) -> TokenStream {
    let p = quote!(::lagrange::__private);
    let (attrs, vis, ident) = (&mechanism.attrs, &mechanism.vis, &mechanism.ident);
    let other_items = &mechanism.other_items;
    let coords = dedup(
        mechanism
            .coords
            .as_ref()
            .map(|(_, f)| &f[..])
            .unwrap_or_default(),
    );
    let n = lit(crate::ast::slot_count(&coords));
    let coords_items = coords_items(mechanism, &coords);
    let params = mechanism.params.as_ref().map(|(s, _)| {
        let mut s = s.clone();
        if let syn::Fields::Named(named) = &mut s.fields {
            let mut seen = BTreeSet::new();
            named.named = named.named.clone().into_iter().filter(|f| seen.insert(f.ident.clone())).collect();
        }
        let ident = &s.ident;
        let unreachable = quote!(#p::core::unreachable!("this mechanism failed to compile"));
        let bodies = model.filter(|m| bodies_are_unique(m)).map(|model| {
            let structs = bodies_structs(model);
            quote! {
                #structs
                impl #ident {
                    pub fn bodies(&self, state: &State) -> Bodies { #unreachable }
                    pub fn body_velocities(&self, state: &State) -> BodyVelocities { #unreachable }
                }
            }
        });
        quote! {
            #s
            #bodies
            impl #p::Mechanism<#n> for #ident {
                type Coords = Coords;
                fn validate(&self) -> #p::Result<()> { #unreachable }
                fn equations_of_motion_at<S: #p::Scalar>(&self, t: S, q: &[S; #n], v: &[S; #n]) -> #p::dynamics::EquationsOfMotion<S, #n> { #unreachable }
                fn kinetic_energy_at<S: #p::Scalar>(&self, t: S, q: &[S; #n], v: &[S; #n]) -> S { #unreachable }
                fn potential_energy_at<S: #p::Scalar>(&self, t: S, q: &[S; #n]) -> S { #unreachable }
                fn momenta_at<S: #p::Scalar>(&self, t: S, q: &[S; #n], v: &[S; #n]) -> [S; #n] { #unreachable }
                fn lagrangian_time_derivative_at(&self, t: f64, q: &[f64; #n], v: &[f64; #n]) -> f64 { #unreachable }
            }
        }
    });
    let errors = ctxt::to_compile_errors(errors);
    quote! {
        #(#attrs)*
        #[allow(dead_code, unused)]
        #vis mod #ident {
            #(#other_items)*
            #params
            #coords_items
            #errors
        }
    }
}

/// Whether `Bodies` can be written: at least one body, no name twice.
fn bodies_are_unique(model: &Model) -> bool {
    let mut seen = BTreeSet::new();
    !model.bodies.is_empty()
        && model
            .bodies
            .iter()
            .all(|b| seen.insert(b.decl.ident().to_string()))
}

/// Fields with repeated names dropped (the repeat was reported).
fn dedup(fields: &[Field]) -> Vec<Field> {
    let mut seen = BTreeSet::new();
    fields
        .iter()
        .filter(|f| seen.insert(f.ident.to_string()))
        .cloned()
        .collect()
}
