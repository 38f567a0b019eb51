//! The `Constraints` impl: names and kinds, the position and velocity rows, friction coefficients.

use super::{bind_bodies, bind_coordinates, bind_inputs, lit, prelude, private, scalar};
use crate::attr::Kind;
use crate::check::Model;
use crate::lift;
use crate::symbolic::constraint_rows::ConstraintDerivatives;
use proc_macro2::TokenStream;
use quote::{format_ident, quote};

/// The `Constraints` impl: one row per constraint item, in declaration order; with `rigid`, the
/// bodies of the rigid tree the declaration takes, whose recursions give the solve M, 𝓕 and b.
pub(super) fn constraints_impl(model: &Model, rigid: Option<usize>) -> TokenStream {
    let p = private();
    let constraints = quote!(#p::lagrange_core::constraints);
    let (params, n, k, c) = (
        model.params_ident,
        lit(model.dof()),
        lit(model.rows),
        lit(model.constraint_row_count()),
    );
    // A friction cone is two rows, `name.x` and `name.y` (the components of its `Vec2`).
    let names = model.constraints.iter().flat_map(|r| {
        let name = r.decl.ident().to_string();
        if r.cone {
            vec![format!("{name}.x"), format!("{name}.y")]
        } else {
            vec![name]
        }
    });
    let kinds = model
        .constraints
        .iter()
        .enumerate()
        .flat_map(|(item, r)| match (r.decl.kind(), r.normal) {
            (Kind::Constraint, _) => vec![quote!(#constraints::ConstraintKind::Holonomic)],
            (Kind::Unilateral, _) => vec![quote!(#constraints::ConstraintKind::Unilateral)],
            (Kind::VelocityConstraint, _) => vec![quote!(#constraints::ConstraintKind::Velocity)],
            (_, normal) => {
                let normal = lit(model.constraint_row(normal.unwrap_or_default()));
                if r.cone {
                    let row = model.constraint_row(item);
                    let (first, second) = (lit(row), lit(row + 1));
                    vec![
                        quote!(#constraints::ConstraintKind::FrictionCone { normal: #normal, partner: #second }),
                        quote!(#constraints::ConstraintKind::FrictionCone { normal: #normal, partner: #first }),
                    ]
                } else {
                    vec![quote!(#constraints::ConstraintKind::Friction { normal: #normal })]
                }
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
    let derivatives = position_derivatives_fn(model);
    // The rows are written on the rates; the module's functions convert a state's velocities.
    let quasi = (!model.angular_velocities.is_empty()).then(|| {
        quote!(const QUASI_VELOCITY_JOINTS: &'static [#p::tree::rigid::Joint] =
            <Self as #p::Dynamics<#n>>::QUASI_VELOCITY_JOINTS;)
    });
    let tree = rigid.map(|b| tree_equations_fn(model, b));
    quote! {
        impl #constraints::Constraints<#n, #k, #c> for #params {
            const NAMES: [&'static str; #c] = [#(#names),*];
            const KINDS: [#constraints::ConstraintKind; #c] = [#(#kinds),*];
            #quasi
            #tree
            #position
            #velocity
            #friction
            #derivatives
        }
    }
}

/// `tree_equations`: M, 𝓕 and b at the coordinates' rates by the rigid tree's recursions over
/// its `b` bodies, with the forces of the model the solve hands it.
fn tree_equations_fn(model: &Model, b: usize) -> TokenStream {
    let p = private();
    let (n, k, b) = (lit(model.dof()), lit(model.rows), lit(b));
    quote! {
        #[inline(always)]
        fn tree_equations<__F: #p::Model<#n, #k>, __S: #p::Scalar>(
            &self,
            __forces: &__F,
            __t: __S,
            __q: &[__S; #n],
            __rates: &[__S; #n],
        ) -> #p::core::option::Option<#p::dynamics::EquationsOfMotion<__S, #n>> {
            let __joints = &<Self as #p::tree::rigid::RigidTree<#n, #b>>::JOINTS;
            let __k = self.__lagrange_rigid_constants();
            #p::core::option::Option::Some(#p::tree::rigid::equations_of_motion_in_rates(
                __forces, __joints, &__k, __t, __q, __rates,
            ))
        }
    }
}

/// Whether every constraint row is a scleronomic `#[constraint]` whose derivatives are written out
/// on its expression tree ([`ConstraintDerivatives`]): then, on affine positions, q̈ and the
/// projection from the prepared constants are straight-line code
/// (`lagrange_core::constraints::regular_accelerations_prepared`).
pub(super) fn written_holonomic(model: &Model) -> bool {
    !model.rheonomic
        && model
            .constraints
            .iter()
            .all(|r| r.decl.kind() == Kind::Constraint)
        && ConstraintDerivatives::of(model).is_some_and(|derivatives| {
            let written = derivatives.written(model.constraint_row_count());
            written.iter().all(|&w| w)
        })
}

/// `POSITION_DERIVATIVES` and `position_constraint_derivatives`, for the position rows read as
/// expression trees ([`crate::symbolic::constraint_rows`]); nothing when none is (every row keeps
/// its dual numbers).
fn position_derivatives_fn(model: &Model) -> Option<TokenStream> {
    let derivatives = ConstraintDerivatives::of(model)?;
    let p = private();
    let constraints = quote!(#p::lagrange_core::constraints);
    let (n, k, c) = (
        lit(model.dof()),
        lit(model.rows),
        lit(model.constraint_row_count()),
    );
    let written = derivatives.written(model.constraint_row_count());
    let body = derivatives.emit(model);
    Some(quote! {
        const POSITION_DERIVATIVES: [bool; #c] = [#(#written),*];
        #[inline(always)]
        #[allow(unused_variables, clippy::all)]
        fn position_constraint_derivatives<__S: #p::Scalar>(
            &self,
            __t: __S,
            __q: &[__S; #n],
            __v: &[__S; #n],
            __motion: &#constraints::CartesianMotion<__S, #n, #k>,
            __out: &mut #constraints::ConstraintRows<__S, #n, #c>,
        ) {
            #body
        }
    })
}

/// `position_constraints` (g or c per position row, zero elsewhere) or `velocity_constraints`
/// (h or the slip velocity per velocity row, zero elsewhere).
fn constraint_rows_fn(model: &Model, position: bool) -> TokenStream {
    let p = private();
    let (n, k, c) = (
        lit(model.dof()),
        lit(model.rows),
        lit(model.constraint_row_count()),
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
    let (cones, values) = row_values(model, position);
    let signature = if position {
        quote!(fn position_constraints<__D: #p::Scalar>(&self, __t: __D, __q: &[__D; #n], __x: &[__D; #k]) -> [__D; #c])
    } else {
        quote!(fn velocity_constraints<__D: #p::Scalar>(&self, __t: __D, __q: &[__D; #n], __v: &[__D; #n], __x: &[__D; #k], __x_dot: &[__D; #k]) -> [__D; #c])
    };
    let velocities = (!position).then(|| velocity_bindings(model));
    // Inlined like `cartesian`: which derivatives of x are structurally absent is then known where
    // the rows are used, and costs nothing.
    quote! {
        #[allow(unused_variables, clippy::all)]
        #[inline(always)]
        #signature {
            #prelude
            #inputs
            #bodies
            #velocities
            #(#cones)*
            [#(#values),*]
        }
    }
}

/// The friction cones' `let`s and the rows' values: a position (or velocity) row its block, a
/// friction cone's two rows the components of its `Vec2`, every other row zero.
fn row_values(model: &Model, position: bool) -> (Vec<TokenStream>, Vec<TokenStream>) {
    let d = scalar();
    // A friction cone's `Vec2` is evaluated once, before the array, and gives two rows.
    let cones = model
        .constraints
        .iter()
        .enumerate()
        .filter(|(_, r)| r.cone && !position)
        .map(|(item, r)| {
            let block = lift::lift_block(&r.decl.block, &d);
            let name = format_ident!("__cone_{}", item);
            quote!(let #name: Vec2<__D> = #block;)
        })
        .collect();
    let values = model.constraints.iter().enumerate().flat_map(|(item, r)| {
        if r.cone && !position {
            let name = format_ident!("__cone_{}", item);
            vec![quote!(#name.x), quote!(#name.y)]
        } else if matches!(r.decl.kind(), Kind::Constraint | Kind::Unilateral) == position
            && !r.cone
        {
            let block = lift::lift_block(&r.decl.block, &d);
            vec![quote!({ let __row: __D = #block; __row })]
        } else {
            vec![quote!(<__D>::zero()); r.width()]
        }
    });
    (cones, values.collect())
}

/// The coordinates' velocities (`<coordinate>_dot`) and the bodies' (`<body>_dot`).
fn velocity_bindings(model: &Model) -> TokenStream {
    let coords = bind_coordinates(model, &quote!(__v), "_dot");
    let names = model.bodies.iter().map(|b| b.decl.ident());
    let body_velocities = model
        .bodies
        .iter()
        .map(|b| format_ident!("{}_dot", b.decl.ident()));
    quote! {
        #coords
        let BodyVelocities { #(#names: #body_velocities),* } = self.__lagrange_velocities_from_cartesian(__x, __x_dot);
    }
}

/// `friction_coefficients`: μₖ and μₛ (μₛ = μₖ unless given) of each friction row.
fn friction_fn(model: &Model) -> TokenStream {
    let p = private();
    let constraints = quote!(#p::lagrange_core::constraints);
    let params: proc_macro2::TokenStream = model.params.iter().map(|f| f.bind_f64()).collect();
    let arms = model
        .constraints
        .iter()
        .enumerate()
        .filter(|(_, r)| r.decl.kind() == Kind::Friction)
        .map(|(item, r)| {
            let row = model.constraint_row(item);
            let rows = (row..row + r.width()).map(lit);
            let kinetic = r.decl.args.kinetic.as_ref();
            let stiction = r.decl.args.stiction.as_ref().or(kinetic);
            quote!(#(#rows)|* => #constraints::Coulomb { kinetic: #kinetic, stiction: #stiction },)
        });
    quote! {
        #[allow(unused_variables, clippy::all)]
        fn friction_coefficients(&self, row: usize) -> #constraints::Coulomb {
            #params
            match row {
                #(#arms)*
                _ => #constraints::Coulomb::default(),
            }
        }
    }
}
