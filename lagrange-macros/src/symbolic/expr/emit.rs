//! Straight-line code for a [`Graph`]: one `let` per node an output needs, in the order the nodes
//! were built (operands first).

use super::{operands, Graph, Id, Node};
use proc_macro2::{Literal, TokenStream};
use quote::{format_ident, quote};

/// A constant as `f64` tokens: its literal, or, where no literal can write it (constants that fold
/// to ±∞ or NaN, as `1.0 / 0.0` does), the named constant, so that the declaration still compiles
/// and the run-time checks refuse the non-finite values it gives.
pub(crate) fn f64_tokens(x: f64) -> TokenStream {
    let f64_type = quote!(::lagrange::__private::core::primitive::f64);
    if x.is_finite() {
        let l = Literal::f64_unsuffixed(x);
        quote!(#l)
    } else if x.is_nan() {
        quote!(#f64_type::NAN)
    } else if x > 0.0 {
        quote!(#f64_type::INFINITY)
    } else {
        quote!(#f64_type::NEG_INFINITY)
    }
}

impl Graph {
    /// A node as an operand on scalar `S` (or in `f64` where `in_f64`).
    fn operand(&self, id: Id, in_f64: bool, s: &TokenStream) -> TokenStream {
        match (&self.nodes[id], in_f64 || self.varies[id]) {
            (Node::Literal(bits), true) => f64_tokens(f64::from_bits(*bits)),
            (Node::Literal(bits), false) => {
                let l = f64_tokens(f64::from_bits(*bits));
                quote!(<#s>::from(#l))
            }
            (_, true) => {
                let n = name(id);
                quote!(#n)
            }
            (_, false) => {
                let n = name(id);
                quote!(<#s>::from(#n))
            }
        }
    }

    /// `let`s for every node `outputs` need, in order: constants in `f64`, the others on `s`.
    /// Literals are written where they are used.
    pub fn emit(&self, outputs: &[Id], s: &TokenStream) -> TokenStream {
        self.emit_prepared(outputs, s, &[])
    }

    /// Which nodes `outputs` need, none below a node of `prepared`.
    fn needed(&self, outputs: &[Id], prepared: &[Id]) -> Vec<bool> {
        let mut needed = vec![false; self.nodes.len()];
        let mut stack: Vec<Id> = outputs.to_vec();
        // An output written `g -= a` needs a, not −a.
        for id in &mut stack {
            *id = self.negated(*id).unwrap_or(*id);
        }
        while let Some(n) = stack.pop() {
            if !std::mem::replace(&mut needed[n], true) && !prepared.contains(&n) {
                stack.extend(operands(&self.nodes[n]));
            }
        }
        needed
    }

    /// The constants the code for `outputs` takes from outside the state's arithmetic: each
    /// constant node (not a literal) an operand of a varying node, in the order built. Computed
    /// once ahead, they are all the constant work of an evaluation.
    pub fn coefficients(&self, outputs: &[Id]) -> Vec<Id> {
        let needed = self.needed(outputs, &[]);
        let mut coefficient = vec![false; self.nodes.len()];
        for (id, node) in self.nodes.iter().enumerate() {
            if needed[id] && self.varies[id] {
                for a in operands(node) {
                    coefficient[a] |= !self.varies[a] && !matches!(self.nodes[a], Node::Literal(_));
                }
            }
        }
        (0..self.nodes.len())
            .filter(|&id| coefficient[id])
            .collect()
    }

    /// [`emit`](Self::emit), node `prepared[i]` read as `__prepared[i]` (an `&[f64; _]`) instead
    /// of computed.
    pub fn emit_prepared(&self, outputs: &[Id], s: &TokenStream, prepared: &[Id]) -> TokenStream {
        let needed = self.needed(outputs, prepared);
        let shared = self.shared_denominators(&needed);
        let mut out = TokenStream::new();
        for (id, node) in self.nodes.iter().enumerate() {
            if !needed[id] || matches!(node, Node::Literal(_)) {
                continue;
            }
            let in_f64 = !self.varies[id];
            let value = match prepared.iter().position(|&p| p == id) {
                Some(i) => {
                    let i = Literal::usize_unsuffixed(i);
                    quote!(__prepared[#i])
                }
                None => self.node_value(node, in_f64, s, &shared),
            };
            let ty = if in_f64 { quote!(f64) } else { s.clone() };
            let n = name(id);
            out.extend(quote!(let #n: #ty = #value;));
            if shared[id] {
                let inverse = reciprocal_name(id);
                out.extend(quote!(let #inverse: #ty = #n.recip();));
            }
        }
        out
    }

    /// Which denominators the quotients share as a reciprocal.
    ///
    /// Quotients by one denominator share its reciprocal: a node divided three times or more is
    /// inverted once and the quotients are products, each within an ulp of the division's. Two
    /// divisions by it are left: they run side by side (a division issues every 4–5 cycles and
    /// takes 13–14, a product 3–4: see `product::cycles`), both done before a reciprocal and a
    /// product would be; from three on, the reciprocal is done first. Literal denominators stay
    /// divisions.
    fn shared_denominators(&self, needed: &[bool]) -> Vec<bool> {
        let mut quotients = vec![0usize; self.nodes.len()];
        for (id, node) in self.nodes.iter().enumerate() {
            if let (true, Node::Div(_, b)) = (needed[id], node) {
                quotients[*b] += 1;
            }
        }
        (0..self.nodes.len())
            .map(|b| quotients[b] >= 3 && !matches!(self.nodes[b], Node::Literal(_)))
            .collect()
    }

    /// A node's value from its operands' names (in `f64` where `in_f64`, on `s` otherwise).
    fn node_value(
        &self,
        node: &Node,
        in_f64: bool,
        s: &TokenStream,
        shared: &[bool],
    ) -> TokenStream {
        let op = |a: Id| self.operand(a, in_f64, s);
        let binary = |a: &Id, b: &Id, symbol: TokenStream, commutes: bool| {
            self.binary(*a, *b, symbol, commutes, in_f64, s)
        };
        match node {
            Node::Literal(_) => unreachable!("literals are written in place"),
            Node::Constant(tokens) => tokens.0.clone(),
            Node::Add(a, b) => binary(a, b, quote!(+), true),
            Node::Sub(a, b) => binary(a, b, quote!(-), false),
            Node::Mul(a, b) => binary(a, b, quote!(*), true),
            Node::Div(a, b) if shared[*b] => {
                let inverse = reciprocal_name(*b);
                match (in_f64, self.varies[*a]) {
                    // A constant over a variable: the reciprocal on `S` times the `f64`.
                    (false, false) => {
                        let a = self.operand(*a, true, s);
                        quote!(#inverse * #a)
                    }
                    _ => {
                        let a = op(*a);
                        quote!(#a * #inverse)
                    }
                }
            }
            Node::Div(a, b) => binary(a, b, quote!(/), false),
            Node::Neg(a) => {
                let a = op(*a);
                quote!(-#a)
            }
            Node::Powi(a, n) => {
                let a = op(*a);
                quote!(#a.powi(#n))
            }
            Node::Sqrt(a) => method(op(*a), "sqrt"),
            Node::Sin(a) => method(op(*a), "sin"),
            Node::Cos(a) => method(op(*a), "cos"),
            Node::Exp(a) => method(op(*a), "exp"),
            Node::Ln(a) => method(op(*a), "ln"),
            Node::Time
            | Node::Coordinate(_)
            | Node::Row(_)
            | Node::Velocity(_)
            | Node::RowVelocity(_)
            | Node::RowAcceleration(_)
            | Node::Jacobian(..) => state_input(node),
        }
    }

    /// `a symbol b`. A binary operation with a constant on the right takes the `f64` as it is
    /// (`DualNum` is closed under operations with its primitive); a commutative one with the
    /// constant on the left is written the other way round (exact).
    fn binary(
        &self,
        a: Id,
        b: Id,
        symbol: TokenStream,
        commutes: bool,
        in_f64: bool,
        s: &TokenStream,
    ) -> TokenStream {
        if !in_f64 && !self.varies[b] {
            let (a, b) = (self.operand(a, in_f64, s), self.operand(b, true, s));
            quote!(#a #symbol #b)
        } else if !in_f64 && !self.varies[a] && commutes {
            let (a, b) = (self.operand(a, true, s), self.operand(b, in_f64, s));
            quote!(#b #symbol #a)
        } else {
            let (a, b) = (self.operand(a, in_f64, s), self.operand(b, in_f64, s));
            quote!(#a #symbol #b)
        }
    }

    /// The node as a value on `s`: its name, a literal lifted, a constant lifted.
    pub fn scalar(&self, id: Id, s: &TokenStream) -> TokenStream {
        self.operand(id, false, s)
    }
}

/// What the generated function reads for a node of the state: `__t`, `__q[j]`, `__x[r]`, `__v[j]`,
/// `__x_dot[r]`, `__x_accel[r]`, `__jacobian[r][j]`.
fn state_input(node: &Node) -> TokenStream {
    let (array, i) = match *node {
        Node::Time => return quote!(__t),
        Node::Jacobian(r, j) => {
            let (r, j) = (Literal::usize_unsuffixed(r), Literal::usize_unsuffixed(j));
            return quote!(__jacobian[#r][#j]);
        }
        Node::Coordinate(j) => (quote!(__q), j),
        Node::Row(r) => (quote!(__x), r),
        Node::Velocity(j) => (quote!(__v), j),
        Node::RowVelocity(r) => (quote!(__x_dot), r),
        Node::RowAcceleration(r) => (quote!(__x_accel), r),
        _ => unreachable!("an operation is no input of the state"),
    };
    let i = Literal::usize_unsuffixed(i);
    quote!(#array[#i])
}

fn method(receiver: TokenStream, name: &str) -> TokenStream {
    let name = format_ident!("{}", name);
    quote!(#receiver.#name())
}

/// `__e12`: the name of node 12.
fn name(id: Id) -> proc_macro2::Ident {
    format_ident!("__e{}", id)
}

/// `__r12`: the reciprocal of node 12, where quotients by it share it.
fn reciprocal_name(id: Id) -> proc_macro2::Ident {
    format_ident!("__r{}", id)
}

#[cfg(test)]
mod tests {
    use super::f64_tokens;

    #[test]
    fn constants_no_literal_can_write_are_named() {
        assert_eq!(f64_tokens(-2.5).to_string(), "- 2.5");
        let path = ":: lagrange :: __private :: core :: primitive :: f64 ::";
        assert_eq!(
            f64_tokens(f64::INFINITY).to_string(),
            format!("{path} INFINITY")
        );
        assert_eq!(
            f64_tokens(f64::NEG_INFINITY).to_string(),
            format!("{path} NEG_INFINITY")
        );
        assert_eq!(f64_tokens(f64::NAN).to_string(), format!("{path} NAN"));
    }
}
