//! What [`Radau5`](super::Radau5) keeps from one step to the next.

use super::algebra::{Factors, Jacobians, Pair};
use crate::integrate::dense::DenseOutput;

/// What [`Radau5`](super::Radau5) keeps from one step to the next
/// ([`EmbeddedPair::Memory`](crate::integrate::EmbeddedPair::Memory)): the converted
/// tolerances, the proposed step and the controller's history, the Jacobian and factorisation
/// being reused, the Newton iteration's contraction estimates, and the last step's collocation
/// polynomial (the next iteration's starting values).
#[derive(Clone, Copy, Debug)]
pub struct Radau5Memory<const N: usize> {
    /// The converted tolerances (rtol′, atol′) and the Newton tolerance κ·tol.
    pub(super) rtol: f64,
    pub(super) atol: f64,
    pub(super) newton_tol: f64,
    pub(super) h: f64,
    pub(super) jacobians: Option<Jacobians<N>>,
    /// Whether the Jacobian was evaluated at the current point (no accepted step since).
    pub(super) jacobian_current: bool,
    pub(super) factors: Option<Factors<N>>,
    /// Contraction rate of the last Newton iteration, and η of HW II (8.10).
    pub(super) theta: f64,
    pub(super) faccon: f64,
    /// No step accepted yet.
    pub(super) first: bool,
    /// Gustafsson's controller: the last accepted step and its error.
    pub(super) h_acc: f64,
    pub(super) err_acc: f64,
    /// The last accepted step's collocation polynomial; `None` at the start and after the field
    /// changed (then the Newton iteration starts from Z = 0).
    pub(super) last: Option<DenseOutput<N>>,
}

impl<const N: usize> Radau5Memory<N> {
    /// After a failed attempt: a Jacobian not evaluated at the current point is evaluated anew.
    pub(super) fn renew_jacobian_if_old(&mut self) {
        if !self.jacobian_current {
            self.jacobians = None;
        }
    }

    /// scᵢ = atol′ + rtol′·|y₀ᵢ|.
    pub(super) fn scale(&self, y: &Pair<N>) -> Pair<N> {
        Pair {
            q: y.q.map(|x| self.atol + self.rtol * x.abs()),
            v: y.v.map(|x| self.atol + self.rtol * x.abs()),
        }
    }
}
