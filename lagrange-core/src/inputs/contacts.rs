//! The contact mode of a declaration with inputs ([`DrivenContacts`]): the declaration's
//! [`ContactState`] evaluated on the declaration with the inputs of the call held
//! ([`WithInputs`]), so a time loop holding the mode over a step — inferring it, stepping its
//! accelerations, projecting, evaluating its event functions and switching it — sees the inputs
//! the outer call holds, as every other evaluation does.

use super::{ActuatedModel, WithInputs};
use crate::constraints::ModeChange;
use crate::constraints::{ConstraintCounts, Constraints, ContactModel, ContactState, Mode};
use crate::error::Result;
use crate::evaluation::{Constants, Prepare};
use crate::geometry::Scalar;

/// The contact mode of a declaration with `NU` inputs and `C` constraint rows over `K` Cartesian
/// coordinates: a [`ContactState`] whose every evaluation reads the model with the inputs of the
/// [`Constants`] it is handed ([`WithInputs::held`]; zeros where there are none), the prepared
/// constants passed on. What `#[mechanism]` names as `Dynamics::Contacts` for a declaration with
/// `#[inputs]` and constraint rows; everything but the forces is the [`ContactState`]'s.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DrivenContacts<const K: usize, const C: usize, const NU: usize>(ContactState<K, C>);

impl<const K: usize, const C: usize, const NU: usize> DrivenContacts<K, C, NU> {
    /// The mode.
    pub fn mode(&self) -> Mode<C> {
        self.0.mode()
    }
}

/// `model` with the inputs `constants` hold, and the constants left to hand it: the prepared
/// ones (the inputs are now the model's).
#[inline(always)]
fn held<'a, M: Prepare, const NU: usize>(
    model: &'a M,
    constants: Constants<'a, M>,
) -> (
    WithInputs<'a, M, f64, NU>,
    Constants<'a, WithInputs<'a, M, f64, NU>>,
) {
    let prepared = Constants {
        prepared: constants.prepared,
        inputs: &[],
    };
    (WithInputs::held(model, constants.inputs), prepared)
}

impl<M, const N: usize, const K: usize, const C: usize, const NU: usize> ContactModel<M, N>
    for DrivenContacts<K, C, NU>
where
    M: ActuatedModel<N, K, NU> + Constraints<N, K, C> + Prepare,
{
    const SWITCHES: bool = <ContactState<K, C> as ContactModel<M, N>>::SWITCHES;
    const HELD_COUNTS: ConstraintCounts = <ContactState<K, C> as ContactModel<M, N>>::HELD_COUNTS;
    type Values = [f64; C];
    type Rows = [bool; C];

    fn start(
        model: &M,
        constants: Constants<'_, M>,
        t: f64,
        q: &[f64; N],
        v: &[f64; N],
    ) -> Result<Self> {
        let (model, constants) = held::<M, NU>(model, constants);
        ContactState::start(&model, constants, t, q, v).map(DrivenContacts)
    }
    fn idle() -> Self {
        DrivenContacts(<ContactState<K, C> as ContactModel<M, N>>::idle())
    }
    fn refresh(
        &mut self,
        model: &M,
        constants: Constants<'_, M>,
        t: f64,
        q: &[f64; N],
        v: &[f64; N],
        span: f64,
    ) -> Result<()> {
        let (model, constants) = held::<M, NU>(model, constants);
        self.0.refresh(&model, constants, t, q, v, span)
    }
    #[inline]
    fn accelerations<S: Scalar>(
        &self,
        model: &M,
        constants: Constants<'_, M>,
        t: S,
        q: &[S; N],
        v: &[S; N],
    ) -> Result<[S; N]> {
        let (model, constants) = held::<M, NU>(model, constants);
        self.0.accelerations(&model, constants, t, q, v)
    }
    fn project(
        &self,
        model: &M,
        constants: Constants<'_, M>,
        t: f64,
        q: &mut [f64; N],
        v: &mut [f64; N],
    ) -> Result<()> {
        let (model, constants) = held::<M, NU>(model, constants);
        self.0.project(&model, constants, t, q, v)
    }
    fn held_positions<S: Scalar>(
        &self,
        model: &M,
        constants: Constants<'_, M>,
        t: S,
        q: &[S; N],
    ) -> [S; N] {
        let (model, constants) = held::<M, NU>(model, constants);
        self.0.held_positions(&model, constants, t, q)
    }
    fn held_position_rows(&self) -> usize {
        <ContactState<K, C> as ContactModel<M, N>>::held_position_rows(&self.0)
    }
    fn event_values(
        &self,
        model: &M,
        constants: Constants<'_, M>,
        t: f64,
        q: &[f64; N],
        v: &[f64; N],
    ) -> Result<[f64; C]> {
        let (model, constants) = held::<M, NU>(model, constants);
        self.0.event_values(&model, constants, t, q, v)
    }
    fn triggered(
        &self,
        model: &M,
        constants: Constants<'_, M>,
        t: f64,
        q: &[f64; N],
        v: &[f64; N],
        end: &[f64; C],
    ) -> [bool; C] {
        let (model, constants) = held::<M, NU>(model, constants);
        self.0.triggered(&model, constants, t, q, v, end)
    }
    fn rearm(&mut self, end: &[f64; C]) {
        <ContactState<K, C> as ContactModel<M, N>>::rearm(&mut self.0, end)
    }
    fn switch(
        &mut self,
        model: &M,
        constants: Constants<'_, M>,
        restitution: f64,
        t: f64,
        state: (&mut [f64; N], &mut [f64; N]),
        row: usize,
    ) -> Result<ModeChange> {
        let (model, constants) = held::<M, NU>(model, constants);
        self.0.switch(&model, constants, restitution, t, state, row)
    }
}
