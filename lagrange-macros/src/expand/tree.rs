//! Expansion of a tree of translations (see [`crate::structure`]): one generic function per body
//! evaluating its own displacement, and the `Tree` impl that seeds each body on its own coordinates.

use crate::check::{Dim, Model};
use crate::expand::{lit, optimized_blocks, position_type, prelude, private, scalar};
use crate::structure::{Tree, TreeBody};
use proc_macro2::{Ident, TokenStream};
use quote::{format_ident, quote};
use std::collections::BTreeSet;

/// The displacement functions and `impl Tree<N, K, W>`.
pub fn tree_items(model: &Model, tree: &Tree) -> TokenStream {
    let p = private();
    let params = model.params_ident;
    let (n, k, w) = (lit(model.dof()), lit(model.rows), lit(tree.width));
    let functions = model
        .bodies
        .iter()
        .zip(&tree.bodies)
        .map(|(body, own)| displacement_fn(model, body.decl.ident(), body.shape, own));

    let mut rows = vec![quote!(); model.rows];
    let mut bodies = Vec::new();
    let mut calls = Vec::new();
    for (body, own) in model.bodies.iter().zip(&tree.bodies) {
        let name = body.decl.ident();
        let function = displacement_name(name);
        let slots = own.coordinates.iter().enumerate().map(|(j, (_, c))| {
            let (c, j) = (lit(*c), lit(j));
            quote!(#p::tree::seed(__q[#c], __v[#c], #j))
        });
        let time = match own.names_time {
            true => {
                let j = lit(own.coordinates.len());
                quote!(#p::tree::time(__t, #p::core::option::Option::Some(#j)))
            }
            false => quote!(#p::tree::time(__t, #p::core::option::Option::None)),
        };
        calls.push(quote!(let #name = self.#function(#time, #(#slots),*);));
        let components = components(body.shape.dim());
        for (c, component) in components.iter().enumerate() {
            rows[body.row + c] = quote!(#name.#component);
        }
        let (row, dim) = (lit(body.row), lit(components.len()));
        let parent = match own.parent {
            Some(parent) => {
                let parent = lit(parent);
                quote!(#p::core::option::Option::Some(#parent))
            }
            None => quote!(#p::core::option::Option::None),
        };
        let seeds = row_seeds(own, tree.width);
        bodies.push(quote!(#p::tree::Body { row: #row, dim: #dim, parent: #parent, seeds: [#(#seeds),*] }));
    }
    let b = lit(bodies.len());
    quote! {
        impl #params {
            #(#functions)*
        }

        impl #p::tree::Tree<#n, #k, #w, #b> for #params {
            const BODIES: [#p::tree::Body<#w>; #b] = [#(#bodies),*];
            #[inline(always)]
            #[allow(unused_variables, clippy::all)]
            fn displacements<S: #p::Scalar>(&self, __t: S, __q: &[S; #n], __v: &[S; #n]) -> [#p::tree::Seeded<S, #w>; #k] {
                #(#calls)*
                [#(#rows),*]
            }
        }
    }
}

fn displacement_name(body: &Ident) -> Ident {
    format_ident!("__lagrange_displacement_{}", body)
}

fn components(dim: Dim) -> Vec<Ident> {
    let names: &[&str] = match dim {
        Dim::Two => &["x", "y"],
        Dim::Three => &["x", "y", "z"],
    };
    names.iter().map(|c| format_ident!("{}", c)).collect()
}

/// `[Seed::Coordinate(c), …, Seed::Time, Seed::Unused, …]`, `width` long.
fn row_seeds(own: &TreeBody, width: usize) -> Vec<TokenStream> {
    let seed = quote!(::lagrange::__private::tree::Seed);
    let mut out: Vec<TokenStream> = own
        .coordinates
        .iter()
        .map(|(_, c)| {
            let c = lit(*c);
            quote!(#seed::Coordinate(#c))
        })
        .collect();
    if own.names_time {
        out.push(quote!(#seed::Time));
    }
    out.resize(width, quote!(#seed::Unused));
    out
}

/// `fn __lagrange_displacement_bob2<__D>(&self, __t: __D, theta2: __D) -> Vec2<__D>`: the body's
/// own part, on any scalar, with its coordinates as arguments.
fn displacement_fn(
    model: &Model,
    body: &Ident,
    shape: crate::check::Shape,
    own: &TreeBody,
) -> TokenStream {
    let (p, d) = (private(), scalar());
    let name = displacement_name(body);
    let prelude = prelude();
    let used: BTreeSet<String> = crate::names::free_names(&own.displacement)
        .iter()
        .map(Ident::to_string)
        .collect();
    let params = model
        .params
        .iter()
        .map(|p| &p.ident)
        .filter(|p| used.contains(&p.to_string()));
    let time = used.contains("t").then(|| quote!(let t = __t;));
    let coordinates = own.coordinates.iter().map(|(c, _)| c);
    let (shared, blocks) = optimized_blocks(model, std::iter::once(&own.displacement));
    let block = &blocks[0];
    let ty = position_type(shape);
    quote! {
        #[inline(always)]
        #[allow(unused_variables, non_snake_case, clippy::all)]
        fn #name<#d: #p::Scalar>(&self, __t: #d, #(#coordinates: #d),*) -> #ty {
            #prelude
            #( let #params = <#d>::from(self.#params); )*
            #time
            #shared
            #block
        }
    }
}
