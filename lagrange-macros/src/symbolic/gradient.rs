//! The gradient of the potential's parts read as expression trees ([`super::read_tree`]),
//! differentiated on the tree ([`super::expr`]) and written out as straight-line code that adds
//! into `Model::potential_gradient`'s `__gradient`.
//!
//! A part names coordinates and rows of x. Its gradient is ∇V = ∂V/∂q + Jᵀ ∂V/∂x (the chain
//! rule, as `lagrange_core::dynamics::potential_forces` takes it on dual numbers): a coordinate's
//! derivative adds to its own slot, a row's is multiplied by the row of J (when the caller has
//! one) on the slots the row can depend on ([`crate::components::dependencies`]).

use super::expr::{Graph, Id, Variable, MAX_NODES};
use super::read_tree::Reader;
use crate::check::Model;
use proc_macro2::{Literal, TokenStream};
use quote::quote;
use syn::Block;

/// The derivatives of one part: (variable, ∂V/∂variable), zero ones left out.
pub struct PartGradient(Vec<(Variable, Id)>);

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
            let d = self.graph.latency_ordered(d);
            if !self.graph.is_zero(d) {
                derivatives.push((v, d));
            }
        }
        (self.graph.len() <= MAX_NODES).then_some(PartGradient(derivatives))
    }

    /// The code adding every part's gradient to `__gradient` (on scalar `__S`, from `__q`, `__x`,
    /// `__rows`): the parameters the constants name in `f64`, one `let` per node, then the sums.
    pub fn emit(&self, model: &Model, parts: &[&PartGradient]) -> TokenStream {
        let outputs: Vec<Id> = parts
            .iter()
            .flat_map(|p| p.0.iter().map(|&(_, d)| d))
            .collect();
        let (p, s) = (crate::expand::private(), quote!(__S));
        let lets = self.graph.emit(&outputs, &s);
        let params = model.params.iter().map(|p| &p.ident);
        let (row_deps, _) = crate::components::dependencies(model);
        let adds = parts.iter().flat_map(|part| &part.0).map(|&(variable, d)| {
            // g −= a for a derivative −a.
            let (op, d) = match self.graph.negation_of(d) {
                Some(a) => (quote!(-=), a),
                None => (quote!(+=), d),
            };
            let d = self.graph.scalar(d, &s);
            match variable {
                Variable::Coordinate(j) => {
                    let j = Literal::usize_unsuffixed(j);
                    quote!(__gradient[#j] #op #d;)
                }
                // Left out above: the gradient is by q.
                Variable::Time => quote!(),
                Variable::Row(r) => {
                    let slots = (0..model.dof())
                        .filter(|&j| row_deps[r][j])
                        .map(Literal::usize_unsuffixed);
                    let r = Literal::usize_unsuffixed(r);
                    quote! {
                        if let #p::core::option::Option::Some(__row) = &__rows[#r] {
                            let __dv: __S = #d;
                            #(__gradient[#slots] #op __dv * __row[#slots];)*
                        }
                    }
                }
            }
        });
        quote! {
            {
                #( let #params: f64 = self.#params; )*
                #lets
                #(#adds)*
            }
        }
    }
}
