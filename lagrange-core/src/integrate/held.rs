//! A mechanism with its contact mode held over a step ([`HeldMode`]): what the fixed-step loop
//! hands a one-step method, so every [`Integrator`](super::Integrator) steps contacts.

use crate::constraints::{ConstraintCounts, ContactModel};
use crate::error::Result;
use crate::evaluation::{Constants, Dynamics, Evaluate, Prepare};
use crate::geometry::Scalar;

/// A constrained mechanism whose contact mode is held: its accelerations are those of the mode
/// ([`ContactModel::accelerations`]: the mode's rows enforced as equalities, its sliding friction
/// a known force), its projection the mode's, everything else the mechanism's. While the mode is
/// held its enforced rows are bilateral, which is what it declares to the integrators
/// ([`ContactModel::HELD_COUNTS`]): constraint rows that every stage carries the force of (never
/// unilateral or friction rows, which they would refuse). To RATTLE
/// ([`StormerVerlet`](crate::StormerVerlet), [`Variational`](crate::Variational)) it hands the
/// position rows the mode enforces: the holonomic rows and the closed contacts, in declaration
/// order ([`ContactModel::held_positions`]). It evaluates with the constants of the call that holds
/// the mode (a driven mechanism's inputs, a validated handle's prepared constants), which it
/// hands the mode's every evaluation.
pub(super) struct HeldMode<'m, M: Prepare, X> {
    pub(super) model: &'m M,
    pub(super) constants: Constants<'m, M>,
    pub(super) contacts: X,
}

impl<M: Dynamics<N>, X: ContactModel<M, N>, const N: usize> Evaluate<N> for HeldMode<'_, M, X> {
    type Model = M;
    type Coords = M::Coords;
    const CONSTRAINT_COUNTS: Option<ConstraintCounts> = Some(X::HELD_COUNTS);
    const CONSTRAINTS: Option<usize> = Some(X::HELD_COUNTS.rows());
    const ONE_BRANCH: bool = false;

    #[inline(always)]
    fn model(&self) -> &M {
        self.model
    }
    /// The outer call's.
    #[inline(always)]
    fn prepared(&self) -> Constants<'_, M> {
        self.constants
    }
    #[inline]
    fn accelerations_at<S: Scalar>(&self, t: S, q: &[S; N], v: &[S; N]) -> Result<[S; N]> {
        self.contacts
            .accelerations(self.model, self.constants, t, q, v)
    }
    #[inline]
    fn regular_accelerations_at(&self, _: f64, _: &[f64; N], _: &[f64; N]) -> Option<[f64; N]> {
        None
    }
    fn holonomic_constraints_at<S: Scalar>(&self, t: S, q: &[S; N]) -> Option<[S; N]> {
        Some(
            self.contacts
                .held_positions(self.model, self.constants, t, q),
        )
    }
    fn enforced_holonomic_rows(&self) -> Option<usize> {
        Some(self.contacts.held_position_rows())
    }
    fn project(&self, t: f64, q: &mut [f64; N], v: &mut [f64; N]) -> Result<()> {
        self.contacts.project(self.model, self.constants, t, q, v)
    }
    /// The loop holding the mode checked the state before the step.
    fn check_constraints(&self, _: f64, _: &[f64; N], _: &[f64; N]) -> Result<()> {
        Ok(())
    }
    /// The loop holding the mode checked the declaration before the step.
    fn check_declaration_at(&self, _: f64, _: &[f64; N], _: &[f64; N]) -> Result<()> {
        Ok(())
    }
}
