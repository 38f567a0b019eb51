//! The checks: every rule a declaration must satisfy, each reported at the offending tokens into
//! the error context. The result is the checked model the expansion works from.

use crate::ast::{Decl, Field, Mechanism};
use crate::attr::{Inertia, Kind};
use crate::ctxt::Ctxt;
use crate::names;
use std::collections::{BTreeSet, HashMap};
use syn::ext::IdentExt;
use syn::{Ident, Type};

/// Functions of the geometry module, in scope in every function body.
pub const GEOMETRY_FUNCTIONS: &[&str] = &[
    "vec2", "vec3", "planar", "spatial", "rot_x", "rot_y", "rot_z",
];
/// Single-segment values of Rust's prelude.
const PRELUDE_VALUES: &[&str] = &["Some", "None", "Ok", "Err", "drop"];

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
    /// Members: 1, or the family's count.
    pub fn members(&self) -> usize {
        self.count.unwrap_or(1)
    }
    /// Rows of x the body (all its members) occupies.
    pub fn rows(&self) -> usize {
        self.shape.rows() * self.members()
    }
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
}

impl<'a> Model<'a> {
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

/// Checks `mechanism`, reporting every problem into `cx`. Returns the model when the declaration
/// has its two structs (even if other errors were found, so that they are all reported).
pub fn check<'a>(cx: &Ctxt, mechanism: &'a Mechanism) -> Option<Model<'a>> {
    // `#[mechanism] mod m {}`: one message for both structs.
    if mechanism.coords.is_none() && mechanism.params.is_none() {
        cx.error_at(
            mechanism.span(),
            "a mechanism declares `pub struct Coords { ... }` (the generalized coordinates) and a parameter struct (`pub struct Name { pub m: f64, ... }`: its name is the mechanism's type)",
        );
        return None;
    }
    // `#[mechanism] mod m { struct Pendulum {..} ... }` without `struct Coords`.
    if mechanism.coords.is_none() {
        cx.error_at(
            mechanism.span(),
            "missing `pub struct Coords { ... }`: the generalized coordinates, one `f64` field each",
        );
    }
    // `#[mechanism] mod m { struct Coords {..} ... }` without a parameter struct.
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
    } else if mechanism.params.is_none() {
        cx.error_at(
            mechanism.span(),
            "missing the parameter struct (`pub struct Name { pub m: f64, ... }`): its name is the mechanism's type",
        );
    }
    let (Some((_, coords)), Some((params_struct, params))) = (&mechanism.coords, &mechanism.params)
    else {
        return None;
    };
    // `struct Coords {}`: nothing moves. (`struct Coords(f64);` was reported as such.)
    let tuple = matches!(
        mechanism.coords.as_ref().map(|(s, _)| &s.fields),
        Some(syn::Fields::Unnamed(_))
    );
    if coords.is_empty() && !tuple {
        cx.error_spanned_by(
            &mechanism.coords.as_ref().unwrap().0.ident,
            "`Coords` needs at least one coordinate",
        );
    }
    check_duplicates(cx, mechanism, coords, params);
    let bodies = lay_out_bodies(cx, mechanism);
    let mut model = Model {
        mechanism,
        params_ident: &params_struct.ident,
        coords,
        params,
        potentials: Vec::new(),
        gravities: Vec::new(),
        uniform_gravities: Vec::new(),
        forces: Vec::new(),
        constraints: mechanism
            .decls
            .iter()
            .filter(|d| d.kind().is_constraint())
            .map(|decl| ConstraintRow {
                decl,
                normal: None,
                cone: decl.kind() == Kind::Friction
                    && return_type_name(decl).as_deref() == Some("Vec2"),
            })
            .collect(),
        free_names: HashMap::new(),
        rheonomic: false,
        rows: bodies.iter().map(|b| b.rows()).sum(),
        inertial_rows: bodies
            .iter()
            .filter(|b| b.shape.has_mass())
            .map(|b| b.rows())
            .sum(),
        bodies,
    };
    for decl in &mechanism.decls {
        check_signature(cx, decl);
        check_function(cx, &mut model, decl);
    }
    check_gravity_covers_every_body(cx, &model);
    check_masses(cx, &model);
    check_indices(cx, &model);
    check_constraint_count(cx, &model);
    check_coordinates_are_used(cx, &model);
    check_helper_calls(cx, &model);
    Some(model)
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
fn family_count(cx: &Ctxt, mechanism: &Mechanism, decl: &Decl) -> Option<usize> {
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

/// The last segment of a return type, if it is a plain name (`Vec2`, `lagrange::Vec2`).
fn return_type_name(decl: &Decl) -> Option<String> {
    match crate::ast::ungroup_type(decl.output()?) {
        Type::Path(p) if p.qself.is_none() => {
            let last = p.path.segments.last()?;
            last.arguments.is_none().then(|| last.ident.to_string())
        }
        _ => None,
    }
}

/// Reports a return type that is not one of `expected`, at the return type (or the name if none).
fn expect_return_type(cx: &Ctxt, decl: &Decl, expected: &[&str], why: &str) -> Option<String> {
    let name = return_type_name(decl).filter(|n| expected.contains(&n.as_str()));
    if name.is_none() {
        let list = expected
            .iter()
            .map(|e| format!("`{e}`"))
            .collect::<Vec<_>>()
            .join(" or ");
        let message = format!("`#[{}]` returns {why}: {list}", decl.kind().name());
        match decl.output() {
            Some(ty) => cx.error_spanned_by(ty, message),
            None => cx.error_spanned_by(&decl.sig, format!("missing return type; {message}")),
        }
    }
    name
}

fn vector_dim(name: Option<String>) -> Dim {
    if name.as_deref() == Some("Vec3") {
        Dim::Three
    } else {
        Dim::Two
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

fn rigid_body_shape(cx: &Ctxt, decl: &Decl) -> Shape {
    let principal = matches!(decl.args.inertia, Some(Inertia::Principal(_)));
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
            cx.error_spanned_by(
                decl.output(),
                "three principal moments `inertia = [I1, I2, I3]` make a spatial body: return `Spatial`",
            );
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

/// Duplicate names among coordinates, parameters, bodies and functions, and the reserved `t`.
fn check_duplicates(cx: &Ctxt, mechanism: &Mechanism, coords: &[Field], params: &[Field]) {
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

/// A marked function takes no arguments, no generics, and is a plain `fn`.
fn check_signature(cx: &Ctxt, decl: &Decl) {
    let sig = &decl.sig;
    if decl.args.count.is_some() {
        // `#[particle(mass = m, count = N)] fn bob() -> Vec2`: a member is a function of its index.
        let is_index = |arg: &syn::FnArg| {
            matches!(arg, syn::FnArg::Typed(t)
                if matches!(&*t.pat, syn::Pat::Ident(p) if p.by_ref.is_none() && p.mutability.is_none() && p.subpat.is_none())
                && matches!(crate::ast::ungroup_type(&t.ty), Type::Path(p) if p.qself.is_none() && p.path.is_ident("usize")))
        };
        if sig.inputs.len() != 1 || !sig.inputs.first().is_some_and(is_index) {
            let message = "a family's function takes its member's index: `fn name(i: usize)`";
            if sig.inputs.is_empty() {
                cx.error_spanned_by(&sig.ident, message);
            } else {
                cx.error_spanned_by(&sig.inputs, message);
            }
        }
    } else if !sig.inputs.is_empty() {
        // `fn bob(theta: f64) -> Vec2`: coordinates, parameters and `t` are in scope by name.
        cx.error_spanned_by(
            &sig.inputs,
            "declaration functions take no arguments: coordinates, parameters and `t` are in scope by name",
        );
    }
    // `fn bob<T>() -> Vec2`: the scalar type is chosen by the macro.
    if !sig.generics.params.is_empty() || sig.generics.where_clause.is_some() {
        cx.error_spanned_by(
            &sig.generics,
            "declaration functions are not generic: the macro makes them generic over the scalar",
        );
    }
    // `fn bob() -> Vec2 { return vec2(x, y); }`: the body is spliced into generated code.
    if let Some(token) = names::first_return(&decl.block) {
        cx.error_spanned_by(
            token,
            "write the value as the function's last expression: `return` is not supported here",
        );
    }
    // `async fn`, `const fn`, `unsafe fn`, `extern fn`: a plain function body is expected.
    if let Some(token) = sig
        .asyncness
        .as_ref()
        .map(|t| t.span)
        .or(sig.constness.map(|t| t.span))
        .or(sig.unsafety.map(|t| t.span))
    {
        cx.error_at(token, "declaration functions are plain `fn`s");
    }
}

/// Checks the return type, target and names of one function and records what it uses.
fn check_function<'a>(cx: &Ctxt, model: &mut Model<'a>, decl: &'a Decl) {
    let mut gravity = None;
    let context = match decl.kind() {
        Kind::Particle | Kind::RigidBody | Kind::Point => {
            let index = model
                .bodies
                .iter()
                .position(|b| std::ptr::eq(b.decl, decl))
                .unwrap();
            Context::Position(index)
        }
        Kind::Potential => {
            // `#[potential] fn spring() -> Vec2`: a potential is an energy.
            expect_return_type(cx, decl, &["f64"], "the potential energy");
            model.potentials.push(decl);
            Context::Potential
        }
        Kind::Gravity => {
            // `#[gravity] fn down() -> f64`: gravity is a field vector.
            let name = expect_return_type(cx, decl, &["Vec2", "Vec3"], "the field vector g");
            let dim = vector_dim(name.clone());
            let acts_on_something = model
                .bodies
                .iter()
                .any(|b| b.shape.has_mass() && b.shape.dim() == dim);
            // `#[gravity] fn down() -> Vec3` when every body moves in the plane: it acts on nothing.
            if name.is_some() && !acts_on_something {
                let (field, bodies) = if dim == Dim::Two {
                    ("Vec2", "the plane")
                } else {
                    ("Vec3", "space")
                };
                cx.error_spanned_by(
                    decl.output(),
                    format!("a `{field}` field acts on bodies in {bodies}, and there are none"),
                );
            }
            gravity = Some(dim);
            Context::Potential
        }
        Kind::Force | Kind::Torque | Kind::GeneralizedForce => {
            if let Some(force) = check_force_target(cx, model, decl) {
                model.forces.push(force);
            }
            Context::Force
        }
        Kind::Constraint | Kind::Unilateral => {
            // `#[constraint] fn rod() -> Vec2`: a constraint row is one scalar.
            expect_return_type(
                cx,
                decl,
                &["f64"],
                "the constraint function, zero when satisfied",
            );
            check_not_a_comparison(cx, decl);
            Context::Constraint
        }
        Kind::VelocityConstraint => {
            expect_return_type(
                cx,
                decl,
                &["f64"],
                "the constraint, zero when satisfied, affine in velocities",
            );
            check_not_a_comparison(cx, decl);
            Context::Force
        }
        Kind::Friction => {
            // `#[friction(..)] fn slip() -> Vec3`: a slip velocity lies in the tangent plane.
            expect_return_type(
                cx,
                decl,
                &["f64", "Vec2"],
                "the slip velocity: along one tangent direction (planar friction), or its \
                 components along two orthonormal tangent directions (friction in the tangent \
                 plane, the Coulomb cone)",
            );
            check_friction(cx, model, decl);
            Context::Force
        }
    };
    let index = family_index(decl);
    let free: Vec<Ident> = names::free_names(&decl.block)
        .into_iter()
        .filter(|i| Some(i) != index)
        .collect();
    let mut seen = BTreeSet::new();
    // Each name is resolved (and reported) once per function.
    let mut constant = true;
    let mut reads_velocity = false;
    for ident in free.iter().filter(|i| seen.insert(i.to_string())) {
        let name = Resolver { model, context }.resolve(cx, ident);
        reads_velocity |= matches!(name, Some(Name::CoordVelocity | Name::BodyVelocity));
        let is_force = matches!(
            decl.kind(),
            Kind::Force | Kind::Torque | Kind::GeneralizedForce
        );
        if name == Some(Name::Time) && !is_force {
            model.rheonomic = true;
        }
        constant &= matches!(name, Some(Name::Param | Name::Item));
    }
    // `#[velocity_constraint] fn on_line() -> f64 { y - x }`: without a velocity it constrains
    // positions, which is a `#[constraint]`.
    if decl.kind() == Kind::VelocityConstraint && !reads_velocity {
        cx.error_spanned_by(
            decl.ident(),
            "a `#[velocity_constraint]` is affine in velocities (`x_dot`, `body_dot`), and this one \
             names none: a condition on positions alone is a `#[constraint]`",
        );
    }
    match gravity {
        Some(dim) if constant => model.uniform_gravities.push((decl, dim)),
        Some(dim) => model.gravities.push((decl, dim)),
        None => {}
    }
    model.free_names.insert(decl.ident().to_string(), free);
}

/// The body or coordinate a force acts on, checked against its kind and return type.
fn check_force_target<'a>(cx: &Ctxt, model: &Model<'a>, decl: &'a Decl) -> Option<Force<'a>> {
    let kind = decl.kind();
    let dim = match kind {
        // `#[force(on = bob)] fn push() -> f64`: a Cartesian force is a vector.
        Kind::Force => Some(vector_dim(expect_return_type(
            cx,
            decl,
            &["Vec2", "Vec3"],
            "the force vector",
        ))),
        // `#[torque(on = bar)] fn motor() -> Vec2`: a planar torque is a scalar, a spatial one a
        // vector; which one the body decides, below.
        Kind::Torque => None,
        _ => expect_return_type(cx, decl, &["f64"], "its magnitude").map(|_| Dim::Two),
    };
    // `#[force] fn drag() -> Vec2`: what does it act on?
    let Some(on) = decl.args.on.as_ref().filter(|_| !decl.args.malformed) else {
        if decl.args.malformed {
            return None;
        }
        cx.error_spanned_by(
            &decl.args.attr,
            format!("missing `on = ...`: `#[{}(on = name)]`", kind.name()),
        );
        return None;
    };
    let target = match kind {
        Kind::GeneralizedForce => {
            let field = model.coords.iter().position(|c| c.ident == *on);
            // `#[generalized_force(on = theta)]` with `theta: [f64; N]`: one element is meant.
            if let Some(f) = field.filter(|&f| model.coords[f].array.is_some()) {
                cx.error_spanned_by(
                    on,
                    format!("`{on}` is an array of coordinates: a generalized force acts on a scalar coordinate"),
                );
                let _ = f;
                return None;
            }
            field.map(|f| crate::ast::slot_count(&model.coords[..f]))
        }
        _ => model.bodies.iter().position(|b| b.decl.ident() == on),
    };
    let Some(target) = target else {
        // `#[force(on = bobb)]`: a typo in the target.
        let what = if kind == Kind::GeneralizedForce {
            "coordinate"
        } else {
            "body or point"
        };
        cx.error_spanned_by(on, format!("`{on}` is not a {what} of this mechanism"));
        return None;
    };
    if kind == Kind::Torque {
        match model.bodies[target].shape {
            // `#[torque(on = bar)] fn motor() -> Vec2` on a planar body: the torque about the plane's
            // normal is a scalar.
            Shape::Planar => {
                expect_return_type(cx, decl, &["f64"], "its magnitude about the plane's normal");
            }
            // `#[torque(on = top)] fn drive() -> f64` on a spatial body: the torque is a vector.
            Shape::Spatial => {
                expect_return_type(cx, decl, &["Vec3"], "the torque vector, in the world frame");
            }
            // `#[torque(on = bob)]` on a particle: only a rigid body has an orientation to twist.
            _ => cx.error_spanned_by(
                on,
                format!(
                    "`{on}` is not a rigid body: a torque acts on a `Planar` or `Spatial` body"
                ),
            ),
        }
    }
    if kind == Kind::Force && dim != Some(model.bodies[target].shape.dim()) {
        // `#[force(on = bob3d)] fn push() -> Vec2`: the force has the dimension of its body.
        let want = if model.bodies[target].shape.dim() == Dim::Two {
            "Vec2"
        } else {
            "Vec3"
        };
        cx.error_spanned_by(
            decl.output(),
            format!(
                "`{on}` moves in {}: the force on it is a `{want}`",
                if want == "Vec2" { "the plane" } else { "space" }
            ),
        );
    }
    let count = family_count(cx, model.mechanism, decl);
    if kind != Kind::GeneralizedForce {
        let members = model.bodies[target].count;
        match (members, count) {
            (Some(n), Some(m)) if n != m => {
                // `#[force(on = bob, count = 4)]` on a family of 8: one force per member.
                cx.error_spanned_by(
                    decl.args.count.as_ref(),
                    format!("mismatched family length: `{on}` has {n} members, this family of forces has {m}"),
                );
            }
            (Some(n), None) if kind == Kind::Force && !decl.args.malformed => cx.error_spanned_by(
                on,
                format!("`{on}` is a family of {n}: the force on it is a family too, `#[force(on = {on}, count = {n})] fn {}(i: usize)`", decl.ident()),
            ),
            (Some(_), _) if kind == Kind::Torque => cx.error_spanned_by(
                on,
                format!("`{on}` is a family: torques on families are not supported"),
            ),
            (None, Some(_)) => cx.error_spanned_by(
                decl.args.count.as_ref(),
                format!("`{on}` is a single body: a family of forces acts on a family of bodies"),
            ),
            _ => {}
        }
    }
    Some(Force {
        decl,
        target,
        kind,
        count,
    })
}

/// Indexing an array coordinate or a family: a literal index must be in range, and a family's own
/// index must not run past an array shorter than the family.
fn check_indices(cx: &Ctxt, model: &Model) {
    let mut lengths: HashMap<String, usize> = HashMap::new();
    for c in model.coords {
        // A length the macro could not read (0) was reported: nothing to check against.
        if let Some((_, n)) = c.array.as_ref().filter(|(_, n)| *n > 0) {
            let n = *n;
            lengths.insert(c.ident.to_string(), n);
            lengths.insert(format!("{}_dot", c.ident), n);
        }
    }
    for b in &model.bodies {
        if let Some(n) = b.count {
            lengths.insert(b.decl.ident().to_string(), n);
            lengths.insert(format!("{}_dot", b.decl.ident()), n);
        }
    }
    if lengths.is_empty() {
        return;
    }
    for decl in &model.mechanism.decls {
        let members = decl
            .args
            .count
            .as_ref()
            .and_then(|c| model.mechanism.constant_length(c));
        let family = family_index(decl).zip(members);
        let mut visitor = Indices {
            cx,
            lengths: &lengths,
            family,
            family_name: decl.ident(),
        };
        syn::visit::Visit::visit_block(&mut visitor, &decl.block);
    }
}

struct Indices<'c, 'l> {
    cx: &'c Ctxt,
    lengths: &'l HashMap<String, usize>,
    /// This function's family index and member count.
    family: Option<(&'l Ident, usize)>,
    family_name: &'l Ident,
}

impl<'ast> syn::visit::Visit<'ast> for Indices<'_, '_> {
    fn visit_expr_index(&mut self, e: &'ast syn::ExprIndex) {
        let base = match crate::ast::ungroup(&e.expr) {
            syn::Expr::Path(p) => p.path.get_ident(),
            _ => None,
        };
        if let Some((name, &len)) = base.and_then(|b| self.lengths.get_key_value(&b.to_string())) {
            match crate::ast::ungroup(&e.index) {
                // `theta[8]` with `theta: [f64; 8]`.
                syn::Expr::Lit(syn::ExprLit {
                    lit: syn::Lit::Int(i),
                    ..
                }) => {
                    if let Ok(k) = i.base10_parse::<usize>() {
                        if k >= len {
                            self.cx.error_spanned_by(
                                i,
                                format!("index {k} is out of range: `{name}` has {len} elements"),
                            );
                        }
                    }
                }
                // `theta[i]` in a family of 9 with `theta: [f64; 8]`.
                syn::Expr::Path(p) => {
                    if let Some((index, members)) = self.family {
                        if p.path.is_ident(index) && members > len {
                            self.cx.error_spanned_by(
                                &e.index,
                                format!(
                                    "mismatched family length: `{}` has {members} members but `{name}` has {len} elements, so `{name}[{index}]` is out of range",
                                    self.family_name
                                ),
                            );
                        }
                    }
                }
                _ => {}
            }
        }
        syn::visit::visit_expr_index(self, e);
    }
    fn visit_item(&mut self, _: &'ast syn::Item) {}
}

/// A constraint's value is an expression that vanishes (or is ≥ 0), not a comparison.
fn check_not_a_comparison(cx: &Ctxt, decl: &Decl) {
    let Some(syn::Stmt::Expr(last, None)) = decl.block.stmts.last() else {
        return;
    };
    let syn::Expr::Binary(binary) = crate::ast::ungroup(last) else {
        return;
    };
    use syn::BinOp::*;
    // `#[constraint] fn rod() -> f64 { bob.norm() == l }`: write `bob.norm() - l`.
    // `#[constraint] fn floor() -> f64 { y >= 0.0 }`: an inequality is a `#[unilateral]` row.
    if matches!(binary.op, Lt(_) | Le(_) | Gt(_) | Ge(_)) && decl.kind() != Kind::Unilateral {
        cx.error_spanned_by(
            binary.op,
            "an inequality is a `#[unilateral]` constraint, written as a value ≥ 0 where the \
             motion is admissible (`y`, not `y >= 0.0`)",
        );
        return;
    }
    if matches!(binary.op, Eq(_) | Ne(_) | Lt(_) | Le(_) | Gt(_) | Ge(_)) {
        let what = if decl.kind() == Kind::Unilateral {
            "≥ 0 where the motion is admissible"
        } else {
            "zero when satisfied"
        };
        cx.error_spanned_by(
            binary.op,
            format!("a constraint is a value, {what}: write `a - b`, not a comparison"),
        );
    }
}

/// Bilateral constraint rows beyond the number of coordinates cannot all be independent.
fn check_constraint_count(cx: &Ctxt, model: &Model) {
    let bilateral = model
        .constraints
        .iter()
        .filter(|r| matches!(r.decl.kind(), Kind::Constraint | Kind::VelocityConstraint));
    // Two coordinates and three `#[constraint]`s: at most two of them can be independent.
    if let Some(extra) = bilateral.clone().nth(model.dof()) {
        let n = model.dof();
        cx.error_spanned_by(
            extra.decl.ident(),
            format!(
                "{} constraints on {n} coordinate{}: at most {n} can be independent",
                bilateral.count(),
                if n == 1 { "" } else { "s" }
            ),
        );
    }
}

/// A friction row: its contact row and its Coulomb coefficients.
fn check_friction(cx: &Ctxt, model: &mut Model, decl: &Decl) {
    let args = &decl.args;
    if args.malformed {
        return;
    }
    // `#[friction(kinetic = mu)] fn slip() -> f64`: friction acts at a contact.
    let Some(on) = &args.on else {
        cx.error_spanned_by(
            &args.attr,
            "missing `on = ...`: the constraint whose force is the normal force",
        );
        return;
    };
    let normal = model
        .constraints
        .iter()
        .position(|c| c.decl.ident() == on && c.decl.kind() != Kind::Friction);
    match normal {
        // `#[friction(on = flor)]`: a typo in the contact.
        None => cx.error_spanned_by(on, format!("`{on}` is not a `#[constraint]`, `#[velocity_constraint]` or `#[unilateral]` of this mechanism")),
        Some(n) => {
            let row = model.constraints.iter().position(|c| std::ptr::eq(c.decl, decl)).unwrap();
            // `#[friction(on = floor)] fn slip() -> Vec2` and another friction on `floor`: the cone
            // already bounds the whole tangential force.
            let cone = model.constraints[row].cone;
            if let Some(other) = model
                .constraints
                .iter()
                .find(|c| c.normal == Some(n) && (cone || c.cone))
            {
                cx.error_spanned_by(
                    on,
                    format!(
                        "`{on}` already has friction `{}`: friction in the tangent plane (a `Vec2` \
                         slip velocity) is the whole friction law of its contact",
                        other.decl.ident()
                    ),
                );
            }
            model.constraints[row].normal = Some(n);
        }
    }
    // `#[friction(on = floor)]`: Coulomb's law needs a coefficient.
    match &args.kinetic {
        None => cx.error_spanned_by(
            &args.attr,
            "missing `kinetic = ...`: the coefficient of sliding friction",
        ),
        Some(kinetic) => check_constant(cx, model, kinetic),
    }
    if let Some(stiction) = &args.stiction {
        check_constant(cx, model, stiction);
    }
}

/// With gravity, every massive body moves in the dimension of some field: a `Vec3` particle under
/// a `Vec2` field alone would silently feel no gravity.
fn check_gravity_covers_every_body(cx: &Ctxt, model: &Model) {
    let fields: Vec<(&Decl, Dim)> = model
        .gravities
        .iter()
        .chain(&model.uniform_gravities)
        .copied()
        .collect();
    // Fields that act on nothing were reported at the field.
    let acting: Vec<&(&Decl, Dim)> = fields
        .iter()
        .filter(|(_, dim)| {
            model
                .bodies
                .iter()
                .any(|b| b.shape.has_mass() && b.shape.dim() == *dim)
        })
        .collect();
    let Some((field, dim)) = acting.first() else {
        return;
    };
    for body in &model.bodies {
        if !body.shape.has_mass() || acting.iter().any(|(_, d)| *d == body.shape.dim()) {
            continue;
        }
        // `#[gravity] fn down() -> Vec2` and `#[particle(..)] fn bead() -> Vec3`.
        let (moves, field_type, other) = match dim {
            Dim::Two => ("space", "Vec2", "Vec3"),
            Dim::Three => ("the plane", "Vec3", "Vec2"),
        };
        cx.error_spanned_by(
            body.decl.output(),
            format!(
                "`{}` moves in {moves}, but the gravity `{}` is a `{field_type}` field and would not act on it: declare a `#[gravity] fn ..() -> {other}` field for it too, or give it the field's dimension",
                body.decl.ident(),
                field.ident()
            ),
        );
    }
}

/// Masses and inertias: present where needed, constant.
fn check_masses(cx: &Ctxt, model: &Model) {
    for body in &model.bodies {
        let args = &body.decl.args;
        let name = body.decl.ident();
        if args.kind == Kind::Point || args.malformed {
            continue;
        }
        // `#[particle] fn bob() -> Vec2`: a body without a mass.
        match &args.mass {
            None => cx.error_spanned_by(
                &args.attr,
                format!(
                    "`{name}` has no mass: write `#[{}(mass = ...)]`",
                    args.kind.name()
                ),
            ),
            Some(mass) => check_constant(cx, model, mass),
        }
        if args.kind != Kind::RigidBody {
            continue;
        }
        match &args.inertia {
            // `#[rigid_body(mass = m)] fn bar() -> Planar`: a rigid body also needs its inertia.
            None => cx.error_spanned_by(
                &args.attr,
                format!("rigid body `{name}` has no inertia: add `inertia = ...` (one moment, or `[I1, I2, I3]`)"),
            ),
            Some(Inertia::Moment(e)) => check_constant(cx, model, e),
            Some(Inertia::Principal(array)) => {
                // `inertia = [a, b]`: three principal moments.
                if array.elems.len() != 3 {
                    cx.error_spanned_by(array, "principal moments are three: `[I1, I2, I3]`");
                }
                array.elems.iter().for_each(|e| check_constant(cx, model, e));
            }
        }
    }
}

/// A mass or inertia names only parameters and module items.
fn check_constant(cx: &Ctxt, model: &Model, expr: &syn::Expr) {
    let mut seen = BTreeSet::new();
    for ident in names::free_names_of_expr(expr)
        .iter()
        .filter(|i| seen.insert(i.to_string()))
    {
        Resolver {
            model,
            context: Context::Mass,
        }
        .resolve(cx, ident);
    }
}

/// `fn helper(x: f64) -> f64` in the module, called from a declaration's function: those functions
/// are evaluated on dual numbers (to differentiate them) — coordinates, parameters and literals alike
/// — so an `f64` parameter cannot take the argument and rustc would report a mismatch on generated
/// types. One message at the call says what to write instead. (In an attribute, `mass = helper(m)`,
/// everything is `f64` and the call is fine.)
fn check_helper_calls(cx: &Ctxt, model: &Model) {
    let helpers: Vec<&Ident> = model
        .mechanism
        .other_items
        .iter()
        .filter_map(|item| match item {
            syn::Item::Fn(f) if f.sig.generics.params.is_empty() => f
                .sig
                .inputs
                .iter()
                .any(|arg| matches!(arg, syn::FnArg::Typed(t) if is_f64_type(&t.ty)))
                .then_some(&f.sig.ident),
            _ => None,
        })
        .collect();
    if helpers.is_empty() {
        return;
    }
    for decl in &model.mechanism.decls {
        let mut calls = HelperCalls {
            helpers: &helpers,
            found: Vec::new(),
        };
        syn::visit::Visit::visit_block(&mut calls, &decl.block);
        for (call, name) in calls.found {
            cx.error_spanned_by(
                call,
                format!(
                    "`{name}` takes `f64`, but a mechanism's functions run on dual numbers (that is how they are differentiated): make it generic, `fn {name}<D: lagrange::Scalar>(x: D) -> D`, or write its expression inline"
                ),
            );
        }
    }
}

fn is_f64_type(ty: &Type) -> bool {
    match ty {
        Type::Path(p) => p.qself.is_none() && p.path.is_ident("f64"),
        Type::Group(g) => is_f64_type(&g.elem),
        Type::Paren(p) => is_f64_type(&p.elem),
        _ => false,
    }
}

/// Calls of helpers that take an `f64` argument.
struct HelperCalls<'a> {
    helpers: &'a [&'a Ident],
    found: Vec<(&'a syn::ExprCall, String)>,
}

impl<'ast: 'a, 'a> syn::visit::Visit<'ast> for HelperCalls<'a> {
    fn visit_expr_call(&mut self, call: &'ast syn::ExprCall) {
        if let syn::Expr::Path(p) = &*call.func {
            if let Some(name) = p.path.get_ident() {
                if self.helpers.contains(&name) {
                    self.found.push((call, name.to_string()));
                }
            }
        }
        syn::visit::visit_expr_call(self, call);
    }
    fn visit_item(&mut self, _: &'ast syn::Item) {}
}

/// A coordinate that no position depends on leaves the mass matrix singular.
fn check_coordinates_are_used(cx: &Ctxt, model: &Model) {
    let mut depends: Vec<BTreeSet<usize>> = Vec::new();
    for body in &model.bodies {
        let mut coords = BTreeSet::new();
        // What the position's value depends on: `let _unused = y;` does not move the body.
        for ident in &names::value_names(&body.decl.block) {
            if let Some(j) = model.coords.iter().position(|c| c.ident == *ident) {
                coords.insert(j);
            } else if let Some(b) = model.bodies.iter().position(|b| b.decl.ident() == ident) {
                coords.extend(depends.get(b).into_iter().flatten().copied());
            }
        }
        depends.push(coords);
    }
    let used: BTreeSet<usize> = depends.into_iter().flatten().collect();
    for (j, coord) in model.coords.iter().enumerate() {
        let repeated = model.coords[..j].iter().any(|c| c.ident == coord.ident);
        // An array whose length was reported has no elements to depend on.
        let unread = matches!(coord.array, Some((_, 0)));
        // `Coords { x, y }` where no body's position names `y`: its mass-matrix row is zero.
        if !used.contains(&j) && !repeated && !unread {
            cx.error_spanned_by(
                &coord.ident,
                format!(
                    "no body or point position depends on coordinate `{}`: its row of the mass matrix would be zero",
                    coord.ident
                ),
            );
        }
    }
}

/// Where a name is being resolved.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Context {
    /// The position of the body with this index.
    Position(usize),
    /// A potential or gravity.
    Potential,
    /// A holonomic or unilateral constraint.
    Constraint,
    /// A force, torque or generalized force.
    Force,
    /// A mass or inertia.
    Mass,
}

/// What a free name refers to.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Name {
    Coord,
    Param,
    Time,
    Body(usize),
    CoordVelocity,
    BodyVelocity,
    Item,
}

struct Resolver<'m, 'a> {
    model: &'m Model<'a>,
    context: Context,
}

impl Resolver<'_, '_> {
    fn lookup(&self, ident: &Ident) -> Option<Name> {
        let model = self.model;
        let name = ident.to_string();
        let velocity_of = name.strip_suffix("_dot");
        if model.coords.iter().any(|c| c.ident == name) {
            Some(Name::Coord)
        } else if model.params.iter().any(|p| p.ident == name) {
            Some(Name::Param)
        } else if name == "t" {
            Some(Name::Time)
        } else if let Some(b) = model.bodies.iter().position(|b| b.decl.ident() == &name) {
            Some(Name::Body(b))
        // `r#type_dot` is not an identifier: the velocity of `r#type` is `type_dot`.
        } else if velocity_of.is_some_and(|v| model.coords.iter().any(|c| c.ident.unraw() == v)) {
            Some(Name::CoordVelocity)
        } else if velocity_of
            .is_some_and(|v| model.bodies.iter().any(|b| b.decl.ident().unraw() == v))
        {
            Some(Name::BodyVelocity)
        } else if model.mechanism.item_names.iter().any(|i| *i == name)
            || GEOMETRY_FUNCTIONS.contains(&name.as_str())
            || PRELUDE_VALUES.contains(&name.as_str())
        {
            Some(Name::Item)
        } else {
            None
        }
    }

    /// Resolves a free name, reporting one that is unknown or not allowed here.
    fn resolve(&self, cx: &Ctxt, ident: &Ident) -> Option<Name> {
        let name = self.lookup(ident);
        match (self.context, name) {
            // `fn bob() -> Vec2 { vec2(self.l, 0.0) }`: parameters are named directly.
            (_, None) if ident == "self" => {
                cx.error_spanned_by(ident, "declaration functions have no `self`: name parameters directly (`l`, not `self.l`)")
            }
            // `vec2(theta.sin(), 0.0) * lenght`: a typo, or something not in scope (unless a glob
            // import may bring it in: then rustc decides).
            (_, None) if !self.model.mechanism.has_glob_import => {
                cx.error_spanned_by(ident, self.unknown_message(ident))
            }
            // `fn bob() -> Vec2 { vec2(theta_dot, 0.0) }`.
            (Context::Position(_), Some(Name::CoordVelocity | Name::BodyVelocity)) => cx.error_spanned_by(
                ident,
                format!("positions cannot depend on velocities: `{ident}` is in scope in forces only"),
            ),
            // `#[constraint] fn rod() -> f64 { x_dot }`.
            (Context::Constraint, Some(Name::CoordVelocity | Name::BodyVelocity)) => cx.error_spanned_by(
                ident,
                format!("a position constraint cannot depend on velocities: `{ident}` is in scope in `#[velocity_constraint]`s, `#[friction]` and forces"),
            ),
            // `#[potential] fn v() -> f64 { theta_dot * theta_dot }`.
            (Context::Potential, Some(Name::CoordVelocity | Name::BodyVelocity)) => cx.error_spanned_by(
                ident,
                format!("potentials cannot depend on velocities: `{ident}` is in scope in forces only (write a `#[force]` or `#[generalized_force]`)"),
            ),
            // `fn bob1() -> Vec2 { bob2 + ... }` where `bob2` comes later (or is `bob1` itself).
            // A family member names earlier members of its own family: `bob[i - 1]`.
            (Context::Position(me), Some(Name::Body(b)))
                if b == me && self.model.bodies[me].count.is_some() => {}
            (Context::Position(me), Some(Name::Body(b))) if b >= me => {
                let this = self.model.bodies[me].decl.ident();
                let message = if b == me {
                    format!("`{this}` cannot use its own position")
                } else {
                    format!("`{ident}` is declared after `{this}`: a position can only use bodies and points declared before it")
                };
                cx.error_spanned_by(ident, message);
            }
            // `#[particle(mass = m * theta)]`: masses are constants.
            (Context::Mass, Some(Name::Coord | Name::Time | Name::Body(_) | Name::CoordVelocity | Name::BodyVelocity)) => {
                cx.error_spanned_by(ident, format!("masses and inertias are constant: they cannot depend on `{ident}`"))
            }
            _ => {}
        }
        name
    }

    fn unknown_message(&self, ident: &Ident) -> String {
        let in_scope = match self.context {
            Context::Position(_) => "a coordinate, parameter, `t`, body or point declared earlier, or item of this module",
            Context::Potential | Context::Constraint => "a coordinate, parameter, `t`, body, point, or item of this module",
            Context::Force => "a coordinate, parameter, `t`, body, point, their `_dot` velocities, or item of this module",
            Context::Mass => "a parameter or an item of this module",
        };
        format!("unknown name `{ident}`: it is not {in_scope}")
    }
}
