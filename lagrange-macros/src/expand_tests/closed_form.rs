//! The closed-form equations of motion, the prepared constants of affine declarations, and the
//! articulated recursion past a few links.

use super::{pendulum, pretty, snapshot};
use crate::expand::expand;
use proc_macro2::TokenStream;
use quote::{format_ident, quote};

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
    // q̈ from the prepared constants where the handle has them.
    assert!(out.contains("affine::accelerations::<") && out.contains(">(self, prepared, t, q, v)"));
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

/// A particle at (x, y) with the items given: an affine declaration.
fn affine_particle_with(items: TokenStream) -> String {
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
}

const ONE_BRANCH: &str = "const PREPARED_IN_ONE_BRANCH: bool = true;";

/// Through a validated handle an affine declaration is checked in one branch when q̈ from the
/// prepared constants is straight-line code: no force, no constraint, and every potential derived
/// on its expression tree.
#[test]
fn straight_line_affine_mechanisms_are_checked_in_one_branch() {
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
        let out = affine_particle_with(items.clone());
        assert!(
            out.contains("affine::AffineConstants<"),
            "{items}: not affine"
        );
        assert!(out.contains(ONE_BRANCH), "{items}");
        assert!(out.contains("affine::regular_accelerations::<"), "{items}");
    }
}

/// Holonomic rows read as trees: the Schur complement from the same constants, in one branch, and
/// the projection from them too.
#[test]
fn affine_mechanisms_with_rows_read_as_trees_are_checked_in_one_branch() {
    let out = affine_particle_with(quote!(
        #[gravity]
        fn down() -> Vec2 {
            vec2(0.0, -k)
        }
        #[constraint]
        fn rod() -> f64 {
            p.norm_squared() - k
        }
    ));
    assert!(out.contains(ONE_BRANCH), "{out}");
    assert!(
        out.contains("constraints::regular_accelerations_prepared::<"),
        "{out}"
    );
    assert!(out.contains("constraints::project_prepared::<"), "{out}");
}

/// A force, a potential left to dual numbers (it runs the declaration's own code) or a contact:
/// still affine, but not checked in one branch.
#[test]
fn other_affine_mechanisms_are_not_checked_in_one_branch() {
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
        let out = affine_particle_with(items.clone());
        assert!(
            out.contains("affine::AffineConstants<"),
            "{items}: not affine"
        );
        assert!(!out.contains("PREPARED_IN_ONE_BRANCH"), "{items}");
        assert!(!out.contains("regular_accelerations"), "{items}");
    }
}
