//! `#[urdf("path")]`: a robot's URDF file read at compile time into the declaration a user would
//! write, expanded by `#[mechanism]`.
//!
//! `#[urdf("path", floating)]`: the same with a free-flying root link (a floating base).
//!
//! read the file (path relative to the calling crate's `CARGO_MANIFEST_DIR`) → parse (`parse`,
//! roxmltree) → check the tree and merge fixed joints (`tree`), name the coordinates and bodies
//! (`names`) → write the declaration (`emit`) → `#[mechanism]` (`crate::expand`). A refusal is
//! one compile error at the attribute's path.

mod emit;
mod frames;
mod names;
mod parse;
#[cfg(test)]
mod tests;
mod tree;

use names::{distinct, sanitise, Named};
use proc_macro2::{Span, TokenStream};
use quote::quote;
use std::path::PathBuf;

pub(crate) fn expand(attr: TokenStream, item: TokenStream) -> TokenStream {
    let Arguments { path, floating } = match syn::parse2(attr) {
        Ok(a) => a,
        Err(e) => return e.to_compile_error(),
    };
    let module: syn::ItemMod = match syn::parse2(item) {
        Ok(m) => m,
        Err(_) => return error(
            Span::call_site(),
            "#[urdf] goes on a module: `pub mod arm {}`, to which the file's declaration is added",
        ),
    };
    match declaration(&path, floating, &module) {
        Ok(tokens) => crate::expand::expand(TokenStream::new(), tokens),
        Err(message) => error(path.span(), &message),
    }
}

/// `#[urdf("robots/arm.urdf")]`, or `#[urdf("robots/dog.urdf", floating)]` for a robot whose
/// root link flies free.
struct Arguments {
    path: syn::LitStr,
    floating: bool,
}

impl syn::parse::Parse for Arguments {
    fn parse(input: syn::parse::ParseStream) -> syn::Result<Self> {
        const USAGE: &str = "`#[urdf]` takes the file's path and, for a free-flying root link, \
                             `floating`: `#[urdf(\"robots/arm.urdf\")]`, \
                             `#[urdf(\"robots/dog.urdf\", floating)]`";
        let path: syn::LitStr = input
            .parse()
            .map_err(|e| syn::Error::new(e.span(), USAGE))?;
        if input.is_empty() {
            return Ok(Arguments {
                path,
                floating: false,
            });
        }
        input.parse::<syn::Token![,]>()?;
        let word: syn::Ident = input
            .parse()
            .map_err(|e| syn::Error::new(e.span(), USAGE))?;
        if word != "floating" || !input.is_empty() {
            return Err(syn::Error::new(word.span(), USAGE));
        }
        Ok(Arguments {
            path,
            floating: true,
        })
    }
}

/// The module with the file's declaration before the user's items, or why not.
fn declaration(
    path: &syn::LitStr,
    floating: bool,
    module: &syn::ItemMod,
) -> Result<TokenStream, String> {
    let written = path.value();
    let dir = std::env::var_os("CARGO_MANIFEST_DIR")
        .map(PathBuf::from)
        .unwrap_or_default();
    let resolved = dir.join(&written);
    let text = std::fs::read_to_string(&resolved)
        .map_err(|e| format!("cannot read the URDF file `{}`: {e}", resolved.display()))?;
    let robot = parse::parse(&text).map_err(|e| match e.position {
        Some((line, column)) => format!("{written}:{line}:{column}: {}", e.message),
        None => format!("{written}: {}", e.message),
    })?;
    let (bodies, base) = tree::bodies(&robot, floating)?;
    let ty = upper_camel(&module.ident.to_string());
    let root_link = &robot.links[tree::root_link(&robot)?].name;
    let root = base.as_ref().map(|_| root_link.as_str());
    let all = identifiers(&robot, &bodies, root, &ty)?;
    let n = bodies.len();
    let decl = emit::Declaration {
        robot: &robot,
        bodies: &bodies,
        coords: all[..n].iter().map(|c| emit::ident(&c.ident)).collect(),
        body_idents: all[n..2 * n]
            .iter()
            .map(|c| emit::ident(&c.ident))
            .collect(),
        ty: emit::ident(&ty),
        base: base.map(|mass| emit::Base {
            mass,
            ident: emit::ident(&all[all.len() - 1].ident),
            link: root.unwrap_or_default().to_string(),
        }),
    };
    let items = decl.items();
    let source = resolved.display().to_string();
    let user = module
        .content
        .as_ref()
        .map(|(_, items)| items.as_slice())
        .unwrap_or_default();
    let syn::ItemMod {
        attrs, vis, ident, ..
    } = module;
    Ok(quote! {
        #(#attrs)*
        #vis mod #ident {
            // Rebuilt when the file changes.
            const _: &[u8] = include_bytes!(#source);
            #items
            #(#user)*
        }
    })
}

/// The identifiers of the coordinates (one per body, in order), then of the bodies, then of the
/// joint forces' parameters and functions; refused when two coincide or one is the
/// declaration's own.
fn identifiers(
    robot: &parse::Robot,
    bodies: &[tree::Body],
    root: Option<&str>,
    ty: &str,
) -> Result<Vec<Named>, String> {
    let coords: Vec<Named> = bodies
        .iter()
        .map(|b| {
            let name = &robot.joints[b.joint].name;
            Named {
                ident: sanitise(name, "joint"),
                element: format!("joint `{name}`"),
            }
        })
        .collect();
    let links: Vec<Named> = bodies
        .iter()
        .map(|b| Named {
            ident: sanitise(&b.link, "link"),
            element: format!("link `{}`", b.link),
        })
        .collect();
    let mut generated: Vec<Named> = Vec::new();
    for (b, q) in bodies.iter().zip(&coords) {
        let joint = &robot.joints[b.joint];
        let used = [(joint.damping, "damping"), (joint.friction, "friction")];
        for (_, what) in used.iter().filter(|(c, _)| *c != 0.0) {
            for suffix in ["", "_force"] {
                generated.push(Named {
                    ident: format!("{}_{what}{suffix}", q.ident),
                    element: format!("the {what} of joint `{}`", joint.name),
                });
            }
        }
    }
    let taken = [
        ("t", "time"),
        ("g", "gravity's parameter"),
        ("gravity", "gravity"),
        ("frame", "a local of the declaration"),
        ("Coords", "the coordinates' struct"),
        (ty, "the parameter struct"),
    ];
    // A floating base: its coordinates, then its body (last).
    for (ident, element) in [
        (emit::BASE_POSITION, "the floating base's position"),
        (emit::BASE_ROTATION, "the floating base's rotation"),
    ] {
        if root.is_some() {
            generated.push(Named {
                ident: ident.to_string(),
                element: element.to_string(),
            });
        }
    }
    if let Some(link) = root {
        generated.push(Named {
            ident: sanitise(link, "link"),
            element: format!("link `{link}`"),
        });
    }
    let all: Vec<Named> = coords.into_iter().chain(links).chain(generated).collect();
    distinct(&all, &taken)?;
    Ok(all)
}

/// `arm7` → `Arm7`, `two_link_arm` → `TwoLinkArm`.
fn upper_camel(s: &str) -> String {
    s.trim_start_matches("r#")
        .split('_')
        .filter(|p| !p.is_empty())
        .map(|p| {
            let mut c = p.chars();
            c.next()
                .map(|f| f.to_ascii_uppercase().to_string() + c.as_str())
                .unwrap_or_default()
        })
        .collect()
}

fn error(span: Span, message: &str) -> TokenStream {
    syn::Error::new(span, message).to_compile_error()
}
