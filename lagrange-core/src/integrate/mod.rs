//! Integrators, generic over every generated mechanism.
//!
//! | method | order | steps | evaluations of q̈ per step | geometric properties |
//! |---|---|---|---|---|
//! | [`Rk4`] | 4 | fixed | 4 | none (energy drifts) |
//! | [`Dopri5`] | 5(4) | adaptive, dense output, events | 6 (FSAL) | none |
//! | [`ImplicitMidpoint`] | 2 | fixed | Newton: 1 with Jacobians per iteration | symmetric; symplectic for constant M |
//! | [`GaussLegendre2`] | 4 | fixed | Newton: 2 with Jacobians per iteration | symmetric; symplectic for constant M |
//! | [`Variational`] | 2 | fixed | Newton on the discrete Euler–Lagrange equations | symplectic in (q, p) for any Lagrangian; refuses constraints |
//! | [`StormerVerlet`] | 2 | fixed | 3 (2 with M, 1 constraint test) | symplectic; refuses a non-constant mass matrix and constraints |
//!
//! Every step is allocation-free (a test counts allocations) and leaves the caller's state
//! unchanged on error. On a mechanism with constraints, RK4, Dopri5, implicit midpoint and
//! Gauss–Legendre integrate the constrained accelerations, check the state against the constraints
//! before a step ([`Mechanism::check_constraints`]) and project after it ([`Mechanism::project`]);
//! the variational integrator and Störmer–Verlet, built on the unconstrained Lagrangian, refuse
//! constrained mechanisms with [`Error::UnsuitableMethod`](crate::Error::UnsuitableMethod).

pub mod dopri5;
pub mod implicit;
mod newton;
mod rk4;
pub mod variational;
pub mod verlet;

pub use dopri5::{
    DenseOutput, Direction, Dopri5, Dopri5Outcome, Dopri5Stats, Dopri5Stepper, Event, EventHit,
    Observation, StopReason,
};
pub use implicit::{GaussLegendre2, ImplicitMidpoint, ImplicitStepStats};
pub use newton::{acceleration_jacobians, refuse_constrained, MAX_NEWTON_ITERATIONS};
pub use rk4::Rk4;
pub use variational::{momentum_rate, Variational, VariationalStepStats};
pub use verlet::{StormerVerlet, MASS_MATRIX_VARIATION};

use crate::error::Result;
use crate::mechanism::Mechanism;
use crate::model::State;

/// A one-step method: advances a state by h. Implementations validate the mechanism, the state
/// and h, do not allocate, and leave the state unchanged on error.
pub trait Integrator {
    /// The method's name, for reports and errors.
    const NAME: &'static str;
    /// Advances `state` by `h`.
    fn step<M: Mechanism<N>, const N: usize>(
        mechanism: &M,
        state: &mut State<M::Coords>,
        h: f64,
    ) -> Result<()>;
}
