//! Expansion: the checked model into the module a user gets (see the README's "The declaration").
//!
//! Generated code names only `::lagrange::__private::…` paths. Per declaration it writes:
//! `Coords<T = f64>` and its `Coordinates` impl, `DOF`, `State`, `Bodies<T = f64>` (each body and
//! point's position: `Vec2`/`Vec3`/`Planar`/`Spatial`), `BodyVelocities<T = f64>` (a particle or
//! point's velocity vector; a planar body's centre-of-mass velocity and angular velocity as a
//! `Planar`; a spatial body's centre-of-mass velocity `Vec3`), inherent `bodies` and
//! `body_velocities`, and the `Model` and `Mechanism` impls. `potential` and `applied_forces` are
//! only written when something is declared for them.
//!
//! One file per artifact: [`coords`] writes `Coords`, its `Coordinates` impl, `DOF` and `State`;
//! [`bodies`] `Bodies`, `BodyVelocities` and the inherent impl; [`model`] the `Model` impl;
//! [`mechanism`] the `Mechanism` impl; [`constraints`] the `Constraints` impl; [`tree`] the
//! `Tree` impl of a tree of translations; [`declaration`] the `Declaration` impl (names and flat
//! values, for the C export); [`drawable`] the `Drawable` impl (bodies, links and constraint
//! bodies, for an animation); [`parametrized`] the `Parametrized` impl (the position, potential and
//! force functions with the parameters as an array of any scalar, for sensitivities); [`fallback`] the stubs written after a failed check.
//! This file holds the entry [`expand`], the whole module ([`generate`]) and the helpers the
//! others share.

mod bodies;
mod closed_form;
mod constraints;
mod coords;
mod declaration;
mod drawable;
mod fallback;
mod inputs;
mod mechanism;
mod model;
mod parametrized;
mod rigid;
mod tree;

use bodies::{bodies_structs, inherent_impl};
use constraints::constraints_impl;
use coords::coords_items;
use declaration::declaration_impl;
use drawable::drawable_impl;
use mechanism::{mechanism_impl, Equations, Glue, Positions};
use model::{gradient_on_trees, model_impl};
use parametrized::parametrized_items;

use crate::ast::{Field, Mechanism};
use crate::check::{self, Dim, Model, Shape};
use crate::ctxt::{self, Ctxt};
use crate::lift;
use crate::optimize;
use proc_macro2::{Span, TokenStream};
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
        Err(errors) => fallback::fallback(&mechanism, model.as_ref(), errors),
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
        use #p::geometry::{planar, rot3, rot_axis, rot_mrp, rot_vector, rot_x, rot_y, rot_z, rpy, spatial, vec2, vec3, Planar, Rot3, Spatial, Vec2, Vec3};
        #[allow(unused_imports)]
        use #p::DualNum as _;
    }
}

/// Terms of the closed form per body beyond which the articulated-body recursion of a tree is
/// faster (measured on the link-by-link chains, BENCHMARKS.md §2: 8 links, 23 terms per body, take
/// less time in closed form — the recursion executes fewer instructions there, but in series, leaf
/// to root and back; 16 links, 47 per body, less by the recursion).
const RECURSION_TERMS_PER_BODY: usize = 32;

/// Whether `tree`'s articulated-body recursion (each coordinate moves one body) beats the closed
/// form's `equations`: the closed form's terms grow with the square of the bodies, the
/// recursion's work with the bodies.
fn recursion_is_cheaper(
    model: &Model,
    equations: &crate::symbolic::Equations,
    tree: Option<&crate::structure::Tree>,
) -> bool {
    tree.is_some_and(|tree| {
        tree.moves_each_coordinate_once(model.dof())
            && equations.terms() > RECURSION_TERMS_PER_BODY * tree.bodies.len()
    })
}

/// Whether a rigid tree's articulated-body recursion beats the closed form's `equations`, by the
/// same measure as [`recursion_is_cheaper`].
fn rigid_recursion_is_cheaper(
    equations: &crate::symbolic::Equations,
    tree: Option<&crate::structure::rigid::RigidTree>,
) -> bool {
    tree.is_some_and(|tree| equations.terms() > RECURSION_TERMS_PER_BODY * tree.nodes.len())
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
    let constrained = (!model.constraints.is_empty()).then_some(model.constraint_row_count());
    // Affine positions: J and M's factors prepared once, for the free and the constrained solve.
    let affine = crate::affine::is_affine(model);
    let positions = match affine {
        true => Positions::Affine {
            straight_line: model.forces.is_empty()
                && gradient_on_trees(model)
                && (model.constraints.is_empty() || constraints::written_holonomic(model)),
        },
        false => Positions::General,
    };
    let (equations, equations_items) = equations_items(model, affine);
    let rigid = match equations {
        Equations::Rigid(b) => Some(b),
        _ => None,
    };
    let mechanism_impl = mechanism_impl(&Glue {
        params: model.params_ident,
        n: model.dof(),
        k: model.rows,
        constrained,
        equations,
        rheonomic: model.rheonomic,
        positions,
        inputs: model.input_count(),
        charts: &model.charts,
        angular_velocities: &model.angular_velocities,
    });
    let constraints_impl = constrained.map(|_| constraints_impl(model, rigid));
    let declaration_impl = declaration_impl(model);
    let drawable_impl = drawable_impl(model);
    let parametrized = parametrized_items(model);
    let inputs = inputs::inputs_items(model);
    quote! {
        #(#attrs)*
        #vis mod #ident {
            #(#other_items)*
            #params_struct
            #inputs
            #coords
            #bodies
            #inherent
            #model_impl
            #equations_items
            #mechanism_impl
            #constraints_impl
            #declaration_impl
            #drawable_impl
            #parametrized
        }
    }
}

/// How the equations of motion are formed, and the items that way needs: in closed form where
/// the positions are read (for affine positions too: the plain mechanism's call, which prepares
/// nothing), otherwise the articulated recursion of a rigid tree, a tree of translations from
/// each body's own seeds, or the dense pass.
fn equations_items(model: &Model, affine: bool) -> (Equations, TokenStream) {
    let tree = crate::structure::tree(model);
    // Positions affine in the coordinates need no recursion: M is a constant.
    let rigid = match affine {
        true => None,
        false => crate::structure::rigid::rigid_tree(model),
    };
    // Inputs reach the forces as data the closed form and a tree of translations do not read:
    // a declaration with inputs takes the rigid tree's recursion or the dense pass. Angular
    // velocities are the rigid tree's alone (the checks saw that it takes them).
    let actuated = model.inputs_ident.is_some();
    let rigid_only = actuated || !model.angular_velocities.is_empty();
    let tree = tree.filter(|_| !rigid_only);
    let closed_form = crate::symbolic::equations(model).filter(|_| !rigid_only);
    let closed_form = closed_form.filter(|equations| {
        !recursion_is_cheaper(model, equations, tree.as_ref())
            && !rigid_recursion_is_cheaper(equations, rigid.as_ref())
    });
    let rigid = rigid.filter(|_| closed_form.is_none());
    let tree = tree.filter(|_| closed_form.is_none() && rigid.is_none());
    let tree_items = tree.as_ref().map(|tree| tree::tree_items(model, tree));
    let rigid_items = rigid.as_ref().map(|tree| rigid::rigid_items(model, tree));
    let closed_form_impl = closed_form
        .as_ref()
        .map(|equations| closed_form::closed_form_impl(model, equations));
    let equations = match (&closed_form_impl, &rigid, &tree) {
        (Some((_, coefficients)), _, _) => Equations::ClosedForm(*coefficients),
        (None, Some(rigid), _) => Equations::Rigid(rigid.nodes.len()),
        (None, None, Some(tree)) => Equations::Tree(tree.width, tree.bodies.len()),
        (None, None, None) => Equations::Dense,
    };
    let closed_form_impl = closed_form_impl.map(|(tokens, _)| tokens);
    (
        equations,
        quote!(#tree_items #rigid_items #closed_form_impl),
    )
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

/// Where a generated function reads the parameters from: the parameter struct's `f64` fields, or
/// the array `__p: &[__S; NP]` of any scalar that the `Parametrized` variants take (see
/// [`parametrized`]).
#[derive(Clone, Copy, PartialEq, Eq)]
pub(crate) enum Params {
    Fields,
    Array,
}

/// `let theta1 = …; let l1 = <__D>::from(self.l1); let t = __t;` for the names `used`.
fn bind_inputs(model: &Model, used: &BTreeSet<String>, q: TokenStream) -> TokenStream {
    bind_inputs_from(model, used, q, Params::Fields)
}

/// [`bind_inputs`] with the parameters read from `params`: from an array, parameter i is
/// `let l1: __D = lift::<__S, __D>(&__p[i]);`.
fn bind_inputs_from(
    model: &Model,
    used: &BTreeSet<String>,
    q: TokenStream,
    params: Params,
) -> TokenStream {
    let d = scalar();
    let coords = bind_coordinates(model, &q, "");
    let mut slot = 0;
    let mut bindings = Vec::new();
    for f in model.params {
        let first = slot;
        slot += f.slots();
        if !used.contains(&f.ident.to_string()) {
            continue;
        }
        bindings.push(match params {
            Params::Fields => f.bind_lifted(&d),
            Params::Array => parameter_from_array(f, first),
        });
    }
    let time = used.contains("t").then(|| quote!(let t = __t;));
    quote! {
        #coords
        #( #bindings )*
        #time
    }
}

/// `let l1: __D = lift::<__S, __D>(&__p[i]);` for the parameter whose first slot of the array
/// `__p` is `i` (`let m: [__D; 3] = [lift(&__p[i]), lift(&__p[i + 1]), lift(&__p[i + 2])];` for
/// an array).
fn parameter_from_array(f: &crate::ast::Field, first: usize) -> TokenStream {
    let (d, p, ident) = (scalar(), private(), &f.ident);
    let lifted = |i: usize| {
        let i = lit(i);
        quote!(#p::parameters::lift::<__S, #d>(&__p[#i]))
    };
    match &f.array {
        Some((_, n)) => {
            let (elements, n) = ((first..first + n).map(lifted), lit(*n));
            quote!(let #ident: [#d; #n] = [#(#elements),*];)
        }
        None => {
            let value = lifted(first);
            quote!(let #ident: #d = #value;)
        }
    }
}

/// The user's `blocks` rewritten by [`optimize`] (parameter-only subexpressions in `f64`, shared
/// `sin_cos`) and lifted to `__D`, with the `let`s the rewrites need (placed after the inputs).
/// With the parameters read from an array ([`Params::Array`]) they may carry derivatives, so no
/// parameter-only subexpression is taken out to `f64`.
pub(crate) fn optimized_blocks_from<'d>(
    model: &Model,
    blocks: impl IntoIterator<Item = &'d syn::Block>,
    params: Params,
) -> (TokenStream, Vec<syn::Block>) {
    let d = scalar();
    let mut blocks: Vec<syn::Block> = blocks.into_iter().cloned().collect();
    let params: BTreeSet<String> = match params {
        Params::Fields => model.scalar_parameter_names(),
        Params::Array => BTreeSet::new(),
    };
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

/// `let Bodies { bob1, .. } = …;` from x.
fn bind_bodies(model: &Model) -> TokenStream {
    let names = model.bodies.iter().map(|b| b.decl.ident());
    quote!(let Bodies { #(#names),* } = self.__lagrange_bodies_from_cartesian(__x);)
}
