//! Expansion: the checked model into the module a user gets (see the README's "The declaration").
//!
//! Generated code names only `::lagrange::__private::…` paths. Per declaration it writes:
//! `Coords<T = f64>` and its `Coordinates` impl, `DOF`, `State`, `Bodies<T = f64>` (each body and
//! point's position: `Vec2`/`Vec3`/`Planar`/`Spatial`), `BodyVelocities<T = f64>` (a particle or
//! point's velocity vector; a planar body's centre-of-mass velocity and angular velocity as a
//! `Planar`; a spatial body's centre-of-mass velocity `Vec3`), inherent `bodies` and
//! `body_velocities`, and the `Model` and `Mechanism` impls. `potential` and `applied_forces` are
//! only written when something is declared for them.

use crate::ast::{Field, Mechanism};
use crate::attr::{Inertia, Kind};
use crate::check::{self, Body, Dim, Model, Shape};
use crate::ctxt::{self, Ctxt};
use crate::lift;
use crate::optimize;
use proc_macro2::{Ident, Span, TokenStream};
use quote::{format_ident, quote};
use std::collections::BTreeSet;

/// The `#[mechanism]` attribute: `attr` are its arguments, `item` the module.
pub(crate) fn expand(attr: TokenStream, item: TokenStream) -> TokenStream {
    let cx = Ctxt::new();
    // `#[mechanism(fast)]`: the attribute takes no arguments.
    if !attr.is_empty() {
        cx.error_spanned_by(&attr, "`#[mechanism]` takes no arguments");
    }
    let module: syn::ItemMod = match syn::parse2(item.clone()) {
        Ok(module) => module,
        // `#[mechanism] struct S;`: the declaration is a module.
        Err(_) => {
            cx.error_at(
                Span::call_site(),
                "#[mechanism] goes on an inline module: `pub mod name { ... }`",
            );
            return errors_then(cx, item);
        }
    };
    let Some(mechanism) = Mechanism::from_module(&cx, module.clone()) else {
        return errors_then(cx, quote!(#module));
    };
    let model = check::check(&cx, &mechanism);
    match cx.check() {
        Ok(()) => generate(&model.expect("the checks report why there is no model")),
        Err(errors) => crate::fallback::fallback(&mechanism, model.as_ref(), errors),
    }
}

fn errors_then(cx: Ctxt, item: TokenStream) -> TokenStream {
    let errors = cx
        .check()
        .err()
        .map(ctxt::to_compile_errors)
        .unwrap_or_default();
    quote!(#errors #item)
}

/// An unsuffixed integer literal (`3`, not `3usize`).
pub(crate) fn lit(n: usize) -> proc_macro2::Literal {
    proc_macro2::Literal::usize_unsuffixed(n)
}

/// `::lagrange::__private`.
pub(crate) fn private() -> TokenStream {
    quote!(::lagrange::__private)
}

/// The scalar type parameter of generated generic functions.
pub(crate) fn scalar() -> TokenStream {
    quote!(__D)
}

/// The geometry functions and types, and num-dual's methods, inside a generated function.
pub(crate) fn prelude() -> TokenStream {
    let p = private();
    quote! {
        #[allow(unused_imports)]
        use #p::geometry::{planar, rot_x, rot_y, rot_z, spatial, vec2, vec3, Planar, Rot3, Spatial, Vec2, Vec3};
        #[allow(unused_imports)]
        use #p::DualNum as _;
    }
}

/// The whole module for a declaration that passed every check.
fn generate(model: &Model) -> TokenStream {
    let mechanism = model.mechanism;
    let (attrs, vis, ident) = (&mechanism.attrs, &mechanism.vis, &mechanism.ident);
    let other_items = &mechanism.other_items;
    let params_struct = &mechanism.params.as_ref().unwrap().0;
    let coords = coords_items(mechanism, model.coords);
    let bodies = bodies_structs(model);
    let inherent = inherent_impl(model);
    let model_impl = model_impl(model);
    let constrained = (!model.constraints.is_empty()).then_some(model.constraints.len());
    let tree = crate::structure::tree(model);
    let tree_items = tree.as_ref().map(|tree| crate::expand_tree::tree_items(model, tree));
    let mechanism_impl = mechanism_impl(
        model.params_ident,
        model.dof(),
        model.rows,
        constrained,
        tree.map(|tree| (tree.width, tree.bodies.len())),
    );
    let constraints_impl = constrained.map(|_| constraints_impl(model));
    quote! {
        #(#attrs)*
        #vis mod #ident {
            #(#other_items)*
            #params_struct
            #coords
            #bodies
            #inherent
            #model_impl
            #tree_items
            #mechanism_impl
            #constraints_impl
        }
    }
}

/// `Coords<T = f64>`, its `Coordinates` impl, `DOF` and `State`.
fn coords_items(mechanism: &Mechanism, coords: &[Field]) -> TokenStream {
    let p = private();
    let n = lit(crate::ast::slot_count(coords));
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
    let names: Vec<&Ident> = coords.iter().map(|f| &f.ident).collect();
    let types = coords.iter().map(|f| match &f.array {
        Some((len, _)) => quote!([T; #len]),
        None => quote!(T),
    });
    // Names, flattened values and the values' fields, element by element for arrays.
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
    // `Default` is derived for scalar fields; arrays longer than 32 have no `Default`, so it is
    // written out when there are arrays.
    let has_arrays = coords.iter().any(|f| f.array.is_some());
    let default_derive = (!has_arrays).then(|| quote!(, #p::core::default::Default));
    let default_impl = has_arrays.then(|| {
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
    });
    quote! {
        #(#attrs)*
        #[derive(#p::core::clone::Clone, #p::core::marker::Copy, #p::core::fmt::Debug, #p::core::cmp::PartialEq #default_derive)]
        #vis struct Coords<T = f64> {
            #( #(#field_attrs)* pub #names: #types, )*
        }
        #default_impl

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

        /// Degrees of freedom: the number of generalized coordinates.
        #[allow(dead_code)]
        pub const DOF: usize = #n;

        /// The state of this mechanism: time, coordinates, velocities.
        #[allow(dead_code)]
        pub type State = #p::State<Coords>;
    }
}

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
        Shape::Spatial => (quote!(#g::Spatial<T>), quote!(#g::Vec3<T>)),
    }
}

pub(crate) fn bodies_structs(model: &Model) -> TokenStream {
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
        /// body's centre of mass and orientation.
        #derive
        #[allow(dead_code)]
        pub struct Bodies<T = f64> {
            #( #(#docs)* pub #names: #positions, )*
        }

        /// The velocity of every body and point, by name: a particle or point's velocity; for a
        /// planar body, its centre-of-mass velocity and angular velocity (as a `Planar`); for a
        /// spatial body, its centre-of-mass velocity.
        #derive
        #[allow(dead_code)]
        pub struct BodyVelocities<T = f64> {
            #( #(#docs)* pub #names: #velocities, )*
        }
    }
}

/// `let [theta1, theta2] = *__q;` (names with `suffix`), or for array coordinates
/// `let x = __q[0]; let theta = [__q[1], __q[2]];`.
fn bind_coordinates(model: &Model, q: &TokenStream, suffix: &str) -> TokenStream {
    // `format_ident!` drops the `r#` of a raw identifier: `r#type` is bound as itself.
    let name = |c: &Field| match suffix {
        "" => c.ident.clone(),
        _ => format_ident!("{}{}", c.ident, suffix),
    };
    if model.coords.iter().all(|c| c.array.is_none()) {
        let names = model.coords.iter().map(name);
        return quote!(let [#(#names),*] = *#q;);
    }
    let mut out = TokenStream::new();
    let mut slot = 0;
    for c in model.coords {
        let ident = name(c);
        let slots: Vec<_> = (slot..slot + c.slots()).map(lit).collect();
        if c.array.is_some() {
            out.extend(quote!(let #ident = [#(#q[#slots]),*];));
        } else {
            out.extend(quote!(let #ident = #(#q[#slots])*;));
        }
        slot += c.slots();
    }
    out
}

/// `let theta1 = …; let l1 = <__D>::from(self.l1); let t = __t;` for the names `used`.
fn bind_inputs(model: &Model, used: &BTreeSet<String>, q: TokenStream) -> TokenStream {
    let d = scalar();
    let coords = bind_coordinates(model, &q, "");
    let params = model
        .params
        .iter()
        .map(|p| &p.ident)
        .filter(|p| used.contains(&p.to_string()));
    let time = used.contains("t").then(|| quote!(let t = __t;));
    quote! {
        #coords
        #( let #params = <#d>::from(self.#params); )*
        #time
    }
}

/// The user's `blocks` rewritten by [`optimize`] (parameter-only subexpressions in `f64`, shared
/// `sin_cos`) and lifted to `__D`, with the `let`s the rewrites need (placed after the inputs).
pub(crate) fn optimized_blocks<'d>(
    model: &Model,
    blocks: impl IntoIterator<Item = &'d syn::Block>,
) -> (TokenStream, Vec<syn::Block>) {
    let d = scalar();
    let mut blocks: Vec<syn::Block> = blocks.into_iter().cloned().collect();
    let params: BTreeSet<String> = model.params.iter().map(|p| p.ident.to_string()).collect();
    let trig: BTreeSet<String> = model
        .coords
        .iter()
        .filter(|c| c.array.is_none())
        .map(|c| c.ident.to_string())
        .chain(std::iter::once("t".to_string()))
        .collect();
    let arrays: BTreeSet<String> = model
        .coords
        .iter()
        .filter(|c| c.array.is_some())
        .map(|c| c.ident.to_string())
        .collect();
    let lets = optimize::optimize(
        &mut blocks,
        &optimize::Scope {
            params: &params,
            trig: &trig,
            arrays: &arrays,
        },
        &d,
    );
    let blocks = blocks.iter().map(|b| lift::lift_block(b, &d)).collect();
    (lets, blocks)
}

/// The Rust type of a body's position on scalar `__D`.
pub(crate) fn position_type(shape: Shape) -> TokenStream {
    let g = quote!(::lagrange::__private::geometry);
    match shape.dim() {
        _ if shape == Shape::Planar => quote!(#g::Planar<__D>),
        _ if shape == Shape::Spatial => quote!(#g::Spatial<__D>),
        Dim::Two => quote!(#g::Vec2<__D>),
        Dim::Three => quote!(#g::Vec3<__D>),
    }
}

/// The inherent impl: `bodies`, `body_velocities`, and the private generic body functions.
fn inherent_impl(model: &Model) -> TokenStream {
    let p = private();
    let (params, n, k) = (model.params_ident, lit(model.dof()), lit(model.rows));
    let bodies_fn = bodies_fn(model);
    let from_cartesian = (!model.potentials.is_empty()
        || !model.gravities.is_empty()
        || !model.forces.is_empty()
        || !model.constraints.is_empty())
    .then(|| positions_from_cartesian(model));
    let velocities_from_cartesian = velocities_from_cartesian(model);
    quote! {
        impl #params {
            /// Every body and point at `state`, by name.
            #[allow(dead_code)]
            pub fn bodies(&self, state: &State) -> Bodies {
                let q = <Coords as #p::Coordinates<#n>>::to_array(&state.q);
                self.__lagrange_bodies(state.t, &q)
            }

            /// The velocity of every body and point at `state`, by name (one forward-mode pass
            /// along (q̇, 1)).
            #[allow(dead_code)]
            pub fn body_velocities(&self, state: &State) -> BodyVelocities {
                let q = <Coords as #p::Coordinates<#n>>::to_array(&state.q);
                let v = <Coords as #p::Coordinates<#n>>::to_array(&state.v);
                let (_, x_dot) = #p::dynamics::cartesian_velocities::<Self, f64, #n, #k>(self, state.t, &q, &v);
                Self::__lagrange_velocities_from_cartesian(&x_dot)
            }

            #bodies_fn
            #from_cartesian
            #velocities_from_cartesian
        }
    }
}

/// The user's position functions as `let` bindings in declaration order, on any scalar.
fn bodies_fn(model: &Model) -> TokenStream {
    let p = private();
    let n = lit(model.dof());
    let prelude = prelude();
    let used = model.names_used_by(model.bodies.iter().map(|b| b.decl));
    let inputs = bind_inputs(model, &used, quote!(__q));
    let names: Vec<&Ident> = model.bodies.iter().map(|b| b.decl.ident()).collect();
    let (shared, blocks) = optimized_blocks(model, model.bodies.iter().map(|b| &b.decl.block));
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
    quote! {
        #[inline(always)]
        #[allow(unused_variables, clippy::all)]
        fn __lagrange_bodies<__D: #p::Scalar>(&self, __t: __D, __q: &[__D; #n]) -> Bodies<__D> {
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

/// A body rebuilt from its rows of x (or ẋ, for velocities).
fn unflatten(body: &Body, x: &TokenStream, velocity: bool) -> TokenStream {
    match body.count {
        Some(n) => {
            let members =
                (0..n).map(|k| unflatten_at(body, body.row + k * body.shape.rows(), x, velocity));
            quote!([#(#members),*])
        }
        None => unflatten_at(body, body.row, x, velocity),
    }
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
        Shape::Spatial if velocity => quote!(#g::vec3(#r0, #r1, #r2)),
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
fn flatten(body: &Body, b: &TokenStream) -> Vec<TokenStream> {
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

fn positions_from_cartesian(model: &Model) -> TokenStream {
    let p = private();
    let k = lit(model.rows);
    let names = model.bodies.iter().map(|b| b.decl.ident());
    let values = model
        .bodies
        .iter()
        .map(|b| unflatten(b, &quote!(__x), false));
    quote! {
        #[inline(always)]
        fn __lagrange_bodies_from_cartesian<__D: #p::Scalar>(__x: &[__D; #k]) -> Bodies<__D> {
            Bodies { #(#names: #values),* }
        }
    }
}

fn velocities_from_cartesian(model: &Model) -> TokenStream {
    let p = private();
    let k = lit(model.rows);
    let names = model.bodies.iter().map(|b| b.decl.ident());
    let values = model
        .bodies
        .iter()
        .map(|b| unflatten(b, &quote!(__x_dot), true));
    quote! {
        #[inline(always)]
        fn __lagrange_velocities_from_cartesian<__D: #p::Scalar>(__x_dot: &[__D; #k]) -> BodyVelocities<__D> {
            BodyVelocities { #(#names: #values),* }
        }
    }
}

/// Parameters bound as `f64`, then each body's mass and inertia: shared by `validate` and `masses`.
fn mass_bindings(model: &Model) -> TokenStream {
    let params = model.params.iter().map(|p| &p.ident);
    let mut out = quote!(#( let #params: f64 = self.#params; )*);
    for body in model.bodies.iter().filter(|b| b.shape.has_mass()) {
        let args = &body.decl.args;
        let mass = args.mass.as_ref().unwrap();
        let mass_ident = format_ident!("__mass_{}", body.decl.ident());
        let inertia_ident = format_ident!("__inertia_{}", body.decl.ident());
        out.extend(quote!(let #mass_ident: f64 = #mass;));
        match &args.inertia {
            Some(Inertia::Moment(i)) => out.extend(quote!(let #inertia_ident: f64 = #i;)),
            Some(Inertia::Principal(i)) => out.extend(quote!(let #inertia_ident: [f64; 3] = #i;)),
            None => {}
        }
    }
    out
}

/// The `Model` impl.
fn model_impl(model: &Model) -> TokenStream {
    let p = private();
    let (params, n, k, inertial) = (
        model.params_ident,
        lit(model.dof()),
        lit(model.rows),
        lit(model.inertial_rows),
    );
    let rheonomic = model.rheonomic;
    let has_potential = !model.potentials.is_empty() || !model.gravities.is_empty();
    let has_forces = !model.forces.is_empty();
    let validate = validate_fn(model);
    let masses = masses_fn(model);
    let cartesian = cartesian_fn(model);
    let potential = has_potential.then(|| potential_fn(model));
    let forces = has_forces.then(|| applied_forces_fn(model));
    let weights = (!model.uniform_gravities.is_empty()).then(|| weights_fn(model));
    quote! {
        impl #p::Model<#n, #k> for #params {
            type Coords = Coords;
            const INERTIAL: usize = #inertial;
            const RHEONOMIC: bool = #rheonomic;
            const HAS_POTENTIAL: bool = #has_potential;
            const HAS_FORCES: bool = #has_forces;
            #validate
            #masses
            #cartesian
            #potential
            #forces
            #weights
        }
    }
}

/// A uniform field as constant Cartesian weights w = μ g on the position rows of every massive body
/// moving in the field's dimension (V = −w·x, 𝓕 = Jᵀw, computed by `lagrange_core::dynamics`).
fn weights_fn(model: &Model) -> TokenStream {
    let p = private();
    let (n, k) = (lit(model.dof()), lit(model.rows));
    let used = model.names_used_by(model.uniform_gravities.iter().map(|(g, _)| *g));
    let params = model
        .params
        .iter()
        .map(|p| &p.ident)
        .filter(|p| used.contains(&p.to_string()));
    let fields = model.uniform_gravities.iter().map(|(decl, dim)| {
        let ident = format_ident!("__gravity_{}", decl.ident());
        let g = quote!(::lagrange::__private::geometry);
        let ty = if *dim == Dim::Two {
            quote!(#g::Vec2<f64>)
        } else {
            quote!(#g::Vec3<f64>)
        };
        let block = &decl.block;
        let components: &[&str] = if *dim == Dim::Two {
            &["x", "y"]
        } else {
            &["x", "y", "z"]
        };
        let rows = model
            .bodies
            .iter()
            .filter(|b| b.shape.has_mass() && b.shape.dim() == *dim)
            .flat_map(|b| {
                let ident = &ident;
                (0..b.members()).flat_map(move |member| {
                    let first = b.row + member * b.shape.rows();
                    components.iter().enumerate().map(move |(i, c)| {
                        let (r, c) = (lit(first + i), format_ident!("{}", c));
                        quote!(__weights[#r] += #ident.#c * __masses[#r];)
                    })
                })
            })
            .collect::<Vec<_>>();
        quote!(let #ident: #ty = #block; #(#rows)*)
    });
    quote! {
        const HAS_GRAVITY: bool = true;
        #[allow(unused_variables, clippy::all)]
        fn weights(&self) -> [f64; #k] {
            #[allow(unused_imports)]
            use #p::geometry::{vec2, vec3};
            #( let #params: f64 = self.#params; )*
            let __masses = <Self as #p::Model<#n, #k>>::masses(self);
            let mut __weights = [0.0; #k];
            #(#fields)*
            __weights
        }
    }
}

fn validate_fn(model: &Model) -> TokenStream {
    let p = private();
    let params = model.params.iter().map(|f| &f.ident);
    let strings = model.params.iter().map(|f| f.ident.to_string());
    let bindings = mass_bindings(model);
    let err = quote!(return #p::core::result::Result::Err);
    let bodies = model.bodies.iter().filter(|b| b.shape.has_mass()).map(|body| {
        let name = body.decl.ident().to_string();
        let mass = format_ident!("__mass_{}", body.decl.ident());
        let inertia = format_ident!("__inertia_{}", body.decl.ident());
        let check_mass = quote! {
            if !(#mass.is_finite() && #mass > 0.0) {
                #err(#p::Error::InvalidInertia { body: #name, reason: #p::std::format!("mass must be positive and finite, got {}", #mass) });
            }
        };
        let check_inertia = match body.shape {
            Shape::Planar => quote! {
                if !(#inertia.is_finite() && #inertia > 0.0) {
                    #err(#p::Error::InvalidInertia { body: #name, reason: #p::std::format!("moment of inertia must be positive and finite, got {}", #inertia) });
                }
            },
            Shape::Spatial => quote! {
                let __sum: f64 = #inertia[0] + #inertia[1] + #inertia[2];
                for (__k, __moment) in #inertia.into_iter().enumerate() {
                    if !(__moment.is_finite() && __moment > 0.0) {
                        #err(#p::Error::InvalidInertia { body: #name, reason: #p::std::format!("principal moment I{} must be positive and finite, got {}", __k + 1, __moment) });
                    }
                    // I_k ≤ I_i + I_j (equality for a flat body), up to rounding.
                    if __moment > __sum - __moment + 1e-12 * __sum {
                        #err(#p::Error::InvalidInertia { body: #name, reason: #p::std::format!("principal moments {:?} violate the triangle inequality: I{} exceeds the sum of the other two", #inertia, __k + 1) });
                    }
                }
            },
            _ => quote!(),
        };
        quote!(#check_mass #check_inertia)
    });
    // The common case first, branch-free: x·0 is 0 exactly when x is finite, so one comparison
    // checks every parameter; masses and moments compare positive. Only a failure (or a spatial
    // body, whose moments have more to check) goes on to the checks that name the culprit.
    let fast = (!model.bodies.iter().any(|b| b.shape == Shape::Spatial)).then(|| {
        let fields = model.params.iter().map(|f| &f.ident);
        let positive = model.bodies.iter().filter(|b| b.shape.has_mass()).map(|body| {
            let mass = format_ident!("__mass_{}", body.decl.ident());
            let inertia = format_ident!("__inertia_{}", body.decl.ident());
            match body.shape {
                Shape::Planar => quote!(& (#mass * 0.0 == 0.0) & (#mass > 0.0) & (#inertia * 0.0 == 0.0) & (#inertia > 0.0)),
                _ => quote!(& (#mass * 0.0 == 0.0) & (#mass > 0.0)),
            }
        });
        let bindings = &bindings;
        quote! {
            {
                #bindings
                if ((0.0 #( + self.#fields * 0.0 )*) == 0.0) #(#positive)* {
                    return #p::core::result::Result::Ok(());
                }
            }
        }
    });
    quote! {
        #[allow(unused_variables, clippy::all)]
        fn validate(&self) -> #p::Result<()> {
            #fast
            #(
                if !self.#params.is_finite() {
                    #err(#p::Error::NonFiniteParameter { name: #strings, value: self.#params });
                }
            )*
            #bindings
            #(#bodies)*
            #p::core::result::Result::Ok(())
        }
    }
}

fn masses_fn(model: &Model) -> TokenStream {
    let k = lit(model.rows);
    let bindings = mass_bindings(model);
    let mut rows = vec![quote!(0.0); model.rows];
    for body in &model.bodies {
        let mass = format_ident!("__mass_{}", body.decl.ident());
        let inertia = format_ident!("__inertia_{}", body.decl.ident());
        for member in 0..body.members() {
            let r = body.row + member * body.shape.rows();
            match body.shape {
                Shape::Point(_) => {}
                Shape::Particle(dim) => {
                    let d = if dim == Dim::Two { 2 } else { 3 };
                    (0..d).for_each(|i| rows[r + i] = quote!(#mass));
                }
                Shape::Planar => {
                    rows[r] = quote!(#mass);
                    rows[r + 1] = quote!(#mass);
                    rows[r + 2] = quote!(#inertia);
                }
                Shape::Spatial => {
                    (0..3).for_each(|i| rows[r + i] = quote!(#mass));
                    // Column k carries J_k = (I₁ + I₂ + I₃)/2 − I_k (see lagrange_core::model).
                    for col in 0..3usize {
                        let j = quote!(((#inertia[0] + #inertia[1] + #inertia[2]) * 0.5 - #inertia[#col]));
                        (0..3).for_each(|i| rows[r + 3 + 3 * col + i] = j.clone());
                    }
                }
            }
        }
    }
    quote! {
        #[allow(unused_variables, clippy::all)]
        fn masses(&self) -> [f64; #k] {
            #bindings
            [#(#rows),*]
        }
    }
}

fn cartesian_fn(model: &Model) -> TokenStream {
    let p = private();
    let (n, k) = (lit(model.dof()), lit(model.rows));
    let mut by_row: Vec<&Body> = model.bodies.iter().collect();
    by_row.sort_by_key(|b| b.row);
    let rows = by_row.iter().flat_map(|b| {
        let name = b.decl.ident();
        flatten(b, &quote!(__bodies.#name))
    });
    quote! {
        #[inline(always)]
        fn cartesian<__D: #p::Scalar>(&self, __t: __D, __q: &[__D; #n]) -> [__D; #k] {
            let __bodies = self.__lagrange_bodies(__t, __q);
            [#(#rows),*]
        }
    }
}

/// `let Bodies { bob1, .. } = …;` from x.
fn bind_bodies(model: &Model) -> TokenStream {
    let names = model.bodies.iter().map(|b| b.decl.ident());
    quote!(let Bodies { #(#names),* } = Self::__lagrange_bodies_from_cartesian(__x);)
}

fn potential_fn(model: &Model) -> TokenStream {
    let p = private();
    let (n, k) = (lit(model.dof()), lit(model.rows));
    let prelude = prelude();
    let decls = model
        .potentials
        .iter()
        .copied()
        .chain(model.gravities.iter().map(|(g, _)| *g));
    let inputs = bind_inputs(model, &model.names_used_by(decls), quote!(__q));
    let bodies = bind_bodies(model);
    let (shared, blocks) = optimized_blocks(model, model.potentials.iter().map(|d| &d.block));
    let potentials = model.potentials.iter().zip(blocks).map(|(decl, block)| {
        let ident = format_ident!("__potential_{}", decl.ident());
        quote!(let #ident: __D = #block; __potential += #ident;)
    });
    let gravities = model
        .gravities
        .iter()
        .map(|(decl, dim)| gravity_terms(model, decl, *dim));
    // Masses only weigh a field that varies; constant fields are `weights`.
    let masses = (!model.gravities.is_empty())
        .then(|| quote!(let __masses = <Self as #p::Model<#n, #k>>::masses(self);));
    quote! {
        #[allow(unused_variables, clippy::all)]
        fn potential<__D: #p::Scalar>(&self, __t: __D, __q: &[__D; #n], __x: &[__D; #k]) -> __D {
            #prelude
            #inputs
            #shared
            #bodies
            #masses
            let mut __potential = <__D>::zero();
            #(#potentials)*
            #(#gravities)*
            __potential
        }
    }
}

/// V −= m g·r for every massive body whose position has the field's dimension.
fn gravity_terms(model: &Model, decl: &crate::ast::Decl, dim: Dim) -> TokenStream {
    let d = scalar();
    let ident = format_ident!("__gravity_{}", decl.ident());
    let ty = position_type(Shape::Point(dim));
    let block = lift::lift_block(&decl.block, &d);
    let terms = model
        .bodies
        .iter()
        .filter(|b| b.shape.has_mass() && b.shape.dim() == dim)
        .flat_map(|b| {
            let ident = &ident;
            (0..b.members()).map(move |member| {
                let name = b.decl.ident();
                let row = lit(b.row + member * b.shape.rows());
                let body = match b.count {
                    Some(_) => {
                        let k = lit(member);
                        quote!(#name[#k])
                    }
                    None => quote!(#name),
                };
                let centre = match b.shape {
                    Shape::Planar | Shape::Spatial => quote!(#body.position),
                    _ => body,
                };
                quote!(__potential -= #ident.dot(&#centre) * __masses[#row];)
            })
        });
    quote!(let #ident: #ty = #block; #(#terms)*)
}

fn applied_forces_fn(model: &Model) -> TokenStream {
    let p = private();
    let (n, k) = (lit(model.dof()), lit(model.rows));
    let prelude = prelude();
    let inputs = bind_inputs(
        model,
        &model.names_used_by(model.forces.iter().map(|f| f.decl)),
        quote!(__q),
    );
    let velocities = bind_coordinates(model, &quote!(__v), "_dot");
    let bodies = bind_bodies(model);
    let names = model.bodies.iter().map(|b| b.decl.ident());
    let body_velocities = model
        .bodies
        .iter()
        .map(|b| format_ident!("{}_dot", b.decl.ident()));
    let (shared, blocks) = optimized_blocks(model, model.forces.iter().map(|f| &f.decl.block));
    let forces = model.forces.iter().zip(blocks).map(|(force, block)| {
        let ident = format_ident!("__{}_{}", force.kind.name(), force.decl.ident());
        match force.kind {
            Kind::Force => {
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
            Kind::Torque => {
                let r = lit(model.bodies[force.target].row + 2);
                quote!(let #ident: __D = #block; __cartesian_force[#r] += #ident;)
            }
            _ => {
                let j = lit(force.target);
                quote!(let #ident: __D = #block; __generalized_force[#j] += #ident;)
            }
        }
    });
    quote! {
        #[allow(unused_variables, clippy::all)]
        fn applied_forces<__D: #p::Scalar>(
            &self,
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
            let BodyVelocities { #(#names: #body_velocities),* } = Self::__lagrange_velocities_from_cartesian(__x_dot);
            #(#forces)*
        }
    }
}

/// The `Mechanism` impl, forwarding to `lagrange_core::dynamics`.
fn mechanism_impl(
    params: &Ident,
    n: usize,
    k: usize,
    constrained: Option<usize>,
    tree: Option<(usize, usize)>,
) -> TokenStream {
    let (p, n, k) = (private(), lit(n), lit(k));
    // A tree of translations is assembled from each body's own seeds; anything else densely.
    let equations_of_motion = match tree {
        Some((w, b)) => {
            let (w, b) = (lit(w), lit(b));
            quote!(#p::tree::equations_of_motion::<Self, S, #n, #k, #w, #b>(self, t, q, v))
        }
        None => quote!(#p::dynamics::equations_of_motion::<Self, S, #n, #k>(self, t, q, v)),
    };
    let overrides = constrained.map(|c| constrained_overrides(n.clone(), k.clone(), lit(c)));
    let validate_constraints = constrained.map(|c| {
        let c = lit(c);
        quote!(<Self as #p::lagrange_core::constraints::Constraints<#n, #k, #c>>::validate_constraints(self)?;)
    });
    quote! {
        impl #p::Mechanism<#n> for #params {
            type Coords = Coords;
            #[inline]
            fn validate(&self) -> #p::Result<()> {
                <Self as #p::Model<#n, #k>>::validate(self)?;
                #validate_constraints
                #p::core::result::Result::Ok(())
            }
            #overrides
            #[inline]
            fn equations_of_motion_at<S: #p::Scalar>(&self, t: S, q: &[S; #n], v: &[S; #n]) -> #p::dynamics::EquationsOfMotion<S, #n> {
                #equations_of_motion
            }
            #[inline]
            fn kinetic_energy_at<S: #p::Scalar>(&self, t: S, q: &[S; #n], v: &[S; #n]) -> S {
                #p::dynamics::kinetic_energy::<Self, S, #n, #k>(self, t, q, v)
            }
            #[inline]
            fn potential_energy_at<S: #p::Scalar>(&self, t: S, q: &[S; #n]) -> S {
                #p::dynamics::potential_energy::<Self, S, #n, #k>(self, t, q)
            }
            #[inline]
            fn momenta_at<S: #p::Scalar>(&self, t: S, q: &[S; #n], v: &[S; #n]) -> [S; #n] {
                #p::dynamics::momenta::<Self, S, #n, #k>(self, t, q, v)
            }
            #[inline]
            fn lagrangian_time_derivative_at(&self, t: f64, q: &[f64; #n], v: &[f64; #n]) -> f64 {
                #p::dynamics::lagrangian_time_derivative::<Self, #n, #k>(self, t, q, v)
            }
        }
    }
}

/// The three `Mechanism` hooks that make every integrator enforce the constraints.
fn constrained_overrides(
    n: proc_macro2::Literal,
    k: proc_macro2::Literal,
    c: proc_macro2::Literal,
) -> TokenStream {
    let p = private();
    let constraints = quote!(#p::lagrange_core::constraints);
    quote! {
        #[inline]
        fn accelerations_at<S: #p::Scalar>(&self, t: S, q: &[S; #n], v: &[S; #n]) -> #p::Result<[S; #n]> {
            #constraints::accelerations::<Self, S, #n, #k, #c>(self, t, q, v)
        }
        fn project(&self, t: f64, q: &mut [f64; #n], v: &mut [f64; #n]) -> #p::Result<()> {
            let mode = #constraints::infer_mode::<Self, #n, #k, #c>(self, t, q, v)?;
            #constraints::project::<Self, #n, #k, #c>(self, t, q, v, &mode)
        }
        fn check_declaration_at(&self, t: f64, q: &[f64; #n], v: &[f64; #n]) -> #p::Result<()> {
            #constraints::check_velocity_rows_affine::<Self, #n, #k, #c>(self, t, q, v)
        }
        fn check_constraints(&self, t: f64, q: &[f64; #n], v: &[f64; #n]) -> #p::Result<()> {
            #constraints::check_consistent::<Self, #n, #k, #c>(self, t, q, v, #constraints::CONSISTENCY_TOLERANCE)
        }
    }
}

/// The `Constraints` impl: one row per constraint item, in declaration order.
fn constraints_impl(model: &Model) -> TokenStream {
    let p = private();
    let constraints = quote!(#p::lagrange_core::constraints);
    let (params, n, k, c) = (
        model.params_ident,
        lit(model.dof()),
        lit(model.rows),
        lit(model.constraints.len()),
    );
    let names = model.constraints.iter().map(|r| r.decl.ident().to_string());
    let kinds = model
        .constraints
        .iter()
        .map(|r| match (r.decl.kind(), r.normal) {
            (Kind::Constraint, _) => quote!(#constraints::ConstraintKind::Holonomic),
            (Kind::Unilateral, _) => quote!(#constraints::ConstraintKind::Unilateral),
            (Kind::VelocityConstraint, _) => quote!(#constraints::ConstraintKind::Velocity),
            (_, normal) => {
                let normal = lit(normal.unwrap_or_default());
                quote!(#constraints::ConstraintKind::Friction { normal: #normal })
            }
        });
    let is_position = |kind: Kind| matches!(kind, Kind::Constraint | Kind::Unilateral);
    // `position_constraints` is required; the other two only when a row needs them.
    let position = constraint_rows_fn(model, true);
    let velocity = model
        .constraints
        .iter()
        .any(|r| !is_position(r.decl.kind()))
        .then(|| constraint_rows_fn(model, false));
    let friction = model
        .constraints
        .iter()
        .any(|r| r.decl.kind() == Kind::Friction)
        .then(|| friction_fn(model));
    quote! {
        impl #constraints::Constraints<#n, #k, #c> for #params {
            const NAMES: [&'static str; #c] = [#(#names),*];
            const KINDS: [#constraints::ConstraintKind; #c] = [#(#kinds),*];
            #position
            #velocity
            #friction
        }
    }
}

/// `position_constraints` (g or c per position row, zero elsewhere) or `velocity_constraints`
/// (h or the slip velocity per velocity row, zero elsewhere).
fn constraint_rows_fn(model: &Model, position: bool) -> TokenStream {
    let p = private();
    let (n, k, c, d) = (
        lit(model.dof()),
        lit(model.rows),
        lit(model.constraints.len()),
        scalar(),
    );
    let prelude = prelude();
    let rows: Vec<_> = model
        .constraints
        .iter()
        .filter(|r| matches!(r.decl.kind(), Kind::Constraint | Kind::Unilateral) == position)
        .map(|r| r.decl)
        .collect();
    let inputs = bind_inputs(
        model,
        &model.names_used_by(rows.iter().copied()),
        quote!(__q),
    );
    let bodies = bind_bodies(model);
    let values = model.constraints.iter().map(|r| {
        if matches!(r.decl.kind(), Kind::Constraint | Kind::Unilateral) == position {
            let block = lift::lift_block(&r.decl.block, &d);
            quote!({ let __row: __D = #block; __row })
        } else {
            quote!(<__D>::zero())
        }
    });
    let signature = if position {
        quote!(fn position_constraints<__D: #p::Scalar>(&self, __t: __D, __q: &[__D; #n], __x: &[__D; #k]) -> [__D; #c])
    } else {
        quote!(fn velocity_constraints<__D: #p::Scalar>(&self, __t: __D, __q: &[__D; #n], __v: &[__D; #n], __x: &[__D; #k], __x_dot: &[__D; #k]) -> [__D; #c])
    };
    let velocities = (!position).then(|| {
        let coords = bind_coordinates(model, &quote!(__v), "_dot");
        let names = model.bodies.iter().map(|b| b.decl.ident());
        let body_velocities = model.bodies.iter().map(|b| format_ident!("{}_dot", b.decl.ident()));
        quote! {
            #coords
            let BodyVelocities { #(#names: #body_velocities),* } = Self::__lagrange_velocities_from_cartesian(__x_dot);
        }
    });
    quote! {
        #[allow(unused_variables, clippy::all)]
        #signature {
            #prelude
            #inputs
            #bodies
            #velocities
            [#(#values),*]
        }
    }
}

/// `friction_coefficients`: μₖ and μₛ (μₛ = μₖ unless given) of each friction row.
fn friction_fn(model: &Model) -> TokenStream {
    let p = private();
    let constraints = quote!(#p::lagrange_core::constraints);
    let params = model.params.iter().map(|p| &p.ident);
    let arms = model
        .constraints
        .iter()
        .enumerate()
        .filter(|(_, r)| r.decl.kind() == Kind::Friction)
        .map(|(i, r)| {
            let i = lit(i);
            let kinetic = r.decl.args.kinetic.as_ref();
            let stiction = r.decl.args.stiction.as_ref().or(kinetic);
            quote!(#i => #constraints::Coulomb { kinetic: #kinetic, stiction: #stiction },)
        });
    quote! {
        #[allow(unused_variables, clippy::all)]
        fn friction_coefficients(&self, row: usize) -> #constraints::Coulomb {
            #( let #params: f64 = self.#params; )*
            match row {
                #(#arms)*
                _ => #constraints::Coulomb::default(),
            }
        }
    }
}
