//! The attributes that mark a declaration's functions, and their arguments.

use crate::ctxt::Ctxt;
use syn::parse::{Parse, ParseStream};
use syn::punctuated::Punctuated;
use syn::{Attribute, Expr, Ident, Token};

/// What a function of the declaration is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    Particle,
    RigidBody,
    Point,
    Potential,
    Gravity,
    Force,
    Torque,
    GeneralizedForce,
    Constraint,
    VelocityConstraint,
    Unilateral,
    Friction,
}

impl Kind {
    /// The attribute name, as written.
    pub fn name(self) -> &'static str {
        match self {
            Kind::Particle => "particle",
            Kind::RigidBody => "rigid_body",
            Kind::Point => "point",
            Kind::Potential => "potential",
            Kind::Gravity => "gravity",
            Kind::Force => "force",
            Kind::Torque => "torque",
            Kind::GeneralizedForce => "generalized_force",
            Kind::Constraint => "constraint",
            Kind::VelocityConstraint => "velocity_constraint",
            Kind::Unilateral => "unilateral",
            Kind::Friction => "friction",
        }
    }

    fn from_attribute(attr: &Attribute) -> Option<Kind> {
        let ident = attr.path().get_ident()?;
        [
            Kind::Particle,
            Kind::RigidBody,
            Kind::Point,
            Kind::Potential,
            Kind::Gravity,
            Kind::Force,
            Kind::Torque,
            Kind::GeneralizedForce,
            Kind::Constraint,
            Kind::VelocityConstraint,
            Kind::Unilateral,
            Kind::Friction,
        ]
        .into_iter()
        .find(|k| ident == k.name())
    }

    /// The arguments this kind accepts.
    fn allowed_arguments(self) -> &'static [&'static str] {
        match self {
            Kind::Particle => &["mass", "count"],
            Kind::RigidBody => &["mass", "inertia", "com", "count"],
            Kind::Point => &["count"],
            Kind::Force => &["on", "count"],
            Kind::Torque | Kind::GeneralizedForce => &["on"],
            Kind::Friction => &["on", "kinetic", "stiction"],
            Kind::Potential | Kind::Gravity => &[],
            Kind::Constraint | Kind::VelocityConstraint | Kind::Unilateral => &[],
        }
    }

    /// Whether the function declares a constraint row.
    pub fn is_constraint(self) -> bool {
        matches!(
            self,
            Kind::Constraint | Kind::VelocityConstraint | Kind::Unilateral | Kind::Friction
        )
    }

    /// Whether the function's body is a position (a body or a point).
    pub fn is_position(self) -> bool {
        matches!(self, Kind::Particle | Kind::RigidBody | Kind::Point)
    }
}

/// A moment of inertia: one about the centre of mass (planar), three principal moments (spatial),
/// or a full tensor about the centre of mass written as three rows (spatial).
#[derive(Clone)]
pub enum Inertia {
    Moment(Expr),
    Principal(syn::ExprArray),
    /// `[[ixx, ixy, ixz], [ixy, iyy, iyz], [ixz, iyz, izz]]`: an array with an array among its
    /// elements (its shape is checked later).
    Tensor(syn::ExprArray),
}

impl Inertia {
    /// The inertia as the expression written.
    pub fn expr(&self) -> Expr {
        match self {
            Inertia::Moment(e) => e.clone(),
            Inertia::Principal(a) | Inertia::Tensor(a) => Expr::Array(a.clone()),
        }
    }
}

/// The parsed arguments of one kind attribute.
#[derive(Clone)]
pub struct Args {
    pub kind: Kind,
    /// The whole attribute, for errors about something missing.
    pub attr: Attribute,
    pub mass: Option<Expr>,
    pub inertia: Option<Inertia>,
    /// A rigid body's centre of mass in the frame its function returns.
    pub com: Option<Expr>,
    pub on: Option<Ident>,
    /// Coulomb coefficients of a friction row.
    pub kinetic: Option<Expr>,
    pub stiction: Option<Expr>,
    /// A family: the number of members (`count = LINKS`), each a function of its index.
    pub count: Option<Expr>,
    /// The arguments did not parse (already reported): nothing is "missing".
    pub malformed: bool,
}

struct Argument {
    key: Ident,
    value: Expr,
}

impl Parse for Argument {
    fn parse(input: ParseStream) -> syn::Result<Self> {
        let key: Ident = input.parse()?;
        let _: Token![=] = input.parse()?;
        let value: Expr = input.parse()?;
        Ok(Argument { key, value })
    }
}

/// Finds the one kind attribute among `attrs`, reporting a second one. Returns the kind attribute
/// and the others (doc comments, lints) untouched.
pub fn split_kind(cx: &Ctxt, attrs: &[Attribute]) -> (Option<(Kind, Attribute)>, Vec<Attribute>) {
    let mut kind = None;
    let mut rest = Vec::new();
    for attr in attrs {
        match Kind::from_attribute(attr) {
            // `#[particle(mass = m)] #[point] fn tip()`: one function is one thing.
            Some(k) if kind.is_some() => cx.error_spanned_by(
                attr,
                format!("a function is only one thing; remove `#[{}]`", k.name()),
            ),
            Some(k) => kind = Some((k, attr.clone())),
            None => rest.push(attr.clone()),
        }
    }
    (kind, rest)
}

/// Parses the arguments of a kind attribute, reporting unknown and repeated ones.
pub fn parse_args(cx: &Ctxt, kind: Kind, attr: &Attribute) -> Args {
    let mut args = Args {
        kind,
        attr: attr.clone(),
        mass: None,
        inertia: None,
        com: None,
        on: None,
        kinetic: None,
        stiction: None,
        count: None,
        malformed: false,
    };
    let parsed = match &attr.meta {
        syn::Meta::Path(_) => Punctuated::new(),
        syn::Meta::List(list) => {
            match list.parse_args_with(Punctuated::<Argument, Token![,]>::parse_terminated) {
                Ok(parsed) => parsed,
                // `#[particle(mass)]`: a malformed argument list.
                Err(e) => {
                    cx.syn_error(e);
                    args.malformed = true;
                    return args;
                }
            }
        }
        // `#[particle = m]`: arguments go in parentheses.
        syn::Meta::NameValue(nv) => {
            cx.error_spanned_by(nv, format!("write `#[{}(name = value)]`", kind.name()));
            args.malformed = true;
            return args;
        }
    };
    for argument in parsed {
        add_argument(cx, &mut args, argument);
    }
    args
}

fn add_argument(cx: &Ctxt, args: &mut Args, Argument { key, value }: Argument) {
    let allowed = args.kind.allowed_arguments();
    // `#[particle(mas = m)]`: an argument this attribute does not know.
    if !allowed.iter().any(|a| key == a) {
        let expected = match allowed {
            [] => format!("`#[{}]` takes no arguments", args.kind.name()),
            _ => format!(
                "expected {}",
                allowed
                    .iter()
                    .map(|a| format!("`{a}`"))
                    .collect::<Vec<_>>()
                    .join(" or ")
            ),
        };
        cx.error_spanned_by(
            &key,
            format!(
                "unknown argument `{key}` of `#[{}]`: {expected}",
                args.kind.name()
            ),
        );
        return;
    }
    let repeated = match key.to_string().as_str() {
        "mass" => args.mass.replace(value).is_some(),
        "kinetic" => args.kinetic.replace(value).is_some(),
        "stiction" => args.stiction.replace(value).is_some(),
        "count" => args.count.replace(value).is_some(),
        "com" => args.com.replace(value).is_some(),
        "inertia" => {
            let inertia = match crate::ast::ungroup(&value).clone() {
                Expr::Array(array)
                    if array
                        .elems
                        .iter()
                        .any(|e| matches!(crate::ast::ungroup(e), Expr::Array(_))) =>
                {
                    Inertia::Tensor(array)
                }
                Expr::Array(array) => Inertia::Principal(array),
                other => Inertia::Moment(other),
            };
            args.inertia.replace(inertia).is_some()
        }
        _ => match crate::ast::ungroup(&value).clone() {
            Expr::Path(p) if p.path.get_ident().is_some() => args
                .on
                .replace(p.path.get_ident().unwrap().clone())
                .is_some(),
            // `#[force(on = bodies[0])]`: the target is a name.
            other => {
                cx.error_spanned_by(
                    other,
                    "`on =` takes the name of a body, point, coordinate or constraint",
                );
                // Reported: the target is not "missing" as well.
                args.malformed = true;
                false
            }
        },
    };
    // `#[particle(mass = m, mass = 2.0)]`: said twice.
    if repeated {
        cx.error_spanned_by(&key, format!("`{key}` is given twice"));
    }
}
