//! [`Stepper`]: the solver value every method shares — a method with its settings and working
//! memory, bound to a mechanism, holding the current state, the dense output of the last step, the
//! statistics, the contact mode of a declaration with unilateral or friction rows and, for
//! sensitivities, the tangent of the trajectory — with [`step`](Stepper::step), integration to a
//! stop time with an observer and events ([`integrate`](Stepper::integrate)) and
//! [`stats`](Stepper::stats).
//!
//! | method | built with | one [`step`](Stepper::step) | dense output |
//! |---|---|---|---|
//! | a one-step method `I` ([`Integrator`]: RK4, implicit midpoint, Gauss–Legendre 2, variational, Störmer–Verlet) | [`Fixed`] (`I::with_step(h)`) | one step of h (shortened to land on the limit) | cubic Hermite from the end points and q̈ there (order 3; one evaluation of q̈ per step) |
//! | an adaptive method ([`Dopri5`](super::Dopri5), [`Dop853`](super::Dop853), [`Radau5`](super::Radau5)) | its settings | one accepted step | the method's own: order 4, 7, 3 |
//!
//! A declaration with unilateral contacts or friction is stepped with its contact mode held over
//! every step and the mode's changes located inside it (see [`Stepper::step`]); nothing else
//! changes for the user.

// `!(a <= b)` comparisons are deliberate (they also catch NaN).
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use super::dense::DenseOutput;
use super::events::{arm, locate_crossings, next_crossing};
use super::events::{Event, EventHit, Observation, Outcome, StopReason};
use super::{EmbeddedPair, Integrator, Stats};
use crate::constraints::{ContactModel, ContactOptions, ModeChange};
use crate::error::{Error, Result};
use crate::evaluation::{diagnose, Dynamics, Evaluate};
use crate::model::{check_state, Coordinates, State};

/// The contact mode of the mechanism a handle `M` evaluates.
pub type ContactsOf<M, const N: usize> = <<M as Evaluate<N>>::Model as Dynamics<N>>::Contacts;

/// A method a [`Stepper`] steps with: a one-step method with its step ([`Fixed`](super::Fixed)), or
/// an adaptive method's settings ([`Dopri5`](super::Dopri5), [`Dop853`](super::Dop853),
/// [`Radau5`](super::Radau5)). Each kind has one loop: the fixed-step one, generic over the
/// one-step method, and the adaptive one, generic over the embedded pair.
pub trait Method<const N: usize>: Copy {
    /// The method's name.
    const NAME: &'static str;
    /// Whether its steps can be carried on dual numbers (trajectory sensitivities).
    const TANGENT: bool;
    /// What it keeps from one step to the next.
    type Memory: Copy;
    /// The work space of a step.
    type Scratch: Clone;

    /// Checks the settings for a solver starting at time `t`.
    fn validate(&self, t: f64) -> Result<()>;
    /// Most step attempts of one [`Stepper::integrate`].
    fn max_steps(&self) -> usize {
        usize::MAX
    }
    /// The memory of a fresh solver.
    fn memory(&self) -> Self::Memory;
    /// A work space.
    fn scratch(&self) -> Self::Scratch;
    /// The settings for an integration over an interval of length `interval` from where the
    /// solver is (Dop853 bounds its largest step by the interval of its first integration).
    fn bounded_to(&self, memory: &Self::Memory, interval: f64) -> Self {
        let _ = (memory, interval);
        *self
    }
    /// The step the method proposes next, where it has one.
    fn proposed_step(&self, memory: &Self::Memory) -> Option<f64>;
    /// One step of `stepper`, not past `t_limit` (> its time): the method's loop.
    fn step<M: Evaluate<N>, T: Tangent<M, N>>(
        stepper: &mut Stepper<'_, M, Self, N, T>,
        t_limit: f64,
    ) -> Result<()>;
}

/// The tangent of the trajectory a [`Stepper`] carries for sensitivities, or nothing
/// ([`NoTangent`]): the state on dual numbers, stepped by the method's own stages.
pub trait Tangent<M: Evaluate<N>, const N: usize>: Clone {
    /// Whether there is a tangent to carry.
    const ACTIVE: bool;
    /// One step of h from time t with the one-step method `I` on the tangent; returns the new
    /// state's real parts (the state the solver moves to).
    fn step<I: Integrator>(
        &mut self,
        mechanism: &M,
        t: f64,
        h: f64,
        stats: &mut Stats,
    ) -> Result<([f64; N], [f64; N])>;
    /// The adaptive method's accepted step of length h from time t taken again on the tangent.
    fn replay<P: EmbeddedPair>(&mut self, mechanism: &M, method: &P, t: f64, h: f64) -> Result<()>;
    /// The mechanism's chart switch ([`Evaluate::switch_charts`]) on the tangent, after the
    /// state's: the tangent moves with the switch's Jacobian.
    fn switch_charts(&mut self, mechanism: &M);
}

/// No tangent: a plain solver.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct NoTangent;

impl<M: Evaluate<N>, const N: usize> Tangent<M, N> for NoTangent {
    const ACTIVE: bool = false;
    fn step<I: Integrator>(
        &mut self,
        _: &M,
        _: f64,
        _: f64,
        _: &mut Stats,
    ) -> Result<([f64; N], [f64; N])> {
        Err(Error::UnsuitableMethod {
            method: I::NAME,
            reason: "the solver carries no tangent".to_string(),
        })
    }
    fn replay<P: EmbeddedPair>(&mut self, _: &M, _: &P, _: f64, _: f64) -> Result<()> {
        Ok(())
    }
    fn switch_charts(&mut self, _: &M) {}
}

/// A solver: a mechanism stepped by one method from a state (see the [`integrate`](crate::integrate) module docs).
///
/// ```
/// use lagrange_core::integrate::{Direction, Event, Observation, StopReason, Stepper};
/// use lagrange_core::{vec2, GaussLegendre2, Integrator, Mechanism, Model, Scalar, State};
///
/// /// A pendulum of unit mass and length, written by hand.
/// struct Pendulum;
/// impl Model<1, 2> for Pendulum {
///     type Coords = [f64; 1];
///     const RHEONOMIC: bool = false;
///     const HAS_POTENTIAL: bool = true;
///     const HAS_FORCES: bool = false;
///     fn validate(&self) -> lagrange_core::Result<()> { Ok(()) }
///     fn masses(&self) -> [f64; 2] { [1.0, 1.0] }
///     fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 1]) -> [D; 2] {
///         vec2(q[0].sin(), -q[0].cos()).to_array()
///     }
///     fn potential<D: Scalar>(&self, _t: D, _q: &[D; 1], x: &[D; 2]) -> D { x[1] * 9.81 }
/// }
/// lagrange_core::impl_mechanism!(Pendulum, 1, 2);
///
/// // Released at rest from 0.5 rad: when does it first pass the bottom (θ falling through 0)?
/// let start = State::new(0.0, [0.5], [0.0]);
/// let mut solver = Stepper::new(&Pendulum, GaussLegendre2::with_step(1e-2), &start)?;
/// let bottom = |s: &State<[f64; 1]>| s.q[0];
/// let mut events = [Event::new(&bottom).direction(Direction::Falling).terminal()];
/// let mut steps = 0;
/// let outcome = solver.integrate(10.0, &mut events, |o| {
///     if let Observation::Step { .. } = o { steps += 1 }
/// })?;
/// let StopReason::Event(hit) = outcome.reason else { panic!("no event") };
/// // A quarter period, K(sin(θ₀/2))·√(l/g) = 0.50946697879 (complete elliptic integral K). Gauss–
/// // Legendre's global error is O((hω)⁴) ≈ 1e-8 relative, the cubic Hermite interpolant's
/// // h⁴/384·|θ⁽⁴⁾| ≈ 1e-11·ω⁴θ₀ ≈ 5e-9: the event time is good to well within 1e-7.
/// assert!((hit.state.t - 0.509_466_978_79).abs() < 1e-7, "{}", hit.state.t);
/// assert_eq!(outcome.state, hit.state);
/// assert!(outcome.stats.newton_iterations > 0 && steps == 50);
/// # Ok::<(), lagrange_core::Error>(())
/// ```
pub struct Stepper<'m, M: Evaluate<N>, Me: Method<N>, const N: usize, T = NoTangent> {
    pub(crate) mechanism: &'m M,
    pub(crate) method: Me,
    pub(crate) memory: Me::Memory,
    pub(crate) scratch: Me::Scratch,
    pub(crate) t: f64,
    pub(crate) q: [f64; N],
    pub(crate) v: [f64; N],
    /// q̈ at (t, q, q̇) in the current contact mode.
    pub(crate) a: [f64; N],
    pub(crate) dense: DenseOutput<N>,
    pub(crate) stats: Stats,
    /// The contact mode held over the next step (nothing without unilateral or friction rows).
    pub(crate) contacts: ContactsOf<M, N>,
    pub(crate) options: ContactOptions,
    /// Every mode change so far (grows only when an event happens).
    pub(crate) changes: Vec<ModeChange>,
    /// Mode changes in a row that did not advance time (an adaptive step cut at its start).
    pub(crate) instant_events: usize,
    pub(crate) tangent: T,
}

impl<M: Evaluate<N>, Me: Method<N>, const N: usize, T: Clone> Clone for Stepper<'_, M, Me, N, T> {
    fn clone(&self) -> Self {
        Stepper {
            scratch: self.scratch.clone(),
            changes: self.changes.clone(),
            tangent: self.tangent.clone(),
            ..*self
        }
    }
}

impl<'m, M: Evaluate<N>, Me: Method<N>, const N: usize> Stepper<'m, M, Me, N> {
    /// A solver at `state`. Errors: invalid settings (a step size that is not positive and finite
    /// or does not advance time, an adaptive method's settings), invalid parameters or state, a
    /// state that violates the constraints (project it first with
    /// [`consistent_state`](crate::constraints::consistent_state)), accelerations that cannot be
    /// evaluated there.
    pub fn new(mechanism: &'m M, method: Me, state: &State<M::Coords>) -> Result<Self> {
        method.validate(state.t)?;
        let (q, v) = mechanism.check(state)?;
        mechanism.check_constraints(state.t, &q, &v)?;
        Self::from_checked(mechanism, method, state.t, q, v)
    }

    /// A solver at (t, q, q̇), already checked: the contact mode inferred there (for a declaration
    /// with unilateral or friction rows) and q̈ evaluated in it.
    pub(crate) fn from_checked(
        mechanism: &'m M,
        method: Me,
        t: f64,
        q: [f64; N],
        v: [f64; N],
    ) -> Result<Self> {
        let (model, constants) = (mechanism.model(), mechanism.prepared());
        let (contacts, a) = if ContactsOf::<M, N>::SWITCHES {
            let contacts = ContactsOf::<M, N>::start(model, constants, t, &q, &v)?;
            (
                contacts,
                contacts.accelerations(model, constants, t, &q, &v)?,
            )
        } else {
            let a = mechanism
                .accelerations_at(t, &q, &v)
                .map_err(|e| diagnose(mechanism, t, &q, &v, e))?;
            (ContactsOf::<M, N>::idle(), a)
        };
        Ok(Stepper {
            mechanism,
            method,
            memory: method.memory(),
            scratch: method.scratch(),
            t,
            q,
            v,
            a,
            dense: DenseOutput::constant(t, &q, &v),
            stats: Stats {
                evaluations: 1,
                ..Stats::default()
            },
            contacts,
            options: ContactOptions::default(),
            changes: Vec::new(),
            instant_events: 0,
            tangent: NoTangent,
        })
    }
}

impl<'m, M: Evaluate<N>, Me: Method<N>, const N: usize> Stepper<'m, M, Me, N> {
    /// The same solver carrying `tangent` (trajectory sensitivities) from here on.
    pub(crate) fn carrying<T>(self, tangent: T) -> Stepper<'m, M, Me, N, T> {
        Stepper {
            mechanism: self.mechanism,
            method: self.method,
            memory: self.memory,
            scratch: self.scratch,
            t: self.t,
            q: self.q,
            v: self.v,
            a: self.a,
            dense: self.dense,
            stats: self.stats,
            contacts: self.contacts,
            options: self.options,
            changes: self.changes,
            instant_events: self.instant_events,
            tangent,
        }
    }
}

impl<'m, M: Evaluate<N>, Me: Method<N>, const N: usize, T: Tangent<M, N>> Stepper<'m, M, Me, N, T> {
    /// The same solver with these contact options (restitution, event tolerance, mode changes per
    /// step; see [`ContactOptions`]), checked. They act on a declaration with unilateral or
    /// friction rows and are kept, unused, for any other.
    pub fn with_contact_options(mut self, options: ContactOptions) -> Result<Self> {
        options.validate()?;
        self.options = options;
        Ok(self)
    }

    /// The method's name.
    pub fn name(&self) -> &'static str {
        Me::NAME
    }

    /// Current time.
    pub fn t(&self) -> f64 {
        self.t
    }

    /// Current state.
    pub fn state(&self) -> State<M::Coords> {
        State::new(
            self.t,
            M::Coords::from_array(self.q),
            M::Coords::from_array(self.v),
        )
    }

    /// Dense output over the last step (a constant before the first).
    pub fn dense(&self) -> &DenseOutput<N> {
        &self.dense
    }

    /// Length of the last step (0 before the first).
    pub fn last_step(&self) -> f64 {
        self.dense.h
    }

    /// The step the method proposes next (an adaptive method's, once it has started; a
    /// fixed-step method's h).
    pub fn proposed_step(&self) -> Option<f64> {
        self.method.proposed_step(&self.memory)
    }

    /// Cost so far.
    pub fn stats(&self) -> Stats {
        self.stats
    }

    /// The contact mode held over the next step ([`ContactState`](crate::constraints::ContactState)
    /// for a declaration with unilateral or friction rows: its [`mode`](crate::constraints::ContactState::mode)).
    pub fn contacts(&self) -> &ContactsOf<M, N> {
        &self.contacts
    }

    /// Every mode change so far, in order.
    pub fn mode_changes(&self) -> &[ModeChange] {
        &self.changes
    }

    /// Takes one step (for an adaptive method one accepted step, rejecting and shrinking as
    /// needed), never past `t_limit` (> the current time; `f64::INFINITY` for a step of the
    /// method's own size). A step that would end within 1 % of a step of `t_limit` ends on it.
    /// A declaration with unilateral or friction
    /// rows is stepped with its contact mode held over the step, a mode change inside it located
    /// (a fixed-step method: on the step length, by the Illinois method to
    /// [`ContactOptions::event_tolerance`], the rest of the step taken in the new mode; an adaptive
    /// method: on the step's dense output, the step cut there) and applied (impact, release,
    /// stick, slip). On error the solver's state, contact mode and mode changes are unchanged.
    pub fn step(&mut self, t_limit: f64) -> Result<()> {
        Me::step(self, t_limit)
    }

    /// Integrates to `t_end` (≥ the current time), calling `observer` after every step and for
    /// every located event, and stopping early at a terminal event or after `max_steps` attempts
    /// (the adaptive methods' setting).
    ///
    /// Events: after each step every event function g(state) is evaluated at the new point; a sign
    /// change in the event's direction is located on the dense output by the Illinois variant of
    /// regula falsi (Dowell & Jarratt, BIT 11 (1971)) ([`DenseOutput::find_root`]) to within
    /// [`EVENT_TIME_TOLERANCE`](super::EVENT_TIME_TOLERANCE); events in one step are reported in
    /// time order; a terminal event ends the integration at its time, with the state taken from
    /// the dense output (the solver then stays at the end of the step that contains it). An event
    /// function with two roots inside one step shows no sign change and is missed.
    ///
    /// Returns the cost, why the integration ended and where ([`Outcome`]). No allocation.
    pub fn integrate(
        &mut self,
        t_end: f64,
        events: &mut [Event<'_, M::Coords>],
        mut observer: impl FnMut(Observation<'_, M::Coords, N>),
    ) -> Result<Outcome<M::Coords>> {
        if !(t_end.is_finite() && t_end >= self.t) {
            return Err(Error::InvalidEndTime { t: self.t, t_end });
        }
        self.method = self.method.bounded_to(&self.memory, t_end - self.t);
        arm(events, &self.state());
        self.stats.event_evaluations += events.len();
        let first = self.stats.accepted + self.stats.rejected;
        while self.t < t_end {
            if self.stats.accepted + self.stats.rejected - first >= self.method.max_steps() {
                let (stats, state) = (self.stats, self.state());
                let reason = StopReason::MaxSteps;
                return Ok(Outcome {
                    stats,
                    reason,
                    state,
                });
            }
            self.step(t_end)?;
            let current = self.state();
            let (t_stop, evaluations) = locate_crossings(events, &current, &self.dense);
            self.stats.event_evaluations += evaluations;
            // Report them in time order, up to the first terminal one.
            while let Some((index, root, rising)) = next_crossing(events, t_stop) {
                let (q, v) = self.dense.eval(root);
                let hit = EventHit {
                    index,
                    state: State::new(root, M::Coords::from_array(q), M::Coords::from_array(v)),
                    rising,
                    terminal: events[index].is_terminal(),
                };
                observer(Observation::Event(&hit));
                if hit.terminal {
                    check_state(&M::Coords::NAMES, root, &q, &v)?;
                    let (stats, state) = (self.stats, hit.state);
                    let reason = StopReason::Event(hit);
                    return Ok(Outcome {
                        stats,
                        reason,
                        state,
                    });
                }
            }
            observer(Observation::Step {
                state: &current,
                dense: &self.dense,
            });
        }
        let (stats, state) = (self.stats, self.state());
        let reason = StopReason::Reached;
        Ok(Outcome {
            stats,
            reason,
            state,
        })
    }
}
