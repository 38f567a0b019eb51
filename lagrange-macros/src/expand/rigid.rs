//! Expansion of a kinematic tree of rigid bodies (see [`crate::structure::rigid`]): the
//! `RigidTree` impl (each joint as the compiler knows it), the constants a validated handle
//! prepares, and q̈ by the articulated-body algorithm written out body by body, each call with a
//! constant body index so that it is compiled for its own joint (`lagrange_core::tree::rigid`).

use crate::attr::Inertia;
use crate::check::{family_index, Dim, Model, Shape};
use crate::expand::{lit, prelude, private};
use crate::structure::rigid::{product, Axis, Joint, Node, Offset, RigidTree};
use proc_macro2::TokenStream;
use quote::{format_ident, quote};

/// Above this many bodies the sweeps are the runtime's loops rather than one call per body: the
/// written-out form's code grows with the bodies, and so does its build time.
const MAX_WRITTEN_BODIES: usize = 64;

/// The `RigidTree` impl and the inherent functions the `Dynamics` impl calls.
pub fn rigid_items(model: &Model, tree: &RigidTree) -> TokenStream {
    let p = private();
    let params = model.params_ident;
    let (n, b) = (lit(model.dof()), lit(tree.nodes.len()));
    let joints = tree.nodes.iter().map(|node| joint(node, &tree.nodes));
    let constants = constants_fn(model, tree);
    let accelerations = accelerations_fn(model, tree);
    quote! {
        impl #p::tree::rigid::RigidTree<#n, #b> for #params {
            const JOINTS: [#p::tree::rigid::Joint; #b] = [#(#joints),*];
        }
        impl #params {
            #constants
            #accelerations
        }
    }
}

/// A joint as a constant of the runtime.
fn joint(node: &Node, nodes: &[Node]) -> TokenStream {
    let r = quote!(::lagrange::__private::tree::rigid);
    let axis = |a: Axis| match a {
        Axis::X => quote!(#r::spatial::Axis::X),
        Axis::Y => quote!(#r::spatial::Axis::Y),
        Axis::Z => quote!(#r::spatial::Axis::Z),
    };
    let (kind, coordinate) = match node.joint {
        Joint::Revolute(a, slot) => {
            let a = axis(a);
            (quote!(#r::JointKind::Revolute(#a)), slot)
        }
        Joint::Prismatic(a, slot) => {
            let a = axis(a);
            (quote!(#r::JointKind::Prismatic(#a)), slot)
        }
        Joint::Fixed => (quote!(#r::JointKind::Fixed), 0),
    };
    let parent = match node.parent {
        Some(p) => {
            let p = lit(p);
            quote!(::lagrange::__private::core::option::Option::Some(#p))
        }
        None => quote!(::lagrange::__private::core::option::Option::None),
    };
    let coordinate = lit(coordinate);
    let rotated = node.rotated(nodes);
    let offset = node.offset_zeros.map(|zero| !zero);
    quote!(#r::Joint {
        parent: #parent,
        kind: #kind,
        coordinate: #coordinate,
        rotated: #rotated,
        offset: [#(#offset),*],
    })
}

/// `fn __lagrange_rigid_constants`: E, r and the inertia of every body, and the uniform field,
/// from the parameters, in `f64` (see the module docs of `crate::structure::rigid`).
fn constants_fn(model: &Model, tree: &RigidTree) -> TokenStream {
    let p = private();
    let b = lit(tree.nodes.len());
    let prelude = prelude();
    let params = model.params.iter().map(|f| &f.ident);
    let bodies = tree
        .nodes
        .iter()
        .enumerate()
        .map(|(i, node)| body_constants(model, tree, i, node));
    let names = (0..tree.nodes.len()).map(|i| format_ident!("__body_{}", i));
    let gravity = gravity(model);
    quote! {
        #[allow(unused_variables, unused_parens, clippy::all)]
        fn __lagrange_rigid_constants(&self) -> #p::tree::rigid::RigidConstants<#b> {
            #prelude
            #( let #params: f64 = self.#params; )*
            #(#bodies)*
            #p::tree::rigid::RigidConstants {
                bodies: [#(#names),*],
                gravity: (#gravity).to_array(),
            }
        }
    }
}

/// `Σ X c` as a `Vec3<f64>` expression.
fn sum(offsets: &[Offset]) -> TokenStream {
    let terms = offsets.iter().map(|o| {
        let (turn, vector) = (product(&o.factors), &o.vector);
        quote!(+ #turn * #vector)
    });
    quote!((Vec3::<f64>::zero() #(#terms)*))
}

/// One body's constants: its C and s (what its children start from), then its own.
fn body_constants(model: &Model, tree: &RigidTree, i: usize, node: &Node) -> TokenStream {
    let p = private();
    let (after, own, name) = (
        format_ident!("__after_{}", i),
        format_ident!("__own_{}", i),
        format_ident!("__body_{}", i),
    );
    let (after_value, own_value) = (product(&node.after), sum(&node.own));
    let parent_turn = match node.parent {
        Some(q) => {
            let q = format_ident!("__after_{}", q);
            quote!(#q)
        }
        None => quote!(Rot3::<f64>::identity()),
    };
    let anchor = match (node.anchored, node.parent) {
        (true, Some(q)) => {
            let q = format_ident!("__own_{}", q);
            quote!(#q +)
        }
        _ => quote!(),
    };
    let (joint_frame, offset) = (product(&node.joint_frame), sum(&node.offset));
    let body = &model.bodies[node.body];
    let member = node.member.zip(family_index(body.decl)).map(|(k, index)| {
        let k = lit(k);
        quote!(let #index: usize = #k;)
    });
    let (mass, tensor) = inertia(model, node);
    let _ = tree;
    quote! {
        let #after: Rot3<f64> = #after_value;
        let #own: Vec3<f64> = #own_value;
        let #name = {
            #member
            let __rotation: Rot3<f64> = #parent_turn * #joint_frame;
            let __offset: Vec3<f64> = #anchor #parent_turn * #offset;
            let __mass: f64 = #mass;
            let __tensor: [[f64; 3]; 3] = #p::tree::rigid::turned_tensor(&#after, #tensor);
            #p::tree::rigid::body_constants(__rotation, __offset, __mass, #own, __tensor)
        };
    }
}

/// A node's mass and its rotational inertia about its centre of mass in the axes its function
/// returns (zero for a particle or point).
fn inertia(model: &Model, node: &Node) -> (TokenStream, TokenStream) {
    let p = private();
    let body = &model.bodies[node.body];
    let args = &body.decl.args;
    let mass = match (&args.mass, body.shape.has_mass()) {
        (Some(m), true) => quote!(#m),
        _ => quote!(0.0),
    };
    let zero = quote!([[0.0; 3]; 3]);
    let tensor = match (body.shape, &args.inertia) {
        (Shape::Planar, Some(Inertia::Moment(i))) => {
            quote!(#p::tree::rigid::diagonal([0.0, 0.0, #i]))
        }
        (Shape::Spatial, Some(Inertia::Principal(i))) => quote!(#p::tree::rigid::diagonal(#i)),
        _ => zero,
    };
    (mass, tensor)
}

/// The uniform fields' acceleration as a `Vec3<f64>` (the plane's fields with z = 0).
fn gravity(model: &Model) -> TokenStream {
    let fields = model.uniform_gravities.iter().map(|(decl, dim)| {
        let block = &decl.block;
        match dim {
            Dim::Two => quote!(+ { let __g: Vec2<f64> = #block; vec3(__g.x, __g.y, 0.0) }),
            Dim::Three => quote!(+ { let __g: Vec3<f64> = #block; __g }),
        }
    });
    quote!((Vec3::<f64>::zero() #(#fields)*))
}

/// `fn __lagrange_rigid_accelerations`: the articulated-body algorithm's three sweeps, one call per
/// body with a constant index, under the generalized forces of everything but the uniform field.
fn accelerations_fn(model: &Model, tree: &RigidTree) -> TokenStream {
    let p = private();
    let r = quote!(#p::tree::rigid);
    let (n, k, b) = (lit(model.dof()), lit(model.rows), lit(tree.nodes.len()));
    let sweeps = if tree.nodes.len() > MAX_WRITTEN_BODIES {
        quote!(#r::accelerations::<Coords, S, #n, #b>(__joints, __k, __t, __q, __v, &__tau))
    } else {
        let down: Vec<_> = (0..tree.nodes.len()).map(lit).collect();
        let up = down.iter().rev();
        quote! {
            let mut __ws = #r::Articulated::<S, #b>::new();
            #( __ws.velocity(__joints, __k, __q, __v, #down); )*
            #(
                if let ::lagrange::__private::core::result::Result::Err(__pivot) = __ws.articulate(__joints, __k, &__tau, #up) {
                    return ::lagrange::__private::core::result::Result::Err(
                        #r::singular::<Coords, S, #n, #b>(__joints, __pivot, __t, __q),
                    );
                }
            )*
            let mut __qdd = [<S as ::lagrange::__private::core::convert::From<f64>>::from(0.0); #n];
            #( __ws.accelerate(__joints, __k, &mut __qdd, #down); )*
            #r::finished::<Coords, S, #n>(__qdd, __t, __q)
        }
    };
    quote! {
        #[inline(always)]
        fn __lagrange_rigid_accelerations<S: #p::Scalar>(
            &self,
            __k: &#r::RigidConstants<#b>,
            __t: S,
            __q: &[S; #n],
            __v: &[S; #n],
        ) -> #p::Result<[S; #n]> {
            let __joints = &<Self as #r::RigidTree<#n, #b>>::JOINTS;
            let __tau: [S; #n] = #r::other_generalized_forces::<Self, S, #n, #k>(self, __t, __q, __v).into();
            #sweeps
        }
    }
}
