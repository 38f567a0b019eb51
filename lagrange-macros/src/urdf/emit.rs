//! The declaration a user would write for the bodies of a file, as tokens for `#[mechanism]`:
//! `Coords` (one field per moving joint), the parameter struct (`g`, and a damping and a friction
//! coefficient per joint whose `<dynamics>` gives one) with a `Default` holding the file's values,
//! the inputs (`Efforts`, one per moving joint), one `#[rigid_body]` per body placed by its joint
//! frame, gravity, and the joint forces (each joint's actuator, damping and friction).

use super::frames::{turn_z_to, MassPart, Vec3};
use super::parse::Robot;
use super::tree::{Body, Motion};
use proc_macro2::{Ident, Literal, Span, TokenStream};
use quote::{format_ident, quote};

/// Gravity's default magnitude, Pinocchio's `Model::gravity981` (9.81 m/s², along −z).
const STANDARD_GRAVITY: f64 = 9.81;

/// A floating base's coordinates: the root link's frame origin in the world, and its orientation
/// in modified Rodrigues parameters (`rot_mrp`, a chart the integrators keep regular: of the two
/// charts, the cheaper per evaluation and the more accurate per step, BENCHMARKS.md §18).
pub const BASE_POSITION: &str = "base_position";
pub const BASE_ROTATION: &str = "base_rotation";

/// A free-flying root link: its mass (with what is welded to it) and its body's identifier.
pub struct Base {
    pub mass: MassPart,
    pub ident: Ident,
    pub link: String,
}

pub struct Declaration<'a> {
    pub robot: &'a Robot,
    pub bodies: &'a [Body],
    /// Per body: its coordinate's identifier and its own.
    pub coords: Vec<Ident>,
    pub body_idents: Vec<Ident>,
    /// The parameter struct's name.
    pub ty: Ident,
    /// The floating base, when the root link flies free.
    pub base: Option<Base>,
}

impl Declaration<'_> {
    /// The module's generated items.
    pub fn items(&self) -> TokenStream {
        let coords = &self.coords;
        let ty = &self.ty;
        let mut fields = vec![quote!(pub g: f64)];
        let mut defaults = vec![{
            let g = number(STANDARD_GRAVITY);
            quote!(g: #g)
        }];
        let mut forces = Vec::new();
        let mut efforts = Vec::new();
        for (b, q) in self.bodies.iter().zip(coords) {
            let joint = &self.robot.joints[b.joint];
            let dot = format_ident!("{}_dot", q);
            // Every moving joint is actuated: its effort (torque, or force along a prismatic
            // axis) is an input, acting on its coordinate.
            let effort = format_ident!("{}_effort", q);
            let on = format_ident!("{}_actuator", q);
            efforts.push(effort.clone());
            forces.push(quote! {
                /// The joint's actuator: the effort the program sets (an input).
                #[generalized_force(on = #q)]
                fn #on() -> f64 { #effort }
            });
            if joint.damping != 0.0 {
                let c = format_ident!("{}_damping", q);
                let f = format_ident!("{}_damping_force", q);
                let v = number(joint.damping);
                fields.push(quote!(pub #c: f64));
                defaults.push(quote!(#c: #v));
                forces.push(quote! {
                    /// Viscous joint damping, −c q̇ (`<dynamics damping>`).
                    #[generalized_force(on = #q)]
                    fn #f() -> f64 { -#c * #dot }
                });
            }
            if joint.friction != 0.0 {
                let c = format_ident!("{}_friction", q);
                let f = format_ident!("{}_friction_force", q);
                let v = number(joint.friction);
                fields.push(quote!(pub #c: f64));
                defaults.push(quote!(#c: #v));
                forces.push(quote! {
                    /// Coulomb friction of constant magnitude opposing the joint's motion,
                    /// −f sgn(q̇), zero at rest (`<dynamics friction>`; no sticking):
                    /// sgn(q̇) = q̇ / max(|q̇|, the least normal f64), exactly ±1 for every normal
                    /// q̇, 0 at 0, with zero derivative.
                    #[generalized_force(on = #q)]
                    fn #f() -> f64 {
                        -#c * (#dot / #dot.abs().max(2.2250738585072014e-308))
                    }
                });
            }
        }
        let bodies = self.bodies.iter().enumerate().map(|(k, b)| self.body(k, b));
        let doc = format!(
            "Parameters of the model: `g`, gravity's magnitude along −z, and each joint's \
             `<dynamics>` coefficients. `{ty}::default()` holds the file's values (g = {STANDARD_GRAVITY})."
        );
        let (base_coords, base_body) = self.base_items();
        quote! {
            pub struct Coords { #base_coords #(pub #coords: f64,)* }
            #[doc = #doc]
            pub struct #ty { #(#fields,)* }
            impl ::core::default::Default for #ty {
                fn default() -> Self { Self { #(#defaults,)* } }
            }
            /// One input per moving joint: the effort its actuator applies (a torque about a
            /// revolute or continuous joint's axis, a force along a prismatic joint's).
            #[inputs]
            pub struct Efforts { #(pub #efforts: f64,)* }
            #base_body
            #(#bodies)*
            /// Gravity along −z.
            #[gravity]
            fn gravity() -> Vec3 { vec3(0.0, 0.0, -g) }
            #(#forces)*
        }
    }

    /// A floating base's coordinates (before the joints') and its body; nothing without one.
    fn base_items(&self) -> (TokenStream, Option<TokenStream>) {
        let Some(base) = &self.base else {
            return (quote!(), None);
        };
        let (p, r) = (ident(BASE_POSITION), ident(BASE_ROTATION));
        let doc = " The floating base's orientation: modified Rodrigues parameters n tan(θ/4) of \
                   the rotation by θ about n, kept within |σ| ≤ 1 (θ ≤ π); its velocities are the \
                   base's angular velocity in the base's frame.";
        let coords = quote! {
            /// The floating base's frame origin in the world frame.
            pub #p: [f64; 3],
            #[doc = #doc]
            #[angular_velocity]
            pub #r: [f64; 3],
        };
        (coords, Some(self.base_body(base)))
    }

    /// The floating base: the root link's frame at `base_position`, turned by `base_rotation`
    /// (modified Rodrigues parameters).
    fn base_body(&self, base: &Base) -> TokenStream {
        let (p, r) = (ident(BASE_POSITION), ident(BASE_ROTATION));
        let doc = format!("Link `{}`, the floating base.", base.link);
        let pose = quote! {
            spatial(vec3(#p[0], #p[1], #p[2]), rot_mrp(vec3(#r[0], #r[1], #r[2])))
        };
        rigid_body(&base.ident, &doc, &base.mass, pose)
    }

    fn body(&self, k: usize, b: &Body) -> TokenStream {
        let name = &self.body_idents[k];
        let q = &self.coords[k];
        let joint = &self.robot.joints[b.joint];
        let doc = format!("Link `{}`, moved by joint `{}`.", b.link, joint.name);
        let (offset, fixed) = self.placement(b);
        let parent = match b.parent {
            Some(p) => Some(&self.body_idents[p]),
            None => self.base.as_ref().map(|base| &base.ident),
        };
        let place = |offset: TokenStream, rotation: TokenStream| match parent {
            Some(p) => quote!(#p.joint(#offset, #rotation)),
            None => quote!(spatial(#offset, #rotation)),
        };
        let pose = match b.motion {
            Motion::Revolute(axis) => {
                let turn = revolute(axis, q);
                let rotation = match fixed {
                    Some(f) => quote!(#f * #turn),
                    None => turn,
                };
                place(offset, rotation)
            }
            Motion::Prismatic(axis) => {
                // The joint frame turned so that its z axis is the slide's, the slide along it, and
                // the frame turned back: the link's frame is the joint frame moved along the axis.
                let (slide, turn, back) = match coordinate_axis(axis) {
                    Some((k, sign)) => {
                        let mut c = [quote!(0.0), quote!(0.0), quote!(0.0)];
                        c[k] = if sign > 0.0 { quote!(#q) } else { quote!(-#q) };
                        (quote!(vec3(#(#c),*)), None, None)
                    }
                    None => {
                        // A turn about z × a by the angle between z and a maps z to a.
                        let (u, angle) = turn_z_to(axis);
                        let (u, there, back) = (vector(u), number(angle), number(-angle));
                        (
                            quote!(vec3(0.0, 0.0, #q)),
                            Some(quote!(rot_axis(#u, #there))),
                            Some(quote!(rot_axis(#u, #back))),
                        )
                    }
                };
                let rotation = match (fixed, turn) {
                    (Some(f), Some(t)) => quote!(#f * #t),
                    (Some(f), None) => f,
                    (None, Some(t)) => t,
                    (None, None) => quote!(rot_z(0.0)),
                };
                let frame = place(offset, rotation);
                let back = back.map(|m| quote!(* #m));
                quote! {
                    let frame = #frame;
                    spatial(frame.point(#slide), frame.rotation #back)
                }
            }
        };
        rigid_body(name, &doc, &b.inertia, pose)
    }

    /// The joint frame's offset and its constant rotation (`None`: none) in the parent's frame:
    /// the offset composed through the fixed joints between (the file's `xyz` when there are
    /// none), the rotation as the file writes it, a product of `rpy`.
    fn placement(&self, b: &Body) -> (TokenStream, Option<TokenStream>) {
        let rotation = b.rpys.iter().fold(None, |product, r| {
            let [r, p, y] = r.map(number);
            Some(match product {
                None => quote!(rpy(#r, #p, #y)),
                Some(before) => quote!(#before * rpy(#r, #p, #y)),
            })
        });
        (vector(b.placement.position), rotation)
    }
}

/// `#[rigid_body]` `name` of mass `mass` (its centre and tensor in the body's frame) at `pose`.
fn rigid_body(name: &Ident, doc: &str, mass: &MassPart, pose: TokenStream) -> TokenStream {
    let m = number(mass.mass);
    let com = vector(mass.centre);
    let i = mass.inertia.map(|row| row.map(number));
    let rows = i.iter().map(|r| quote!([#(#r),*]));
    quote! {
        #[doc = #doc]
        #[rigid_body(mass = #m, com = #com, inertia = [#(#rows),*])]
        fn #name() -> Spatial { #pose }
    }
}

/// A rotation by `q` about the unit `axis`: about a coordinate axis when it is one (±), else
/// `rot_axis`.
fn revolute(axis: Vec3, q: &Ident) -> TokenStream {
    match coordinate_axis(axis) {
        Some((k, sign)) => {
            let f = [
                format_ident!("rot_x"),
                format_ident!("rot_y"),
                format_ident!("rot_z"),
            ][k]
                .clone();
            if sign > 0.0 {
                quote!(#f(#q))
            } else {
                quote!(#f(-#q))
            }
        }
        None => {
            let a = vector(axis);
            quote!(rot_axis(#a, #q))
        }
    }
}

/// `Some((k, ±1))` when `axis` is ±e_k exactly.
fn coordinate_axis(axis: Vec3) -> Option<(usize, f64)> {
    let k = (0..3).find(|&k| axis[k] != 0.0)?;
    (0..3)
        .all(|j| j == k || axis[j] == 0.0)
        .then(|| (k, axis[k].signum()))
        .filter(|_| axis[k].abs() == 1.0)
}

fn vector(v: Vec3) -> TokenStream {
    let [x, y, z] = v.map(number);
    quote!(vec3(#x, #y, #z))
}

/// A finite number as a literal, negative ones with a leading `-` (−0 written as 0).
pub fn number(x: f64) -> TokenStream {
    if x < 0.0 {
        let l = Literal::f64_unsuffixed(-x);
        quote!(-#l)
    } else {
        let l = Literal::f64_unsuffixed(x.abs());
        quote!(#l)
    }
}

/// An identifier at the macro call.
pub fn ident(s: &str) -> Ident {
    Ident::new(s, Span::call_site())
}
