//! The `Drawable` impl: what the declaration looks like — its bodies and points with their poses
//! (laid out as x's rows; a body declared by its frame drawn at that frame), the links its position functions state, the bodies each constraint names — so that
//! `lagrange::animation::Recorder` can draw any declared mechanism.

use super::bodies::flatten;
use super::{lit, private};
use crate::check::{Dim, Model, Shape};
use crate::named_bodies::{constraint_bodies, links, Member};
use proc_macro2::TokenStream;
use quote::quote;
use syn::ext::IdentExt;

/// `lagrange_core::animation`.
fn animation() -> TokenStream {
    let p = private();
    quote!(#p::lagrange_core::animation)
}

/// The `Shape` a body is drawn as.
fn shape(shape: Shape) -> TokenStream {
    let a = animation();
    match shape {
        Shape::Particle(Dim::Two) => quote!(#a::Shape::Particle2),
        Shape::Particle(Dim::Three) => quote!(#a::Shape::Particle3),
        Shape::Point(Dim::Two) => quote!(#a::Shape::Point2),
        Shape::Point(Dim::Three) => quote!(#a::Shape::Point3),
        Shape::Planar => quote!(#a::Shape::Planar),
        Shape::Spatial => quote!(#a::Shape::Spatial),
    }
}

fn body_ref((body, member): Member) -> TokenStream {
    let a = animation();
    let (body, member) = (lit(body), lit(member));
    quote!(#a::BodyRef { body: #body, member: #member })
}

/// `impl Drawable<N> for Params`.
pub(super) fn drawable_impl(model: &Model) -> TokenStream {
    let (p, a) = (private(), animation());
    let (params, n) = (model.params_ident, lit(model.dof()));
    let bodies = model.bodies.iter().map(|b| {
        let name = b.decl.ident().unraw().to_string();
        let (shape, row) = (shape(b.shape), lit(b.row));
        let count = match b.count {
            Some(c) => {
                let c = lit(c);
                quote!(#p::core::option::Option::Some(#c))
            }
            None => quote!(#p::core::option::Option::None),
        };
        quote!(#a::BodyLayout { name: #name, shape: #shape, count: #count, row: #row })
    });
    let links = links(model).into_iter().map(|(from, to)| {
        let (from, to) = (body_ref(from), body_ref(to));
        quote!(#a::Link { from: #from, to: #to })
    });
    let constraints = model
        .constraints
        .iter()
        .zip(constraint_bodies(model))
        .map(|(row, named)| {
            let name = row.decl.ident().unraw().to_string();
            let named = named.into_iter().map(body_ref);
            quote!(#a::ConstraintLayout { name: #name, bodies: &[#(#named),*] })
        });
    // Each body's pose as `Bodies` holds it: x's rows, except that a body declared by its frame
    // is drawn at that frame rather than at its centre of mass and principal axes.
    let poses = model.bodies.iter().flat_map(|b| {
        let name = b.decl.ident();
        flatten(b, &quote!(__bodies.#name))
    });
    quote! {
        impl #a::Drawable<#n> for #params {
            const BODIES: &'static [#a::BodyLayout] = &[#(#bodies),*];
            const LINKS: &'static [#a::Link] = &[#(#links),*];
            const CONSTRAINT_BODIES: &'static [#a::ConstraintLayout] = &[#(#constraints),*];
            fn cartesian_rows(&self, t: f64, q: &[f64; #n], rows: &mut #p::std::vec::Vec<f64>) {
                let __bodies = self.__lagrange_bodies(t, q);
                rows.clear();
                rows.extend_from_slice(&[#(#poses),*]);
            }
        }
    }
}
