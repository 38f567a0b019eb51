//! `Bodies<T = f64>`, `BodyVelocities<T = f64>` and the inherent impl of the parameter struct:
//! `bodies`, `body_velocities`, the generic `__lagrange_bodies`, and the conversions between bodies
//! and rows of x (flatten, unflatten).

use super::{
    bind_inputs_from, lit, optimized_blocks_from, position_type, prelude, private, Params,
};
use crate::attr::Inertia;
use crate::check::{self, attribute_sets, Body, Dim, Model, Shape};
use proc_macro2::{Ident, TokenStream};
use quote::{format_ident, quote};

/// The type of a body's position and velocity in `Bodies<T>` / `BodyVelocities<T>`.
fn body_types(shape: Shape) -> (TokenStream, TokenStream) {
    let g = quote!(::lagrange::__private::geometry);
    match shape {
        Shape::Particle(Dim::Two) | Shape::Point(Dim::Two) => {
            (quote!(#g::Vec2<T>), quote!(#g::Vec2<T>))
        }
        Shape::Particle(Dim::Three) | Shape::Point(Dim::Three) => {
            (quote!(#g::Vec3<T>), quote!(#g::Vec3<T>))
        }
        Shape::Planar => (quote!(#g::Planar<T>), quote!(#g::Planar<T>)),
        Shape::Spatial => (quote!(#g::Spatial<T>), quote!(#g::SpatialVelocity<T>)),
    }
}

pub(super) fn bodies_structs(model: &Model) -> TokenStream {
    let p = private();
    let names: Vec<&Ident> = model.bodies.iter().map(|b| b.decl.ident()).collect();
    let docs: Vec<Vec<&syn::Attribute>> = model
        .bodies
        .iter()
        .map(|b| {
            b.decl
                .attrs
                .iter()
                .filter(|a| a.path().is_ident("doc"))
                .collect()
        })
        .collect();
    let (positions, velocities): (Vec<_>, Vec<_>) = model
        .bodies
        .iter()
        .map(|b| {
            let (position, velocity) = body_types(b.shape);
            match b.count {
                Some(n) => {
                    let n = lit(n);
                    (quote!([#position; #n]), quote!([#velocity; #n]))
                }
                None => (position, velocity),
            }
        })
        .unzip();
    let derive = quote!(#[derive(#p::core::clone::Clone, #p::core::marker::Copy, #p::core::fmt::Debug, #p::core::cmp::PartialEq)]);
    quote! {
        /// Every body and point of the mechanism, by name: a particle or point's position, a rigid
        /// body's pose as its function returns it (its centre of mass and orientation, or, for a
        /// body declared with its `com`, its frame).
        #derive
        #[allow(dead_code)]
        pub struct Bodies<T = f64> {
            #( #(#docs)* pub #names: #positions, )*
        }

        /// The velocity of every body and point, by name: a particle or point's velocity; for a
        /// planar body, its centre-of-mass velocity and angular velocity (as a `Planar`); for a
        /// spatial body, a `SpatialVelocity` (centre-of-mass and angular velocity, world frame).
        /// For a body declared with its `com`, the velocity of its frame's origin in place of the
        /// centre of mass's.
        #derive
        #[allow(dead_code)]
        pub struct BodyVelocities<T = f64> {
            #( #(#docs)* pub #names: #velocities, )*
        }
    }
}

/// The inherent impl: `bodies`, `body_velocities`, and the private generic body functions.
pub(super) fn inherent_impl(model: &Model) -> TokenStream {
    let p = private();
    let (params, n, k) = (model.params_ident, lit(model.dof()), lit(model.rows));
    let bodies_fn = bodies_fn(model, Params::Fields);
    let from_cartesian = (!model.potentials.is_empty()
        || !model.gravities.is_empty()
        || !model.forces.is_empty()
        || !model.constraints.is_empty())
    .then(|| positions_from_cartesian(model));
    let velocities_from_cartesian = velocities_from_cartesian(model);
    let mass_frames = mass_frame_fns(model);
    quote! {
        impl #params {
            /// Every body and point at `state`, by name.
            #[allow(dead_code)]
            pub fn bodies(&self, state: &State) -> Bodies {
                let q = <Coords as #p::Coordinates<#n>>::to_array(&state.q);
                self.__lagrange_bodies(state.t, &q)
            }

            /// The velocity of every body and point at `state`, by name (one forward-mode pass
            /// along (q̇, 1), q̇ the coordinates' rates at the state's velocities).
            #[allow(dead_code)]
            pub fn body_velocities(&self, state: &State) -> BodyVelocities {
                let q = <Coords as #p::Coordinates<#n>>::to_array(&state.q);
                let v = <Coords as #p::Coordinates<#n>>::to_array(&state.v);
                // The coordinates' rates (the velocities themselves unless some are angular
                // velocities).
                let v = <Self as #p::Dynamics<#n>>::position_rates_at(self, &q, &v);
                let (x, x_dot) = #p::dynamics::cartesian_velocities::<Self, f64, #n, #k>(self, state.t, &q, &v);
                self.__lagrange_velocities_from_cartesian(&x, &x_dot)
            }

            #bodies_fn
            #from_cartesian
            #velocities_from_cartesian
            #mass_frames
        }
    }
}

/// The name of the method that gives a framed body's mass frame ([`mass_frame_fns`]): member k's
/// for a family whose attributes are by member (`member` `Some(k)`).
pub(crate) fn mass_frame_method(body: &Body, member: Option<usize>) -> Ident {
    match member {
        None => format_ident!("__lagrange_mass_frame_{}", body.decl.ident()),
        Some(k) => format_ident!("__lagrange_mass_frame{}_{}", k, body.decl.ident()),
    }
}

/// For each body declared by its frame ([`Body::is_framed`]), `__lagrange_mass_frame_<body>`:
/// where its mass lies in that frame (`lagrange_core::inertia::SpatialMassFrame` or
/// `PlanarMassFrame`), from its `com` and the principal axes of its tensor. The parameters are
/// read as `f64`: a centre of mass and an inertia are constants, never seeded.
fn mass_frame_fns(model: &Model) -> TokenStream {
    let p = private();
    let prelude = prelude();
    let framed = attribute_sets(model.bodies.iter().filter(|b| b.is_framed()));
    let methods = framed.map(|(body, member)| {
        let args = &body.decl.args;
        let method = mass_frame_method(body, member);
        let index = super::model::bind_family_index(body, member);
        let mut used = std::collections::BTreeSet::new();
        for expr in args.com.iter().cloned().chain(args.inertia.as_ref().map(|i| i.expr())) {
            used.extend(crate::names::free_names_of_expr(&expr).iter().map(|i| i.to_string()));
        }
        let params = model.params.iter().filter(|f| used.contains(&f.ident.to_string()));
        let params = params.map(|f| f.bind_f64());
        let (ty, value) = match body.shape {
            Shape::Planar => {
                let com = args.com.as_ref().expect("a framed planar body has a `com`");
                (quote!(#p::inertia::PlanarMassFrame), quote!(#p::inertia::PlanarMassFrame { com: #com }))
            }
            _ => {
                let com = match &args.com {
                    Some(com) => quote!(#p::core::option::Option::Some(#com)),
                    None => quote!(#p::core::option::Option::None),
                };
                let axes = match &args.inertia {
                    Some(Inertia::Tensor(tensor)) => quote!(#p::core::option::Option::Some(#p::inertia::principal_axes(&#tensor).1)),
                    _ => quote!(#p::core::option::Option::None),
                };
                (quote!(#p::inertia::SpatialMassFrame), quote!(#p::inertia::SpatialMassFrame { com: #com, axes: #axes }))
            }
        };
        quote! {
            #[doc(hidden)]
            #[inline(always)]
            #[allow(unused_variables, clippy::all)]
            fn #method(&self) -> #ty {
                #prelude
                #(#params)*
                #index
                #value
            }
        }
    });
    quote!(#(#methods)*)
}

/// The user's position functions as `let` bindings in declaration order, on any scalar:
/// `__lagrange_bodies` reads the parameters from the fields, `__lagrange_bodies_with` from an array
/// `__p` of any scalar (see [`Params`]).
pub(super) fn bodies_fn(model: &Model, params: Params) -> TokenStream {
    let p = private();
    let n = lit(model.dof());
    let prelude = prelude();
    let used = model.names_used_by(model.bodies.iter().map(|b| b.decl));
    let inputs = bind_inputs_from(model, &used, quote!(__q), params);
    let names: Vec<&Ident> = model.bodies.iter().map(|b| b.decl.ident()).collect();
    let (shared, blocks) =
        optimized_blocks_from(model, model.bodies.iter().map(|b| &b.decl.block), params);
    let values: Vec<TokenStream> = model
        .bodies
        .iter()
        .zip(blocks)
        .map(|(b, block)| {
            let ty = position_type(b.shape);
            let name = b.decl.ident();
            match (b.count, check::family_index(b.decl)) {
                // A family: member i is the block with the index bound, earlier members readable.
                (Some(n), Some(index)) => {
                    let n = lit(n);
                    let zero = zero_position(b.shape);
                    quote!(let #name: [#ty; #n] = {
                        let mut #name: [#ty; #n] = #p::core::array::from_fn(|_| #zero);
                        for #index in 0..#n {
                            let __member: #ty = #block;
                            #name[#index] = __member;
                        }
                        #name
                    };)
                }
                _ => quote!(let #name: #ty = #block;),
            }
        })
        .collect();
    let signature = match params {
        Params::Fields => {
            quote!(fn __lagrange_bodies<__D: #p::Scalar>(&self, __t: __D, __q: &[__D; #n]) -> Bodies<__D>)
        }
        Params::Array => {
            let np = lit(crate::ast::slot_count(model.params));
            quote!(fn __lagrange_bodies_with<__S: #p::Scalar, __D: #p::Scalar>(&self, __p: &[__S; #np], __t: __D, __q: &[__D; #n]) -> Bodies<__D>)
        }
    };
    quote! {
        #[inline(always)]
        #[allow(unused_variables, clippy::all)]
        #signature {
            #prelude
            #inputs
            #shared
            #(#values)*
            Bodies { #(#names),* }
        }
    }
}

/// A position of `shape` at the origin, on `__D` (the start of a family being filled in).
fn zero_position(shape: Shape) -> TokenStream {
    let g = quote!(::lagrange::__private::geometry);
    let z = quote!(<__D>::zero());
    match shape {
        Shape::Planar => quote!(#g::planar(#g::vec2(#z, #z), #z)),
        Shape::Spatial => {
            quote!(#g::spatial(#g::vec3(#z, #z, #z), #g::Rot3 { rows: [[#z, #z, #z], [#z, #z, #z], [#z, #z, #z]] }))
        }
        _ if shape.dim() == Dim::Two => quote!(#g::vec2(#z, #z)),
        _ => quote!(#g::vec3(#z, #z, #z)),
    }
}

/// `x[i]` as tokens.
fn row(x: &TokenStream, i: usize) -> TokenStream {
    let i = lit(i);
    quote!(#x[#i])
}

/// One body (or family member) whose first row is `first`.
fn unflatten_at(body: &Body, first: usize, x: &TokenStream, velocity: bool) -> TokenStream {
    let g = quote!(::lagrange::__private::geometry);
    let r = |i: usize| row(x, first + i);
    let (r0, r1, r2) = (r(0), r(1), r(2));
    match body.shape {
        Shape::Particle(Dim::Two) | Shape::Point(Dim::Two) => quote!(#g::vec2(#r0, #r1)),
        Shape::Particle(Dim::Three) | Shape::Point(Dim::Three) => quote!(#g::vec3(#r0, #r1, #r2)),
        Shape::Planar => quote!(#g::planar(#g::vec2(#r0, #r1), #r2)),
        // The centre of mass's velocity, and ω = ½ Σₖ rₖ × ṙₖ from the rotation's columns
        // (positions in `__x`, rates in the velocity rows).
        Shape::Spatial if velocity => {
            let column = |x: &TokenStream, k: usize| {
                let rows = (0..3).map(|i| row(x, first + 3 + 3 * k + i));
                quote!(#g::vec3(#(#rows),*))
            };
            let positions = quote!(__x);
            let (c0, c1, c2) = (
                column(&positions, 0),
                column(&positions, 1),
                column(&positions, 2),
            );
            let (d0, d1, d2) = (column(x, 0), column(x, 1), column(x, 2));
            quote!(#g::SpatialVelocity {
                linear: #g::vec3(#r0, #r1, #r2),
                angular: #g::angular_velocity([#c0, #c1, #c2], [#d0, #d1, #d2]),
            })
        }
        Shape::Spatial => {
            // Column k of the rotation occupies rows 3 + 3k .. 6 + 3k: rows[r][k] = x[3 + 3k + r].
            let rows = (0..3).map(|i| {
                let entries = (0..3).map(|k| r(3 + 3 * k + i));
                quote!([#(#entries),*])
            });
            quote!(#g::spatial(#g::vec3(#r0, #r1, #r2), #g::Rot3 { rows: [#(#rows),*] }))
        }
    }
}

/// The rows of x a body (every member of a family) occupies, read from its position `b`.
pub(super) fn flatten(body: &Body, b: &TokenStream) -> Vec<TokenStream> {
    match body.count {
        Some(n) => (0..n)
            .flat_map(|k| {
                let k = lit(k);
                flatten_one(body, &quote!(#b[#k]))
            })
            .collect(),
        None => flatten_one(body, b),
    }
}

fn flatten_one(body: &Body, b: &TokenStream) -> Vec<TokenStream> {
    match body.shape {
        Shape::Particle(Dim::Two) | Shape::Point(Dim::Two) => vec![quote!(#b.x), quote!(#b.y)],
        Shape::Particle(Dim::Three) | Shape::Point(Dim::Three) => {
            vec![quote!(#b.x), quote!(#b.y), quote!(#b.z)]
        }
        Shape::Planar => vec![
            quote!(#b.position.x),
            quote!(#b.position.y),
            quote!(#b.angle),
        ],
        Shape::Spatial => {
            let mut rows = vec![
                quote!(#b.position.x),
                quote!(#b.position.y),
                quote!(#b.position.z),
            ];
            for k in 0..3usize {
                rows.extend((0..3).map(|r| {
                    let (r, k) = (lit(r), lit(k));
                    quote!(#b.rotation.rows[#r][#k])
                }));
            }
            rows
        }
    }
}

/// `let __frame_<body> = self.__lagrange_mass_frame_<body>();` for each framed body (each member
/// of a family whose frames are by member).
fn bind_mass_frames(model: &Model) -> TokenStream {
    let framed = attribute_sets(model.bodies.iter().filter(|b| b.is_framed()));
    let frames = framed.map(|(b, member)| {
        let (frame, method) = (mass_frame_binding(b, member), mass_frame_method(b, member));
        quote!(let #frame = self.#method();)
    });
    quote!(#(#frames)*)
}

/// The local a body's mass frame (member k's, `member` `Some(k)`) is bound to
/// ([`bind_mass_frames`]).
fn mass_frame_binding(body: &Body, member: Option<usize>) -> Ident {
    match member {
        None => format_ident!("__frame_{}", body.decl.ident()),
        Some(k) => format_ident!("__frame{}_{}", k, body.decl.ident()),
    }
}

/// A body (every member of a family) from its rows of x: its pose as its function returns it
/// (for a framed body, the frame of its centre of mass and principal axes mapped back).
fn body_from_rows(body: &Body) -> TokenStream {
    let x = quote!(__x);
    let member = |k: usize| {
        let first = body.row + k * body.shape.rows();
        let principal = unflatten_at(body, first, &x, false);
        match body.is_framed() {
            true => {
                let frame = mass_frame_binding(body, body.attribute_member(k));
                quote!(#frame.frame(#principal))
            }
            false => principal,
        }
    };
    match body.count {
        Some(n) => {
            let members = (0..n).map(member);
            quote!([#(#members),*])
        }
        None => member(0),
    }
}

/// A body's velocity (every member of a family) from its rows of x and ẋ: the velocity of the
/// pose its function returns (for a framed body, of the frame's origin).
fn velocity_from_rows(body: &Body) -> TokenStream {
    let (x, x_dot) = (quote!(__x), quote!(__x_dot));
    let member = |k: usize| {
        let first = body.row + k * body.shape.rows();
        let velocity = unflatten_at(body, first, &x_dot, true);
        match body.is_framed() {
            true => {
                let frame = mass_frame_binding(body, body.attribute_member(k));
                let principal = unflatten_at(body, first, &x, false);
                quote!(#frame.frame_velocity(&#principal, #velocity))
            }
            false => velocity,
        }
    };
    match body.count {
        Some(n) => {
            let members = (0..n).map(member);
            quote!([#(#members),*])
        }
        None => member(0),
    }
}

fn positions_from_cartesian(model: &Model) -> TokenStream {
    let p = private();
    let k = lit(model.rows);
    let names = model.bodies.iter().map(|b| b.decl.ident());
    let frames = bind_mass_frames(model);
    let values = model.bodies.iter().map(body_from_rows);
    quote! {
        #[inline(always)]
        fn __lagrange_bodies_from_cartesian<__D: #p::Scalar>(&self, __x: &[__D; #k]) -> Bodies<__D> {
            #frames
            Bodies { #(#names: #values),* }
        }
    }
}

fn velocities_from_cartesian(model: &Model) -> TokenStream {
    let p = private();
    let k = lit(model.rows);
    let names = model.bodies.iter().map(|b| b.decl.ident());
    let frames = bind_mass_frames(model);
    let values = model.bodies.iter().map(velocity_from_rows);
    quote! {
        #[inline(always)]
        #[allow(unused_variables)]
        fn __lagrange_velocities_from_cartesian<__D: #p::Scalar>(&self, __x: &[__D; #k], __x_dot: &[__D; #k]) -> BodyVelocities<__D> {
            #frames
            BodyVelocities { #(#names: #values),* }
        }
    }
}
