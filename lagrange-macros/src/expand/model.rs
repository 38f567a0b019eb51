//! The `Model` impl: masses, `validate`, `cartesian`, the weights of uniform fields, the potential
//! and the applied forces.

use super::bodies::{flatten, mass_frame_method};
use super::{
    bind_bodies, bind_inputs_from, lit, optimized_blocks_from, position_type, prelude, private,
    scalar, Params,
};
use crate::attr::Inertia;
use crate::check::{Body, Dim, Model, Shape};
use crate::lift;
use proc_macro2::TokenStream;
use quote::{format_ident, quote, ToTokens};

mod forces;
mod gradient;
mod validate;

pub(super) use forces::{applied_forces_fn, coordinate_forces_fn, Forces};
pub(super) use gradient::gradient_on_trees;
use validate::validate_fn;

/// The local holding a body's `what` (`mass`, `inertia`, `moments`, `com`): `__mass_<body>`, or
/// `__mass<k>_<body>` for member k of a family whose attributes are by member.
pub(crate) fn attribute_ident(what: &str, body: &Body, member: Option<usize>) -> syn::Ident {
    match member {
        None => format_ident!("__{}_{}", what, body.decl.ident()),
        Some(k) => format_ident!("__{}{}_{}", what, k, body.decl.ident()),
    }
}

/// `let i: usize = k;` for member k of a family whose attributes are by member: the index its
/// attributes name.
pub(crate) fn bind_family_index(body: &Body, member: Option<usize>) -> TokenStream {
    let index = crate::check::family_index(body.decl);
    match (member, index) {
        (Some(k), Some(index)) => {
            let k = lit(k);
            quote!(let #index: usize = #k;)
        }
        _ => quote!(),
    }
}

/// A body's attribute `expr` as member k evaluates it (`{ let i: usize = k; expr }`), or as written
/// when the body's attributes are one for all its members.
pub(crate) fn attribute_value(
    body: &Body,
    member: Option<usize>,
    expr: &dyn ToTokens,
) -> TokenStream {
    match member {
        Some(_) => {
            let index = bind_family_index(body, member);
            quote!({ #index #expr })
        }
        None => expr.to_token_stream(),
    }
}

/// Parameters bound as `f64`, then each body's mass and inertia (a family's by member when they
/// name its index): shared by `validate` and `masses`.
fn mass_bindings(model: &Model) -> TokenStream {
    let mut out: TokenStream = model.params.iter().map(|f| f.bind_f64()).collect();
    for body in model.bodies.iter().filter(|b| b.shape.has_mass()) {
        let args = &body.decl.args;
        let mass = args.mass.as_ref().unwrap();
        for member in body.attribute_members() {
            let mass_ident = attribute_ident("mass", body, member);
            let inertia_ident = attribute_ident("inertia", body, member);
            let value = |ty: TokenStream, e: &dyn ToTokens| {
                let e = attribute_value(body, member, e);
                quote!(let #inertia_ident: #ty = #e;)
            };
            let mass = attribute_value(body, member, mass);
            out.extend(quote!(let #mass_ident: f64 = #mass;));
            match &args.inertia {
                Some(Inertia::Moment(i)) => out.extend(value(quote!(f64), i)),
                Some(Inertia::Principal(i)) => out.extend(value(quote!([f64; 3]), i)),
                Some(Inertia::Tensor(i)) => out.extend(value(quote!([[f64; 3]; 3]), i)),
                None => {}
            }
        }
    }
    out
}

/// Above this many entries (rows × coordinates) `DEPENDS` is left at its default: the table's
/// size grows as K·N, its saving only where the dense assembly is used (not for trees).
const MAX_DEPENDS_ENTRIES: usize = 1024;

/// `const DEPENDS` when the declaration rules some entries of J out (see
/// [`crate::structure::rows_depend_on`]).
fn depends_const(model: &Model) -> Option<TokenStream> {
    if model.rows * model.dof() > MAX_DEPENDS_ENTRIES {
        return None;
    }
    let rows = crate::structure::rows_depend_on(model)?;
    let (n, k) = (lit(model.dof()), lit(model.rows));
    let rows = rows.iter().map(|r| quote!([#(#r),*]));
    Some(quote!(const DEPENDS: [[bool; #n]; #k] = [#(#rows),*];))
}

/// Whether every force is a `#[generalized_force]` that names no body and no body velocity (a
/// motor, joint damping): its value needs neither x nor ẋ (`Model::GENERALIZED_FORCES_ONLY`).
pub(super) fn generalized_forces_only(model: &Model) -> bool {
    model.forces.iter().all(|f| {
        let used = model.names_used_by([f.decl]);
        f.kind == crate::attr::Kind::GeneralizedForce
            && !forces::names_a_body(model, &used, false)
            && !forces::names_a_body(model, &used, true)
    })
}

/// The `Model` impl.
pub(super) fn model_impl(model: &Model) -> TokenStream {
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
    let generalized_only = (has_forces && generalized_forces_only(model)).then(|| {
        let forces = coordinate_forces_fn(model, Forces::Plain);
        quote!(const GENERALIZED_FORCES_ONLY: bool = true; #forces)
    });
    let validate = validate_fn(model);
    let masses = masses_fn(model);
    let cartesian = cartesian_fn(model, Params::Fields);
    let potential = has_potential.then(|| potential_fn(model, Params::Fields));
    let forces = has_forces.then(|| applied_forces_fn(model, Forces::Plain));
    let weights = (!model.uniform_gravities.is_empty()).then(|| weights_fn(model));
    let depends = depends_const(model);
    let (potential_gradient, potential_methods) = gradient::potential_gradient(model);
    quote! {
        #potential_methods
        impl #p::Model<#n, #k> for #params {
            type Coords = Coords;
            const INERTIAL: usize = #inertial;
            const RHEONOMIC: bool = #rheonomic;
            const HAS_POTENTIAL: bool = #has_potential;
            const HAS_FORCES: bool = #has_forces;
            #generalized_only
            #depends
            #validate
            #masses
            #cartesian
            #potential
            #potential_gradient
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
    let params: TokenStream = model
        .params
        .iter()
        .filter(|p| used.contains(&p.ident.to_string()))
        .map(|p| p.bind_f64())
        .collect();
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
            #params
            let __masses = <Self as #p::Model<#n, #k>>::masses(self);
            let mut __weights = [0.0; #k];
            #(#fields)*
            __weights
        }
    }
}

fn masses_fn(model: &Model) -> TokenStream {
    let p = private();
    let k = lit(model.rows);
    let bindings = mass_bindings(model);
    let principal = model
        .bodies
        .iter()
        .filter(|b| b.has_tensor())
        .flat_map(|body| {
            let p = p.clone();
            body.attribute_members().into_iter().map(move |member| {
                let inertia = attribute_ident("inertia", body, member);
                let moments = attribute_ident("moments", body, member);
                quote!(let #moments: [f64; 3] = #p::inertia::principal_axes(&#inertia).0;)
            })
        });
    let mut rows = vec![quote!(0.0); model.rows];
    for body in &model.bodies {
        for member in 0..body.members() {
            let r = body.row + member * body.shape.rows();
            let member_attributes = body.attribute_member(member);
            let mass = attribute_ident("mass", body, member_attributes);
            let inertia = attribute_ident("inertia", body, member_attributes);
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
                    // A full tensor's principal moments, in the order of the principal axes its
                    // mass frame turns the body's columns into (lagrange_core::inertia).
                    let moments = match body.has_tensor() {
                        true => attribute_ident("moments", body, member_attributes),
                        false => inertia.clone(),
                    };
                    // Column k carries J_k = (I₁ + I₂ + I₃)/2 − I_k (see lagrange_core::model).
                    for col in 0..3usize {
                        let j = quote!(((#moments[0] + #moments[1] + #moments[2]) * 0.5 - #moments[#col]));
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
            #(#principal)*
            [#(#rows),*]
        }
    }
}

/// x(q, t) from the bodies: `cartesian` with the parameters from the fields, `cartesian_with` from
/// an array (see [`Params`]).
pub(super) fn cartesian_fn(model: &Model, params: Params) -> TokenStream {
    let p = private();
    let (n, k) = (lit(model.dof()), lit(model.rows));
    let mut by_row: Vec<&Body> = model.bodies.iter().collect();
    by_row.sort_by_key(|b| b.row);
    // A body declared by its frame enters x by its centre of mass and principal axes.
    let principal = model.bodies.iter().filter(|b| b.is_framed()).map(|b| {
        let (name, method) = (b.decl.ident(), mass_frame_method(b, None));
        let principal = format_ident!("__principal_{}", name);
        match b.count {
            // A family whose frames are by member: member k by its own frame.
            Some(n) if b.attributes_by_member() => {
                let members = (0..n).map(|k| {
                    let (method, k) = (mass_frame_method(b, Some(k)), lit(k));
                    quote!(self.#method().principal(__bodies.#name[#k]))
                });
                quote!(let #principal = [#(#members),*];)
            }
            Some(_) => quote!(let #principal = { let __frame = self.#method(); __bodies.#name.map(|__b| __frame.principal(__b)) };),
            None => quote!(let #principal = self.#method().principal(__bodies.#name);),
        }
    });
    let rows = by_row.iter().flat_map(|b| {
        let name = b.decl.ident();
        match b.is_framed() {
            true => flatten(b, &format_ident!("__principal_{}", name).to_token_stream()),
            false => flatten(b, &quote!(__bodies.#name)),
        }
    });
    let (signature, bodies) = match params {
        Params::Fields => (
            quote!(fn cartesian<__D: #p::Scalar>(&self, __t: __D, __q: &[__D; #n]) -> [__D; #k]),
            quote!(self.__lagrange_bodies(__t, __q)),
        ),
        Params::Array => {
            let np = lit(crate::ast::slot_count(model.params));
            (
                quote!(fn cartesian_with<__S: #p::Scalar, __D: #p::Scalar>(&self, __p: &[__S; #np], __t: __D, __q: &[__D; #n]) -> [__D; #k]),
                quote!(self.__lagrange_bodies_with(__p, __t, __q)),
            )
        }
    };
    quote! {
        #[inline(always)]
        #signature {
            let __bodies = #bodies;
            #(#principal)*
            [#(#rows),*]
        }
    }
}

/// The potential: `potential` with the parameters from the fields, `potential_with` from an array
/// (see [`Params`]).
pub(super) fn potential_fn(model: &Model, params: Params) -> TokenStream {
    let p = private();
    let (n, k) = (lit(model.dof()), lit(model.rows));
    let prelude = prelude();
    let decls = model
        .potentials
        .iter()
        .copied()
        .chain(model.gravities.iter().map(|(g, _)| *g));
    let inputs = bind_inputs_from(model, &model.names_used_by(decls), quote!(__q), params);
    let bodies = bind_bodies(model);
    let (shared, blocks) =
        optimized_blocks_from(model, model.potentials.iter().map(|d| &d.block), params);
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
    let signature = match params {
        Params::Fields => {
            quote!(fn potential<__D: #p::Scalar>(&self, __t: __D, __q: &[__D; #n], __x: &[__D; #k]) -> __D)
        }
        Params::Array => {
            let np = lit(crate::ast::slot_count(model.params));
            quote!(fn potential_with<__S: #p::Scalar, __D: #p::Scalar>(&self, __p: &[__S; #np], __t: __D, __q: &[__D; #n], __x: &[__D; #k]) -> __D)
        }
    };
    quote! {
        #[allow(unused_variables, clippy::all)]
        #signature {
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
                // A body declared by its frame: its centre of mass is its position rows of x.
                let centre = match b.shape {
                    Shape::Planar | Shape::Spatial if b.is_framed() => {
                        let g = quote!(::lagrange::__private::geometry);
                        let r = |i: usize| lit(b.row + member * b.shape.rows() + i);
                        match b.shape {
                            Shape::Planar => {
                                let (x, y) = (r(0), r(1));
                                quote!(#g::vec2(__x[#x], __x[#y]))
                            }
                            _ => {
                                let (x, y, z) = (r(0), r(1), r(2));
                                quote!(#g::vec3(__x[#x], __x[#y], __x[#z]))
                            }
                        }
                    }
                    Shape::Planar | Shape::Spatial => quote!(#body.position),
                    _ => body,
                };
                quote!(__potential -= #ident.dot(&#centre) * __masses[#row];)
            })
        });
    quote!(let #ident: #ty = #block; #(#terms)*)
}
