//! `Model::potential_gradient` and the methods it calls: each part of the potential
//! ([`crate::potentials::potential_parts`]) derived on its expression tree
//! ([`crate::symbolic::gradient`]) where the tree is read, on narrow dual numbers otherwise.

use super::super::{
    bind_bodies, bind_inputs_from, lit, optimized_blocks_from, prelude, private, Params,
};
use crate::check::Model;
use crate::potentials::Part;
use crate::symbolic::gradient::{Gradients, PartGradient};
use proc_macro2::TokenStream;
use quote::{format_ident, quote};

/// `potential_gradient` and the methods of the parts on dual numbers, when
/// [`crate::potentials::own_gradient`] rules that it is written.
pub(super) fn potential_gradient(model: &Model) -> (Option<TokenStream>, Option<TokenStream>) {
    match potential_gradient_plan(model) {
        Some((parts, symbolic)) => (
            Some(potential_gradient_fn(model, &parts, &symbolic)),
            Some(potential_methods(model, &parts, &symbolic)),
        ),
        None => (None, None),
    }
}

/// Whether ∇V is straight-line code read off expression trees: no potential at all (a uniform
/// field is constant weights), or `Model::potential_gradient` written with every part that names
/// a coordinate read as a tree — no part left to dual numbers over the declaration's own code.
pub(in crate::expand) fn gradient_on_trees(model: &Model) -> bool {
    if model.potentials.is_empty() && model.gravities.is_empty() {
        return true;
    }
    potential_gradient_plan(model).is_some_and(|(parts, symbolic)| {
        (0..parts.len()).all(|index| !symbolic.on_duals(&parts, index))
    })
}

/// The parts of the potential, each with its gradient read off its expression tree where the
/// tree is read, when [`crate::potentials::own_gradient`] rules that `potential_gradient` is
/// written.
fn potential_gradient_plan(model: &Model) -> Option<(Vec<Part>, Symbolic)> {
    let parts = crate::potentials::potential_parts(model)?;
    let mut gradients = Gradients::default();
    // A part that names no coordinate adds nothing to the gradient: neither read nor evaluated.
    let read: Vec<Option<PartGradient>> = parts
        .iter()
        .map(|part| {
            (!part.slots.is_empty())
                .then(|| gradients.part(model, &part.block))
                .flatten()
        })
        .collect();
    let is_read: Vec<bool> = read.iter().map(Option::is_some).collect();
    crate::potentials::own_gradient(model, &parts, &is_read)
        .then_some((parts, Symbolic { gradients, read }))
}

/// The parts' gradients taken on their trees (`None` for a part that is not).
struct Symbolic {
    gradients: Gradients,
    read: Vec<Option<PartGradient>>,
}

impl Symbolic {
    /// Whether part `index` is left to dual numbers (and names some coordinate).
    fn on_duals(&self, parts: &[Part], index: usize) -> bool {
        self.read[index].is_none() && !parts[index].slots.is_empty()
    }
}

/// The name of part `index` of the potential (see [`crate::potentials::Part`]).
fn part_method(model: &Model, parts: &[Part], index: usize) -> proc_macro2::Ident {
    let decl = model.potentials[parts[index].potential];
    let term = parts[..index]
        .iter()
        .filter(|p| p.potential == parts[index].potential)
        .count();
    format_ident!("__potential_{}_{}", decl.ident(), term)
}

/// Each part of the potential left to dual numbers (a declared potential, or a term of its sum)
/// as a method of its own on any scalar: what [`potential_gradient_fn`] evaluates on narrow dual
/// numbers.
fn potential_methods(model: &Model, parts: &[Part], symbolic: &Symbolic) -> TokenStream {
    let p = private();
    let (params, n, k) = (model.params_ident, lit(model.dof()), lit(model.rows));
    let prelude = prelude();
    let bodies = bind_bodies(model);
    let on_duals = parts
        .iter()
        .enumerate()
        .filter(|(index, _)| symbolic.on_duals(parts, *index));
    let methods = on_duals.map(|(index, part)| {
        let decl = model.potentials[part.potential];
        let ident = part_method(model, parts, index);
        let inputs = bind_inputs_from(
            model,
            &model.names_used_by([decl]),
            quote!(__q),
            Params::Fields,
        );
        let (shared, blocks) = optimized_blocks_from(model, [&part.block], Params::Fields);
        let block = &blocks[0];
        quote! {
            #[doc(hidden)]
            #[inline(always)]
            #[allow(unused_variables, clippy::all)]
            fn #ident<__D: #p::Scalar>(&self, __t: __D, __q: &[__D; #n], __x: &[__D; #k]) -> __D {
                #prelude
                #inputs
                #shared
                #bodies
                let __value: __D = #block;
                __value
            }
        }
    });
    quote! {
        impl #params {
            #(#methods)*
        }
    }
}

/// `Model::potential_gradient`: the parts read as trees by their derivatives written out
/// ([`crate::symbolic::gradient`]); each other part on dual numbers seeded only on its own
/// coordinate slots (from [`crate::potentials::potential_parts`]), x's rows carrying their
/// Jacobian rows restricted to those slots (a body a part names depends on no other coordinate).
fn potential_gradient_fn(model: &Model, parts: &[Part], symbolic: &Symbolic) -> TokenStream {
    let p = private();
    let (n, k) = (model.dof(), model.rows);
    let (n_lit, k_lit) = (lit(n), lit(k));
    let read: Vec<&PartGradient> = symbolic.read.iter().flatten().collect();
    let trees = (!read.is_empty()).then(|| symbolic.gradients.emit(model, &read, false).0);
    let scaled = scaled_potential_gradient_fn(model, parts, symbolic);
    let terms = parts
        .iter()
        .enumerate()
        .filter(|(index, _)| symbolic.on_duals(parts, *index))
        .map(|(index, part)| {
            let set = &part.slots;
            let ident = part_method(model, parts, index);
            let w = lit(set.len());
            let dual = quote!(#p::num_dual::DualSVec<__S, #w>);
            let seeds = (0..n).map(|j| match set.iter().position(|&s| s == j) {
                Some(a) => {
                    let a = lit(a);
                    quote!(<#dual>::from_re(__q[#j]).derivative(#a))
                }
                None => quote!(<#dual>::from_re(__q[#j])),
            });
            let slots: Vec<_> = set.iter().map(|&s| lit(s)).collect();
            let positions: Vec<_> = (0..set.len()).map(lit).collect();
            quote! {
                {
                    let __qn: [#dual; #n_lit] = [#(#seeds),*];
                    let __xn: [#dual; #k_lit] = #p::core::array::from_fn(|__i| {
                        <#dual>::new(
                            __x[__i],
                            #p::num_dual::Derivative::new(__rows[__i].map(|__r| {
                                #p::nalgebra::SVector::<__S, #w>::from([#(__r[#slots]),*])
                            })),
                        )
                    });
                    let __v = self.#ident(<#dual>::from_re(__t), &__qn, &__xn);
                    if let #p::core::option::Option::Some(__g) = __v.eps.0 {
                        #(__gradient[#slots] += __g[#positions];)*
                    }
                }
            }
        });
    quote! {
        #[inline]
        #[allow(unused_variables, clippy::all)]
        fn potential_gradient<__S: #p::Scalar>(
            &self,
            __t: __S,
            __q: &[__S; #n_lit],
            __x: &[__S; #k_lit],
            __rows: &[#p::core::option::Option<#p::nalgebra::SVector<__S, #n_lit>>; #k_lit],
        ) -> #p::core::option::Option<#p::nalgebra::SVector<__S, #n_lit>> {
            // From −0, the identity of `+` (x + (−0) = x for every x, +0 included; 0 − x = −x
            // likewise from −0): the compiler then drops each slot's first addition instead of
            // adding it to a zero.
            let mut __gradient = #p::nalgebra::SVector::<__S, #n_lit>::repeat(<__S>::from(-0.0));
            #trees
            #(#terms)*
            #p::core::option::Option::Some(__gradient)
        }
        #scaled
    }
}

/// `Model::scaled_potential_gradient`, for affine positions (whose handle solves with a constant
/// M, `lagrange_core::affine`) with every part that names a coordinate read as a tree: each
/// slot's scale joined to the constant factors of its derivatives.
fn scaled_potential_gradient_fn(
    model: &Model,
    parts: &[Part],
    symbolic: &Symbolic,
) -> Option<TokenStream> {
    let all_read = (0..parts.len()).all(|index| !symbolic.on_duals(parts, index));
    if !(crate::affine::is_affine(model) && all_read) {
        return None;
    }
    let p = private();
    let (n, k) = (lit(model.dof()), lit(model.rows));
    let read: Vec<&PartGradient> = symbolic.read.iter().flatten().collect();
    let (trees, coefficients) = match read.is_empty() {
        true => (None, None),
        false => {
            let (trees, coefficients) = symbolic.gradients.emit(model, &read, true);
            (Some(trees), coefficients)
        }
    };
    let count = quote!(#p::lagrange_core::model::GRADIENT_COEFFICIENTS);
    Some(quote! {
        #[inline]
        #[allow(unused_variables, clippy::all)]
        fn gradient_coefficients(&self, __scale: &[f64; #n]) -> [f64; #count] {
            let mut __coefficients = [0.0; #count];
            #coefficients
            __coefficients
        }
        #[inline]
        #[allow(unused_variables, clippy::all)]
        fn scaled_potential_gradient<__S: #p::Scalar>(
            &self,
            __t: __S,
            __q: &[__S; #n],
            __x: &[__S; #k],
            __rows: &[#p::core::option::Option<#p::nalgebra::SVector<__S, #n>>; #k],
            __scale: &[f64; #n],
            __prepared: &[f64; #count],
        ) -> #p::core::option::Option<#p::nalgebra::SVector<__S, #n>> {
            // From −0, as in `potential_gradient`.
            let mut __gradient = #p::nalgebra::SVector::<__S, #n>::repeat(<__S>::from(-0.0));
            #trees
            #p::core::option::Option::Some(__gradient)
        }
    })
}
