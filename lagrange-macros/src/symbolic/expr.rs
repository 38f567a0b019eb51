//! Expressions as written, kept as a tree (a graph with shared nodes), differentiated in forward
//! mode by the chain rule and written out as straight-line code: one `let` per node.
//!
//! Nothing is expanded: a spring's ω²/4 (q₁ − q₀)² keeps the difference q₁ − q₀ as a node, and its
//! derivative by q₁ is ω²/4 · (2 (q₁ − q₀)) computed from that same difference; by q₀ the same
//! value negated. The derivative applies the rules of the dual numbers (Griewank & Walther,
//! *Evaluating Derivatives*, 2nd ed., 2008, §2.2 and Table 2.3, the tangent of each elementary
//! operation) to the same operands, so it rounds as the dual numbers do, without their products
//! by a zero or unit seed. The only rewritings are exact in floating point: adding a zero,
//! multiplying by one, a sign moved out of a product, a power of two moved out of a sum or into a
//! constant factor, literals folded. Derivatives are taken along directions ([`derivative`]): by
//! one variable, or along the motion of a mechanism for the constraint rows. A derivative about to
//! be written out may then have its products reassociated for latency ([`Graph::latency_ordered`],
//! in `product`): the one rewriting that rounds, by a few ulps.
//!
//! Nodes are interned ([`Graph::node`]): a subexpression built twice is one node, so a derivative
//! reuses the values it shares with the function (the √ of a distance, the quotient of a
//! reciprocal) and with the other derivatives.

use proc_macro2::TokenStream;
#[cfg(test)]
use quote::quote;
use std::collections::HashMap;

mod derivative;
mod emit;
mod product;

pub use derivative::Direction;
pub(crate) use emit::f64_tokens;

/// A node's index in its [`Graph`].
pub type Id = usize;

/// What a node is.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum Node {
    /// A number (its bits): `2.0`, `0.5`.
    Literal(u64),
    /// A constant as written (a parameter, `alpha.cos()`, `PI`), evaluated in `f64`.
    Constant(TokenStream2),
    /// Time.
    Time,
    /// A coordinate's slot in q.
    Coordinate(usize),
    /// A row of x (a component of a body's position, a planar body's angle).
    Row(usize),
    /// A coordinate's velocity q̇ⱼ, by its slot.
    Velocity(usize),
    /// A row's velocity ẋᵣ.
    RowVelocity(usize),
    /// A row's acceleration at q̈ = 0, d²/ds² xᵣ(q + s q̇, t + s)│₀.
    RowAcceleration(usize),
    /// An entry ∂xᵣ/∂qⱼ of x's Jacobian: (r, j).
    Jacobian(usize, usize),
    Add(Id, Id),
    Sub(Id, Id),
    Mul(Id, Id),
    Div(Id, Id),
    Neg(Id),
    Powi(Id, i32),
    Sqrt(Id),
    Sin(Id),
    Cos(Id),
    Exp(Id),
    Ln(Id),
}

/// Tokens compared and hashed by their text (two constants written alike are one node).
#[derive(Clone, Debug)]
pub struct TokenStream2(pub TokenStream, String);

impl TokenStream2 {
    pub fn new(tokens: TokenStream) -> Self {
        let text = tokens.to_string();
        TokenStream2(tokens, text)
    }
}

impl PartialEq for TokenStream2 {
    fn eq(&self, other: &Self) -> bool {
        self.1 == other.1
    }
}
impl Eq for TokenStream2 {}
impl std::hash::Hash for TokenStream2 {
    fn hash<H: std::hash::Hasher>(&self, state: &mut H) {
        self.1.hash(state)
    }
}

/// A variable a derivative is taken by: a coordinate, a row of x, or time.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Variable {
    Coordinate(usize),
    Row(usize),
    Time,
}

/// At most this many nodes: beyond it a potential keeps the dual numbers (the build would slow).
pub const MAX_NODES: usize = 4096;

/// The nodes, each built after its operands (so their order is an evaluation order).
#[derive(Default)]
pub struct Graph {
    nodes: Vec<Node>,
    /// Whether each node depends on a coordinate, a row or time (is evaluated on the scalar; the
    /// others are constants evaluated in `f64`).
    varies: Vec<bool>,
    /// Each node's cycles from the state to its value, by a latency model (see [`product`]).
    latencies: Vec<u32>,
    index: HashMap<Node, Id>,
    /// The derivatives taken, by node and direction.
    derivatives: HashMap<(Id, Direction), Id>,
    /// The directions, interned: the rate of each leaf that moves.
    directions: Vec<HashMap<Id, Id>>,
    direction_index: HashMap<Vec<(Id, Id)>, Direction>,
    /// Nodes rewritten for latency ([`Graph::latency_ordered`]), by the node rewritten.
    ordered: HashMap<Id, Id>,
}

impl Graph {
    pub fn len(&self) -> usize {
        self.nodes.len()
    }

    /// The node, interned: an equal node built before is returned as it is.
    pub fn node(&mut self, node: Node) -> Id {
        if let Some(&id) = self.index.get(&node) {
            return id;
        }
        let varies = match &node {
            Node::Literal(_) | Node::Constant(_) => false,
            Node::Time
            | Node::Coordinate(_)
            | Node::Row(_)
            | Node::Velocity(_)
            | Node::RowVelocity(_)
            | Node::RowAcceleration(_)
            | Node::Jacobian(..) => true,
            Node::Add(a, b) | Node::Sub(a, b) | Node::Mul(a, b) | Node::Div(a, b) => {
                self.varies[*a] || self.varies[*b]
            }
            Node::Neg(a)
            | Node::Powi(a, _)
            | Node::Sqrt(a)
            | Node::Sin(a)
            | Node::Cos(a)
            | Node::Exp(a)
            | Node::Ln(a) => self.varies[*a],
        };
        let id = self.nodes.len();
        self.latencies.push(self.latency_of(&node, varies));
        self.nodes.push(node.clone());
        self.varies.push(varies);
        self.index.insert(node, id);
        id
    }

    pub fn literal(&mut self, value: f64) -> Id {
        // −0 and 0 are one value for what is built here.
        self.node(Node::Literal((value + 0.0).to_bits()))
    }

    fn value(&self, id: Id) -> Option<f64> {
        match self.nodes[id] {
            Node::Literal(bits) => Some(f64::from_bits(bits)),
            _ => None,
        }
    }

    fn is(&self, id: Id, value: f64) -> bool {
        self.value(id) == Some(value)
    }

    /// The operand of a negation.
    fn negated(&self, id: Id) -> Option<Id> {
        match self.nodes[id] {
            Node::Neg(a) => Some(a),
            _ => None,
        }
    }

    pub fn add(&mut self, a: Id, b: Id) -> Id {
        match (self.value(a), self.value(b)) {
            (Some(x), Some(y)) => self.literal(x + y),
            (Some(0.0), _) => b,
            (_, Some(0.0)) => a,
            _ => match (self.negated(b), self.common_power(a, b)) {
                // a + (−b) = a − b, exactly.
                (Some(b), _) => self.sub(a, b),
                // 2ᵏ x + 2ᵏ y = 2ᵏ (x + y), exactly (short of overflow).
                (None, Some((power, x, y))) => {
                    let sum = self.add(x, y);
                    self.mul(power, sum)
                }
                (None, None) => self.node(Node::Add(a, b)),
            },
        }
    }

    pub fn sub(&mut self, a: Id, b: Id) -> Id {
        match (self.value(a), self.value(b)) {
            (Some(x), Some(y)) => self.literal(x - y),
            (Some(0.0), _) => self.neg(b),
            (_, Some(0.0)) => a,
            _ => match self.common_power(a, b) {
                Some((power, x, y)) => {
                    let difference = self.sub(x, y);
                    self.mul(power, difference)
                }
                None => self.node(Node::Sub(a, b)),
            },
        }
    }

    /// (2ᵏ, x, y) for a = 2ᵏ x and b = 2ᵏ y.
    fn common_power(&self, a: Id, b: Id) -> Option<(Id, Id, Id)> {
        let ((pa, x), (pb, y)) = (self.scaled(a)?, self.scaled(b)?);
        (pa == pb).then_some((pa, x, y))
    }

    pub fn mul(&mut self, a: Id, b: Id) -> Id {
        if let (Some(x), Some(y)) = (self.value(a), self.value(b)) {
            return self.literal(x * y);
        }
        if self.is(a, 0.0) || self.is(b, 0.0) {
            return self.literal(0.0);
        }
        if self.is(a, 1.0) {
            return b;
        }
        if self.is(b, 1.0) {
            return a;
        }
        if self.is(a, -1.0) {
            return self.neg(b);
        }
        if self.is(b, -1.0) {
            return self.neg(a);
        }
        // c (2ᵏ x) = (c 2ᵏ) x for a constant c: a power of two scales without rounding (short of
        // overflow), so the factor joins the constant, computed once in `f64`.
        if !self.varies[a] {
            if let Some((power, x)) = self.scaled(b) {
                let constant = self.mul(a, power);
                return self.mul(constant, x);
            }
        }
        if !self.varies[b] {
            if let Some((power, x)) = self.scaled(a) {
                let constant = self.mul(b, power);
                return self.mul(constant, x);
            }
        }
        // (−a) b = −(a b) and a (−b) = −(a b), exactly: the sign moves out to meet its twin.
        if let Some(a) = self.negated(a) {
            let product = self.mul(a, b);
            return self.neg(product);
        }
        if let Some(b) = self.negated(b) {
            let product = self.mul(a, b);
            return self.neg(product);
        }
        self.node(Node::Mul(a, b))
    }

    /// (2ᵏ, x) for a node 2ᵏ x (either order) with x varying.
    fn scaled(&self, id: Id) -> Option<(Id, Id)> {
        let Node::Mul(a, b) = self.nodes[id] else {
            return None;
        };
        let power_of_two = |v: f64| v.is_normal() && v.to_bits() & ((1u64 << 52) - 1) == 0;
        match (self.value(a), self.value(b)) {
            (Some(v), _) if power_of_two(v) && self.varies[b] => Some((a, b)),
            (_, Some(v)) if power_of_two(v) && self.varies[a] => Some((b, a)),
            _ => None,
        }
    }

    pub fn div(&mut self, a: Id, b: Id) -> Id {
        if let (Some(x), Some(y)) = (self.value(a), self.value(b)) {
            if y != 0.0 {
                return self.literal(x / y);
            }
        }
        if self.is(a, 0.0) && !self.is(b, 0.0) {
            return self.literal(0.0);
        }
        if self.is(b, 1.0) {
            return a;
        }
        if let Some(a) = self.negated(a) {
            let quotient = self.div(a, b);
            return self.neg(quotient);
        }
        self.node(Node::Div(a, b))
    }

    pub fn neg(&mut self, a: Id) -> Id {
        if let Some(x) = self.value(a) {
            return self.literal(-x);
        }
        match self.negated(a) {
            Some(inner) => inner,
            None => self.node(Node::Neg(a)),
        }
    }

    pub fn powi(&mut self, a: Id, n: i32) -> Id {
        match n {
            0 => self.literal(1.0),
            1 => a,
            _ => self.node(Node::Powi(a, n)),
        }
    }

    /// The operand of a negation, for writing `g -= a` instead of `g += −a`.
    pub fn negation_of(&self, id: Id) -> Option<Id> {
        self.negated(id)
    }

    /// Whether the node is a coordinate itself or a constant: a row of x written as one equals it
    /// exactly, and its row of J is a unit vector or zero.
    pub fn is_coordinate_or_constant(&self, id: Id) -> bool {
        !self.varies[id] || matches!(self.nodes[id], Node::Coordinate(_))
    }

    pub fn is_zero(&self, id: Id) -> bool {
        self.is(id, 0.0)
    }
}

fn operands(node: &Node) -> Vec<Id> {
    match node {
        Node::Add(a, b) | Node::Sub(a, b) | Node::Mul(a, b) | Node::Div(a, b) => vec![*a, *b],
        Node::Neg(a)
        | Node::Powi(a, _)
        | Node::Sqrt(a)
        | Node::Sin(a)
        | Node::Cos(a)
        | Node::Exp(a)
        | Node::Ln(a) => vec![*a],
        _ => vec![],
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_spring_keeps_its_difference() {
        // ω²/4 (q₁ − q₀)²: both derivatives from one node 2 (q₁ − q₀), one the other's negation.
        let mut g = Graph::default();
        let c = g.node(Node::Constant(TokenStream2::new(quote!(
            omega * omega / 4.0
        ))));
        let (q0, q1) = (g.node(Node::Coordinate(0)), g.node(Node::Coordinate(1)));
        let d = g.sub(q1, q0);
        let square = g.powi(d, 2);
        let v = g.mul(c, square);
        let d1 = g.derivative(v, Variable::Coordinate(1));
        let d0 = g.derivative(v, Variable::Coordinate(0));
        assert_eq!(g.negation_of(d0), Some(d1));
        let two = g.literal(2.0);
        let twice = g.mul(two, d);
        assert_eq!(d1, g.mul(c, twice));
        assert_eq!(
            g.variables(v),
            vec![Variable::Coordinate(0), Variable::Coordinate(1)]
        );
    }

    #[test]
    fn exact_rewritings_only() {
        let mut g = Graph::default();
        let (a, b) = (g.node(Node::Coordinate(0)), g.node(Node::Row(3)));
        let (zero, one) = (g.literal(0.0), g.literal(1.0));
        assert_eq!(g.add(a, zero), a);
        assert_eq!(g.mul(one, a), a);
        let vanished = g.mul(zero, b);
        assert!(g.is_zero(vanished));
        let nb = g.neg(b);
        assert_eq!(g.neg(nb), b);
        let diff = g.sub(a, b);
        assert_eq!(g.add(a, nb), diff);
        // a (−b) is −(a b); nothing else is reassociated.
        let ab = g.mul(a, b);
        let product = g.mul(a, nb);
        assert_eq!(g.negation_of(product), Some(ab));
        let three = g.literal(3.0);
        let left = g.mul(three, ab);
        let three_a = g.mul(three, a);
        let right = g.mul(three_a, b);
        assert_ne!(left, right);
    }

    #[test]
    fn quotients_and_roots_reuse_their_value() {
        // d(1/√(r r))/dr = −((1/√(r r))/√(r r)) · (r/√(r r)): the 2 of (r r)' = 2 r r' cancels
        // the 2 of (√a)' = a'/(2√a), and the quotient's factor is shared.
        let mut g = Graph::default();
        let r = g.node(Node::Row(0));
        let square = g.mul(r, r);
        let root = g.node(Node::Sqrt(square));
        let one = g.literal(1.0);
        let v = g.div(one, root);
        let d = g.derivative(v, Variable::Row(0));
        let factor = g.div(v, root);
        let droot = g.div(r, root);
        let expected = g.mul(factor, droot);
        assert_eq!(g.negation_of(d), Some(expected));
    }

    #[test]
    fn a_common_power_of_two_is_taken_out_of_a_sum() {
        // 2 (x ẋ) + 2 (y ẏ) = 2 (x ẋ + y ẏ) and 2a − 2b = 2 (a − b), exactly; 2a + 4b is left.
        let mut g = Graph::default();
        let (x, y) = (g.node(Node::Coordinate(0)), g.node(Node::Coordinate(1)));
        let (two, four) = (g.literal(2.0), g.literal(4.0));
        let (ax, by) = (g.mul(two, x), g.mul(two, y));
        let sum = g.add(ax, by);
        let inner = g.add(x, y);
        assert_eq!(sum, g.mul(two, inner));
        let difference = g.sub(ax, by);
        let inner = g.sub(x, y);
        assert_eq!(difference, g.mul(two, inner));
        let four_y = g.mul(four, y);
        let mixed = g.add(ax, four_y);
        assert_eq!(g.nodes[mixed], Node::Add(ax, four_y));
    }

    #[test]
    fn powers_of_two_join_constant_factors() {
        // c · (2 d) = (c · 2) · d: one product at run time.
        let mut g = Graph::default();
        let c = g.node(Node::Constant(TokenStream2::new(quote!(k))));
        let d = g.node(Node::Coordinate(0));
        let (two, three) = (g.literal(2.0), g.literal(3.0));
        let twice = g.mul(two, d);
        let product = g.mul(c, twice);
        let c2 = g.mul(c, two);
        assert_eq!(product, g.mul(c2, d));
        // Not a factor 3, which would round.
        let thrice = g.mul(three, d);
        let product = g.mul(c, thrice);
        assert_eq!(g.nodes[product], Node::Mul(c, thrice));
    }

    #[test]
    fn constants_are_f64_and_lifted_where_a_scalar_needs_them() {
        let mut g = Graph::default();
        let k = g.node(Node::Constant(TokenStream2::new(quote!(k))));
        let half = g.literal(0.5);
        let c = g.mul(k, half);
        let x = g.node(Node::Coordinate(0));
        let v = g.sub(c, x);
        let code = g.emit(&[v], &quote!(S)).to_string();
        assert!(code.contains("let __e0 : f64 = k ;"), "{code}");
        assert!(code.contains("let __e2 : f64 = __e0 * 0.5 ;"), "{code}");
        assert!(
            code.contains("let __e4 : S = < S > :: from (__e2) - __e3 ;"),
            "{code}"
        );
    }
}
