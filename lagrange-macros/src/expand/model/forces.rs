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

/// Which applied-forces function is written.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(in crate::expand) enum Forces {
    /// `Model::applied_forces`: the parameters from the fields (the inputs, if any, zero).
    Plain,
    /// `Parametrized::applied_forces_with`: the parameters from an array (the inputs zero). A
    /// declaration with inputs has it forward to `ParametrizedHeld` with none held.
    Parametrized,
    /// `Parametrized::applied_forces_with_inputs_held`: the parameters from an array, the inputs
    /// from the held flat values `__u: &[f64]` (zeros past its end).
    ParametrizedHeld,
    /// `ActuatedModel::applied_forces_with_inputs`: the parameters from the fields, the inputs
    /// from `__u: &[__U; NU]`.
    WithInputs,
}

/// The applied forces, as `which` function (see [`Forces`]). A declaration with inputs has its
/// `applied_forces` forward to `applied_forces_with_inputs` at zero inputs.
pub(in crate::expand) fn applied_forces_fn(model: &Model, which: Forces) -> TokenStream {
    forces_fn(model, which, false)
}

/// The forces of a declaration whose forces are all on coordinates and name no body
/// (`Model::GENERALIZED_FORCES_ONLY`), without x: `coordinate_forces` (`Forces::Plain`) or
/// `coordinate_forces_with_inputs` (`Forces::WithInputs`).
pub(in crate::expand) fn coordinate_forces_fn(model: &Model, which: Forces) -> TokenStream {
    forces_fn(model, which, true)
}

/// The applied forces as `which` function, with the Cartesian rows (`applied_forces…`) or, where
/// every force acts on a coordinate and names no body, without (`coordinate_forces…`).
fn forces_fn(model: &Model, which: Forces, on_coordinates: bool) -> TokenStream {
    let (rows, row_args) = match on_coordinates {
        false => {
            let k = lit(model.rows);
            (
                quote!(__x: &[__D; #k], __x_dot: &[__D; #k], __cartesian_force: &mut [__D; #k],),
                quote!(__x, __x_dot, __cartesian_force,),
            )
        }
        true => (quote!(), quote!()),
    };
    let prefix = match on_coordinates {
        false => "applied_forces",
        true => "coordinate_forces",
    };
    match (which, model.input_count()) {
        (Forces::Plain, Some(nu)) => return at_zero_inputs(model, prefix, nu, (&rows, &row_args)),
        (Forces::Parametrized, Some(_)) => return none_held(model, (&rows, &row_args)),
        _ => {}
    }
    let (name, generics, array) = signature(model, which, prefix);
    let body = forces_body(model, which, on_coordinates);
    let n = lit(model.dof());
    quote! {
        #[allow(unused_variables, clippy::all)]
        fn #name #generics(
            &self,
            #array
            __t: __D,
            __q: &[__D; #n],
            __v: &[__D; #n],
            #rows
            __generalized_force: &mut [__D; #n],
        ) {
            #body
        }
    }
}

/// A declaration with inputs: `prefix` (the `Model` function) is `prefix_with_inputs` at zero
/// inputs.
fn at_zero_inputs(
    model: &Model,
    prefix: &str,
    nu: usize,
    (rows, row_args): (&TokenStream, &TokenStream),
) -> TokenStream {
    let p = private();
    let (n, k, nu) = (lit(model.dof()), lit(model.rows), lit(nu));
    let (name, with_inputs) = (
        format_ident!("{prefix}"),
        format_ident!("{prefix}_with_inputs"),
    );
    quote! {
        #[inline(always)]
        fn #name<__D: #p::Scalar>(&self, __t: __D, __q: &[__D; #n], __v: &[__D; #n], #rows __generalized_force: &mut [__D; #n]) {
            <Self as #p::lagrange_core::inputs::ActuatedModel<#n, #k, #nu>>::#with_inputs::<__D, f64>(self, &[0.0; #nu], __t, __q, __v, #row_args __generalized_force)
        }
    }
}

/// A declaration with inputs: `applied_forces_with` is `applied_forces_with_inputs_held` with no
/// inputs held (all zero).
fn none_held(model: &Model, (rows, row_args): (&TokenStream, &TokenStream)) -> TokenStream {
    let p = private();
    let (n, k) = (lit(model.dof()), lit(model.rows));
    let np = lit(crate::ast::slot_count(model.params));
    quote! {
        #[inline(always)]
        fn applied_forces_with<__S: #p::Scalar, __D: #p::Scalar>(&self, __p: &[__S; #np], __t: __D, __q: &[__D; #n], __v: &[__D; #n], #rows __generalized_force: &mut [__D; #n]) {
            <Self as #p::parameters::Parametrized<#n, #k, #np>>::applied_forces_with_inputs_held::<__S, __D>(self, __p, &[], __t, __q, __v, #row_args __generalized_force)
        }
    }
}

/// The function's name, generic parameters and leading argument (the parameters' or the inputs'
/// array) for `which`.
fn signature(
    model: &Model,
    which: Forces,
    prefix: &str,
) -> (TokenStream, TokenStream, TokenStream) {
    let p = private();
    match which {
        Forces::Plain => {
            let name = format_ident!("{prefix}");
            (quote!(#name), quote!(<__D: #p::Scalar>), quote!())
        }
        Forces::Parametrized => {
            let np = lit(crate::ast::slot_count(model.params));
            (
                quote!(applied_forces_with),
                quote!(<__S: #p::Scalar, __D: #p::Scalar>),
                quote!(__p: &[__S; #np],),
            )
        }
        Forces::ParametrizedHeld => {
            let np = lit(crate::ast::slot_count(model.params));
            (
                quote!(applied_forces_with_inputs_held),
                quote!(<__S: #p::Scalar, __D: #p::Scalar>),
                quote!(__p: &[__S; #np], __u: &[f64],),
            )
        }
        Forces::WithInputs => {
            let nu = lit(model.input_count().unwrap_or(0));
            let name = format_ident!("{prefix}_with_inputs");
            (
                quote!(#name),
                quote!(<__D: #p::Scalar, __U: #p::Scalar>),
                quote!(__u: &[__U; #nu],),
            )
        }
    }
}

/// The forces' body: the names they read bound, then each force added where it acts.
fn forces_body(model: &Model, which: Forces, on_coordinates: bool) -> TokenStream {
    let params = match which {
        Forces::Parametrized | Forces::ParametrizedHeld => Params::Array,
        Forces::Plain | Forces::WithInputs => Params::Fields,
    };
    let prelude = prelude();
    let used = model.names_used_by(model.forces.iter().map(|f| f.decl));
    let inputs = bind_inputs_from(model, &used, quote!(__q), params);
    let input_values = bind_input_values(model, &used, which);
    let velocities = bind_coordinates(model, &quote!(__v), "_dot");
    // The bodies and their velocities, where a force names them: a spatial body's frame from its
    // rows costs a decomposition of its inertia (its principal axes), which forces on coordinates
    // alone (motors, joint damping) do not pay.
    let names_body = |velocity: bool| names_a_body(model, &used, velocity) && !on_coordinates;
    let bodies = names_body(false).then(|| bind_bodies(model));
    let names = model.bodies.iter().map(|b| b.decl.ident());
    let body_velocities = model
        .bodies
        .iter()
        .map(|b| format_ident!("{}_dot", b.decl.ident()));
    let velocities_of_bodies = names_body(true).then(|| {
        quote!(let BodyVelocities { #(#names: #body_velocities),* } = self.__lagrange_velocities_from_cartesian(__x, __x_dot);)
    });
    let (shared, blocks) =
        optimized_blocks_from(model, model.forces.iter().map(|f| &f.decl.block), params);
    let forces = model
        .forces
        .iter()
        .zip(blocks)
        .map(|(force, block)| applied_force(model, force, &block));
    quote! {
        #prelude
        #inputs
        #input_values
        #shared
        #velocities
        #bodies
        #velocities_of_bodies
        #(#forces)*
    }
}

/// Whether `used` names a body (`velocity`: a body's velocity, `bob_dot`; the velocity of
/// `r#box` is `box_dot`).
pub(in crate::expand) fn names_a_body(
    model: &Model,
    used: &std::collections::BTreeSet<String>,
    velocity: bool,
) -> bool {
    use syn::ext::IdentExt;
    model.bodies.iter().any(|b| {
        let ident = b.decl.ident();
        match velocity {
            false => used.contains(&ident.to_string()),
            true => used.contains(&format!("{}_dot", ident.unraw())),
        }
    })
}

/// `let tau: __D = input::<__U, __D>(&__u[0]);` for each input the forces name (an array input
/// element by element): from `__u` in `applied_forces_with_inputs` and (held values, zeros past
/// its end) in `applied_forces_with_inputs_held`, zero elsewhere.
fn bind_input_values(
    model: &Model,
    used: &std::collections::BTreeSet<String>,
    which: Forces,
) -> TokenStream {
    let p = private();
    let value = |slot: usize| match which {
        Forces::WithInputs => {
            let slot = lit(slot);
            quote!(#p::lagrange_core::inputs::input::<__U, __D>(&__u[#slot]))
        }
        Forces::ParametrizedHeld => {
            let slot = lit(slot);
            quote!(<__D>::from(__u.get(#slot).copied().unwrap_or(0.0)))
        }
        Forces::Plain | Forces::Parametrized => quote!(<__D>::from(0.0)),
    };
    let mut slot = 0;
    let mut bindings = Vec::new();
    for u in model.inputs {
        let first = slot;
        slot += u.slots();
        if !used.contains(&u.ident.to_string()) {
            continue;
        }
        let ident = &u.ident;
        bindings.push(match &u.array {
            Some((_, len)) => {
                let (values, len) = ((first..first + len).map(value), lit(*len));
                quote!(let #ident: [__D; #len] = [#(#values),*];)
            }
            None => {
                let value = value(first);
                quote!(let #ident: __D = #value;)
            }
        });
    }
    quote!(#(#bindings)*)
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
