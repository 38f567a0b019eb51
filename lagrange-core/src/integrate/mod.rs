//! Integrators, generic over every generated mechanism.

mod rk4;
pub use rk4::Rk4;

use crate::error::Result;
use crate::mechanism::Mechanism;
use crate::model::State;

/// A one-step method: advances a state by h. Implementations validate the mechanism, the state
/// and h, do not allocate, and leave the state unchanged on error.
pub trait Integrator {
    /// The method's name, for reports and errors.
    const NAME: &'static str;
    /// Advances `state` by `h`.
    fn step<M: Mechanism<N>, const N: usize>(mechanism: &M, state: &mut State<M::Coords>, h: f64) -> Result<()>;
}
