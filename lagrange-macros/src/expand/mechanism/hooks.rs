//! The step hooks of the `Dynamics` impl: what every integrator calls around a step — the
//! constraints' projection and checks, and the rotation charts' switch.

use super::{Equations, Glue, Prepared};
use crate::check::ChartKind;
use crate::expand::{lit, private};
use proc_macro2::{Literal, TokenStream};
use quote::quote;

/// The hooks of a constrained mechanism that make every integrator enforce its constraints: the
/// rows' values, the projection after a step (from an affine mechanism's prepared constants
/// through a handle), the checks of the declaration and of a state.
pub(super) fn constraint_hooks(glue: &Glue, c: Literal) -> TokenStream {
    let p = private();
    let (n, k) = glue.sizes();
    let constraints = quote!(#p::lagrange_core::constraints);
    let plain_projection = quote!({
        let mode = #constraints::infer_mode::<Self, #n, #k, #c>(self, t, q, v)?;
        #constraints::project::<Self, #n, #k, #c>(self, t, q, v, &mode)
    });
    let projection = match glue.prepared() {
        Prepared::Affine { .. } => quote! {
            match prepared {
                #p::core::option::Option::Some(prepared) => {
                    #constraints::project_prepared::<Self, #n, #k, #c>(self, prepared, t, q, v)
                }
                #p::core::option::Option::None => #plain_projection,
            }
        },
        _ => quote!({
            let _ = prepared;
            #plain_projection
        }),
    };
    quote! {
        #[inline]
        fn holonomic_constraints_at<S: #p::Scalar>(&self, t: S, q: &[S; #n]) -> #p::core::option::Option<[S; #n]> {
            #p::core::option::Option::Some(#constraints::holonomic_values::<Self, S, #n, #k, #c>(self, t, q))
        }
        fn project(&self, __constants: #p::lagrange_core::evaluation::Constants<'_, Self>, t: f64, q: &mut [f64; #n], v: &mut [f64; #n]) -> #p::Result<()> {
            let prepared = __constants.prepared;
            #projection
        }
        // Inlined (the mechanism is often declared in another crate than the caller): without
        // velocity rows the check is a constant `Ok`.
        #[inline]
        fn check_declaration_at(&self, t: f64, q: &[f64; #n], v: &[f64; #n]) -> #p::Result<()> {
            #constraints::check_velocity_rows_affine::<Self, #n, #k, #c>(self, t, q, v)
        }
        fn check_constraints(&self, t: f64, q: &[f64; #n], v: &[f64; #n]) -> #p::Result<()> {
            #constraints::check_consistent::<Self, #n, #k, #c>(self, t, q, v, #constraints::CONSISTENCY_TOLERANCE)
        }
    }
}

/// A declaration with rotation charts keeps each regular after every step
/// (`lagrange_core::geometry::switch_chart`, or `switch_orientation` for a chart whose velocities
/// are the angular velocity: the coordinates move, the velocities stay); without, the trait's
/// default (no switch).
pub(super) fn switch_charts(glue: &Glue) -> Option<TokenStream> {
    if glue.charts.is_empty() {
        return None;
    }
    let p = private();
    let n = lit(glue.n);
    let geometry = quote!(#p::lagrange_core::geometry);
    let switches = glue.charts.iter().map(|chart| {
        let kind = match chart.kind {
            ChartKind::Vector => quote!(Vector),
            ChartKind::Mrp => quote!(Mrp),
        };
        let angular = glue.angular_velocities.contains(&chart.slots);
        let slots = chart.slots.map(lit);
        match angular {
            // The angular velocity is the rotation's, whatever its chart.
            true => quote!(#geometry::switch_orientation(#geometry::RotationChart::#kind, [#(#slots),*], q)),
            false => quote!(#geometry::switch_chart(#geometry::RotationChart::#kind, [#(#slots),*], q, v)),
        }
    });
    Some(quote! {
        #[inline]
        fn switch_charts<S: #p::Scalar>(&self, q: &mut [S; #n], v: &mut [S; #n]) -> bool {
            false #(| #switches)*
        }
    })
}

/// A declaration with `#[angular_velocity]` charts (a rigid tree's free or ball joints, see
/// `check::velocities`): the tree's joints, among which those whose velocities are the angular
/// velocity, from which `lagrange_core` forms q̇ = G(q) v and the other maps
/// (`tree::rigid::free`); without, the trait's default (none: q̇ = v).
pub(super) fn quasi_velocities(glue: &Glue) -> Option<TokenStream> {
    let (&Equations::Rigid(b), false) = (&glue.equations, glue.angular_velocities.is_empty())
    else {
        return None;
    };
    let p = private();
    let (n, bodies) = (lit(glue.n), lit(b));
    Some(quote! {
        const QUASI_VELOCITY_JOINTS: &'static [#p::tree::rigid::Joint] =
            &<Self as #p::tree::rigid::RigidTree<#n, #bodies>>::JOINTS;
    })
}
