//! The one-call integrations with contacts: `integrate_contacts` of [`Dopri5`], [`Dop853`] and
//! [`Radau5`] over a [`ContactAdaptive`] solver, and what the mechanism's hidden
//! `Dynamics::integrate_contacts` hook does, through which their `integrate` take that solver
//! for a declaration with unilateral or friction rows.

// `!(x >= y)` is deliberate: it also rejects NaN.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use super::{Constraints, ContactAdaptive, ContactOptions, ModeChange};
use crate::error::{Error, Result};
use crate::integrate::{Dop853, Dopri5, EmbeddedPair, Event, Observation, Outcome, Radau5};
use crate::integrate::{Stepper, StopReason};
use crate::model::State;

/// [`Dopri5::integrate_contacts`], [`Dop853::integrate_contacts`] and
/// [`Radau5::integrate_contacts`].
#[allow(clippy::type_complexity)]
fn integrate_contacts<
    P: EmbeddedPair,
    M: Constraints<N, K, C>,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    method: P,
    model: &M,
    state: &mut State<M::Coords>,
    t_end: f64,
    options: ContactOptions,
    events: &mut [Event<'_, M::Coords>],
    observer: impl FnMut(Observation<'_, M::Coords, N>),
) -> Result<(Outcome<M::Coords>, Vec<ModeChange>)> {
    if !(t_end.is_finite() && t_end >= state.t) {
        return Err(Error::InvalidEndTime { t: state.t, t_end });
    }
    let mut solver = ContactAdaptive::new(model, method, state, options)?;
    let outcome = solver.integrate(t_end, events, observer)?;
    *state = match outcome.reason {
        StopReason::Event(hit) => hit.state,
        _ => solver.state(),
    };
    Ok((outcome, solver.contact.events))
}

/// What the `Dynamics::integrate_contacts` hook of a constrained mechanism does: integrates with
/// the contact mode held per step ([`ContactAdaptive`], default [`ContactOptions`]) when the
/// declaration has unilateral or friction rows, and returns `None` otherwise (bilateral rows are
/// smooth: the method's own stepper integrates them).
#[doc(hidden)]
#[allow(clippy::type_complexity)]
pub fn integrate_declared_contacts<
    P: EmbeddedPair,
    M: Constraints<N, K, C>,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    method: P,
    model: &M,
    state: &mut State<M::Coords>,
    t_end: f64,
    events: &mut [Event<'_, M::Coords>],
    observer: impl FnMut(Observation<'_, M::Coords, N>),
) -> Option<Result<Outcome<M::Coords>>> {
    let counts = super::ConstraintCounts::of(&M::KINDS);
    if counts.unilateral + counts.friction == 0 {
        return None;
    }
    Some(
        integrate_contacts(
            method,
            model,
            state,
            t_end,
            ContactOptions::default(),
            events,
            observer,
        )
        .map(|(outcome, _)| outcome),
    )
}

impl Dopri5 {
    /// Integrates a mechanism with unilateral contacts or friction from `state` to `t_end` with the
    /// mode changes located ([`ContactDopri5`](super::ContactDopri5)), calling `observer` after every step and for every
    /// located user event, as [`Dopri5::integrate`] does. On success `state` is the final state; on
    /// error it is unchanged. Returns the outcome and the mode changes.
    ///
    /// ```
    /// use lagrange_core::constraints::{ConstraintKind, ContactOptions, Constraints, RowMode};
    /// use lagrange_core::integrate::Dopri5;
    /// use lagrange_core::{Model, Scalar, State};
    ///
    /// /// A unit mass falling onto the floor y ≥ 0, bouncing with restitution ½.
    /// struct Ball;
    /// impl Model<1, 1> for Ball {
    ///     type Coords = [f64; 1];
    ///     const RHEONOMIC: bool = false;
    ///     const HAS_POTENTIAL: bool = true;
    ///     const HAS_FORCES: bool = false;
    ///     fn validate(&self) -> lagrange_core::Result<()> { Ok(()) }
    ///     fn masses(&self) -> [f64; 1] { [1.0] }
    ///     fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 1]) -> [D; 1] { [q[0]] }
    ///     fn potential<D: Scalar>(&self, _t: D, _q: &[D; 1], x: &[D; 1]) -> D { x[0] * 9.81 }
    /// }
    /// impl Constraints<1, 1, 1> for Ball {
    ///     const NAMES: [&'static str; 1] = ["floor"];
    ///     const KINDS: [ConstraintKind; 1] = [ConstraintKind::Unilateral];
    ///     fn position_constraints<D: Scalar>(&self, _t: D, q: &[D; 1], _x: &[D; 1]) -> [D; 1] { [q[0]] }
    /// }
    ///
    /// let mut s = State::new(0.0, [1.0], [0.0]);
    /// let options = ContactOptions { restitution: 0.5, ..Default::default() };
    /// let (outcome, changes) =
    ///     Dopri5::new(1e-10, 1e-10).integrate_contacts(&Ball, &mut s, 1.0, options, &mut [], |_| {})?;
    /// // Lands at t₁ = √(2/g), leaves at half the speed and lands again 2·(½√(2g))/g later.
    /// let t1 = (2.0f64 / 9.81).sqrt();
    /// assert!((changes[0].t - t1).abs() < 1e-12 && changes[0].to == RowMode::Inactive);
    /// assert!((changes[1].t - 2.0 * t1).abs() < 1e-12);
    /// assert_eq!((s.t, outcome.stats.rejected), (1.0, 0));
    /// # Ok::<(), lagrange_core::Error>(())
    /// ```
    #[allow(clippy::type_complexity)]
    pub fn integrate_contacts<
        M: Constraints<N, K, C>,
        const N: usize,
        const K: usize,
        const C: usize,
    >(
        &self,
        model: &M,
        state: &mut State<M::Coords>,
        t_end: f64,
        options: ContactOptions,
        events: &mut [Event<'_, M::Coords>],
        observer: impl FnMut(Observation<'_, M::Coords, N>),
    ) -> Result<(Outcome<M::Coords>, Vec<ModeChange>)> {
        integrate_contacts(*self, model, state, t_end, options, events, observer)
    }
}

impl Dop853 {
    /// [`Dopri5::integrate_contacts`] with Dormand–Prince 8(5,3) ([`ContactDop853`](super::ContactDop853)).
    ///
    /// ```
    /// use lagrange_core::constraints::{ConstraintKind, ContactOptions, Constraints, RowMode};
    /// use lagrange_core::integrate::Dop853;
    /// use lagrange_core::{Model, Scalar, State};
    ///
    /// /// A unit mass falling onto the floor y ≥ 0.
    /// struct Ball;
    /// impl Model<1, 1> for Ball {
    ///     type Coords = [f64; 1];
    ///     const RHEONOMIC: bool = false;
    ///     const HAS_POTENTIAL: bool = true;
    ///     const HAS_FORCES: bool = false;
    ///     fn validate(&self) -> lagrange_core::Result<()> { Ok(()) }
    ///     fn masses(&self) -> [f64; 1] { [1.0] }
    ///     fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 1]) -> [D; 1] { [q[0]] }
    ///     fn potential<D: Scalar>(&self, _t: D, _q: &[D; 1], x: &[D; 1]) -> D { x[0] * 9.81 }
    /// }
    /// impl Constraints<1, 1, 1> for Ball {
    ///     const NAMES: [&'static str; 1] = ["floor"];
    ///     const KINDS: [ConstraintKind; 1] = [ConstraintKind::Unilateral];
    ///     fn position_constraints<D: Scalar>(&self, _t: D, q: &[D; 1], _x: &[D; 1]) -> [D; 1] { [q[0]] }
    /// }
    ///
    /// let mut s = State::new(0.0, [1.0], [0.0]);
    /// let (_, changes) = Dop853::new(1e-10, 1e-10)
    ///     .integrate_contacts(&Ball, &mut s, 1.0, ContactOptions::default(), &mut [], |_| {})?;
    /// // A plastic landing at √(2/g) (a quadratic: exact but for the root finder and round-off).
    /// assert!((changes[0].t - (2.0f64 / 9.81).sqrt()).abs() < 1e-12);
    /// assert_eq!((changes.len(), changes[0].to), (1, RowMode::Active));
    /// assert!(s.q[0].abs() < 1e-12 && s.t == 1.0);
    /// # Ok::<(), lagrange_core::Error>(())
    /// ```
    #[allow(clippy::type_complexity)]
    pub fn integrate_contacts<
        M: Constraints<N, K, C>,
        const N: usize,
        const K: usize,
        const C: usize,
    >(
        &self,
        model: &M,
        state: &mut State<M::Coords>,
        t_end: f64,
        options: ContactOptions,
        events: &mut [Event<'_, M::Coords>],
        observer: impl FnMut(Observation<'_, M::Coords, N>),
    ) -> Result<(Outcome<M::Coords>, Vec<ModeChange>)> {
        integrate_contacts(*self, model, state, t_end, options, events, observer)
    }
}

impl Radau5 {
    /// [`Dopri5::integrate_contacts`] with the implicit Radau IIA method of order 5
    /// ([`ContactRadau5`](super::ContactRadau5)), for stiff mechanisms with contacts.
    ///
    /// ```
    /// use lagrange_core::constraints::{ConstraintKind, ContactOptions, Constraints, RowMode};
    /// use lagrange_core::integrate::Radau5;
    /// use lagrange_core::{Model, Scalar, State};
    ///
    /// /// A unit mass falling onto the floor y ≥ 0, bouncing with restitution ½.
    /// struct Ball;
    /// impl Model<1, 1> for Ball {
    ///     type Coords = [f64; 1];
    ///     const RHEONOMIC: bool = false;
    ///     const HAS_POTENTIAL: bool = true;
    ///     const HAS_FORCES: bool = false;
    ///     fn validate(&self) -> lagrange_core::Result<()> { Ok(()) }
    ///     fn masses(&self) -> [f64; 1] { [1.0] }
    ///     fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 1]) -> [D; 1] { [q[0]] }
    ///     fn potential<D: Scalar>(&self, _t: D, _q: &[D; 1], x: &[D; 1]) -> D { x[0] * 9.81 }
    /// }
    /// impl Constraints<1, 1, 1> for Ball {
    ///     const NAMES: [&'static str; 1] = ["floor"];
    ///     const KINDS: [ConstraintKind; 1] = [ConstraintKind::Unilateral];
    ///     fn position_constraints<D: Scalar>(&self, _t: D, q: &[D; 1], _x: &[D; 1]) -> [D; 1] { [q[0]] }
    /// }
    ///
    /// let mut s = State::new(0.0, [1.0], [0.0]);
    /// let options = ContactOptions { restitution: 0.5, ..Default::default() };
    /// let (_, changes) =
    ///     Radau5::new(1e-10, 1e-10).integrate_contacts(&Ball, &mut s, 1.0, options, &mut [], |_| {})?;
    /// // Lands at t₁ = √(2/g), leaves at half the speed and lands again 2·(½√(2g))/g later: the
    /// // flights are quadratics, which the collocation polynomial reproduces exactly.
    /// let t1 = (2.0f64 / 9.81).sqrt();
    /// assert!((changes[0].t - t1).abs() < 1e-12 && changes[0].to == RowMode::Inactive);
    /// assert!((changes[1].t - 2.0 * t1).abs() < 1e-12);
    /// assert_eq!(s.t, 1.0);
    /// # Ok::<(), lagrange_core::Error>(())
    /// ```
    #[allow(clippy::type_complexity)]
    pub fn integrate_contacts<
        M: Constraints<N, K, C>,
        const N: usize,
        const K: usize,
        const C: usize,
    >(
        &self,
        model: &M,
        state: &mut State<M::Coords>,
        t_end: f64,
        options: ContactOptions,
        events: &mut [Event<'_, M::Coords>],
        observer: impl FnMut(Observation<'_, M::Coords, N>),
    ) -> Result<(Outcome<M::Coords>, Vec<ModeChange>)> {
        integrate_contacts(*self, model, state, t_end, options, events, observer)
    }
}

/// What the `Dynamics::step_contacts` hook of a constrained mechanism does: one step of `h` with
/// the fixed-step method `I`, the contact mode held over it and its switches located and applied
/// as [`ContactRk4`](super::ContactRk4) does ([`ContactRk4::step_with`](super::ContactRk4::step_with),
/// default [`ContactOptions`], the mode inferred from `state`), when the declaration has
/// unilateral or friction rows; `None` otherwise. On error `state` is unchanged.
#[doc(hidden)]
pub fn step_declared_contacts<I, M, const N: usize, const K: usize, const C: usize>(
    model: &M,
    state: &mut State<<M as crate::model::Model<N, K>>::Coords>,
    h: f64,
) -> Option<Result<()>>
where
    I: crate::integrate::Integrator,
    M: Constraints<N, K, C> + crate::mechanism::Mechanism<N>,
{
    let counts = super::ConstraintCounts::of(&M::KINDS);
    if counts.unilateral + counts.friction == 0 {
        return None;
    }
    let step = || {
        let mut contact = super::ContactRk4::new(model, state, ContactOptions::default())?;
        let mut next = *state;
        contact.step_with::<I, M, N, K>(model, &mut next, h)?;
        Ok(next)
    };
    Some(step().map(|next| *state = next))
}
