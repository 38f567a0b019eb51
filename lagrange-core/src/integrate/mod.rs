//! Integrators, generic over every generated mechanism, behind one stepping interface: the
//! solver value [`Stepper`] — `step`, `integrate` to a stop time with an observer, dense output
//! and events, [`Stats`] — built with a one-step method and its step ([`Fixed`], for every
//! [`Integrator`]) or an adaptive method's settings ([`Dopri5`], [`Dop853`], [`Radau5`]);
//! `sys.step::<I>(&mut s, h)` is one validated step and `sys.simulate` many
//! ([`Mechanism`](crate::Mechanism)). A declaration with unilateral contacts or friction is
//! stepped by every method with its contact mode held over a step and the mode's changes located
//! (the state a loop carries, not another solver); trajectory sensitivities are a solver that
//! carries the tangent of the trajectory ([`Stepper::with_sensitivities`]).
//!
//! What is here: method data (`rk4`, the explicit pairs [`dopri5`] and [`dop853`] and their
//! dense outputs, [`radau`]'s stages, the collocation methods of [`implicit`], the symplectic
//! schemes [`verlet`] and [`variational`] with [`rattle`]), two loops (the fixed-step one,
//! generic over the one-step method, and the adaptive one, generic over the [`EmbeddedPair`]),
//! and what a loop carries: the [`DenseOutput`] of its last step, the [`Event`]s it locates, its
//! [`Stats`], the methods' working memory, the contact mode and the tangent.
//!
//! | method | order | steps | evaluations of q̈ per step | geometric properties |
//! |---|---|---|---|---|
//! | [`Rk4`] | 4 | fixed | 4 | none (energy drifts) |
//! | [`Dopri5`] | 5(4) | adaptive, dense output (order 4), events | 6 (FSAL) | none |
//! | [`Dop853`] | 8(5,3) | adaptive, dense output (order 7), events | 12 (FSAL), + 3 for the dense output | none |
//! | [`Radau5`] | 5 | adaptive, dense output (order 3), events, contacts; for stiff mechanisms | simplified Newton: 3 per iteration (usually 1–4 iterations), + 1 at the new point; one Jacobian of q̈ (2 dual passes) and one factorisation reused across steps while the iteration contracts well | L-stable |
//! | [`ImplicitMidpoint`] | 2 | fixed | simplified Newton: 1 plain evaluation of (p, ṗ) per iteration; one Jacobian, reused across steps while the iteration contracts well | symmetric; symplectic in (q, p) for any Lagrangian |
//! | [`GaussLegendre2`] | 4 | fixed | simplified Newton: 2 plain evaluations of (p, ṗ) per iteration; Jacobian reused as above | symmetric; symplectic in (q, p) for any Lagrangian |
//! | [`Variational`] | 2 | fixed | Newton on the discrete Euler–Lagrange equations (with the multipliers of holonomic constraints: RATTLE) | symplectic in (q, p) for any Lagrangian, also with holonomic constraints and, in the contact loop, with the closed unilateral contacts of a held mode; refuses velocity constraints and friction |
//! | [`StormerVerlet`] | 2 | fixed | 2 with M (+ Newton on the multipliers of holonomic constraints: RATTLE) | symplectic, also with holonomic constraints and, in the contact loop, with the closed unilateral contacts of a held mode; refuses a non-constant mass matrix, velocity constraints and friction |
//!
//! Implicit midpoint, Gauss–Legendre and the variational integrator integrate the canonical
//! equations in (q, p), p = ∂L/∂q̇ (converting at both ends of a step, so the public state stays
//! (q, q̇)): their step maps (q₀, p₀) ↦ (q₁, p₁) are symplectic for any Lagrangian without
//! non-conservative forces, whatever the mass matrix (Hairer, Lubich & Wanner, *Geometric Numerical
//! Integration*, Theorem VI.4.2; Marsden & West, Acta Numerica 10 (2001), §1.2). Störmer–Verlet is
//! symplectic where it applies (constant mass matrix). A test measures ΦᵀΩΦ − Ω for the step maps
//! on the double pendulum. With non-conservative forces, or with a projection onto constraints,
//! the maps are not symplectic.
//!
//! Every step is allocation-free (a test counts allocations) and leaves the caller's state
//! unchanged on error. On a mechanism with constraints, every method integrates the constrained
//! accelerations, checks the state against the constraints before a run
//! (`Dynamics::check_constraints`) and projects after every step (`Dynamics::project`).
//! Unilateral contacts and friction switch their mode inside a step: every loop then holds the
//! mode over a step and locates the switches — the fixed-step loop on the step length (a step cut
//! at a located event, the rest taken as a shorter step in the new mode), the adaptive loop on the
//! step's dense output (the step cut there) — and applies them (impacts with
//! [`ContactOptions::restitution`](crate::constraints::ContactOptions::restitution), releases,
//! stick and slip). Implicit midpoint and Gauss–Legendre step a held mode as a mechanism of its
//! own; Störmer–Verlet and the variational integrator enforce its closed contacts by RATTLE.
//! Störmer–Verlet and the variational integrator enforce holonomic constraints g(q, t) = 0 by
//! RATTLE ([`rattle`]: the multipliers of a position stage solved by Newton with the step, then the
//! velocity projection), which keeps them symplectic on the constraint manifold. In the contact
//! loop a held mode's closed unilateral contacts are such rows for the step (released where their
//! multiplier crosses 0, closed where their gap does): symplectic on the manifold of the contacts
//! that hold. They refuse velocity constraints and friction, whose rows constrain q̇, with
//! [`Error::UnsuitableMethod`] (the other methods integrate
//! those). Which constraints a method enforces is decided by the declaration alone —
//! `Dynamics::CONSTRAINT_COUNTS` and `Dynamics::CONSTRAINTS` — never by the multipliers at
//! some state (a pendulum released horizontally at rest has λ = 0 at its first step and is treated
//! as constrained all the same): the symplectic methods refuse an implementation that does not
//! declare its constraints, and implicit midpoint and Gauss–Legendre add the constraint force at
//! every stage unless the mechanism declares none.

mod adaptive;
mod canonical;
mod control;
mod dense;
pub mod dop853;
pub mod dopri5;
mod events;
mod fixed;
mod held;
pub mod implicit;
pub(crate) mod newton;
pub mod pair;
pub mod radau;
mod rates;
pub mod rattle;
pub(crate) mod rk4;
mod stepper;
pub mod variational;
pub mod verlet;

pub use crate::evaluation::momentum_rate;
pub use control::Controller;
pub use dense::{DenseOutput, EVENT_TIME_TOLERANCE};
pub use dop853::Dop853;
pub use dopri5::Dopri5;
pub use events::{Direction, Event, EventHit, Observation, Outcome, StopReason};
pub use fixed::Fixed;
pub use implicit::{GaussLegendre2, ImplicitMidpoint, ImplicitStepStats, NewtonMemory};
pub use newton::{acceleration_jacobians, MAX_NEWTON_ITERATIONS};
pub use pair::{AccelerationField, Accepted, EmbeddedPair, StepStart};
pub use radau::{Radau5, Radau5Memory};
pub use rattle::holonomic_rows;
pub use rk4::Rk4;
pub use stepper::{ContactsOf, Method, NoTangent, Stepper, Tangent};
pub use variational::{Variational, VariationalStepStats};
pub use verlet::{StormerVerlet, MASS_MATRIX_VARIATION};

use crate::constraints::ContactModel;
use crate::error::{Error, Result};
use crate::evaluation::Evaluate;
use crate::geometry::Scalar;
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

/// [`Error::InvalidSetting`]: `method`'s `setting` has a `value` that does not meet `requirement`.
pub(crate) fn invalid_setting(
    method: &'static str,
    setting: &'static str,
    value: f64,
    requirement: &'static str,
) -> Error {
    Error::InvalidSetting {
        method,
        setting,
        value,
        requirement,
    }
}

/// Checks the tolerances every adaptive method has: `rtol` and `atol` finite and non-negative
/// ([`Error::InvalidSetting`] naming the first that is not).
pub(crate) fn check_tolerances(method: &'static str, rtol: f64, atol: f64) -> Result<()> {
    for (name, value) in [("rtol", rtol), ("atol", atol)] {
        if !(value.is_finite() && value >= 0.0) {
            return Err(invalid_setting(
                method,
                name,
                value,
                "finite and non-negative",
            ));
        }
    }
    Ok(())
}

/// Checks the step bounds every adaptive method has: `h_max` positive, `max_steps` at least 1
/// ([`Error::InvalidSetting`]).
// `!(a > b)` is deliberate: it also refuses NaN.
#[allow(clippy::neg_cmp_op_on_partial_ord)]
pub(crate) fn check_step_bounds(method: &'static str, h_max: f64, max_steps: usize) -> Result<()> {
    if !(h_max > 0.0) {
        return Err(invalid_setting(method, "h_max", h_max, "positive"));
    }
    if max_steps == 0 {
        return Err(invalid_setting(method, "max_steps", 0.0, "at least 1"));
    }
    Ok(())
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
/// keeps its rotation charts regular, checks it and only then writes it to `state` (unchanged on
/// every error).
pub(crate) fn validated_step<M: Evaluate<N>, const N: usize>(
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
    mechanism.switch_charts(&mut q1, &mut v1);
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

/// A one-step method, as a type: `sys.step::<Rk4>(&mut state, h)` ([`Mechanism::step`]) is one
/// validated step with it, and `Stepper::new(&sys, Rk4::with_step(h), &state)` a solver of it
/// ([`Fixed`]). Implementations do not allocate and leave the state unchanged on error.
///
/// [`Mechanism::step`]: crate::Mechanism::step
pub trait Integrator: Sized {
    /// The method's name, for reports and errors.
    const NAME: &'static str;
    /// Working memory a solver keeps from one step to the next: the implicit methods' factorised
    /// Newton matrix ([`NewtonMemory`]), nothing (`()`) for the others.
    type Memory<const N: usize>: Default + Copy;

    /// Whether [`advance`](Self::advance) integrates adaptively over h with a loop of its own
    /// (Dopri5, Dop853, Radau5), which holds a declaration's contact mode itself; a one-step method
    /// has the mode held over its step by the fixed-step loop.
    const ADAPTIVE: bool = false;

    /// Whether the method enforces only position rows g(q, t) = 0 (RATTLE: Störmer–Verlet and the
    /// variational integrator), so that a declaration with velocity or friction rows is refused,
    /// also with its contact mode held.
    ///
    /// ```
    /// use lagrange_core::{GaussLegendre2, Integrator, StormerVerlet, Variational};
    /// assert!(StormerVerlet::POSITION_ROWS_ONLY && Variational::POSITION_ROWS_ONLY);
    /// assert!(!GaussLegendre2::POSITION_ROWS_ONLY);
    /// ```
    const POSITION_ROWS_ONLY: bool = false;

    /// Whether [`advance_on_duals`](Self::advance_on_duals) steps on dual numbers (trajectory
    /// sensitivities): RK4.
    const STEPS_ON_DUALS: bool = false;

    /// One step of h from (t, q, q̇) on raw arrays, without validation or projection, adding its
    /// cost to `stats`: (q, q̇) at t + h.
    fn advance<M: Evaluate<N>, const N: usize>(
        mechanism: &M,
        memory: &mut Self::Memory<N>,
        t: f64,
        q: &[f64; N],
        v: &[f64; N],
        h: f64,
        stats: &mut Stats,
    ) -> Result<([f64; N], [f64; N])>;

    /// One step of h from (t, q, v) on any scalar (dual numbers carrying sensitivities) with the
    /// position rates `rates` (q̇ = G(q) v) and the accelerations `acc`, adding its cost to
    /// `stats`: the same operations as [`advance`](Self::advance) in the same order, so the real
    /// parts are the `f64` step's. [`Error::UnsuitableMethod`] unless
    /// [`STEPS_ON_DUALS`](Self::STEPS_ON_DUALS).
    fn advance_on_duals<S: Scalar, const N: usize>(
        t: f64,
        y: (&[S; N], &[S; N]),
        h: f64,
        rates: impl Fn(&[S; N], &[S; N]) -> [S; N],
        acc: impl FnMut(f64, &[S; N], &[S; N]) -> Result<[S; N]>,
        stats: &mut Stats,
    ) -> Result<([S; N], [S; N])> {
        let _ = (t, y, h, rates, acc, stats);
        Err(Error::UnsuitableMethod {
            method: Self::NAME,
            reason: "it does not step on dual numbers: sensitivities with a fixed step are RK4's"
                .to_string(),
        })
    }

    /// The method with step `h`, for a [`Stepper`]: `Stepper::new(&sys, Rk4::with_step(h), &s)`.
    fn with_step(h: f64) -> Fixed<Self> {
        Fixed::new(h)
    }

    /// Advances `state` by `h`: checks h, the parameters, the state and its constraints, takes one
    /// step with fresh working memory, projects onto the constraints and checks the result; on a
    /// declaration with unilateral or friction rows holds the contact mode read from the state
    /// over the step, its changes located and applied. On error the state is unchanged.
    ///
    /// Fresh working memory means that an implicit method forms its Jacobians and factorises its
    /// Newton matrix in every such step: repeated steps are taken by
    /// [`Mechanism::simulate`](crate::Mechanism::simulate) or a [`Stepper`], which keep them.
    fn step<M: Evaluate<N>, const N: usize>(
        mechanism: &M,
        state: &mut State<M::Coords>,
        h: f64,
    ) -> Result<()> {
        step_keeping_memory::<Self, M, N>(mechanism, &mut Default::default(), state, h)
    }
}

/// [`Integrator::step`] with the method's working memory `memory`, which a caller taking several
/// steps keeps from one to the next ([`Mechanism::simulate`](crate::Mechanism::simulate)). A
/// declaration with unilateral or friction rows takes fresh memory in every (sub)step of its held
/// contact mode, whose rows may change within the step.
pub(crate) fn step_keeping_memory<I: Integrator, M: Evaluate<N>, const N: usize>(
    mechanism: &M,
    memory: &mut I::Memory<N>,
    state: &mut State<M::Coords>,
    h: f64,
) -> Result<()> {
    if ContactsOf::<M, N>::SWITCHES && !I::ADAPTIVE {
        return fixed::step_holding_contacts::<I, M, N>(mechanism, state, h);
    }
    let mut stats = Stats::default();
    validated_step(mechanism, state, h, |t, q, v| {
        I::advance(mechanism, memory, t, q, v, h, &mut stats)
    })
}
