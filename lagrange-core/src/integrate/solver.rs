//! The stepping interface every method shares: a [`Stepper`] is a solver value — a method with
//! its options and working memory, bound to a mechanism, holding the current state — with
//! [`step`](Stepper::step), integration to a stop time with an observer, dense output and events
//! ([`integrate`](Stepper::integrate)), and [`Stats`].
//!
//! | solver | built by | one [`step`](Stepper::step) | dense output |
//! |---|---|---|---|
//! | [`FixedStepper`] | [`FixedStepper::new`] with any [`Integrator`] (RK4, implicit midpoint, Gauss–Legendre 2, variational, Störmer–Verlet) and a step h | one step of h (shortened to land on the limit) | cubic Hermite from the end points and q̈ there (order 3; one evaluation of q̈ per step) |
//! | [`Dopri5Stepper`](super::Dopri5Stepper) | [`Dopri5Stepper::new`](super::Dopri5Stepper::new) with tolerances | one accepted adaptive step | the method's own, order 4 |
//! | [`ContactSolver`](crate::constraints::ContactSolver) | [`ContactSolver::new`](crate::constraints::ContactSolver::new) around a [`ContactRk4`](crate::constraints::ContactRk4) | one RK4 step of h with located mode changes | cubic Hermite |
//! | [`ContactDopri5`](crate::constraints::ContactDopri5), [`ContactDop853`](crate::constraints::ContactDop853), [`ContactRadau5`](crate::constraints::ContactRadau5) | [`ContactAdaptive::new`](crate::constraints::ContactAdaptive::new) with a [`Dopri5`](super::Dopri5), [`Dop853`](super::Dop853) or [`Radau5`](super::Radau5) and [`ContactOptions`](crate::constraints::ContactOptions) | one accepted step in a fixed contact mode, cut at the first mode change inside it | the method's, order 4, 7 or 3 (Radau5's collocation polynomial) |
//!
//! The shorthand `sys.step::<I>(&mut state, h)` ([`Mechanism::step`]) is one validated step of an
//! [`Integrator`] with fresh working memory; for [`Dopri5`](super::Dopri5) it integrates over
//! [t, t + h] with the default tolerances.
//!
//! ```
//! use lagrange_core::integrate::{Direction, Event, FixedStepper, Observation, StopReason, Stepper};
//! use lagrange_core::{vec2, GaussLegendre2, Mechanism, Model, Scalar, State};
//!
//! /// A pendulum of unit mass and length, written by hand.
//! struct Pendulum;
//! impl Model<1, 2> for Pendulum {
//!     type Coords = [f64; 1];
//!     const RHEONOMIC: bool = false;
//!     const HAS_POTENTIAL: bool = true;
//!     const HAS_FORCES: bool = false;
//!     fn validate(&self) -> lagrange_core::Result<()> { Ok(()) }
//!     fn masses(&self) -> [f64; 2] { [1.0, 1.0] }
//!     fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 1]) -> [D; 2] {
//!         vec2(q[0].sin(), -q[0].cos()).to_array()
//!     }
//!     fn potential<D: Scalar>(&self, _t: D, _q: &[D; 1], x: &[D; 2]) -> D { x[1] * 9.81 }
//! }
//! lagrange_core::impl_mechanism!(Pendulum, 1, 2);
//!
//! // Released at rest from 0.5 rad: when does it first pass the bottom (θ falling through 0)?
//! let start = State::new(0.0, [0.5], [0.0]);
//! let mut solver = FixedStepper::<_, GaussLegendre2, 1>::new(&Pendulum, &start, 1e-2)?;
//! let bottom = |s: &State<[f64; 1]>| s.q[0];
//! let mut events = [Event::new(&bottom).direction(Direction::Falling).terminal()];
//! let mut steps = 0;
//! let outcome = solver.integrate(10.0, &mut events, |o| {
//!     if let Observation::Step { .. } = o { steps += 1 }
//! })?;
//! let StopReason::Event(hit) = outcome.reason else { panic!("no event") };
//! // A quarter period, K(sin(θ₀/2))·√(l/g) = 0.50946697879 (complete elliptic integral K). Gauss–
//! // Legendre's global error is O((hω)⁴) ≈ 1e-8 relative, the cubic Hermite interpolant's
//! // h⁴/384·|θ⁽⁴⁾| ≈ 1e-11·ω⁴θ₀ ≈ 5e-9: the event time is good to well within 1e-7.
//! assert!((hit.state.t - 0.509_466_978_79).abs() < 1e-7, "{}", hit.state.t);
//! assert!(outcome.stats.newton_iterations > 0 && steps == 50);
//! # Ok::<(), lagrange_core::Error>(())
//! ```

// `!(a <= b)` comparisons are deliberate (they also catch NaN).
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use super::dopri5::DenseOutput;
use super::Integrator;
use crate::error::{Error, Result};
use crate::mechanism::{diagnose, Mechanism};
use crate::model::{check_state, Coordinates, State};

/// What a solver's work cost, counted the same way by every method.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Stats {
    /// Accepted steps.
    pub accepted: usize,
    /// Rejected step attempts (adaptive methods).
    pub rejected: usize,
    /// Evaluations of the right-hand side in plain `f64`: q̈ for the explicit methods, the
    /// canonical field (p, ṗ) for the implicit ones, the discrete Euler–Lagrange residual for the
    /// variational integrator.
    pub evaluations: usize,
    /// Evaluations of Jacobians (by dual numbers).
    pub jacobians: usize,
    /// LU factorisations of a Newton matrix.
    pub factorizations: usize,
    /// Newton iterations (of every nonlinear solve in a step).
    pub newton_iterations: usize,
    /// Evaluations of event functions (including root finding).
    pub event_evaluations: usize,
}

impl std::ops::AddAssign for Stats {
    fn add_assign(&mut self, o: Stats) {
        self.accepted += o.accepted;
        self.rejected += o.rejected;
        self.evaluations += o.evaluations;
        self.jacobians += o.jacobians;
        self.factorizations += o.factorizations;
        self.newton_iterations += o.newton_iterations;
        self.event_evaluations += o.event_evaluations;
    }
}

/// Checks a step size: positive and finite ([`Error::InvalidStep`]).
pub fn check_step(h: f64) -> Result<()> {
    if h.is_finite() && h > 0.0 {
        Ok(())
    } else {
        Err(Error::InvalidStep { h })
    }
}

/// Checks a step size from time `t`: positive and finite ([`Error::InvalidStep`]), and large enough
/// that t + h ≠ t in floating point ([`Error::StepDoesNotAdvance`]; a subnormal h at t = 1, say).
/// A non-finite `t` passes here and is refused by the state check that follows.
pub fn check_step_at(t: f64, h: f64) -> Result<()> {
    check_step(h)?;
    if t + h == t {
        Err(Error::StepDoesNotAdvance { t, h })
    } else {
        Ok(())
    }
}

/// The validated step every method shares: checks h, the parameters, the state and its
/// constraints, runs `advance` on (t, q, v), projects the result onto the constraints at t + h,
/// checks it and only then writes it to `state` (unchanged on every error).
pub(crate) fn validated_step<M: Mechanism<N>, const N: usize>(
    mechanism: &M,
    state: &mut State<M::Coords>,
    h: f64,
    advance: impl FnOnce(f64, &[f64; N], &[f64; N]) -> Result<([f64; N], [f64; N])>,
) -> Result<()> {
    check_step_at(state.t, h)?;
    let (q, v) = mechanism.check(state)?;
    mechanism.check_constraints(state.t, &q, &v)?;
    let (mut q1, mut v1) = advance(state.t, &q, &v)?;
    mechanism.project(state.t + h, &mut q1, &mut v1)?;
    commit(state, state.t + h, &q1, &v1)
}

/// Checks (t, q, v) and writes it to `state`; `state` is unchanged on error.
pub(crate) fn commit<C: Coordinates<N>, const N: usize>(
    state: &mut State<C>,
    t: f64,
    q: &[f64; N],
    v: &[f64; N],
) -> Result<()> {
    check_state(&C::NAMES, t, q, v)?;
    state.t = t;
    state.q = C::from_array(*q);
    state.v = C::from_array(*v);
    Ok(())
}

/// Which sign changes of an event function count.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Direction {
    /// g goes from negative to non-negative.
    Rising,
    /// g goes from positive to non-positive.
    Falling,
    /// Either.
    #[default]
    Either,
}

/// An event function g(state) whose sign changes are located during [`Stepper::integrate`].
pub struct Event<'a, C> {
    g: &'a dyn Fn(&State<C>) -> f64,
    direction: Direction,
    terminal: bool,
    g_prev: f64,
    pending: Option<(f64, bool)>,
}

impl<'a, C> Event<'a, C> {
    /// An event on every sign change of g, not terminal.
    pub fn new(g: &'a dyn Fn(&State<C>) -> f64) -> Self {
        Event {
            g,
            direction: Direction::Either,
            terminal: false,
            g_prev: f64::NAN,
            pending: None,
        }
    }

    /// Only sign changes in this direction count.
    pub fn direction(mut self, direction: Direction) -> Self {
        self.direction = direction;
        self
    }

    /// The integration stops at this event.
    pub fn terminal(mut self) -> Self {
        self.terminal = true;
        self
    }

    /// Whether the change from g_prev to g_new is a crossing to report, and its direction (rising?).
    fn crossing(&self, g_new: f64) -> Option<bool> {
        let g0 = self.g_prev;
        let rising = g0 < 0.0 && g_new >= 0.0;
        let falling = g0 > 0.0 && g_new <= 0.0;
        match self.direction {
            Direction::Rising if rising => Some(true),
            Direction::Falling if falling => Some(false),
            Direction::Either if rising || falling => Some(rising),
            _ => None,
        }
    }
}

/// An event located during an integration.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EventHit<C> {
    /// Index of the event in the slice passed to [`Stepper::integrate`].
    pub index: usize,
    /// The state at the event (from the dense output).
    pub state: State<C>,
    /// Whether g was rising (negative to non-negative).
    pub rising: bool,
    /// Whether the event stopped the integration.
    pub terminal: bool,
}

/// Why [`Stepper::integrate`] returned.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum StopReason<C> {
    /// t_end was reached.
    Reached,
    /// A terminal event occurred; the state is the state at the event.
    Event(EventHit<C>),
    /// The solver's most step attempts (Dopri5's `max_steps`) were made before reaching t_end; the state is the last accepted one.
    MaxSteps,
}

/// The result of [`Stepper::integrate`] (and [`Stepper::integrate`](super::Dopri5::integrate)).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Outcome<C> {
    /// Cost.
    pub stats: Stats,
    /// Why the integration ended.
    pub reason: StopReason<C>,
}

/// What [`Stepper::integrate`] shows its observer.
#[derive(Debug)]
pub enum Observation<'a, C, const N: usize> {
    /// An accepted step: the state at its end and the dense output over it.
    Step {
        /// The state at the end of the step.
        state: &'a State<C>,
        /// The dense output over the step.
        dense: &'a DenseOutput<N>,
    },
    /// A located event (reported before the step it lies in).
    Event(&'a EventHit<C>),
}

/// The stepping interface every solver implements (see the [module docs](self)).
pub trait Stepper<C: Coordinates<N>, const N: usize> {
    /// The method's name.
    fn name(&self) -> &'static str;
    /// Current time.
    fn t(&self) -> f64;
    /// Current state.
    fn state(&self) -> State<C>;
    /// Takes one step (for an adaptive method one accepted step, rejecting and shrinking as
    /// needed), never past `t_limit` (> the current time). On error the solver's state is unchanged.
    fn step(&mut self, t_limit: f64) -> Result<()>;
    /// Dense output over the last step (a constant before the first).
    fn dense(&self) -> &DenseOutput<N>;
    /// Cost so far.
    fn stats(&self) -> Stats;
    /// Adds event-function evaluations to the statistics.
    fn count_event_evaluations(&mut self, n: usize);
    /// Most step attempts one [`integrate`](Stepper::integrate) may make (unbounded by default).
    fn max_steps(&self) -> usize {
        usize::MAX
    }

    /// Integrates to `t_end` (≥ the current time), calling `observer` after every step and for
    /// every located event, and stopping early at a terminal event or after
    /// [`max_steps`](Stepper::max_steps) attempts.
    ///
    /// Events: after each step every event function g(state) is evaluated at the new point; a sign
    /// change in the event's direction is located on the dense output by the Illinois variant of
    /// regula falsi ([`DenseOutput::find_root`]) to within
    /// [`EVENT_TIME_TOLERANCE`](super::dopri5::EVENT_TIME_TOLERANCE); events in one step are
    /// reported in time order; a terminal event ends the integration at its time, with the state
    /// taken from the dense output (the solver then stays at the end of the step that contains it).
    /// An event function with two roots inside one step shows no sign change and is missed.
    ///
    /// Returns the cost and why the integration ended; the final state is in the outcome's
    /// `reason` for a terminal event and is [`state`](Stepper::state) otherwise. No allocation.
    fn integrate(
        &mut self,
        t_end: f64,
        events: &mut [Event<'_, C>],
        mut observer: impl FnMut(Observation<'_, C, N>),
    ) -> Result<Outcome<C>>
    where
        Self: Sized,
    {
        if !(t_end.is_finite() && t_end >= self.t()) {
            return Err(Error::InvalidEndTime { t: self.t(), t_end });
        }
        let start = self.state();
        for ev in events.iter_mut() {
            ev.g_prev = (ev.g)(&start);
            ev.pending = None;
        }
        self.count_event_evaluations(events.len());
        let first = self.stats();
        let mut reason = StopReason::Reached;
        while self.t() < t_end {
            let now = self.stats();
            if now.accepted + now.rejected - first.accepted - first.rejected >= self.max_steps() {
                reason = StopReason::MaxSteps;
                break;
            }
            self.step(t_end)?;
            let current = self.state();
            // Locate this step's crossings.
            let mut t_stop = f64::INFINITY;
            let mut any = false;
            let mut evaluations = 0;
            for ev in events.iter_mut() {
                let g_new = (ev.g)(&current);
                evaluations += 1;
                ev.pending = None;
                if let Some(rising) = ev.crossing(g_new) {
                    let g = ev.g;
                    let (root, n) = self.dense().find_root(
                        |t, q, v| g(&State::new(t, C::from_array(*q), C::from_array(*v))),
                        ev.g_prev,
                        g_new,
                    );
                    evaluations += n;
                    ev.pending = Some((root, rising));
                    any = true;
                    if ev.terminal {
                        t_stop = t_stop.min(root);
                    }
                }
                ev.g_prev = g_new;
            }
            self.count_event_evaluations(evaluations);
            // Report them in time order, up to the first terminal one.
            while any && events.iter().any(|e| e.pending.is_some()) {
                let mut best: Option<(usize, f64, bool)> = None;
                for (i, ev) in events.iter().enumerate() {
                    if let Some((root, rising)) = ev.pending {
                        if root <= t_stop && best.is_none_or(|(_, t, _)| root < t) {
                            best = Some((i, root, rising));
                        }
                    }
                }
                let Some((index, root, rising)) = best else {
                    break;
                };
                events[index].pending = None;
                let (q, v) = self.dense().eval(root);
                let hit = EventHit {
                    index,
                    state: State::new(root, C::from_array(q), C::from_array(v)),
                    rising,
                    terminal: events[index].terminal,
                };
                observer(Observation::Event(&hit));
                if hit.terminal {
                    check_state(&C::NAMES, root, &q, &v)?;
                    return Ok(Outcome {
                        stats: self.stats(),
                        reason: StopReason::Event(hit),
                    });
                }
            }
            observer(Observation::Step {
                state: &current,
                dense: self.dense(),
            });
        }
        Ok(Outcome {
            stats: self.stats(),
            reason,
        })
    }
}

/// A fixed-step solver for any [`Integrator`]: holds the mechanism, the state, the step h, the
/// method's working memory (the implicit methods keep their factorised Newton matrix from step to
/// step while the iteration converges well) and the dense output of the last step (cubic Hermite
/// interpolation of (q, v) from the end points and q̈ there: order 3, one evaluation of q̈ at the
/// end of each step).
pub struct FixedStepper<'m, M: Mechanism<N>, I: Integrator, const N: usize> {
    mechanism: &'m M,
    h: f64,
    t: f64,
    q: [f64; N],
    v: [f64; N],
    a: [f64; N],
    memory: I::Memory<N>,
    dense: DenseOutput<N>,
    stats: Stats,
}

impl<'m, M: Mechanism<N>, I: Integrator, const N: usize> FixedStepper<'m, M, I, N> {
    /// A solver at `state` with step `h`. Errors: an invalid h, invalid parameters or state, a
    /// state that violates the constraints, accelerations that cannot be evaluated there.
    pub fn new(mechanism: &'m M, state: &State<M::Coords>, h: f64) -> Result<Self> {
        check_step_at(state.t, h)?;
        let (q, v) = mechanism.check(state)?;
        mechanism.check_constraints(state.t, &q, &v)?;
        let a = mechanism
            .accelerations_at(state.t, &q, &v)
            .map_err(|e| diagnose(mechanism, state.t, &q, &v, e))?;
        Ok(FixedStepper {
            mechanism,
            h,
            t: state.t,
            q,
            v,
            a,
            memory: Default::default(),
            dense: DenseOutput::constant(state.t, &q, &v),
            stats: Stats {
                evaluations: 1,
                ..Stats::default()
            },
        })
    }

    /// The step size.
    pub fn step_size(&self) -> f64 {
        self.h
    }
}

impl<M: Mechanism<N>, I: Integrator, const N: usize> Stepper<M::Coords, N>
    for FixedStepper<'_, M, I, N>
{
    fn name(&self) -> &'static str {
        I::NAME
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

    /// One step of h, or of t_limit − t when that is shorter (or only slightly longer, so no
    /// sliver of a step is left).
    fn step(&mut self, t_limit: f64) -> Result<()> {
        if !(t_limit > self.t) || !t_limit.is_finite() {
            return Err(Error::InvalidEndTime {
                t: self.t,
                t_end: t_limit,
            });
        }
        let (mut h, mut t1) = (self.h, self.t + self.h);
        if self.t + 1.01 * self.h >= t_limit {
            (h, t1) = (t_limit - self.t, t_limit);
        }
        check_step_at(self.t, h)?;
        let m = self.mechanism;
        let mut memory = self.memory;
        let mut stats = Stats::default();
        let (mut q1, mut v1) = I::advance(m, &mut memory, self.t, &self.q, &self.v, h, &mut stats)?;
        m.project(t1, &mut q1, &mut v1)?;
        check_state(&M::Coords::NAMES, t1, &q1, &v1)?;
        let a1 = m
            .accelerations_at(t1, &q1, &v1)
            .map_err(|e| diagnose(m, t1, &q1, &v1, e))?;
        stats.evaluations += 1;
        stats.accepted += 1;
        self.dense
            .set_hermite(self.t, h, (&self.q, &self.v, &self.a), (&q1, &v1, &a1));
        (self.t, self.q, self.v, self.a, self.memory) = (t1, q1, v1, a1, memory);
        self.stats += stats;
        Ok(())
    }
}
