//! `Coords<T = f64>`, its `Coordinates` impl, `DOF` and `State`.

use super::{lit, private};
use crate::ast::{Field, Mechanism};
use proc_macro2::{Literal, TokenStream};
use quote::quote;

/// `Coords<T = f64>`, its `Coordinates` impl, `DOF` and `State`.
pub(super) fn coords_items(mechanism: &Mechanism, coords: &[Field]) -> TokenStream {
    let p = private();
    let n = lit(crate::ast::slot_count(coords));
    let coords_struct = coords_struct(mechanism, coords);
    let coordinates_impl = coordinates_impl(coords, &n);
    quote! {
        #coords_struct

        #coordinates_impl

        /// Degrees of freedom: the number of generalized coordinates.
        #[allow(dead_code)]
        pub const DOF: usize = #n;

        /// The state of this mechanism: time, coordinates, velocities.
        #[allow(dead_code)]
        pub type State = #p::State<Coords>;
    }
}

/// `Coords<T = f64>` with the user's attributes, and its `Default`.
fn coords_struct(mechanism: &Mechanism, coords: &[Field]) -> TokenStream {
    let p = private();
    // The user's attributes but their derives: `Coords` derives what it needs itself.
    let attrs = mechanism
        .coords
        .iter()
        .flat_map(|(s, _)| &s.attrs)
        .filter(|a| !a.path().is_ident("derive"));
    let vis = mechanism
        .coords
        .as_ref()
        .map(|(s, _)| s.vis.clone())
        .unwrap_or(syn::Visibility::Inherited);
    let field_attrs = coords.iter().map(|f| &f.attrs);
    let names = coords.iter().map(|f| &f.ident);
    let types = coords.iter().map(|f| match &f.array {
        Some((len, _)) => quote!([T; #len]),
        None => quote!(T),
    });
    // `Default` is derived for scalar fields; arrays longer than 32 have no `Default`, so it is
    // written out when there are arrays.
    let has_arrays = coords.iter().any(|f| f.array.is_some());
    let default_derive = (!has_arrays).then(|| quote!(, #p::core::default::Default));
    let default_impl = has_arrays.then(|| default_impl(coords));
    quote! {
        #(#attrs)*
        #[derive(#p::core::clone::Clone, #p::core::marker::Copy, #p::core::fmt::Debug, #p::core::cmp::PartialEq #default_derive)]
        #vis struct Coords<T = f64> {
            #( #(#field_attrs)* pub #names: #types, )*
        }
        #default_impl
    }
}

/// `Default` for `Coords` with array fields, written out.
fn default_impl(coords: &[Field]) -> TokenStream {
    let p = private();
    let names = coords.iter().map(|f| &f.ident);
    let values = coords.iter().map(|f| match &f.array {
        Some(_) => quote!(#p::core::array::from_fn(|_| T::default())),
        None => quote!(T::default()),
    });
    quote! {
        impl<T: #p::core::default::Default> #p::core::default::Default for Coords<T> {
            fn default() -> Self {
                Coords { #(#names: #values),* }
            }
        }
    }
}

/// The `Coordinates` impl: the names, the flattened values and the values' fields, element by
/// element for arrays, in declaration order.
fn coordinates_impl(coords: &[Field], n: &Literal) -> TokenStream {
    let p = private();
    let mut strings = Vec::new();
    let mut flat = Vec::new();
    let mut rebuilt = Vec::new();
    let mut slot = 0;
    for field in coords {
        let name = &field.ident;
        match &field.array {
            Some((_, len)) => {
                let slots: Vec<_> = (slot..slot + len).map(lit).collect();
                strings.extend((0..*len).map(|k| format!("{name}[{k}]")));
                flat.extend((0..*len).map(|k| {
                    let k = lit(k);
                    quote!(self.#name[#k])
                }));
                rebuilt.push(quote!(#name: [#(values[#slots]),*]));
                slot += len;
            }
            None => {
                let s = lit(slot);
                strings.push(name.to_string());
                flat.push(quote!(self.#name));
                rebuilt.push(quote!(#name: values[#s]));
                slot += 1;
            }
        }
    }
    quote! {
        impl #p::Coordinates<#n> for Coords<f64> {
            const NAMES: [&'static str; #n] = [#(#strings),*];
            #[inline(always)]
            fn to_array(&self) -> [f64; #n] {
                [#(#flat),*]
            }
            #[inline(always)]
            fn from_array(values: [f64; #n]) -> Self {
                Coords { #(#rebuilt),* }
            }
        }
    }
}
