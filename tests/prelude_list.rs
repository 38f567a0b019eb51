//! `#[mechanism]` resolves the names a declaration takes from `use lagrange::prelude::*;` by a
//! list of its own (the macro cannot see the facade crate it is re-exported from). That list is
//! held here to the prelude as `src/lib.rs` declares it, so a name added to or removed from one
//! and not the other fails this test.

use std::collections::BTreeSet;

/// The names `pub mod prelude { … }` of the facade re-exports: the last segment of every
/// `pub use path::Name;` and every name of `pub use path::{A, B};`.
fn prelude_names(lib: &str) -> BTreeSet<String> {
    let start = lib
        .find("pub mod prelude {")
        .expect("src/lib.rs declares `pub mod prelude`");
    let body = &lib[start + "pub mod prelude {".len()..];
    let body = &body[..body.find("\n}").expect("the prelude module closes")];
    body.split(';')
        .filter_map(|statement| statement.trim().strip_prefix("pub use "))
        .flat_map(|path| match path.find('{') {
            Some(open) => path[open + 1..path.rfind('}').expect("a closed brace")]
                .split(',')
                .map(str::to_owned)
                .collect::<Vec<_>>(),
            None => vec![path.rsplit("::").next().expect("a path").to_owned()],
        })
        .map(|name| name.trim().to_owned())
        .filter(|name| !name.is_empty())
        .collect()
}

/// The strings of `const LAGRANGE_PRELUDE: &[&str] = &[ … ];` in the macro's source.
fn macro_list(ast: &str) -> BTreeSet<String> {
    let start = ast
        .find("const LAGRANGE_PRELUDE")
        .expect("the macro declares LAGRANGE_PRELUDE");
    let list = &ast[start..];
    let list = &list[list.find("&[\n").expect("the list opens")..list.find("];").unwrap()];
    list.split('"')
        .skip(1)
        .step_by(2)
        .map(str::to_owned)
        .collect()
}

#[test]
fn the_macro_knows_the_prelude_by_the_same_list() {
    let prelude = prelude_names(include_str!("../src/lib.rs"));
    let known = macro_list(include_str!("../lagrange-macros/src/ast.rs"));
    // Both lists are read, not empty: a parse that found nothing would agree trivially.
    assert!(
        prelude.contains("Mechanism") && prelude.contains("vec3"),
        "{prelude:?}"
    );
    assert_eq!(
        prelude,
        known,
        "only in the prelude: {:?}; only in the macro's list: {:?}",
        prelude.difference(&known).collect::<Vec<_>>(),
        known.difference(&prelude).collect::<Vec<_>>()
    );
}
