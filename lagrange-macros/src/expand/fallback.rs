//! The expansion of a declaration that failed a check: the user's items, stubs for what the rest of
//! their code names, and every error. The stubs are what keeps one mistake at one message: without
//! them, each use of `Coords`, `State` or the parameter struct outside the module would add a rustc
//! error of its own.

use super::bodies::bodies_structs;
use crate::ast::{Field, Mechanism};
use crate::check::Model;
use crate::ctxt;
use proc_macro2::TokenStream;
use quote::quote;
use std::collections::BTreeSet;

/// An unsuffixed integer literal (`3`, not `3usize`).
fn lit(n: usize) -> proc_macro2::Literal {
    proc_macro2::Literal::usize_unsuffixed(n)
}

/// On error: the user's items, stubs for what the rest of their code names (`Coords`, the
/// parameter struct, `State`, a `Mechanism`, `Declaration` and `Drawable` impl that is never
/// run), and every error. So one
/// mistake gives one message, not a cascade of rustc errors about missing items.
pub(crate) fn fallback(
    mechanism: &Mechanism,
    model: Option<&Model>,
    errors: Vec<syn::Error>,
) -> TokenStream {
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
    let coords_items = coords_stub(mechanism, &coords);
    let params = mechanism.params.as_ref().map(|(s, _)| {
        let s = params_struct(s);
        let bodies = model
            .filter(|m| bodies_are_unique(m))
            .map(|model| bodies_stub(model, &s.ident));
        let impls = trait_stubs(&s.ident, &n);
        quote! {
            #s
            #bodies
            #impls
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

/// The parameter struct as written, without its `cfg`s and with each field once.
fn params_struct(s: &syn::ItemStruct) -> syn::ItemStruct {
    let mut s = s.clone();
    s.attrs.retain(|a| !is_cfg(a));
    if let syn::Fields::Named(named) = &mut s.fields {
        let mut seen = BTreeSet::new();
        named.named = named
            .named
            .clone()
            .into_iter()
            .filter(|f| seen.insert(f.ident.clone()))
            .collect();
        named
            .named
            .iter_mut()
            .for_each(|f| f.attrs.retain(|a| !is_cfg(a)));
    }
    s
}

/// `Bodies`, `BodyVelocities` and the parameter struct's `bodies` and `body_velocities`, never run.
fn bodies_stub(model: &Model, ident: &syn::Ident) -> TokenStream {
    let unreachable = unreachable();
    let structs = bodies_structs(model);
    quote! {
        #structs
        impl #ident {
            pub fn bodies(&self, state: &State) -> Bodies { #unreachable }
            pub fn body_velocities(&self, state: &State) -> BodyVelocities { #unreachable }
        }
    }
}

/// The `Prepare`, `Dynamics`, `Declaration` and `Drawable` impls, never run.
fn trait_stubs(ident: &syn::Ident, n: &proc_macro2::Literal) -> TokenStream {
    let p = quote!(::lagrange::__private);
    let unreachable = unreachable();
    quote! {
        impl #p::Prepare for #ident {
            type Prepared = ();
            fn prepare(&self) -> #p::Result<()> { #unreachable }
        }
        impl #p::Dynamics<#n> for #ident {
            type Coords = Coords;
            type Contacts = #p::lagrange_core::constraints::NoContacts;
            fn check_parameters(&self) -> #p::Result<()> { #unreachable }
            fn equations_of_motion_at<S: #p::Scalar>(&self, prepared: #p::core::option::Option<&()>, t: S, q: &[S; #n], v: &[S; #n]) -> #p::dynamics::EquationsOfMotion<S, #n> { #unreachable }
            fn kinetic_energy_at<S: #p::Scalar>(&self, prepared: #p::core::option::Option<&()>, t: S, q: &[S; #n], v: &[S; #n]) -> S { #unreachable }
            fn potential_energy_at<S: #p::Scalar>(&self, prepared: #p::core::option::Option<&()>, t: S, q: &[S; #n]) -> S { #unreachable }
            fn momenta_at<S: #p::Scalar>(&self, prepared: #p::core::option::Option<&()>, t: S, q: &[S; #n], v: &[S; #n]) -> [S; #n] { #unreachable }
            fn lagrangian_time_derivative_at(&self, prepared: #p::core::option::Option<&()>, t: f64, q: &[f64; #n], v: &[f64; #n]) -> f64 { #unreachable }
        }
        impl #p::lagrange_core::declaration::Declaration for #ident {
            const DOF: usize = #n;
            const PARAMETERS: &'static [&'static str] = &[];
            fn from_parameters(values: &[f64]) -> #p::core::option::Option<Self> { #unreachable }
            fn parameters(&self) -> #p::std::vec::Vec<f64> { #unreachable }
        }
        impl #p::lagrange_core::animation::Drawable<#n> for #ident {
            const BODIES: &'static [#p::lagrange_core::animation::BodyLayout] = &[];
            const LINKS: &'static [#p::lagrange_core::animation::Link] = &[];
            const CONSTRAINT_BODIES: &'static [#p::lagrange_core::animation::ConstraintLayout] = &[];
            fn cartesian_rows(&self, t: f64, q: &[f64; #n], rows: &mut #p::std::vec::Vec<f64>) { #unreachable }
        }
    }
}

/// The body of a stub: a panic that says why.
fn unreachable() -> TokenStream {
    quote!(::lagrange::__private::core::unreachable!(
        "this mechanism failed to compile"
    ))
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

/// `#[cfg]` and `#[cfg_attr]` (reported where the macro cannot honour them: not re-emitted, so that
/// rustc does not remove a field the stubs name).
fn is_cfg(attr: &syn::Attribute) -> bool {
    attr.path().is_ident("cfg") || attr.path().is_ident("cfg_attr")
}

/// `Coords<T = f64>` with the fields as written, its `Coordinates` impl (never run), `DOF` and
/// `State`: what code outside the module names. An array whose length the macro could not read
/// keeps the length as written, so the user's own uses of it type-check as they would have.
fn coords_stub(mechanism: &Mechanism, coords: &[Field]) -> TokenStream {
    let p = quote!(::lagrange::__private);
    let n = lit(crate::ast::slot_count(coords));
    let attrs = mechanism
        .coords
        .iter()
        .flat_map(|(s, _)| &s.attrs)
        .filter(|a| !a.path().is_ident("derive") && !is_cfg(a));
    let vis = mechanism
        .coords
        .as_ref()
        .map(|(s, _)| s.vis.clone())
        .unwrap_or(syn::Visibility::Inherited);
    let field_attrs = coords
        .iter()
        .map(|f| f.attrs.iter().filter(|a| !is_cfg(a)).collect::<Vec<_>>());
    let names: Vec<_> = coords.iter().map(|f| &f.ident).collect();
    let types = coords.iter().map(|f| match &f.array {
        Some((len, _)) => quote!([T; #len]),
        None => quote!(T),
    });
    let defaults = coords.iter().map(|f| match &f.array {
        Some(_) => quote!(#p::core::array::from_fn(|_| T::default())),
        None => quote!(T::default()),
    });
    let unreachable = quote!(#p::core::unreachable!("this mechanism failed to compile"));
    // `struct Coords {}` (reported): `T` is still used.
    let marker = coords
        .is_empty()
        .then(|| quote!(#[doc(hidden)] pub __scalar: #p::core::marker::PhantomData<T>,));
    let marker_default = coords
        .is_empty()
        .then(|| quote!(__scalar: #p::core::marker::PhantomData,));
    quote! {
        #(#attrs)*
        #[derive(#p::core::clone::Clone, #p::core::marker::Copy, #p::core::fmt::Debug, #p::core::cmp::PartialEq)]
        #vis struct Coords<T = f64> {
            #( #(#field_attrs)* pub #names: #types, )*
            #marker
        }
        impl<T: #p::core::default::Default> #p::core::default::Default for Coords<T> {
            fn default() -> Self {
                Coords { #(#names: #defaults,)* #marker_default }
            }
        }
        impl #p::Coordinates<#n> for Coords<f64> {
            const NAMES: [&'static str; #n] = [""; #n];
            fn to_array(&self) -> [f64; #n] { #unreachable }
            fn from_array(values: [f64; #n]) -> Self { #unreachable }
        }
        pub const DOF: usize = #n;
        pub type State = #p::State<Coords>;
    }
}
