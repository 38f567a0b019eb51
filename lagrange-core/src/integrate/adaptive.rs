//! The adaptive loop, generic over the embedded pair ([`EmbeddedPair`]: Dopri5, Dop853, Radau5):
//! one accepted step of the method, the projection onto the constraints and q̈ at the new point;
//! for a declaration with unilateral or friction rows, the contact mode held over the step, the
//! step cut at the first mode change inside it, located on the step's dense output, and the mode
//! switched there.
//!
//! With a held mode, without an event a step costs what a step of the method costs (Dopri5: 6
//! evaluations of q̈, FSAL; Dop853: 12 + 3 for the dense output; Radau5: 3 per Newton iteration +
//! 1 at the new point, and its Jacobians and factorisations — exact for the mode, by dual numbers
//! through its solve) plus the event functions at its end ([`Stats::event_evaluations`]; one
//! constrained solve when a contact is closed); a cut step adds the step recomputed as one step
//! from its start to the event ([`EmbeddedPair::shorten`]: a shorter step, so its local error is
//! within the tolerance as well) and one evaluation at the switched state. After a switch the
//! step size the controller proposed is kept; what the method computed on the old field (Radau5's
//! Jacobian, factorisation and starting values) is not ([`EmbeddedPair::field_changed`]). The
//! dense output of a step is the method's over the step (up to the cut); the state after a step is
//! the state after the switch (the post-impact velocities, say). Events are detected at step
//! ends: an event function that dips below zero and back within one step is missed (bound
//! `h_max` if that can happen).

// `!(x > 0)` is deliberate: it also treats NaN as not positive.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use super::dense::DenseOutput;
use super::newton::jacobians_by_duals;
use super::pair::{AccelerationField, OfMechanism, StepStart};
use super::stepper::{ContactsOf, Method, Stepper, Tangent};
use super::{EmbeddedPair, Integrator, Stats};
use crate::constraints::{ContactModel, ModeChange};
use crate::error::{Error, Result};
use crate::evaluation::{diagnose, Constants, Dynamics, Evaluate, Prepare};
use crate::model::{check_state, Coordinates};
use nalgebra::SMatrix;

/// (q, q̇, q̈) at the end of an accepted step.
type Phase<const N: usize> = ([f64; N], [f64; N], [f64; N]);

impl<P: EmbeddedPair, const N: usize> Method<N> for P {
    const NAME: &'static str = <P as EmbeddedPair>::NAME;
    const TANGENT: bool = P::REPLAYS_ON_DUALS;
    /// The method's memory, from the first step on (the first step is chosen there, once the
    /// interval of a first integration is known).
    type Memory = Option<P::Memory<N>>;
    type Scratch = P::Scratch<N>;

    fn validate(&self, _: f64) -> Result<()> {
        EmbeddedPair::validate(self)
    }
    fn max_steps(&self) -> usize {
        EmbeddedPair::max_steps(self)
    }
    fn memory(&self) -> Self::Memory {
        None
    }
    fn scratch(&self) -> Self::Scratch {
        <P as EmbeddedPair>::scratch()
    }
    fn bounded_to(&self, memory: &Self::Memory, interval: f64) -> Self {
        match memory {
            None => EmbeddedPair::bounded_to(self, interval),
            Some(_) => *self,
        }
    }
    fn proposed_step(&self, memory: &Self::Memory) -> Option<f64> {
        memory.as_ref().map(<P as EmbeddedPair>::proposed_step)
    }

    /// One accepted step, not past `t_limit`, cut at the first mode change inside it for a
    /// declaration with unilateral or friction rows (see the [`integrate`](crate::integrate) module docs). On error the
    /// solver (state, memory, statistics, contact mode, mode changes) is unchanged.
    #[inline]
    fn step<M: Evaluate<N>, T: Tangent<M, N>>(
        s: &mut Stepper<'_, M, Self, N, T>,
        t_limit: f64,
    ) -> Result<()> {
        let mut stats = s.stats;
        let memory = match s.memory {
            Some(memory) => memory,
            None => {
                let start = (s.t, &s.q, &s.v, &s.a);
                if ContactsOf::<M, N>::SWITCHES {
                    let field = InMode {
                        model: s.mechanism.model(),
                        constants: s.mechanism.prepared(),
                        contacts: s.contacts,
                    };
                    s.method.start(&field, start, &mut stats)
                } else {
                    s.method.start(&OfMechanism(s.mechanism), start, &mut stats)
                }
            }
        };
        if ContactsOf::<M, N>::SWITCHES {
            step_holding(s, memory, stats, t_limit)
        } else {
            step_plain(s, memory, stats, t_limit)
        }
    }
}

/// `sys.step::<P>(&mut state, h)` for an adaptive method ([`Dopri5`](super::Dopri5),
/// [`Dop853`](super::Dop853), [`Radau5`](super::Radau5)): integrates over [t, t + h] with its
/// [one-step settings](EmbeddedPair::one_step_settings) (the default tolerances), as many adaptive
/// steps as that takes, landing exactly on t + h — the state advances by h, as with every
/// fixed-step method. For other tolerances, dense output or events use a [`Stepper`].
impl<P: EmbeddedPair> Integrator for P {
    const NAME: &'static str = <P as EmbeddedPair>::NAME;
    type Memory<const N: usize> = ();
    const ADAPTIVE: bool = true;

    fn advance<M: Evaluate<N>, const N: usize>(
        mechanism: &M,
        _memory: &mut (),
        t: f64,
        q: &[f64; N],
        v: &[f64; N],
        h: f64,
        stats: &mut Stats,
    ) -> Result<([f64; N], [f64; N])> {
        let mut stepper = Stepper::from_checked(mechanism, P::one_step_settings(), t, *q, *v)?;
        let t_end = t + h;
        let mut result = Ok(());
        while stepper.t < t_end && result.is_ok() {
            result = stepper.step(t_end);
        }
        *stats += stepper.stats;
        result.map(|()| (stepper.q, stepper.v))
    }
}

/// One accepted step on the mechanism's own accelerations: the method's step with its dense output
/// written in place, the projection onto the constraints (the FSAL q̈ kept, see
/// [`project_accepted`]), q̈ at the new point when the method did not evaluate it, and on a
/// solver that carries a tangent the step taken again on it. Inlined into the solver's step, so
/// that its memory and statistics are not copied through a call.
#[inline(always)]
fn step_plain<P, M, T, const N: usize>(
    s: &mut Stepper<'_, M, P, N, T>,
    mut memory: P::Memory<N>,
    mut stats: Stats,
    t_limit: f64,
) -> Result<()>
where
    P: EmbeddedPair,
    M: Evaluate<N>,
    T: Tangent<M, N>,
{
    let m = s.mechanism;
    let (t, q, v) = (s.t, s.q, s.v);
    let start = (t, &q, &v, &s.a);
    let field = OfMechanism(m);
    let step = s.method.step::<M::Coords, N>(
        &mut memory,
        &mut s.scratch,
        &field,
        start,
        t_limit,
        &mut stats,
        &mut s.dense,
    )?;
    // The dense output is the new step's from here on: an error leaves the constant at the state.
    let mut finish = || -> Result<(Phase<N>, T, bool)> {
        let (mut qp, mut vp) = project_accepted(m, step.t, (step.q, step.v))?;
        // A chart switch moves the state to other coordinates: the method's q̈ at the end was
        // in the old ones (the dense output stays there), so q̈ is evaluated again.
        let switched = m.switch_charts(&mut qp, &mut vp);
        let a = match step.a {
            Some(a) if !switched => a,
            _ => {
                stats.evaluations += 1;
                m.accelerations_at(step.t, &qp, &vp)
                    .map_err(|e| diagnose(m, step.t, &qp, &vp, e))?
            }
        };
        let mut tangent = s.tangent.clone();
        if T::ACTIVE {
            tangent.replay(m, &s.method, t, s.dense.h)?;
            if switched {
                tangent.switch_charts(m);
            }
        }
        Ok(((qp, vp, a), tangent, switched))
    };
    match finish() {
        Ok(((qp, vp, a), tangent, switched)) => {
            if switched {
                P::field_changed(&mut memory);
            }
            (s.t, s.q, s.v, s.a) = (step.t, qp, vp, a);
            (s.memory, s.stats, s.tangent) = (Some(memory), stats, tangent);
            Ok(())
        }
        Err(e) => {
            s.dense = DenseOutput::constant(t, &q, &v);
            Err(e)
        }
    }
}

/// Projects an accepted step's end (q₁, q̇₁) onto the constraints (a no-op without any) and checks
/// the projected state. q̈ is not evaluated again there: the step's last evaluation, at the end
/// before the projection, stays the first stage of the next step. The projection moves the state
/// by one step's drift off the constraints, which is of the order of the step's local error,
/// O(hᵖ⁺¹) (the exact flow keeps g = 0, so g(q₁) is G times the local error); q̈ differs between
/// the two points by as much, and the next step takes it times h, so the perturbation is
/// O(hᵖ⁺²), below the local error the step controls, and the order is kept.
fn project_accepted<M: Evaluate<N>, const N: usize>(
    mechanism: &M,
    t: f64,
    (q1, v1): ([f64; N], [f64; N]),
) -> Result<([f64; N], [f64; N])> {
    // A declaration without constraint rows has nothing to project onto (the hook is a no-op):
    // nothing to copy or check.
    if matches!(M::CONSTRAINTS, Some(0)) {
        return Ok((q1, v1));
    }
    let (mut qp, mut vp) = (q1, v1);
    mechanism.project(t, &mut qp, &mut vp)?;
    if qp != q1 || vp != v1 {
        check_state(&M::Coords::NAMES, t, &qp, &vp)?;
    }
    Ok((qp, vp))
}

/// The accelerations of a constrained mechanism in a held contact mode: q̈ in `f64`, and its
/// Jacobians by dual numbers through the same solve (exact for the mode: the mode's rows
/// enforced, its sliding directions and slip signs fixed), with the constants of the call that
/// holds the mode.
struct InMode<'m, M: Prepare, X> {
    model: &'m M,
    constants: Constants<'m, M>,
    contacts: X,
}

impl<M: Dynamics<N>, X: ContactModel<M, N>, const N: usize> AccelerationField<N>
    for InMode<'_, M, X>
{
    #[inline]
    fn accelerations(&self, t: f64, q: &[f64; N], v: &[f64; N]) -> Result<[f64; N]> {
        self.contacts
            .accelerations(self.model, self.constants, t, q, v)
    }

    #[inline(always)]
    fn position_rates(&self, q: &[f64; N], v: &[f64; N]) -> [f64; N] {
        Dynamics::position_rates_at(self.model, q, v)
    }

    #[inline(always)]
    fn quasi_velocities(&self) -> bool {
        M::QUASI_VELOCITIES
    }

    #[inline(always)]
    fn quasi_joints(&self) -> &'static [crate::tree::rigid::Joint] {
        M::QUASI_VELOCITY_JOINTS
    }

    fn jacobians(
        &self,
        t: f64,
        q: &[f64; N],
        v: &[f64; N],
    ) -> Result<(SMatrix<f64, N, N>, SMatrix<f64, N, N>)> {
        let (_, by_q, by_v) = jacobians_by_duals(t, q, v, |t, q, v| {
            self.contacts
                .accelerations(self.model, self.constants, t, q, v)
        })?;
        Ok((by_q, by_v))
    }
}

/// Where a step in a held mode ends: at its end, or at the first mode change inside it (the row
/// that switches), with q̈ there when the method evaluated it.
struct StepEnd<const N: usize> {
    t: f64,
    q: [f64; N],
    v: [f64; N],
    a: Option<[f64; N]>,
    change: Option<usize>,
}

/// One accepted step in the held contact mode: the mode refreshed for the step (a sliding cone's
/// reference direction), the method's step on the mode's accelerations, the step cut at its first
/// event ([`cut_at_event`]), the projection onto the mode's rows, and the mode switched where an
/// event cut it ([`switch_or_rearm`]).
fn step_holding<P, M, T, const N: usize>(
    s: &mut Stepper<'_, M, P, N, T>,
    mut memory: P::Memory<N>,
    mut stats: Stats,
    t_limit: f64,
) -> Result<()>
where
    P: EmbeddedPair,
    M: Evaluate<N>,
    T: Tangent<M, N>,
{
    let (model, constants) = (s.mechanism.model(), s.mechanism.prepared());
    let (t, q, v) = (s.t, s.q, s.v);
    let mut contacts = s.contacts;
    // A sliding cone continues its slip direction of the step's start.
    let h_next = <P as EmbeddedPair>::proposed_step(&memory).min(t_limit - t);
    contacts.refresh(model, constants, t, &q, &v, h_next)?;
    let field = InMode {
        model,
        constants,
        contacts,
    };
    let a = if contacts == s.contacts {
        s.a
    } else {
        stats.evaluations += 1;
        field.accelerations(t, &q, &v)?
    };
    let start = (t, &q, &v, &a);
    let mut dense = s.dense;
    let method = s.method;
    let working = (&mut memory, &mut s.scratch);
    let step = method.step::<M::Coords, N>(
        working.0, working.1, &field, start, t_limit, &mut stats, &mut dense,
    )?;
    stats.event_evaluations += 1;
    let phi_end = contacts.event_values(model, constants, step.t, &step.q, &step.v)?;
    let step_end = (step, &phi_end);
    let mut end = cut_at_event::<P, M::Model, M::Coords, N>(
        &method, working, &field, start, step_end, &mut dense, &mut stats,
    )?;
    let unprojected = (end.q, end.v);
    contacts.project(model, constants, end.t, &mut end.q, &mut end.v)?;
    if (end.q, end.v) != unprojected {
        check_state(&M::Coords::NAMES, end.t, &end.q, &end.v)?;
    }
    let (a_end, event) =
        switch_or_rearm::<P, M, N>(s, &mut contacts, &field, &mut end, &phi_end, &mut stats)?;
    let mut a_end = a_end;
    if s.mechanism.switch_charts(&mut end.q, &mut end.v) {
        // In the regular chart the end's q̈ is another vector (the dense output stays in the
        // chart the step was taken in).
        stats.evaluations += 1;
        a_end = contacts.accelerations(model, constants, end.t, &end.q, &end.v)?;
        P::field_changed(&mut memory);
    } else if event.is_some() {
        P::field_changed(&mut memory);
    }
    let instant_events = if event.is_some() && end.t == t {
        s.instant_events + 1
    } else {
        0
    };
    if instant_events > s.options.max_events_per_step {
        return Err(Error::TooManyEvents {
            t,
            events: instant_events,
        });
    }
    // Accepted: commit everything at once.
    (s.t, s.q, s.v, s.a) = (end.t, end.q, end.v, a_end);
    (s.memory, s.stats, s.dense) = (Some(memory), stats, dense);
    s.contacts = contacts;
    s.instant_events = instant_events;
    s.changes.extend(event);
    Ok(())
}

/// The end of an accepted step in a held mode: where the first row whose event fired over it
/// crosses zero, located on the step's dense output ([`locate`]); the step cut there
/// ([`EmbeddedPair::shorten`], its dense output written into `dense`), or at the step's start
/// when several rows switch at one instant; the step's end when no event fired.
#[allow(clippy::too_many_arguments)]
fn cut_at_event<P: EmbeddedPair, M: Dynamics<N>, C: Coordinates<N>, const N: usize>(
    method: &P,
    (memory, scratch): (&mut P::Memory<N>, &mut P::Scratch<N>),
    field: &InMode<'_, M, M::Contacts>,
    start: StepStart<'_, N>,
    (step, phi_end): (
        super::pair::Accepted<N>,
        &<M::Contacts as ContactModel<M, N>>::Values,
    ),
    dense: &mut DenseOutput<N>,
    stats: &mut Stats,
) -> Result<StepEnd<N>> {
    let (model, constants, contacts) = (field.model, field.constants, &field.contacts);
    let (t, q, v, a) = start;
    let mut end = StepEnd {
        t: step.t,
        q: step.q,
        v: step.v,
        a: step.a,
        change: None,
    };
    let triggered = contacts.triggered(model, constants, t, q, v, phi_end);
    if !triggered.as_ref().iter().any(|&b| b) {
        return Ok(end);
    }
    stats.event_evaluations += 1;
    let phi_start = contacts.event_values(model, constants, t, q, v)?;
    let mut first: Option<(f64, usize)> = None;
    for (row, _) in triggered.as_ref().iter().enumerate().filter(|(_, &b)| b) {
        let phi = (phi_start.as_ref()[row], phi_end.as_ref()[row]);
        let root = locate(field, dense, row, phi, stats);
        if first.is_none_or(|f| root < f.0) {
            first = Some((root, row));
        }
    }
    let Some((root, row)) = first else {
        return Ok(end);
    };
    end.t = root;
    end.change = Some(row);
    if root <= t + 4.0 * f64::EPSILON * t.abs().max(step.t - t) {
        // At the step's start (several rows switching at one instant).
        (end.q, end.v, end.a) = (*q, *v, Some(*a));
        *dense = DenseOutput::constant(t, q, v);
    } else if root < step.t {
        // Cut: the step recomputed from its start to the event.
        let cut = method.shorten::<C, N>(memory, scratch, field, start, root - t, stats, dense)?;
        (end.q, end.v, end.a) = (cut.q, cut.v, cut.a);
    }
    Ok(end)
}

/// After a step in a held mode, projected: without an event, q̈ at its end (the method's, kept
/// through the projection as in a projected step, see [`project_accepted`], or evaluated) and the
/// rows positive there armed; at an event, the mode switched there ([`ContactModel::switch`]),
/// the switched state checked and q̈ in the new mode. Returns q̈ and the mode change.
fn switch_or_rearm<P: EmbeddedPair, M: Evaluate<N>, const N: usize>(
    s: &Stepper<'_, M, P, N, impl Tangent<M, N>>,
    contacts: &mut ContactsOf<M, N>,
    field: &InMode<'_, M::Model, ContactsOf<M, N>>,
    end: &mut StepEnd<N>,
    phi_end: &<ContactsOf<M, N> as ContactModel<M::Model, N>>::Values,
    stats: &mut Stats,
) -> Result<([f64; N], Option<ModeChange>)> {
    let (model, constants) = (field.model, field.constants);
    match end.change {
        None => {
            let a = match end.a {
                Some(a) => a,
                None => {
                    stats.evaluations += 1;
                    field.accelerations(end.t, &end.q, &end.v)?
                }
            };
            contacts.rearm(phi_end);
            Ok((a, None))
        }
        Some(row) => {
            stats.event_evaluations += 1;
            let restitution = s.options.restitution;
            let state = (&mut end.q, &mut end.v);
            let change = contacts.switch(model, constants, restitution, end.t, state, row)?;
            check_state(&M::Coords::NAMES, end.t, &end.q, &end.v)?;
            // The next step integrates another field (or the same from a state that jumped).
            stats.evaluations += 1;
            let a = contacts.accelerations(model, constants, end.t, &end.q, &end.v)?;
            Ok((a, Some(change)))
        }
    }
}

/// The first root in (t₀, t₁] of row `row`'s event function on the step's dense output, from its
/// values at both ends. A function that starts at zero (a contact that just bounced off) is
/// bracketed from the first of t₀ + h·2⁻ᵏ (k = 40, …, 1) where it is positive, as the fixed-step
/// loop does; if there is none, the event is at t₀. Adds the evaluations to `stats`.
fn locate<M: Prepare, X: ContactModel<M, N>, const N: usize>(
    field: &InMode<'_, M, X>,
    dense: &DenseOutput<N>,
    row: usize,
    (phi_start, phi_end): (f64, f64),
    stats: &mut Stats,
) -> f64 {
    let g = |t: f64, q: &[f64; N], v: &[f64; N]| {
        (field.contacts)
            .event_values(field.model, field.constants, t, q, v)
            .map_or(f64::NAN, |phi| phi.as_ref()[row])
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
