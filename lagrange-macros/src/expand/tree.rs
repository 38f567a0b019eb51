//! Expansion of a tree of translations (see [`crate::structure`]): one generic function per distinct
//! displacement, and the `Tree` impl that seeds each body (or family member) on its own coordinates.

use crate::check::{family_index, Dim, Model};
use crate::expand::{lit, position_type, prelude, private, scalar};
use crate::optimize;
use crate::structure::{Displacement, Tree, TreeBody};
use proc_macro2::{Ident, Literal, TokenStream};
use quote::{format_ident, quote};
use std::collections::BTreeSet;

/// The displacement functions and `impl Tree<N, K, W, B>`.
pub fn tree_items(model: &Model, tree: &Tree) -> TokenStream {
    let p = private();
    let params = model.params_ident;
    let (n, k, w) = (lit(model.dof()), lit(model.rows), lit(tree.width));
    let functions = tree
        .functions
        .iter()
        .enumerate()
        .map(|(f, displacement)| displacement_fn(model, f, displacement));

    let mut rows = vec![quote!(); model.rows];
    let mut bodies = Vec::new();
    let mut calls = Vec::new();
    for (b, own) in tree.bodies.iter().enumerate() {
        let body = &model.bodies[own.body];
        let local = format_ident!("__body_{}", b);
        let function = function_name(model, own.function, &tree.functions[own.function]);
        let member = own.member.map(|m| {
            let m = lit(m);
            quote!(#m,)
        });
        let slots = own.slots.iter().enumerate().map(|(j, c)| {
            let (c, j) = (lit(*c), lit(j));
            quote!(#p::tree::seed(__q[#c], __v[#c], #j))
        });
        let time = match own.names_time {
            true => {
                let j = lit(own.slots.len());
                quote!(#p::tree::time(__t, #p::core::option::Option::Some(#j)))
            }
            false => quote!(#p::tree::time(__t, #p::core::option::Option::None)),
        };
        calls.push(quote!(let #local = self.#function(#member #time, #(#slots),*);));
        let components = components(body.shape.dim());
        let first = body.row + own.member.unwrap_or(0) * components.len();
        for (c, component) in components.iter().enumerate() {
            rows[first + c] = quote!(#local.#component);
        }
        let (row, dim) = (lit(first), lit(components.len()));
        let parent = match own.parent {
            Some(parent) => {
                let parent = lit(parent);
                quote!(#p::core::option::Option::Some(#parent))
            }
            None => quote!(#p::core::option::Option::None),
        };
        let seeds = row_seeds(own, tree.width);
        bodies.push(
            quote!(#p::tree::Body { row: #row, dim: #dim, parent: #parent, seeds: [#(#seeds),*] }),
        );
    }
    let b = lit(bodies.len());
    let mass_matrix = mass_matrix_fn(model, tree, (&n, &k, &w, &b));
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
            #mass_matrix
        }
    }
}

/// Above this many pairs, the default loop over `ANCESTORS` is kept: the straight-line form's
/// code grows with the pairs (a chain's N(N + 1)/2) while its saving, the loop's bookkeeping,
/// shrinks beside the products themselves.
const MAX_WRITTEN_PAIRS: usize = 160;

/// `fn mass_matrix`: one `couple(b, a)` per body and each body above it, with constant indices,
/// so the compiler emits straight-line code for M (see `lagrange_core::tree::couple`).
fn mass_matrix_fn(
    model: &Model,
    tree: &Tree,
    (n, k, w, b): (&Literal, &Literal, &Literal, &Literal),
) -> TokenStream {
    let p = private();
    // Whether anything at or below each body carries mass (children come after their parents).
    let mut massive: Vec<bool> = tree
        .bodies
        .iter()
        .map(|own| model.bodies[own.body].shape.has_mass())
        .collect();
    for b in (0..tree.bodies.len()).rev() {
        if let (true, Some(parent)) = (massive[b], tree.bodies[b].parent) {
            massive[parent] = true;
        }
    }
    let mut pairs = Vec::new();
    for (body, own) in tree.bodies.iter().enumerate() {
        if !massive[body] {
            continue;
        }
        pairs.push((body, body));
        let mut above = own.parent;
        while let Some(a) = above {
            pairs.push((body, a));
            above = tree.bodies[a].parent;
        }
    }
    if pairs.len() > MAX_WRITTEN_PAIRS {
        return quote!();
    }
    let couples = pairs.iter().map(|&(body, above)| {
        let (body, above) = (lit(body), lit(above));
        quote!(#p::tree::couple::<Self, S, #n, #k, #w, #b>(&mut __m, __jacobian, __composite, #body, #above);)
    });
    quote! {
        #[inline(always)]
        fn mass_matrix<S: #p::Scalar>(
            __jacobian: &#p::tree::BodyJacobians<S, #w, #b>,
            __composite: &[f64; #b],
        ) -> #p::nalgebra::SMatrix<S, #n, #n> {
            let mut __m = #p::nalgebra::SMatrix::<S, #n, #n>::zeros();
            #(#couples)*
            __m
        }
    }
}

/// `__lagrange_displacement_bob2`, or `__lagrange_displacement_bob_1` for a body with several
/// (the branches of a family).
fn function_name(model: &Model, f: usize, displacement: &Displacement) -> Ident {
    let body = model.bodies[displacement.body].decl.ident();
    let name = body.to_string();
    let name = name.trim_start_matches("r#");
    if model.bodies[displacement.body].count.is_some() {
        format_ident!("__lagrange_displacement_{}_{}", name, f)
    } else {
        format_ident!("__lagrange_displacement_{}", name)
    }
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
        .slots
        .iter()
        .map(|c| {
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
/// own part, on any scalar, with its coordinates (or the array elements it reads) as arguments; a
/// family's function takes the member's index first.
fn displacement_fn(model: &Model, f: usize, displacement: &Displacement) -> TokenStream {
    let (p, d) = (private(), scalar());
    let body = &model.bodies[displacement.body];
    let name = function_name(model, f, displacement);
    let prelude = prelude();
    let used: BTreeSet<String> = crate::names::free_names(&displacement.block)
        .iter()
        .map(Ident::to_string)
        .collect();
    let params = model
        .params
        .iter()
        .filter(|p| used.contains(&p.ident.to_string()));
    let params = params.map(|p| p.bind_lifted(&d));
    let time = used.contains("t").then(|| quote!(let t = __t;));
    let index = family_index(body.decl).map(|i| quote!(#i: usize,));
    let arguments = &displacement.arguments;
    // Parameter-only subexpressions in f64, sin and cos of an argument shared (see `optimize`).
    let mut blocks = [displacement.block.clone()];
    let param_names = model.scalar_parameter_names();
    let trig: BTreeSet<String> = arguments
        .iter()
        .map(Ident::to_string)
        .chain(std::iter::once("t".to_string()))
        .collect();
    let shared = optimize::optimize(
        &mut blocks,
        &optimize::Scope {
            params: &param_names,
            trig: &trig,
            arrays: &BTreeSet::new(),
        },
        &d,
    );
    let block = crate::lift::lift_block_with_integers(&blocks[0], &d, family_index(body.decl));
    let ty = position_type(body.shape);
    quote! {
        #[inline(always)]
        #[allow(unused_variables, non_snake_case, clippy::all)]
        fn #name<#d: #p::Scalar>(&self, #index __t: #d, #(#arguments: #d),*) -> #ty {
            #prelude
            #(#params)*
            #time
            #shared
            #block
        }
    }
}
