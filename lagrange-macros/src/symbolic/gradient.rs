//! The gradient of the potential's parts read as expression trees ([`super::read_tree`]),
//! differentiated on the tree ([`super::expr`]) and written out as straight-line code that adds
//! into `Model::potential_gradient`'s `__gradient`.
//!
//! A part names coordinates and rows of x. Its gradient is ∇V = ∂V/∂q + Jᵀ ∂V/∂x (the chain
//! rule, as `lagrange_core::dynamics::potential_forces` takes it on dual numbers): a coordinate's
//! derivative adds to its own slot, a row's is multiplied by the row of J (when the caller has
//! one) on the slots the row can depend on ([`crate::components::dependencies`]).

use super::expr::{Graph, Id, Node, TokenStream2, Variable, MAX_NODES};
use super::read_tree::Reader;
use crate::check::Model;
use proc_macro2::{Literal, TokenStream};
use quote::quote;
use std::collections::HashMap;
use syn::Block;

/// At most this many coefficients are prepared (`lagrange_core::model::GRADIENT_COEFFICIENTS`).
pub const COEFFICIENTS: usize = 16;

/// The derivatives of one part: (variable, ∂V/∂variable, sⱼ ∂V/∂qⱼ for a coordinate qⱼ), zero
/// ones left out. sⱼ is the scale `__scale[j]` of `Model::scaled_potential_gradient`, a constant
/// factor joined to the derivative's others.
pub struct PartGradient(Vec<(Variable, Id, Id)>);

/// The parts' gradients in one graph (a node shared between parts is computed once).
#[derive(Default)]
pub struct Gradients {
    graph: Graph,
}

impl Gradients {
    /// The gradient of a part's block, or `None` when it is not read (or would be too large):
    /// the part keeps its dual numbers.
    pub fn part(&mut self, model: &Model, block: &Block) -> Option<PartGradient> {
        let value = Reader::new(model, &mut self.graph).potential(block)?;
        let mut derivatives = Vec::new();
        // Time is no variable of the gradient.
        for v in self
            .graph
            .variables(value)
            .into_iter()
            .filter(|&v| v != Variable::Time)
        {
            let d = self.graph.derivative(value, v);
            if self.graph.is_zero(d) {
                continue;
            }
            let scaled = match v {
                Variable::Coordinate(j) => {
                    let j = Literal::usize_unsuffixed(j);
                    let scale = self
                        .graph
                        .node(Node::Constant(TokenStream2::new(quote!(__scale[#j]))));
                    let product = self.graph.mul(scale, d);
                    self.graph.latency_ordered(product)
                }
                // Scaled where it is added by its row of J.
                _ => self.graph.latency_ordered(d),
            };
            derivatives.push((v, self.graph.latency_ordered(d), scaled));
        }
        (self.graph.len() <= MAX_NODES).then_some(PartGradient(derivatives))
    }

    /// The code adding every part's gradient to `__gradient` (on scalar `__S`, from `__q`, `__x`,
    /// `__rows`): the parameters the constants name in `f64`, one `let` per node, then the sums.
    ///
    /// `scaled`: each slot j times `__scale[j]` (an `&[f64; N]`). A slot that one derivative
    /// alone adds to, not shared with another slot (Kepler's x), takes the scale among that
    /// derivative's constant factors (or its row of J's entry), so no product waits for the sum;
    /// any other slot (a mass between two springs; the two ends of one spring, whose derivatives
    /// are one value and its negation) is multiplied once its sum is done, as many products as
    /// the solve by a diagonal M would take.
    ///
    /// With `scaled`, also the code of the coefficients: the constants the gradient's code takes
    /// ([`Graph::coefficients`], at most [`COEFFICIENTS`] of them, the rest computed where used)
    /// computed from the parameters and `__scale` into `__coefficients`, which the gradient's
    /// code reads as `__prepared`.
    pub fn emit(
        &self,
        model: &Model,
        parts: &[&PartGradient],
        scaled: bool,
    ) -> (TokenStream, Option<TokenStream>) {
        let (row_deps, _) = crate::components::dependencies(model);
        let terms: Vec<&Term> = parts.iter().flat_map(|part| &part.0).collect();
        let folded = match scaled {
            true => self.folded_slots(&row_deps, &terms, model.dof()),
            false => vec![false; model.dof()],
        };
        let pick = |&(variable, d, scaled): &Term| match variable {
            Variable::Coordinate(j) if folded[j] => scaled,
            _ => d,
        };
        let outputs: Vec<Id> = terms.iter().map(|&term| pick(term)).collect();
        let mut prepared = match scaled {
            true => self.graph.coefficients(&outputs),
            false => Vec::new(),
        };
        prepared.truncate(COEFFICIENTS);
        let lets = self.graph.emit_prepared(&outputs, &quote!(__S), &prepared);
        let params: proc_macro2::TokenStream = model.params.iter().map(|f| f.bind_f64()).collect();
        let coefficients = scaled.then(|| self.coefficients(&params, &prepared));
        let adds = terms
            .iter()
            .map(|&term| self.add(term.0, pick(term), &row_deps, &folded));
        let sums_scaled = (0..model.dof()).filter(|&j| scaled && !folded[j]).map(|j| {
            let j = Literal::usize_unsuffixed(j);
            quote!(__gradient[#j] *= __scale[#j];)
        });
        let gradient = quote! {
            {
                #params
                #lets
                #(#adds)*
                #(#sums_scaled)*
            }
        };
        (gradient, coefficients)
    }

    /// Which slots take their scale among one derivative's constant factors: those one
    /// derivative alone adds to, that derivative adding to no other slot (a derivative and its
    /// negation counted as one).
    fn folded_slots(&self, row_deps: &[Vec<bool>], terms: &[&Term], n: usize) -> Vec<bool> {
        let node = |d: Id| self.graph.negation_of(d).unwrap_or(d);
        // How many derivatives add to each slot, and how many slots each derivative adds to.
        let (mut per_slot, mut per_node) = (vec![0usize; n], HashMap::<Id, usize>::new());
        for &&(variable, d, _) in terms {
            for j in slots(variable, row_deps) {
                per_slot[j] += 1;
                *per_node.entry(node(d)).or_default() += 1;
            }
        }
        let alone = |j: usize, d: Id| per_slot[j] == 1 && per_node[&node(d)] == 1;
        (0..n)
            .map(|j| {
                terms.iter().any(|&&(variable, d, _)| match variable {
                    Variable::Coordinate(k) => k == j && alone(j, d),
                    Variable::Row(r) => row_deps[r][j] && alone(j, d),
                    Variable::Time => false,
                })
            })
            .collect()
    }

    /// `__coefficients[i] = cᵢ` in `f64` from the parameters (and `__scale`).
    fn coefficients(&self, params: &TokenStream, prepared: &[Id]) -> TokenStream {
        let f64 = quote!(f64);
        let lets = self.graph.emit(prepared, &f64);
        let values = prepared.iter().enumerate().map(|(i, &c)| {
            let i = Literal::usize_unsuffixed(i);
            let value = match self.graph.negation_of(c) {
                Some(a) => {
                    let a = self.graph.scalar(a, &f64);
                    quote!(-#a)
                }
                None => self.graph.scalar(c, &f64),
            };
            quote!(__coefficients[#i] = #value;)
        });
        quote! {
            #params
            #lets
            #(#values)*
        }
    }

    /// One derivative `d` added to `__gradient`: to its coordinate's slot, or (for a row of x)
    /// times the row of J on the slots the row can depend on, when the caller has the row.
    fn add(
        &self,
        variable: Variable,
        d: Id,
        row_deps: &[Vec<bool>],
        folded: &[bool],
    ) -> TokenStream {
        // g −= a for a derivative −a.
        let (op, d) = match self.graph.negation_of(d) {
            Some(a) => (quote!(-=), a),
            None => (quote!(+=), d),
        };
        let d = self.graph.scalar(d, &quote!(__S));
        match variable {
            Variable::Coordinate(j) => {
                let j = Literal::usize_unsuffixed(j);
                quote!(__gradient[#j] #op #d;)
            }
            // Left out above: the gradient is by q.
            Variable::Time => quote!(),
            Variable::Row(r) => {
                let adds = slots(variable, row_deps).map(|j| {
                    let slot = Literal::usize_unsuffixed(j);
                    // sⱼ joins the row's constant entry, off the path from the state.
                    match folded[j] {
                        true => {
                            quote!(__gradient[#slot] #op __dv * (__row[#slot] * __scale[#slot]);)
                        }
                        false => quote!(__gradient[#slot] #op __dv * __row[#slot];),
                    }
                });
                let (p, r) = (crate::expand::private(), Literal::usize_unsuffixed(r));
                quote! {
                    if let #p::core::option::Option::Some(__row) = &__rows[#r] {
                        let __dv: __S = #d;
                        #(#adds)*
                    }
                }
            }
        }
    }
}

/// One derivative of a part: (variable, ∂V/∂variable, its scaled form), see [`PartGradient`].
type Term = (Variable, Id, Id);

/// The slots a derivative by `variable` adds to: a coordinate's own, the ones a row can depend on,
/// none for time.
fn slots(variable: Variable, row_deps: &[Vec<bool>]) -> impl Iterator<Item = usize> + '_ {
    let (row, own) = match variable {
        Variable::Coordinate(j) => (None, Some(j)),
        Variable::Row(r) => (Some(&row_deps[r]), None),
        Variable::Time => (None, None),
    };
    let in_row = row
        .into_iter()
        .flat_map(|deps| (0..deps.len()).filter(move |&j| deps[j]));
    own.into_iter().chain(in_row)
}
