//! The checked model: bodies laid out in x, forces, constraint rows, and what the functions name.
//! Construction reports only what it cannot lay out without: a body's shape and a family's count.

use super::signatures::{expect_return_type, return_type_name, vector_dim};
use crate::ast::{Decl, Field, Mechanism};
use crate::attr::{Inertia, Kind};
use crate::ctxt::Ctxt;
use std::collections::{BTreeSet, HashMap};
use syn::Ident;

/// Dimension of a vector.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Dim {
    Two,
    Three,
}

/// What a body or point is, geometrically.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Shape {
    Particle(Dim),
    Point(Dim),
    Planar,
    Spatial,
}

impl Shape {
    /// Rows of the Cartesian coordinates x it occupies.
    pub fn rows(self) -> usize {
        match self {
            Shape::Particle(Dim::Two) | Shape::Point(Dim::Two) => 2,
            Shape::Particle(Dim::Three) | Shape::Point(Dim::Three) => 3,
            Shape::Planar => 3,
            Shape::Spatial => 12,
        }
    }
    /// Dimension of its position (centre of mass).
    pub fn dim(self) -> Dim {
        match self {
            Shape::Particle(d) | Shape::Point(d) => d,
            Shape::Planar => Dim::Two,
            Shape::Spatial => Dim::Three,
        }
    }
    pub fn has_mass(self) -> bool {
        !matches!(self, Shape::Point(_))
    }
}

/// A body or point: its declaration, shape, first row in x, and free names.
pub struct Body<'a> {
    pub decl: &'a Decl,
    pub shape: Shape,
    pub row: usize,
    /// A family (`count = N`): the number of members, member k at rows `row + k * shape.rows()`.
    pub count: Option<usize>,
}

impl Body<'_> {
    /// Whether the body's function returns its frame with the centre of mass at a declared `com`
    /// in it.
    pub fn has_com(&self) -> bool {
        self.decl.args.com.is_some()
    }

    /// Whether the body's inertia is a full tensor, whose principal axes differ from its frame's.
    pub fn has_tensor(&self) -> bool {
        matches!(self.decl.args.inertia, Some(Inertia::Tensor(_)))
    }

    /// Whether the pose the body's function returns is not its centre of mass and principal axes
    /// (a `com`, or a full tensor): its rows of x are then the pose's `principal` image under
    /// `lagrange_core::inertia::{SpatialMassFrame, PlanarMassFrame}`, not the pose itself.
    pub fn is_framed(&self) -> bool {
        self.has_com() || self.has_tensor()
    }

    /// Members: 1, or the family's count.
    pub fn members(&self) -> usize {
        self.count.unwrap_or(1)
    }

    /// Whether a family's mass, inertia or `com` names its index (`mass = m[i]`): each member
    /// then has its own, evaluated with the index bound.
    pub fn attributes_by_member(&self) -> bool {
        let (Some(_), Some(index)) = (self.count, family_index(self.decl)) else {
            return false;
        };
        let args = &self.decl.args;
        let exprs = args.mass.iter().cloned();
        let exprs = exprs.chain(args.inertia.as_ref().map(|i| i.expr()));
        let exprs = exprs.chain(args.com.iter().cloned());
        exprs
            .flat_map(|e| crate::names::free_names_of_expr(&e))
            .any(|name| name == *index)
    }

    /// The member whose attributes member `member` has: itself when they are
    /// [by member](Body::attributes_by_member), else `None` (one for the whole body).
    pub fn attribute_member(&self, member: usize) -> Option<usize> {
        self.attributes_by_member().then_some(member)
    }

    /// The attribute sets of the body: `[None]`, or one per member.
    pub fn attribute_members(&self) -> Vec<Option<usize>> {
        match self.attributes_by_member() {
            true => (0..self.members()).map(Some).collect(),
            false => vec![None],
        }
    }
    /// Rows of x the body (all its members) occupies.
    pub fn rows(&self) -> usize {
        self.shape.rows() * self.members()
    }
}

/// Each of `bodies` with each of its attribute sets ([`Body::attribute_members`]): `(body, None)`,
/// or `(body, Some(k))` for every member k of a family whose attributes are by member.
pub fn attribute_sets<'b, 'a: 'b>(
    bodies: impl Iterator<Item = &'b Body<'a>>,
) -> impl Iterator<Item = (&'b Body<'a>, Option<usize>)> {
    bodies.flat_map(|b| b.attribute_members().into_iter().map(move |m| (b, m)))
}

/// A force, torque or generalized force and what it acts on.
pub struct Force<'a> {
    pub decl: &'a Decl,
    /// Index into `bodies` (force, torque) or the coordinate's slot (generalized force).
    pub target: usize,
    pub kind: Kind,
    /// A family of forces, one on each member of a family of bodies.
    pub count: Option<usize>,
}

/// A constraint row, in declaration order among constraints.
pub struct ConstraintRow<'a> {
    pub decl: &'a Decl,
    /// For a friction row, the index of its contact (normal) row among the constraint items.
    pub normal: Option<usize>,
    /// A friction item whose slip velocity is a `Vec2` (the Coulomb cone): two runtime rows.
    pub cone: bool,
}

impl ConstraintRow<'_> {
    /// Runtime rows of the item: 2 for a friction cone, 1 otherwise.
    pub fn width(&self) -> usize {
        if self.cone {
            2
        } else {
            1
        }
    }
}

/// A checked declaration: what the expansion works from.
pub struct Model<'a> {
    pub mechanism: &'a Mechanism,
    pub params_ident: &'a Ident,
    pub coords: &'a [Field],
    pub params: &'a [Field],
    /// The `#[inputs]` struct's name and fields (empty without one): read by the forces.
    pub inputs_ident: Option<&'a Ident>,
    pub inputs: &'a [Field],
    /// Bodies and points in declaration order.
    pub bodies: Vec<Body<'a>>,
    pub potentials: Vec<&'a Decl>,
    /// Fields that depend on coordinates, time or bodies: part of the potential.
    pub gravities: Vec<(&'a Decl, Dim)>,
    /// Fields that name only parameters and constants: constant Cartesian weights m g, no
    /// differentiation needed.
    pub uniform_gravities: Vec<(&'a Decl, Dim)>,
    pub forces: Vec<Force<'a>>,
    /// Constraint rows, in declaration order.
    pub constraints: Vec<ConstraintRow<'a>>,
    /// Free names of each declared function, by function name.
    pub free_names: HashMap<String, Vec<Ident>>,
    /// Whether `t` is named in a position, potential or gravity.
    pub rheonomic: bool,
    /// Rows of x in total.
    pub rows: usize,
    /// Rows that carry mass (massless points come after).
    pub inertial_rows: usize,
    /// The rotations written in a chart of three coordinates (`rot_vector`, `rot_mrp`).
    pub charts: Vec<super::Chart>,
    /// The charts (their three slots) whose velocities are the angular velocity
    /// (`#[angular_velocity]`, see `check::velocities`).
    pub angular_velocities: Vec<[usize; 3]>,
}

impl<'a> Model<'a> {
    /// The names of the scalar parameters: those the optimiser may read as `f64` constants (an
    /// array of parameters is read by element, in the scalar's code).
    pub fn scalar_parameter_names(&self) -> std::collections::BTreeSet<String> {
        let scalars = self.params.iter().filter(|p| p.array.is_none());
        scalars.map(|p| p.ident.to_string()).collect()
    }

    /// The number of inputs, flat (an array counts its elements), when the declaration has
    /// `#[inputs]`.
    pub fn input_count(&self) -> Option<usize> {
        self.inputs_ident
            .map(|_| crate::ast::slot_count(self.inputs))
    }

    /// The model before its functions are checked: bodies laid out in x and the constraint rows;
    /// potentials, gravities, forces, friction contacts and free names are added function by
    /// function.
    pub(super) fn new(
        cx: &Ctxt,
        mechanism: &'a Mechanism,
        params_ident: &'a Ident,
        coords: &'a [Field],
        params: &'a [Field],
    ) -> Self {
        let bodies = lay_out_bodies(cx, mechanism);
        let inputs = mechanism.inputs.as_ref();
        Model {
            mechanism,
            params_ident,
            coords,
            params,
            inputs_ident: inputs.map(|(s, _)| &s.ident),
            inputs: inputs.map_or(&[], |(_, fields)| fields.as_slice()),
            potentials: Vec::new(),
            gravities: Vec::new(),
            uniform_gravities: Vec::new(),
            forces: Vec::new(),
            constraints: constraint_rows(mechanism),
            free_names: HashMap::new(),
            rheonomic: false,
            rows: bodies.iter().map(|b| b.rows()).sum(),
            inertial_rows: bodies
                .iter()
                .filter(|b| b.shape.has_mass())
                .map(|b| b.rows())
                .sum(),
            bodies,
            charts: Vec::new(),
            angular_velocities: Vec::new(),
        }
    }

    /// The index of a body's or point's declaration among `bodies`.
    pub(super) fn body_index(&self, decl: &Decl) -> usize {
        self.bodies
            .iter()
            .position(|b| std::ptr::eq(b.decl, decl))
            .expect("every position declaration is laid out as a body")
    }

    /// The index of a constraint's declaration among `constraints`.
    pub(super) fn constraint_index(&self, decl: &Decl) -> usize {
        self.constraints
            .iter()
            .position(|c| std::ptr::eq(c.decl, decl))
            .expect("every constraint declaration has a row")
    }

    /// Whether some body with mass moves in `dim` (the plane or space): what a gravity field of
    /// that dimension acts on.
    pub(super) fn has_massive_body_in(&self, dim: Dim) -> bool {
        self.bodies
            .iter()
            .any(|b| b.shape.has_mass() && b.shape.dim() == dim)
    }

    /// The first runtime constraint row of constraint item `item` (a friction cone takes two).
    pub fn constraint_row(&self, item: usize) -> usize {
        self.constraints[..item]
            .iter()
            .map(ConstraintRow::width)
            .sum()
    }

    /// Runtime constraint rows in total.
    pub fn constraint_row_count(&self) -> usize {
        self.constraint_row(self.constraints.len())
    }

    /// Degrees of freedom: every element of every coordinate.
    pub fn dof(&self) -> usize {
        crate::ast::slot_count(self.coords)
    }

    /// The free names of a group of functions.
    pub fn names_used_by<'d>(&self, decls: impl IntoIterator<Item = &'d Decl>) -> BTreeSet<String> {
        decls
            .into_iter()
            .flat_map(|d| {
                self.free_names
                    .get(&d.ident().to_string())
                    .into_iter()
                    .flatten()
            })
            .map(|i| i.to_string())
            .collect()
    }
}

/// Constraint rows in declaration order, their contacts not yet known.
fn constraint_rows(mechanism: &Mechanism) -> Vec<ConstraintRow<'_>> {
    mechanism
        .decls
        .iter()
        .filter(|d| d.kind().is_constraint())
        .map(|decl| ConstraintRow {
            decl,
            normal: None,
            cone: decl.kind() == Kind::Friction
                && return_type_name(decl).as_deref() == Some("Vec2"),
        })
        .collect()
}

/// Bodies and points with their shapes, massive ones first in x, points last.
fn lay_out_bodies<'a>(cx: &Ctxt, mechanism: &'a Mechanism) -> Vec<Body<'a>> {
    let mut bodies: Vec<Body> = mechanism
        .decls
        .iter()
        .filter(|d| d.kind().is_position())
        .map(|decl| Body {
            decl,
            shape: body_shape(cx, decl),
            row: 0,
            count: family_count(cx, mechanism, decl),
        })
        .collect();
    let mut row = 0;
    for massive in [true, false] {
        for body in bodies.iter_mut().filter(|b| b.shape.has_mass() == massive) {
            body.row = row;
            row += body.rows();
        }
    }
    bodies
}

/// The number of members of a family (`count = LINKS`), reporting a length the macro cannot read.
pub(super) fn family_count(cx: &Ctxt, mechanism: &Mechanism, decl: &Decl) -> Option<usize> {
    let expr = decl.args.count.as_ref()?;
    match mechanism.constant_length(expr) {
        // `#[particle(mass = m, count = 0)]`: a family has members.
        Some(0) => {
            cx.error_spanned_by(expr, "a family needs at least one member");
            None
        }
        Some(n) => Some(n),
        // `count = links()`: the macro lays out rows, so it needs the number.
        None => {
            cx.error_spanned_by(
                expr,
                "`count` is an integer literal or a `const NAME: usize = <integer>;` of this module",
            );
            None
        }
    }
}

/// The index of a family member: the one `usize` argument of its function.
pub fn family_index(decl: &Decl) -> Option<&Ident> {
    decl.args.count.as_ref()?;
    match decl.sig.inputs.first()? {
        syn::FnArg::Typed(t) => match &*t.pat {
            syn::Pat::Ident(p) => Some(&p.ident),
            _ => None,
        },
        _ => None,
    }
}

/// The shape of a body from its return type and inertia, reporting mismatches.
fn body_shape(cx: &Ctxt, decl: &Decl) -> Shape {
    match decl.kind() {
        // `#[particle(mass = m)] fn bob() -> f64`: a particle is where it is.
        Kind::Particle => Shape::Particle(vector_dim(expect_return_type(
            cx,
            decl,
            &["Vec2", "Vec3"],
            "its position",
        ))),
        // `#[point] fn tip() -> Planar`: a point is a position.
        Kind::Point => Shape::Point(vector_dim(expect_return_type(
            cx,
            decl,
            &["Vec2", "Vec3"],
            "its position",
        ))),
        _ => rigid_body_shape(cx, decl),
    }
}

/// A rigid body is `Planar` with one moment of inertia and `Spatial` with three principal moments
/// or a full tensor; a return type that disagrees with the inertia is reported (and the body taken
/// as `Spatial`).
fn rigid_body_shape(cx: &Ctxt, decl: &Decl) -> Shape {
    let principal = matches!(
        decl.args.inertia,
        Some(Inertia::Principal(_) | Inertia::Tensor(_))
    );
    // `#[rigid_body(..)] fn bar() -> Vec2`: a rigid body has an orientation too.
    let name = expect_return_type(
        cx,
        decl,
        &["Planar", "Spatial"],
        "its centre of mass and orientation",
    );
    match (name.as_deref(), principal) {
        (Some("Spatial"), true) | (None, true) => Shape::Spatial,
        (Some("Planar"), false) | (None, false) => Shape::Planar,
        // `#[rigid_body(mass = m, inertia = [a, b, c])] fn top() -> Planar`.
        (Some(_), true) => {
            let message = match decl.args.inertia {
                Some(Inertia::Tensor(_)) => "an inertia tensor `inertia = [[..], [..], [..]]` makes a spatial body: return `Spatial`",
                _ => "three principal moments `inertia = [I1, I2, I3]` make a spatial body: return `Spatial`",
            };
            cx.error_spanned_by(decl.output(), message);
            Shape::Spatial
        }
        // `#[rigid_body(mass = m, inertia = i)] fn top() -> Spatial`.
        (Some(_), false) => {
            cx.error_spanned_by(
                decl.output(),
                "a spatial body needs its principal moments `inertia = [I1, I2, I3]`; one moment makes a `Planar` body",
            );
            Shape::Spatial
        }
    }
}
