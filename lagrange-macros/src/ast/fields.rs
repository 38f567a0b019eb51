//! The fields of the coordinates, parameters and inputs structs: each `f64` or an array of
//! `f64`, without `#[cfg]`, and `#[angular_velocity]` read off a coordinate.

use super::{ungroup_type, Field};
use crate::ctxt::Ctxt;
use syn::{Attribute, ItemStruct, Type};

/// Which struct's fields are read.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(super) enum Fields {
    Coordinates,
    Parameters,
    Inputs,
}

/// The named fields of the coordinates, parameters or inputs struct, each checked to be `f64`.
pub(super) fn struct_fields(cx: &Ctxt, s: &ItemStruct, what: Fields) -> Vec<Field> {
    match &s.fields {
        syn::Fields::Named(named) => named
            .named
            .iter()
            .map(|f| {
                reject_cfg(
                    cx,
                    &f.attrs,
                    match what {
                        Fields::Coordinates => "a coordinate",
                        Fields::Parameters => "a parameter",
                        Fields::Inputs => "an input",
                    },
                );
                let array = match ungroup_type(&f.ty) {
                    // `pub theta: [f64; LINKS]`: an array of coordinates, or of parameters
                    // (`pub m: [f64; LINKS]`, a family's masses read as `m[i]`).
                    Type::Array(a) if is_f64(&a.elem) => Some((a.len.clone(), 0)),
                    // `pub l: f32`: everything is f64 (and lifted to dual numbers).
                    ty if !is_f64(ty) => {
                        let message = match what {
                            Fields::Coordinates => "coordinates are `f64` or arrays `[f64; LEN]`",
                            Fields::Parameters => "parameters are `f64` or arrays `[f64; LEN]`",
                            Fields::Inputs => "inputs are `f64` or arrays `[f64; LEN]`",
                        };
                        cx.error_spanned_by(ty, message);
                        None
                    }
                    _ => None,
                };
                let (attrs, angular_velocity) = angular_velocity_marker(cx, &f.attrs, what);
                Field {
                    attrs,
                    ident: f.ident.clone().unwrap(),
                    angular_velocity,
                    array,
                }
            })
            .collect(),
        syn::Fields::Unit => Vec::new(),
        // `struct Coords(f64, f64)`: coordinates and parameters have names.
        syn::Fields::Unnamed(u) => {
            cx.error_spanned_by(
                u,
                format!(
                    "`{}` needs named fields: `{} {{ pub x: f64 }}`",
                    s.ident, s.ident
                ),
            );
            Vec::new()
        }
    }
}

/// The struct as the module keeps it: `#[angular_velocity]`, which [`struct_fields`] read (and
/// reported where it does not belong), taken off its fields.
pub(super) fn strip_angular_velocity(s: &mut ItemStruct) {
    for field in s.fields.iter_mut() {
        field
            .attrs
            .retain(|a| !a.path().is_ident("angular_velocity"));
    }
}

/// A field's attributes without `#[angular_velocity]`, and that marker: on a coordinate, once and
/// without arguments; anywhere else an error.
fn angular_velocity_marker(
    cx: &Ctxt,
    attrs: &[Attribute],
    what: Fields,
) -> (Vec<Attribute>, Option<Attribute>) {
    let (markers, rest): (Vec<Attribute>, Vec<Attribute>) = attrs
        .iter()
        .cloned()
        .partition(|a| a.path().is_ident("angular_velocity"));
    let mut markers = markers.into_iter();
    let marker = markers.next();
    for extra in markers {
        cx.error_spanned_by(&extra, "`#[angular_velocity]` is written once");
    }
    match (&marker, what) {
        (Some(m), Fields::Coordinates) if !matches!(m.meta, syn::Meta::Path(_)) => {
            cx.error_spanned_by(m, "`#[angular_velocity]` takes no arguments");
        }
        (Some(m), Fields::Parameters | Fields::Inputs) => {
            cx.error_spanned_by(
                m,
                "`#[angular_velocity]` marks generalized coordinates (the three of a free or \
                 ball joint's rotation chart, in `Coords`)",
            );
            return (rest, None);
        }
        _ => {}
    }
    (rest, marker)
}

/// `#[cfg(..)]` and `#[cfg_attr(..)]` where the macro cannot honour them. `#[mechanism]` runs before
/// `cfg` is evaluated inside the module, so it would lay out a body, row or coordinate that rustc
/// then removes (or keep one the user meant to remove); it is reported instead.
pub(super) fn reject_cfg(cx: &Ctxt, attrs: &[Attribute], what: &str) {
    for attr in attrs {
        if attr.path().is_ident("cfg") || attr.path().is_ident("cfg_attr") {
            cx.error_spanned_by(
                attr,
                format!(
                    "`#[{}]` on {what} is not supported: `#[mechanism]` lays out the mechanism before `cfg` is evaluated; declare each configuration as its own mechanism, or put `#[cfg]` on the whole module",
                    attr.path().get_ident().map(|i| i.to_string()).unwrap_or_default()
                ),
            );
        }
    }
}

fn is_f64(ty: &Type) -> bool {
    matches!(ungroup_type(ty), Type::Path(p) if p.qself.is_none() && p.path.is_ident("f64"))
}
