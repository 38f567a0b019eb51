//! `Model::validate` and its one-branch form `parameters_pass`: the parameters finite, each body's
//! mass, inertia and centre of mass valid, and every rotation the functions write from constants a
//! rotation.

use super::super::{lit, prelude, private};
use super::{attribute_ident, attribute_value, mass_bindings};
use crate::attr::Inertia;
use crate::check::{attribute_sets, Body, Model, Shape};
use proc_macro2::TokenStream;
use quote::quote;
use std::collections::BTreeSet;
use syn::visit::{self, Visit};

/// `validate`, and `parameters_pass` where every check folds into one test.
pub(super) fn validate_fn(model: &Model) -> TokenStream {
    let p = private();
    let (n, k) = (lit(model.dof()), lit(model.rows));
    let finite = model.params.iter().map(finite_parameter);
    let bindings = mass_bindings(model);
    let coms = com_bindings(model);
    let bodies = attribute_sets(model.bodies.iter().filter(|b| b.shape.has_mass()));
    let bodies = bodies.map(|(body, member)| body_checks(body, member));
    let rotations = rotation_checks(model);
    // Centres of mass and rotations are written with the geometry's constructors.
    let prelude = (model.bodies.iter().any(|b| b.has_com()) || !rotations.is_empty()).then(prelude);
    let fast = rotations
        .is_empty()
        .then(|| parameters_pass_fn(model))
        .flatten();
    let fast_path = fast.is_some().then(|| {
        quote! {
            if <Self as #p::Model<#n, #k>>::parameters_pass(self) {
                return #p::core::result::Result::Ok(());
            }
        }
    });
    quote! {
        #fast
        #[allow(unused_variables, clippy::all)]
        fn validate(&self) -> #p::Result<()> {
            #fast_path
            #(#finite)*
            #prelude
            #bindings
            #coms
            #(#bodies)*
            #(#rotations)*
            #p::core::result::Result::Ok(())
        }
    }
}

/// A parameter is finite: `NonFiniteParameter` naming it (`m[2]` for an element of an array).
fn finite_parameter(field: &crate::ast::Field) -> TokenStream {
    let p = private();
    let ident = &field.ident;
    let check = |value: TokenStream, name: String| {
        quote! {
            if !#value.is_finite() {
                return #p::core::result::Result::Err(#p::Error::NonFiniteParameter { name: #name, value: #value });
            }
        }
    };
    match &field.array {
        Some((_, n)) => (0..*n)
            .map(|k| check(quote!(self.#ident[#k]), format!("{ident}[{k}]")))
            .collect(),
        None => check(quote!(self.#ident), ident.to_string()),
    }
}

/// The common case first, branch-free: x·0 is 0 exactly when x is finite, so one comparison
/// checks every parameter (and every centre of mass); masses and moments compare positive. Only a
/// failure goes on to the checks that name the culprit. `None` when a spatial body's moments or
/// tensor have more to check.
fn parameters_pass_fn(model: &Model) -> Option<TokenStream> {
    if model.bodies.iter().any(|b| b.shape == Shape::Spatial) {
        return None;
    }
    let fields = model.params.iter().map(|f| match &f.array {
        // Every element of an array of parameters.
        Some((_, n)) => {
            let ident = &f.ident;
            let k = 0..*n;
            quote!(#( + self.#ident[#k] )*)
        }
        None => {
            let ident = &f.ident;
            quote!(+ self.#ident)
        }
    });
    // Every mass and moment: one sum for their finiteness (with the parameters'), one comparison
    // each for their sign.
    let derived: Vec<_> = attribute_sets(model.bodies.iter().filter(|b| b.shape.has_mass()))
        .flat_map(|(body, member)| {
            let mass = attribute_ident("mass", body, member);
            let inertia = attribute_ident("inertia", body, member);
            match body.shape {
                Shape::Planar => vec![mass, inertia],
                _ => vec![mass],
            }
        })
        .collect();
    // A planar body's centre of mass: finite, of either sign.
    let coms = attribute_sets(model.bodies.iter().filter(|b| b.has_com()));
    let coms = coms.map(|(body, member)| {
        let com = attribute_ident("com", body, member);
        quote!(+ #com.x + #com.y)
    });
    let prelude = model.bodies.iter().any(|b| b.has_com()).then(prelude);
    let bindings = mass_bindings(model);
    let com_bindings = com_bindings(model);
    // The sum of finite values is finite (one that overflows only sends the caller to the checks
    // that name a culprit, which then pass), and s·0 is 0 exactly when s is finite.
    Some(quote! {
        #[inline(always)]
        #[allow(unused_variables, clippy::all)]
        fn parameters_pass(&self) -> bool {
            #prelude
            #bindings
            #com_bindings
            ((0.0 #( #fields )* #( + #derived )* #(#coms)*) * 0.0 == 0.0) #( & (#derived > 0.0) )*
        }
    })
}

/// `let __com_<body>: Vec3<f64> = <com>;` (or `Vec2`) for each body with a `com`, after the
/// parameters are bound as `f64`.
fn com_bindings(model: &Model) -> TokenStream {
    let g = quote!(::lagrange::__private::geometry);
    let coms = attribute_sets(model.bodies.iter()).filter_map(|(body, member)| {
        let com = body.decl.args.com.as_ref()?;
        let ident = attribute_ident("com", body, member);
        let ty = match body.shape {
            Shape::Planar => quote!(#g::Vec2<f64>),
            _ => quote!(#g::Vec3<f64>),
        };
        let com = attribute_value(body, member, com);
        Some(quote!(let #ident: #ty = #com;))
    });
    quote!(#(#coms)*)
}

/// The checks of one body with mass: its mass, its inertia (one moment, principal moments, or a
/// full tensor) and its centre of mass.
fn body_checks(body: &Body, member: Option<usize>) -> TokenStream {
    let p = private();
    let err = quote!(return #p::core::result::Result::Err);
    let name = match member {
        Some(k) => format!("{}[{k}]", body.decl.ident()),
        None => body.decl.ident().to_string(),
    };
    let mass = attribute_ident("mass", body, member);
    let inertia = attribute_ident("inertia", body, member);
    let check_mass = quote! {
        if !(#mass.is_finite() && #mass > 0.0) {
            #err(#p::Error::InvalidInertia { body: #name, reason: #p::std::format!("mass must be positive and finite, got {}", #mass) });
        }
    };
    let check_inertia = match (body.shape, &body.decl.args.inertia) {
        (Shape::Planar, _) => quote! {
            if !(#inertia.is_finite() && #inertia > 0.0) {
                #err(#p::Error::InvalidInertia { body: #name, reason: #p::std::format!("moment of inertia must be positive and finite, got {}", #inertia) });
            }
        },
        (Shape::Spatial, Some(Inertia::Tensor(_))) => quote! {
            if let #p::core::result::Result::Err(__error) = #p::inertia::check_inertia_tensor(#name, &#inertia) {
                #err(__error);
            }
        },
        (Shape::Spatial, _) => quote! {
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
    let check_com = body.has_com().then(|| {
        let com = attribute_ident("com", body, member);
        quote! {
            if let #p::core::result::Result::Err(__error) = #p::inertia::check_centre_of_mass(#name, &#com.to_array()) {
                #err(__error);
            }
        }
    });
    quote!(#check_mass #check_inertia #check_com)
}

/// A `rot3(..)` or `rot_axis(axis, ..)` whose matrix or axis is written from literals and
/// parameters alone, in the function named `function`.
struct ConstantRotation {
    function: String,
    /// `rot3`'s rows, or `rot_axis`'s axis.
    argument: syn::Expr,
    is_axis: bool,
}

/// For each rotation a function writes from constants ([`constant_rotations`]), its check in
/// `validate`: the matrix a rotation, the axis a direction (`lagrange_core::inertia`).
fn rotation_checks(model: &Model) -> Vec<TokenStream> {
    let p = private();
    constant_rotations(model)
        .into_iter()
        .map(|rotation| {
            let (name, argument) = (&rotation.function, &rotation.argument);
            let check = match rotation.is_axis {
                true => quote!(#p::inertia::check_axis(#name, &#argument)),
                false => quote!(#p::inertia::check_rotation(#name, &rot3(#argument))),
            };
            quote! {
                if let #p::core::result::Result::Err(__error) = #check {
                    return #p::core::result::Result::Err(__error);
                }
            }
        })
        .collect()
}

/// Every `rot3(rows)` and `rot_axis(axis, angle)` of the declaration's functions whose `rows` or
/// `axis` names parameters and geometry constructors only (no coordinate, body, local or index):
/// a constant of the declaration, checked once in `validate`. One that depends on anything else is
/// evaluated as it comes.
fn constant_rotations(model: &Model) -> Vec<ConstantRotation> {
    let params: BTreeSet<String> = model.params.iter().map(|f| f.ident.to_string()).collect();
    let mut found = Vec::new();
    for decl in &model.mechanism.decls {
        let mut calls = RotationCalls::default();
        calls.visit_block(&decl.block);
        for (argument, is_axis) in calls.calls {
            let constant = crate::names::free_names_of_expr(&argument)
                .iter()
                .map(|i| i.to_string())
                .all(|name| {
                    (params.contains(&name) && !calls.bound.contains(&name))
                        || crate::check::GEOMETRY_FUNCTIONS.contains(&name.as_str())
                });
            if constant {
                found.push(ConstantRotation {
                    function: decl.ident().to_string(),
                    argument,
                    is_axis,
                });
            }
        }
    }
    found
}

/// The `rot3` and `rot_axis` calls of a block (their rows or axis, and which), and every name a
/// pattern in it binds (a local that shadows a parameter is not that parameter).
#[derive(Default)]
struct RotationCalls {
    calls: Vec<(syn::Expr, bool)>,
    bound: BTreeSet<String>,
}

impl<'ast> Visit<'ast> for RotationCalls {
    fn visit_expr_call(&mut self, call: &'ast syn::ExprCall) {
        if let syn::Expr::Path(path) = crate::ast::ungroup(&call.func) {
            let args: Vec<&syn::Expr> = call.args.iter().collect();
            match (path.path.get_ident(), args.as_slice()) {
                (Some(f), [rows]) if f == "rot3" => self.calls.push(((*rows).clone(), false)),
                (Some(f), [axis, _]) if f == "rot_axis" => self.calls.push(((*axis).clone(), true)),
                _ => {}
            }
        }
        visit::visit_expr_call(self, call);
    }
    fn visit_pat_ident(&mut self, p: &'ast syn::PatIdent) {
        self.bound.insert(p.ident.to_string());
        visit::visit_pat_ident(self, p);
    }
    fn visit_item(&mut self, _: &'ast syn::Item) {}
}
