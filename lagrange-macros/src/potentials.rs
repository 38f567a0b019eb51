//! The parts of the potential whose gradients `Model::potential_gradient` takes one by one
//! ([`potential_parts`]), which coordinates each can depend on, and how each gradient is taken
//! ([`own_gradient`]): a spring between two masses of a chain of N costs a 2-wide gradient, not an
//! N-wide one.
//!
//! A potential's value written as a sum, `k/2·(q[1] − q[0])² + (q[2] − q[1])⁴ + …`, is read term
//! by term ([`terms`]): the sum is split at its top-level `+` and `−`, and a constant factor
//! (`ω²/4 · (a² + b²)`) or divisor is distributed over a sum it multiplies. Each term keeps the
//! block's `let`s and depends on what it names, its locals through the names of their values.
//!
//! A term depends on the coordinates it names — an element `q[3]` of an array coordinate indexed by
//! an integer literal names that element, any other use of the array names all of it — and on those
//! of the bodies it names ([`crate::components::dependencies`]). The reading is conservative: a set
//! may be wider than the truth, never narrower; a potential written with a macro invocation
//! (whose tokens are not read), a `return`, or a `let` that binds anything but names is not split
//! and counts as depending on every coordinate it could.

use crate::check::Model;
use crate::components::{coordinate_slots, dependencies};
use crate::names;
use std::collections::{BTreeMap, BTreeSet};
use syn::visit::{self, Visit};
use syn::{BinOp, Block, Expr, Lit, Pat, Stmt};

/// One part of the potential whose gradient is taken on its own: a declared potential or a term
/// of its sum, as a block (the potential's `let`s, the term as its value) and the coordinate slots
/// (sorted) it can depend on.
pub struct Part {
    /// Index into `model.potentials`.
    pub potential: usize,
    pub block: Block,
    pub slots: Vec<usize>,
}

/// The parts of the declared potentials, when `Model::potential_gradient` can take the gradient:
/// at least one potential and no field that varies in space (its potential is not declared
/// function by function). `None` otherwise.
pub fn potential_parts(model: &Model) -> Option<Vec<Part>> {
    let n = model.dof();
    if model.potentials.is_empty() || !model.gravities.is_empty() {
        return None;
    }
    let slots_of = coordinate_slots(model);
    let (_, body_deps) = dependencies(model);
    let parameters: BTreeSet<String> = model.params.iter().map(|p| p.ident.to_string()).collect();
    let mut parts = Vec::new();
    for (potential, decl) in model.potentials.iter().enumerate() {
        let locals = local_values(&decl.block);
        let blocks = match (&locals, terms_of(&decl.block, locals.as_ref(), &parameters)) {
            (Some(_), Some(terms)) => terms,
            _ => vec![decl.block.clone()],
        };
        for block in blocks {
            let slots = match &locals {
                Some(locals) => {
                    let Some(Stmt::Expr(value, None)) = block.stmts.last() else {
                        unreachable!("a part's block ends in its value");
                    };
                    term_slots(value, locals, &slots_of, &body_deps, n)
                }
                None => block_slots(&block, &slots_of, &body_deps, n),
            };
            parts.push(Part {
                potential,
                block,
                slots,
            });
        }
    }
    Some(parts)
}

/// Whether `Model::potential_gradient` is written, given which parts are `symbolic` (their
/// gradient read off the expression tree, `crate::symbolic::gradient`; the others on dual numbers
/// seeded on their own slots): when some part is symbolic, or every part is narrower than all N
/// coordinates. Otherwise the dense gradient of `lagrange_core::dynamics` is as narrow.
pub fn own_gradient(model: &Model, parts: &[Part], symbolic: &[bool]) -> bool {
    let n = model.dof();
    symbolic.iter().any(|&s| s) || (n >= 2 && parts.iter().all(|p| p.slots.len() < n))
}

/// The coordinate slots a whole block's uses can depend on.
fn block_slots(
    block: &Block,
    slots_of: &BTreeMap<String, Vec<usize>>,
    body_deps: &BTreeMap<String, Vec<bool>>,
    n: usize,
) -> Vec<usize> {
    let mut uses = Uses::new(slots_of);
    uses.visit_block(block);
    uses.slots(slots_of, body_deps, n)
}

/// The coordinate slots a term can depend on: its own uses, and those of the values of the locals
/// it names, transitively.
fn term_slots(
    term: &Expr,
    locals: &BTreeMap<String, Expr>,
    slots_of: &BTreeMap<String, Vec<usize>>,
    body_deps: &BTreeMap<String, Vec<bool>>,
    n: usize,
) -> Vec<usize> {
    let mut uses = Uses::new(slots_of);
    uses.visit_expr(term);
    let mut seen = BTreeSet::new();
    let mut pending: Vec<String> = uses.whole.iter().cloned().collect();
    while let Some(name) = pending.pop() {
        if !seen.insert(name.clone()) {
            continue;
        }
        if let Some(value) = locals.get(&name) {
            let mut inner = Uses::new(slots_of);
            inner.visit_expr(value);
            uses.elements.extend(inner.elements);
            uses.opaque |= inner.opaque;
            pending.extend(inner.whole.iter().cloned());
            uses.whole.extend(inner.whole);
        }
    }
    uses.slots(slots_of, body_deps, n)
}

/// The block's `let`s as name → value (a tuple pattern bound to a tuple of the same length, by
/// position; any other tuple pattern, each name to the whole value). `None` when the block has a
/// statement other than simple `let`s and its final value, a `return`, or a name bound twice: it
/// is not split.
fn local_values(block: &Block) -> Option<BTreeMap<String, Expr>> {
    if names::first_return(block).is_some() {
        return None;
    }
    let mut locals = BTreeMap::new();
    let (value, lets) = block.stmts.split_last()?;
    if !matches!(value, Stmt::Expr(_, None)) {
        return None;
    }
    for stmt in lets {
        let Stmt::Local(local) = stmt else {
            return None;
        };
        let init = local.init.as_ref().filter(|i| i.diverge.is_none())?;
        match strip_type(&local.pat) {
            Pat::Ident(ident) if ident.subpat.is_none() => {
                // A name bound twice would resolve to its last value only: not split.
                if locals
                    .insert(ident.ident.to_string(), (*init.expr).clone())
                    .is_some()
                {
                    return None;
                }
            }
            Pat::Tuple(tuple) => {
                let parts = match &*init.expr {
                    Expr::Tuple(t) if t.elems.len() == tuple.elems.len() => {
                        t.elems.iter().cloned().collect()
                    }
                    other => vec![other.clone(); tuple.elems.len()],
                };
                for (pat, value) in tuple.elems.iter().zip(parts) {
                    let Pat::Ident(ident) = strip_type(pat) else {
                        return None;
                    };
                    if locals.insert(ident.ident.to_string(), value).is_some() {
                        return None;
                    }
                }
            }
            _ => return None,
        }
    }
    Some(locals)
}

/// `x: f64` as a pattern: the `x`.
fn strip_type(pat: &Pat) -> &Pat {
    match pat {
        Pat::Type(typed) => &typed.pat,
        other => other,
    }
}

/// The block once per term of its value's sum ([`terms`]), each with the block's `let`s; `None`
/// when the value is a single term.
fn terms_of(
    block: &Block,
    locals: Option<&BTreeMap<String, Expr>>,
    parameters: &BTreeSet<String>,
) -> Option<Vec<Block>> {
    let locals = locals?;
    let Some(Stmt::Expr(value, None)) = block.stmts.last() else {
        return None;
    };
    let parts = terms(value, &Scope { locals, parameters });
    (parts.len() > 1).then(|| {
        parts
            .into_iter()
            .map(|term| {
                let mut part = block.clone();
                *part.stmts.last_mut().unwrap() = Stmt::Expr(term, None);
                part
            })
            .collect()
    })
}

/// The terms of a sum: split at top-level `+` and `−` (a subtracted term negated), through
/// parentheses, and through a product with, or a quotient by, a factor that names no local and
/// no name of the declaration but parameters and constants (distributed over each term).
fn terms(expr: &Expr, scope: &Scope) -> Vec<Expr> {
    match expr {
        Expr::Paren(p) => terms(&p.expr, scope),
        Expr::Binary(b) => {
            let (lhs, rhs) = (&*b.left, &*b.right);
            match b.op {
                BinOp::Add(_) => [terms(lhs, scope), terms(rhs, scope)].concat(),
                BinOp::Sub(_) => {
                    let mut out = terms(lhs, scope);
                    out.extend(
                        terms(rhs, scope)
                            .into_iter()
                            .map(|t| syn::parse_quote!(-(#t))),
                    );
                    out
                }
                BinOp::Mul(_) if constant(lhs, scope) => {
                    let factor = operand(lhs);
                    terms(rhs, scope)
                        .into_iter()
                        .map(|t| syn::parse_quote!(#factor * (#t)))
                        .collect()
                }
                BinOp::Mul(_) if constant(rhs, scope) => {
                    let factor = operand(rhs);
                    terms(lhs, scope)
                        .into_iter()
                        .map(|t| syn::parse_quote!((#t) * #factor))
                        .collect()
                }
                BinOp::Div(_) if constant(rhs, scope) => {
                    let divisor = operand(rhs);
                    terms(lhs, scope)
                        .into_iter()
                        .map(|t| syn::parse_quote!((#t) / #divisor))
                        .collect()
                }
                _ => vec![expr.clone()],
            }
        }
        _ => vec![expr.clone()],
    }
}

/// A constant factor as an operand: a literal or a name as written (so the lifting of literals to
/// the scalar type still sees a literal), anything else in parentheses.
fn operand(expr: &Expr) -> Expr {
    match expr {
        Expr::Lit(_) | Expr::Path(_) => expr.clone(),
        _ => syn::parse_quote!((#expr)),
    }
}

/// Whether `expr` is a constant factor: no macro, and every name in it a parameter (a local of
/// the block, a coordinate, a body, `t` or a module constant makes it not one, conservatively).
fn constant(expr: &Expr, scope: &Scope) -> bool {
    let no_arrays = BTreeMap::new();
    let mut uses = Uses::new(&no_arrays);
    uses.visit_expr(expr);
    !uses.opaque
        && names::free_names_of_expr(expr).iter().all(|name| {
            let name = name.to_string();
            !scope.locals.contains_key(&name) && scope.parameters.contains(&name)
        })
}

/// What [`terms`] reads a sum in: the block's locals and the declaration's parameters.
struct Scope<'a> {
    locals: &'a BTreeMap<String, Expr>,
    parameters: &'a BTreeSet<String>,
}

/// The names a block uses, with the literal-indexed elements of array coordinates apart.
struct Uses<'m> {
    arrays: &'m BTreeMap<String, Vec<usize>>,
    /// Slots named as `array[literal]`.
    elements: BTreeSet<usize>,
    /// Names used otherwise (coordinates, bodies, anything else).
    whole: BTreeSet<String>,
    /// Whether the block holds tokens that are not read (a macro invocation).
    opaque: bool,
}

impl<'m> Uses<'m> {
    fn new(arrays: &'m BTreeMap<String, Vec<usize>>) -> Self {
        Uses {
            arrays,
            elements: BTreeSet::new(),
            whole: BTreeSet::new(),
            opaque: false,
        }
    }

    /// The coordinate slots (sorted) the uses can depend on: the elements, every slot of a
    /// coordinate used whole, a body's dependencies; all N when something was not read.
    fn slots(
        &self,
        slots_of: &BTreeMap<String, Vec<usize>>,
        body_deps: &BTreeMap<String, Vec<bool>>,
        n: usize,
    ) -> Vec<usize> {
        if self.opaque {
            return (0..n).collect();
        }
        let mut deps = vec![false; n];
        for &slot in &self.elements {
            deps[slot] = true;
        }
        for name in &self.whole {
            if let Some(slots) = slots_of.get(name) {
                slots.iter().for_each(|&j| deps[j] = true);
            } else if let Some(body) = body_deps.get(name) {
                deps.iter_mut().zip(body).for_each(|(d, &b)| *d |= b);
            }
        }
        (0..n).filter(|&j| deps[j]).collect()
    }
}

impl<'ast> Visit<'ast> for Uses<'_> {
    fn visit_expr(&mut self, expr: &'ast Expr) {
        if let Expr::Index(index) = expr {
            let array = match &*index.expr {
                Expr::Path(p) => p.path.get_ident().map(|i| i.to_string()),
                _ => None,
            };
            let literal = match &*index.index {
                Expr::Lit(l) => match &l.lit {
                    Lit::Int(i) => i.base10_parse::<usize>().ok(),
                    _ => None,
                },
                _ => None,
            };
            if let (Some(array), Some(k)) = (array, literal) {
                if let Some(slots) = self.arrays.get(&array).filter(|s| s.len() > 1) {
                    if let Some(&slot) = slots.get(k) {
                        self.elements.insert(slot);
                        return;
                    }
                }
            }
        }
        if let Expr::Path(p) = expr {
            if let Some(ident) = p.path.get_ident() {
                self.whole.insert(ident.to_string());
            }
        }
        visit::visit_expr(self, expr);
    }

    fn visit_macro(&mut self, _: &'ast syn::Macro) {
        self.opaque = true;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// (slots named element by element, other names, opaque) of a block, with `q` a 4-element
    /// array coordinate and `x` a scalar one.
    fn uses(src: &str) -> (Vec<usize>, Vec<String>, bool) {
        let arrays: BTreeMap<String, Vec<usize>> = [
            ("q".to_string(), vec![0, 1, 2, 3]),
            ("x".to_string(), vec![4]),
        ]
        .into();
        let block: syn::Block = syn::parse_str(src).unwrap();
        let mut u = Uses::new(&arrays);
        u.visit_block(&block);
        (
            u.elements.into_iter().collect(),
            u.whole.into_iter().collect(),
            u.opaque,
        )
    }

    #[test]
    fn literal_elements_are_read_apart() {
        let (elements, whole, opaque) = uses("{ let d = q[2] - q[1]; k * d * d + x }");
        assert_eq!(elements, vec![1, 2]);
        assert!(whole.contains(&"x".to_string()) && !whole.contains(&"q".to_string()));
        assert!(!opaque);
    }

    #[test]
    fn any_other_use_of_an_array_names_all_of_it() {
        // A computed index, the array passed whole, a method on it.
        for src in [
            "{ q[i] * k }",
            "{ helper(q) }",
            "{ q.iter().sum::<f64>() }",
            "{ q[1 + 0] }",
        ] {
            let (_, whole, _) = uses(src);
            assert!(whole.contains(&"q".to_string()), "{src}");
        }
    }

    /// The terms of `src` (an expression) as strings, with `k` a parameter and `d` a local.
    fn split(src: &str) -> Vec<String> {
        let expr: Expr = syn::parse_str(src).unwrap();
        let locals: BTreeMap<String, Expr> =
            [("d".to_string(), syn::parse_str("q[1]").unwrap())].into();
        let parameters: BTreeSet<String> = ["k".to_string()].into();
        let scope = Scope {
            locals: &locals,
            parameters: &parameters,
        };
        terms(&expr, &scope)
            .iter()
            .map(|t| quote::quote!(#t).to_string())
            .collect()
    }

    #[test]
    fn a_sum_is_read_term_by_term() {
        // Constant factors and divisors are distributed, a subtracted term negated.
        assert_eq!(
            split("k * (q[0] + q[1] * q[1]) / 2.0 - q[2]"),
            vec![
                "(k * (q [0])) / 2.0",
                "(k * (q [1] * q [1])) / 2.0",
                "- (q [2])"
            ]
        );
        // A factor naming a local, a coordinate or an unknown name is not distributed.
        assert_eq!(split("d * (q[0] + q[1])").len(), 1);
        assert_eq!(split("q[3] * (q[0] + q[1])").len(), 1);
        assert_eq!(split("LINKS * (q[0] + q[1])").len(), 1);
        // Nor is a product of two sums.
        assert_eq!(split("(q[0] + q[1]) * (q[2] + q[3])").len(), 1);
    }

    #[test]
    fn a_block_with_a_return_or_a_complex_let_is_not_split() {
        let block: Block =
            syn::parse_str("{ if q[0] > 0.0 { return q[0]; } q[1] + q[2] }").unwrap();
        assert!(local_values(&block).is_none());
        let block: Block = syn::parse_str("{ let [a, b] = [q[0], q[1]]; a + b }").unwrap();
        assert!(local_values(&block).is_none());
        // A name bound twice (its first value would be lost to the reading).
        let block: Block = syn::parse_str("{ let d = q[0]; let d = d * q[1]; d + q[2] }").unwrap();
        assert!(local_values(&block).is_none());
        let block: Block = syn::parse_str("{ let (a, b) = (q[0], q[1]); a + b }").unwrap();
        let locals = local_values(&block).unwrap();
        let b = &locals["b"];
        assert_eq!(quote::quote!(#b).to_string(), "q [1]");
    }

    #[test]
    fn a_macro_makes_the_block_opaque() {
        assert!(uses("{ some_macro!(q[0]) }").2);
    }
}
