//! [`ContactRk4`]: RK4 with the constraint mode fixed during a step and mode changes located in time.

use super::cone;
use super::solve::{accelerations_in_mode, worst_violation};
use super::{
    check_consistent, infer_mode, project, ConstraintKind, Constraints, Mode, RowMode,
    CONSISTENCY_TOLERANCE,
};
use crate::error::{Error, Result};
use crate::integrate::rk4::rk4_step;
use crate::integrate::{check_step_at, DenseOutput, Stats, Stepper};
use crate::model::{check_state, Coordinates, State};

/// Options of [`ContactRk4`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactOptions {
    /// Coefficient of restitution e ∈ [0, 1] of every unilateral contact (Newton's law ċ⁺ = −e ċ⁻).
    /// 0 (the default) is a plastic impact: the contact closes and stays closed while λ ≥ 0.
    pub restitution: f64,
    /// Relative accuracy of event times: the bracket around an event is narrowed to
    /// `event_tolerance · (|t| + h)`. Default 1e-13 (events are located to ≤ 1e-12).
    pub event_tolerance: f64,
    /// Mode changes allowed within one step before the step fails with
    /// [`Error::TooManyEvents`] (a Zeno sequence of impacts, or an inconsistent friction mode).
    pub max_events_per_step: usize,
}

impl ContactOptions {
    /// Checks the options ([`Error::InvalidSetting`] naming the first one out of range): the
    /// restitution in [0, 1], the event tolerance positive and below 1 (it is relative to the step,
    /// so 1 or more would place events anywhere in it), at least one event per step.
    ///
    /// ```
    /// use lagrange_core::constraints::ContactOptions;
    /// assert!(ContactOptions::default().validate().is_ok());
    /// let loose = ContactOptions { event_tolerance: f64::INFINITY, ..Default::default() };
    /// assert!(loose.validate().is_err());
    /// ```
    // `!(x > 0)`-style tests are deliberate: they also reject NaN.
    #[allow(clippy::neg_cmp_op_on_partial_ord)]
    pub fn validate(&self) -> Result<()> {
        let invalid = |setting, value, requirement| {
            Err(Error::InvalidSetting {
                method: "ContactRk4",
                setting,
                value,
                requirement,
            })
        };
        if !(0.0..=1.0).contains(&self.restitution) {
            return invalid("restitution", self.restitution, "in [0, 1]");
        }
        if !(self.event_tolerance > 0.0 && self.event_tolerance < 1.0) {
            return invalid(
                "event_tolerance",
                self.event_tolerance,
                "positive and below 1",
            );
        }
        if self.max_events_per_step == 0 {
            return invalid("max_events_per_step", 0.0, "at least 1");
        }
        Ok(())
    }
}

impl Default for ContactOptions {
    fn default() -> Self {
        ContactOptions {
            restitution: 0.0,
            event_tolerance: 1e-13,
            max_events_per_step: 32,
        }
    }
}

/// The number of rows of a [`Constraints`] declaration, from its [`NAMES`](Constraints::NAMES):
/// what [`impl_mechanism!`](crate::impl_mechanism) declares as
/// `Dynamics::CONSTRAINTS`.
pub const fn row_count<const C: usize>(_names: &[&'static str; C]) -> usize {
    C
}

/// One located mode change.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ModeChange {
    /// When it happened.
    pub t: f64,
    /// The row whose event fired.
    pub row: usize,
    /// Its name.
    pub constraint: &'static str,
    /// The row's mode before.
    pub from: RowMode,
    /// The row's mode after (after any impact and the complementarity checks that follow it). A
    /// contact that bounced off (restitution e > 0) records `Inactive` → `Inactive`; a grazing
    /// contact whose force would pull records `Inactive` → `Inactive` too.
    pub to: RowMode,
}

/// Fixed-step RK4 for mechanisms with unilateral contacts and friction, with events.
///
/// Within a step the [`Mode`] is fixed and the mechanism is integrated by classical RK4 on the
/// constrained accelerations ([`accelerations_in_mode`]) and projected back onto the enforced rows
/// after each (sub)step ([`project`]). Each row has an event function whose sign change is a mode
/// change:
///
/// | row mode | event function φ | crosses 0 when | new mode |
/// |---|---|---|---|
/// | unilateral, separated | c | the contact closes | impact, then in contact (e = 0) or bouncing (e > 0) |
/// | unilateral, in contact | λ | the contact would pull | separated |
/// | friction, sliding with sign σ | σ·s | the slip velocity reaches 0 | s set to 0 exactly, then stick if μₛ holds, else slide the other way |
/// | friction, sticking | μₛ|λₙ| − |λₜ| | static friction is exceeded | slide against λₜ |
/// | friction cone, sliding | s·ŝ_ref (ŝ_ref: the slip direction at the step's start) | the slip stops | s set to 0, then stick if μₛ holds, else slide against the stick force |
/// | friction cone, sticking | μₛ|λₙ| − |(λⱼ, λₖ)| | static friction is exceeded | slide along −λ/|λ| |
///
/// When an event function is negative at the end of a step, the step length τ at which it is zero
/// is found by the Illinois variant of regula falsi (Dowell & Jarratt, BIT 11 (1971) 168–174) on
/// τ ↦ φ(RK4 step of length τ from the step's start), to `event_tolerance` relative; the state is
/// advanced to the event (just past it), the mode switched, and the rest of the step integrated in
/// the new mode, so `step` always advances by exactly `h`. A row whose event just fired is disarmed
/// until its new event function is positive, which rules out chattering at a stick/slip boundary or
/// a grazing release. Events are detected at step ends only: an event function that dips below 0
/// and back within one step is missed (choose h below the time scale of the contact dynamics).
///
/// The state passed to [`ContactRk4::new`] must satisfy the constraints (use
/// [`consistent_state`](super::consistent_state) on a guess). The stepper keeps the mode and the
/// list of mode changes; a failed step leaves both, and the caller's state, unchanged. It assumes
/// the state it steps is the one it produced last: after changing the state by hand, call
/// [`ContactRk4::reset`].
#[derive(Clone, Debug)]
pub struct ContactRk4<const C: usize> {
    pub(super) mode: Mode<C>,
    pub(super) armed: [bool; C],
    /// The options.
    pub options: ContactOptions,
    /// Every mode change so far, in order (grows only when an event happens).
    pub events: Vec<ModeChange>,
    /// What the steps so far cost (see [`ContactRk4::stats`]).
    pub(super) stats: Stats,
}

/// One RK4 step of length `h` in `mode` ([`rk4_step`] on the mode's accelerations), then the
/// projection onto the mode's rows.
fn substep<M: Constraints<N, K, C>, const N: usize, const K: usize, const C: usize>(
    model: &M,
    t: f64,
    q: &[f64; N],
    v: &[f64; N],
    h: f64,
    mode: &Mode<C>,
) -> Result<([f64; N], [f64; N])> {
    let (mut qn, mut vn) = rk4_step(t, q, v, h, |t, q, v| {
        Ok(accelerations_in_mode(model, t, q, v, mode)?.accelerations)
    })?;
    project(model, t + h, &mut qn, &mut vn, mode)?;
    Ok((qn, vn))
}

/// A (sub)step of length τ from (t, q, q̇) in a held mode, projected onto its rows: (q, q̇) at t + τ.
pub(super) type Substep<'a, const N: usize, const C: usize> =
    dyn Fn(f64, &[f64; N], &[f64; N], f64, &Mode<C>) -> Result<([f64; N], [f64; N])> + 'a;

/// The event function of every row in `mode` (+∞ for rows without one).
pub(super) fn event_values<
    M: Constraints<N, K, C>,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    model: &M,
    t: f64,
    q: &[f64; N],
    v: &[f64; N],
    mode: &Mode<C>,
) -> Result<[f64; C]> {
    let needs_lambda = (0..C).any(|i| {
        matches!(
            (M::KINDS[i], mode.rows[i]),
            (ConstraintKind::Unilateral, RowMode::Active) | (_, RowMode::Stick)
        )
    });
    let lambda = if needs_lambda {
        accelerations_in_mode(model, t, q, v, mode)?.multipliers
    } else {
        [0.0; C]
    };
    let x = model.cartesian(t, q);
    let c = model.position_constraints(t, q, &x);
    let needs_slip = (0..C).any(|i| {
        matches!(
            mode.rows[i],
            RowMode::SlipPositive | RowMode::SlipNegative | RowMode::Sliding
        )
    });
    let s = if needs_slip {
        let (x, x_dot) = crate::dynamics::cartesian_velocities(model, t, q, v);
        model.velocity_constraints(t, q, v, &x, &x_dot)
    } else {
        [0.0; C]
    };
    Ok(std::array::from_fn(|i| match (M::KINDS[i], mode.rows[i]) {
        (ConstraintKind::Unilateral, RowMode::Inactive) => c[i],
        (ConstraintKind::Unilateral, RowMode::Active) => lambda[i],
        (ConstraintKind::Friction { .. }, RowMode::SlipPositive) => s[i],
        (ConstraintKind::Friction { .. }, RowMode::SlipNegative) => -s[i],
        (ConstraintKind::Friction { normal }, RowMode::Stick) => {
            model.friction_coefficients(i).stiction * lambda[normal].abs() - lambda[i].abs()
        }
        // A cone's pair has one event, on its first row: the slip along the step's reference
        // direction, or the margin of static friction.
        (ConstraintKind::FrictionCone { partner, .. }, RowMode::Sliding) if i < partner => {
            s[i] * mode.reference[i] + s[partner] * mode.reference[partner]
        }
        (ConstraintKind::FrictionCone { normal, partner }, RowMode::Stick) if i < partner => {
            -cone::stick_excess(model, i, partner, normal, &lambda)
        }
        _ => f64::INFINITY,
    }))
}

/// The rows whose event fired over a (sub)step from (t, q, v) in `mode`, given the event functions
/// `phi_end` at its end: armed rows whose function is negative there, and also a contact that
/// bounced off (disarmed, separating at the start) and closes again within the same step.
pub(super) fn triggered_rows<
    M: Constraints<N, K, C>,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    model: &M,
    t: f64,
    q: &[f64; N],
    v: &[f64; N],
    mode: &Mode<C>,
    armed: &[bool; C],
    phi_end: &[f64; C],
) -> [bool; C] {
    let separated = |i: usize| {
        matches!(
            (M::KINDS[i], mode.rows[i]),
            (ConstraintKind::Unilateral, RowMode::Inactive)
        )
    };
    let separating: [bool; C] = if (0..C).any(|i| !armed[i] && phi_end[i] < 0.0 && separated(i)) {
        let (cr, scales) = super::rows::rows_and_scales(model, t, q, v);
        std::array::from_fn(|i| {
            separated(i) && cr.rate[i] > CONSISTENCY_TOLERANCE * scales.velocity[i]
        })
    } else {
        [false; C]
    };
    std::array::from_fn(|i| (armed[i] || separating[i]) && phi_end[i] < 0.0)
}

impl<const C: usize> ContactRk4<C> {
    /// A stepper starting at `state`, whose mode is inferred by complementarity ([`infer_mode`]).
    ///
    /// Errors: invalid options ([`ContactOptions::validate`]), invalid parameters or friction
    /// coefficients, a state that violates the constraints beyond [`CONSISTENCY_TOLERANCE`]
    /// ([`Error::ConstraintViolation`]; project it first with
    /// [`consistent_state`](super::consistent_state)), a velocity row that is not linear in q̇.
    pub fn new<M: Constraints<N, K, C>, const N: usize, const K: usize>(
        model: &M,
        state: &State<M::Coords>,
        options: ContactOptions,
    ) -> Result<Self> {
        options.validate()?;
        model.validate()?;
        let (q, v) = (state.q.to_array(), state.v.to_array());
        check_state(&<M::Coords as Coordinates<N>>::NAMES, state.t, &q, &v)?;
        check_consistent(model, state.t, &q, &v, CONSISTENCY_TOLERANCE)?;
        let mode = infer_mode(model, state.t, &q, &v)?;
        let phi = event_values(model, state.t, &q, &v, &mode)?;
        Ok(ContactRk4 {
            mode,
            armed: std::array::from_fn(|i| phi[i] > 0.0),
            options,
            events: Vec::new(),
            stats: Stats::default(),
        })
    }

    /// Restarts at a new state (one not produced by this stepper): checks it and infers its mode
    /// as [`ContactRk4::new`] does, keeping the options and the event list.
    pub fn reset<M: Constraints<N, K, C>, const N: usize, const K: usize>(
        &mut self,
        model: &M,
        state: &State<M::Coords>,
    ) -> Result<()> {
        let fresh = Self::new(model, state, self.options)?;
        self.mode = fresh.mode;
        self.armed = fresh.armed;
        Ok(())
    }

    /// The current mode.
    pub fn mode(&self) -> Mode<C> {
        self.mode
    }

    /// What the successful steps so far cost: `accepted` counts the (sub)steps whose end was kept
    /// (one per step and one more per mode change), `evaluations` (and, for the implicit and
    /// RATTLE methods of [`step_with`](Self::step_with), the Newton counts) every (sub)step taken,
    /// the trial steps of the event location included. RK4 ([`step`](Self::step)) evaluates q̈
    /// four times per (sub)step.
    ///
    /// ```
    /// use lagrange_core::constraints::{ConstraintKind, ContactOptions, ContactRk4, Constraints};
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
    /// let mut contact = ContactRk4::new(&Ball, &s, ContactOptions::default())?;
    /// for _ in 0..10 {
    ///     contact.step(&Ball, &mut s, 1e-2)?;
    /// }
    /// // Ten RK4 steps in flight: 4 evaluations each.
    /// assert_eq!((contact.stats().accepted, contact.stats().evaluations), (10, 40));
    /// # Ok::<(), lagrange_core::Error>(())
    /// ```
    pub fn stats(&self) -> Stats {
        self.stats
    }

    /// Advances `state` by exactly `h`, switching modes at located events. On error the state, the
    /// mode and the event list are unchanged.
    ///
    /// Errors, before anything is computed: an invalid step or one that does not advance time
    /// ([`Error::StepDoesNotAdvance`]), invalid [`options`](Self::options), invalid parameters, a
    /// state that violates the constraints ([`Error::ConstraintViolation`], as for the plain
    /// integrators).
    pub fn step<M: Constraints<N, K, C>, const N: usize, const K: usize>(
        &mut self,
        model: &M,
        state: &mut State<M::Coords>,
        h: f64,
    ) -> Result<()> {
        let substeps = std::cell::Cell::new(0);
        self.step_by(model, state, h, &|t, q, v, tau, mode| {
            substeps.set(substeps.get() + 1);
            substep(model, t, q, v, tau, mode)
        })?;
        self.stats.evaluations += 4 * substeps.get();
        Ok(())
    }

    /// [`step`](Self::step) with `substep(t, q, v, τ, mode)` as the (sub)step of length τ in a
    /// held mode, projected onto the mode's rows: RK4 for [`step`](Self::step), another one-step
    /// method for [`step_with`](Self::step_with).
    pub(super) fn step_by<M: Constraints<N, K, C>, const N: usize, const K: usize>(
        &mut self,
        model: &M,
        state: &mut State<M::Coords>,
        h: f64,
        substep: &Substep<'_, N, C>,
    ) -> Result<()> {
        check_step_at(state.t, h)?;
        self.options.validate()?;
        model.validate()?;
        let names = &<M::Coords as Coordinates<N>>::NAMES;
        let (mut q, mut v) = (state.q.to_array(), state.v.to_array());
        check_state(names, state.t, &q, &v)?;
        // Like every integrator: a state that violates the constraints is refused, not projected
        // (this also checks the friction coefficients and that velocity rows are linear).
        check_consistent(model, state.t, &q, &v, CONSISTENCY_TOLERANCE)?;
        let t0 = state.t;
        let t_end = t0 + h;
        let mut t = t0;
        let mut mode = self.mode;
        let mut armed = self.armed;
        let mut events: Vec<ModeChange> = Vec::new();
        loop {
            let span = t_end - t;
            // A sliding cone continues its slip direction of this (sub)step's start.
            cone::refresh_references(model, t, &q, &v, span, &mut mode)?;
            let (q1, v1) = substep(t, &q, &v, span, &mode)?;
            let phi1 = event_values(model, t_end, &q1, &v1, &mode)?;
            let triggered = triggered_rows(model, t, &q, &v, &mode, &armed, &phi1);
            if !triggered.iter().any(|&b| b) {
                for i in 0..C {
                    armed[i] |= phi1[i] > 0.0;
                }
                (q, v) = (q1, v1);
                break;
            }
            let phi0 = event_values(model, t, &q, &v, &mode)?;
            let mut first: Option<(f64, usize, [f64; N], [f64; N])> = None;
            for i in 0..C {
                if triggered[i] {
                    let (mode, phi, end) = (&mode, (phi0[i], phi1[i]), (q1, v1));
                    let hit = self.locate(model, substep, (t, &q, &v), span, mode, i, phi, end)?;
                    if first.is_none_or(|f| hit.0 < f.0) {
                        first = Some((hit.0, i, hit.1, hit.2));
                    }
                }
            }
            let Some((tau, row, qe, ve)) = first else {
                break;
            };
            t += tau;
            (q, v) = (qe, ve);
            let phi_e = event_values(model, t, &q, &v, &mode)?;
            for i in 0..C {
                armed[i] |= i != row && phi_e[i] > 0.0;
            }
            let before = mode;
            let from = mode.rows[row];
            self.transition(model, t, &mut q, &mut v, &mut mode, row)?;
            for i in 0..C {
                if mode.rows[i] != before.rows[i] || i == row {
                    armed[i] = false;
                }
            }
            events.push(ModeChange {
                t,
                row,
                constraint: M::NAMES[row],
                from,
                to: mode.rows[row],
            });
            if events.len() > self.options.max_events_per_step {
                return Err(Error::TooManyEvents {
                    t,
                    events: events.len(),
                });
            }
            // An event within round-off of the step's end ends the step.
            if t_end - t <= 4.0 * f64::EPSILON * t_end.abs().max(h) {
                break;
            }
        }
        check_state(names, t_end, &q, &v)?;
        state.t = t_end;
        state.q = M::Coords::from_array(q);
        state.v = M::Coords::from_array(v);
        self.mode = mode;
        self.armed = armed;
        self.stats.accepted += events.len() + 1;
        self.events.extend(events);
        Ok(())
    }

    /// Illinois iteration on the step length for the zero of row `row`'s event function; returns the
    /// step length just past the event and the state there.
    #[allow(clippy::too_many_arguments)]
    fn locate<M: Constraints<N, K, C>, const N: usize, const K: usize>(
        &self,
        model: &M,
        substep: &Substep<'_, N, C>,
        (t, q, v): (f64, &[f64; N], &[f64; N]),
        span: f64,
        mode: &Mode<C>,
        row: usize,
        (phi_start, phi_end): (f64, f64),
        end: ([f64; N], [f64; N]),
    ) -> Result<(f64, [f64; N], [f64; N])> {
        let (mut a, mut fa) = (0.0, phi_start);
        if !(phi_start > 0.0) {
            // The event function starts at zero (a contact that just bounced off): the bracket
            // starts at the first of span·2⁻ᵏ (k = 40, …, 1) where it is positive.
            let mut found = false;
            for k in (1..=40).rev() {
                let tau = span * 0.5f64.powi(k);
                let sample = substep(t, q, v, tau, mode)?;
                let f = event_values(model, t + tau, &sample.0, &sample.1, mode)?[row];
                if f > 0.0 {
                    (a, fa, found) = (tau, f, true);
                    break;
                }
            }
            if !found {
                return Ok((0.0, *q, *v));
            }
        }
        let tol = self.options.event_tolerance * (t.abs() + span);
        let (mut b, mut fb, mut sb) = (span, phi_end, end);
        let mut side = 0i8;
        for _ in 0..200 {
            if b - a <= tol {
                break;
            }
            let mut c = b - fb * (b - a) / (fb - fa);
            if !(c > a && c < b) {
                c = 0.5 * (a + b);
            }
            let sc = substep(t, q, v, c, mode)?;
            let fc = event_values(model, t + c, &sc.0, &sc.1, mode)?[row];
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
        Ok((b, sb.0, sb.1))
    }

    /// Switches row `row` after its event at (t, q, v): impact, release, slip stop or stick break,
    /// then restores complementarity of the whole mode and projects onto it.
    pub(super) fn transition<M: Constraints<N, K, C>, const N: usize, const K: usize>(
        &self,
        model: &M,
        t: f64,
        q: &mut [f64; N],
        v: &mut [f64; N],
        mode: &mut Mode<C>,
        row: usize,
    ) -> Result<()> {
        let follow = |mode: &mut Mode<C>, slip: &[f64; C], stick: &[f64; C]| {
            super::mode::friction_rows_follow(&M::KINDS, mode, slip, Some(row), stick);
        };
        match (M::KINDS[row], mode.rows[row]) {
            (ConstraintKind::Unilateral, RowMode::Inactive) => {
                // Impact: a frictionless impulse along the contact row (and the rows already
                // enforced, which stay satisfied), ċ⁺ = −e ċ⁻.
                let (cr, scales) = super::rows::rows_and_scales(model, t, q, v);
                let approach = cr.rate[row];
                let e = self.options.restitution;
                mode.rows[row] = RowMode::Active;
                if approach < 0.0 {
                    let use_row: [bool; C] = std::array::from_fn(|i| {
                        mode.enforced(i) && M::KINDS[i].friction_normal().is_none()
                    });
                    // Lower the contact's rate from ċ⁻ to −e ċ⁻, the others' to 0.
                    let decrease: [f64; C] = std::array::from_fn(|i| {
                        if i == row {
                            cr.rate[i] + e * approach
                        } else {
                            cr.rate[i]
                        }
                    });
                    let mut velocity_only = *mode;
                    for i in 0..C {
                        if !use_row[i] {
                            velocity_only.rows[i] = RowMode::Inactive;
                        }
                    }
                    impulse(model, t, q, v, &velocity_only, &decrease)?;
                    if e * -approach > CONSISTENCY_TOLERANCE * scales.velocity[row] {
                        mode.rows[row] = RowMode::Inactive; // bounces off
                    }
                }
                let (after, scales) = super::rows::rows_and_scales(model, t, q, v);
                follow(mode, &after.value, &scales.stick());
            }
            (ConstraintKind::Unilateral, RowMode::Active) => {
                mode.rows[row] = RowMode::Inactive;
                let slip = [0.0; C];
                follow(mode, &slip, &[0.0; C]);
            }
            (ConstraintKind::Friction { .. }, RowMode::SlipPositive | RowMode::SlipNegative) => {
                // The slip velocity reached zero: make it exactly zero, then test static friction.
                mode.rows[row] = RowMode::Stick;
                project(model, t, q, v, mode)?;
            }
            (ConstraintKind::Friction { .. }, RowMode::Stick) => {
                let lambda = accelerations_in_mode(model, t, q, v, mode)?.multipliers;
                mode.rows[row] = if lambda[row] > 0.0 {
                    RowMode::SlipNegative
                } else {
                    RowMode::SlipPositive
                };
            }
            (ConstraintKind::FrictionCone { partner, .. }, RowMode::Sliding) => {
                // The slip stopped: both tangent slips set to zero, then the stick test below.
                mode.rows[row] = RowMode::Stick;
                mode.rows[partner] = RowMode::Stick;
                mode.reference[row] = 0.0;
                mode.reference[partner] = 0.0;
                mode.stopping[row] = false;
                mode.stopping[partner] = false;
                project(model, t, q, v, mode)?;
            }
            (ConstraintKind::FrictionCone { partner, .. }, RowMode::Stick) => {
                let lambda = accelerations_in_mode(model, t, q, v, mode)?.multipliers;
                cone::break_stick(mode, row, partner, &lambda);
            }
            _ => {}
        }
        // Complementarity of the new mode (a closed contact that pulls opens, a stick that needs
        // more than μₛ|λₙ| slides), most violated first.
        for _ in 0..=2 * C {
            let lambda = accelerations_in_mode(model, t, q, v, mode)?.multipliers;
            match worst_violation(model, mode, &lambda) {
                None => break,
                Some((i, new)) => super::mode::apply_fix::<M, N, K, C>(mode, i, new, &lambda),
            }
        }
        project(model, t, q, v, mode)?;
        Ok(())
    }
}

/// Velocity jump v ← v − M⁻¹Rᵀ(RM⁻¹Rᵀ)⁻¹d over the rows enforced in `mode`: an impulse along those
/// rows that lowers each row's rate r·v + r_t by exactly dᵢ.
fn impulse<M: Constraints<N, K, C>, const N: usize, const K: usize, const C: usize>(
    model: &M,
    t: f64,
    q: &[f64; N],
    v: &mut [f64; N],
    mode: &Mode<C>,
    decrease: &[f64; C],
) -> Result<()> {
    let cr = super::constraint_rows(model, t, q, v);
    let mass = crate::dynamics::mass_matrix(model, t, q);
    let l = crate::linalg::cholesky(&mass).map_err(|e| Error::SingularMassMatrix {
        t,
        configuration: crate::error::describe_configuration(
            &<M::Coords as Coordinates<N>>::NAMES,
            q,
        ),
        coordinate: <M::Coords as Coordinates<N>>::NAMES[e.index],
        pivot: e.pivot,
    })?;
    let enforced: [bool; C] = std::array::from_fn(|i| mode.enforced(i));
    let y: [nalgebra::SVector<f64, N>; C] = std::array::from_fn(|i| {
        if enforced[i] {
            crate::linalg::cholesky_substitute(&l, &cr.rows[i])
        } else {
            nalgebra::SVector::zeros()
        }
    });
    let mut s = nalgebra::SMatrix::<f64, C, C>::identity();
    let mut rhs = nalgebra::SVector::<f64, C>::zeros();
    for i in 0..C {
        if enforced[i] {
            for k in 0..C {
                if enforced[k] {
                    s[(i, k)] = cr.rows[i].dot(&y[k]);
                }
            }
            rhs[i] = decrease[i];
        }
    }
    let mu = crate::linalg::cholesky_solve(&s, &rhs).map_err(|e| Error::SingularConstraints {
        t,
        configuration: crate::error::describe_configuration(
            &<M::Coords as Coordinates<N>>::NAMES,
            q,
        ),
        constraints: format!("`{}`", M::NAMES[e.index.min(C - 1)]),
        pivot: e.pivot,
    })?;
    for k in 0..C {
        if enforced[k] {
            for j in 0..N {
                v[j] -= y[k][j] * mu[k];
            }
        }
    }
    Ok(())
}

/// [`ContactRk4`] as a solver of the common stepping interface ([`Stepper`]): holds the model,
/// the state, the step h and the stepper (its mode and the list of mode changes), with a cubic
/// Hermite dense output over each step (from q̈ in the step's final mode at both ends: across a
/// mode change inside the step it is only a rough interpolant) and [`Stats`].
///
/// ```
/// use lagrange_core::constraints::{ConstraintKind, ContactOptions, ContactRk4, ContactSolver, Constraints};
/// use lagrange_core::integrate::{Stepper, StopReason};
/// use lagrange_core::{vec2, Model, Scalar, State};
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
/// let mut solver = ContactSolver::new(&Ball, &start, 1e-2, ContactOptions::default())?;
/// let outcome = solver.integrate(1.0, &mut [], |_| {})?;
/// assert_eq!(outcome.reason, StopReason::Reached);
/// // It lands at √(2/g) = 0.4515 s (a plastic impact) and stays on the floor.
/// let landing = solver.contact().events[0].t;
/// assert!((landing - (2.0f64 / 9.81).sqrt()).abs() < 1e-10);
/// assert!(solver.state().q[0].abs() < 1e-12 && outcome.stats.accepted == 100);
/// # Ok::<(), lagrange_core::Error>(())
/// ```
pub struct ContactSolver<
    'm,
    M: Constraints<N, K, C>,
    const N: usize,
    const K: usize,
    const C: usize,
> {
    model: &'m M,
    contact: ContactRk4<C>,
    h: f64,
    state: State<M::Coords>,
    a: [f64; N],
    dense: DenseOutput<N>,
    stats: Stats,
}

impl<'m, M: Constraints<N, K, C>, const N: usize, const K: usize, const C: usize>
    ContactSolver<'m, M, N, K, C>
{
    /// A solver at `state` with step `h`: the errors of [`ContactRk4::new`] and an invalid h.
    pub fn new(
        model: &'m M,
        state: &State<M::Coords>,
        h: f64,
        options: ContactOptions,
    ) -> Result<Self> {
        check_step_at(state.t, h)?;
        let contact = ContactRk4::new(model, state, options)?;
        let (q, v) = (state.q.to_array(), state.v.to_array());
        let a = accelerations_in_mode(model, state.t, &q, &v, &contact.mode)?.accelerations;
        Ok(ContactSolver {
            model,
            contact,
            h,
            state: *state,
            a,
            dense: DenseOutput::constant(state.t, &q, &v),
            stats: Stats {
                evaluations: 1,
                ..Stats::default()
            },
        })
    }

    /// The contact stepper: its mode and the mode changes so far.
    pub fn contact(&self) -> &ContactRk4<C> {
        &self.contact
    }
}

impl<M: Constraints<N, K, C>, const N: usize, const K: usize, const C: usize> Stepper<M::Coords, N>
    for ContactSolver<'_, M, N, K, C>
{
    fn name(&self) -> &'static str {
        "ContactRk4"
    }
    fn t(&self) -> f64 {
        self.state.t
    }
    fn state(&self) -> State<M::Coords> {
        self.state
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

    /// One step of h (or of t_limit − t, when that is shorter or only slightly longer), with
    /// the mode changes inside it located ([`ContactRk4::step`]).
    fn step(&mut self, t_limit: f64) -> Result<()> {
        let t0 = self.state.t;
        if !(t_limit > t0) || !t_limit.is_finite() {
            return Err(Error::InvalidEndTime {
                t: t0,
                t_end: t_limit,
            });
        }
        let h = if t0 + 1.01 * self.h >= t_limit {
            t_limit - t0
        } else {
            self.h
        };
        let mut state = self.state;
        let events = self.contact.events.len();
        // Leaves the mode and the event list unchanged on error.
        self.contact.step(self.model, &mut state, h)?;
        let (q1, v1) = (state.q.to_array(), state.v.to_array());
        let a1 = accelerations_in_mode(self.model, state.t, &q1, &v1, &self.contact.mode)
            .map(|a| a.accelerations)
            .unwrap_or([f64::NAN; N]);
        let (q0, v0) = (self.state.q.to_array(), self.state.v.to_array());
        self.dense
            .set_hermite(t0, h, (&q0, &v0, &self.a), (&q1, &v1, &a1));
        // Four evaluations per RK4 sub-step; one more for the dense output.
        self.stats.evaluations += 4 * (self.contact.events.len() - events + 1) + 1;
        self.stats.accepted += 1;
        (self.state, self.a) = (state, a1);
        Ok(())
    }
}
