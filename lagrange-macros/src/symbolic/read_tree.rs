//! A potential's block read as an expression tree ([`super::expr`]), as written.
//!
//! The forms read: numeric literals; coordinates, and elements of array coordinates at integer
//! literals (`q[2]`); bodies and points, as the rows of x they occupy (members of a family at
//! integer literals, `mass[1]`); time; `let`s binding a name; sums, differences, products,
//! quotients and negations of scalars, of vectors (a vector times or divided by a scalar); the
//! methods `sin`, `cos`, `exp`, `ln`, `sqrt`, `recip`, `powi` (an integer literal), `norm`,
//! `norm_squared`, `dot`, `rotated` (of a `Vec2`) and `point` (of a planar body); the fields `x`, `y`, `z`, `position`, `angle`; `vec2`, `vec3` and
//! `planar`. An expression that names no coordinate, body, local or `t` is a constant as
//! written (a parameter, `alpha.cos()`, `PI`), evaluated in `f64`. Anything else (a spatial
//! body, `abs`, `powf`, a branch, a macro, a call of a function) is not read: the potential keeps
//! its dual numbers.

use super::expr::{Graph, Id, Node, TokenStream2};
use super::read::{constructor, number};
use crate::check::{Model, Shape};
use proc_macro2::TokenTree;
use quote::{quote, ToTokens};
use std::collections::HashMap;
use syn::{BinOp, Block, Expr, Lit, Pat, Stmt, UnOp};

/// The value of an expression: a scalar, a 2- or 3-vector, a planar pose, or a family of them.
#[derive(Clone, Debug)]
enum Value {
    Scalar(Id),
    Vector(Vec<Id>),
    /// Centre of mass and angle.
    Planar(Vec<Id>, Id),
    Family(Vec<Value>),
}

/// The names a potential sees, and the graph it is read into.
pub struct Reader<'g> {
    graph: &'g mut Graph,
    coords: HashMap<String, usize>,
    /// First slot and length.
    arrays: HashMap<String, (usize, usize)>,
    /// Bodies as the rows they occupy; `None` for a body not read (a spatial body, a body declared
    /// by its frame).
    bodies: HashMap<String, Option<Value>>,
    locals: Vec<HashMap<String, Value>>,
}

impl<'g> Reader<'g> {
    /// A reader of the potentials of `model` into `graph`.
    pub fn new(model: &Model, graph: &'g mut Graph) -> Self {
        let (coords, arrays) = super::coordinate_slots(model);
        let mut bodies = HashMap::new();
        for body in &model.bodies {
            // A body declared by its frame has its centre of mass in x, not the pose its
            // function returns: not read.
            if body.is_framed() {
                bodies.insert(body.decl.ident().to_string(), None);
                continue;
            }
            let stride = body.shape.rows();
            let member = |graph: &mut Graph, first: usize| {
                let mut row = |k: usize| graph.node(Node::Row(first + k));
                match body.shape {
                    Shape::Particle(_) | Shape::Point(_) => {
                        Some(Value::Vector((0..stride).map(&mut row).collect()))
                    }
                    Shape::Planar => Some(Value::Planar(vec![row(0), row(1)], row(2))),
                    Shape::Spatial => None,
                }
            };
            let value = match body.count {
                None => member(graph, body.row),
                Some(n) => (0..n)
                    .map(|k| member(graph, body.row + k * stride))
                    .collect::<Option<Vec<_>>>()
                    .map(Value::Family),
            };
            bodies.insert(body.decl.ident().to_string(), value);
        }
        let mut reader = Reader {
            graph,
            coords,
            arrays,
            bodies,
            locals: Vec::new(),
        };
        for body in model.bodies.iter().filter(|b| b.count.is_none()) {
            reader.substitute(&body.decl.ident().to_string(), &body.decl.block);
        }
        reader
    }

    /// A body's rows written as a coordinate or a constant (`vec2(x, y)`, `vec2(q[i], 0.0)`) read
    /// as that coordinate or constant: equal to the row of x, with a unit or zero row of J, so its
    /// derivative goes straight to the coordinate's slot. Other rows stay rows of x.
    fn substitute(&mut self, name: &str, block: &Block) {
        let (Some(Some(rows)), Some(written)) = (self.bodies.get(name).cloned(), self.block(block))
        else {
            return;
        };
        let g = &*self.graph;
        let pick = |row: &Id, written: &Id| {
            if g.is_coordinate_or_constant(*written) {
                *written
            } else {
                *row
            }
        };
        let pick_all = |rows: &[Id], written: &[Id]| -> Vec<Id> {
            rows.iter().zip(written).map(|(r, w)| pick(r, w)).collect()
        };
        let value = match (rows, written) {
            (Value::Vector(rows), Value::Vector(written)) if rows.len() == written.len() => {
                Value::Vector(pick_all(&rows, &written))
            }
            (Value::Planar(rows, angle), Value::Planar(written, written_angle)) => {
                Value::Planar(pick_all(&rows, &written), pick(&angle, &written_angle))
            }
            _ => return,
        };
        self.bodies.insert(name.to_string(), Some(value));
    }

    /// The scalar value of a potential's block, or `None` when it is not of the forms read.
    pub fn potential(&mut self, block: &Block) -> Option<Id> {
        match self.block(block)? {
            Value::Scalar(v) => Some(v),
            _ => None,
        }
    }

    fn block(&mut self, block: &Block) -> Option<Value> {
        self.locals.push(HashMap::new());
        let value = self.statements(block);
        self.locals.pop();
        value
    }

    fn statements(&mut self, block: &Block) -> Option<Value> {
        let (last, lets) = block.stmts.split_last()?;
        for stmt in lets {
            let Stmt::Local(local) = stmt else {
                return None;
            };
            let init = local.init.as_ref().filter(|i| i.diverge.is_none())?;
            let pat = match &local.pat {
                Pat::Type(typed) => &*typed.pat,
                other => other,
            };
            let bindings: Vec<(String, Value)> = match pat {
                Pat::Ident(ident) if ident.subpat.is_none() => {
                    vec![(ident.ident.to_string(), self.expr(&init.expr)?)]
                }
                // `let (a, b) = (x, y);`
                Pat::Tuple(tuple) => {
                    let Expr::Tuple(values) = &*init.expr else {
                        return None;
                    };
                    if values.elems.len() != tuple.elems.len() {
                        return None;
                    }
                    let mut out = Vec::new();
                    for (pat, value) in tuple.elems.iter().zip(&values.elems) {
                        let Pat::Ident(ident) = pat else { return None };
                        out.push((ident.ident.to_string(), self.expr(value)?));
                    }
                    out
                }
                _ => return None,
            };
            let scope = self.locals.last_mut().expect("a block pushes its scope");
            scope.extend(bindings);
        }
        match last {
            Stmt::Expr(expr, None) => self.expr(expr),
            _ => None,
        }
    }

    fn local(&self, name: &str) -> Option<&Value> {
        self.locals.iter().rev().find_map(|scope| scope.get(name))
    }

    fn expr(&mut self, expr: &Expr) -> Option<Value> {
        match expr {
            Expr::Lit(lit) => Some(Value::Scalar(self.graph.literal(number(&lit.lit)?))),
            Expr::Paren(e) => self.expr(&e.expr),
            Expr::Group(e) => self.expr(&e.expr),
            Expr::Reference(r) if r.mutability.is_none() => self.expr(&r.expr),
            Expr::Block(block) if block.label.is_none() => self.block(&block.block),
            Expr::Path(path) if path.qself.is_none() && path.path.get_ident().is_some() => {
                self.name(&path.path.get_ident()?.to_string(), expr)
            }
            Expr::Unary(unary) if matches!(unary.op, UnOp::Neg(_)) => {
                let value = self.expr(&unary.expr)?;
                map(value, &mut |a| self.graph.neg(a))
            }
            Expr::Binary(binary) => {
                let lhs = self.expr(&binary.left)?;
                let rhs = self.expr(&binary.right)?;
                self.binary(&binary.op, lhs, rhs)
            }
            Expr::Call(call) => match constructor(&call.func) {
                Some(name) => {
                    let args = call
                        .args
                        .iter()
                        .map(|a| self.expr(a))
                        .collect::<Option<Vec<_>>>()?;
                    construct(name, args)
                }
                None => self.constant(expr),
            },
            Expr::MethodCall(call) => match self.method(call) {
                Some(value) => Some(value),
                None => self.constant(expr),
            },
            Expr::Field(field) => self.field(field),
            Expr::Index(index) => match self.element(index) {
                Some(value) => Some(value),
                None => self.constant(expr),
            },
            _ => self.constant(expr),
        }
    }

    /// A local, time, a coordinate, a body, or a constant (a parameter, a constant of the module).
    fn name(&mut self, name: &str, expr: &Expr) -> Option<Value> {
        if let Some(value) = self.local(name) {
            return Some(value.clone());
        }
        if name == "t" {
            return Some(Value::Scalar(self.graph.node(Node::Time)));
        }
        if let Some(&j) = self.coords.get(name) {
            return Some(Value::Scalar(self.graph.node(Node::Coordinate(j))));
        }
        if let Some(body) = self.bodies.get(name) {
            return body.clone();
        }
        self.constant(expr)
    }

    fn binary(&mut self, op: &BinOp, lhs: Value, rhs: Value) -> Option<Value> {
        use Value::{Scalar, Vector};
        let g = &mut *self.graph;
        match (op, lhs, rhs) {
            (BinOp::Add(_), Scalar(a), Scalar(b)) => Some(Scalar(g.add(a, b))),
            (BinOp::Sub(_), Scalar(a), Scalar(b)) => Some(Scalar(g.sub(a, b))),
            (BinOp::Mul(_), Scalar(a), Scalar(b)) => Some(Scalar(g.mul(a, b))),
            (BinOp::Div(_), Scalar(a), Scalar(b)) => Some(Scalar(g.div(a, b))),
            (BinOp::Add(_), Vector(a), Vector(b)) if a.len() == b.len() => Some(Vector(
                a.iter().zip(&b).map(|(&a, &b)| g.add(a, b)).collect(),
            )),
            (BinOp::Sub(_), Vector(a), Vector(b)) if a.len() == b.len() => Some(Vector(
                a.iter().zip(&b).map(|(&a, &b)| g.sub(a, b)).collect(),
            )),
            // Component by component, the scalar on the side it is written.
            (BinOp::Mul(_), Vector(v), Scalar(s)) => {
                Some(Vector(v.iter().map(|&c| g.mul(c, s)).collect()))
            }
            (BinOp::Mul(_), Scalar(s), Vector(v)) => {
                Some(Vector(v.iter().map(|&c| g.mul(s, c)).collect()))
            }
            (BinOp::Div(_), Vector(v), Scalar(s)) => {
                Some(Vector(v.iter().map(|&c| g.div(c, s)).collect()))
            }
            _ => None,
        }
    }

    /// `sin`, `cos`, `exp`, `ln`, `sqrt`, `recip`, `powi(n)` of a scalar; `norm`, `norm_squared`
    /// and `dot` of vectors, as `lagrange_core::geometry` computes them.
    fn method(&mut self, call: &syn::ExprMethodCall) -> Option<Value> {
        let name = call.method.to_string();
        let receiver = self.expr(&call.receiver)?;
        let args = call
            .args
            .iter()
            .map(|a| self.expr(a))
            .collect::<Option<Vec<_>>>();
        let g = &mut *self.graph;
        let scalar = match (name.as_str(), receiver, call.args.len()) {
            ("sin", Value::Scalar(a), 0) => g.node(Node::Sin(a)),
            ("cos", Value::Scalar(a), 0) => g.node(Node::Cos(a)),
            ("exp", Value::Scalar(a), 0) => g.node(Node::Exp(a)),
            ("ln", Value::Scalar(a), 0) => g.node(Node::Ln(a)),
            ("sqrt", Value::Scalar(a), 0) => g.node(Node::Sqrt(a)),
            ("recip", Value::Scalar(a), 0) => {
                let one = g.literal(1.0);
                g.div(one, a)
            }
            ("powi", Value::Scalar(a), 1) => g.powi(a, integer(&call.args[0])?),
            ("norm_squared", Value::Vector(v), 0) => dot(g, &v, &v),
            ("norm", Value::Vector(v), 0) => {
                let squared = dot(g, &v, &v);
                g.node(Node::Sqrt(squared))
            }
            ("dot", Value::Vector(a), 1) => match args?.pop()? {
                Value::Vector(b) if b.len() == a.len() => dot(g, &a, &b),
                _ => return None,
            },
            ("rotated", Value::Vector(v), 1) if v.len() == 2 => match args?.pop()? {
                Value::Scalar(angle) => return Some(Value::Vector(rotated(g, &v, angle))),
                _ => return None,
            },
            // A planar body's point at a body-frame offset: position + offset rotated by the angle.
            ("point", Value::Planar(position, angle), 1) => match args?.pop()? {
                Value::Vector(offset) if offset.len() == 2 => {
                    let turned = rotated(g, &offset, angle);
                    let point = position
                        .iter()
                        .zip(&turned)
                        .map(|(&p, &r)| g.add(p, r))
                        .collect();
                    return Some(Value::Vector(point));
                }
                _ => return None,
            },
            _ => return None,
        };
        Some(Value::Scalar(scalar))
    }

    /// `v.x`, `v.y`, `v.z`, `pose.position`, `pose.angle`.
    fn field(&mut self, field: &syn::ExprField) -> Option<Value> {
        let syn::Member::Named(member) = &field.member else {
            return None;
        };
        match (self.expr(&field.base)?, member.to_string().as_str()) {
            (Value::Vector(v), "x") => v.first().copied().map(Value::Scalar),
            (Value::Vector(v), "y") => v.get(1).copied().map(Value::Scalar),
            (Value::Vector(v), "z") => v.get(2).copied().map(Value::Scalar),
            (Value::Planar(position, _), "position") => Some(Value::Vector(position)),
            (Value::Planar(_, angle), "angle") => Some(Value::Scalar(angle)),
            _ => None,
        }
    }

    /// `q[k]` of an array coordinate, `bob[k]` of a family, at an integer literal in range.
    fn element(&mut self, index: &syn::ExprIndex) -> Option<Value> {
        let Expr::Path(path) = &*index.expr else {
            return None;
        };
        let name = path.path.get_ident()?.to_string();
        let k = usize::try_from(integer(&index.index)?).ok()?;
        if self.local(&name).is_some() {
            return None;
        }
        if let Some(&(first, len)) = self.arrays.get(&name) {
            return (k < len).then(|| Value::Scalar(self.graph.node(Node::Coordinate(first + k))));
        }
        match self.bodies.get(&name)? {
            Some(Value::Family(members)) => members.get(k).cloned(),
            _ => None,
        }
    }

    /// An expression that names no coordinate, body, local or `t`: a constant as written, its
    /// literals lifted to `f64` as the dual-number path lifts them to its scalar.
    fn constant(&mut self, expr: &Expr) -> Option<Value> {
        let tokens = expr.to_token_stream();
        if !self.names_only_constants(tokens.clone()) {
            return None;
        }
        // A name (a parameter) as it is; anything else lifted.
        if let Expr::Path(path) = expr {
            if path.path.get_ident().is_some() {
                let node = Node::Constant(TokenStream2::new(tokens));
                return Some(Value::Scalar(self.graph.node(node)));
            }
        }
        let block: Block = syn::parse_quote!({ #expr });
        let lifted = crate::lift::lift_block(&block, &quote!(f64));
        let node = Node::Constant(TokenStream2::new(lifted.to_token_stream()));
        Some(Value::Scalar(self.graph.node(node)))
    }

    fn names_only_constants(&self, tokens: proc_macro2::TokenStream) -> bool {
        tokens.into_iter().all(|tree| match tree {
            TokenTree::Ident(ident) => {
                let name = ident.to_string();
                name != "t"
                    && name != "self"
                    && !self.coords.contains_key(&name)
                    && !self.arrays.contains_key(&name)
                    && !self.bodies.contains_key(&name)
                    && self.local(&name).is_none()
            }
            TokenTree::Group(group) => self.names_only_constants(group.stream()),
            // A macro's tokens are not read.
            TokenTree::Punct(p) => p.as_char() != '!',
            TokenTree::Literal(_) => true,
        })
    }
}

/// Σ aᵢ bᵢ, left to right as `geometry::Vec2::dot` and `Vec3::dot` sum.
fn dot(g: &mut Graph, a: &[Id], b: &[Id]) -> Id {
    let mut terms = a
        .iter()
        .zip(b)
        .map(|(&a, &b)| g.mul(a, b))
        .collect::<Vec<_>>();
    let first = terms.remove(0);
    terms.into_iter().fold(first, |sum, term| g.add(sum, term))
}

/// (c x − s y, s x + c y), c = cos θ, s = sin θ: `geometry::Vec2::rotated` as it computes it.
fn rotated(g: &mut Graph, v: &[Id], angle: Id) -> Vec<Id> {
    let (sin, cos) = (g.node(Node::Sin(angle)), g.node(Node::Cos(angle)));
    let (cx, sy) = (g.mul(cos, v[0]), g.mul(sin, v[1]));
    let (sx, cy) = (g.mul(sin, v[0]), g.mul(cos, v[1]));
    vec![g.sub(cx, sy), g.add(sx, cy)]
}

/// An integer literal, possibly negated.
fn integer(expr: &Expr) -> Option<i32> {
    match expr {
        Expr::Lit(syn::ExprLit {
            lit: Lit::Int(i), ..
        }) => i.base10_parse().ok(),
        Expr::Unary(u) if matches!(u.op, UnOp::Neg(_)) => integer(&u.expr).map(|n| -n),
        Expr::Paren(p) => integer(&p.expr),
        _ => None,
    }
}

fn construct(name: &str, args: Vec<Value>) -> Option<Value> {
    let scalars = |args: Vec<Value>| {
        args.into_iter()
            .map(|a| match a {
                Value::Scalar(s) => Some(s),
                _ => None,
            })
            .collect::<Option<Vec<_>>>()
    };
    match (name, args.len()) {
        ("vec2", 2) | ("vec3", 3) => Some(Value::Vector(scalars(args)?)),
        ("planar", 2) => {
            let mut args = args.into_iter();
            match (args.next()?, args.next()?) {
                (Value::Vector(position), Value::Scalar(angle)) if position.len() == 2 => {
                    Some(Value::Planar(position, angle))
                }
                _ => None,
            }
        }
        _ => None,
    }
}

/// The value with `f` applied to each component.
fn map(value: Value, f: &mut impl FnMut(Id) -> Id) -> Option<Value> {
    Some(match value {
        Value::Scalar(a) => Value::Scalar(f(a)),
        Value::Vector(v) => Value::Vector(v.into_iter().map(&mut *f).collect()),
        Value::Planar(v, a) => Value::Planar(v.into_iter().map(&mut *f).collect(), f(a)),
        Value::Family(_) => return None,
    })
}
