//! A step of a method on momenta conjugate to q̇ for a mechanism with quasi-velocities, taken in
//! the coordinates' rates ([`InRates`]) between conversions at its ends: implicit midpoint,
//! Gauss–Legendre and the variational integrator then take exactly the steps they take on the same
//! declaration written with the chart's rates for velocities, symplectic in its (q, p).

use crate::error::Result;
use crate::evaluation::rates::{velocities, InRates};
use crate::evaluation::Evaluate;

/// A step of a method on momenta conjugate to q̇ from (q, v) of a mechanism with
/// quasi-velocities: q̇ = G v, `step` on [`InRates`] from (q, q̇) (what it reports beside the end
/// passed on), and v₁ = B(q₁) q̇₁ at its end.
pub(super) fn step_in_rates<M: Evaluate<N>, X, const N: usize>(
    mechanism: &M,
    (q, v): (&[f64; N], &[f64; N]),
    step: impl FnOnce(&InRates<'_, M>, &[f64; N]) -> Result<([f64; N], [f64; N], X)>,
) -> Result<([f64; N], [f64; N], X)> {
    let rates = mechanism.position_rates_at(q, v);
    let (q1, rates1, x) = step(&InRates(mechanism), &rates)?;
    let v1 = velocities::<M, f64, N>(&q1, &rates1);
    Ok((q1, v1, x))
}
