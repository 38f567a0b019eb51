//! Projection of (q, q̇) onto the constraints enforced in a mode: [`project`], by mass-weighted
//! least-norm corrections.

use super::rows::{position_rows_and_jacobian, velocity_rows_and_jacobian};
use super::solve::singular_constraints;
use super::{Constraints, Mode, CONSISTENCY_TOLERANCE};
use crate::dynamics;
use crate::error::{describe_state, Error, Result};
use crate::linalg::{cholesky, cholesky_substitute};
use crate::model::Coordinates;
use nalgebra::{SMatrix, SVector};

/// Iterations of the Newton projection of positions before giving up.
const MAX_PROJECTION_ITERATIONS: usize = 12;

fn mass_from_jacobian<M: Constraints<N, K, C>, const N: usize, const K: usize, const C: usize>(
    model: &M,
    jac: &[SVector<f64, N>; K],
) -> SMatrix<f64, N, N> {
    let masses = model.masses();
    let mut m = SMatrix::<f64, N, N>::zeros();
    for i in 0..M::INERTIAL {
        if masses[i] != 0.0 {
            m += jac[i] * jac[i].transpose() * masses[i];
        }
    }
    m
}

/// The largest |gᵢ|/sizeᵢ of the position rows enforced in `mode` at (t, q) (plain f64, no
/// derivatives): each row against its own size (see [`CONSISTENCY_TOLERANCE`]).
fn position_residual<M: Constraints<N, K, C>, const N: usize, const K: usize, const C: usize>(
    model: &M,
    t: f64,
    q: &[f64; N],
    mode: &Mode<C>,
    sizes: &[f64; C],
) -> f64 {
    let x = model.cartesian(t, q);
    let g = model.position_constraints(t, q, &x);
    relative_residual(&g, sizes, |i| M::KINDS[i].is_position() && mode.enforced(i))
}

/// maxᵢ |gᵢ|/sizeᵢ over the rows `use_row` selects (a row of size zero counts only if g is not
/// zero: then infinitely far).
pub(super) fn relative_residual<const C: usize>(
    g: &[f64; C],
    sizes: &[f64; C],
    use_row: impl Fn(usize) -> bool,
) -> f64 {
    (0..C)
        .filter(|&i| use_row(i) && g[i] != 0.0)
        .fold(0.0f64, |m, i| m.max(g[i].abs() / sizes[i]))
}

/// One mass-weighted least-norm correction δ = −M⁻¹Rᵀ(RM⁻¹Rᵀ)⁻¹r over the rows selected by `use_row`,
/// moving only the coordinates marked in `free`: held coordinates are removed from R and M is
/// replaced by its free block (the held rows and columns by the identity), so δ is exactly zero
/// on them and mass-weighted least-norm on the rest.
#[allow(clippy::too_many_arguments)]
fn least_norm_correction<
    M: Constraints<N, K, C>,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    model: &M,
    t: f64,
    q: &[f64; N],
    jac: &[SVector<f64, N>; K],
    rows: &[SVector<f64, N>; C],
    residual: &[f64; C],
    use_row: &[bool; C],
    free: &[bool; N],
) -> Result<SVector<f64, N>> {
    let mut mass = mass_from_jacobian(model, jac);
    let held_rows: [SVector<f64, N>; C];
    let rows = if free.iter().all(|&f| f) {
        rows
    } else {
        for a in 0..N {
            for b in 0..N {
                if !free[a] || !free[b] {
                    mass[(a, b)] = if a == b { 1.0 } else { 0.0 };
                }
            }
        }
        held_rows = std::array::from_fn(|i| {
            SVector::from_fn(|j, _| if free[j] { rows[i][j] } else { 0.0 })
        });
        &held_rows
    };
    let l = cholesky(&mass)
        .map_err(|e| dynamics::mass_matrix_failure::<M::Coords, f64, N>(&mass, e, t, q))?;
    let y: [SVector<f64, N>; C] = std::array::from_fn(|i| {
        if use_row[i] {
            cholesky_substitute(&l, &rows[i])
        } else {
            SVector::zeros()
        }
    });
    let mut schur = SMatrix::<f64, C, C>::zeros();
    let mut rhs = SVector::<f64, C>::zeros();
    let mut diagonal = 0.0f64;
    for i in 0..C {
        if use_row[i] {
            for k in 0..C {
                if use_row[k] {
                    schur[(i, k)] = rows[i].dot(&y[k]);
                }
            }
            rhs[i] = residual[i];
            diagonal = diagonal.max(schur[(i, i)]);
        }
    }
    let filler = if diagonal > 0.0 { diagonal } else { 1.0 };
    for i in 0..C {
        if !use_row[i] {
            schur[(i, i)] = filler;
        }
    }
    let ls = cholesky(&schur)
        .map_err(|e| singular_constraints::<M, f64, N, K, C>(e, &schur, use_row, t, q))?;
    let mu = cholesky_substitute(&ls, &rhs);
    let mut delta = SVector::<f64, N>::zeros();
    for k in 0..C {
        if use_row[k] {
            delta -= y[k] * mu[k];
        }
    }
    Ok(delta)
}

/// The Newton iteration of the position projection, shared by [`project`] and
/// [`project_prepared`](super::project_prepared): from q and `at_q` = `evaluate(q)` (the residual
/// maxᵢ |gᵢ|/sizeᵢ, relative to each row's size, and what `correction` needs there), steps
/// q ← q + δ with δ = `correction(q, ·)` while the residual decreases, until it reaches zero,
/// Newton's quadratic convergence makes the next correction fall below round-off (1e-8 of q, both
/// weighted by `weights` = √Mⱼⱼ so that coordinates of any unit compare), or it stalls at
/// round-off, at most [`MAX_PROJECTION_ITERATIONS`] times. Returns the best iterate, its
/// evaluation, its residual and the number of corrections computed.
#[inline(always)]
pub(super) fn newton_onto_positions<X, const N: usize>(
    q: [f64; N],
    at_q: (f64, X),
    weights: &[f64; N],
    mut evaluate: impl FnMut(&[f64; N]) -> (f64, X),
    mut correction: impl FnMut(&[f64; N], &X) -> Result<SVector<f64, N>>,
) -> Result<([f64; N], X, f64, usize)> {
    let (mut qn, (mut residual, mut at_qn)) = (q, at_q);
    let mut iterations = 0;
    while residual > 0.0 {
        if iterations == MAX_PROJECTION_ITERATIONS {
            break;
        }
        iterations += 1;
        let delta = correction(&qn, &at_qn)?;
        let trial: [f64; N] = std::array::from_fn(|j| qn[j] + delta[j]);
        let (new_residual, at_trial) = evaluate(&trial);
        if !(new_residual < residual) {
            break; // round-off floor reached: keep the best iterate
        }
        let stalled = new_residual > 0.25 * residual;
        let weighted =
            |x: &dyn Fn(usize) -> f64| (0..N).fold(0.0f64, |m, j| m.max(weights[j] * x(j).abs()));
        // Newton converges quadratically: after a correction this small the next one would be
        // ≲ |δ|²·(curvature) — below round-off — so it is not computed.
        let converged = weighted(&|j| delta[j]) <= 1e-8 * weighted(&|j| qn[j]);
        (qn, residual, at_qn) = (trial, new_residual, at_trial);
        if converged || (stalled && residual < CONSISTENCY_TOLERANCE * 1e-4) {
            break;
        }
    }
    Ok((qn, at_qn, residual, iterations))
}

/// [`Error::ProjectionFailed`] at the state (t, q, q̇) the projection started from when the
/// residual it reached (relative to each row's size) is above [`CONSISTENCY_TOLERANCE`] (or NaN).
pub(super) fn projection_failed<Names: Coordinates<N>, const N: usize>(
    t: f64,
    q: &[f64; N],
    v: &[f64; N],
    iterations: usize,
    residual: f64,
) -> Option<Error> {
    (!(residual <= CONSISTENCY_TOLERANCE)).then(|| Error::ProjectionFailed {
        t,
        iterations,
        residual,
        state: describe_state(&Names::NAMES, t, q, v),
    })
}

/// Projects (q, q̇) onto the rows enforced in `mode` (see the [module docs](super)): Newton on the
/// position rows with the mass-weighted least-norm step until the residual stops decreasing (round-off),
/// then one exact projection of q̇ onto every enforced row's velocity-level equation.
///
/// Errors: the Newton iteration does not bring the position residual below
/// [`CONSISTENCY_TOLERANCE`] ([`Error::ProjectionFailed`]), singular M or R M⁻¹ Rᵀ. On error `q`
/// and `v` are unchanged.
pub fn project<M: Constraints<N, K, C>, const N: usize, const K: usize, const C: usize>(
    model: &M,
    t: f64,
    q: &mut [f64; N],
    v: &mut [f64; N],
    mode: &Mode<C>,
) -> Result<()> {
    super::quasi::in_rates::<M, _, N, K, C>(q, v, |q, rates| {
        project_in_rates(model, t, q, rates, mode)
    })
}

/// [`project`] of (q, q̇), the coordinates' rates.
pub(crate) fn project_in_rates<
    M: Constraints<N, K, C>,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    model: &M,
    t: f64,
    q: &mut [f64; N],
    v: &mut [f64; N],
    mode: &Mode<C>,
) -> Result<()> {
    project_holding(model, t, q, v, mode, &[true; N], &[true; N])
}

/// [`project`] moving only the coordinates marked in `free_q` and the velocities marked in
/// `free_v`; the others are kept bit for bit.
pub(super) fn project_holding<
    M: Constraints<N, K, C>,
    const N: usize,
    const K: usize,
    const C: usize,
>(
    model: &M,
    t: f64,
    q: &mut [f64; N],
    v: &mut [f64; N],
    mode: &Mode<C>,
    free_q: &[bool; N],
    free_v: &[bool; N],
) -> Result<()> {
    let enforced: [bool; C] = std::array::from_fn(|i| mode.enforced(i));
    let position_rows: [bool; C] =
        std::array::from_fn(|i| enforced[i] && M::KINDS[i].is_position());
    let mut qn = *q;
    if position_rows.iter().any(|&b| b) {
        // The rows at the start size the residuals (and serve the first correction).
        let start = position_rows_and_jacobian(model, t, &qn);
        let weights =
            super::consistency::mass_weights(&super::rows::mass_diagonal(model, &start.2));
        let sizes = super::consistency::row_sizes(&start.0, &weights, &qn);
        let at_start = relative_residual(&start.1, &sizes, |i| position_rows[i]);
        let residual_at = |q: &[f64; N]| (position_residual(model, t, q, mode, &sizes), None);
        let (projected, _, residual, iterations) = newton_onto_positions(
            qn,
            (at_start, Some(start)),
            &weights,
            residual_at,
            |qn, at| {
                let (rows, value, jac) = match at {
                    Some(start) => *start,
                    None => position_rows_and_jacobian(model, t, qn),
                };
                least_norm_correction(model, t, qn, &jac, &rows, &value, &position_rows, free_q)
            },
        )?;
        if let Some(e) = projection_failed::<M::Coords, N>(t, q, v, iterations, residual) {
            return Err(e);
        }
        qn = projected;
    }
    let mut vn = *v;
    if enforced.iter().any(|&b| b) {
        let (rows, rate, jac) = velocity_rows_and_jacobian(model, t, &qn, &vn);
        let delta = least_norm_correction(model, t, &qn, &jac, &rows, &rate, &enforced, free_v)?;
        for j in 0..N {
            vn[j] += delta[j];
        }
    }
    if !qn.iter().chain(vn.iter()).all(|x| x.is_finite()) {
        return Err(Error::NonFiniteState {
            state: describe_state(&<M::Coords as Coordinates<N>>::NAMES, t, &qn, &vn),
        });
    }
    *q = qn;
    *v = vn;
    Ok(())
}
