//! [`ContactAdaptive`] ([`ContactDopri5`], [`ContactDop853`], [`ContactRadau5`]): an adaptive
//! method with the constraint mode held over each step and the mode changes located on the step's
//! dense output.

// `!(x > 0)` is deliberate: it also treats NaN as not positive.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use super::contact::{event_values, triggered_rows};
use super::{accelerations_in_mode, cone, project, Constraints, ContactOptions, ContactRk4};
use super::{Mode, ModeChange};
use crate::error::{Error, Result};
use crate::integrate::newton::jacobians_by_duals;
use crate::integrate::{AccelerationField, DenseOutput, Dop853, Dopri5, EmbeddedPair, Radau5};
use crate::integrate::{Stats, Stepper};
use crate::model::{check_state, Coordinates, State};
use nalgebra::SMatrix;

/// The accelerations of a constrained mechanism in a held [`Mode`] ([`accelerations_in_mode`]):
/// q̈ in `f64`, and its Jacobians by dual numbers through the same solve (exact for the mode:
/// the mode's rows enforced, its sliding directions and slip signs fixed).
pub(super) struct InMode<'m, M, const K: usize, const C: usize> {
    pub(super) model: &'m M,
    pub(super) mode: Mode<C>,
}

impl<M: Constraints<N, K, C>, const N: usize, const K: usize, const C: usize> AccelerationField<N>
    for InMode<'_, M, K, C>
{
    #[inline]
    fn accelerations(&self, t: f64, q: &[f64; N], v: &[f64; N]) -> Result<[f64; N]> {
        Ok(accelerations_in_mode(self.model, t, q, v, &self.mode)?.accelerations)
    }

    fn jacobians(
        &self,
        t: f64,
        q: &[f64; N],
        v: &[f64; N],
    ) -> Result<(SMatrix<f64, N, N>, SMatrix<f64, N, N>)> {
        let (_, by_q, by_v) = jacobians_by_duals(t, q, v, |t, q, v| {
            Ok(accelerations_in_mode(self.model, t, q, v, &self.mode)?.accelerations)
        })?;
        Ok((by_q, by_v))
    }
}

/// [`ContactAdaptive`] with Dormand–Prince 5(4).
pub type ContactDopri5<'m, M, const N: usize, const K: usize, const C: usize> =
    ContactAdaptive<'m, Dopri5, M, N, K, C>;

/// [`ContactAdaptive`] with Dormand–Prince 8(5,3) (its dense output of order 7 unless
/// `dense: false`, which locates events on the cubic Hermite interpolant).
pub type ContactDop853<'m, M, const N: usize, const K: usize, const C: usize> =
    ContactAdaptive<'m, Dop853, M, N, K, C>;

/// [`ContactAdaptive`] with the implicit Radau IIA method of order 5 ([`Radau5`]), for stiff
/// mechanisms with contacts: its stages and its Newton iteration on the accelerations of the held
/// mode, with their exact Jacobians (dual numbers through [`accelerations_in_mode`]); events
/// located on the collocation polynomial; a cut step's collocation equations solved anew for the
/// shorter step, from that polynomial. After a mode change the Jacobian, the factorisation and the
/// extrapolated starting values are renewed (the field is another one).
///
/// ```
/// use lagrange_core::constraints::{ConstraintKind, ContactOptions, ContactRadau5, Constraints};
/// use lagrange_core::integrate::{Radau5, Stepper};
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
/// let start = State::new(0.0, [1.0], [0.0]);
/// let mut solver =
///     ContactRadau5::new(&Ball, Radau5::new(1e-10, 1e-10), &start, ContactOptions::default())?;
/// solver.integrate(1.0, &mut [], |_| {})?;
/// // It lands at √(2/g) = 0.4515 s and stays on the floor. The fall is a quadratic, which the
/// // collocation polynomial (cubic) reproduces exactly: only the root finder's 1e-13 and
/// // round-off remain.
/// assert!((solver.events()[0].t - (2.0f64 / 9.81).sqrt()).abs() < 1e-12);
/// assert!(solver.state().q[0].abs() < 1e-12 && solver.state().t == 1.0);
/// # Ok::<(), lagrange_core::Error>(())
/// ```
pub type ContactRadau5<'m, M, const N: usize, const K: usize, const C: usize> =
    ContactAdaptive<'m, Radau5, M, N, K, C>;

/// An adaptive method ([`Dopri5`], [`Dop853`] or [`Radau5`], an [`EmbeddedPair`]) for mechanisms
/// with unilateral contacts and friction, with the mode changes located: a solver of the common
/// stepping interface ([`Stepper`]). [`ContactDopri5`], [`ContactDop853`] and [`ContactRadau5`]
/// name the three.
///
/// A contact that can release (or a friction row that can stick or slip) makes the constrained
/// accelerations a different function in each [`Mode`]; re-inferring the mode at every stage puts
/// a switch inside a step, where the error estimate sees a kink and the controller rejects and
/// shrinks the step around every switch. Here, as in [`ContactRk4`], the mode is fixed for the
/// duration of a step, so every stage (and Radau5's Newton iteration, with the exact Jacobians of
/// that right-hand side) integrates one smooth right-hand side ([`accelerations_in_mode`]) and the
/// error estimate is honest:
///
/// 1. a step is attempted and accepted by the method's own error control, in the mode of its
///    start;
/// 2. the event functions of [`ContactRk4`] (a contact's gap c while separated, its multiplier λ
///    while closed, a slip velocity while sliding, the margin of static friction while sticking)
///    are evaluated at the step's end; where one fell below zero, its root is located on the
///    step's dense output (order 4 for Dopri5, 7 for Dop853, the collocation polynomial of order
///    3 for Radau5) by the Illinois method
///    ([`DenseOutput::find_root`]), to
///    [`EVENT_TIME_TOLERANCE`](crate::integrate::dopri5::EVENT_TIME_TOLERANCE);
/// 3. the step is cut at the earliest root: recomputed as one step from its start to the
///    root ([`EmbeddedPair::shorten`]: a step shorter than the accepted one, so its local error is
///    within the tolerance as well), projected onto the mode's rows, and the mode is switched there as [`ContactRk4`]
///    switches it (impact law with the [`ContactOptions::restitution`], release, stick or slip,
///    then complementarity of the whole mode and the projection onto it);
/// 4. the next step starts in the new mode from the switched state; the step size the controller
///    proposed for the accepted step is kept (what the method computed on the old field, Radau5's
///    Jacobian and starting values, is not: [`EmbeddedPair::field_changed`]).
///
/// Without an event a step costs what a step of the method costs (Dopri5: 6 evaluations of q̈,
/// FSAL; Dop853: 12 + 3 for the dense output; Radau5: 3 per Newton iteration + 1 at the new
/// point, and its Jacobians and factorisations) plus the event functions at its end
/// ([`Stats::event_evaluations`]; one constrained solve when a contact is closed); a cut step adds
/// the recomputed step and one evaluation at the switched state. A row whose event
/// just fired is disarmed until its new event function is positive (no chattering), as in
/// [`ContactRk4`]. Events are detected at step ends: an event function that dips below zero and
/// back within one step is missed (bound `h_max` if that can happen).
///
/// Of the [`ContactOptions`], the restitution and [`max_events_per_step`](ContactOptions::max_events_per_step)
/// (here: mode changes at one instant, which do not advance time) apply; event times are located
/// to the root finder's tolerance on the dense output, not to `event_tolerance` (which is
/// [`ContactRk4`]'s, on its sub-steps).
///
/// The [`Stepper::dense`] output of a step is the method's over the step (up to the cut); the state
/// after a step is the state after the switch (the post-impact velocities, say).
///
/// ```
/// use lagrange_core::constraints::{ConstraintKind, ContactDopri5, ContactOptions, Constraints};
/// use lagrange_core::integrate::{Dopri5, Stepper};
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
/// let start = State::new(0.0, [1.0], [0.0]);
/// let mut solver =
///     ContactDopri5::new(&Ball, Dopri5::new(1e-10, 1e-10), &start, ContactOptions::default())?;
/// let outcome = solver.integrate(1.0, &mut [], |_| {})?;
/// // It lands at √(2/g) = 0.4515 s (a plastic impact) and stays on the floor. The fall is a
/// // quadratic, which Dopri5 integrates exactly: only the root finder's 1e-13 and round-off remain.
/// let landing = solver.events()[0].t;
/// assert!((landing - (2.0f64 / 9.81).sqrt()).abs() < 1e-12);
/// assert!(solver.state().q[0].abs() < 1e-12 && solver.state().t == 1.0);
/// assert!(outcome.stats.accepted < 20);
/// # Ok::<(), lagrange_core::Error>(())
/// ```
pub struct ContactAdaptive<
    'm,
    P: EmbeddedPair,
    M: Constraints<N, K, C>,
    const N: usize,
    const K: usize,
    const C: usize,
> {
    model: &'m M,
    method: P,
    /// The mode, the armed rows, the options and the mode changes so far; its transition switches
    /// modes.
    pub(super) contact: ContactRk4<C>,
    t: f64,
    q: [f64; N],
    v: [f64; N],
    /// q̈ at (t, q, v) in the current mode (the first stage of the next step).
    a: [f64; N],
    /// What the method keeps from one step to the next (its controller; Radau5's Jacobian too).
    memory: P::Memory<N>,
    /// Events in a row that did not advance time (several rows switching at one instant).
    instant_events: usize,
    dense: DenseOutput<N>,
    stats: Stats,
}

impl<
        'm,
        P: EmbeddedPair,
        M: Constraints<N, K, C>,
        const N: usize,
        const K: usize,
        const C: usize,
    > ContactAdaptive<'m, P, M, N, K, C>
{
    /// A solver at `state`, whose mode is inferred by complementarity
    /// ([`infer_mode`](super::infer_mode)).
    ///
    /// Errors: invalid settings ([`Dopri5::validate`], [`Dop853::validate`],
    /// [`Radau5::validate`]), the errors of
    /// [`ContactRk4::new`] (invalid
    /// options or parameters, a state off the constraints: project it first with
    /// [`consistent_state`](super::consistent_state)), accelerations that cannot be evaluated
    /// there.
    pub fn new(
        model: &'m M,
        method: P,
        state: &State<M::Coords>,
        options: ContactOptions,
    ) -> Result<Self> {
        method.validate()?;
        let contact = ContactRk4::new(model, state, options)?;
        let (t, q, v) = (state.t, state.q.to_array(), state.v.to_array());
        let field = InMode {
            model,
            mode: contact.mode,
        };
        let a = field.accelerations(t, &q, &v)?;
        let mut stats = Stats {
            evaluations: 1,
            ..Stats::default()
        };
        let memory = method.start(&field, (t, &q, &v, &a), &mut stats);
        Ok(ContactAdaptive {
            model,
            method,
            contact,
            t,
            q,
            v,
            a,
            memory,
            instant_events: 0,
            dense: DenseOutput::constant(t, &q, &v),
            stats,
        })
    }

    /// The current mode.
    pub fn mode(&self) -> Mode<C> {
        self.contact.mode
    }

    /// Every mode change so far, in order.
    pub fn events(&self) -> &[ModeChange] {
        &self.contact.events
    }

    /// The step the controller proposes next.
    pub fn proposed_step(&self) -> f64 {
        P::proposed_step(&self.memory)
    }

    /// The first root in (t₀, t₁] of row `row`'s event function on the step's dense output, from
    /// its values at both ends. A function that starts at zero (a contact that just bounced off)
    /// is bracketed from the first of t₀ + h·2⁻ᵏ (k = 40, …, 1) where it is positive, as
    /// [`ContactRk4`] does; if there is none, the event is at t₀. Adds the evaluations to `stats`.
    #[allow(clippy::too_many_arguments)]
    fn locate(
        &self,
        dense: &DenseOutput<N>,
        mode: &Mode<C>,
        row: usize,
        phi_start: f64,
        phi_end: f64,
        stats: &mut Stats,
    ) -> f64 {
        let model = self.model;
        let g = |t: f64, q: &[f64; N], v: &[f64; N]| {
            event_values(model, t, q, v, mode).map_or(f64::NAN, |phi| phi[row])
        };
        let (t0, t1) = (dense.t_start(), dense.t_end());
        let mut start = (t0, phi_start);
        if !(phi_start > 0.0) {
            let found = (1..=40).rev().find_map(|k| {
                let tk = t0 + (t1 - t0) * 0.5f64.powi(k);
                let (q, v) = dense.eval(tk);
                stats.event_evaluations += 1;
                let f = g(tk, &q, &v);
                (f > 0.0).then_some((tk, f))
            });
            match found {
                Some(s) => start = s,
                None => return t0,
            }
        }
        let (root, n) = dense.find_root_between(g, start, (t1, phi_end));
        stats.event_evaluations += n;
        root
    }
}

impl<P: EmbeddedPair, M: Constraints<N, K, C>, const N: usize, const K: usize, const C: usize>
    Stepper<M::Coords, N> for ContactAdaptive<'_, P, M, N, K, C>
{
    fn name(&self) -> &'static str {
        P::NAME
    }
    fn t(&self) -> f64 {
        self.t
    }
    fn state(&self) -> State<M::Coords> {
        State::new(
            self.t,
            M::Coords::from_array(self.q),
            M::Coords::from_array(self.v),
        )
    }
    fn dense(&self) -> &DenseOutput<N> {
        &self.dense
    }
    fn stats(&self) -> Stats {
        self.stats
    }
    fn count_event_evaluations(&mut self, n: usize) {
        self.stats.event_evaluations += n;
    }
    fn max_steps(&self) -> usize {
        self.method.max_steps()
    }

    /// One accepted step in the current mode, not past `t_limit`, cut at the first mode change
    /// inside it (see the [type docs](ContactAdaptive)). On error the solver (state, mode,
    /// event list, statistics) is unchanged.
    ///
    /// Errors: those of the method's step ([`EmbeddedPair::step`]: a step size underflow, dynamics
    /// that cannot be evaluated, Radau5's Newton iteration failing), a projection or an impact that fails,
    /// more than [`ContactOptions::max_events_per_step`] mode changes at one instant
    /// ([`Error::TooManyEvents`]).
    fn step(&mut self, t_limit: f64) -> Result<()> {
        let model = self.model;
        let names = &<M::Coords as Coordinates<N>>::NAMES;
        let (t, q, v) = (self.t, self.q, self.v);
        let mut stats = self.stats;
        let mut memory = self.memory;
        let mut mode = self.contact.mode;
        let mut armed = self.contact.armed;
        // A sliding cone continues its slip direction of the step's start.
        let h_next = P::proposed_step(&memory).min(t_limit - t);
        cone::refresh_references(model, t, &q, &v, h_next, &mut mode)?;
        let field = InMode { model, mode };
        let a = if mode == self.contact.mode {
            self.a
        } else {
            stats.evaluations += 1;
            field.accelerations(t, &q, &v)?
        };
        let method = self.method;
        let start = (t, &q, &v, &a);
        let step = method.step::<M::Coords, N>(&mut memory, &field, start, t_limit, &mut stats)?;
        let (t1, q1, v1) = (step.t, step.q, step.v);
        let mut dense = step.dense;
        stats.event_evaluations += 1;
        let phi1 = event_values(model, t1, &q1, &v1, &mode)?;
        let triggered = triggered_rows(model, t, &q, &v, &mode, &armed, &phi1);
        let mut change = None;
        // q̈ at the end, when the method evaluated it (FSAL).
        let (mut te, mut qe, mut ve, mut a_end) = (t1, q1, v1, step.a);
        if triggered.iter().any(|&b| b) {
            stats.event_evaluations += 1;
            let phi0 = event_values(model, t, &q, &v, &mode)?;
            let mut first: Option<(f64, usize)> = None;
            for row in (0..C).filter(|&i| triggered[i]) {
                let root = self.locate(&dense, &mode, row, phi0[row], phi1[row], &mut stats);
                if first.is_none_or(|f| root < f.0) {
                    first = Some((root, row));
                }
            }
            if let Some((root, row)) = first {
                te = root;
                if root <= t + 4.0 * f64::EPSILON * t.abs().max(t1 - t) {
                    // At the step's start (several rows switching at one instant).
                    (te, qe, ve, a_end) = (t, q, v, Some(a));
                    dense = DenseOutput::constant(t, &q, &v);
                } else if root < t1 {
                    // Cut: the step recomputed from its start to the event.
                    let cut = method.shorten::<M::Coords, N>(
                        &mut memory,
                        &field,
                        start,
                        root - t,
                        &mut stats,
                    )?;
                    (qe, ve, a_end, dense) = (cut.q, cut.v, cut.a, cut.dense);
                }
                change = Some(row);
            }
        }
        // Onto the mode's rows (those of the step: the switch below projects onto its own).
        let (qu, vu) = (qe, ve);
        project(model, te, &mut qe, &mut ve, &mode)?;
        if (qe, ve) != (qu, vu) {
            check_state(names, te, &qe, &ve)?;
        }
        let mut event = None;
        let ae = match change {
            None => {
                // The method's q̈ at the end is kept through the projection, as in a projected
                // Dopri5 or Dop853 step: the projection moves the state by the step's drift, of
                // the order of its local error, so the order is kept (see `project_accepted` in
                // `integrate::dopri5`).
                let ae = match a_end {
                    Some(ae) => ae,
                    None => {
                        stats.evaluations += 1;
                        field.accelerations(te, &qe, &ve)?
                    }
                };
                for i in 0..C {
                    armed[i] |= phi1[i] > 0.0;
                }
                ae
            }
            Some(row) => {
                stats.event_evaluations += 1;
                let phi_e = event_values(model, te, &qe, &ve, &mode)?;
                for i in 0..C {
                    armed[i] |= i != row && phi_e[i] > 0.0;
                }
                let (before, from) = (mode, mode.rows[row]);
                self.contact
                    .transition(model, te, &mut qe, &mut ve, &mut mode, row)?;
                for i in 0..C {
                    if mode.rows[i] != before.rows[i] || i == row {
                        armed[i] = false;
                    }
                }
                check_state(names, te, &qe, &ve)?;
                // The next step integrates another field (or the same from a state that jumped).
                P::field_changed(&mut memory);
                stats.evaluations += 1;
                let ae = InMode { model, mode }.accelerations(te, &qe, &ve)?;
                event = Some(ModeChange {
                    t: te,
                    row,
                    constraint: M::NAMES[row],
                    from,
                    to: mode.rows[row],
                });
                ae
            }
        };
        let instant_events = if event.is_some() && te == t {
            self.instant_events + 1
        } else {
            0
        };
        if instant_events > self.contact.options.max_events_per_step {
            return Err(Error::TooManyEvents {
                t,
                events: instant_events,
            });
        }
        // Accepted: commit everything at once.
        (self.t, self.q, self.v, self.a) = (te, qe, ve, ae);
        (self.memory, self.stats, self.dense) = (memory, stats, dense);
        (self.contact.mode, self.contact.armed) = (mode, armed);
        self.instant_events = instant_events;
        self.contact.events.extend(event);
        Ok(())
    }
}
