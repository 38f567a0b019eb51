//! The coordinate and parameter structs, and the names they and the functions declare.

use crate::ast::{Field, Mechanism};
use crate::ctxt::Ctxt;
use std::collections::HashMap;

/// Duplicate names among coordinates, parameters, bodies and functions, and the reserved `t`.
pub(super) fn check_duplicates(
    cx: &Ctxt,
    mechanism: &Mechanism,
    coords: &[Field],
    params: &[Field],
) {
    let mut seen: HashMap<String, &'static str> = HashMap::new();
    let names = coords
        .iter()
        .map(|f| (&f.ident, "a coordinate"))
        .chain(params.iter().map(|f| (&f.ident, "a parameter")))
        .chain(mechanism.decls.iter().map(|d| (d.ident(), "a function")));
    for (ident, what) in names {
        // `pub struct Coords { pub t: f64 }`: `t` is time.
        if ident == "t" {
            cx.error_spanned_by(ident, "`t` is time; choose another name");
        }
        // `pub struct Coords { pub x: f64, pub x: f64 }`, or a parameter named like a coordinate.
        if let Some(first) = seen.insert(ident.to_string(), what) {
            cx.error_spanned_by(ident, format!("`{ident}` is already declared as {first}"));
        }
    }
}
