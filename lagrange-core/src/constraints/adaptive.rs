//! [`ContactAdaptive`] ([`ContactDopri5`], [`ContactDop853`]): an adaptive Dormand–Prince pair
//! with the constraint mode frozen over each step and the mode changes located on the step's dense
//! output.

// `!(x > 0)` is deliberate: it also treats NaN as not positive.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use super::contact::{event_values, triggered_rows};
use super::{accelerations_in_mode, cone, project, Constraints, ContactOptions, ContactRk4};
use super::{Mode, ModeChange};
use crate::error::{Error, Result};
use crate::integrate::dopri5::{adaptive_step, initial_step_on, Controller};
use crate::integrate::{DenseOutput, Dop853, Dopri5, EmbeddedPair, Event, Observation, Outcome};
use crate::integrate::{Stats, Stepper, StopReason};
use crate::model::{check_state, Coordinates, State};

/// q̈ in `mode` (the constrained accelerations with the mode's rows enforced).
fn accelerations<'a, M: Constraints<N, K, C>, const N: usize, const K: usize, const C: usize>(
    model: &'a M,
    mode: &Mode<C>,
) -> impl Fn(f64, &[f64; N], &[f64; N]) -> Result<[f64; N]> + 'a {
    let mode = *mode;
    move |t, q, v| Ok(accelerations_in_mode(model, t, q, v, &mode)?.accelerations)
}

/// [`ContactAdaptive`] with Dormand–Prince 5(4).
pub type ContactDopri5<'m, M, const N: usize, const K: usize, const C: usize> =
    ContactAdaptive<'m, Dopri5, M, N, K, C>;

/// [`ContactAdaptive`] with Dormand–Prince 8(5,3) (its dense output of order 7 unless
/// `dense: false`, which locates events on the cubic Hermite interpolant).
pub type ContactDop853<'m, M, const N: usize, const K: usize, const C: usize> =
    ContactAdaptive<'m, Dop853, M, N, K, C>;

/// An adaptive Dormand–Prince pair ([`Dopri5`] or [`Dop853`], an [`EmbeddedPair`]) for mechanisms
/// with unilateral contacts and friction, with the mode changes located: a solver of the common
/// stepping interface ([`Stepper`]). [`ContactDopri5`] and [`ContactDop853`] name the two.
///
/// A contact that can release (or a friction row that can stick or slip) makes the constrained
/// accelerations a different function in each [`Mode`]; re-inferring the mode at every stage puts
/// a switch inside a step, where the error estimate sees a kink and the controller rejects and
/// shrinks the step around every switch. Here, as in [`ContactRk4`], the mode is fixed for the
/// duration of a step, so every stage integrates one smooth right-hand side
/// ([`accelerations_in_mode`]) and the error estimate is honest:
///
/// 1. a step is attempted and accepted by the method's own error control, in the mode of its
///    start;
/// 2. the event functions of [`ContactRk4`] (a contact's gap c while separated, its multiplier λ
///    while closed, a slip velocity while sliding, the margin of static friction while sticking)
///    are evaluated at the step's end; where one fell below zero, its root is located on the
///    step's dense output (order 4 for Dopri5, 7 for Dop853) by the Illinois method
///    ([`DenseOutput::find_root`]), to
///    [`EVENT_TIME_TOLERANCE`](crate::integrate::dopri5::EVENT_TIME_TOLERANCE);
/// 3. the step is cut at the earliest root: recomputed as one step from its start to the
///    root (a step shorter than the accepted one, so its local error is within the tolerance as
///    well), projected onto the mode's rows, and the mode is switched there as [`ContactRk4`]
///    switches it (impact law with the [`ContactOptions::restitution`], release, stick or slip,
///    then complementarity of the whole mode and the projection onto it);
/// 4. the next step starts in the new mode from the switched state; the step size the controller
///    proposed for the accepted step is kept.
///
/// Without an event a step costs what a step of the method costs (Dopri5: 6 evaluations of q̈,
/// FSAL; Dop853: 12 + 3 for the dense output) plus the event functions at its end
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
    contact: ContactRk4<C>,
    t: f64,
    q: [f64; N],
    v: [f64; N],
    /// q̈ at (t, q, v) in the current mode (the first stage of the next step).
    a: [f64; N],
    control: Controller,
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
    /// Errors: invalid settings ([`Dopri5::validate`], [`Dop853::validate`]), the errors of
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
        let settings = method.controls();
        let contact = ContactRk4::new(model, state, options)?;
        let (t, q, v) = (state.t, state.q.to_array(), state.v.to_array());
        let acc = accelerations(model, &contact.mode);
        let a = acc(t, &q, &v)?;
        let mut stats = Stats {
            evaluations: 1,
            ..Stats::default()
        };
        let h = match settings.h_init {
            Some(h) => h.min(settings.h_max),
            None => initial_step_on(&acc, &settings, (t, &q, &v, &a), P::ORDER, &mut stats),
        };
        Ok(ContactAdaptive {
            model,
            method,
            contact,
            t,
            q,
            v,
            a,
            control: Controller { h, fac_old: 1e-4 },
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
        self.control.h
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
        self.method.controls().max_steps
    }

    /// One accepted step in the current mode, not past `t_limit`, cut at the first mode change
    /// inside it (see the [type docs](ContactAdaptive)). On error the solver (state, mode,
    /// event list, statistics) is unchanged.
    ///
    /// Errors: those of [`Dopri5Stepper::step`](crate::integrate::Dopri5Stepper::step) (a step
    /// size underflow, dynamics that cannot be evaluated), a projection or an impact that fails,
    /// more than [`ContactOptions::max_events_per_step`] mode changes at one instant
    /// ([`Error::TooManyEvents`]).
    fn step(&mut self, t_limit: f64) -> Result<()> {
        let model = self.model;
        let names = &<M::Coords as Coordinates<N>>::NAMES;
        let (t, q, v) = (self.t, self.q, self.v);
        let mut stats = self.stats;
        let mut control = self.control;
        let mut mode = self.contact.mode;
        let mut armed = self.contact.armed;
        // A sliding cone continues its slip direction of the step's start.
        cone::refresh_references(model, t, &q, &v, control.h.min(t_limit - t), &mut mode)?;
        let acc = accelerations(model, &mode);
        let a = if mode == self.contact.mode {
            self.a
        } else {
            stats.evaluations += 1;
            acc(t, &q, &v)?
        };
        let method = self.method;
        let start = (t, &q, &v, &a);
        let ((q1, v1, attempt), h, t1) = adaptive_step(
            P::NAME,
            &method.controls(),
            P::EXPONENTS,
            t,
            t_limit,
            &mut control,
            &mut stats,
            |h, stats| {
                method
                    .attempt::<M::Coords, N>(start, h, stats, &acc)
                    .map(|(q1, v1, err, attempt)| ((q1, v1, attempt), err))
            },
        )?;
        let (a1, mut dense) = method.accept(start, h, attempt, &mut stats, &acc)?;
        stats.event_evaluations += 1;
        let phi1 = event_values(model, t1, &q1, &v1, &mode)?;
        let triggered = triggered_rows(model, t, &q, &v, &mode, &armed, &phi1);
        let mut change = None;
        let (mut te, mut qe, mut ve, mut ae) = (t1, q1, v1, a1);
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
                if root <= t + 4.0 * f64::EPSILON * t.abs().max(h) {
                    // At the step's start (several rows switching at one instant).
                    (te, qe, ve) = (t, q, v);
                    dense = DenseOutput::constant(t, &q, &v);
                } else if root < t1 {
                    // Cut: the step recomputed from its start to the event.
                    let (qc, vc, _, cut) =
                        method.attempt::<M::Coords, N>(start, root - t, &mut stats, &acc)?;
                    (ae, dense) = method.accept(start, root - t, cut, &mut stats, &acc)?;
                    (qe, ve) = (qc, vc);
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
        match change {
            None => {
                if (qe, ve) != (qu, vu) {
                    stats.evaluations += 1;
                    ae = acc(te, &qe, &ve)?;
                }
                for i in 0..C {
                    armed[i] |= phi1[i] > 0.0;
                }
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
                stats.evaluations += 1;
                ae = accelerations(model, &mode)(te, &qe, &ve)?;
                event = Some(ModeChange {
                    t: te,
                    row,
                    constraint: M::NAMES[row],
                    from,
                    to: mode.rows[row],
                });
            }
        }
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
        (self.control, self.stats, self.dense) = (control, stats, dense);
        (self.contact.mode, self.contact.armed) = (mode, armed);
        self.instant_events = instant_events;
        self.contact.events.extend(event);
        Ok(())
    }
}

/// [`Dopri5::integrate_contacts`] and [`Dop853::integrate_contacts`].
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
/// smooth: the pair's own stepper integrates them).
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
    /// mode changes located ([`ContactDopri5`]), calling `observer` after every step and for every
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
    /// [`Dopri5::integrate_contacts`] with Dormand–Prince 8(5,3) ([`ContactDop853`]).
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
