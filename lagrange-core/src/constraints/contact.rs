//! The contact mode a time loop holds over a step ([`ContactModel`]): which unilateral contacts are
//! closed and how friction rows act, the event functions whose sign changes switch it, and the
//! switch itself. What the declaration's rows are ([`ContactState`] for a declaration with
//! unilateral or friction rows, [`NoContacts`] for one without) is `Dynamics::Contacts`; the
//! loops that hold it, locate its events and apply its switches are in [`crate::integrate`].

use super::events::{event_values, triggered_rows};
#[cfg(doc)]
use super::infer_mode;
use super::mode::infer_mode_in_rates;
use super::switch::transition;
use super::{accelerations_in_mode, cone, project, quasi, ConstraintCounts, Constraints};
use super::{Mode, RowMode};
use crate::error::{Error, Result};
use crate::evaluation::{Constants, Prepare};
use crate::geometry::Scalar;

/// The contact mode of a declaration as a time loop holds it over a step: the accelerations, the
/// projection and the position rows in the mode, the event function of every row and its switch.
///
/// Within a step the mode is fixed; each row has an event function whose sign change is a mode
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
/// A row whose event just fired is disarmed until its new event function is positive, which rules
/// out chattering at a stick/slip boundary or a grazing release. Implemented by [`ContactState`]
/// for a [`Constraints`] declaration, by [`DrivenContacts`](crate::inputs::DrivenContacts) for one
/// with inputs and by [`NoContacts`] (nothing switches) for any other; `M` is the declaration's
/// model, every method evaluates on it with the constants of the call that holds the mode (the
/// inputs a [`Driven`](crate::inputs::Driven) mechanism holds, a validated handle's prepared
/// constants), so a mode held over a step sees what the step's other evaluations see.
pub trait ContactModel<M: Prepare, const N: usize>: Copy + PartialEq + std::fmt::Debug {
    /// Whether the declaration has rows whose mode switches (unilateral contacts, friction):
    /// otherwise nothing is held and a time loop takes the mechanism's own steps.
    const SWITCHES: bool;
    /// What the rows are while a mode is held: every enforced row is bilateral for the step, the
    /// holonomic and unilateral rows as holonomic rows, the velocity and friction rows as velocity
    /// rows (what the held mechanism declares to the one-step methods).
    const HELD_COUNTS: ConstraintCounts;
    /// One number per constraint row.
    type Values: Copy + AsRef<[f64]>;
    /// One flag per constraint row.
    type Rows: Copy + AsRef<[bool]>;

    /// The mode at (t, q, q̇) by complementarity ([`infer_mode`]), with the rows whose event
    /// function is positive armed. The state is assumed checked and on the constraints.
    fn start(
        model: &M,
        constants: Constants<'_, M>,
        t: f64,
        q: &[f64; N],
        v: &[f64; N],
    ) -> Result<Self>;
    /// A mode held by nobody: what a solver keeps for a declaration whose mode does not switch.
    fn idle() -> Self;
    /// Before an interval of length `span` from (t, q, q̇): a sliding friction cone continues its
    /// slip direction of the interval's start (see [`Mode::reference`]).
    fn refresh(
        &mut self,
        model: &M,
        constants: Constants<'_, M>,
        t: f64,
        q: &[f64; N],
        v: &[f64; N],
        span: f64,
    ) -> Result<()>;
    /// q̈ in the mode ([`accelerations_in_mode`]), for any scalar.
    fn accelerations<S: Scalar>(
        &self,
        model: &M,
        constants: Constants<'_, M>,
        t: S,
        q: &[S; N],
        v: &[S; N],
    ) -> Result<[S; N]>;
    /// Projects (q, q̇) onto the rows the mode enforces ([`project`]); unchanged on error.
    fn project(
        &self,
        model: &M,
        constants: Constants<'_, M>,
        t: f64,
        q: &mut [f64; N],
        v: &mut [f64; N],
    ) -> Result<()>;
    /// The values g(q, t) of the position rows the mode enforces (holonomic rows and closed
    /// contacts), in declaration order, padded with zeros to N entries: what RATTLE enforces.
    fn held_positions<S: Scalar>(
        &self,
        model: &M,
        constants: Constants<'_, M>,
        t: S,
        q: &[S; N],
    ) -> [S; N];
    /// How many of [`held_positions`](Self::held_positions) are rows.
    fn held_position_rows(&self) -> usize;
    /// The event function of every row (+∞ for rows without one).
    fn event_values(
        &self,
        model: &M,
        constants: Constants<'_, M>,
        t: f64,
        q: &[f64; N],
        v: &[f64; N],
    ) -> Result<Self::Values>;
    /// The rows whose event fired over an interval from (t, q, q̇) whose end has the event values
    /// `end`: armed rows negative there, and a contact that bounced off and closes again.
    fn triggered(
        &self,
        model: &M,
        constants: Constants<'_, M>,
        t: f64,
        q: &[f64; N],
        v: &[f64; N],
        end: &Self::Values,
    ) -> Self::Rows;
    /// After an interval without an event, ending with `end`: arms every row positive there.
    fn rearm(&mut self, end: &Self::Values);
    /// Switches row `row` at its located event (t, q, q̇): arms the other rows positive there,
    /// applies the switch (impact with coefficient `restitution`, release, slip stop, stick break,
    /// then complementarity and the projection onto the new mode, moving (q, q̇)), and disarms
    /// every row whose mode changed. Returns the change.
    #[allow(clippy::too_many_arguments)]
    fn switch(
        &mut self,
        model: &M,
        constants: Constants<'_, M>,
        restitution: f64,
        t: f64,
        state: (&mut [f64; N], &mut [f64; N]),
        row: usize,
    ) -> Result<ModeChange>;
}

/// The contact mode of a declaration without unilateral or friction rows: nothing switches, no
/// time loop holds anything ([`ContactModel::SWITCHES`] is false and none of its methods is
/// called; they return neutral values).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct NoContacts;

impl<M: Prepare, const N: usize> ContactModel<M, N> for NoContacts {
    const SWITCHES: bool = false;
    const HELD_COUNTS: ConstraintCounts = ConstraintCounts::NONE;
    type Values = [f64; 0];
    type Rows = [bool; 0];

    fn start(_: &M, _: Constants<'_, M>, _: f64, _: &[f64; N], _: &[f64; N]) -> Result<Self> {
        Ok(NoContacts)
    }
    fn idle() -> Self {
        NoContacts
    }
    fn refresh(
        &mut self,
        _: &M,
        _: Constants<'_, M>,
        _: f64,
        _: &[f64; N],
        _: &[f64; N],
        _: f64,
    ) -> Result<()> {
        Ok(())
    }
    fn accelerations<S: Scalar>(
        &self,
        _: &M,
        _: Constants<'_, M>,
        _: S,
        _: &[S; N],
        _: &[S; N],
    ) -> Result<[S; N]> {
        Err(no_contacts())
    }
    fn project(
        &self,
        _: &M,
        _: Constants<'_, M>,
        _: f64,
        _: &mut [f64; N],
        _: &mut [f64; N],
    ) -> Result<()> {
        Ok(())
    }
    fn held_positions<S: Scalar>(&self, _: &M, _: Constants<'_, M>, _: S, _: &[S; N]) -> [S; N] {
        [S::zero(); N]
    }
    fn held_position_rows(&self) -> usize {
        0
    }
    fn event_values(
        &self,
        _: &M,
        _: Constants<'_, M>,
        _: f64,
        _: &[f64; N],
        _: &[f64; N],
    ) -> Result<[f64; 0]> {
        Ok([])
    }
    fn triggered(
        &self,
        _: &M,
        _: Constants<'_, M>,
        _: f64,
        _: &[f64; N],
        _: &[f64; N],
        _: &[f64; 0],
    ) -> [bool; 0] {
        []
    }
    fn rearm(&mut self, _: &[f64; 0]) {}
    fn switch(
        &mut self,
        _: &M,
        _: Constants<'_, M>,
        _: f64,
        _: f64,
        _: (&mut [f64; N], &mut [f64; N]),
        _: usize,
    ) -> Result<ModeChange> {
        Err(no_contacts())
    }
}

fn no_contacts() -> Error {
    Error::UnsuitableMethod {
        method: "contacts",
        reason: "the declaration has no unilateral or friction rows to hold a mode of".to_string(),
    }
}

/// The contact mode of a declaration with `C` constraint rows over `K` Cartesian coordinates: the
/// [`Mode`] (which rows are enforced, how friction acts) and which rows' events are armed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactState<const K: usize, const C: usize> {
    mode: Mode<C>,
    armed: [bool; C],
}

impl<const K: usize, const C: usize> ContactState<K, C> {
    /// The mode.
    pub fn mode(&self) -> Mode<C> {
        self.mode
    }
}

/// The position rows (holonomic, unilateral) `mode` enforces, in declaration order.
fn position_rows<M: Constraints<N, K, C>, const N: usize, const K: usize, const C: usize>(
    mode: &Mode<C>,
) -> impl Iterator<Item = usize> + '_ {
    (0..C).filter(|&i| M::KINDS[i].is_position() && mode.enforced(i))
}

/// The declaration as it is: it has no inputs to hold, and the mode's solve is the general one,
/// which reads no prepared constants.
impl<M, const N: usize, const K: usize, const C: usize> ContactModel<M, N> for ContactState<K, C>
where
    M: Constraints<N, K, C> + Prepare,
{
    const SWITCHES: bool = {
        let counts = ConstraintCounts::of(&M::KINDS);
        counts.unilateral + counts.friction > 0
    };
    const HELD_COUNTS: ConstraintCounts = {
        let declared = ConstraintCounts::of(&M::KINDS);
        ConstraintCounts {
            holonomic: declared.holonomic + declared.unilateral,
            velocity: declared.velocity + declared.friction,
            ..ConstraintCounts::NONE
        }
    };
    type Values = [f64; C];
    type Rows = [bool; C];

    fn start(model: &M, _: Constants<'_, M>, t: f64, q: &[f64; N], v: &[f64; N]) -> Result<Self> {
        let rates = quasi::rates::<M, f64, N, K, C>(q, v);
        let mode = infer_mode_in_rates(model, t, q, &rates)?;
        let phi = event_values(model, t, q, &rates, &mode)?;
        Ok(ContactState {
            mode,
            armed: std::array::from_fn(|i| phi[i] > 0.0),
        })
    }

    fn idle() -> Self {
        ContactState {
            mode: Mode::all_active::<M, N, K>(),
            armed: [false; C],
        }
    }

    fn refresh(
        &mut self,
        model: &M,
        _: Constants<'_, M>,
        t: f64,
        q: &[f64; N],
        v: &[f64; N],
        span: f64,
    ) -> Result<()> {
        let rates = quasi::rates::<M, f64, N, K, C>(q, v);
        cone::refresh_references(model, t, q, &rates, span, &mut self.mode)
    }

    #[inline]
    fn accelerations<S: Scalar>(
        &self,
        model: &M,
        _: Constants<'_, M>,
        t: S,
        q: &[S; N],
        v: &[S; N],
    ) -> Result<[S; N]> {
        Ok(accelerations_in_mode(model, t, q, v, &self.mode)?.accelerations)
    }

    fn project(
        &self,
        model: &M,
        _: Constants<'_, M>,
        t: f64,
        q: &mut [f64; N],
        v: &mut [f64; N],
    ) -> Result<()> {
        project(model, t, q, v, &self.mode)
    }

    fn held_positions<S: Scalar>(
        &self,
        model: &M,
        _: Constants<'_, M>,
        t: S,
        q: &[S; N],
    ) -> [S; N] {
        let x = model.cartesian(t, q);
        let g = model.position_constraints(t, q, &x);
        let mut out = [S::zero(); N];
        for (slot, i) in position_rows::<M, N, K, C>(&self.mode).take(N).enumerate() {
            out[slot] = g[i];
        }
        out
    }

    fn held_position_rows(&self) -> usize {
        position_rows::<M, N, K, C>(&self.mode).count()
    }

    fn event_values(
        &self,
        model: &M,
        _: Constants<'_, M>,
        t: f64,
        q: &[f64; N],
        v: &[f64; N],
    ) -> Result<[f64; C]> {
        event_values(
            model,
            t,
            q,
            &quasi::rates::<M, f64, N, K, C>(q, v),
            &self.mode,
        )
    }

    fn triggered(
        &self,
        model: &M,
        _: Constants<'_, M>,
        t: f64,
        q: &[f64; N],
        v: &[f64; N],
        end: &[f64; C],
    ) -> [bool; C] {
        let rates = quasi::rates::<M, f64, N, K, C>(q, v);
        triggered_rows(model, t, q, &rates, &self.mode, &self.armed, end)
    }

    fn rearm(&mut self, end: &[f64; C]) {
        for i in 0..C {
            self.armed[i] |= end[i] > 0.0;
        }
    }

    fn switch(
        &mut self,
        model: &M,
        _: Constants<'_, M>,
        restitution: f64,
        t: f64,
        (q, v): (&mut [f64; N], &mut [f64; N]),
        row: usize,
    ) -> Result<ModeChange> {
        let rates = quasi::rates::<M, f64, N, K, C>(q, v);
        let at_event = event_values(model, t, q, &rates, &self.mode)?;
        for i in 0..C {
            self.armed[i] |= i != row && at_event[i] > 0.0;
        }
        let (before, from) = (self.mode, self.mode.rows[row]);
        let mode = &mut self.mode;
        quasi::in_rates::<M, _, N, K, C>(q, v, |q, rates| {
            transition(model, restitution, t, (q, rates), mode, row)
        })?;
        for i in 0..C {
            if self.mode.rows[i] != before.rows[i] || i == row {
                self.armed[i] = false;
            }
        }
        Ok(ModeChange {
            t,
            row,
            constraint: M::NAMES[row],
            from,
            to: self.mode.rows[row],
        })
    }
}

/// How a time loop treats the contact mode it holds (see [`ContactModel`]): the impact law, how
/// closely a fixed-step loop locates events, and how many mode changes a step may take.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactOptions {
    /// Coefficient of restitution e ∈ [0, 1] of every unilateral contact (Newton's law ċ⁺ = −e ċ⁻).
    /// 0 (the default) is a plastic impact: the contact closes and stays closed while λ ≥ 0.
    pub restitution: f64,
    /// Relative accuracy of event times in a fixed-step loop: the bracket around an event is
    /// narrowed to `event_tolerance · (|t| + h)`. Default 1e-13 (events are located to ≤ 1e-12).
    /// An adaptive loop locates events on its dense output, to
    /// [`EVENT_TIME_TOLERANCE`](crate::integrate::EVENT_TIME_TOLERANCE).
    pub event_tolerance: f64,
    /// Mode changes allowed within one step of a fixed-step loop (in an adaptive loop: at one
    /// instant) before the step fails with [`Error::TooManyEvents`] (a Zeno sequence of impacts, or
    /// an inconsistent friction mode).
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
                method: "contacts",
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
