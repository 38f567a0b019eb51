//! One collocation step: the simplified Newton iteration, its exact Newton fallback, and the end.

use super::matrix::{simplified_matrix, NewtonMatrix, MASS_REFRESH_THETA};
use super::predictor::PreviousStep;
use super::tableau::Tableau;
use super::{ImplicitStepStats, NewtonMemory, JACOBIAN_REUSE_THETA};
use crate::error::{Error, Result};
use crate::evaluation::Evaluate;
use crate::integrate::canonical::{
    canonical_field, field_jacobians, velocities_and_mass_from_momenta, FieldJacobians,
};
use crate::integrate::newton::{
    self, breakdown, carries_constraint_forces, mass_weights, max_norm, newton, position_floor,
    BlockLu, NewtonEnd, NewtonScale, Unknowns as _, MAX_NEWTON_ITERATIONS,
};
use crate::integrate::Stats;
use nalgebra::{SMatrix, SVector};

/// What [`finish`] gives: q₁, v₁, p₁, M(q₁) if the velocity recovery solved with it, and the
/// step's cost.
type StepEnd<const N: usize> = (
    [f64; N],
    [f64; N],
    SVector<f64, N>,
    Option<SMatrix<f64, N, N>>,
    ImplicitStepStats,
);

const NOT_FINITE: &str =
    "the collocation residual is not finite (the stages left the region where \
                          the equations of motion are finite; reduce h)";

/// Qⱼ = q₀ + h Σₖ aⱼₖ Vₖ.
fn stage_position<const N: usize, const S: usize>(
    tableau: &Tableau<S>,
    q0: &SVector<f64, N>,
    stages: &[SVector<f64, N>; S],
    h: f64,
    j: usize,
) -> SVector<f64, N> {
    let mut qj = *q0;
    for k in 0..S {
        qj += stages[k] * (h * tableau.a[j][k]);
    }
    qj
}

/// What the stage velocities' increments are measured against (see `NewtonScale`): weighted by
/// √Mᵢᵢ, sized by the step's velocities (v₀ and the predicted stages), resolved to the positions'
/// size over h.
fn step_scale<const N: usize, const S: usize>(
    weights: SVector<f64, N>,
    q0: &SVector<f64, N>,
    v0: &SVector<f64, N>,
    predictor: &[SVector<f64, N>; S],
    h: f64,
) -> NewtonScale<[SVector<f64, N>; S]> {
    let stages = [weights; S];
    NewtonScale {
        weights: stages,
        size: v0
            .weighted_norm(&weights)
            .max(predictor.weighted_norm(&stages)),
        resolution: position_floor(&weights, q0, h),
    }
}

/// One collocation step: the simplified Newton iteration with the memory's matrix (or a fresh one),
/// falling back to the exact Newton iteration when even a fresh simplified one does not contract.
#[allow(clippy::too_many_arguments, clippy::type_complexity)]
pub(super) fn collocation_step<M: Evaluate<N>, const N: usize, const S: usize>(
    mechanism: &M,
    tableau: &Tableau<S>,
    memory: &mut NewtonMemory<N, S>,
    t: f64,
    q: &[f64; N],
    v: &[f64; N],
    h: f64,
    stats: &mut Stats,
) -> Result<([f64; N], [f64; N], ImplicitStepStats)> {
    newton::refuse_contacts::<M, N>(tableau.name)?;
    let v0 = SVector::<f64, N>::from(*v);
    let q0 = SVector::<f64, N>::from(*q);
    // The previous step of this solver, if it ended where this one starts.
    let previous = memory.previous.filter(|prev| prev.t_end == t);
    let p0 = match previous {
        Some(prev) if prev.q1 == q0 && prev.v1 == v0 => prev.p1,
        _ => SVector::<f64, N>::from(mechanism.momenta_at(t, q, v)),
    };
    // The stages are predicted from the previous step when there is one (the solver's memory), else
    // Vᵢ = v₀ + cᵢ h q̈(t₀, q₀, v₀), O(h²) from the solution: one plain evaluation. Whether the
    // field carries constraint forces is the declaration's (Dynamics::CONSTRAINTS): every stage
    // includes Jᵀλ unless the mechanism declares no rows, whatever λ is at the start of the step.
    let constrained = carries_constraint_forces::<M, N>();
    // The extrapolation from the last step, and the predictor: it corrected by that step's own
    // extrapolation error.
    let extrapolated = previous
        .filter(|prev| prev.h == h)
        .map(|prev| prev.extrapolate(&tableau.c, &(v0 - prev.v1)));
    let predictor: [SVector<f64, N>; S] = match (previous, extrapolated) {
        (Some(prev), Some(x)) => std::array::from_fn(|i| x[i] + prev.extrapolation_error[i]),
        _ => {
            stats.evaluations += 1;
            let a0 = SVector::<f64, N>::from(mechanism.accelerations_at(t, q, v)?);
            std::array::from_fn(|i| v0 + a0 * (tableau.c[i] * h))
        }
    };
    memory.previous = None;
    let mut counts = ImplicitStepStats::default();
    for attempt in 0..2 {
        // The matrix: the memory's if it is still good (refactorised for a new h), else fresh.
        let reuse = attempt == 0 && memory.matrix.is_some_and(|m| m.reusable);
        // A kept matrix that contracted slower than MASS_REFRESH_THETA takes ∂p/∂v = M(q₀) where
        // the last step left it (the block that goes stale fastest: the others are scaled by h
        // or h²).
        let mass = previous
            .and_then(|prev| prev.mass1)
            .filter(|_| reuse && memory.matrix.is_some_and(|m| m.theta > MASS_REFRESH_THETA));
        let jacobians = match memory.matrix {
            Some(m) if reuse => FieldJacobians {
                p_v: mass.unwrap_or(m.jacobians.p_v),
                ..m.jacobians
            },
            _ => {
                stats.jacobians += 1;
                counts.jacobian_evaluations += 1;
                field_jacobians(mechanism, t + 0.5 * h, q, v, constrained)?
            }
        };
        let matrix = match memory.matrix {
            Some(m) if reuse && m.h == h && mass.is_none() => m,
            _ => {
                stats.factorizations += 1;
                counts.factorizations += 1;
                let Some(lu) = BlockLu::factor(&simplified_matrix(tableau, &jacobians, h)) else {
                    memory.matrix = None;
                    break; // singular or not finite: the exact iteration reports it
                };
                NewtonMatrix {
                    jacobians,
                    lu,
                    h,
                    reusable: true,
                    theta: 0.0,
                }
            }
        };
        let mut stages = predictor;
        let mut rates = [SVector::<f64, N>::zeros(); S];
        let mut last = [SVector::<f64, N>::zeros(); S];
        let mut evaluations = 0;
        let before = stats.newton_iterations;
        // Stage velocities weighted by √Mᵢᵢ (M = ∂p/∂v), against the step's velocities; resolved
        // to the positions' size over h.
        let scale = || step_scale(mass_weights(&jacobians.p_v), &q0, &v0, &predictor, h);
        let end = newton(
            &mut stages,
            MAX_NEWTON_ITERATIONS,
            true,
            stats,
            scale,
            |stages| {
                let mut p = [SVector::<f64, N>::zeros(); S];
                for j in 0..S {
                    let qj = stage_position(tableau, &q0, stages, h, j);
                    let (pj, rj) = canonical_field(
                        mechanism,
                        t + tableau.c[j] * h,
                        &qj.into(),
                        &stages[j].into(),
                        constrained,
                    )?;
                    evaluations += 1;
                    p[j] = pj.into();
                    rates[j] = rj.into();
                }
                let mut residual = [SVector::<f64, N>::zeros(); S];
                let mut norm = 0.0f64;
                for i in 0..S {
                    let mut r = p[i] - p0;
                    for j in 0..S {
                        r -= rates[j] * (h * tableau.a[i][j]);
                    }
                    norm = norm.max(max_norm(&r));
                    residual[i] = r;
                }
                if !norm.is_finite() {
                    return Err(breakdown(tableau.name, t, h, evaluations / S, NOT_FINITE));
                }
                last = matrix.lu.solve(&residual);
                Ok((last, norm))
            },
        );
        stats.evaluations += evaluations;
        counts.field_evaluations += evaluations;
        counts.iterations += stats.newton_iterations - before;
        let theta = match end {
            Ok(NewtonEnd::Converged { theta, .. }) => theta,
            // A stale matrix may not contract, or carry the stages where the field is not finite:
            // refresh it; with a fresh one, fall back to the exact iteration.
            Ok(NewtonEnd::Slow { .. }) | Err(Error::NewtonBreakdown { .. }) => {
                memory.matrix = None;
                if reuse {
                    continue;
                }
                break;
            }
            Err(e) => return Err(e),
        };
        memory.matrix = Some(NewtonMatrix {
            reusable: theta <= JACOBIAN_REUSE_THETA,
            theta,
            ..matrix
        });
        // ṗⱼ carried from the last evaluation to the final iterate by the reference Jacobians
        // (first order in the last increment, which is at the round-off floor).
        let j = &matrix.jacobians;
        for i in 0..S {
            let mut dq = SVector::<f64, N>::zeros();
            for k in 0..S {
                dq += last[k] * (h * tableau.a[i][k]);
            }
            rates[i] -= j.rate_q * dq + j.rate_v * last[i];
        }
        let (q1, v1, p1, mass1, counts) = finish(
            mechanism, tableau, t, &q0, &v0, &p0, &stages, &rates, h, stats, counts,
        )?;
        memory.previous = Some(PreviousStep {
            t_end: t + h,
            h,
            v0,
            stages,
            extrapolation_error: match extrapolated {
                Some(x) => std::array::from_fn(|i| stages[i] - x[i]),
                None => [SVector::zeros(); S],
            },
            q1: q1.into(),
            v1: v1.into(),
            p1,
            mass1,
        });
        return Ok((q1, v1, counts));
    }
    exact_collocation(
        mechanism,
        tableau,
        t,
        &q0,
        &v0,
        &p0,
        predictor,
        constrained,
        h,
        stats,
        counts,
    )
}

/// q₁ = q₀ + h Σ bⱼ Vⱼ, p₁ = p₀ + h Σ bⱼ ṗⱼ, and v₁ from p₁ (inverse Legendre transform at t₁),
/// starting from the collocation polynomial's end velocity v₀ + Σ dᵢ (Vᵢ − v₀), dᵀ = bᵀA⁻¹,
/// which is exact when p = M v with M constant.
#[allow(clippy::too_many_arguments, clippy::type_complexity)]
fn finish<M: Evaluate<N>, const N: usize, const S: usize>(
    mechanism: &M,
    tableau: &Tableau<S>,
    t: f64,
    q0: &SVector<f64, N>,
    v0: &SVector<f64, N>,
    p0: &SVector<f64, N>,
    stages: &[SVector<f64, N>; S],
    rates: &[SVector<f64, N>; S],
    h: f64,
    stats: &mut Stats,
    mut counts: ImplicitStepStats,
) -> Result<StepEnd<N>> {
    let mut q1 = *q0;
    let mut p1 = *p0;
    let mut guess = *v0;
    for j in 0..S {
        q1 += stages[j] * (h * tableau.b[j]);
        p1 += rates[j] * (h * tableau.b[j]);
        guess += (stages[j] - v0) * tableau.d[j];
    }
    let (v1, velocity_iterations, mass1) = velocities_and_mass_from_momenta(
        mechanism,
        t + h,
        &q1.into(),
        &p1.into(),
        &guess.into(),
        stats,
    )?;
    counts.velocity_iterations = velocity_iterations;
    Ok((q1.into(), v1, p1, mass1, counts))
}

/// The collocation equations solved by Newton's method with exact Jacobians at every iterate
/// (each stage's field and its Jacobians by dual numbers, the (S·N)-square matrix factorised
/// anew): quadratic convergence, the fallback when a simplified iteration with a fresh matrix
/// does not contract (steps far too large for the mechanism's time scales).
#[allow(clippy::too_many_arguments, clippy::type_complexity)]
fn exact_collocation<M: Evaluate<N>, const N: usize, const S: usize>(
    mechanism: &M,
    tableau: &Tableau<S>,
    t: f64,
    q0: &SVector<f64, N>,
    v0: &SVector<f64, N>,
    p0: &SVector<f64, N>,
    mut stages: [SVector<f64, N>; S],
    constrained: bool,
    h: f64,
    stats: &mut Stats,
    mut counts: ImplicitStepStats,
) -> Result<([f64; N], [f64; N], ImplicitStepStats)> {
    let zero = SMatrix::<f64, N, N>::zeros();
    let mut rates = [SVector::<f64, N>::zeros(); S];
    let mut last = [SVector::<f64, N>::zeros(); S];
    let mut field: [FieldJacobians<N>; S] = [FieldJacobians {
        p: SVector::zeros(),
        rate: SVector::zeros(),
        p_q: zero,
        p_v: zero,
        rate_q: zero,
        rate_v: zero,
    }; S];
    let mut iteration = 0;
    let before = stats.newton_iterations;
    // Weighted by the first iterate's M = ∂p/∂v at the first stage (see `NewtonScale`).
    let weights = std::cell::Cell::new(SVector::<f64, N>::zeros());
    let predictor = stages;
    let scale = || step_scale(weights.get(), q0, v0, &predictor, h);
    let end = newton(
        &mut stages,
        MAX_NEWTON_ITERATIONS,
        false,
        stats,
        scale,
        |stages| {
            iteration += 1;
            for j in 0..S {
                let qj = stage_position(tableau, q0, stages, h, j);
                field[j] = field_jacobians(
                    mechanism,
                    t + tableau.c[j] * h,
                    &qj.into(),
                    &stages[j].into(),
                    constrained,
                )?;
                rates[j] = field[j].rate;
            }
            if iteration == 1 {
                weights.set(mass_weights(&field[0].p_v));
            }
            let mut residual = [SVector::<f64, N>::zeros(); S];
            let mut jac = [[zero; S]; S];
            let mut norm = 0.0f64;
            for i in 0..S {
                let mut r = field[i].p - p0;
                for j in 0..S {
                    r -= field[j].rate * (h * tableau.a[i][j]);
                }
                norm = norm.max(max_norm(&r));
                residual[i] = r;
                for k in 0..S {
                    let mut block = field[i].p_q * (h * tableau.a[i][k]);
                    if i == k {
                        block += field[i].p_v;
                    }
                    for j in 0..S {
                        block -= field[j].rate_q * (h * h * tableau.a[i][j] * tableau.a[j][k]);
                    }
                    block -= field[k].rate_v * (h * tableau.a[i][k]);
                    jac[i][k] = block;
                }
            }
            if !norm.is_finite() {
                return Err(breakdown(tableau.name, t, h, iteration, NOT_FINITE));
            }
            let Some(lu) = BlockLu::factor(&jac) else {
                let finite = jac
                    .iter()
                    .flatten()
                    .all(|b| b.iter().all(|x| x.is_finite()));
                return Err(breakdown(
                    tableau.name,
                    t,
                    h,
                    iteration,
                    if finite {
                        "the Newton matrix is singular"
                    } else {
                        "the Newton matrix is not finite (h is too large for this mechanism)"
                    },
                ));
            };
            last = lu.solve(&residual);
            Ok((last, norm))
        },
    );
    let n = stats.newton_iterations - before;
    stats.jacobians += S * iteration;
    stats.factorizations += n;
    counts.iterations += n;
    counts.jacobian_evaluations += S * iteration;
    counts.factorizations += n;
    end?.converged(t)?;
    // ṗⱼ carried to the final iterate by its own Jacobians (first order in the last increment,
    // which is at the round-off floor: no extra evaluation).
    for j in 0..S {
        let mut dq = SVector::<f64, N>::zeros();
        for k in 0..S {
            dq += last[k] * (h * tableau.a[j][k]);
        }
        rates[j] -= field[j].rate_q * dq + field[j].rate_v * last[j];
    }
    finish(
        mechanism, tableau, t, q0, v0, p0, &stages, &rates, h, stats, counts,
    )
    .map(|(q1, v1, _, _, counts)| (q1, v1, counts))
}
