//! The declaration as a typed model: the module's structs and marked functions, with their spans.

use crate::attr::{self, Args, Kind};
use crate::ctxt::Ctxt;
use proc_macro2::Span;
use syn::{
    Attribute, Block, Ident, Item, ItemMod, ItemStruct, ReturnType, Signature, Type, Visibility,
};

/// What `lagrange::prelude` exports.
const LAGRANGE_PRELUDE: &[&str] = &[
    "planar",
    "rot3",
    "rot_axis",
    "rot_mrp",
    "rot_vector",
    "rot_x",
    "rot_y",
    "rot_z",
    "rpy",
    "spatial",
    "vec2",
    "vec3",
    "Planar",
    "Rot3",
    "Spatial",
    "SpatialVelocity",
    "Vec2",
    "Vec3",
    "Dop853",
    "Dopri5",
    "GaussLegendre2",
    "ImplicitMidpoint",
    "Integrator",
    "Radau5",
    "Rk4",
    "Stepper",
    "StormerVerlet",
    "Variational",
    "Coordinates",
    "Error",
    "Mechanism",
    "State",
    "Validated",
    "mechanism",
    "urdf",
];

mod fields;
use fields::{reject_cfg, strip_angular_velocity, struct_fields, Fields};

/// One `f64` field of the coordinates or parameters struct, or an array `[f64; LEN]` of
/// coordinates or parameters.
#[derive(Clone)]
pub struct Field {
    pub attrs: Vec<Attribute>,
    pub ident: Ident,
    /// `#[angular_velocity]` on a coordinate (removed from `attrs`): its velocities are a free or
    /// ball joint's angular velocity, not its rates (see `check::velocities`).
    pub angular_velocity: Option<Attribute>,
    /// For an array coordinate or parameter: its length as written (a literal or a module `const`) and its
    /// value, once resolved.
    pub array: Option<(syn::Expr, usize)>,
}

impl Field {
    /// Generalized coordinates (or parameter values) this field holds.
    pub fn slots(&self) -> usize {
        self.array.as_ref().map_or(1, |(_, n)| *n)
    }

    /// The field's type in `f64` code: `f64`, or `[f64; LEN]` for an array.
    pub fn f64_type(&self) -> proc_macro2::TokenStream {
        match &self.array {
            Some((_, n)) => {
                let n = proc_macro2::Literal::usize_unsuffixed(*n);
                quote::quote!([f64; #n])
            }
            None => quote::quote!(f64),
        }
    }

    /// `let l: f64 = self.l;` (`let m: [f64; 3] = self.m;` for an array): a parameter bound in
    /// `f64` code.
    pub fn bind_f64(&self) -> proc_macro2::TokenStream {
        let (ident, ty) = (&self.ident, self.f64_type());
        quote::quote!(let #ident: #ty = self.#ident;)
    }

    /// `let l = <D>::from(self.l);` (`let m: [D; 3] = self.m.map(<D>::from);` for an array): a
    /// parameter lifted to the scalar `d`.
    pub fn bind_lifted(&self, d: &proc_macro2::TokenStream) -> proc_macro2::TokenStream {
        let ident = &self.ident;
        match &self.array {
            Some((_, n)) => {
                let n = proc_macro2::Literal::usize_unsuffixed(*n);
                quote::quote!(let #ident: [#d; #n] = self.#ident.map(<#d>::from);)
            }
            None => quote::quote!(let #ident = <#d>::from(self.#ident);),
        }
    }
}

/// Total generalized coordinates of a list of fields.
pub fn slot_count(fields: &[Field]) -> usize {
    fields.iter().map(Field::slots).sum()
}

/// The flat slot among `fields` that `expr` names: a scalar field `u`, or an element `tau[k]` of an
/// array field with a literal index in range (parentheses and invisible groups around either).
pub fn flat_slot(fields: &[Field], expr: &syn::Expr) -> Option<usize> {
    use crate::structure::strip;
    use syn::{Expr, ExprLit, Lit};
    let (name, element) = match strip(expr) {
        Expr::Path(p) => (p.path.get_ident()?, None),
        Expr::Index(i) => match (strip(&i.expr), strip(&i.index)) {
            (
                Expr::Path(p),
                Expr::Lit(ExprLit {
                    lit: Lit::Int(k), ..
                }),
            ) => (p.path.get_ident()?, Some(k.base10_parse::<usize>().ok()?)),
            _ => return None,
        },
        _ => return None,
    };
    let mut first = 0;
    for field in fields {
        if field.ident == *name {
            return match (&field.array, element) {
                (None, None) => Some(first),
                (Some((_, len)), Some(k)) if k < *len => Some(first + k),
                _ => None,
            };
        }
        first += field.slots();
    }
    None
}

/// A marked function: a body, point, potential, gravity or force.
#[derive(Clone)]
pub struct Decl {
    pub args: Args,
    /// Attributes other than the kind (doc comments).
    pub attrs: Vec<Attribute>,
    pub sig: Signature,
    pub block: Block,
}

impl Decl {
    pub fn ident(&self) -> &Ident {
        &self.sig.ident
    }
    pub fn kind(&self) -> Kind {
        self.args.kind
    }
    /// The declared return type, if any.
    pub fn output(&self) -> Option<&Type> {
        match &self.sig.output {
            ReturnType::Type(_, ty) => Some(ty),
            ReturnType::Default => None,
        }
    }
}

/// The whole declaration.
pub struct Mechanism {
    pub attrs: Vec<Attribute>,
    pub vis: Visibility,
    pub ident: Ident,
    /// `struct Coords`, as written, and its fields.
    pub coords: Option<(ItemStruct, Vec<Field>)>,
    /// The parameter struct, as written, and its fields.
    pub params: Option<(ItemStruct, Vec<Field>)>,
    /// The `#[inputs]` struct, as written less that attribute, and its fields: what a program
    /// driving the mechanism sets between steps, read by the forces.
    pub inputs: Option<(ItemStruct, Vec<Field>)>,
    pub decls: Vec<Decl>,
    /// Everything else (`use`, helper functions, constants), re-emitted untouched.
    pub other_items: Vec<Item>,
    /// Names of the module's own items and imports: in scope in every function.
    pub item_names: Vec<Ident>,
    /// A `use path::*;` brings in names we cannot see: unknown names are then left to rustc.
    pub has_glob_import: bool,
}

impl Mechanism {
    /// Parses the module, reporting what is not a declaration.
    pub fn from_module(cx: &Ctxt, module: ItemMod) -> Option<Mechanism> {
        let Some((_, items)) = module.content else {
            // `#[mechanism] mod m;`: the declaration must be inline.
            cx.error_spanned_by(
                &module.ident,
                "#[mechanism] goes on an inline module: `mod name { ... }`",
            );
            return None;
        };
        let mut mechanism = Mechanism {
            attrs: module.attrs,
            vis: module.vis,
            ident: module.ident,
            coords: None,
            params: None,
            inputs: None,
            decls: Vec::new(),
            other_items: Vec::new(),
            item_names: Vec::new(),
            has_glob_import: false,
        };
        for item in items {
            mechanism.add_item(cx, item);
        }
        mechanism.resolve_array_lengths(cx);
        Some(mechanism)
    }

    /// The value of a length written as an integer literal or the name of a module `const` with
    /// an integer literal value (`const LINKS: usize = 8;`), or integer arithmetic of those
    /// (`2 * LINKS + 1`; `None` on overflow or division by zero).
    pub fn constant_length(&self, expr: &syn::Expr) -> Option<usize> {
        self.length_within(expr, 0)
    }

    /// [`Mechanism::constant_length`], following at most 16 `const`s deep (`const A: usize = B;
    /// const B: usize = A;` has no value).
    fn length_within(&self, expr: &syn::Expr, depth: usize) -> Option<usize> {
        if depth > 16 {
            return None;
        }
        let length = |e: &syn::Expr| self.length_within(e, depth + 1);
        match expr {
            syn::Expr::Lit(syn::ExprLit {
                lit: syn::Lit::Int(i),
                ..
            }) => i.base10_parse().ok(),
            syn::Expr::Path(p) => {
                let name = p.path.get_ident()?;
                self.other_items.iter().find_map(|item| match item {
                    Item::Const(c) if c.ident == *name => length(&c.expr),
                    _ => None,
                })
            }
            syn::Expr::Paren(p) => length(&p.expr),
            syn::Expr::Group(g) => length(&g.expr),
            syn::Expr::Binary(b) => {
                let (l, r) = (length(&b.left)?, length(&b.right)?);
                match b.op {
                    syn::BinOp::Add(_) => l.checked_add(r),
                    syn::BinOp::Sub(_) => l.checked_sub(r),
                    syn::BinOp::Mul(_) => l.checked_mul(r),
                    syn::BinOp::Div(_) => l.checked_div(r),
                    _ => None,
                }
            }
            _ => None,
        }
    }

    fn resolve_array_lengths(&mut self, cx: &Ctxt) {
        if let Some((coords_struct, mut fields)) = self.coords.take() {
            self.resolve_lengths(cx, &mut fields, "coordinates");
            self.coords = Some((coords_struct, fields));
        }
        if let Some((params_struct, mut fields)) = self.params.take() {
            self.resolve_lengths(cx, &mut fields, "parameters");
            self.params = Some((params_struct, fields));
        }
        if let Some((inputs_struct, mut fields)) = self.inputs.take() {
            self.resolve_lengths(cx, &mut fields, "inputs");
            self.inputs = Some((inputs_struct, fields));
        }
    }

    /// Each array field's length, from its written expression; `what` names the struct's fields.
    fn resolve_lengths(&self, cx: &Ctxt, fields: &mut [Field], what: &str) {
        for field in fields {
            if let Some((expr, len)) = &mut field.array {
                match self.constant_length(expr) {
                    // `theta: [f64; 0]`: nothing moves (no parameter either).
                    Some(0) => cx.error_spanned_by(
                        &*expr,
                        format!("an array of {what} needs at least one element"),
                    ),
                    Some(n) => *len = n,
                    // `theta: [f64; links()]`: the macro needs the length.
                    None => cx.error_spanned_by(
                        &*expr,
                        format!("the length of an array of {what} is an integer literal or a `const NAME: usize = <integer>;` of this module"),
                    ),
                }
            }
        }
    }

    fn add_item(&mut self, cx: &Ctxt, item: Item) {
        match item {
            Item::Struct(s) => self.add_struct(cx, s),
            Item::Fn(f) => match attr::split_kind(cx, &f.attrs) {
                (Some((kind, kind_attr)), attrs) => {
                    reject_cfg(cx, &attrs, "a declaration function");
                    let args = attr::parse_args(cx, kind, &kind_attr);
                    self.decls.push(Decl {
                        args,
                        attrs,
                        sig: f.sig,
                        block: *f.block,
                    });
                }
                (None, _) => {
                    self.item_names.push(f.sig.ident.clone());
                    self.other_items.push(Item::Fn(f));
                }
            },
            other => {
                self.record_names(&other);
                self.other_items.push(other);
            }
        }
    }

    fn add_struct(&mut self, cx: &Ctxt, mut s: ItemStruct) {
        // `pub struct Coordinates { .. }`: the coordinates struct has one name.
        let lower = s.ident.to_string().to_lowercase();
        if s.ident != "Coords"
            && self.coords.is_none()
            && matches!(s.fields, syn::Fields::Named(_))
            && (lower.starts_with("coord") || lower.starts_with("generalizedcoord"))
        {
            cx.error_spanned_by(
                &s.ident,
                format!("the generalized coordinates are `pub struct Coords {{ .. }}`: rename `{}` to `Coords`", s.ident),
            );
            s.ident = Ident::new("Coords", s.ident.span());
        }
        // `pub struct Pendulum<T> { pub m: T }`: the macro chooses the scalar.
        if matches!(s.fields, syn::Fields::Named(_))
            && (!s.generics.params.is_empty() || s.generics.where_clause.is_some())
        {
            cx.error_spanned_by(
                &s.generics,
                format!("`{}` is not generic: its fields are `f64`, and the macro makes the generated code generic over the scalar", s.ident),
            );
            // Its fields typed by a parameter are read as `f64`, not reported again.
            let params: Vec<Ident> = s.generics.type_params().map(|p| p.ident.clone()).collect();
            for field in s.fields.iter_mut() {
                if matches!(&field.ty, Type::Path(p) if p.path.get_ident().is_some_and(|i| params.contains(i)))
                {
                    field.ty = syn::parse_quote!(f64);
                }
            }
            s.generics = syn::Generics::default();
        }
        // Unit and tuple structs (markers, newtypes) are ordinary items; the parameter struct has
        // named fields.
        if s.ident != "Coords" && !matches!(s.fields, syn::Fields::Named(_)) {
            self.item_names.push(s.ident.clone());
            self.other_items.push(Item::Struct(s));
            return;
        }
        if let Some(at) = s.attrs.iter().position(|a| a.path().is_ident("inputs")) {
            let marker = s.attrs.remove(at);
            return self.add_inputs(cx, s, marker);
        }
        let what = match s.ident == "Coords" {
            true => Fields::Coordinates,
            false => Fields::Parameters,
        };
        let fields = struct_fields(cx, &s, what);
        let mut s = s;
        strip_angular_velocity(&mut s);
        reject_cfg(cx, &s.attrs, &format!("`{}`", s.ident));
        if s.ident == "Coords" {
            // Two `struct Coords`: rustc would say so too, but only once here.
            if self.coords.is_some() {
                cx.error_spanned_by(&s.ident, "`Coords` is declared twice");
            } else {
                self.coords = Some((s, fields));
            }
        } else if let Some((first, _)) = &self.params {
            // `struct Pendulum {..} struct Helper {..}`: the parameter struct is the only other struct
            // with named fields.
            cx.error_spanned_by(
                &s.ident,
                format!(
                    "a mechanism has one parameter struct, `{}`; move `{}` out of the module",
                    first.ident, s.ident
                ),
            );
        } else {
            self.params = Some((s, fields));
        }
    }

    /// `#[inputs] pub struct Torques { pub tau: f64 }`: the one struct of inputs, its fields
    /// `f64` or arrays like the parameters'.
    fn add_inputs(&mut self, cx: &Ctxt, s: ItemStruct, marker: Attribute) {
        // `#[inputs(tau)]`: the attribute marks the struct, its fields are the inputs.
        if !matches!(marker.meta, syn::Meta::Path(_)) {
            cx.error_spanned_by(
                &marker,
                "`#[inputs]` takes no arguments: the struct's fields are the inputs",
            );
        }
        reject_cfg(cx, &s.attrs, &format!("`{}`", s.ident));
        if s.ident == "Coords" {
            cx.error_spanned_by(&marker, "`Coords` are the coordinates; inputs are a struct of their own (`#[inputs] pub struct Torques { .. }`)");
            return;
        }
        let fields = struct_fields(cx, &s, Fields::Inputs);
        let mut s = s;
        strip_angular_velocity(&mut s);
        if let Some((first, known)) = &mut self.inputs {
            cx.error_spanned_by(
                &s.ident,
                format!("a mechanism has one `#[inputs]` struct, `{}`", first.ident),
            );
            // Its fields are still names the functions may read: one message, not one per use.
            known.extend(fields);
            return;
        }
        self.inputs = Some((s, fields));
    }

    fn record_names(&mut self, item: &Item) {
        let ident = match item {
            Item::Const(i) => Some(&i.ident),
            Item::Static(i) => Some(&i.ident),
            Item::Enum(i) => Some(&i.ident),
            Item::Mod(i) => Some(&i.ident),
            Item::Type(i) => Some(&i.ident),
            Item::Union(i) => Some(&i.ident),
            Item::Trait(i) => Some(&i.ident),
            Item::Macro(i) => i.ident.as_ref(),
            Item::Use(u) => {
                self.record_use(&u.tree);
                None
            }
            _ => None,
        };
        self.item_names.extend(ident.cloned());
    }

    fn record_use(&mut self, tree: &syn::UseTree) {
        self.record_use_under(&mut Vec::new(), tree);
    }

    fn record_use_under(&mut self, prefix: &mut Vec<String>, tree: &syn::UseTree) {
        match tree {
            syn::UseTree::Path(p) => {
                prefix.push(p.ident.to_string());
                self.record_use_under(prefix, &p.tree);
                prefix.pop();
            }
            syn::UseTree::Name(n) => self.item_names.push(n.ident.clone()),
            syn::UseTree::Rename(r) => self.item_names.push(r.rename.clone()),
            // `use lagrange::prelude::*;` brings in names we know.
            syn::UseTree::Glob(g)
                if prefix
                    .iter()
                    .map(String::as_str)
                    .eq(["lagrange", "prelude"]) =>
            {
                let names = LAGRANGE_PRELUDE
                    .iter()
                    .map(|n| Ident::new(n, g.star_token.span));
                self.item_names.extend(names);
            }
            syn::UseTree::Glob(_) => self.has_glob_import = true,
            syn::UseTree::Group(g) => g
                .items
                .iter()
                .for_each(|t| self.record_use_under(prefix, t)),
        }
    }

    /// The module name's span, for errors about something missing.
    pub fn span(&self) -> Span {
        self.ident.span()
    }
}

/// `expr` without the invisible groups around it. A `macro_rules!` fragment (`$n:expr`,
/// `$n:literal`) arrives wrapped in a `Delimiter::None` group, which syn keeps as `Expr::Group`:
/// wherever the macro reads an expression's shape it looks through them.
pub fn ungroup(mut expr: &syn::Expr) -> &syn::Expr {
    while let syn::Expr::Group(g) = expr {
        expr = &g.expr;
    }
    expr
}

/// `ty` without the invisible groups around it (a `$t:ty` fragment).
pub fn ungroup_type(mut ty: &Type) -> &Type {
    while let Type::Group(g) = ty {
        ty = &g.elem;
    }
    ty
}
