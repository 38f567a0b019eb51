//! The coordinate and parameter structs, and the names they and the functions declare.

use crate::ast::{Field, Mechanism};
use crate::ctxt::Ctxt;
use std::collections::HashMap;
use syn::{Ident, ItemStruct};

/// The parameter struct's name, the coordinates and the parameters, when both structs are
/// declared; each missing or malformed struct is reported.
pub(super) fn check_structs<'a>(
    cx: &Ctxt,
    mechanism: &'a Mechanism,
) -> Option<(&'a Ident, &'a [Field], &'a [Field])> {
    if !check_declares_a_struct(cx, mechanism) {
        return None;
    }
    check_declares_coords(cx, mechanism);
    check_declares_params(cx, mechanism);
    let (Some(coords), Some((params_struct, params))) = (&mechanism.coords, &mechanism.params)
    else {
        return None;
    };
    check_coords_not_empty(cx, coords);
    Some((&params_struct.ident, &coords.1, params))
}

/// A mechanism is its coordinates and its parameters: a module with neither (`#[mechanism] mod m
/// {}`) gets one message naming both, rather than one per struct. Whether either is declared.
fn check_declares_a_struct(cx: &Ctxt, mechanism: &Mechanism) -> bool {
    let declared = mechanism.coords.is_some() || mechanism.params.is_some();
    if !declared {
        cx.error_at(
            mechanism.span(),
            "a mechanism declares `pub struct Coords { ... }` (the generalized coordinates) and a parameter struct (`pub struct Name { pub m: f64, ... }`: its name is the mechanism's type)",
        );
    }
    declared
}

/// `struct Coords` holds the generalized coordinates: without it nothing moves.
fn check_declares_coords(cx: &Ctxt, mechanism: &Mechanism) {
    // `#[mechanism] mod m { struct Pendulum {..} ... }` without `struct Coords`.
    if mechanism.coords.is_none() {
        cx.error_at(
            mechanism.span(),
            "missing `pub struct Coords { ... }`: the generalized coordinates, one `f64` field each",
        );
    }
}

/// The parameter struct names the mechanism's type and its parameters, which the functions name
/// directly: it is a struct with named fields.
fn check_declares_params(cx: &Ctxt, mechanism: &Mechanism) {
    // `pub struct Pendulum(f64, f64);`: there is a parameter struct, but its fields have no names.
    let tuple = mechanism.other_items.iter().find_map(|item| match item {
        syn::Item::Struct(s) if matches!(&s.fields, syn::Fields::Unnamed(u) if !u.unnamed.is_empty()) => Some(s),
        _ => None,
    });
    if let (None, Some(s)) = (&mechanism.params, tuple) {
        cx.error_spanned_by(
            &s.fields,
            format!(
                "the parameter struct has named fields: `pub struct {} {{ pub m: f64, ... }}`",
                s.ident
            ),
        );
    // `#[mechanism] mod m { struct Coords {..} ... }` without a parameter struct.
    } else if mechanism.params.is_none() {
        cx.error_at(
            mechanism.span(),
            "missing the parameter struct (`pub struct Name { pub m: f64, ... }`): its name is the mechanism's type",
        );
    }
}

/// A mechanism moves: `struct Coords {}` has no degree of freedom. (`struct Coords(f64);` was
/// reported as such while parsing.)
fn check_coords_not_empty(cx: &Ctxt, (coords_struct, coords): &(ItemStruct, Vec<Field>)) {
    let tuple = matches!(coords_struct.fields, syn::Fields::Unnamed(_));
    if coords.is_empty() && !tuple {
        cx.error_spanned_by(
            &coords_struct.ident,
            "`Coords` needs at least one coordinate",
        );
    }
}

/// Coordinates, parameters and functions share one scope in every function body, so each name is
/// declared once; `t` is time there, so nothing else is named `t`.
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
        .chain(
            mechanism
                .inputs
                .iter()
                .flat_map(|(_, inputs)| inputs.iter().map(|f| (&f.ident, "an input"))),
        )
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
