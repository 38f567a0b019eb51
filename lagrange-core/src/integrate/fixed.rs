//! The fixed-step loop, generic over the one-step method ([`Fixed`]): a step of h with the method,
//! the projection onto the constraints and the dense output; for a declaration with unilateral or
//! friction rows, the contact mode held over the step and its changes located on the step length
//! ([`hold_over_step`]), which is also what `sys.step` takes on such a declaration.

// `!(a <= b)` comparisons are deliberate (they also catch NaN).
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use super::control::check_limit;
use super::held::HeldMode;
use super::stepper::{ContactsOf, Method, Stepper, Tangent};
use super::{check_step_at, commit, Integrator, Stats};
use crate::constraints::{ContactModel, ContactOptions, ModeChange};
use crate::error::{Error, Result};
use crate::evaluation::{diagnose, Dynamics, Evaluate};
use crate::model::{check_state, Coordinates, State};
use std::marker::PhantomData;

/// The one-step method `I` with step h, for a [`Stepper`]: `Fixed::<Rk4>::new(1e-3)`, or
/// `Rk4::with_step(1e-3)` ([`Integrator::with_step`]). The solver keeps the method's working memory
/// from step to step (the implicit methods' factorised Newton matrix) and, unless
/// [`without_dense`](Fixed::without_dense), evaluates q̈ at the end of every step for the cubic
/// Hermite dense output (order 3).
pub struct Fixed<I> {
    h: f64,
    dense: bool,
    method: PhantomData<fn() -> I>,
}

impl<I> Clone for Fixed<I> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<I> Copy for Fixed<I> {}

impl<I> std::fmt::Debug for Fixed<I> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Fixed")
            .field("h", &self.h)
            .field("dense", &self.dense)
            .finish()
    }
}

impl<I> Fixed<I> {
    /// The method with step `h` (checked when the solver is made), with dense output.
    pub fn new(h: f64) -> Self {
        Fixed {
            h,
            dense: true,
            method: PhantomData,
        }
    }

    /// Without the evaluation of q̈ at the end of every step: the dense output is then the cubic
    /// Hermite interpolant of q from q and q̇ at both ends and the straight line between the two
    /// q̇ (what events are located on).
    pub fn without_dense(self) -> Self {
        Fixed {
            dense: false,
            ..self
        }
    }

    /// The step size.
    pub fn step_size(&self) -> f64 {
        self.h
    }
}

impl<I: Integrator, const N: usize> Method<N> for Fixed<I> {
    const NAME: &'static str = I::NAME;
    const TANGENT: bool = I::STEPS_ON_DUALS;
    type Memory = I::Memory<N>;
    type Scratch = ();

    fn validate(&self, t: f64) -> Result<()> {
        check_step_at(t, self.h)
    }
    fn memory(&self) -> I::Memory<N> {
        Default::default()
    }
    fn scratch(&self) {}
    fn proposed_step(&self, _: &I::Memory<N>) -> Option<f64> {
        Some(self.h)
    }

    /// One step of h, or of t_limit − t when that is shorter (or only slightly longer, so no
    /// sliver of a step is left).
    fn step<M: Evaluate<N>, T: Tangent<M, N>>(
        s: &mut Stepper<'_, M, Self, N, T>,
        t_limit: f64,
    ) -> Result<()> {
        check_limit(s.t, t_limit)?;
        let (mut h, mut t1) = (s.method.h, s.t + s.method.h);
        if s.t + 1.01 * s.method.h >= t_limit {
            (h, t1) = (t_limit - s.t, t_limit);
        }
        check_step_at(s.t, h)?;
        if ContactsOf::<M, N>::SWITCHES {
            step_holding(s, h, t1)
        } else {
            step_plain(s, h, t1)
        }
    }
}

/// A step of h ending at t₁ (t + h, or the limit it lands on): the method's step (on the tangent,
/// whose real parts are the new state, when the solver carries one), the projection onto the
/// constraints, the check of the new state and the dense output.
fn step_plain<I, M, T, const N: usize>(
    s: &mut Stepper<'_, M, Fixed<I>, N, T>,
    h: f64,
    t1: f64,
) -> Result<()>
where
    I: Integrator,
    M: Evaluate<N>,
    T: Tangent<M, N>,
{
    let m = s.mechanism;
    let mut memory = s.memory;
    let mut tangent = s.tangent.clone();
    let mut stats = Stats::default();
    let (mut q1, mut v1) = if T::ACTIVE {
        tangent.step::<I>(m, s.t, h, &mut stats)?
    } else {
        I::advance(m, &mut memory, s.t, &s.q, &s.v, h, &mut stats)?
    };
    m.project(t1, &mut q1, &mut v1)?;
    check_state(&M::Coords::NAMES, t1, &q1, &v1)?;
    let start = (&s.q, &s.v);
    let rates = (
        m.position_rates_at(&s.q, &s.v),
        m.position_rates_at(&q1, &v1),
    );
    let rates = (&rates.0, &rates.1);
    let a1 = if s.method.dense {
        let a1 = m
            .accelerations_at(t1, &q1, &v1)
            .map_err(|e| diagnose(m, t1, &q1, &v1, e))?;
        stats.evaluations += 1;
        let (start, end) = ((start.0, start.1, &s.a), (&q1, &v1, &a1));
        s.dense.set_hermite(s.t, h, start, end, rates);
        a1
    } else {
        s.dense
            .set_hermite_positions(s.t, h, start, (&q1, &v1), rates);
        s.a
    };
    // The dense output stays in the chart the step was taken in; the next step starts in the
    // regular one, its q̈ evaluated there.
    let a1 = if m.switch_charts(&mut q1, &mut v1) {
        tangent.switch_charts(m);
        // What the method kept of the old coordinates (an implicit method's Jacobian) is stale.
        memory = I::Memory::<N>::default();
        stats.evaluations += 1;
        m.accelerations_at(t1, &q1, &v1)
            .map_err(|e| diagnose(m, t1, &q1, &v1, e))?
    } else {
        a1
    };
    stats.accepted += 1;
    (s.t, s.q, s.v, s.a, s.memory) = (t1, q1, v1, a1, memory);
    s.tangent = tangent;
    s.stats += stats;
    Ok(())
}

/// A step of h ending at t₁ for a declaration with unilateral or friction rows: the contact mode
/// held over it and its changes located ([`hold_over_step`]), then q̈ in the final mode and the
/// cubic Hermite dense output (across a mode change inside the step only a rough interpolant).
fn step_holding<I, M, T, const N: usize>(
    s: &mut Stepper<'_, M, Fixed<I>, N, T>,
    h: f64,
    t1: f64,
) -> Result<()>
where
    I: Integrator,
    M: Evaluate<N>,
    T: Tangent<M, N>,
{
    let (m, model, constants) = (s.mechanism, s.mechanism.model(), s.mechanism.prepared());
    let mut contacts = s.contacts;
    let mut stats = Stats::default();
    let start = (s.t, &s.q, &s.v);
    let ((q1, v1), changes) =
        hold_over_step::<I, M, N>(m, &mut contacts, &s.options, start, h, &mut stats)?;
    let a1 = contacts
        .accelerations(model, constants, t1, &q1, &v1)
        .unwrap_or([f64::NAN; N]);
    stats.evaluations += 1;
    let rates = (
        m.position_rates_at(&s.q, &s.v),
        m.position_rates_at(&q1, &v1),
    );
    let (start, end) = ((&s.q, &s.v, &s.a), (&q1, &v1, &a1));
    s.dense
        .set_hermite(s.t, h, start, end, (&rates.0, &rates.1));
    let (mut q1, mut v1) = (q1, v1);
    let a1 = if m.switch_charts(&mut q1, &mut v1) {
        stats.evaluations += 1;
        contacts
            .accelerations(model, constants, t1, &q1, &v1)
            .unwrap_or([f64::NAN; N])
    } else {
        a1
    };
    stats.accepted += 1;
    (s.t, s.q, s.v, s.a) = (t1, q1, v1, a1);
    s.contacts = contacts;
    s.changes.extend(changes);
    s.stats += stats;
    Ok(())
}

/// `sys.step::<I>(&mut state, h)` on a declaration with unilateral or friction rows: one step of
/// h with the contact mode inferred from the state held over it and its changes located and
/// applied ([`hold_over_step`], default [`ContactOptions`]). On error the state is unchanged.
pub(super) fn step_holding_contacts<I: Integrator, M: Evaluate<N>, const N: usize>(
    mechanism: &M,
    state: &mut State<M::Coords>,
    h: f64,
) -> Result<()> {
    check_step_at(state.t, h)?;
    let (q, v) = mechanism.check(state)?;
    mechanism.check_constraints(state.t, &q, &v)?;
    let (model, constants) = (mechanism.model(), mechanism.prepared());
    let mut contacts = ContactsOf::<M, N>::start(model, constants, state.t, &q, &v)?;
    let options = ContactOptions::default();
    let start = (state.t, &q, &v);
    let mut stats = Stats::default();
    let ((mut q1, mut v1), _) =
        hold_over_step::<I, M, N>(mechanism, &mut contacts, &options, start, h, &mut stats)?;
    mechanism.switch_charts(&mut q1, &mut v1);
    commit(state, state.t + h, &q1, &v1)
}

/// A (sub)step of length τ from (t, q, q̇) with a contact mode held: one step of `I` with fresh
/// working memory on the mechanism in that mode ([`HeldMode`], with the outer call's constants),
/// projected onto the mode's rows.
fn held_step<I: Integrator, M: Dynamics<N>, const N: usize>(
    held: &HeldMode<'_, M, M::Contacts>,
    (t, q, v): (f64, &[f64; N], &[f64; N]),
    tau: f64,
    stats: &mut Stats,
) -> Result<([f64; N], [f64; N])> {
    let mut memory = I::Memory::<N>::default();
    let (mut q1, mut v1) = I::advance(held, &mut memory, t, q, v, tau, stats)?;
    held.project(t + tau, &mut q1, &mut v1)?;
    Ok((q1, v1))
}

/// Advances (t₀, q₀, q̇₀) by exactly h with the one-step method `I` and the contact mode
/// `contacts` held over every (sub)step: when an event function is negative at the end of a
/// (sub)step, the (sub)step length τ at which it is zero is found by the Illinois variant of
/// regula falsi (Dowell & Jarratt, BIT 11 (1971) 168–174) on τ ↦ φ((sub)step of length τ from its
/// start), to [`ContactOptions::event_tolerance`] relative; the state is advanced to the event
/// (just past it), the mode switched ([`ContactModel::switch`]), and the rest of the step taken in
/// the new mode. Events are detected at (sub)step ends only: an event function that dips below 0
/// and back within one step is missed (choose h below the time scale of the contact dynamics).
///
/// Returns the state at t₀ + h and the mode changes; `contacts` is the new mode. The cost of every
/// (sub)step, those of the event location included, goes to `stats` (no accepted step: the
/// caller counts it). Errors: a method that enforces only position rows on a declaration with
/// velocity or friction rows ([`Error::UnsuitableMethod`]), the method's errors, a projection or a
/// switch that fails, more than [`ContactOptions::max_events_per_step`] mode changes
/// ([`Error::TooManyEvents`]); `contacts` is then unchanged.
#[allow(clippy::type_complexity)]
pub(super) fn hold_over_step<I: Integrator, M: Evaluate<N>, const N: usize>(
    mechanism: &M,
    contacts: &mut ContactsOf<M, N>,
    options: &ContactOptions,
    (t0, q0, v0): (f64, &[f64; N], &[f64; N]),
    h: f64,
    stats: &mut Stats,
) -> Result<(([f64; N], [f64; N]), Vec<ModeChange>)> {
    refuse_velocity_rows::<I, M, N>()?;
    let (model, constants) = (mechanism.model(), mechanism.prepared());
    let t_end = t0 + h;
    let (mut t, mut q, mut v) = (t0, *q0, *v0);
    let mut x = *contacts;
    let mut cost = Stats::default();
    let mut changes: Vec<ModeChange> = Vec::new();
    loop {
        let span = t_end - t;
        x.refresh(model, constants, t, &q, &v, span)?;
        let held = HeldMode {
            model,
            constants,
            contacts: x,
        };
        let end = held_step::<I, M::Model, N>(&held, (t, &q, &v), span, &mut cost)?;
        let phi1 = x.event_values(model, constants, t_end, &end.0, &end.1)?;
        let triggered = x.triggered(model, constants, t, &q, &v, &phi1);
        let Some(first) = triggered.as_ref().iter().position(|&b| b) else {
            x.rearm(&phi1);
            (q, v) = end;
            break;
        };
        let interval = Interval {
            start: (t, &q, &v),
            span,
            end,
            phi_end: &phi1,
        };
        let fired = (first, &triggered);
        let (tau, row, state) =
            earliest_event::<I, M::Model, N>(&held, options, &interval, fired, &mut cost)?;
        t += tau;
        (q, v) = state;
        let restitution = options.restitution;
        changes.push(x.switch(model, constants, restitution, t, (&mut q, &mut v), row)?);
        if changes.len() > options.max_events_per_step {
            return Err(Error::TooManyEvents {
                t,
                events: changes.len(),
            });
        }
        // An event within round-off of the step's end ends the step.
        if t_end - t <= 4.0 * f64::EPSILON * t_end.abs().max(h) {
            break;
        }
    }
    check_state(&M::Coords::NAMES, t_end, &q, &v)?;
    *contacts = x;
    // Accepted steps are the caller's to count.
    *stats += Stats {
        accepted: 0,
        ..cost
    };
    Ok(((q, v), changes))
}

/// A (sub)step of a held mode whose end has events: its start, length, end and the event values
/// there.
struct Interval<'a, V, const N: usize> {
    start: (f64, &'a [f64; N], &'a [f64; N]),
    span: f64,
    end: ([f64; N], [f64; N]),
    phi_end: &'a V,
}

/// The earliest event among the rows of a (sub)step that fired (`first`, and those `triggered`
/// after it): its (sub)step length just past the event, its row and the state there.
#[allow(clippy::type_complexity)]
fn earliest_event<I: Integrator, M: Dynamics<N>, const N: usize>(
    held: &HeldMode<'_, M, M::Contacts>,
    options: &ContactOptions,
    interval: &Interval<'_, <M::Contacts as ContactModel<M, N>>::Values, N>,
    (first, triggered): (usize, &<M::Contacts as ContactModel<M, N>>::Rows),
    stats: &mut Stats,
) -> Result<(f64, usize, ([f64; N], [f64; N]))> {
    let (t, q, v) = interval.start;
    let phi0 = held
        .contacts
        .event_values(held.model, held.constants, t, q, v)?;
    let locate_row = |row: usize, stats: &mut Stats| {
        let phi = (phi0.as_ref()[row], interval.phi_end.as_ref()[row]);
        locate::<I, M, N>(held, options, interval, row, phi, stats)
    };
    let (tau, state) = locate_row(first, stats)?;
    let mut earliest = (tau, first, state);
    let later = triggered.as_ref().iter().enumerate().skip(first + 1);
    for (row, _) in later.filter(|(_, &fired)| fired) {
        let (tau, state) = locate_row(row, stats)?;
        if tau < earliest.0 {
            earliest = (tau, row, state);
        }
    }
    Ok(earliest)
}

/// The Illinois iteration on the (sub)step length for the zero of row `row`'s event function, from
/// its values `(phi_start, phi_end)` at both ends; returns the length just past the event and the
/// state there. A function that starts at zero (a contact that just bounced off) is bracketed
/// from the first of span·2⁻ᵏ (k = 40, …, 1) where it is positive; if there is none, the event is
/// at the start.
#[allow(clippy::type_complexity)]
fn locate<I: Integrator, M: Dynamics<N>, const N: usize>(
    held: &HeldMode<'_, M, M::Contacts>,
    options: &ContactOptions,
    interval: &Interval<'_, <M::Contacts as ContactModel<M, N>>::Values, N>,
    row: usize,
    (phi_start, phi_end): (f64, f64),
    stats: &mut Stats,
) -> Result<(f64, ([f64; N], [f64; N]))> {
    let (t, q, v) = interval.start;
    let span = interval.span;
    let at = |tau: f64, stats: &mut Stats| -> Result<(f64, ([f64; N], [f64; N]))> {
        let state = held_step::<I, M, N>(held, (t, q, v), tau, stats)?;
        let (model, constants) = (held.model, held.constants);
        let value = held
            .contacts
            .event_values(model, constants, t + tau, &state.0, &state.1)?;
        let value = value.as_ref()[row];
        Ok((value, state))
    };
    let (mut a, mut fa) = (0.0, phi_start);
    if !(phi_start > 0.0) {
        let mut found = false;
        for k in (1..=40).rev() {
            let tau = span * 0.5f64.powi(k);
            let (f, _) = at(tau, stats)?;
            if f > 0.0 {
                (a, fa, found) = (tau, f, true);
                break;
            }
        }
        if !found {
            return Ok((0.0, (*q, *v)));
        }
    }
    let tol = options.event_tolerance * (t.abs() + span);
    let (mut b, mut fb, mut sb) = (span, phi_end, interval.end);
    let mut side = 0i8;
    for _ in 0..200 {
        if b - a <= tol {
            break;
        }
        // A secant point within tol/2 of an end (or past it) is moved to tol/2 from it (Brent's
        // least step, *Algorithms for Minimization without Derivatives*, 1973, §4.2): when that
        // end is the zero to rounding, the bracket closes at the next test, whichever side of the
        // zero the rounding put it, instead of shrinking from the far end one halving at a time.
        let secant = b - fb * (b - a) / (fb - fa);
        let c = if secant.is_nan() {
            0.5 * (a + b)
        } else {
            secant.max(a + 0.5 * tol).min(b - 0.5 * tol)
        };
        let (fc, sc) = at(c, stats)?;
        if fc <= 0.0 {
            (b, fb, sb) = (c, fc, sc);
            if side == -1 {
                fa *= 0.5;
            }
            side = -1;
        } else {
            (a, fa) = (c, fc);
            if side == 1 {
                fb *= 0.5;
            }
            side = 1;
        }
    }
    Ok((b, sb))
}

/// Refuses, for a method that enforces only position rows (RATTLE:
/// [`Integrator::POSITION_ROWS_ONLY`]), a declaration with velocity or friction rows: decided by
/// the declaration, never by a state.
fn refuse_velocity_rows<I: Integrator, M: Evaluate<N>, const N: usize>() -> Result<()> {
    if !I::POSITION_ROWS_ONLY || ContactsOf::<M, N>::HELD_COUNTS.velocity == 0 {
        return Ok(());
    }
    let declared = <M::Model as Dynamics<N>>::CONSTRAINT_COUNTS.unwrap_or_default();
    Err(Error::UnsuitableMethod {
        method: I::NAME,
        reason: format!(
            "the declaration has {} velocity and {} friction rows, which constrain the velocities, \
             not the positions: RATTLE enforces only rows g(q, t) = 0 (holonomic rows, and the \
             closed unilateral contacts while the contact mode is held); integrate friction with \
             GaussLegendre2 or ImplicitMidpoint (symplectic methods on (q, p), the mode held over \
             each step), Rk4, Dopri5, Dop853 or Radau5",
            declared.velocity, declared.friction
        ),
    })
}
