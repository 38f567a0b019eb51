//! A position function's block read as polynomials over the atoms of [`super::poly`].
//!
//! The forms read: numeric literals, coordinates, parameters, earlier bodies and `let`s, sums,
//! differences, negation, products, quotients by one monomial in constants and coordinates, `powi` with a literal
//! exponent, `sin`/`cos` of an integer combination of coordinates (expanded by the angle-sum
//! formulas, so sin(θ₁ − θ₂) = sin θ₁ cos θ₂ − cos θ₁ sin θ₂), the vector constructors `vec2`,
//! `vec3`, `planar`, the fields `x`, `y`, `z`, `position`, `angle`, a planar pose's `point` and
//! `joint` (its angle an integer combination of coordinates), and an element of an array
//! coordinate at an integer literal (`theta[1]`). Any other expression is
//! read as an opaque constant when it names no coordinate, body, local or `t` (`alpha.cos()`,
//! `std::f64::consts::PI`), and otherwise not at all: the declaration then keeps the dual-number
//! path.

use super::poly::{Atom, Poly};
use proc_macro2::{TokenStream, TokenTree};
use quote::ToTokens;
use std::collections::HashMap;
use syn::{BinOp, Block, Expr, Lit, Pat, Stmt, UnOp};

/// The value of an expression: a scalar, a 2- or 3-vector, or a planar pose.
#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    Scalar(Poly),
    Vector(Vec<Poly>),
    /// Centre of mass (x, y) and angle.
    Planar(Vec<Poly>, Poly),
}

/// The names in scope and the constants met so far.
pub struct Reader {
    /// Scalar coordinates, by slot in q.
    coords: HashMap<String, usize>,
    /// Array coordinates: first slot and length (`theta[1]` with a literal index is a coordinate).
    arrays: HashMap<String, (usize, usize)>,
    params: HashMap<String, usize>,
    bodies: HashMap<String, Value>,
    locals: Vec<HashMap<String, Value>>,
    /// Opaque constant subexpressions, as written (their tokens name parameters and constants).
    pub constants: Vec<TokenStream>,
}

/// At most this many terms in any polynomial read: beyond it the dual-number path is kept.
const MAX_VALUE_TERMS: usize = 256;

impl Reader {
    pub fn new(
        coords: HashMap<String, usize>,
        arrays: HashMap<String, (usize, usize)>,
        params: HashMap<String, usize>,
    ) -> Self {
        Reader {
            coords,
            arrays,
            params,
            bodies: HashMap::new(),
            locals: Vec::new(),
            constants: Vec::new(),
        }
    }

    /// Makes `name` (an earlier body) readable by later bodies.
    pub fn define_body(&mut self, name: String, value: Value) {
        self.bodies.insert(name, value);
    }

    /// The value of a function body's block.
    pub fn block(&mut self, block: &Block) -> Option<Value> {
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
            let pat = match &local.pat {
                Pat::Type(typed) => &*typed.pat,
                other => other,
            };
            let Pat::Ident(ident) = pat else { return None };
            let init = local.init.as_ref().filter(|i| i.diverge.is_none())?;
            let value = self.expr(&init.expr)?;
            self.locals
                .last_mut()
                .expect("a block pushes its scope")
                .insert(ident.ident.to_string(), value);
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
        let value = match expr {
            Expr::Lit(lit) => Value::Scalar(Poly::number(number(&lit.lit)?)),
            Expr::Paren(e) => self.expr(&e.expr)?,
            Expr::Group(e) => self.expr(&e.expr)?,
            Expr::Block(block) if block.label.is_none() => self.block(&block.block)?,
            Expr::Path(path) if path.qself.is_none() && path.path.get_ident().is_some() => {
                self.name(&path.path.get_ident()?.to_string(), expr)?
            }
            Expr::Unary(unary) if matches!(unary.op, UnOp::Neg(_)) => {
                map(&self.expr(&unary.expr)?, |p| p.scale(-1.0))
            }
            Expr::Binary(binary) => {
                let lhs = self.expr(&binary.left)?;
                let rhs = self.expr(&binary.right)?;
                binary_op(&binary.op, lhs, rhs)?
            }
            Expr::Call(call) => match constructor(&call.func) {
                Some(name) => {
                    let args = call
                        .args
                        .iter()
                        .map(|a| self.expr(a))
                        .collect::<Option<Vec<_>>>()?;
                    construct(name, args)?
                }
                None => self.constant(expr)?,
            },
            Expr::MethodCall(call) => match self.method(call) {
                Some(value) => value,
                None => self.constant(expr)?,
            },
            Expr::Field(field) => match self.field(field) {
                Some(value) => value,
                None => self.constant(expr)?,
            },
            Expr::Index(index) => match self.element(index) {
                Some(j) => Value::Scalar(Poly::atom(Atom::Coord(j))),
                None => self.constant(expr)?,
            },
            _ => self.constant(expr)?,
        };
        let size = match &value {
            Value::Scalar(p) => p.terms.len(),
            Value::Vector(ps) => ps.iter().map(|p| p.terms.len()).sum(),
            Value::Planar(ps, a) => ps.iter().map(|p| p.terms.len()).sum::<usize>() + a.terms.len(),
        };
        (size <= MAX_VALUE_TERMS).then_some(value)
    }

    /// A name: a local, a coordinate, a body, a parameter, or a constant of the module.
    fn name(&mut self, name: &str, expr: &Expr) -> Option<Value> {
        if let Some(value) = self.local(name) {
            return Some(value.clone());
        }
        if let Some(&j) = self.coords.get(name) {
            return Some(Value::Scalar(Poly::atom(Atom::Coord(j))));
        }
        if let Some(value) = self.bodies.get(name) {
            return Some(value.clone());
        }
        if let Some(&i) = self.params.get(name) {
            return Some(Value::Scalar(Poly::atom(Atom::Param(i))));
        }
        self.constant(expr)
    }

    /// The centre of mass of a planar body whose frame is `frame` and whose `com` is written
    /// `com`: `planar(frame.point(com), frame.angle)`.
    pub fn centre_of_mass(&mut self, frame: &Value, com: &Expr) -> Option<Value> {
        let Value::Planar(position, angle) = frame else {
            return None;
        };
        let Value::Vector(offset) = self.expr(com)? else {
            return None;
        };
        Some(Value::Planar(
            planar_point(position, angle, &offset)?,
            angle.clone(),
        ))
    }

    /// `pose.point(offset)` and `pose.joint(origin, angle)` of a planar pose.
    fn pose_method(&mut self, call: &syn::ExprMethodCall) -> Option<Value> {
        let Value::Planar(position, angle) = self.expr(&call.receiver)? else {
            return None;
        };
        let args = call
            .args
            .iter()
            .map(|a| self.expr(a))
            .collect::<Option<Vec<_>>>()?;
        match (call.method.to_string().as_str(), &args[..]) {
            ("point", [Value::Vector(offset)]) => {
                Some(Value::Vector(planar_point(&position, &angle, offset)?))
            }
            ("joint", [Value::Vector(origin), Value::Scalar(turn)]) => Some(Value::Planar(
                planar_point(&position, &angle, origin)?,
                angle.add(turn),
            )),
            _ => None,
        }
    }

    /// `receiver.sin()`, `.cos()`, `.powi(n)`; `.point(..)` and `.joint(..)` of a planar pose.
    fn method(&mut self, call: &syn::ExprMethodCall) -> Option<Value> {
        let method = call.method.to_string();
        if matches!(method.as_str(), "point" | "joint") {
            return self.pose_method(call);
        }
        if !matches!(method.as_str(), "sin" | "cos" | "powi") {
            return None;
        }
        let Value::Scalar(receiver) = self.expr(&call.receiver)? else {
            return None;
        };
        if receiver.is_constant() {
            // `alpha.cos()` of a parameter: a constant as written.
            return None;
        }
        match (method.as_str(), call.args.len()) {
            ("sin", 0) => Some(Value::Scalar(sin_cos(&receiver)?.0)),
            ("cos", 0) => Some(Value::Scalar(sin_cos(&receiver)?.1)),
            ("powi", 1) => {
                let Expr::Lit(lit) = &call.args[0] else {
                    return None;
                };
                let Lit::Int(n) = &lit.lit else { return None };
                let n: u32 = n.base10_parse().ok().filter(|&n| n <= 8)?;
                let mut power = Poly::number(1.0);
                for _ in 0..n {
                    power = power.mul(&receiver);
                }
                Some(Value::Scalar(power))
            }
            _ => None,
        }
    }

    /// The slot of `theta[k]`: an array coordinate indexed by an integer literal in range.
    fn element(&self, index: &syn::ExprIndex) -> Option<usize> {
        let Expr::Path(path) = &*index.expr else {
            return None;
        };
        let &(first, len) = self.arrays.get(&path.path.get_ident()?.to_string())?;
        let Expr::Lit(syn::ExprLit {
            lit: Lit::Int(k), ..
        }) = &*index.index
        else {
            return None;
        };
        let k: usize = k.base10_parse().ok().filter(|&k| k < len)?;
        Some(first + k)
    }

    /// `v.x`, `v.y`, `v.z`, `pose.position`, `pose.angle`.
    fn field(&mut self, field: &syn::ExprField) -> Option<Value> {
        let syn::Member::Named(member) = &field.member else {
            return None;
        };
        let base = self.expr(&field.base)?;
        let member = member.to_string();
        match (base, member.as_str()) {
            (Value::Vector(v), "x") => v.first().cloned().map(Value::Scalar),
            (Value::Vector(v), "y") => v.get(1).cloned().map(Value::Scalar),
            (Value::Vector(v), "z") => v.get(2).cloned().map(Value::Scalar),
            (Value::Planar(position, _), "position") => Some(Value::Vector(position)),
            (Value::Planar(_, angle), "angle") => Some(Value::Scalar(angle)),
            _ => None,
        }
    }

    /// An expression that names no coordinate, body, local or `t`, as an opaque scalar constant.
    fn constant(&mut self, expr: &Expr) -> Option<Value> {
        let tokens = expr.to_token_stream();
        if !self.names_only_constants(tokens.clone()) {
            return None;
        }
        let key = tokens.to_string();
        let index = match self.constants.iter().position(|c| c.to_string() == key) {
            Some(index) => index,
            None => {
                self.constants.push(tokens);
                self.constants.len() - 1
            }
        };
        Some(Value::Scalar(Poly::atom(Atom::Constant(index))))
    }

    fn names_only_constants(&self, tokens: TokenStream) -> bool {
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
            _ => true,
        })
    }
}

/// A float or integer literal's value (shared with `read_tree`).
pub(super) fn number(lit: &Lit) -> Option<f64> {
    match lit {
        Lit::Float(f) => f.base10_parse().ok(),
        Lit::Int(i) => i.base10_parse().ok(),
        _ => None,
    }
}

/// `vec2`, `vec3` or `planar` when `func` names one (shared with `read_tree`).
pub(super) fn constructor(func: &Expr) -> Option<&'static str> {
    let Expr::Path(path) = func else { return None };
    let ident = path.path.get_ident()?;
    ["vec2", "vec3", "planar"]
        .into_iter()
        .find(|name| ident == name)
}

fn construct(name: &str, args: Vec<Value>) -> Option<Value> {
    let scalars = |args: Vec<Value>| {
        args.into_iter()
            .map(|a| match a {
                Value::Scalar(p) => Some(p),
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

/// The value with `f` applied to each component (vectors and poses componentwise).
fn map(value: &Value, f: impl Fn(&Poly) -> Poly) -> Value {
    match value {
        Value::Scalar(p) => Value::Scalar(f(p)),
        Value::Vector(v) => Value::Vector(v.iter().map(&f).collect()),
        Value::Planar(v, a) => Value::Planar(v.iter().map(&f).collect(), f(a)),
    }
}

fn binary_op(op: &BinOp, lhs: Value, rhs: Value) -> Option<Value> {
    use Value::{Scalar, Vector};
    match (op, lhs, rhs) {
        (BinOp::Add(_), Scalar(a), Scalar(b)) => Some(Scalar(a.add(&b))),
        (BinOp::Sub(_), Scalar(a), Scalar(b)) => Some(Scalar(a.sub(&b))),
        (BinOp::Add(_), Vector(a), Vector(b)) if a.len() == b.len() => {
            Some(Vector(a.iter().zip(&b).map(|(a, b)| a.add(b)).collect()))
        }
        (BinOp::Sub(_), Vector(a), Vector(b)) if a.len() == b.len() => {
            Some(Vector(a.iter().zip(&b).map(|(a, b)| a.sub(b)).collect()))
        }
        (BinOp::Mul(_), Scalar(s), v) | (BinOp::Mul(_), v @ Vector(_), Scalar(s)) => {
            Some(map(&v, |p| p.mul(&s)))
        }
        (BinOp::Div(_), v, Scalar(s)) if !matches!(v, Value::Planar(..)) => {
            let inverse = s.reciprocal()?;
            Some(map(&v, |p| p.mul(&inverse)))
        }
        _ => None,
    }
}

/// `position + offset` turned by `angle`: (x + c oₓ − s o_y, y + s oₓ + c o_y), with (s, c) of the
/// angle by [`sin_cos`] (`Planar::point`).
fn planar_point(position: &[Poly], angle: &Poly, offset: &[Poly]) -> Option<Vec<Poly>> {
    let ([x, y], [ox, oy]) = (position, offset) else {
        return None;
    };
    let (s, c) = sin_cos(angle)?;
    Some(vec![
        x.add(&c.mul(ox)).sub(&s.mul(oy)),
        y.add(&s.mul(ox)).add(&c.mul(oy)),
    ])
}

/// (sin φ, cos φ) of φ = Σ kⱼ qⱼ with integer kⱼ, by sin(a + b) = sin a cos b + cos a sin b and
/// cos(a + b) = cos a cos b − sin a sin b, one qⱼ at a time.
fn sin_cos(angle: &Poly) -> Option<(Poly, Poly)> {
    let (mut sin, mut cos) = (Poly::zero(), Poly::number(1.0));
    for (monomial, &k) in &angle.terms {
        let [(Atom::Coord(j), 1)] = monomial[..] else {
            return None;
        };
        if k.fract() != 0.0 || k.abs() > 4.0 {
            return None;
        }
        // sin(−q) = −sin q.
        let sign = k.signum();
        let (s, c) = (
            Poly::atom(Atom::Sin(j)).scale(sign),
            Poly::atom(Atom::Cos(j)),
        );
        for _ in 0..k.abs() as usize {
            (sin, cos) = (sin.mul(&c).add(&cos.mul(&s)), cos.mul(&c).sub(&sin.mul(&s)));
        }
    }
    Some((sin, cos))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn reader() -> Reader {
        let coords = [("a".to_string(), 0), ("b".to_string(), 1)].into();
        let arrays = [("phi".to_string(), (2, 2))].into();
        let params = [("l".to_string(), 0)].into();
        Reader::new(coords, arrays, params)
    }

    #[test]
    fn array_elements_with_literal_indices_are_coordinates() {
        assert_eq!(
            read("{ vec2(phi[1].sin(), phi[0]) }"),
            Some(Value::Vector(vec![
                Poly::atom(Atom::Sin(3)),
                Poly::atom(Atom::Coord(2))
            ]))
        );
        // Out of range, or an index that is not a literal: not read.
        assert_eq!(read("{ vec2(phi[2], 0.0) }"), None);
        assert_eq!(read("{ let k = 1; vec2(phi[k], 0.0) }"), None);
        assert_eq!(read("{ vec2(phi.len() as f64, 0.0) }"), None);
    }

    fn read(src: &str) -> Option<Value> {
        reader().block(&syn::parse_str(src).unwrap())
    }

    fn scalar(src: &str) -> Poly {
        match read(src) {
            Some(Value::Scalar(p)) => p,
            other => panic!("{src}: {other:?}"),
        }
    }

    #[test]
    fn angle_sums_expand() {
        let (sa, ca) = (Poly::atom(Atom::Sin(0)), Poly::atom(Atom::Cos(0)));
        let (sb, cb) = (Poly::atom(Atom::Sin(1)), Poly::atom(Atom::Cos(1)));
        assert_eq!(scalar("{ (a - b).sin() }"), sa.mul(&cb).sub(&ca.mul(&sb)));
        assert_eq!(scalar("{ (a - b).cos() }"), ca.mul(&cb).add(&sa.mul(&sb)));
        assert_eq!(scalar("{ (2.0 * a).sin() }"), sa.mul(&ca).scale(2.0));
    }

    #[test]
    fn bodies_read_as_vectors() {
        let l = Poly::atom(Atom::Param(0));
        let (sa, ca) = (Poly::atom(Atom::Sin(0)), Poly::atom(Atom::Cos(0)));
        assert_eq!(
            read("{ vec2(a.sin(), -a.cos()) * l }"),
            Some(Value::Vector(vec![sa.mul(&l), ca.mul(&l).scale(-1.0)]))
        );
        let mut r = reader();
        let pendulum = r.block(&syn::parse_str("{ vec2(l * a.sin(), 0.0) }").unwrap());
        r.define_body("bob".into(), pendulum.unwrap());
        let planar = r
            .block(&syn::parse_str("{ let d = bob.x / 2.0; planar(vec2(d, b), b) }").unwrap())
            .unwrap();
        let Value::Planar(position, angle) = planar else {
            panic!()
        };
        assert_eq!(position[0], sa.mul(&l).scale(0.5));
        assert_eq!(angle, Poly::atom(Atom::Coord(1)));
    }

    #[test]
    fn constants_are_opaque_and_shared() {
        let mut r = reader();
        let v = r
            .block(
                &syn::parse_str("{ vec2(a * l.cos(), std::f64::consts::PI + l.cos()) }").unwrap(),
            )
            .unwrap();
        assert_eq!(r.constants.len(), 2);
        let k0 = Poly::atom(Atom::Constant(0));
        assert_eq!(
            v,
            Value::Vector(vec![
                Poly::atom(Atom::Coord(0)).mul(&k0),
                Poly::atom(Atom::Constant(1)).add(&k0)
            ])
        );
    }

    #[test]
    fn other_forms_are_not_read() {
        for src in [
            "{ vec2(a.sqrt(), 0.0) }",
            "{ vec2(a / (a + b), 0.0) }",
            "{ vec2(a / b.sin(), 0.0) }",
            "{ vec2(a + t, 0.0) }",
            "{ vec2((a * a).sin(), 0.0) }",
            "{ vec2((a + l).sin(), 0.0) }",
            "{ let s = a; vec2(s.exp(), 0.0) }",
            "{ if a > 0.0 { vec2(a, 0.0) } else { vec2(0.0, a) } }",
            "{ vec2(f(a), 0.0) }",
        ] {
            assert_eq!(read(src), None, "{src}");
        }
    }
}
