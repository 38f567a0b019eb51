//! Integrators, generic over every generated mechanism, behind one stepping interface
//! ([`solver`]: the [`Stepper`] trait — `step`, `integrate` to a stop time with an observer, dense
//! output and events, [`Stats`] — implemented by [`FixedStepper`] for every [`Integrator`], by
//! [`Dopri5Stepper`], [`Dop853Stepper`] and [`Radau5Stepper`], and by the contact solvers
//! [`ContactSolver`](crate::constraints::ContactSolver) (RK4) and
//! [`ContactAdaptive`](crate::constraints::ContactAdaptive) (Dopri5, Dop853, Radau5));
//! `sys.step::<I>(&mut s, h)` is one validated step.
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
//! unchanged on error. On a mechanism with constraints, RK4, Dopri5, Dop853, Radau5, implicit
//! midpoint and Gauss–Legendre integrate the constrained accelerations, check the state against
//! the constraints before a step (`Dynamics::check_constraints`) and project after it
//! (`Dynamics::project`). Unilateral contacts and friction switch their mode inside a step:
//! Dopri5, Dop853 and Radau5 then hold the mode per step and locate the switches
//! ([`ContactDopri5`](crate::constraints::ContactDopri5),
//! [`ContactRadau5`](crate::constraints::ContactRadau5): their `integrate` and `sys.step` take
//! them by themselves), RK4 has [`ContactRk4`](crate::ContactRk4), whose event loop also steps
//! with implicit midpoint, Gauss–Legendre, Störmer–Verlet or the variational integrator
//! ([`ContactRk4::step_with`](crate::ContactRk4::step_with), which a single `sys.step` with any of
//! these four takes); stepped on their own ([`FixedStepper`], and the plain [`Radau5Stepper`]) they
//! refuse such a declaration with [`Error::UnsuitableMethod`](crate::Error::UnsuitableMethod).
//! Störmer–Verlet and the variational integrator enforce holonomic constraints g(q, t) = 0 by
//! RATTLE ([`rattle`]: the multipliers of a position stage solved by Newton with the step, then the
//! velocity projection), which keeps them symplectic on the constraint manifold. In the contact
//! loop a held mode's closed unilateral contacts are such rows for the step (released where their
//! multiplier crosses 0, closed where their gap does): symplectic on the manifold of the contacts
//! that hold. They refuse velocity constraints and friction, whose rows constrain q̇, with
//! [`Error::UnsuitableMethod`](crate::Error::UnsuitableMethod) (use [`ContactRk4`](crate::ContactRk4),
//! `step_with` with implicit midpoint or Gauss–Legendre, or [`ContactDopri5`](crate::ContactDopri5)
//! for those). Which constraints a method enforces is decided by the declaration alone —
//! `Dynamics::CONSTRAINT_COUNTS` and `Dynamics::CONSTRAINTS` — never by the multipliers at
//! some state (a pendulum released horizontally at rest has λ = 0 at its first step and is treated
//! as constrained all the same): the symplectic methods refuse an implementation that does not
//! declare its constraints, and implicit midpoint and Gauss–Legendre add the constraint force at
//! every stage unless the mechanism declares none.

mod canonical;
pub mod dop853;
pub mod dopri5;
pub mod implicit;
pub(crate) mod newton;
pub mod pair;
pub mod radau;
pub mod rattle;
pub(crate) mod rk4;
pub mod solver;
pub mod variational;
pub mod verlet;

pub use dop853::{Dop853, Dop853Stepper};
pub use dopri5::{DenseOutput, Dopri5, Dopri5Outcome, Dopri5Stats, Dopri5Stepper};
pub use implicit::{GaussLegendre2, ImplicitMidpoint, ImplicitStepStats, NewtonMemory};
pub use newton::{acceleration_jacobians, MAX_NEWTON_ITERATIONS};
pub use pair::{AccelerationField, Accepted, EmbeddedPair, StepStart};
pub use radau::{Radau5, Radau5Memory, Radau5Stepper};
pub use rattle::holonomic_rows;
pub use rk4::Rk4;
pub use solver::{
    check_step, check_step_at, Direction, Event, EventHit, FixedStepper, Observation, Outcome,
    Stats, Stepper, StopReason,
};
pub use variational::{momentum_rate, Variational, VariationalStepStats};
pub use verlet::{StormerVerlet, MASS_MATRIX_VARIATION};

use crate::error::Result;
use crate::mechanism::Mechanism;
use crate::model::State;

/// A one-step method, as a type: `sys.step::<Rk4>(&mut state, h)` ([`Mechanism::step`]) is one
/// validated step with it, and [`FixedStepper`] makes a solver of it. Implementations do not
/// allocate and leave the state unchanged on error.
pub trait Integrator: Sized {
    /// The method's name, for reports and errors.
    const NAME: &'static str;
    /// Working memory a solver keeps from one step to the next: the implicit methods' factorised
    /// Newton matrix ([`NewtonMemory`]), nothing (`()`) for the others.
    type Memory<const N: usize>: Default + Copy;

    /// Whether [`step`](Self::step) integrates a declaration with unilateral or friction rows by
    /// holding the contact mode over the step and locating its switches
    /// ([`ContactRk4::step_with`](crate::constraints::ContactRk4::step_with)): the implicit
    /// collocation methods, whose Newton iteration needs one smooth right-hand side over a step,
    /// and Störmer–Verlet and the variational integrator, whose RATTLE enforces a closed contact
    /// as a holonomic row over the step. The others evaluate such declarations with the mode read
    /// from each stage's state.
    const HOLDS_CONTACT_MODE: bool = false;

    /// Whether the method enforces only position rows g(q, t) = 0 (RATTLE: Störmer–Verlet and the
    /// variational integrator), so that a declaration with velocity or friction rows is refused,
    /// also in the contact loop ([`ContactRk4::step_with`](crate::constraints::ContactRk4::step_with)).
    ///
    /// ```
    /// use lagrange_core::{GaussLegendre2, Integrator, StormerVerlet, Variational};
    /// assert!(StormerVerlet::POSITION_ROWS_ONLY && Variational::POSITION_ROWS_ONLY);
    /// assert!(!GaussLegendre2::POSITION_ROWS_ONLY && GaussLegendre2::HOLDS_CONTACT_MODE);
    /// ```
    const POSITION_ROWS_ONLY: bool = false;

    /// One step of h from (t, q, q̇) on raw arrays, without validation or projection, adding its
    /// cost to `stats`: (q, q̇) at t + h.
    fn advance<M: Mechanism<N>, const N: usize>(
        mechanism: &M,
        memory: &mut Self::Memory<N>,
        t: f64,
        q: &[f64; N],
        v: &[f64; N],
        h: f64,
        stats: &mut Stats,
    ) -> Result<([f64; N], [f64; N])>;

    /// Advances `state` by `h`: checks h, the parameters, the state and its constraints, takes one
    /// step with fresh working memory, projects onto the constraints and checks the result. On
    /// error the state is unchanged.
    fn step<M: Mechanism<N>, const N: usize>(
        mechanism: &M,
        state: &mut State<M::Coords>,
        h: f64,
    ) -> Result<()> {
        if Self::HOLDS_CONTACT_MODE {
            if let Some(result) = mechanism.step_contacts::<Self>(state, h) {
                return result;
            }
        }
        let mut memory = Self::Memory::<N>::default();
        let mut stats = Stats::default();
        solver::validated_step(mechanism, state, h, |t, q, v| {
            Self::advance(mechanism, &mut memory, t, q, v, h, &mut stats)
        })
    }
}
