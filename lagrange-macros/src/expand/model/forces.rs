//! The applied forces (`applied_forces`, `applied_forces_with`): each declared force, torque or
//! generalized force evaluated and added to the Cartesian rows it acts on or to its coordinate's
//! slot.

use super::super::{
    bind_bodies, bind_coordinates, bind_inputs_from, lit, optimized_blocks_from, position_type,
    prelude, private, Params,
};
use crate::attr::Kind;
use crate::check::{self, Dim, Force, Model, Shape};
use proc_macro2::{Ident, TokenStream};
use quote::{format_ident, quote};

/// The applied forces: `applied_forces` with the parameters from the fields, `applied_forces_with`
/// from an array (see [`Params`]).
pub(in crate::expand) fn applied_forces_fn(model: &Model, params: Params) -> TokenStream {
    let p = private();
    let (n, k) = (lit(model.dof()), lit(model.rows));
    let prelude = prelude();
    let inputs = bind_inputs_from(
        model,
        &model.names_used_by(model.forces.iter().map(|f| f.decl)),
        quote!(__q),
        params,
    );
    let velocities = bind_coordinates(model, &quote!(__v), "_dot");
    let bodies = bind_bodies(model);
    let names = model.bodies.iter().map(|b| b.decl.ident());
    let body_velocities = model
        .bodies
        .iter()
        .map(|b| format_ident!("{}_dot", b.decl.ident()));
    let (shared, blocks) =
        optimized_blocks_from(model, model.forces.iter().map(|f| &f.decl.block), params);
    let forces = model
        .forces
        .iter()
        .zip(blocks)
        .map(|(force, block)| applied_force(model, force, &block));
    let (name, generics, array) = match params {
        Params::Fields => (quote!(applied_forces), quote!(<__D: #p::Scalar>), quote!()),
        Params::Array => {
            let np = lit(crate::ast::slot_count(model.params));
            (
                quote!(applied_forces_with),
                quote!(<__S: #p::Scalar, __D: #p::Scalar>),
                quote!(__p: &[__S; #np],),
            )
        }
    };
    quote! {
        #[allow(unused_variables, clippy::all)]
        fn #name #generics(
            &self,
            #array
            __t: __D,
            __q: &[__D; #n],
            __v: &[__D; #n],
            __x: &[__D; #k],
            __x_dot: &[__D; #k],
            __cartesian_force: &mut [__D; #k],
            __generalized_force: &mut [__D; #n],
        ) {
            #prelude
            #inputs
            #shared
            #velocities
            #bodies
            let BodyVelocities { #(#names: #body_velocities),* } = self.__lagrange_velocities_from_cartesian(__x, __x_dot);
            #(#forces)*
        }
    }
}

/// One declared force: its value `block` bound to `__<kind>_<name>` and added where it acts.
fn applied_force(model: &Model, force: &Force, block: &syn::Block) -> TokenStream {
    let ident = format_ident!("__{}_{}", force.kind.name(), force.decl.ident());
    match force.kind {
        Kind::Force => force_on_body(model, force, &ident, block),
        // A planar body's angle row carries the torque itself.
        Kind::Torque if model.bodies[force.target].shape == Shape::Planar => {
            let r = lit(model.bodies[force.target].row + 2);
            quote!(let #ident: __D = #block; __cartesian_force[#r] += #ident;)
        }
        Kind::Torque => torque_on_spatial_body(model.bodies[force.target].row, &ident, block),
        _ => {
            let j = lit(force.target);
            quote!(let #ident: __D = #block; __generalized_force[#j] += #ident;)
        }
    }
}

/// A force on a body (or one on each member of a family): its components added to the body's
/// position rows.
fn force_on_body(model: &Model, force: &Force, ident: &Ident, block: &syn::Block) -> TokenStream {
    let body = &model.bodies[force.target];
    let ty = position_type(Shape::Point(body.shape.dim()));
    let components: &[&str] = if body.shape.dim() == Dim::Two {
        &["x", "y"]
    } else {
        &["x", "y", "z"]
    };
    if let (Some(n), Some(index)) = (force.count, check::family_index(force.decl)) {
        // One force per member: member i's rows start at row + i · rows.
        let (first, stride, n) = (lit(body.row), lit(body.shape.rows()), lit(n));
        let adds = components.iter().enumerate().map(|(i, c)| {
            let (i, c) = (lit(i), format_ident!("{}", c));
            quote!(__cartesian_force[#first + #index * #stride + #i] += #ident.#c;)
        });
        quote!(for #index in 0..#n { let #ident: #ty = #block; #(#adds)* })
    } else {
        let adds = components.iter().enumerate().map(|(i, c)| {
            let (r, c) = (lit(body.row + i), format_ident!("{}", c));
            quote!(__cartesian_force[#r] += #ident.#c;)
        });
        quote!(let #ident: #ty = #block; #(#adds)*)
    }
}

/// A spatial body's torque τ (its body rows from `row`) acts on the columns rₖ of its rotation R
/// as the Cartesian forces Fₖ = ½ τ × rₖ: with δrₖ = δφ × rₖ and Σₖ rₖrₖᵀ = I, Σₖ Fₖ·δrₖ = τ·δφ,
/// the virtual work of the torque.
fn torque_on_spatial_body(row: usize, ident: &Ident, block: &syn::Block) -> TokenStream {
    let first = row + 3;
    let p = private();
    let g = quote!(#p::geometry);
    let adds = (0..3).map(|k| {
        let rows: Vec<_> = (0..3).map(|i| lit(first + 3 * k + i)).collect();
        let (r0, r1, r2) = (&rows[0], &rows[1], &rows[2]);
        quote! {
            let __f = #ident.cross(&#g::vec3(__x[#r0], __x[#r1], __x[#r2])) * <__D>::from(0.5);
            __cartesian_force[#r0] += __f.x;
            __cartesian_force[#r1] += __f.y;
            __cartesian_force[#r2] += __f.z;
        }
    });
    quote!(let #ident: #g::Vec3<__D> = #block; #(#adds)*)
}
