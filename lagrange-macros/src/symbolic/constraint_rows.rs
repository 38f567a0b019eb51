//! The derivatives of holonomic and unilateral rows g(q, t, x) read as expression trees
//! ([`super::read_tree`]), taken on the tree ([`super::expr`]) and written out as straight-line
//! code: `Constraints::position_constraint_derivatives`.
//!
//! With the partial derivatives ∂g/∂qⱼ, ∂g/∂xᵣ and ∂g/∂t of the tree (x's rows as variables of
//! their own), and derivatives along the motion q → q + s q̇, x → x + s ẋ, t → t + s at q̈ = 0
//! (the table of `lagrange_core::constraints`):
//!
//! ```text
//! Gⱼ = ∂g/∂qⱼ + Σᵣ (∂g/∂xᵣ) Jᵣⱼ,   ġ = d/ds g   (q̇, ẋ and 1 the rates of q, x and t),
//! β = d/ds ġ   with q̇ fixed, ẋᵣ moving at aᵣ (x's acceleration at q̈ = 0), t at 1,
//! ```
//!
//! the chain rule for g(q(s), t(s), x(q(s), t(s))) (Hairer & Wanner, *Solving Ordinary Differential
//! Equations II*, 2nd ed., §VII.1: the index-1 constraint G q̈ + β = 0 from g̈ = 0). Both are taken
//! forward on the tree ([`super::expr::Graph::along`]); for g = |r| − l that is G = r/|r|,
//! ġ = (r·ṙ)/|r| (the rate of the sum of squares is 2 r·ṙ, and √'s rule cancels the 2) and, ġ's
//! quotient differentiated once more with ṙ fixed, β = (|ṙ|² − ġ²)/|r|: the formula by hand.

use super::expr::{Graph, Id, Node, Variable, MAX_NODES};
use super::read_tree::Reader;
use crate::attr::Kind;
use crate::check::Model;
use proc_macro2::{Literal, TokenStream};
use quote::quote;

/// One row's derivatives: nodes of the shared graph.
struct Row {
    /// Its index among the constraint rows.
    index: usize,
    value: Id,
    /// Gⱼ for each coordinate slot (zero ones included: the row is written whole).
    gradient: Vec<Id>,
    rate: Id,
    bias: Id,
}

/// The position rows read as trees, with their derivatives in one graph (a node shared between
/// rows, x's row norms say, is computed once).
pub struct ConstraintDerivatives {
    graph: Graph,
    rows: Vec<Row>,
}

impl ConstraintDerivatives {
    /// The rows of `model`'s holonomic and unilateral items whose blocks are read, or `None` when
    /// none is (or the graph would be too large): the rows not read keep their dual numbers.
    pub fn of(model: &Model) -> Option<Self> {
        let mut graph = Graph::default();
        let (row_deps, _) = crate::components::dependencies(model);
        let mut rows = Vec::new();
        for (item, constraint) in model.constraints.iter().enumerate() {
            if !matches!(constraint.decl.kind(), Kind::Constraint | Kind::Unilateral) {
                continue;
            }
            let Some(value) = Reader::new(model, &mut graph).potential(&constraint.decl.block)
            else {
                continue;
            };
            let index = model.constraint_row(item);
            rows.push(derivatives(model, &mut graph, &row_deps, index, value));
        }
        (!rows.is_empty() && graph.len() <= MAX_NODES)
            .then_some(ConstraintDerivatives { graph, rows })
    }

    /// Whether each constraint row (of `count`) is written here.
    pub fn written(&self, count: usize) -> Vec<bool> {
        let mut written = vec![false; count];
        for row in &self.rows {
            written[row.index] = true;
        }
        written
    }

    /// The body of `position_constraint_derivatives` (on scalar `__S`, from `__t`, `__q`, `__v`,
    /// `__motion`, into `__out`): the parameters in `f64`, one `let` per node, then the rows.
    pub fn emit(&self, model: &Model) -> TokenStream {
        let s = quote!(__S);
        let outputs: Vec<Id> = self
            .rows
            .iter()
            .flat_map(|r| {
                [r.value, r.rate, r.bias]
                    .into_iter()
                    .chain(r.gradient.clone())
            })
            .collect();
        let lets = self.graph.emit(&outputs, &s);
        let params: proc_macro2::TokenStream = model.params.iter().map(|f| f.bind_f64()).collect();
        let p = crate::expand::private();
        let writes = self.rows.iter().map(|row| {
            let i = Literal::usize_unsuffixed(row.index);
            // The emitter names −a's operand, not −a: negated where it is used.
            let scalar = |id: Id| match self.graph.negation_of(id) {
                Some(a) => {
                    let a = self.graph.scalar(a, &s);
                    quote!(-#a)
                }
                None => self.graph.scalar(id, &s),
            };
            let (value, rate, bias) = (scalar(row.value), scalar(row.rate), scalar(row.bias));
            let gradient = row.gradient.iter().map(|&g| scalar(g));
            quote! {
                __out.value[#i] = #value;
                __out.rows[#i] = #p::nalgebra::SVector::from([#(#gradient),*]);
                __out.rate[#i] = #rate;
                __out.bias[#i] = #bias;
            }
        });
        quote! {
            #params
            let (__x, __x_dot, __x_accel, __jacobian) =
                (&__motion.x, &__motion.x_dot, &__motion.x_accel, &__motion.jacobian);
            #lets
            #(#writes)*
        }
    }
}

/// G, ġ and β of the row whose value is `value` (see the module docs).
fn derivatives(
    model: &Model,
    g: &mut Graph,
    row_deps: &[Vec<bool>],
    index: usize,
    value: Id,
) -> Row {
    let n = model.dof();
    // The partial derivatives, each with its variable's rate along the motion: q̇ for q, ẋ for x,
    // 1 for t (a scleronomic declaration's g cannot read t). β's direction moves ẋ at a as well,
    // q̇ fixed.
    let mut partials: Vec<(Variable, Id, Id)> = Vec::new();
    let mut second = Vec::new();
    for v in g.variables(value) {
        let leaf = g.leaf(v);
        let rate = match v {
            Variable::Coordinate(j) => g.node(Node::Velocity(j)),
            Variable::Row(r) => {
                let (velocity, acceleration) = (
                    g.node(Node::RowVelocity(r)),
                    g.node(Node::RowAcceleration(r)),
                );
                second.push((velocity, acceleration));
                velocity
            }
            Variable::Time => g.literal(if model.rheonomic { 1.0 } else { 0.0 }),
        };
        second.push((leaf, rate));
        let d = g.derivative(value, v);
        if !g.is_zero(d) {
            partials.push((v, d, rate));
        }
    }
    // Gⱼ = ∂g/∂qⱼ + Σᵣ (∂g/∂xᵣ) Jᵣⱼ, over the slots row r can depend on.
    let mut gradient: Vec<Id> = (0..n).map(|_| g.literal(0.0)).collect();
    for &(v, d, _) in &partials {
        match v {
            Variable::Coordinate(j) => gradient[j] = g.add(gradient[j], d),
            Variable::Row(r) => {
                for (j, slot) in gradient.iter_mut().enumerate() {
                    if row_deps[r][j] {
                        let entry = g.node(Node::Jacobian(r, j));
                        let term = g.mul(d, entry);
                        *slot = g.add(*slot, term);
                    }
                }
            }
            Variable::Time => {}
        }
    }
    // ġ by the chain rule along the motion (not G·q̇: for a distance, ġ = (r·ṙ)/|r| is then the
    // rate of |r| itself, which β's quotient rule meets again, β = (|ṙ|² − ġ²)/|r|).
    let first: Vec<(Id, Id)> = partials
        .iter()
        .map(|&(v, _, rate)| (g.leaf(v), rate))
        .collect();
    let along_motion = g.direction(&first);
    let rate = g.along(value, along_motion);
    let motion = g.direction(&second);
    let bias = g.along(rate, motion);
    Row {
        index,
        value,
        gradient,
        rate,
        bias,
    }
}
