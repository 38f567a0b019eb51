//! Events located during an integration ([`Event`]), what the integration shows its observer
//! ([`Observation`]) and what it returns ([`Outcome`]).

use super::dense::DenseOutput;
use super::Stats;
use crate::model::{Coordinates, State};

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

/// An event function g(state) whose sign changes are located during [`Stepper::integrate`](super::Stepper::integrate).
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

    /// Whether the integration stops at this event.
    pub(super) fn is_terminal(&self) -> bool {
        self.terminal
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
    /// Index of the event in the slice passed to [`Stepper::integrate`](super::Stepper::integrate).
    pub index: usize,
    /// The state at the event (from the dense output).
    pub state: State<C>,
    /// Whether g was rising (negative to non-negative).
    pub rising: bool,
    /// Whether the event stopped the integration.
    pub terminal: bool,
}

/// Why [`Stepper::integrate`](super::Stepper::integrate) returned.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum StopReason<C> {
    /// t_end was reached.
    Reached,
    /// A terminal event occurred; the state is the state at the event.
    Event(EventHit<C>),
    /// The solver's most step attempts (the adaptive methods' `max_steps`) were made before
    /// reaching t_end; the state is the last accepted one.
    MaxSteps,
}

/// The result of [`Stepper::integrate`](super::Stepper::integrate).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Outcome<C> {
    /// The cost of the solver so far.
    pub stats: Stats,
    /// Why the integration ended.
    pub reason: StopReason<C>,
    /// Where it ended: at t_end, at the terminal event (the event's state), or at the last step
    /// taken (after `max_steps` attempts).
    pub state: State<C>,
}

/// What [`Stepper::integrate`](super::Stepper::integrate) shows its observer.
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

/// Locates the crossings of every event over a step on its dense output, from each event's value
/// at the step's start (kept from the step before) and at `current`, its end: marks each crossing
/// pending with its root, returns the earliest root of a terminal one (∞ without) and the
/// evaluations of event functions it took.
#[inline]
pub(super) fn locate_crossings<C: Coordinates<N>, const N: usize>(
    events: &mut [Event<'_, C>],
    current: &State<C>,
    dense: &DenseOutput<N>,
) -> (f64, usize) {
    let mut t_stop = f64::INFINITY;
    let mut evaluations = 0;
    for ev in events.iter_mut() {
        let g_new = (ev.g)(current);
        evaluations += 1;
        ev.pending = None;
        if let Some(rising) = ev.crossing(g_new) {
            let g = ev.g;
            let (root, n) = dense.find_root(
                |t, q, v| g(&State::new(t, C::from_array(*q), C::from_array(*v))),
                ev.g_prev,
                g_new,
            );
            evaluations += n;
            ev.pending = Some((root, rising));
            if ev.terminal {
                t_stop = t_stop.min(root);
            }
        }
        ev.g_prev = g_new;
    }
    (t_stop, evaluations)
}

/// The earliest pending crossing at or before `t_stop` (its index, root and whether g rises),
/// taken off the pending ones.
pub(super) fn next_crossing<C>(
    events: &mut [Event<'_, C>],
    t_stop: f64,
) -> Option<(usize, f64, bool)> {
    let mut best: Option<(usize, f64, bool)> = None;
    for (i, ev) in events.iter().enumerate() {
        if let Some((root, rising)) = ev.pending {
            if root <= t_stop && best.is_none_or(|(_, t, _)| root < t) {
                best = Some((i, root, rising));
            }
        }
    }
    if let Some((i, _, _)) = best {
        events[i].pending = None;
    }
    best
}

/// Every event's value at the start of an integration.
pub(super) fn arm<C>(events: &mut [Event<'_, C>], start: &State<C>) {
    for ev in events.iter_mut() {
        ev.g_prev = (ev.g)(start);
        ev.pending = None;
    }
}
