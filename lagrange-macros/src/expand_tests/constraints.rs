//! Constraint rows: the KKT hooks, their derivatives, friction only when declared, and the
//! structural zeros of J.

use super::{pendulum, pretty, snapshot};
use crate::expand::expand;
use proc_macro2::TokenStream;
use quote::quote;

#[test]
fn constraints_implement_the_kkt_hooks() {
    let out = snapshot(
        "sliding_block",
        quote! {
            pub mod sliding_block {
                pub struct Coords { pub x: f64, pub y: f64 }
                pub struct SlidingBlock { pub m: f64, pub g: f64, pub mu: f64 }
                #[particle(mass = m)]
                fn block() -> Vec2 { vec2(x, y) }
                #[gravity]
                fn down() -> Vec2 { vec2(0.0, -g) }
                #[unilateral]
                fn floor() -> f64 { block.y }
                #[friction(on = floor, kinetic = mu)]
                fn slide() -> f64 { block_dot.x }
            }
        },
    );
    assert!(out.contains("constraints::Constraints<2, 2, 2>"));
    assert!(out.contains("ConstraintKind::Friction {\n                normal: 0,"));
    assert!(
        out.contains("fn accelerations_at")
            && out.contains("fn project")
            && out.contains("fn check_constraints")
    );
    // Without constraints, none of it.
    let free = pretty(expand(TokenStream::new(), pendulum()));
    assert!(!free.contains("Constraints<") && !free.contains("fn project"));
}

#[test]
fn constraint_rows_read_as_trees_write_their_derivatives() {
    let out = snapshot(
        "cartesian_pendulum",
        quote! {
            pub mod cartesian_pendulum {
                pub struct Coords { pub x: f64, pub y: f64 }
                pub struct CartesianPendulum { pub m: f64, pub l: f64, pub g: f64 }
                #[particle(mass = m)]
                fn bob() -> Vec2 { vec2(x, y) }
                #[gravity]
                fn down() -> Vec2 { vec2(0.0, -g) }
                #[constraint]
                fn rod() -> f64 { bob.norm() - l }
                #[constraint]
                fn opaque() -> f64 { bob.x.abs() - l }
            }
        },
    );
    // The rod is read (`bob` is `vec2(x, y)`: its rows are the coordinates); `abs` is not, and that
    // row keeps its dual numbers.
    assert!(out.contains("const POSITION_DERIVATIVES: [bool; 2] = [true, false];"));
    assert!(out.contains("fn position_constraint_derivatives"));
    // G = r/|r|: the square root once, and no row of x read.
    assert_eq!(out.matches(".sqrt()").count(), 1, "{out}");
    assert!(!out.contains("__jacobian["));
}

/// A block on a ramp held by a bilateral `#[constraint]`, optionally with friction on it.
fn block_on_ramp(friction: bool) -> TokenStream {
    let friction = friction.then(|| {
        quote! {
            #[friction(on = surface, kinetic = mu)]
            fn slip() -> f64 { block_dot.x * alpha.cos() - block_dot.y * alpha.sin() }
        }
    });
    quote! {
        pub mod ramp {
            pub struct Coords { pub x: f64, pub y: f64 }
            pub struct Ramp { pub m: f64, pub alpha: f64, pub mu: f64, pub g: f64 }
            #[particle(mass = m)]
            fn block() -> Vec2 { vec2(x, y) }
            #[constraint]
            fn surface() -> f64 { block.x * alpha.sin() + block.y * alpha.cos() }
            #friction
            #[gravity]
            fn down() -> Vec2 { vec2(0.0, -g) }
        }
    }
}

#[test]
fn no_constraints_means_no_constraint_solve() {
    // The unconstrained pendulum solves M q̈ = 𝓕 − b (from its prepared coefficients through a
    // handle), never the constrained system, and keeps the trait's no-op hooks.
    let out = pretty(expand(TokenStream::new(), pendulum()));
    assert!(!out.contains("Constraints<"), "no Constraints impl:\n{out}");
    assert!(out.contains("dynamics::solve_accelerations"), "{out}");
    assert!(
        !out.contains("constraints::accelerations"),
        "no KKT solve:\n{out}"
    );
    assert!(!out.contains("fn project"), "no projection hook:\n{out}");
}

#[test]
fn a_constraint_brings_the_constrained_solve_and_friction_only_when_declared() {
    let bilateral = pretty(expand(TokenStream::new(), block_on_ramp(false)));
    assert!(bilateral.contains("Constraints<2, 2, 1>"));
    assert!(bilateral.contains("fn accelerations_at"));
    assert!(bilateral.contains("fn project"));
    // Without friction, no Coulomb coefficients and no friction row: the runtime's mode inference
    // (which rows slide or stick) is decided from KINDS at compile time and skipped.
    assert!(!bilateral.contains("fn friction_coefficients"));
    assert!(!bilateral.contains("ConstraintKind::Friction"));
    let rough = pretty(expand(TokenStream::new(), block_on_ramp(true)));
    assert!(rough.contains("Constraints<2, 2, 2>"));
    assert!(rough.contains("fn friction_coefficients"));
    assert!(rough.contains("ConstraintKind::Friction"));
}

/// The structural zeros of J a declaration states: each row depends on the coordinates its body
/// names and on those of the bodies it names (the coupler names the crank's angle through `tip`,
/// the rocker only its own), so the dense assembly skips the products that are zero.
#[test]
fn rows_depend_on_the_coordinates_their_bodies_name() {
    let out = pretty(expand(
        TokenStream::new(),
        quote! {
            pub mod linkage {
                pub struct Coords { pub a: f64, pub b: f64, pub c: f64 }
                pub struct Linkage { pub m: f64, pub l: f64 }
                #[particle(mass = m)]
                fn crank() -> Vec2 { vec2(a.cos(), a.sin()) * l }
                #[particle(mass = m)]
                fn coupler() -> Vec2 {
                    let tip = crank;
                    tip + vec2(b.cos(), b.sin()) * l
                }
                #[particle(mass = m)]
                fn rocker() -> Vec2 { vec2(c.cos(), c.sin()) * l }
                #[constraint]
                fn closed() -> f64 { coupler.x - rocker.x }
            }
        },
    ));
    let compact: String = out.split_whitespace().collect();
    let depends = compact
        .split("constDEPENDS:[[bool;3];6]=")
        .nth(1)
        .and_then(|rest| rest.split("];").next())
        .expect("DEPENDS is declared");
    assert_eq!(
        depends,
        "[[true,false,false],[true,false,false],[true,true,false],[true,true,false],\
         [false,false,true],[false,false,true],"
    );
}

/// Where every row names every coordinate there is nothing to rule out: the default stays.
#[test]
fn no_depends_table_when_every_row_names_every_coordinate() {
    let out = pretty(expand(TokenStream::new(), pendulum()));
    assert!(!out.contains("const DEPENDS"));
}
