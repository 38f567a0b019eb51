//! A declaration's `#[inputs]`: the struct (with what it derives), its `Inputs` impl (names and
//! flat values, zero by default), the mechanism's `Actuated` impl naming it, and the
//! `ActuatedModel` impl whose applied forces read the inputs (see `lagrange_core::inputs`).

use super::coords::{flat_fields, FlatFields};
use super::model::{applied_forces_fn, coordinate_forces_fn, generalized_forces_only, Forces};
use super::{lit, private};
use crate::check::Model;
use proc_macro2::TokenStream;
use quote::quote;

/// Every item of the inputs, or nothing for a declaration without `#[inputs]`.
pub(super) fn inputs_items(model: &Model) -> TokenStream {
    let (Some((inputs_struct, fields)), Some(count)) =
        (&model.mechanism.inputs, model.input_count())
    else {
        return TokenStream::new();
    };
    let p = private();
    let (ident, params) = (&inputs_struct.ident, model.params_ident);
    let (n, k, nu) = (lit(model.dof()), lit(model.rows), lit(count));
    // The user's attributes but their derives: the struct derives what `Inputs` needs itself.
    let mut declared = inputs_struct.clone();
    declared.attrs.retain(|a| !a.path().is_ident("derive"));
    let FlatFields {
        names,
        flat: values,
        rebuilt: fields_from,
    } = flat_fields(fields, &quote!(__values));
    let forces = applied_forces_fn(model, Forces::WithInputs);
    let coordinate_forces = (!model.forces.is_empty() && generalized_forces_only(model))
        .then(|| coordinate_forces_fn(model, Forces::WithInputs));
    let coordinates = input_coordinates(model).map(|js| {
        let js = js.into_iter().map(lit);
        quote!(const COORDINATES: #p::core::option::Option<[usize; #nu]> = #p::core::option::Option::Some([#(#js),*]);)
    });
    quote! {
        #[derive(#p::core::clone::Clone, #p::core::marker::Copy, #p::core::fmt::Debug, #p::core::cmp::PartialEq)]
        #declared
        impl #p::core::default::Default for #ident {
            /// Every input zero.
            fn default() -> Self {
                <Self as #p::lagrange_core::inputs::Inputs<#nu>>::from_array([0.0; #nu])
            }
        }
        impl #p::lagrange_core::inputs::Inputs<#nu> for #ident {
            const NAMES: [&'static str; #nu] = [#(#names),*];
            #[inline]
            fn to_array(&self) -> [f64; #nu] {
                [#(#values),*]
            }
            #[inline]
            fn from_array(__values: [f64; #nu]) -> Self {
                #ident { #(#fields_from),* }
            }
        }
        impl #p::lagrange_core::inputs::Actuated<#nu> for #params {
            type Inputs = #ident;
            #coordinates
        }
        impl #p::lagrange_core::inputs::ActuatedModel<#n, #k, #nu> for #params {
            #forces
            #coordinate_forces
        }
    }
}

/// The `Dynamics` items of a declaration with `nu` inputs (N = `n`, K = `k`, `constrained` rows,
/// `rigid` the bodies of a rigid tree it takes the recursions of): the inputs' names, and q̈ with
/// inputs of the state's scalar — the declaration with those inputs held (`WithInputs`) through
/// the constrained solve where it has rows, else the rigid tree's recursion (whose velocities may
/// be angular velocities), else the generic solve.
pub(super) fn dynamics_items(
    (n, k, nu): (usize, usize, usize),
    constrained: Option<usize>,
    rigid: bool,
) -> TokenStream {
    let p = private();
    let (n, k, nu) = (lit(n), lit(k), lit(nu));
    let held =
        quote!(#p::lagrange_core::inputs::WithInputs::<'_, Self, S, #nu>::held(self, inputs));
    let solve = match (constrained, rigid) {
        (Some(c), _) => {
            let c = lit(c);
            quote!(#p::lagrange_core::constraints::accelerations::<_, S, #n, #k, #c>(&#held, t, q, v))
        }
        (None, true) => quote!(self.__lagrange_rigid_accelerations(
            &#held,
            &self.__lagrange_rigid_constants(),
            t,
            q,
            v
        )),
        (None, false) => {
            quote!(#p::dynamics::accelerations_generic::<_, S, #n, #k>(&#held, t, q, v))
        }
    };
    quote! {
        const INPUT_NAMES: &'static [&'static str] =
            &<<Self as #p::lagrange_core::inputs::Actuated<#nu>>::Inputs as #p::lagrange_core::inputs::Inputs<#nu>>::NAMES;
        #[inline]
        fn accelerations_with_inputs_at<S: #p::Scalar>(&self, inputs: &[S], t: S, q: &[S; #n], v: &[S; #n]) -> #p::Result<[S; #n]> {
            #solve
        }
    }
}

/// The coordinate each input acts on, in input order, where every input is the whole of one
/// `#[generalized_force(on = q)]` (`{ u }`, or `{ tau[2] }` for an element) named by no other
/// force, each on a coordinate of its own; `None` otherwise.
fn input_coordinates(model: &Model) -> Option<Vec<usize>> {
    // Slot of the input an expression is, if it is one: `u`, or `tau[k]` with a literal k.
    let slot_of = |expr: &syn::Expr| crate::ast::flat_slot(model.inputs, expr);
    let count = model.input_count()?;
    let mut coordinates: Vec<Option<usize>> = vec![None; count];
    let inputs: std::collections::BTreeSet<String> =
        model.inputs.iter().map(|u| u.ident.to_string()).collect();
    for force in &model.forces {
        let whole = match force.decl.block.stmts.as_slice() {
            [syn::Stmt::Expr(expr, None)] if force.kind == crate::attr::Kind::GeneralizedForce => {
                slot_of(expr)
            }
            _ => None,
        };
        match whole {
            // A second force for the same input, or a second input on the coordinate.
            Some(slot)
                if coordinates[slot].is_none() && !coordinates.contains(&Some(force.target)) =>
            {
                coordinates[slot] = Some(force.target)
            }
            Some(_) => return None,
            // Any other force that names an input.
            None if !model.names_used_by([force.decl]).is_disjoint(&inputs) => return None,
            None => {}
        }
    }
    coordinates.into_iter().collect()
}
