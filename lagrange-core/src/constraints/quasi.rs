//! A state's velocities and the coordinates' rates the rows are written in. A declaration whose
//! free or ball joints have the body's angular velocity for velocities
//! ([`Constraints::QUASI_VELOCITY_JOINTS`]) carries quasi-velocities v, q̇ = G(q) v
//! ([`crate::tree::rigid::free`]). The rows, the KKT solve, the mode's complementarity, the
//! projection and the impact law are written on (q, q̇), and each is a statement about the motion
//! that a change of velocities at fixed q leaves as it is:
//!
//! ```text
//! q̇ = G v,   q̈ = G (v̇ − Ḃ q̇)  ⇔  v̇ = B q̈ + Ḃ q̇,   constraint forces dual to v: Gᵀ (Rᵀ λ),
//! ```
//!
//! the multipliers the same; the velocity projection min ½ (q̇ − q̇₀)ᵀ M (q̇ − q̇₀) subject to
//! R q̇ = r is, with q̇ = G v and M = Bᵀ M_v B, min ½ (v − v₀)ᵀ M_v (v − v₀) subject to (R G) v = r,
//! the projection in v with its own mass matrix. So the public functions of the module convert
//! at their entry and exit and run the functions written on the rates (`…_in_rates`) between;
//! for every other declaration the joints are none and each map below is the identity, decided
//! at compile time.

use super::Constraints;
use crate::error::Result;
use crate::geometry::Scalar;
use crate::tree::rigid::{free, Joint};

/// Whether `M`'s velocities are quasi-velocities (a constant).
#[inline(always)]
pub(super) const fn quasi<
    M: Constraints<N, K, C>,
    const N: usize,
    const K: usize,
    const C: usize,
>() -> bool {
    free::has_angular_velocities(M::QUASI_VELOCITY_JOINTS)
}

/// One of the maps of [`free`]: the joints, q, x.
type JointMap<S, const N: usize> = fn(&[Joint], &[S; N], &[S; N]) -> [S; N];

/// `map` of `M`'s joints at q applied to x; x itself without quasi-velocities.
#[inline(always)]
fn through<M: Constraints<N, K, C>, S: Scalar, const N: usize, const K: usize, const C: usize>(
    q: &[S; N],
    x: &[S; N],
    map: JointMap<S, N>,
) -> [S; N] {
    match quasi::<M, N, K, C>() {
        false => *x,
        true => map(M::QUASI_VELOCITY_JOINTS, q, x),
    }
}

/// q̇ = G(q) v.
#[inline(always)]
pub(super) fn rates<
    M: Constraints<N, K, C>,
    S: Scalar,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    q: &[S; N],
    v: &[S; N],
) -> [S; N] {
    through::<M, S, N, K, C>(q, v, free::position_rates)
}

/// v = B(q) q̇.
#[inline(always)]
pub(super) fn velocities<
    M: Constraints<N, K, C>,
    S: Scalar,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    q: &[S; N],
    rates: &[S; N],
) -> [S; N] {
    through::<M, S, N, K, C>(q, rates, free::velocities_from_rates)
}

/// v̇ = B q̈ + Ḃ q̇ from q̈ at (q, q̇).
#[inline(always)]
pub(super) fn accelerations<
    M: Constraints<N, K, C>,
    S: Scalar,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    q: &[S; N],
    rates: &[S; N],
    qdd: &[S; N],
) -> [S; N] {
    match quasi::<M, N, K, C>() {
        false => *qdd,
        true => free::velocity_accelerations(M::QUASI_VELOCITY_JOINTS, q, rates, qdd),
    }
}

/// Ḃ q̇ at (q, q̇): what v̇ adds to B q̈.
#[inline(always)]
pub(super) fn velocity_bias<
    M: Constraints<N, K, C>,
    S: Scalar,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    q: &[S; N],
    rates: &[S; N],
) -> [S; N] {
    free::velocity_bias(M::QUASI_VELOCITY_JOINTS, q, rates)
}

/// Gᵀ f: a generalized force (or a row) dual to q̇ made dual to v.
#[inline(always)]
pub(super) fn forces<
    M: Constraints<N, K, C>,
    S: Scalar,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    q: &[S; N],
    f: &[S; N],
) -> [S; N] {
    through::<M, S, N, K, C>(q, f, free::velocity_forces)
}

/// Runs `change` on (q, q̇ = G v), which may move both, and writes v = B(q) q̇ back at the moved
/// q; on error (which leaves q as it was) `v` is unchanged too.
#[inline(always)]
pub(super) fn in_rates<
    M: Constraints<N, K, C>,
    R,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    q: &mut [f64; N],
    v: &mut [f64; N],
    change: impl FnOnce(&mut [f64; N], &mut [f64; N]) -> Result<R>,
) -> Result<R> {
    let mut rates = rates::<M, f64, N, K, C>(q, v);
    let out = change(q, &mut rates)?;
    *v = velocities::<M, f64, N, K, C>(q, &rates);
    Ok(out)
}
