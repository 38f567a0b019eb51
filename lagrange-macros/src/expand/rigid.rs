//! Expansion of a kinematic tree of rigid bodies (see [`crate::structure::rigid`]): the
//! `RigidTree` impl (each joint as the compiler knows it), the constants a validated handle
//! prepares, and q̈ by the articulated-body algorithm written out body by body, each call with a
//! constant body index so that it is compiled for its own joint (`lagrange_core::tree::rigid`).

use crate::attr::Inertia;
use crate::check::{family_index, ChartKind, Dim, Model, Shape};
use crate::expand::{lit, prelude, private};
use crate::structure::rigid::{product, Axis, Joint, Node, Offset, RigidTree};
use proc_macro2::TokenStream;
use quote::{format_ident, quote};

/// Up to this many bodies a sweep's per-body steps are written into the function that runs it.
/// A larger tree's sweeps are split into functions of [`CHUNK`] bodies each: the compiler's work on
/// one function grows faster than its length (a 16-body arm's sweeps build in a few seconds, a
/// 31-body tree's, written into one function, in half a minute), and a function per chunk keeps
/// it proportional to the bodies.
const MAX_INLINED_BODIES: usize = 16;
const CHUNK: usize = 8;

/// A sweep over the bodies in `order`, one statement per body from `step(body, code)`: written
/// into the caller for a small tree; for a large one, a call per chunk to a function of its own
/// (`name_0`, `name_1`, …, taking `params` and called with `args`), returned with the statements.
/// A chunk returns `Result<(), Pivot>` (the per-body statements may `return` an error).
struct Sweep<'a> {
    name: &'a str,
    params: TokenStream,
    args: TokenStream,
}

impl Sweep<'_> {
    fn write(
        &self,
        order: &[usize],
        codes: &[TokenStream],
        step: impl Fn(&proc_macro2::Literal, &TokenStream) -> TokenStream,
    ) -> (TokenStream, TokenStream) {
        let p = private();
        let statements: Vec<TokenStream> =
            order.iter().map(|&i| step(&lit(i), &codes[i])).collect();
        if order.len() <= MAX_INLINED_BODIES {
            return (quote!(#(#statements)*), quote!());
        }
        let (params, args) = (&self.params, &self.args);
        let ok = quote!(::lagrange::__private::core::result::Result::Ok(()));
        let mut calls = TokenStream::new();
        let mut functions = TokenStream::new();
        for (c, chunk) in statements.chunks(CHUNK).enumerate() {
            let f = format_ident!("__lagrange_rigid_{}_{}", self.name, c);
            functions.extend(quote! {
                #[inline(never)]
                #[allow(clippy::all)]
                fn #f<S: #p::Scalar>(&self, #params) -> ::lagrange::__private::core::result::Result<(), #p::tree::rigid::Pivot> {
                    #(#chunk)*
                    #ok
                }
            });
            calls.extend(quote! {
                if let ::lagrange::__private::core::result::Result::Err(__pivot) = self.#f::<S>(#args) {
                    return ::lagrange::__private::core::result::Result::Err(__pivot);
                }
            });
        }
        (calls, functions)
    }
}

/// Each body's joint code (`lagrange_core::tree::rigid::Joint::code`), a constant the per-body
/// steps are compiled for: one copy of each step per distinct kind of joint, its structural zeros
/// folded.
fn codes(model: &Model, tree: &RigidTree) -> Vec<TokenStream> {
    let p = private();
    let (params, n, b) = (model.params_ident, lit(model.dof()), lit(tree.nodes.len()));
    (0..tree.nodes.len())
        .map(|i| {
            let i = lit(i);
            quote!({ <#params as #p::tree::rigid::RigidTree<#n, #b>>::JOINTS[#i].code() })
        })
        .collect()
}

/// The `RigidTree` impl and the inherent functions the `Dynamics` impl calls.
pub fn rigid_items(model: &Model, tree: &RigidTree) -> TokenStream {
    let p = private();
    let params = model.params_ident;
    let (n, b) = (lit(model.dof()), lit(tree.nodes.len()));
    let joints = tree
        .nodes
        .iter()
        .map(|node| joint(node, &tree.nodes, &model.angular_velocities));
    let constants = constants_fn(model, tree);
    let accelerations = accelerations_fn(model, tree);
    let inverse = inverse_dynamics_fn(model, tree);
    quote! {
        impl #p::tree::rigid::RigidTree<#n, #b> for #params {
            const JOINTS: [#p::tree::rigid::Joint; #b] = [#(#joints),*];
        }
        impl #params {
            #constants
            #accelerations
            #inverse
        }
    }
}

/// A chart as the runtime names it.
fn rotation_chart(chart: ChartKind) -> TokenStream {
    let geometry = quote!(::lagrange::__private::lagrange_core::geometry);
    match chart {
        ChartKind::Mrp => quote!(#geometry::RotationChart::Mrp),
        ChartKind::Vector => quote!(#geometry::RotationChart::Vector),
    }
}

/// A free or ball joint's velocities as the runtime names them: the angular velocity where its
/// chart, `slots`, is among `angular` (`#[angular_velocity]`), else the chart's rates.
fn velocities(slots: [usize; 3], angular: &[[usize; 3]]) -> TokenStream {
    let r = quote!(::lagrange::__private::tree::rigid);
    match angular.contains(&slots) {
        true => quote!(#r::Velocities::AngularVelocity),
        false => quote!(#r::Velocities::ChartRates),
    }
}

/// A joint as a constant of the runtime.
fn joint(node: &Node, nodes: &[Node], angular: &[[usize; 3]]) -> TokenStream {
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
        Joint::Free(chart, first) => {
            let chart = rotation_chart(chart);
            let v = velocities([first + 3, first + 4, first + 5], angular);
            (quote!(#r::JointKind::Free(#chart, #v)), first)
        }
        Joint::Ball(chart, first) => {
            let chart = rotation_chart(chart);
            let v = velocities([first, first + 1, first + 2], angular);
            (quote!(#r::JointKind::Ball(#chart, #v)), first)
        }
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
    let params: proc_macro2::TokenStream = model.params.iter().map(|f| f.bind_f64()).collect();
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
            #params
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
    let com = centre_of_mass(model, node);
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
            let __centre: Vec3<f64> = #own + #after * #com;
            #p::tree::rigid::body_constants(__rotation, __offset, __mass, __centre, __tensor)
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
        (Shape::Spatial, Some(Inertia::Tensor(t))) => quote!(#t),
        _ => zero,
    };
    (mass, tensor)
}

/// The centre of mass in the frame the body's function returns: its `com` (a `Vec3<f64>`; a
/// planar body's in the plane), or the frame's origin.
fn centre_of_mass(model: &Model, node: &Node) -> TokenStream {
    let body = &model.bodies[node.body];
    match (&body.decl.args.com, body.shape) {
        (Some(c), Shape::Planar) => quote!({ let __c: Vec2<f64> = #c; vec3(__c.x, __c.y, 0.0) }),
        (Some(c), _) => quote!({ let __c: Vec3<f64> = #c; __c }),
        (None, _) => quote!(Vec3::<f64>::zero()),
    }
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
/// body with a constant index, under the generalized forces of everything but the uniform field;
/// the sweeps themselves in `__lagrange_rigid_sweeps`, which reports a failed pivot.
fn accelerations_fn(model: &Model, tree: &RigidTree) -> TokenStream {
    let p = private();
    let r = quote!(#p::tree::rigid);
    let (n, k, b) = (lit(model.dof()), lit(model.rows), lit(tree.nodes.len()));
    let code = codes(model, tree);
    let down: Vec<usize> = (0..tree.nodes.len()).collect();
    let up: Vec<usize> = down.iter().rev().copied().collect();
    let ws = quote!(__ws: &mut #r::Articulated<S, #b>, __joints: &[#r::Joint; #b], __k: &#r::RigidConstants<#b>);
    let sweep = |name, extra: TokenStream, args: TokenStream| Sweep {
        name,
        params: quote!(#ws, #extra),
        args: quote!(__ws, __joints, __k, #args),
    };
    let (velocities, f1) = sweep(
        "velocity",
        quote!(__q: &[S; #n], __v: &[S; #n]),
        quote!(__q, __v),
    )
    .write(
        &down,
        &code,
        |i, c| quote!(__ws.velocity::<#c, #n>(__joints, __k, __q, __v, #i);),
    );
    let (articulation, f2) = sweep("articulate", quote!(__tau: &[S; #n]), quote!(__tau))
        .write(&up, &code, |i, c| quote! {
            if let ::lagrange::__private::core::result::Result::Err(__pivot) = __ws.articulate::<#c, #n>(__joints, __k, __tau, #i) {
                return ::lagrange::__private::core::result::Result::Err(__pivot);
            }
        });
    let (accelerations, f3) = sweep("accelerate", quote!(__qdd: &mut [S; #n]), quote!(__qdd))
        .write(
            &down,
            &code,
            |i, c| quote!(__ws.accelerate::<#c, #n>(__joints, __k, __qdd, #i);),
        );
    quote! {
        #f1
        #f2
        #f3
        #[inline(always)]
        #[allow(clippy::all)]
        fn __lagrange_rigid_sweeps<S: #p::Scalar>(
            &self,
            __ws: &mut #r::Articulated<S, #b>,
            __joints: &[#r::Joint; #b],
            __k: &#r::RigidConstants<#b>,
            (__q, __v, __tau): (&[S; #n], &[S; #n], &[S; #n]),
            __qdd: &mut [S; #n],
        ) -> ::lagrange::__private::core::result::Result<(), #r::Pivot> {
            #velocities
            #articulation
            #accelerations
            ::lagrange::__private::core::result::Result::Ok(())
        }
        #[inline(always)]
        fn __lagrange_rigid_accelerations<S: #p::Scalar, __F: #p::Model<#n, #k>>(
            &self,
            __forces: &__F,
            __k: &#r::RigidConstants<#b>,
            __t: S,
            __q: &[S; #n],
            __v: &[S; #n],
        ) -> #p::Result<[S; #n]> {
            let __joints = &<Self as #r::RigidTree<#n, #b>>::JOINTS;
            let __tau: [S; #n] = #r::other_generalized_forces::<__F, S, #n, #k, #b>(__forces, __joints, __t, __q, __v).into();
            let mut __ws = #r::Articulated::<S, #b>::new();
            let mut __qdd = [<S as ::lagrange::__private::core::convert::From<f64>>::from(0.0); #n];
            if let ::lagrange::__private::core::result::Result::Err(__pivot) =
                self.__lagrange_rigid_sweeps(&mut __ws, __joints, __k, (__q, __v, &__tau), &mut __qdd)
            {
                return ::lagrange::__private::core::result::Result::Err(
                    #r::singular::<Coords, S, #n, #b>(__joints, __pivot, __t, __q),
                );
            }
            #r::finished::<Coords, S, #n>(__qdd, __t, __q)
        }
    }
}

/// `fn __lagrange_rigid_inverse_dynamics`: the Newton–Euler algorithm's two sweeps, one call per
/// body with a constant index (in `__lagrange_rigid_newton_euler`), less the generalized forces of
/// everything but the uniform field.
fn inverse_dynamics_fn(model: &Model, tree: &RigidTree) -> TokenStream {
    let p = private();
    let r = quote!(#p::tree::rigid);
    let (n, k, b) = (lit(model.dof()), lit(model.rows), lit(tree.nodes.len()));
    let code = codes(model, tree);
    let down: Vec<usize> = (0..tree.nodes.len()).collect();
    let up: Vec<usize> = down.iter().rev().copied().collect();
    let ws = quote!(__ws: &mut #r::NewtonEuler<S, #b>, __joints: &[#r::Joint; #b], __k: &#r::RigidConstants<#b>);
    let state = quote!(__state: (&[S; #n], &[S; #n], &[S; #n]));
    let tau = quote!(__tau: &mut [S; #n]);
    let (forward, f1) = Sweep {
        name: "forward",
        params: quote!(#ws, #state),
        args: quote!(__ws, __joints, __k, __state),
    }
    .write(
        &down,
        &code,
        |i, c| quote!(__ws.forward::<#c, #n>(__joints, __k, __state, #i);),
    );
    let (backward, f2) = Sweep {
        name: "backward",
        params: quote!(#ws, #tau),
        args: quote!(__ws, __joints, __k, __tau),
    }
    .write(
        &up,
        &code,
        |i, c| quote!(__ws.backward::<#c, #n>(__joints, __k, __tau, #i);),
    );
    quote! {
        #f1
        #f2
        /// The two sweeps; neither fails (the chunks' `Result` is for the sweeps that can).
        #[inline(always)]
        #[allow(clippy::all)]
        fn __lagrange_rigid_newton_euler<S: #p::Scalar>(&self, #ws, #state, #tau)
            -> ::lagrange::__private::core::result::Result<(), #r::Pivot>
        {
            #forward
            #backward
            ::lagrange::__private::core::result::Result::Ok(())
        }
        #[inline(always)]
        fn __lagrange_rigid_inverse_dynamics<S: #p::Scalar, __F: #p::Model<#n, #k>>(
            &self,
            __forces: &__F,
            __k: &#r::RigidConstants<#b>,
            __t: S,
            __q: &[S; #n],
            __v: &[S; #n],
            __qdd: &[S; #n],
        ) -> [S; #n] {
            let __joints = &<Self as #r::RigidTree<#n, #b>>::JOINTS;
            let mut __ws = #r::NewtonEuler::<S, #b>::new();
            let mut __tau = [<S as ::lagrange::__private::core::convert::From<f64>>::from(0.0); #n];
            let _ = self.__lagrange_rigid_newton_euler(&mut __ws, __joints, __k, (__q, __v, __qdd), &mut __tau);
            #r::less_other_forces::<__F, S, #n, #k, #b>(__forces, __joints, __tau, __t, __q, __v)
        }
    }
}
