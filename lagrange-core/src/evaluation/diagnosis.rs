//! The error path of an evaluation: an error of the accelerations re-examined for its real cause.

use super::Evaluate;
use crate::error::{describe_configuration, Error};
use crate::model::Coordinates;

/// Re-examines an error of the accelerations at (t, q, q̇) for its real cause: a mass matrix
/// reported singular because one of its entries overflowed (a coordinate of 1e300 in a mass
/// matrix that grows like its square, or the stage of a step that blew up) is
/// [`Error::NonFiniteDynamics`] at that state, not a singular matrix with a meaningless pivot. Other
/// errors pass unchanged. Only called on the error path.
#[cold]
#[inline(never)]
pub fn diagnose<M: Evaluate<N>, const N: usize>(
    mechanism: &M,
    t: f64,
    q: &[f64; N],
    v: &[f64; N],
    error: Error,
) -> Error {
    if let Error::SingularMassMatrix { .. } = error {
        let m = mechanism.equations_of_motion_at(t, q, v).mass_matrix;
        if !m.iter().all(|x| x.is_finite()) {
            return non_finite_at::<M::Coords, N>(t, q, Some(v));
        }
    }
    error
}

/// [`Error::NonFiniteDynamics`] at (t, q), naming the velocities too when they were an input (a
/// huge velocity overflows T while q is harmless).
#[cold]
#[inline(never)]
pub(crate) fn non_finite_at<C: Coordinates<N>, const N: usize>(
    t: f64,
    q: &[f64; N],
    v: Option<&[f64; N]>,
) -> Error {
    let mut configuration = describe_configuration(&C::NAMES, q);
    if let Some(v) = v {
        configuration = format!(
            "{configuration}, velocities ({})",
            describe_configuration(&C::NAMES, v)
        );
    }
    Error::NonFiniteDynamics { t, configuration }
}
