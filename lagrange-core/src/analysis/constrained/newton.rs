//! Newton's method with a backtracking line search ([`line_search`](crate::analysis::line_search)) on F(q, λ) = 0 for a fixed set of enforced
//! rows (see [`constrained_equilibrium`](super::constrained_equilibrium)).

use super::kkt::{check_independent, kkt_terms, trial_residual, Kkt};
use crate::analysis::line_search::{backtrack, descent_direction};
use crate::analysis::{describe, max_abs, EquilibriumOptions};
use crate::constraints::Constraints;
use crate::error::{Error, Result};
use crate::mechanism::Mechanism;
use nalgebra::{DMatrix, DVector};

/// The result of one Newton solve with a fixed set of enforced rows.
pub(super) struct Solved<const N: usize> {
    pub(super) q: [f64; N],
    pub(super) lambda: Vec<f64>,
    pub(super) kkt: Kkt<N>,
    pub(super) iterations: usize,
}

/// The initial multipliers: least squares on the force balance, (G Gᵀ) λ = −G r (zero where the
/// normal equations are singular).
fn least_squares_multipliers<const N: usize>(kkt: &Kkt<N>, m: usize) -> Vec<f64> {
    let g_mat = DMatrix::from_fn(m, N, |a, k| kkt.grad[a][k]);
    if m == 0 {
        Vec::new()
    } else {
        let normal = &g_mat * g_mat.transpose();
        let rhs = -(&g_mat * DVector::from_column_slice(kkt.rest.residual.as_slice()));
        normal
            .lu()
            .solve(&rhs)
            .map(|v| v.iter().copied().collect())
            .unwrap_or_else(|| vec![0.0; m])
    }
}

/// Whether F = `f` passes the residual criterion: the force rows against the terms that cancel
/// in them, each constraint row against the change of g over a displacement of the size of q.
fn residual_converged<const N: usize>(
    kkt: &Kkt<N>,
    q: &[f64; N],
    lambda: &[f64],
    f: &DVector<f64>,
    options: &EquilibriumOptions,
) -> bool {
    let force_residual = max_abs(f.rows(0, N).iter());
    let force_ok = force_residual == 0.0
        || force_residual <= options.residual_tolerance * kkt.force_scale(q, lambda);
    let constraints_ok = (0..kkt.g.len()).all(|a| {
        kkt.g[a] == 0.0 || kkt.g[a].abs() <= options.residual_tolerance * kkt.constraint_scale(q, a)
    });
    force_ok && constraints_ok
}

/// The terms at the starting point q with the least-squares multipliers, once they are finite
/// and the enforced rows independent.
fn starting_terms<M, const N: usize, const K: usize, const C: usize>(
    mechanism: &M,
    t: f64,
    q: &[f64; N],
    rows: &[usize],
) -> Result<(Kkt<N>, Vec<f64>)>
where
    M: Constraints<N, K, C> + Mechanism<N>,
{
    let kkt = kkt_terms(mechanism, t, q, rows);
    if !kkt.finite() {
        return Err(Error::NonFiniteDynamics {
            t,
            configuration: describe::<M, N>(q),
        });
    }
    check_independent::<M, N, K, C>(&kkt, rows, t, q)?;
    let lambda = least_squares_multipliers(&kkt, rows.len());
    Ok((kkt, lambda))
}

/// The search direction on ½‖F‖² at (q, λ) (see [`descent_direction`]): from the Newton step
/// J p = −F with the KKT matrix J, or steepest descent along Jᵀ F.
fn search_direction<const N: usize>(
    kkt: &Kkt<N>,
    lambda: &[f64],
    f: &DVector<f64>,
) -> Option<(DVector<f64>, f64, bool)> {
    let jac = kkt.jacobian(lambda);
    let grad = jac.transpose() * f;
    let newton_step = (jac.clone().lu().solve(&(-f))).filter(|p| p.iter().all(|x| x.is_finite()));
    descent_direction(newton_step, &grad, f.norm_squared())
}

/// Whether a step `direction` = (δq, δλ) passes the step criterion: δq against max(1, ‖q‖∞), δλ
/// against max(‖λ‖∞, force scale / ‖∇g‖).
fn step_converged<const N: usize>(
    kkt: &Kkt<N>,
    q: &[f64; N],
    lambda: &[f64],
    direction: &DVector<f64>,
    options: &EquilibriumOptions,
) -> bool {
    let q_step = max_abs(direction.rows(0, N).iter());
    let l_step = max_abs(direction.rows(N, lambda.len()).iter());
    let l_scale = max_abs(lambda.iter()).max(kkt.multiplier_scale(q, lambda));
    q_step <= options.step_tolerance * max_abs(q.iter()).max(1.0)
        && l_step <= options.step_tolerance * l_scale
}

/// (q, λ) += `direction` = (δq, δλ).
fn take_step<const N: usize>(q: &mut [f64; N], lambda: &mut [f64], direction: &DVector<f64>) {
    for k in 0..N {
        q[k] += direction[k];
    }
    for (a, l) in lambda.iter_mut().enumerate() {
        *l += direction[N + a];
    }
}

/// Newton's method with line search on F(q, λ) = 0 for the enforced rows `rows`, from q0.
pub(super) fn newton<M, const N: usize, const K: usize, const C: usize>(
    mechanism: &M,
    t: f64,
    q0: [f64; N],
    rows: &[usize],
    options: &EquilibriumOptions,
    iterations_before: usize,
) -> Result<Solved<N>>
where
    M: Constraints<N, K, C> + Mechanism<N>,
{
    let m = rows.len();
    let mut q = q0;
    let not_found = |iterations: usize, residual: f64, q: &[f64; N]| Error::EquilibriumNotFound {
        t,
        iterations,
        residual,
        configuration: describe::<M, N>(q),
    };
    let (mut kkt, mut lambda) = starting_terms(mechanism, t, &q, rows)?;
    let mut iterations = 0;
    loop {
        let f = kkt.residual(&lambda);
        if residual_converged(&kkt, &q, &lambda, &f, options) {
            return Ok(Solved {
                q,
                lambda,
                kkt,
                iterations,
            });
        }
        let total = iterations_before + iterations;
        let f_norm = max_abs(f.iter());
        if iterations >= options.max_iterations {
            return Err(not_found(total, f_norm, &q));
        }
        iterations += 1;

        let merit = 0.5 * f.norm_squared();
        let Some((direction, slope, is_newton)) = search_direction(&kkt, &lambda, &f) else {
            return Err(not_found(total + 1, f_norm, &q));
        };
        if is_newton && step_converged(&kkt, &q, &lambda, &direction, options) {
            // A Newton step below the step tolerance: take it and stop.
            take_step(&mut q, &mut lambda, &direction);
            kkt = kkt_terms(mechanism, t, &q, rows);
            if !kkt.finite() {
                return Err(not_found(total + 1, f64::NAN, &q));
            }
            return Ok(Solved {
                q,
                lambda,
                kkt,
                iterations,
            });
        }

        let accepted = backtrack(merit, slope, |alpha| {
            let trial_q: [f64; N] = std::array::from_fn(|k| q[k] + alpha * direction[k]);
            let trial_l: Vec<f64> = (0..m)
                .map(|a| lambda[a] + alpha * direction[N + a])
                .collect();
            let f_trial = trial_residual(mechanism, t, &trial_q, &trial_l, rows);
            ((trial_q, trial_l), f_trial)
        });
        let Some((next_q, next_l)) = accepted else {
            return Err(not_found(total, f_norm, &q));
        };
        q = next_q;
        lambda = next_l;
        kkt = kkt_terms(mechanism, t, &q, rows);
        if !kkt.finite() {
            return Err(not_found(total, f64::NAN, &q));
        }
    }
}
