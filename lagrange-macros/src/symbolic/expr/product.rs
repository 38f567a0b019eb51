//! Products rewritten for latency: the code a derivative is written as should wait as little as
//! possible for its slowest operand. A tree of products and quotients (with negations) is
//! flattened into a sign, constant factors and varying factors; the constants join into one
//! coefficient (computed in `f64`, off the path that waits for the state); the varying factors
//! are multiplied shallowest first, two at a time (the pairing of Huffman, "A Method for the
//! Construction of Minimum-Redundancy Codes", 1952, with the later of two operands' ready times
//! plus a product's latency in place of the sum of weights); and the quotient is one
//! division at the end. Three or more equal factors √a in one product are taken as
//! a·…·√a: the derivative of −μ m/√(r²) by x, −((μ m/√r²)/√r²)(x/√r²) as taken by the chain rule
//! (a reciprocal and three dependent products), becomes (μ m x)/(r² √r²): one product after the
//! root, then the division (the form of q̈ = −q/(r²√r²) written by hand).
//!
//! These rewritings reassociate products, so a result may differ from the chain rule's by a few
//! rounding errors of its factors' count, never more; they keep every operation that can fail: no
//! factor cancels against a divisor (x/x stays NaN at x = 0), and a √a is taken out only where one
//! is left in the product (√a of a negative a still makes it NaN).

use super::{Graph, Id, Node};
use std::collections::HashMap;

/// Cycles before a result can be used, per operation (Agner Fog, *Instruction tables*, 2022,
/// AMD Zen 2/3 and Intel Skylake rows, rounded up: addsd/mulsd 3–4, divsd 13–14, sqrtsd 14–20);
/// a function call (sin, cos, exp, ln) counted as a few dozen.
mod cycles {
    pub const ADD: u32 = 4;
    pub const MUL: u32 = 4;
    pub const DIV: u32 = 14;
    pub const SQRT: u32 = 20;
    pub const CALL: u32 = 40;
}

/// A product's factors: its sign, constant factors above and below the line, and varying factors
/// above and below the line (each as often as it occurs).
#[derive(Default)]
struct Factors {
    negative: bool,
    constants: Vec<Id>,
    constant_divisors: Vec<Id>,
    numerator: Vec<Id>,
    denominator: Vec<Id>,
}

impl Graph {
    /// The node rewritten for latency (see the [module docs](self)): every product and quotient
    /// in it, down to its leaves.
    pub fn latency_ordered(&mut self, id: Id) -> Id {
        if !self.varies[id] {
            return id;
        }
        if let Some(&done) = self.ordered.get(&id) {
            return done;
        }
        let out = match self.nodes[id].clone() {
            Node::Mul(..) | Node::Div(..) => self.product(id),
            Node::Neg(a) => {
                let a = self.latency_ordered(a);
                self.neg(a)
            }
            Node::Add(a, b) => {
                let (a, b) = (self.latency_ordered(a), self.latency_ordered(b));
                self.add(a, b)
            }
            Node::Sub(a, b) => {
                let (a, b) = (self.latency_ordered(a), self.latency_ordered(b));
                self.sub(a, b)
            }
            Node::Powi(a, n) => {
                let a = self.latency_ordered(a);
                self.powi(a, n)
            }
            Node::Sqrt(a) => self.unary(a, Node::Sqrt),
            Node::Sin(a) => self.unary(a, Node::Sin),
            Node::Cos(a) => self.unary(a, Node::Cos),
            Node::Exp(a) => self.unary(a, Node::Exp),
            Node::Ln(a) => self.unary(a, Node::Ln),
            _ => id,
        };
        self.ordered.insert(id, out);
        self.ordered.insert(out, out);
        out
    }

    fn unary(&mut self, a: Id, node: fn(Id) -> Node) -> Id {
        let a = self.latency_ordered(a);
        self.node(node(a))
    }

    /// A product or quotient as (sign) coefficient × (product of the numerator's factors) /
    /// (product of the denominator's).
    fn product(&mut self, id: Id) -> Id {
        let mut factors = Factors::default();
        self.collect(id, true, &mut factors);
        let numerator = self.powers_of_roots(std::mem::take(&mut factors.numerator));
        let denominator = self.powers_of_roots(std::mem::take(&mut factors.denominator));
        let mut coefficient = None;
        for c in factors.constants {
            coefficient = Some(coefficient.map_or(c, |k| self.mul(k, c)));
        }
        for c in factors.constant_divisors {
            let one = self.literal(1.0);
            coefficient = Some(self.div(coefficient.unwrap_or(one), c));
        }
        let above = self.shallowest_first(coefficient.into_iter().chain(numerator).collect());
        let below = self.shallowest_first(denominator);
        let value = match (above, below) {
            (Some(above), None) => above,
            (above, Some(below)) => {
                let above = above.unwrap_or_else(|| self.literal(1.0));
                // A numerator ready a division's time after the denominator waits less for the
                // reciprocal taken early: a (1/b) instead of a/b.
                if self.latency(below) + cycles::DIV <= self.latency(above) {
                    let one = self.literal(1.0);
                    let reciprocal = self.div(one, below);
                    self.mul(above, reciprocal)
                } else {
                    self.div(above, below)
                }
            }
            (None, None) => self.literal(1.0),
        };
        if factors.negative {
            self.neg(value)
        } else {
            value
        }
    }

    /// The factors of a tree of products, quotients and negations (`above`: whether `id` is
    /// above the line), its other nodes rewritten each as one factor.
    fn collect(&mut self, id: Id, above: bool, factors: &mut Factors) {
        match self.nodes[id].clone() {
            _ if !self.varies[id] => {
                if above {
                    factors.constants.push(id)
                } else {
                    factors.constant_divisors.push(id)
                }
            }
            Node::Mul(a, b) => {
                self.collect(a, above, factors);
                self.collect(b, above, factors);
            }
            Node::Div(a, b) => {
                self.collect(a, above, factors);
                self.collect(b, !above, factors);
            }
            Node::Neg(a) => {
                factors.negative = !factors.negative;
                self.collect(a, above, factors);
            }
            _ => {
                let factor = self.latency_ordered(id);
                if above {
                    factors.numerator.push(factor)
                } else {
                    factors.denominator.push(factor)
                }
            }
        }
    }

    /// An odd number 2k + 1 ≥ 3 of factors √a as k factors a and one √a (exact up to rounding;
    /// an even number is left, so that √a of a negative a still makes the product NaN).
    fn powers_of_roots(&mut self, factors: Vec<Id>) -> Vec<Id> {
        let mut count: HashMap<Id, usize> = HashMap::new();
        for &f in &factors {
            *count.entry(f).or_default() += 1;
        }
        let mut out = Vec::with_capacity(factors.len());
        for f in factors {
            match (&self.nodes[f], count[&f]) {
                (Node::Sqrt(a), n) if n >= 3 && n % 2 == 1 => {
                    let a = *a;
                    // Once, at the first occurrence.
                    if count.insert(f, 0) == Some(n) {
                        out.extend(std::iter::repeat_n(a, n / 2));
                        out.push(f);
                    }
                }
                (_, 0) => {}
                _ => out.push(f),
            }
        }
        out
    }

    /// The product of the factors, the two that are ready first multiplied first, until one is
    /// left (`None` for none).
    fn shallowest_first(&mut self, mut factors: Vec<Id>) -> Option<Id> {
        while factors.len() > 1 {
            // Ties keep the order of the factors (the order they were written in).
            let mut order: Vec<usize> = (0..factors.len()).collect();
            order.sort_by_key(|&i| self.latency(factors[i]));
            let (first, second) = (order[0].min(order[1]), order[0].max(order[1]));
            let (a, b) = (factors[first], factors[second]);
            factors.remove(second);
            factors[first] = self.mul(a, b);
        }
        factors.pop()
    }

    /// The cycles before the node's value can be used, from the state (see [`cycles`]); constants
    /// are computed off that path and count zero.
    pub(super) fn latency(&self, id: Id) -> u32 {
        self.latencies[id]
    }

    /// [`latency`](Self::latency) of a node about to be built, from its operands'.
    pub(super) fn latency_of(&self, node: &Node, varies: bool) -> u32 {
        if !varies {
            return 0;
        }
        let of = |a: Id| self.latencies[a];
        match *node {
            Node::Add(a, b) | Node::Sub(a, b) => of(a).max(of(b)) + cycles::ADD,
            Node::Mul(a, b) => of(a).max(of(b)) + cycles::MUL,
            Node::Div(a, b) => of(a).max(of(b)) + cycles::DIV,
            Node::Neg(a) => of(a) + 1,
            Node::Powi(a, n) => {
                let squarings = 32 - n.unsigned_abs().leading_zeros();
                let inverse = if n < 0 { cycles::DIV } else { 0 };
                of(a) + cycles::MUL * squarings + inverse
            }
            Node::Sqrt(a) => of(a) + cycles::SQRT,
            Node::Sin(a) | Node::Cos(a) | Node::Exp(a) | Node::Ln(a) => of(a) + cycles::CALL,
            _ => 0,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::symbolic::expr::Variable;

    impl Graph {
        /// The node's value in `f64` at coordinates `q` (literals, coordinates and the operations).
        fn evaluate(&self, id: Id, q: &[f64]) -> f64 {
            let of = |a: Id| self.evaluate(a, q);
            match self.nodes[id] {
                Node::Literal(bits) => f64::from_bits(bits),
                Node::Coordinate(j) => q[j],
                Node::Add(a, b) => of(a) + of(b),
                Node::Sub(a, b) => of(a) - of(b),
                Node::Mul(a, b) => of(a) * of(b),
                Node::Div(a, b) => of(a) / of(b),
                Node::Neg(a) => -of(a),
                Node::Powi(a, n) => of(a).powi(n),
                Node::Sqrt(a) => of(a).sqrt(),
                Node::Sin(a) => of(a).sin(),
                Node::Cos(a) => of(a).cos(),
                Node::Exp(a) => of(a).exp(),
                Node::Ln(a) => of(a).ln(),
                ref other => panic!("not evaluated here: {other:?}"),
            }
        }
    }

    /// Kepler's −μm/√(x² + y²) with μm a literal (0.7), and its gradient (as taken, and rewritten).
    fn kepler(g: &mut Graph) -> ([Id; 2], [Id; 2]) {
        let (x, y) = (g.node(Node::Coordinate(0)), g.node(Node::Coordinate(1)));
        let (xx, yy) = (g.mul(x, x), g.mul(y, y));
        let r2 = g.add(xx, yy);
        let r = g.node(Node::Sqrt(r2));
        let mu_m = g.literal(0.7);
        let quotient = g.div(mu_m, r);
        let v = g.neg(quotient);
        let taken = [0, 1].map(|j| g.derivative(v, Variable::Coordinate(j)));
        let rewritten = taken.map(|d| g.latency_ordered(d));
        (taken, rewritten)
    }

    /// Points spread over several orders of magnitude, from a fixed seed (xorshift).
    fn points(count: usize, dim: usize) -> Vec<Vec<f64>> {
        let mut state = 0x9E37_79B9_7F4A_7C15u64;
        let mut next = move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        (0..count)
            .map(|_| {
                (0..dim)
                    .map(|_| (2.0 * next() - 1.0) * 10f64.powf(6.0 * next() - 3.0))
                    .collect()
            })
            .collect()
    }

    #[test]
    fn keplers_gradient_is_one_product_and_one_division_after_the_root() {
        // ∂/∂x (−μm/√r²) = (μm x)/(r² √r²): the root's one product, then the division.
        let mut g = Graph::default();
        let (taken, [dx, dy]) = kepler(&mut g);
        let Node::Div(above, below) = g.nodes[dx] else {
            panic!("{:?}", g.nodes[dx])
        };
        let (x, mu_m) = (g.node(Node::Coordinate(0)), g.literal(0.7));
        assert_eq!(above, g.mul(mu_m, x));
        let Node::Mul(r2, r) = g.nodes[below] else {
            panic!("{:?}", g.nodes[below])
        };
        assert_eq!(g.nodes[r], Node::Sqrt(r2));
        // y's shares the denominator.
        assert!(matches!(g.nodes[dy], Node::Div(_, b) if b == below));
        // The latency model's count: a product and a division after the root, not two
        // quotients in series and a product.
        assert_eq!(g.latency(dx), g.latency(r) + cycles::MUL + cycles::DIV);
        assert_eq!(
            g.latency(taken[0]),
            g.latency(r) + 2 * cycles::DIV + cycles::MUL
        );
    }

    #[test]
    fn rewritten_products_equal_the_chain_rules_to_round_off() {
        // Each form is the exact value of the same factors times a product of at most m factors
        // (1 + δ), |δ| ≤ u = 2⁻⁵³ (Higham, *Accuracy and Stability of Numerical Algorithms*, 2nd
        // ed., 2002, §3.1, Lemma 3.1): m counts the roundings of products, quotients and roots
        // that differ between the forms (≤ 6 each here; the sum of squares is one node either
        // way). Two such values differ by at most about 2·6u relatively: 6 ε, asserted as 8 ε.
        let mut g = Graph::default();
        let (taken, rewritten) = kepler(&mut g);
        // Products with a sum, a power and a sine among their factors (each such factor is one
        // node either way, so its value is the same): x³ sin(y) (x² + y²) / (y (1 + x²)) and
        // (x/y) (y/(x + 1)) (x sin y) x / (y + 2).
        let (x, y) = (g.node(Node::Coordinate(0)), g.node(Node::Coordinate(1)));
        let (xx, yy, one, two) = (g.mul(x, x), g.mul(y, y), g.literal(1.0), g.literal(2.0));
        let (sum, cube, sin) = (g.add(xx, yy), g.powi(x, 3), g.node(Node::Sin(y)));
        let onexx = g.add(one, xx);
        let (a, b) = (g.mul(cube, sin), g.mul(y, onexx));
        let ab = g.mul(a, sum);
        let first = g.div(ab, b);
        let (x_y, x1, y2, x_sin) = (g.div(x, y), g.add(x, one), g.add(y, two), g.mul(x, sin));
        let y_x1 = g.div(y, x1);
        let p = g.mul(x_y, y_x1);
        let p = g.mul(p, x_sin);
        let p = g.mul(p, x);
        let second = g.div(p, y2);
        let more = [first, second];
        let more_rewritten = more.map(|d| g.latency_ordered(d));
        for q in points(10_000, 2) {
            for (old, new) in taken
                .iter()
                .zip(&rewritten)
                .chain(more.iter().zip(&more_rewritten))
            {
                let (old, new) = (g.evaluate(*old, &q), g.evaluate(*new, &q));
                if old.is_finite() && old.abs() > f64::MIN_POSITIVE {
                    assert!(
                        (new - old).abs() <= 8.0 * f64::EPSILON * old.abs(),
                        "{new} vs {old} at {q:?}"
                    );
                } else {
                    // Overflow, underflow or NaN: the rewritten form's too (the same failures).
                    assert_eq!(old.is_nan(), new.is_nan(), "{new} vs {old} at {q:?}");
                }
            }
        }
    }

    #[test]
    fn what_fails_still_fails() {
        // At the centre Kepler's gradient is 0/0 either way; a NaN coordinate stays NaN.
        let mut g = Graph::default();
        let (taken, rewritten) = kepler(&mut g);
        for q in [[0.0, 0.0], [f64::NAN, 1.0], [1.0, f64::NAN]] {
            for (old, new) in taken.iter().zip(&rewritten) {
                assert!(g.evaluate(*old, &q).is_nan());
                assert!(g.evaluate(*new, &q).is_nan(), "at {q:?}");
            }
        }
        // x/x does not cancel (NaN at 0); √a √a √a keeps a √a (NaN for a < 0); √a √a is left.
        let x = g.node(Node::Coordinate(0));
        let xx = g.div(x, x);
        let x_over_x = g.latency_ordered(xx);
        assert!(g.evaluate(x_over_x, &[0.0]).is_nan());
        let root = g.node(Node::Sqrt(x));
        let square = g.mul(root, root);
        let cube = g.mul(square, root);
        let (square, cube) = (g.latency_ordered(square), g.latency_ordered(cube));
        assert_eq!(g.nodes[square], Node::Mul(root, root));
        assert_eq!(g.nodes[cube], Node::Mul(x, root));
        assert!(g.evaluate(cube, &[-4.0]).is_nan());
        assert_eq!(g.evaluate(cube, &[4.0]), 8.0);
    }
}
