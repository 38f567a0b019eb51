//! The macro on unusual and broken input: it never panics, and what it accepts expands to code that
//! parses. The declarations are fed to [`expand`] as `proc_macro2` tokens, so a panic here is a
//! panic a user would see as "proc macro panicked".

use crate::expand::expand;
use proc_macro2::TokenStream;
use quote::quote;

/// Expands `module`, failing the test on a panic; returns the expansion.
fn expand_module(module: TokenStream) -> TokenStream {
    expand(TokenStream::new(), module)
}

/// The expansion of a declaration that must be accepted: it parses as Rust and holds no error.
fn accepted(module: TokenStream) -> String {
    let out = expand_module(module);
    let text = out.to_string();
    assert!(!text.contains("compile_error"), "rejected: {text}");
    syn::parse2::<syn::File>(out).expect("the expansion parses as a file");
    text
}

#[test]
fn raw_identifier_coordinate_expands() {
    let text = accepted(quote! {
        pub mod raw {
            pub struct Coords { pub r#type: f64 }
            pub struct Raw { pub m: f64, pub l: f64 }
            #[particle(mass = m)]
            fn bob() -> Vec2 { vec2(r#type.sin(), -r#type.cos()) * l }
        }
    });
    assert!(text.contains("r#type"), "{text}");
}

/// Valid declarations the property test mutates: scalar and array coordinates, a family, every kind
/// of function.
fn seeds() -> Vec<TokenStream> {
    vec![
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
        quote! {
            pub mod chain {
                pub const LINKS: usize = 3;
                pub struct Coords { pub theta: [f64; LINKS] }
                pub struct Chain { pub m: f64, pub l: f64, pub g: f64, pub c: f64 }
                #[particle(mass = m, count = LINKS)]
                fn bob(i: usize) -> Vec2 {
                    let link = vec2(theta[i].sin(), -theta[i].cos()) * l;
                    if i == 0 { link } else { bob[i - 1] + link }
                }
                #[force(on = bob, count = LINKS)]
                fn drag(i: usize) -> Vec2 { bob_dot[i] * (-c) }
                #[gravity]
                fn down() -> Vec2 { vec2(0.0, -g) }
            }
        },
        quote! {
            pub mod wheel {
                pub struct Coords { pub x: f64, pub y: f64, pub phi: f64, pub r#type: f64 }
                pub struct Wheel { pub m: f64, pub i: f64, pub r: f64, pub k: f64, pub mu: f64 }
                #[rigid_body(mass = m, inertia = i)]
                fn disc() -> Planar { planar(vec2(x, y), phi + r#type.sin()) }
                #[point]
                fn rim() -> Vec2 { disc.position() + vec2(r, 0.0) }
                #[particle(mass = m)]
                fn spinner() -> Vec3 { vec3(x, y, r#type.cos()) }
                #[potential]
                fn spring() -> f64 { 0.5 * k * (rim.x * rim.x) }
                #[torque(on = disc)]
                fn motor() -> f64 { -phi_dot * 2.0 }
                #[generalized_force(on = x)]
                fn push() -> f64 { t.sin() }
                #[constraint]
                fn ground() -> f64 { y - r }
                #[velocity_constraint]
                fn roll() -> f64 { x_dot - r * phi_dot }
                #[unilateral]
                fn floor() -> f64 { spinner.z }
                #[friction(on = floor, kinetic = mu, stiction = 2.0 * mu)]
                fn slip() -> f64 { spinner_dot.x }
            }
        },
    ]
}

/// A token stream flattened to leaves and group boundaries, so that a mutation can reach inside
/// the module and keep the brackets balanced.
#[derive(Clone, Debug)]
enum Piece {
    Open(proc_macro2::Delimiter),
    Close,
    Leaf(proc_macro2::TokenTree),
}

fn flatten(tokens: TokenStream, out: &mut Vec<Piece>) {
    for tree in tokens {
        match tree {
            proc_macro2::TokenTree::Group(g) => {
                out.push(Piece::Open(g.delimiter()));
                flatten(g.stream(), out);
                out.push(Piece::Close);
            }
            leaf => out.push(Piece::Leaf(leaf)),
        }
    }
}

fn rebuild(pieces: &[Piece]) -> TokenStream {
    let mut stack: Vec<(proc_macro2::Delimiter, Vec<proc_macro2::TokenTree>)> =
        vec![(proc_macro2::Delimiter::None, Vec::new())];
    for piece in pieces {
        match piece {
            Piece::Open(d) => stack.push((*d, Vec::new())),
            Piece::Close => {
                let (d, trees) = stack.pop().unwrap();
                let group = proc_macro2::Group::new(d, trees.into_iter().collect());
                stack.last_mut().unwrap().1.push(group.into());
            }
            Piece::Leaf(t) => stack.last_mut().unwrap().1.push(t.clone()),
        }
    }
    stack.pop().unwrap().1.into_iter().collect()
}

/// Tokens a mutation may put in: names the macro treats specially, keywords, punctuation and
/// literals of every kind.
fn pool() -> Vec<proc_macro2::TokenTree> {
    let text =
        "theta theta1 bob bob1 Coords f64 usize Vec2 Vec3 Planar Spatial mass count on inertia \
                kinetic t self fn struct pub mod let return r#type r#fn _ theta_dot bob_dot LINKS \
                , ; = # - * : . ! & < > == >= 0 1 8 0usize 1.5 -1 \"s\" 'c' 1e400 i";
    text.parse::<TokenStream>().unwrap().into_iter().collect()
}

/// One mutation of `pieces`, chosen by `op`, at positions `a` and `b` (taken modulo the length).
fn mutate(pieces: &mut Vec<Piece>, op: u8, a: usize, b: usize, pool: &[proc_macro2::TokenTree]) {
    let leaves: Vec<usize> = (0..pieces.len())
        .filter(|&i| matches!(pieces[i], Piece::Leaf(_)))
        .collect();
    let opens: Vec<usize> = (0..pieces.len())
        .filter(|&i| matches!(pieces[i], Piece::Open(_)))
        .collect();
    if leaves.is_empty() || opens.is_empty() {
        return;
    }
    let (i, j) = (leaves[a % leaves.len()], leaves[b % leaves.len()]);
    match op % 7 {
        0 => {
            pieces.remove(i);
        }
        1 => {
            let copy = pieces[i].clone();
            pieces.insert(i, copy);
        }
        2 => pieces.swap(i, j),
        3 => pieces[i] = Piece::Leaf(pool[b % pool.len()].clone()),
        4 => pieces.insert(i, Piece::Leaf(pool[b % pool.len()].clone())),
        // A token wrapped in an invisible group, as a `macro_rules!` fragment arrives.
        5 => {
            pieces.insert(i + 1, Piece::Close);
            pieces.insert(i, Piece::Open(proc_macro2::Delimiter::None));
        }
        // A group's brackets changed, or the group dropped with its contents.
        _ => {
            let o = opens[a % opens.len()];
            if b.is_multiple_of(2) {
                let delimiters = [
                    proc_macro2::Delimiter::Parenthesis,
                    proc_macro2::Delimiter::Brace,
                    proc_macro2::Delimiter::Bracket,
                    proc_macro2::Delimiter::None,
                ];
                pieces[o] = Piece::Open(delimiters[b / 2 % 4]);
            } else {
                let mut depth = 0;
                let mut end = o;
                for (k, piece) in pieces.iter().enumerate().skip(o) {
                    match piece {
                        Piece::Open(_) => depth += 1,
                        Piece::Close => depth -= 1,
                        Piece::Leaf(_) => {}
                    }
                    if depth == 0 {
                        end = k;
                        break;
                    }
                }
                pieces.drain(o..=end);
            }
        }
    }
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(400))]

    /// Random token mutations of valid declarations: the macro reports or expands, never panics.
    #[test]
    fn mutated_declarations_never_panic(
        seed in 0usize..3,
        mutations in proptest::collection::vec((0u8..7, 0usize..10_000, 0usize..10_000), 1..4),
    ) {
        let pool = pool();
        let mut pieces = Vec::new();
        flatten(seeds()[seed].clone(), &mut pieces);
        for (op, a, b) in mutations {
            mutate(&mut pieces, op, a, b, &pool);
        }
        // A panic fails the case; a mistake is reported, so something always comes out.
        let out = expand_module(rebuild(&pieces));
        proptest::prop_assert!(!out.is_empty());
    }
}

#[test]
fn seeds_are_accepted() {
    for seed in seeds() {
        accepted(seed);
    }
}

/// `tokens` in an invisible group, as a `macro_rules!` fragment (`$n:literal`, `$n:expr`) arrives.
fn invisible(tokens: TokenStream) -> proc_macro2::Group {
    proc_macro2::Group::new(proc_macro2::Delimiter::None, tokens)
}

#[test]
fn invisible_groups_are_looked_through() {
    let n = invisible(quote!(3));
    let len = invisible(quote!(LINKS));
    let on = invisible(quote!(bob));
    let ty = invisible(quote!(Vec2));
    let index = invisible(quote!(i - 1));
    accepted(quote! {
        pub mod chain {
            pub const LINKS: usize = #n;
            pub struct Coords { pub theta: [f64; #len] }
            pub struct Chain { pub m: f64, pub l: f64, pub c: f64 }
            #[particle(mass = m, count = #n)]
            fn bob(i: usize) -> #ty {
                let link = vec2(theta[i].sin(), -theta[i].cos()) * l;
                if i == 0 { link } else { bob[#index] + link }
            }
            #[force(on = #on, count = #len)]
            fn drag(i: usize) -> Vec2 { bob_dot[i] * (-c) }
        }
    });
}
