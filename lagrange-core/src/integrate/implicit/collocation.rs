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
    self, breakdown, carries_constraint_forces, max_norm, newton, BlockLu, NewtonEnd,
    MAX_NEWTON_ITERATIONS,
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

/// Stage j's point (tⱼ, Qⱼ, Vⱼ): tⱼ = t + cⱼh, Qⱼ = q₀ + h Σₖ aⱼₖ Vₖ.
#[inline(always)]
fn stage_point<const N: usize, const S: usize>(
    tableau: &Tableau<S>,
    (t, q0): (f64, &SVector<f64, N>),
    stages: &[SVector<f64, N>; S],
    h: f64,
    j: usize,
) -> (f64, [f64; N], [f64; N]) {
    let mut qj = *q0;
    for k in 0..S {
        qj += stages[k] * (h * tableau.a[j][k]);
    }
    (t + tableau.c[j] * h, qj.into(), stages[j].into())
}

/// The start of a collocation step: (q₀, v₀) as vectors, p₀, the solver's previous step if this
/// one starts where it ended, and the stages' predictor with the extrapolation it corrects.
struct Start<const N: usize, const S: usize> {
    q0: SVector<f64, N>,
    v0: SVector<f64, N>,
    p0: SVector<f64, N>,
    previous: Option<PreviousStep<N, S>>,
    extrapolated: Option<[SVector<f64, N>; S]>,
    predictor: [SVector<f64, N>; S],
}

/// p₀ (the previous step's p₁ when the state is where that step left it) and the stages'
/// predictor: the previous step's stages extrapolated and corrected by that extrapolation's error
/// on it when it had the same h, else Vᵢ = v₀ + cᵢ h q̈(t₀, q₀, v₀), O(h²) from the solution (one
/// plain evaluation).
#[inline(always)]
fn start_of_step<M: Evaluate<N>, const N: usize, const S: usize>(
    mechanism: &M,
    tableau: &Tableau<S>,
    memory: &NewtonMemory<N, S>,
    (t, q, v): (f64, &[f64; N], &[f64; N]),
    h: f64,
    stats: &mut Stats,
) -> Result<Start<N, S>> {
    let v0 = SVector::<f64, N>::from(*v);
    let q0 = SVector::<f64, N>::from(*q);
    // The previous step of this solver, if it ended where this one starts.
    let previous = memory.previous.filter(|prev| prev.t_end == t);
    let p0 = match previous {
        Some(prev) if prev.q1 == q0 && prev.v1 == v0 => prev.p1,
        _ => SVector::<f64, N>::from(mechanism.momenta_at(t, q, v)),
    };
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
    Ok(Start {
        q0,
        v0,
        p0,
        previous,
        extrapolated,
        predictor,
    })
}

/// The matrix of a simplified Newton iteration: the memory's if `reuse` (refactorised for a new
/// h), else from fresh field Jacobians at the step's midpoint; `None` when its factorisation is
/// singular or not finite. A kept matrix that contracted slower than [`MASS_REFRESH_THETA`] takes
/// ∂p/∂v = M(q₀) where the last step left it (the block that goes stale fastest: the others are
/// scaled by h or h²).
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn attempt_matrix<M: Evaluate<N>, const N: usize, const S: usize>(
    mechanism: &M,
    tableau: &Tableau<S>,
    memory: &NewtonMemory<N, S>,
    previous: Option<PreviousStep<N, S>>,
    reuse: bool,
    ((t, q, v), h): ((f64, &[f64; N], &[f64; N]), f64),
    stats: &mut Stats,
    counts: &mut ImplicitStepStats,
) -> Result<Option<NewtonMatrix<N, S>>> {
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
            let constrained = carries_constraint_forces::<M, N>();
            field_jacobians(mechanism, t + 0.5 * h, q, v, constrained)?
        }
    };
    Ok(match memory.matrix {
        Some(m) if reuse && m.h == h && mass.is_none() => Some(m),
        _ => {
            stats.factorizations += 1;
            counts.factorizations += 1;
            BlockLu::factor(&simplified_matrix(tableau, &jacobians, h)).map(|lu| NewtonMatrix {
                jacobians,
                lu,
                h,
                reusable: true,
                theta: 0.0,
            })
        }
    })
}

/// The collocation residuals Rᵢ = pᵢ − p₀ − h Σⱼ aᵢⱼ ṗⱼ of the stages' momenta `p` and rates, and
/// their largest max-norm.
#[inline(always)]
fn collocation_residual<const N: usize, const S: usize>(
    tableau: &Tableau<S>,
    h: f64,
    p0: &SVector<f64, N>,
    p: impl Fn(usize) -> SVector<f64, N>,
    rates: impl Fn(usize) -> SVector<f64, N>,
) -> ([SVector<f64, N>; S], f64) {
    let mut residual = [SVector::<f64, N>::zeros(); S];
    let mut norm = 0.0f64;
    for i in 0..S {
        let mut r = p(i) - p0;
        for j in 0..S {
            r -= rates(j) * (h * tableau.a[i][j]);
        }
        norm = norm.max(max_norm(&r));
        residual[i] = r;
    }
    (residual, norm)
}

/// ṗᵢ carried from the last evaluation to the final iterate by the stage's Jacobians
/// (`jacobians(i)`): ṗᵢ −= ∂ṗ/∂q h Σₖ aᵢₖ δₖ + ∂ṗ/∂v δᵢ, first order in the last increment δ,
/// which is at the round-off floor: no extra evaluation.
#[inline(always)]
fn carry_rates<'a, const N: usize, const S: usize>(
    rates: &mut [SVector<f64, N>; S],
    last: &[SVector<f64, N>; S],
    tableau: &Tableau<S>,
    h: f64,
    jacobians: impl Fn(usize) -> &'a FieldJacobians<N>,
) {
    for i in 0..S {
        let mut dq = SVector::<f64, N>::zeros();
        for k in 0..S {
            dq += last[k] * (h * tableau.a[i][k]);
        }
        let j = jacobians(i);
        rates[i] -= j.rate_q * dq + j.rate_v * last[i];
    }
}

/// The simplified Newton iteration on the stages with `matrix` (stopping when it is slow): how it
/// ended, the stages' rates ṗⱼ at the last evaluation and the last increment.
#[allow(clippy::too_many_arguments, clippy::type_complexity)]
#[inline(always)]
fn simplified_iteration<M: Evaluate<N>, const N: usize, const S: usize>(
    mechanism: &M,
    tableau: &Tableau<S>,
    matrix: &NewtonMatrix<N, S>,
    (q0, p0): (&SVector<f64, N>, &SVector<f64, N>),
    stages: &mut [SVector<f64, N>; S],
    (t, h): (f64, f64),
    stats: &mut Stats,
    counts: &mut ImplicitStepStats,
) -> (
    Result<NewtonEnd>,
    [SVector<f64, N>; S],
    [SVector<f64, N>; S],
) {
    let constrained = carries_constraint_forces::<M, N>();
    let mut rates = [SVector::<f64, N>::zeros(); S];
    let mut last = [SVector::<f64, N>::zeros(); S];
    let mut evaluations = 0;
    let before = stats.newton_iterations;
    let end = newton(stages, MAX_NEWTON_ITERATIONS, true, stats, |stages| {
        let mut p = [SVector::<f64, N>::zeros(); S];
        for j in 0..S {
            let (tj, qj, vj) = stage_point(tableau, (t, q0), stages, h, j);
            let (pj, rj) = canonical_field(mechanism, tj, &qj, &vj, constrained)?;
            evaluations += 1;
            p[j] = pj.into();
            rates[j] = rj.into();
        }
        let (residual, norm) = collocation_residual(tableau, h, p0, |i| p[i], |j| rates[j]);
        if !norm.is_finite() {
            return Err(breakdown(tableau.name, t, h, evaluations / S, NOT_FINITE));
        }
        last = matrix.lu.solve(&residual);
        Ok((last, norm))
    });
    stats.evaluations += evaluations;
    counts.field_evaluations += evaluations;
    counts.iterations += stats.newton_iterations - before;
    (end, rates, last)
}

/// One collocation step: the simplified Newton iteration with the memory's matrix (or a fresh one),
/// falling back to the exact Newton iteration when even a fresh simplified one does not contract.
/// Whether the field carries constraint forces is the declaration's (`Dynamics::CONSTRAINTS`):
/// every stage includes Jᵀλ unless the mechanism declares no rows, whatever λ is at the start of
/// the step.
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
    let start = start_of_step(mechanism, tableau, memory, (t, q, v), h, stats)?;
    let (q0, v0, p0) = (start.q0, start.v0, start.p0);
    memory.previous = None;
    let mut counts = ImplicitStepStats::default();
    for attempt in 0..2 {
        // The matrix: the memory's if it is still good (refactorised for a new h), else fresh.
        let reuse = attempt == 0 && memory.matrix.is_some_and(|m| m.reusable);
        let y = ((t, q, v), h);
        let found = attempt_matrix(
            mechanism,
            tableau,
            memory,
            start.previous,
            reuse,
            y,
            stats,
            &mut counts,
        )?;
        let Some(matrix) = found else {
            memory.matrix = None;
            break; // singular or not finite: the exact iteration reports it
        };
        let mut stages = start.predictor;
        let (end, mut rates, last) = simplified_iteration(
            mechanism,
            tableau,
            &matrix,
            (&q0, &p0),
            &mut stages,
            (t, h),
            stats,
            &mut counts,
        );
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
        // ṗⱼ carried to the final iterate by the reference Jacobians.
        carry_rates(&mut rates, &last, tableau, h, |_| &matrix.jacobians);
        let (q1, v1, p1, mass1, counts) = finish(
            mechanism, tableau, t, &q0, &v0, &p0, &stages, &rates, h, stats, counts,
        )?;
        let end = (q1.into(), v1.into(), p1, mass1);
        memory.previous = Some(remember(&start, (t, h), stages, end));
        return Ok((q1, v1, counts));
    }
    exact_collocation(mechanism, tableau, t, &start, h, stats, counts)
}

/// What the next step of the solver takes from this one, which ended at (q₁, v₁, p₁) with the
/// mass matrix `mass1` there (if it was evaluated): its stages, and their error against the
/// extrapolation of the step before (zero without one).
#[inline(always)]
fn remember<const N: usize, const S: usize>(
    start: &Start<N, S>,
    (t, h): (f64, f64),
    stages: [SVector<f64, N>; S],
    (q1, v1, p1, mass1): (
        SVector<f64, N>,
        SVector<f64, N>,
        SVector<f64, N>,
        Option<SMatrix<f64, N, N>>,
    ),
) -> PreviousStep<N, S> {
    PreviousStep {
        t_end: t + h,
        h,
        v0: start.v0,
        stages,
        extrapolation_error: match start.extrapolated {
            Some(x) => std::array::from_fn(|i| stages[i] - x[i]),
            None => [SVector::zeros(); S],
        },
        q1,
        v1,
        p1,
        mass1,
    }
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

/// The Newton matrix of the collocation equations at the stages, from each stage's field
/// Jacobians: block (i, k) = ∂pᵢ/∂q h aᵢₖ + δᵢₖ ∂pᵢ/∂v − h² Σⱼ aᵢⱼ aⱼₖ ∂ṗⱼ/∂q − h aᵢₖ ∂ṗₖ/∂v.
#[inline(always)]
fn exact_matrix<const N: usize, const S: usize>(
    tableau: &Tableau<S>,
    field: &[FieldJacobians<N>; S],
    h: f64,
) -> [[SMatrix<f64, N, N>; S]; S] {
    let mut jac = [[SMatrix::<f64, N, N>::zeros(); S]; S];
    for i in 0..S {
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
    jac
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
    start: &Start<N, S>,
    h: f64,
    stats: &mut Stats,
    mut counts: ImplicitStepStats,
) -> Result<([f64; N], [f64; N], ImplicitStepStats)> {
    let (q0, v0, p0) = (&start.q0, &start.v0, &start.p0);
    let mut stages = start.predictor;
    let constrained = carries_constraint_forces::<M, N>();
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
    let end = newton(&mut stages, MAX_NEWTON_ITERATIONS, false, stats, |stages| {
        iteration += 1;
        for j in 0..S {
            let (tj, qj, vj) = stage_point(tableau, (t, q0), stages, h, j);
            field[j] = field_jacobians(mechanism, tj, &qj, &vj, constrained)?;
            rates[j] = field[j].rate;
        }
        let (residual, norm) =
            collocation_residual(tableau, h, p0, |i| field[i].p, |j| field[j].rate);
        let jac = exact_matrix(tableau, &field, h);
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
    });
    let n = stats.newton_iterations - before;
    stats.jacobians += S * iteration;
    stats.factorizations += n;
    counts.iterations += n;
    counts.jacobian_evaluations += S * iteration;
    counts.factorizations += n;
    end?.converged(t)?;
    // ṗⱼ carried to the final iterate by its own Jacobians.
    carry_rates(&mut rates, &last, tableau, h, |j| &field[j]);
    finish(
        mechanism, tableau, t, q0, v0, p0, &stages, &rates, h, stats, counts,
    )
    .map(|(q1, v1, _, _, counts)| (q1, v1, counts))
}
