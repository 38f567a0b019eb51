//! Why an evaluation of q̈ failed: a non-finite result, an overflowed or singular mass matrix,
//! each named by the configuration (t, q) it happened at. Off the hot path (`#[cold]`) except the
//! one-branch finiteness test.

use crate::error::{describe_configuration, Error, Result};
use crate::geometry::Scalar;
use crate::linalg::NotPositiveDefinite;
use crate::model::{lane_sum, Coordinates};
use nalgebra::{SMatrix, SVector};

/// `qdd` when every entry is finite, otherwise [`Error::NonFiniteDynamics`] at (t, q).
#[inline(always)]
pub(crate) fn finite_accelerations<C: Coordinates<N>, S: Scalar, const N: usize>(
    qdd: SVector<S, N>,
    t: S,
    q: &[S; N],
) -> Result<[S; N]> {
    // One branch, one product: s·0 is 0 exactly when s is finite, and the sum s of the entries
    // is finite when they all are. A sum that overflows although every entry is finite is sorted
    // out off the hot path.
    if lane_sum::<N>(|j| qdd[j].re()) * 0.0 == 0.0 {
        Ok(qdd.into())
    } else {
        finite_or_overflowed::<C, S, N>(qdd, t, q)
    }
}

/// [`finite_accelerations`] when the sum of the entries is not finite: `qdd` when every entry is
/// (the sum overflowed), otherwise [`Error::NonFiniteDynamics`] at (t, q).
#[cold]
#[inline(never)]
fn finite_or_overflowed<C: Coordinates<N>, S: Scalar, const N: usize>(
    qdd: SVector<S, N>,
    t: S,
    q: &[S; N],
) -> Result<[S; N]> {
    if qdd.iter().all(|a| a.re().is_finite()) {
        Ok(qdd.into())
    } else {
        Err(non_finite_dynamics::<C, S, N>(t, q))
    }
}

/// Why a factorisation of the mass matrix failed at (t, q): a matrix that overflowed (a blown-up
/// state) is not singular — [`Error::NonFiniteDynamics`] — otherwise the singular pivot.
#[cold]
#[inline(never)]
pub(crate) fn mass_matrix_failure<C: Coordinates<N>, S: Scalar, const N: usize>(
    mass_matrix: &SMatrix<S, N, N>,
    e: NotPositiveDefinite,
    t: S,
    q: &[S; N],
) -> Error {
    if mass_matrix.iter().any(|m| !m.re().is_finite()) {
        non_finite_dynamics::<C, S, N>(t, q)
    } else {
        singular_mass_matrix::<C, S, N>(e, t, q)
    }
}

/// The error for a mass matrix that is singular at (t, q), naming the configuration and the pivot.
#[cold]
#[inline(never)]
pub(crate) fn singular_mass_matrix<C: Coordinates<N>, S: Scalar, const N: usize>(
    e: NotPositiveDefinite,
    t: S,
    q: &[S; N],
) -> Error {
    Error::SingularMassMatrix {
        t: t.re(),
        configuration: describe_configuration(&C::NAMES, &q.map(|q| q.re())),
        coordinate: C::NAMES[e.index],
        pivot: e.pivot,
    }
}

/// The error for equations of motion that came out non-finite at (t, q).
#[cold]
#[inline(never)]
pub(crate) fn non_finite_dynamics<C: Coordinates<N>, S: Scalar, const N: usize>(
    t: S,
    q: &[S; N],
) -> Error {
    Error::NonFiniteDynamics {
        t: t.re(),
        configuration: describe_configuration(&C::NAMES, &q.map(|q| q.re())),
    }
}
