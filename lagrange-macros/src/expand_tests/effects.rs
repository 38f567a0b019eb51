//! Only the effects a declaration calls for are generated: forces, potentials, time, every item
//! kind, arrays and families, and the items kept on error.

use super::{pendulum, pretty, snapshot};
use crate::expand::expand;
use proc_macro2::TokenStream;
use quote::quote;

#[test]
fn pendulum_is_scleronomic_without_forces() {
    let out = snapshot("pendulum", pendulum());
    assert!(out.contains("const RHEONOMIC: bool = false;"));
    assert!(out.contains("const HAS_FORCES: bool = false;"));
    // Scleronomic: the methods on (q, p) get the one-pass canonical field and q̇ = M⁻¹p.
    assert!(out.contains("const SCLERONOMIC: bool = true;"));
    assert!(out.contains("fn canonical_field_at"));
    assert!(
        !out.contains("fn applied_forces"),
        "a mechanism without forces has no force pass"
    );
    // A constant field is constant Cartesian weights: no potential to differentiate.
    assert!(out.contains("const HAS_GRAVITY: bool = true;"));
    assert!(out.contains("fn weights"));
    assert!(
        !out.contains("fn potential<"),
        "a uniform field needs no potential pass"
    );
    assert!(out.contains("const HAS_POTENTIAL: bool = false;"));
}

#[test]
fn drag_adds_a_force_pass() {
    let out = snapshot(
        "pendulum_with_drag",
        quote! {
            pub mod pendulum {
                pub struct Coords { pub theta: f64 }
                pub struct Pendulum { pub m: f64, pub l: f64, pub g: f64, pub c: f64 }
                #[particle(mass = m)]
                fn bob() -> Vec2 { vec2(theta.sin(), -theta.cos()) * l }
                #[gravity]
                fn down() -> Vec2 { vec2(0.0, -g) }
                #[force(on = bob)]
                fn drag() -> Vec2 { bob_dot * (-c) }
            }
        },
    );
    assert!(out.contains("fn applied_forces"));
    assert!(out.contains("const HAS_FORCES: bool = true;"));
    assert!(
        out.contains("const RHEONOMIC: bool = false;"),
        "forces naming t do not make x(q, t) rheonomic"
    );
}

#[test]
fn no_potential_means_no_potential_fn() {
    let out = snapshot(
        "free_particle",
        quote! {
            pub mod free {
                pub struct Coords { pub x: f64, pub y: f64 }
                pub struct Free { pub m: f64 }
                #[particle(mass = m)]
                fn ball() -> Vec2 { vec2(x, y) }
            }
        },
    );
    assert!(!out.contains("fn potential<"));
    assert!(out.contains("const HAS_POTENTIAL: bool = false;"));
}

#[test]
fn time_in_a_position_is_rheonomic() {
    let out = snapshot(
        "driven_pendulum",
        quote! {
            pub mod driven {
                pub struct Coords { pub theta: f64 }
                pub struct Driven { pub m: f64, pub l: f64, pub a: f64, pub w: f64, pub g: f64 }
                #[particle(mass = m)]
                fn bob() -> Vec2 { vec2(a * (w * t).cos() + l * theta.sin(), -l * theta.cos()) }
                #[gravity]
                fn down() -> Vec2 { vec2(0.0, -g) }
            }
        },
    );
    assert!(out.contains("const RHEONOMIC: bool = true;"));
    // x depends on t: p = M q̇ + Jᵀ diag(μ) ∂x/∂t, so neither the one-pass canonical field nor the
    // one-solve velocities apply.
    assert!(out.contains("const SCLERONOMIC: bool = false;"));
    assert!(!out.contains("fn canonical_field_at"));
}

#[test]
fn a_field_that_varies_in_time_is_a_potential() {
    let out = snapshot(
        "varying_gravity",
        quote! {
            pub mod varying {
                pub struct Coords { pub y: f64 }
                pub struct Varying { pub m: f64, pub g: f64, pub w: f64 }
                #[particle(mass = m)]
                fn ball() -> Vec2 { vec2(0.0, y) }
                #[gravity]
                fn down() -> Vec2 { vec2(0.0, -g * (w * t).cos()) }
            }
        },
    );
    assert!(out.contains("fn potential<"));
    assert!(!out.contains("fn weights"));
    assert!(out.contains("const RHEONOMIC: bool = true;"));
}

#[test]
fn every_item_kind() {
    let out = snapshot(
        "every_item_kind",
        quote! {
            pub mod everything {
                use core::f64::consts::PI;
                const HALF: f64 = 0.5;
                pub struct Coords { pub theta: f64, pub phi: f64 }
                pub struct Everything { pub m: f64, pub i: f64, pub k: f64, pub c: f64, pub tau: f64, pub g: f64 }
                /// A bar on a pivot.
                #[rigid_body(mass = m, inertia = i)]
                fn bar() -> Planar { planar(vec2(theta.sin(), -theta.cos()) * HALF, theta) }
                #[point]
                fn tip() -> Vec2 { bar.point(vec2(0.5, 0.0)) }
                #[rigid_body(mass = m, inertia = [i, i, i * 1.5])]
                fn top() -> Spatial { spatial(vec3(0.0, 0.0, 1.0), rot_z(phi) * rot_x(PI * 0.1)) }
                #[potential]
                fn spring() -> f64 { k * phi.powf(2.0) * 0.5 }
                #[gravity]
                fn down() -> Vec3 { vec3(0.0, 0.0, -g) }
                #[gravity]
                fn plane_down() -> Vec2 { vec2(0.0, -g) }
                #[force(on = tip)]
                fn push() -> Vec2 { vec2(c, 0.0) }
                #[torque(on = bar)]
                fn motor() -> f64 { tau }
                #[generalized_force(on = phi)]
                fn damping() -> f64 { -c * phi_dot }
            }
        },
    );
    // The massless point comes after both bodies: 3 + 12 inertial rows, then 2.
    assert!(out.contains("const INERTIAL: usize = 15;"));
    assert!(out.contains("Model<2, 17>"));
    // Literals are lifted, except a direct argument of a method.
    assert!(out.contains("phi.powf(2.0)"));
    assert!(out.contains("<__D>::from(0.5)"));
}

#[test]
fn an_error_still_emits_the_items_and_stubs() {
    let out = pretty(expand(
        TokenStream::new(),
        quote! {
            pub mod broken {
                pub struct Coords { pub theta: f64 }
                pub struct Broken { pub m: f64 }
                #[particle(mass = m)]
                fn bob() -> Vec2 { vec2(thta, 0.0) }
            }
        },
    ));
    assert_eq!(
        out.matches("compile_error!").count(),
        2,
        "unknown name and unused coordinate:\n{out}"
    );
    assert!(out.contains("pub struct Broken"));
    assert!(out.contains("pub struct Coords<T = f64>"));
    assert!(out.contains("pub type State"));
    assert!(out.contains("Dynamics<1> for Broken"));
}

#[test]
fn array_coordinates_and_a_family_of_bodies() {
    let out = snapshot(
        "chain",
        quote! {
            pub mod chain {
                pub const LINKS: usize = 3;
                pub struct Coords { pub theta: [f64; LINKS] }
                pub struct Chain { pub m: f64, pub l: f64, pub g: f64 }
                #[particle(mass = m, count = LINKS)]
                fn bob(i: usize) -> Vec2 {
                    let link = vec2(theta[i].sin(), -theta[i].cos()) * l;
                    if i == 0 { link } else { bob[i - 1] + link }
                }
                #[gravity]
                fn down() -> Vec2 { vec2(0.0, -g) }
            }
        },
    );
    assert!(out.contains("pub theta: [T; LINKS]"));
    assert!(
        out.contains(r#"const NAMES: [&'static str; 3] = ["theta[0]", "theta[1]", "theta[2]"];"#)
    );
    assert!(out.contains("impl ::lagrange::__private::Model<3, 6> for Chain"));
    // One sin_cos per element, shared by every member's sin and cos.
    assert!(out.contains("theta.map(|__x| __x.sin_cos())"));
    assert!(!out.contains(".sin()"));
    // Read member by member, the family is a tree: link k is link k − 1 plus its own rod, seeded on
    // theta[k] alone through one shared function of the member's index.
    let squashed: String = out.split_whitespace().collect();
    assert!(squashed.contains("tree::Tree<3,6,1,3>forChain"));
    assert!(squashed.contains("fn__lagrange_displacement_bob_0<__D:::lagrange::__private::Scalar>(&self,i:usize,__t:__D,__theta_at_i:__D,)"));
    assert!(squashed.contains("parent:::lagrange::__private::core::option::Option::Some(1)"));
    assert!(squashed.contains("tree::seed(__q[2],__v[2],0)"));
}
