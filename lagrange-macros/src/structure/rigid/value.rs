//! A body's function read as the composition of frames it writes: rotations as products of
//! factors (an earlier body's rotation, constant rotations, a rotation about a coordinate axis by a
//! coordinate), positions as sums of rotated pieces (an earlier body's position, constant vectors,
//! a slide by a coordinate). Anything else — a coordinate inside a `sin`, a body named inside a
//! product, a helper function — is not read, and the declaration keeps the dense pass.
//!
//! Constants (everything that names only parameters, literals, module items and the family index)
//! are kept as expressions to be evaluated once, in `f64`, when the constants are prepared.

use crate::check::{ChartKind, Model};
use crate::structure::{condition, evaluate, strip, Family};
use proc_macro2::TokenStream;
use quote::{quote, ToTokens};
use syn::{BinOp, Block, Expr, Lit, Stmt, UnOp};

/// A coordinate axis of a frame.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Axis {
    X,
    Y,
    Z,
}

/// A factor of a rotation product, left to right.
#[derive(Clone, Debug)]
pub enum Factor {
    /// The rotation of tree node `n` as its function returns it.
    Body(usize),
    /// A constant rotation (a `Rot3<f64>` expression).
    Constant(TokenStream),
    /// A rotation about a coordinate axis by coordinate `slot`.
    Joint(Axis, usize),
    /// `rot_mrp` or `rot_vector` of the coordinates `slot`, `slot + 1`, `slot + 2` (see
    /// [`super::free`]).
    Chart(ChartKind, usize),
}

/// What a piece of a position is before the rotations of its term act on it.
#[derive(Clone, Debug)]
pub enum Piece {
    /// The position of tree node `n` as its function returns it (only unrotated).
    Origin(usize),
    /// A constant vector (a `Vec3<f64>` expression), and which of its components are literal
    /// zeros.
    Constant(TokenStream, [bool; 3]),
    /// c ± e_axis q_slot: a slide along a coordinate axis by a coordinate (backwards when the flag
    /// is set), from a constant.
    Slide(Option<TokenStream>, Axis, usize, bool),
    /// (q_slot, q_slot+1, q_slot+2): three consecutive coordinates (see [`super::free`]).
    Coordinates(usize),
}

/// A term of a position: rotations (left to right) applied to a piece.
#[derive(Clone, Debug)]
pub struct Term {
    pub rotation: Vec<Factor>,
    pub piece: Piece,
}

/// The value of an expression of a body's function.
#[derive(Clone, Debug)]
pub enum Value {
    /// A constant scalar (an `f64` expression).
    Scalar(TokenStream),
    /// A coordinate, by slot.
    Coordinate(usize),
    /// ±q + c: a coordinate (slot), negated or not, plus a constant.
    Affine(TokenStream, usize, bool),
    /// A planar angle: a rotation about z.
    Angle(Vec<Factor>),
    Rotation(Vec<Factor>),
    Vector(Vec<Term>),
    /// A frame: a `Spatial` or `Planar` value.
    Pose {
        position: Vec<Term>,
        rotation: Vec<Factor>,
    },
}

/// Reads one body's (or family member's) function.
pub struct Reader<'a> {
    pub model: &'a Model<'a>,
    /// The tree nodes so far: (body index, member) each.
    pub nodes: &'a [(usize, Option<usize>)],
    pub family: Family<'a>,
    /// Values of the locals bound so far, innermost last.
    locals: Vec<(String, Value)>,
}

impl<'a> Reader<'a> {
    pub fn new(
        model: &'a Model<'a>,
        nodes: &'a [(usize, Option<usize>)],
        family: Family<'a>,
    ) -> Self {
        Reader {
            model,
            nodes,
            family,
            locals: Vec::new(),
        }
    }

    /// The value of a block: its `let`s, then its final expression.
    pub fn block(&mut self, block: &Block) -> Option<Value> {
        let depth = self.locals.len();
        let mut value = None;
        for (k, stmt) in block.stmts.iter().enumerate() {
            match stmt {
                Stmt::Local(local) => {
                    let syn::Pat::Ident(p) = &local.pat else {
                        return None;
                    };
                    let init = local.init.as_ref()?;
                    if init.diverge.is_some() || p.by_ref.is_some() || p.mutability.is_some() {
                        return None;
                    }
                    let v = self.expr(&init.expr)?;
                    self.locals.push((p.ident.to_string(), v));
                }
                Stmt::Expr(e, None) if k + 1 == block.stmts.len() => value = self.expr(e),
                _ => return None,
            }
        }
        self.locals.truncate(depth);
        value
    }

    /// The value of an expression.
    pub fn expr(&mut self, e: &Expr) -> Option<Value> {
        match e {
            Expr::Paren(p) => self.expr(&p.expr),
            Expr::Group(g) => self.expr(&g.expr),
            Expr::Block(b) if b.label.is_none() => self.block(&b.block),
            Expr::If(i) => self.branch(i),
            Expr::Lit(l) => matches!(l.lit, Lit::Float(_) | Lit::Int(_)).then(|| scalar(e)),
            Expr::Path(_) => self.path(e),
            Expr::Index(i) => self.index(i),
            Expr::Call(c) => self.call(c),
            Expr::Array(a) => self.array(a),
            Expr::MethodCall(m) => self.method(m),
            Expr::Field(f) => self.field(f),
            Expr::Binary(b) => self.binary(b),
            Expr::Unary(u) if matches!(u.op, UnOp::Neg(_)) => negate(self.expr(&u.expr)?),
            Expr::Cast(c) => match self.expr(&c.expr)? {
                Value::Scalar(s) => {
                    let ty = &c.ty;
                    Some(Value::Scalar(quote!((#s as #ty))))
                }
                _ => None,
            },
            _ => None,
        }
    }

    /// `[..]` of constants, nested or not (`rot3`'s matrix written out): a constant, rebuilt from
    /// its elements' values (so a family's index in it is the member's).
    fn array(&mut self, a: &syn::ExprArray) -> Option<Value> {
        let elements = a
            .elems
            .iter()
            .map(|e| match self.expr(e)? {
                Value::Scalar(s) => Some(s),
                _ => None,
            })
            .collect::<Option<Vec<_>>>()?;
        Some(Value::Scalar(quote!([#(#elements),*])))
    }

    /// `if i == 0 { .. } else { .. }`: the member decides.
    fn branch(&mut self, e: &syn::ExprIf) -> Option<Value> {
        match condition(&e.cond, self.family?)? {
            true => self.block(&e.then_branch),
            false => self.expr(&e.else_branch.as_ref()?.1),
        }
    }

    fn local(&self, name: &str) -> Option<&Value> {
        self.locals
            .iter()
            .rev()
            .find(|(n, _)| n == name)
            .map(|(_, v)| v)
    }

    fn path(&mut self, e: &Expr) -> Option<Value> {
        let Expr::Path(p) = e else { return None };
        let ident = p.path.get_ident()?;
        let name = ident.to_string();
        if let Some(v) = self.local(&name) {
            return Some(v.clone());
        }
        if let Some((index, member)) = self.family {
            if ident == index {
                let member = crate::expand::lit(member);
                return Some(Value::Scalar(quote!(#member)));
            }
        }
        if let Some(slot) = self.scalar_coordinate(&name) {
            return Some(Value::Coordinate(slot));
        }
        if let Some(node) = self.node_of(&name, None) {
            return Some(self.body_value(node));
        }
        self.is_constant_name(&name).then(|| scalar(e))
    }

    /// `q[i]`, `link[i - 1]`, or a constant indexed (`d[i]`, a parameter array).
    fn index(&mut self, i: &syn::ExprIndex) -> Option<Value> {
        let Expr::Path(p) = strip(&i.expr) else {
            return None;
        };
        let name = p.path.get_ident()?.to_string();
        let k = evaluate(&i.index, self.family);
        if let Some((offset, len)) = self.array_coordinate(&name) {
            let k = k?;
            return (k < len).then_some(Value::Coordinate(offset + k));
        }
        if self.model.bodies.iter().any(|b| b.decl.ident() == &name) {
            return Some(self.body_value(self.node_of(&name, Some(k?))?));
        }
        match self.expr(&i.index)? {
            Value::Scalar(index) if self.is_constant_name(&name) => {
                let array = &i.expr;
                Some(Value::Scalar(quote!(#array[#index])))
            }
            _ => None,
        }
    }

    fn call(&mut self, c: &syn::ExprCall) -> Option<Value> {
        let Expr::Path(f) = strip(&c.func) else {
            return None;
        };
        let name = f.path.segments.last()?.ident.to_string();
        let args: Vec<Value> = c.args.iter().map(|a| self.expr(a)).collect::<Option<_>>()?;
        match (name.as_str(), args.as_slice()) {
            ("vec3", [x, y, z]) => vector(&[x, y, z]),
            ("vec2", [x, y]) => vector(&[x, y, &Value::Scalar(quote!(0.0))]),
            ("rot_x", [a]) => rotation_about(Axis::X, a),
            ("rot_y", [a]) => rotation_about(Axis::Y, a),
            ("rot_z", [a]) => rotation_about(Axis::Z, a),
            ("rpy", [Value::Scalar(r), Value::Scalar(p), Value::Scalar(y)]) => Some(
                Value::Rotation(vec![Factor::Constant(quote!(rpy(#r, #p, #y)))]),
            ),
            ("rot3", [Value::Scalar(m)]) => {
                Some(Value::Rotation(vec![Factor::Constant(quote!(rot3(#m)))]))
            }
            ("rot_axis", [axis, angle]) => rotation_about_axis(axis, angle),
            ("rot_mrp" | "rot_vector", [c]) => super::free::chart(ChartKind::named(&name)?, c),
            ("spatial", [Value::Vector(position), Value::Rotation(rotation)]) => {
                Some(Value::Pose {
                    position: position.clone(),
                    rotation: rotation.clone(),
                })
            }
            ("planar", [Value::Vector(position), angle]) => Some(Value::Pose {
                position: position.clone(),
                rotation: angle_factors(angle)?,
            }),
            _ => None,
        }
    }

    fn method(&mut self, m: &syn::ExprMethodCall) -> Option<Value> {
        let receiver = self.expr(&m.receiver)?;
        let args: Vec<Value> = m.args.iter().map(|a| self.expr(a)).collect::<Option<_>>()?;
        let method = m.method.to_string();
        match (receiver, method.as_str(), args.as_slice()) {
            (Value::Pose { position, rotation }, "point", [Value::Vector(offset)]) => {
                Some(Value::Vector(point(position, &rotation, offset)?))
            }
            (Value::Pose { position, rotation }, "joint", [Value::Vector(offset), turn]) => {
                let turn = match turn {
                    Value::Rotation(r) => r.clone(),
                    angle => angle_factors(angle)?,
                };
                let joined = rotation.iter().cloned().chain(turn).collect();
                Some(Value::Pose {
                    position: point(position, &rotation, offset)?,
                    rotation: joined,
                })
            }
            (Value::Vector(v), "rotated", [angle]) => {
                Some(Value::Vector(rotate(&angle_factors(angle)?, &v)?))
            }
            (Value::Scalar(s), _, _) if args.iter().all(|a| matches!(a, Value::Scalar(_))) => {
                let args = args.iter().map(|a| match a {
                    Value::Scalar(s) => s.clone(),
                    _ => unreachable!(),
                });
                let method = &m.method;
                Some(Value::Scalar(quote!((#s).#method(#(#args),*))))
            }
            _ => None,
        }
    }

    fn field(&mut self, f: &syn::ExprField) -> Option<Value> {
        let syn::Member::Named(name) = &f.member else {
            return None;
        };
        match (self.expr(&f.base)?, name.to_string().as_str()) {
            (Value::Pose { position, .. }, "position") => Some(Value::Vector(position)),
            (Value::Pose { rotation, .. }, "rotation") => Some(Value::Rotation(rotation)),
            (Value::Pose { rotation, .. }, "angle") => Some(Value::Angle(rotation)),
            _ => None,
        }
    }

    fn binary(&mut self, b: &syn::ExprBinary) -> Option<Value> {
        let (l, r) = (self.expr(&b.left)?, self.expr(&b.right)?);
        use Value::*;
        match (b.op, l, r) {
            (op, Scalar(x), Scalar(y)) => {
                let op = op.to_token_stream();
                Some(Scalar(quote!((#x #op #y))))
            }
            (BinOp::Mul(_), Rotation(x), Rotation(y)) => {
                Some(Rotation(x.into_iter().chain(y).collect()))
            }
            (BinOp::Mul(_), Rotation(x), Vector(v)) => Some(Vector(rotate(&x, &v)?)),
            (BinOp::Mul(_), Vector(v), Scalar(s)) | (BinOp::Mul(_), Scalar(s), Vector(v)) => {
                Some(Vector(scale(&v, &s)?))
            }
            (BinOp::Div(_), Vector(v), Scalar(s)) => Some(Vector(scale(&v, &quote!((1.0 / #s)))?)),
            (BinOp::Add(_), Vector(x), Vector(y)) => Some(Vector(x.into_iter().chain(y).collect())),
            (BinOp::Sub(_), Vector(x), y @ Vector(_)) => match negate(y)? {
                Vector(y) => Some(Vector(x.into_iter().chain(y).collect())),
                _ => None,
            },
            (BinOp::Add(_), x, Scalar(c)) | (BinOp::Add(_), Scalar(c), x)
                if matches!(x, Coordinate(_) | Affine(..)) =>
            {
                shifted(x, &c)
            }
            (BinOp::Sub(_), x, Scalar(c)) if matches!(x, Coordinate(_) | Affine(..)) => {
                shifted(x, &quote!((-#c)))
            }
            (BinOp::Sub(_), Scalar(c), x) if matches!(x, Coordinate(_) | Affine(..)) => {
                shifted(negate(x)?, &c)
            }
            (BinOp::Add(_), x, y) => {
                let (x, y) = (angle_factors(&x)?, angle_factors(&y)?);
                Some(Angle(x.into_iter().chain(y).collect()))
            }
            _ => None,
        }
    }

    /// A tree node's value: a frame for a rigid body, a position for a particle or point.
    fn body_value(&self, node: usize) -> Value {
        let (body, _) = self.nodes[node];
        let position = vec![Term {
            rotation: Vec::new(),
            piece: Piece::Origin(node),
        }];
        match self.model.bodies[body].shape {
            crate::check::Shape::Planar | crate::check::Shape::Spatial => Value::Pose {
                position,
                rotation: vec![Factor::Body(node)],
            },
            _ => Value::Vector(position),
        }
    }

    /// The tree node of body `name` (its member `member`, for a family).
    fn node_of(&self, name: &str, member: Option<usize>) -> Option<usize> {
        let body = self
            .model
            .bodies
            .iter()
            .position(|b| b.decl.ident() == name)?;
        self.nodes
            .iter()
            .position(|&(b, m)| b == body && m == member)
    }

    fn scalar_coordinate(&self, name: &str) -> Option<usize> {
        let mut slot = 0;
        for c in self.model.coords {
            if c.ident == name {
                return c.array.is_none().then_some(slot);
            }
            slot += c.slots();
        }
        None
    }

    fn array_coordinate(&self, name: &str) -> Option<(usize, usize)> {
        let mut slot = 0;
        for c in self.model.coords {
            if c.ident == name {
                return c.array.as_ref().map(|(_, len)| (slot, *len));
            }
            slot += c.slots();
        }
        None
    }

    /// A parameter or an item of the module: a constant.
    fn is_constant_name(&self, name: &str) -> bool {
        self.model.params.iter().any(|p| p.ident == name)
            || self.model.mechanism.item_names.iter().any(|i| i == name)
    }
}

fn scalar(e: &Expr) -> Value {
    Value::Scalar(quote!((#e)))
}

/// `vec3(x, y, z)` of constants, or with one coordinate as a component (a slide).
fn vector(components: &[&Value]) -> Option<Value> {
    if let Some(v) = super::free::coordinates(components) {
        return Some(v);
    }
    let mut exprs = Vec::new();
    let mut slide = None;
    let mut zeros = [false; 3];
    for (k, c) in components.iter().enumerate() {
        match c {
            Value::Scalar(s) => {
                let text = s.to_string().replace(['(', ')', ' '], "");
                zeros[k] = matches!(text.as_str(), "0.0" | "0." | "-0.0");
                exprs.push(s.clone());
            }
            Value::Coordinate(slot) if slide.is_none() => {
                slide = Some(([Axis::X, Axis::Y, Axis::Z][k], *slot, false));
                exprs.push(quote!(0.0));
            }
            Value::Affine(c, slot, negative) if slide.is_none() => {
                slide = Some(([Axis::X, Axis::Y, Axis::Z][k], *slot, *negative));
                exprs.push(c.clone());
            }
            _ => return None,
        }
    }
    let constant = quote!(vec3(#(#exprs),*));
    let piece = match slide {
        None => Piece::Constant(constant, zeros),
        Some((axis, slot, negative)) => Piece::Slide(Some(constant), axis, slot, negative),
    };
    Some(Value::Vector(vec![Term {
        rotation: Vec::new(),
        piece,
    }]))
}

/// `rot_a(θ)`: constant, a coordinate (a joint), or a coordinate plus a constant (both: rotations
/// about one axis commute).
fn rotation_about(axis: Axis, angle: &Value) -> Option<Value> {
    let f = match axis {
        Axis::X => quote!(rot_x),
        Axis::Y => quote!(rot_y),
        Axis::Z => quote!(rot_z),
    };
    let factors = match angle {
        Value::Scalar(s) => vec![Factor::Constant(quote!(#f(#s)))],
        Value::Coordinate(slot) => vec![Factor::Joint(axis, *slot)],
        // rot_a(c ± q) = rot_a(c) rot_a(±q), and rot_a(−q) = F rot_a(q) Fᵀ for F a half turn
        // about an axis across a.
        Value::Affine(c, slot, negative) => {
            let mut out = vec![Factor::Constant(quote!(#f(#c)))];
            let flip = flip(axis);
            if *negative {
                out.push(Factor::Constant(flip.clone()));
            }
            out.push(Factor::Joint(axis, *slot));
            if *negative {
                out.push(Factor::Constant(flip));
            }
            out
        }
        Value::Angle(parts) => {
            // Constants and one coordinate, as a planar angle sums them.
            let mut out = Vec::new();
            for part in parts {
                match part {
                    Factor::Constant(c) if axis == Axis::Z => out.push(Factor::Constant(c.clone())),
                    Factor::Joint(Axis::Z, slot) => out.push(Factor::Joint(axis, *slot)),
                    _ => return None,
                }
            }
            out
        }
        _ => return None,
    };
    Some(Value::Rotation(factors))
}

/// A half turn about an axis across `axis` (its own transpose): it maps `axis` to its opposite.
pub fn flip(axis: Axis) -> TokenStream {
    let a = match axis {
        Axis::X => quote!(::lagrange::__private::tree::rigid::spatial::Axis::X),
        Axis::Y => quote!(::lagrange::__private::tree::rigid::spatial::Axis::Y),
        Axis::Z => quote!(::lagrange::__private::tree::rigid::spatial::Axis::Z),
    };
    quote!(::lagrange::__private::tree::rigid::flip(#a))
}

/// ±q + c plus a constant.
fn shifted(x: Value, c: &TokenStream) -> Option<Value> {
    match x {
        Value::Coordinate(slot) => Some(Value::Affine(c.clone(), slot, false)),
        Value::Affine(d, slot, negative) => Some(Value::Affine(quote!((#d + #c)), slot, negative)),
        _ => None,
    }
}

/// `rot_axis(a, θ)` about a constant axis a: by a coordinate, a frame whose z axis is a, the joint
/// about z, and the frame back.
fn rotation_about_axis(axis: &Value, angle: &Value) -> Option<Value> {
    let Value::Vector(terms) = axis else {
        return None;
    };
    let [Term {
        rotation,
        piece: Piece::Constant(a, _),
    }] = terms.as_slice()
    else {
        return None;
    };
    if !rotation.is_empty() {
        return None;
    }
    match angle {
        Value::Scalar(s) => Some(Value::Rotation(vec![Factor::Constant(
            quote!(rot_axis(#a, #s)),
        )])),
        Value::Coordinate(slot) => {
            let frame = quote!(::lagrange::__private::tree::rigid::axis_frame(#a));
            Some(Value::Rotation(vec![
                Factor::Constant(frame.clone()),
                Factor::Joint(Axis::Z, *slot),
                Factor::Constant(quote!(#frame.transpose())),
            ]))
        }
        _ => None,
    }
}

/// A planar angle's factors: a body's angle, constants (rotations about z), one coordinate.
fn angle_factors(angle: &Value) -> Option<Vec<Factor>> {
    match angle {
        Value::Angle(f) => Some(f.clone()),
        Value::Scalar(s) => Some(vec![Factor::Constant(quote!(rot_z(#s)))]),
        Value::Coordinate(slot) => Some(vec![Factor::Joint(Axis::Z, *slot)]),
        Value::Affine(..) => match rotation_about(Axis::Z, angle)? {
            Value::Rotation(factors) => Some(factors),
            _ => None,
        },
        _ => None,
    }
}

/// `pose.point(offset)`: the pose's position plus its rotation applied to the offset.
fn point(position: Vec<Term>, rotation: &[Factor], offset: &[Term]) -> Option<Vec<Term>> {
    Some(
        position
            .into_iter()
            .chain(rotate(rotation, offset)?)
            .collect(),
    )
}

/// R v: the factors prepended to every term (an unrotated body position cannot be rotated).
fn rotate(rotation: &[Factor], v: &[Term]) -> Option<Vec<Term>> {
    v.iter()
        .map(|t| match t.piece {
            Piece::Origin(_) => None,
            _ => Some(Term {
                rotation: rotation.iter().cloned().chain(t.rotation.clone()).collect(),
                piece: t.piece.clone(),
            }),
        })
        .collect()
}

/// v s for a constant s (constant pieces only).
fn scale(v: &[Term], s: &TokenStream) -> Option<Vec<Term>> {
    v.iter()
        .map(|t| match &t.piece {
            Piece::Constant(c, zeros) => Some(Term {
                rotation: t.rotation.clone(),
                piece: Piece::Constant(quote!((#c * #s)), *zeros),
            }),
            _ => None,
        })
        .collect()
}

fn negate(v: Value) -> Option<Value> {
    match v {
        Value::Scalar(s) => Some(Value::Scalar(quote!((-#s)))),
        Value::Coordinate(slot) => Some(Value::Affine(quote!(0.0), slot, true)),
        Value::Affine(c, slot, negative) => Some(Value::Affine(quote!((-#c)), slot, !negative)),
        Value::Vector(terms) => Some(Value::Vector(scale(&terms, &quote!((-1.0)))?)),
        _ => None,
    }
}
