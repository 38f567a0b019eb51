//! The `Parametrized` impl: the position, potential and force functions again, with the parameters
//! read from an array `__p: &[__S; NP]` of any scalar instead of the struct's `f64` fields, so a
//! simulation can carry derivatives with respect to them (`lagrange_core::parameters`). The
//! functions are the ones [`super::model`] and [`super::bodies`] write, with [`Params::Array`];
//! being generic, they cost nothing in a program that never differentiates by a parameter.

use super::bodies::bodies_fn;
use super::model::{applied_forces_fn, cartesian_fn, potential_fn, Forces};
use super::{lit, private, Params};
use crate::attr::Inertia;
use crate::check::Model;
use crate::names::free_names_of_expr;
use proc_macro2::TokenStream;
use quote::quote;
use std::collections::BTreeSet;

/// The inherent `__lagrange_bodies_with` and the `Parametrized` impl.
pub(super) fn parametrized_items(model: &Model) -> TokenStream {
    let p = private();
    let (params, n, k, np) = (
        model.params_ident,
        lit(model.dof()),
        lit(model.rows),
        lit(crate::ast::slot_count(model.params)),
    );
    // One entry per value: an array of parameters by element (`m[0]`, `m[1]`, ...).
    let plain = plain_parameters(model);
    let (mut names, mut values, mut seedable) = (Vec::new(), Vec::new(), Vec::new());
    for f in model.params {
        let (ident, seeds) = (&f.ident, !plain.contains(&f.ident.to_string()));
        match &f.array {
            Some((_, len)) => {
                for k in 0..*len {
                    names.push(format!("{ident}[{k}]"));
                    let k = lit(k);
                    values.push(quote!(self.#ident[#k]));
                    seedable.push(seeds);
                }
            }
            None => {
                names.push(ident.to_string());
                values.push(quote!(self.#ident));
                seedable.push(seeds);
            }
        }
    }
    let bodies = bodies_fn(model, Params::Array);
    let cartesian = cartesian_fn(model, Params::Array);
    let has_potential = !model.potentials.is_empty() || !model.gravities.is_empty();
    let potential = has_potential.then(|| potential_fn(model, Params::Array));
    let forces = (!model.forces.is_empty()).then(|| applied_forces_fn(model, Forces::Parametrized));
    let held = (!model.forces.is_empty() && model.input_count().is_some())
        .then(|| applied_forces_fn(model, Forces::ParametrizedHeld));
    quote! {
        impl #params {
            #bodies
        }

        impl #p::parameters::Parametrized<#n, #k, #np> for #params {
            const PARAMETER_NAMES: [&'static str; #np] = [#(#names),*];
            const SEEDABLE: [bool; #np] = [#(#seedable),*];
            #[inline(always)]
            fn parameters(&self) -> [f64; #np] {
                [#(#values),*]
            }
            #cartesian
            #potential
            #forces
            #held
        }
    }
}

/// Parameters the dynamics take as plain `f64`: those named in a mass, a moment of inertia, a
/// centre of mass or a uniform field (`Model::masses`, the bodies' mass frames, `Model::weights`).
fn plain_parameters(model: &Model) -> BTreeSet<String> {
    let mut names: BTreeSet<String> = model
        .names_used_by(model.uniform_gravities.iter().map(|(g, _)| *g))
        .into_iter()
        .collect();
    for body in &model.bodies {
        let args = &body.decl.args;
        let inertia = args.inertia.as_ref().map(Inertia::expr);
        for expr in args
            .mass
            .iter()
            .chain(inertia.as_ref())
            .chain(args.com.as_ref())
        {
            names.extend(free_names_of_expr(expr).iter().map(|i| i.to_string()));
        }
    }
    names
}
