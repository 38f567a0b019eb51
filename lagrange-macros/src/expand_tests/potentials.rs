//! The gradient of the potential read as an expression tree.

use super::{pretty, snapshot};
use crate::expand::expand;
use proc_macro2::TokenStream;
use quote::quote;

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

/// Springs between the masses of a chain, read through the bodies' rows: each row's derivative
/// multiplied by its row of J, and every slot, which two springs add to, scaled once its sum is
/// done (`__gradient[j] *= __scale[j]`).
#[test]
fn springs_between_bodies_add_through_the_rows_of_j() {
    let out = snapshot(
        "spring_chain",
        quote! {
            pub mod spring_chain {
                pub const MASSES: usize = 3;
                pub struct Coords { pub x: [f64; MASSES] }
                pub struct SpringChain { pub m: f64, pub k_wall: f64, pub k: f64 }
                #[particle(mass = m, count = MASSES)]
                fn mass(i: usize) -> Vec2 { vec2(x[i], 0.0) }
                #[potential]
                fn springs() -> f64 {
                    let d1 = mass[1].x - mass[0].x;
                    let d2 = mass[2].x - mass[1].x;
                    0.5 * k_wall * mass[0].x * mass[0].x + 0.5 * k * (d1 * d1 + d2 * d2)
                }
            }
        },
    );
    let gradient = &out[out.find("fn potential_gradient").unwrap()..];
    assert!(!gradient.contains("DualSVec"), "{gradient}");
    assert!(out.contains("__row[0]"), "{gradient}");
    assert!(out.contains("__gradient[1] *= __scale[1];"), "{out}");
}

/// Two particles on perpendicular lines tied by a spring, and a pin on one coordinate: a slot
/// one derivative alone adds to takes its scale into its row of J's entry
/// (`__row[j] * __scale[j]`).
#[test]
fn a_slot_one_derivative_adds_to_takes_the_scale_into_the_row() {
    let out = snapshot(
        "stretched",
        quote! {
            pub mod stretched {
                pub struct Coords { pub a: f64, pub b: f64 }
                pub struct Stretched { pub m1: f64, pub m2: f64, pub k: f64 }
                #[particle(mass = m1)]
                fn p() -> Vec2 { vec2(2.0 * a + 0.3, 0.0) }
                #[particle(mass = m2)]
                fn r() -> Vec2 { vec2(0.0, 3.0 * b) }
                #[potential]
                fn spring() -> f64 { k * ((p - r).norm() - 1.0).powi(2) }
                #[potential]
                fn pin() -> f64 { k * a.powi(2) / 3.0 }
            }
        },
    );
    assert!(out.contains("__row[1] * __scale[1])"), "{out}");
}
