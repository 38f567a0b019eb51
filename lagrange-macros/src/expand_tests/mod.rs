//! Expansion tests: each declaration is expanded, pretty-printed and compared with a snapshot in
//! `tests/expand/`. Run with `LAGRANGE_BLESS=1` to rewrite the snapshots after a deliberate change
//! (and read the diff). The assertions in the submodules pin down that only the effects a declaration calls for
//! are generated (README, "How it works").

use crate::expand::expand;
use proc_macro2::TokenStream;
use quote::quote;
use std::path::PathBuf;

mod closed_form;
mod constraints;
mod effects;
mod potentials;
mod trees;

fn pretty(tokens: TokenStream) -> String {
    prettyplease::unparse(&syn::parse2(tokens).expect("the expansion parses as a file"))
}

/// Expands `module`, compares with the snapshot `name`, and returns the pretty-printed expansion.
fn snapshot(name: &str, module: TokenStream) -> String {
    let expanded = pretty(expand(TokenStream::new(), module));
    compare_with_snapshot(&format!("{name}.expanded.rs"), &expanded);
    expanded
}

/// Compares `text` with the file `tests/expand/<file>` (rewrites it with `LAGRANGE_BLESS=1`).
pub(crate) fn compare_with_snapshot(file: &str, text: &str) {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/expand")
        .join(file);
    if std::env::var_os("LAGRANGE_BLESS").is_some() {
        std::fs::write(&path, text).unwrap();
    } else {
        let want = std::fs::read_to_string(&path).unwrap_or_else(|_| {
            panic!("no snapshot {}; run with LAGRANGE_BLESS=1", path.display())
        });
        assert!(
            want == text,
            "`{file}` differs from {}:\n{text}",
            path.display()
        );
    }
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
