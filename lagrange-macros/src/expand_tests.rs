//! Expansion tests: each declaration is expanded, pretty-printed and compared with a snapshot in
//! `tests/expand/`. Run with `LAGRANGE_BLESS=1` to rewrite the snapshots after a deliberate change
//! (and read the diff). The assertions below pin down that only the effects a declaration calls for
//! are generated (README, "How it works").

use crate::expand::expand;
use proc_macro2::TokenStream;
use quote::{format_ident, quote};
use std::path::PathBuf;

fn pretty(tokens: TokenStream) -> String {
    prettyplease::unparse(&syn::parse2(tokens).expect("the expansion parses as a file"))
}

/// Expands `module`, compares with the snapshot `name`, and returns the pretty-printed expansion.
fn snapshot(name: &str, module: TokenStream) -> String {
    let expanded = pretty(expand(TokenStream::new(), module));
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/expand")
        .join(format!("{name}.expanded.rs"));
    if std::env::var_os("LAGRANGE_BLESS").is_some() {
        std::fs::write(&path, &expanded).unwrap();
    } else {
        let want = std::fs::read_to_string(&path).unwrap_or_else(|_| {
            panic!("no snapshot {}; run with LAGRANGE_BLESS=1", path.display())
        });
        assert!(
            want == expanded,
            "expansion of `{name}` differs from {}:\n{expanded}",
            path.display()
        );
    }
    expanded
}

fn pendulum() -> TokenStream {
    quote! {
        pub mod pendulum {
            pub struct Coords { pub theta: f64 }
            pub struct Pendulum { pub m: f64, pub l: f64, pub g: f64 }
            #[particle(mass = m)]
            fn bob() -> Vec2 { vec2(theta.sin(), -theta.cos()) * l }
            #[gravity]
            fn down() -> Vec2 { vec2(0.0, -g) }
        }
    }
}

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
    // The unconstrained pendulum keeps the trait's plain accelerations and no-op hooks.
    let out = pretty(expand(TokenStream::new(), pendulum()));
    assert!(!out.contains("Constraints<"), "no Constraints impl:\n{out}");
    assert!(
        !out.contains("fn accelerations_at"),
        "no KKT override:\n{out}"
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

#[test]
fn a_body_translated_from_another_is_seeded_on_its_own_angle() {
    // Drag on the second bob: a force, so the equations are not derived in closed form and the
    // tree of translations serves.
    let out = pretty(expand(
        TokenStream::new(),
        quote! {
            pub mod double_pendulum {
                pub struct Coords { pub theta1: f64, pub theta2: f64 }
                pub struct DoublePendulum { pub m1: f64, pub m2: f64, pub l1: f64, pub l2: f64, pub g: f64, pub c: f64 }
                #[particle(mass = m1)]
                fn bob1() -> Vec2 { vec2(theta1.sin(), -theta1.cos()) * l1 }
                #[particle(mass = m2)]
                fn bob2() -> Vec2 { bob1 + vec2(theta2.sin(), -theta2.cos()) * l2 }
                #[gravity]
                fn down() -> Vec2 { vec2(0.0, -g) }
                #[force(on = bob2)]
                fn drag() -> Vec2 { -bob2_dot * c }
            }
        },
    ));
    // Compared without whitespace: the pretty-printer breaks lines where it likes.
    let out: String = out.split_whitespace().collect();
    assert!(!out.contains("__lagrange_closed_form"));
    // Two coordinates, four rows, seeds one wide, two bodies: bob2 is bob1 plus its own arm.
    assert!(out.contains("Tree<2,4,1,2>forDoublePendulum"));
    assert!(out.contains("tree::equations_of_motion::<Self,S,2,4,1,2,>"));
    assert!(out.contains("parent:::lagrange::__private::core::option::Option::Some(0)"));
    // The arm alone, seeded on theta2 only: bob1 is not evaluated again on the seeds.
    assert!(out.contains("fn__lagrange_displacement_bob2<__D:::lagrange::__private::Scalar>(&self,__t:__D,theta2:__D,)"));
    assert!(out.contains("tree::seed(__q[1],__v[1],0)"));
}

#[test]
fn a_double_pendulum_is_derived_in_closed_form() {
    let out = snapshot(
        "double_pendulum",
        quote! {
            pub mod double_pendulum {
                pub struct Coords { pub theta1: f64, pub theta2: f64 }
                pub struct DoublePendulum { pub m1: f64, pub m2: f64, pub l1: f64, pub l2: f64, pub g: f64 }
                #[particle(mass = m1)]
                fn bob1() -> Vec2 { vec2(theta1.sin(), -theta1.cos()) * l1 }
                #[particle(mass = m2)]
                fn bob2() -> Vec2 { bob1 + vec2(theta2.sin(), -theta2.cos()) * l2 }
                #[gravity]
                fn down() -> Vec2 { vec2(0.0, -g) }
            }
        },
    );
    let out: String = out.split_whitespace().collect();
    assert!(!out.contains("tree::Tree<"));
    assert!(out.contains("self.__lagrange_closed_form::<S>(q,v)"));
    // One sin_cos per angle; M₁₁ and M₂₂ constant (sin² + cos² = 1), M₁₂ through
    // cos(θ₁ − θ₂) = sin θ₁ sin θ₂ + cos θ₁ cos θ₂ scaled once.
    assert!(out.contains("let(__sin_0,__cos_0)=__q[0].sin_cos();"));
    assert!(out.contains("let(__sin_1,__cos_1)=__q[1].sin_cos();"));
    // The constant factors are computed apart, once per validated handle.
    assert!(out.contains("fn__lagrange_coefficients(&self)->[f64;5]"));
    assert!(out.contains("[l1*l1*__masses[0]+l1*l1*__masses[2],"));
    assert!(out.contains("(__product_0+__product_1)*__k[1]"));
    assert!(out.contains("typePrepared=[f64;5];"));
}

#[test]
fn a_pendulum_is_derived_in_closed_form() {
    // M = m l² (sin² θ + cos² θ) = m l², b = 0, 𝓕 = −m g l sin θ: one sine, no cosine.
    let out = snapshot("pendulum", pendulum());
    let out: String = out.split_whitespace().collect();
    assert!(!out.contains("dynamics::equations_of_motion::<"));
    assert!(out.contains("let__sin_0=__q[0].sin();"));
    assert!(!out.contains("__cos_0"));
    assert!(out.contains("[[<__D>::from(__k[0])]],[-__sin_0*__k[1]],[<__D>::from(0.0)],"));
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

#[test]
fn an_affine_declaration_prepares_its_mass_matrix_once() {
    // A block on a wedge that slides on the floor: every row is a coordinate times a constant
    // of the parameters, so J and M are constants, prepared when the handle is validated.
    let out = snapshot(
        "wedge_block",
        quote! {
            pub mod wedge_block {
                pub struct Coords { pub x: f64, pub d: f64 }
                pub struct WedgeBlock { pub big_m: f64, pub m: f64, pub alpha: f64, pub g: f64 }
                #[particle(mass = big_m)]
                fn wedge() -> Vec2 { vec2(x, 0.0) }
                #[particle(mass = m)]
                fn block() -> Vec2 { wedge + vec2(d * alpha.cos(), -d * alpha.sin()) }
                #[gravity]
                fn down() -> Vec2 { vec2(0.0, -g) }
            }
        },
    );
    assert!(out.contains("affine::AffineConstants<") && out.contains("AffineConstants::of::<"));
    assert!(out.contains("fn accelerations_prepared_at"));
    // A pendulum's rows are sines and cosines of its angle: its closed form's coefficients are
    // what it prepares, not J and M.
    let pendulum = pretty(expand(TokenStream::new(), pendulum()));
    assert!(pendulum.contains("type Prepared = [f64; 2];"));
    assert!(!pendulum.contains("AffineConstants"));
}

/// A chain of `links` pendulum links declared one by one.
fn chain_declared_link_by_link(links: usize) -> TokenStream {
    let angles: Vec<_> = (0..links).map(|k| format_ident!("theta{}", k)).collect();
    let bobs: Vec<_> = (0..links).map(|k| format_ident!("bob{}", k)).collect();
    let bodies = (0..links).map(|k| {
        let (bob, angle) = (&bobs[k], &angles[k]);
        let parent = (k > 0).then(|| {
            let parent = &bobs[k - 1];
            quote!(#parent +)
        });
        quote! {
            #[particle(mass = m)]
            fn #bob() -> Vec2 { #parent vec2(#angle.sin(), -#angle.cos()) * l }
        }
    });
    quote! {
        pub mod chain {
            pub struct Coords { #(pub #angles: f64),* }
            pub struct Chain { pub m: f64, pub l: f64, pub g: f64 }
            #(#bodies)*
            #[gravity]
            fn down() -> Vec2 { vec2(0.0, -g) }
        }
    }
}

#[test]
fn chains_past_a_few_links_take_the_articulated_recursion() {
    // 8 links: 184 terms in M, 𝓕 and b (23 per body), written out. 16 links: 752 (47 per body),
    // past what the articulated-body recursion of the tree costs, so the tree serves, with q̈ from
    // the recursion (each angle moves one link).
    let eight = pretty(expand(TokenStream::new(), chain_declared_link_by_link(8)));
    assert!(eight.contains("fn __lagrange_closed_form<"));
    assert!(!eight.contains("tree::Tree<"));
    let sixteen = pretty(expand(TokenStream::new(), chain_declared_link_by_link(16)));
    assert!(!sixteen.contains("fn __lagrange_closed_form<"));
    assert!(sixteen.contains("tree::Tree<"));
    assert!(sixteen.contains("tree::accelerations::<"));
}

/// The gradient of the potential from its expression tree: the spring's difference q₁ − q₀ is
/// computed once and its derivative by q₀ subtracts what its derivative by q₁ adds; Kepler's
/// −μ m/|r| through the body is multiplied by J's rows; no dual number in `potential_gradient`.
#[test]
fn potentials_read_as_trees_are_derived_in_closed_form() {
    let out = snapshot(
        "symbolic_potentials",
        quote! {
            pub mod springs {
                pub struct Coords { pub q: [f64; 2], pub x: f64, pub y: f64 }
                pub struct Springs { pub m: f64, pub omega: f64, pub mu: f64 }
                #[particle(mass = m, count = 2)]
                fn mass(i: usize) -> Vec2 { vec2(q[i], 0.0) }
                #[particle(mass = m)]
                fn planet() -> Vec2 { vec2(x, y) }
                #[potential]
                fn stiff() -> f64 { omega * omega / 4.0 * (q[1] - q[0]).powi(2) }
                #[potential]
                fn gravitation() -> f64 { -mu * m / planet.norm() }
            }
        },
    );
    let gradient = &out[out.find("fn potential_gradient").unwrap()..];
    assert!(
        !gradient.contains("DualSVec"),
        "no dual numbers:\n{gradient}"
    );
    assert!(gradient.contains("__gradient[1] +="), "{gradient}");
    assert!(gradient.contains("__gradient[0] -="), "{gradient}");
    assert!(!out.contains("fn __potential_stiff_0"));
}

/// Which potentials the tree reader reads (their gradient has no dual number) and which keep the
/// dual numbers; each names two of three coordinates, so the dual path is the narrow one.
#[test]
fn the_tree_reader_reads_what_it_can_differentiate_exactly() {
    let gradient_of = |body: TokenStream| -> String {
        let out = pretty(expand(
            TokenStream::new(),
            quote! {
                pub mod m {
                    pub const N: usize = 3;
                    pub struct Coords { pub q: [f64; N] }
                    pub struct M { pub m: f64, pub k: f64 }
                    #[particle(mass = m, count = N)]
                    fn bead(i: usize) -> Vec2 { vec2(q[i], 0.0) }
                    #[point]
                    fn tip() -> Vec2 { bead[1] + vec2(q[0], 1.0) }
                    #[potential]
                    fn v() -> f64 #body
                }
            },
        ));
        match out.find("fn potential_gradient") {
            Some(at) => out[at..].to_string(),
            None => panic!("{body}: no potential_gradient"),
        }
    };
    let read = [
        quote!({ k * (q[1] - q[0]).powi(3) }),
        quote!({
            let d = bead[1].x - bead[0].x;
            (k * d).sin() + d.cos().exp()
        }),
        quote!({ (tip - bead[1]).norm().ln() * k.sqrt() + t * q[0] }),
        quote!({ k / (1.0 + q[0] * q[0]).sqrt() - q[1].recip() * std::f64::consts::PI }),
        quote!({
            let (a, b) = (q[0], q[1]);
            a.powi(-2) * b / 2
        }),
    ];
    for body in read {
        let gradient = gradient_of(body.clone());
        assert!(!gradient.contains("DualSVec"), "{body}: {gradient}");
    }
    let unread = [
        quote!({ k * (q[1] - q[0]).abs() }),
        quote!({ q[0].powf(k) + q[1] }),
        quote!({
            if q[0] > 0.0 {
                q[1]
            } else {
                q[0]
            }
        }),
        quote!({ q[0].tanh() + q[1] }),
        quote!({ q[0].hypot(q[1]) }),
        quote!({ q[0].max(q[1]) }),
    ];
    for body in unread {
        let gradient = gradient_of(body.clone());
        assert!(gradient.contains("DualSVec"), "{body}: {gradient}");
    }
}

/// Through a validated handle an affine declaration is checked in one branch when q̈ from the
/// prepared constants is straight-line code: no force, no constraint, and every potential derived
/// on its expression tree (a part left to dual numbers runs the declaration's own code).
#[test]
fn only_straight_line_affine_mechanisms_are_checked_in_one_branch() {
    let with = |items: TokenStream| -> String {
        pretty(expand(
            TokenStream::new(),
            quote! {
                pub mod m {
                    pub struct Coords { pub x: f64, pub y: f64 }
                    pub struct M { pub m: f64, pub k: f64 }
                    #[particle(mass = m)]
                    fn p() -> Vec2 { vec2(x, y) }
                    #items
                }
            },
        ))
    };
    let one_branch = "const PREPARED_IN_ONE_BRANCH: bool = true;";
    let straight_line = [
        quote!(
            #[potential]
            fn v() -> f64 {
                k * p.norm_squared()
            }
        ),
        quote!(
            #[gravity]
            fn down() -> Vec2 {
                vec2(0.0, -k)
            }
        ),
    ];
    for items in straight_line {
        let out = with(items.clone());
        assert!(
            out.contains("affine::AffineConstants<"),
            "{items}: not affine"
        );
        assert!(out.contains(one_branch), "{items}");
        assert!(out.contains("affine::regular_accelerations::<"), "{items}");
    }
    // Holonomic rows read as trees: the Schur complement from the same constants, in one branch,
    // and the projection from them too.
    let out = with(quote!(
        #[gravity]
        fn down() -> Vec2 {
            vec2(0.0, -k)
        }
        #[constraint]
        fn rod() -> f64 {
            p.norm_squared() - k
        }
    ));
    assert!(out.contains(one_branch), "{out}");
    assert!(
        out.contains("constraints::regular_accelerations_prepared::<"),
        "{out}"
    );
    assert!(out.contains("constraints::project_prepared::<"), "{out}");
    let other = [
        quote!(
            #[force(on = p)]
            fn push() -> Vec2 {
                vec2(k, 0.0)
            }
        ),
        quote!(
            #[potential]
            fn v() -> f64 {
                x.tanh() + y
            }
        ),
        quote!(
            #[unilateral]
            fn floor() -> f64 {
                y
            }
        ),
    ];
    for items in other {
        let out = with(items.clone());
        assert!(
            out.contains("affine::AffineConstants<"),
            "{items}: not affine"
        );
        assert!(!out.contains("PREPARED_IN_ONE_BRANCH"), "{items}");
        assert!(!out.contains("regular_accelerations"), "{items}");
    }
}

/// A spatial arm as the README writes it: the tree pass, its three sweeps written body by body, the
/// joint with no constant rotation before it known as such.
#[test]
fn a_spatial_arm_takes_the_rigid_tree_pass() {
    let out = snapshot(
        "spatial_arm",
        quote! {
            pub mod arm {
                pub struct Coords { pub q1: f64, pub q2: f64 }
                pub struct Arm { pub m1: f64, pub m2: f64, pub d: f64, pub e: f64, pub g: f64 }
                #[rigid_body(mass = m1, inertia = [0.03, 0.025, 0.01])]
                fn link1() -> Spatial {
                    let r = rot_z(q1);
                    spatial(r * vec3(0.0, 0.0, 0.5 * d), r)
                }
                #[rigid_body(mass = m2, inertia = [0.03, 0.025, 0.01])]
                fn link2() -> Spatial {
                    let r = link1.rotation * rot_y(q2);
                    let joint = link1.point(vec3(-e, 0.0, 0.5 * d));
                    spatial(joint + r * vec3(e, 0.0, 0.5 * d), r)
                }
                #[gravity]
                fn down() -> Vec3 { vec3(0.0, 0.0, -g) }
            }
        },
    );
    let squeezed: String = out.split_whitespace().collect();
    assert!(out.contains("tree::rigid::RigidTree<2, 2> for Arm"));
    assert!(squeezed
        .contains("JointKind::Revolute(::lagrange::__private::tree::rigid::spatial::Axis::Y,)"));
    // The second joint's offset from the first's: (−e, 0, d/2) + (0, 0, d/2), y structurally zero.
    assert!(out.contains("offset: [true, false, true]"));
    // The second joint follows its parent's frame with no constant rotation between.
    assert!(out.contains("rotated: false"));
    // Each body's step is compiled for its own joint (its code a constant of the tree).
    for b in 0..2 {
        let code = format!("{{<Armas::lagrange::__private::tree::rigid::RigidTree<2,2,>>::JOINTS[{b}].code()}},2,>");
        assert!(squeezed.contains(&format!("__ws.velocity::<{code}(__joints,__k,__q,__v,{b})")));
        assert!(squeezed.contains(&format!(".articulate::<{code}(__joints,__k,__tau,{b})")));
        assert!(squeezed.contains(&format!("__ws.accelerate::<{code}(__joints,__k,__qdd,{b})")));
    }
    assert!(out.contains("type Prepared = ::lagrange::__private::tree::rigid::RigidConstants<2>"));
    assert!(out.contains("fn inverse_dynamics_prepared_at"));
    // No dense pass for q̈.
    assert!(!out.contains("dynamics::equations_of_motion::<Self"));
}

/// A branched tree (a torso and two legs) is one tree with two branches: both legs' parent is the
/// torso.
#[test]
fn a_branched_tree_takes_the_rigid_tree_pass() {
    let out = snapshot(
        "branched_tree",
        quote! {
            pub mod legs {
                pub struct Coords { pub yaw: f64, pub left: f64, pub right: f64 }
                pub struct Legs { pub m: f64, pub w: f64, pub g: f64 }
                #[rigid_body(mass = m, inertia = [0.2, 0.15, 0.1])]
                fn torso() -> Spatial { spatial(vec3(0.0, 0.0, 1.0), rot_z(yaw)) }
                #[rigid_body(mass = m, inertia = [0.05, 0.05, 0.01])]
                fn left_leg() -> Spatial {
                    let r = torso.rotation * rot_x(left);
                    spatial(torso.point(vec3(w, 0.0, -0.3)) + r * vec3(0.0, 0.0, -0.2), r)
                }
                #[rigid_body(mass = m, inertia = [0.05, 0.05, 0.01])]
                fn right_leg() -> Spatial {
                    let r = torso.rotation * rot_x(right);
                    spatial(torso.point(vec3(-w, 0.0, -0.3)) + r * vec3(0.0, 0.0, -0.2), r)
                }
                #[gravity]
                fn down() -> Vec3 { vec3(0.0, 0.0, -g) }
            }
        },
    );
    assert!(out.contains("tree::rigid::RigidTree<3, 3> for Legs"));
    assert_eq!(
        out.matches("parent: ::lagrange::__private::core::option::Option::Some(0)")
            .count(),
        2
    );
}

/// A body declared by its joint frame, with its centre of mass and a full tensor in that frame:
/// x holds the centre of mass and the principal axes (`principal` of the frame), the bodies seen
/// by potentials and forces are the frames mapped back (`frame`), the tensor's principal moments
/// are computed once per `masses`, and `validate` checks the tensor, the centre of mass and the
/// constant rotations (`rot3`, `rot_axis`).
#[test]
fn a_body_declared_by_its_frame() {
    let out = snapshot(
        "framed_body",
        quote! {
            pub mod arm {
                pub struct Coords { pub q1: f64, pub q2: f64 }
                pub struct Arm { pub m: f64, pub l: f64, pub c: f64, pub ixx: f64, pub ixy: f64, pub izz: f64, pub k: f64 }
                #[rigid_body(mass = m, com = vec3(0.0, 0.0, c), inertia = [[ixx, ixy, 0.0], [ixy, ixx, 0.0], [0.0, 0.0, izz]])]
                fn upper() -> Spatial { spatial(vec3(0.0, 0.0, 0.0), rot_z(q1)) }
                #[rigid_body(mass = m, com = vec3(0.0, 0.0, c), inertia = [ixx, ixx, izz])]
                fn lower() -> Spatial {
                    upper.joint(vec3(0.0, 0.0, l), rot3([[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]]) * rot_axis(vec3(0.0, 1.0, 0.0), q2))
                }
                #[potential]
                fn spring() -> f64 { 0.5 * k * lower.position.norm_squared() }
            }
        },
    );
    // Without the pretty-printer's line breaks.
    let out: String = out.split_whitespace().collect();
    assert!(out.contains("fn__lagrange_mass_frame_upper(&self,)"));
    assert!(out.contains("principal_axes(&__inertia_upper,).0"));
    assert!(out.contains(".__lagrange_mass_frame_upper().principal(__bodies.upper)"));
    assert!(out.contains("__frame_lower.frame("));
    assert!(out.contains("check_inertia_tensor(\"upper\""));
    assert!(out.contains("check_centre_of_mass(\"lower\""));
    assert!(out.contains("check_rotation(\"lower\""));
    assert!(out.contains("check_axis(\"lower\""));
    // Principal moments need no decomposition: the lower link's frame has no axes to turn.
    assert!(!out.contains("principal_axes(&__inertia_lower"));
}
