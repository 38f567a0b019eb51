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
use crate::integrate::rates::step_in_rates;
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
/// √Mᵢᵢ (`mass` is M = ∂p/∂v), sized by the step's velocities (v₀ and the predicted stages),
/// resolved to the positions' size over h.
#[inline(always)]
fn step_scale<M, const N: usize, const S: usize>(
    step: &Collocation<'_, M, N, S>,
    mass: &SMatrix<f64, N, N>,
    predictor: &[SVector<f64, N>; S],
) -> NewtonScale<[SVector<f64, N>; S]> {
    let weights = mass_weights(mass);
    let stages = [weights; S];
    NewtonScale {
        weights: stages,
        size: step
            .v0
            .weighted_norm(&weights)
            .max(predictor.weighted_norm(&stages)),
        resolution: position_floor(&weights, &step.q0, step.h),
    }
}

/// What every part of one step reads: the mechanism and the method, the step [t, t + h] from
/// (q₀, v₀) with p₀ = p(t, q₀, v₀), and whether the field carries constraint forces.
struct Collocation<'a, M, const N: usize, const S: usize> {
    mechanism: &'a M,
    tableau: &'a Tableau<S>,
    t: f64,
    h: f64,
    q0: SVector<f64, N>,
    v0: SVector<f64, N>,
    p0: SVector<f64, N>,
    constrained: bool,
}

impl<'a, M: Evaluate<N>, const N: usize, const S: usize> Collocation<'a, M, N, S> {
    /// The step from (t, q, v) over h; p₀ is the previous step's p₁ when it ended in this state.
    #[inline(always)]
    fn start(
        mechanism: &'a M,
        tableau: &'a Tableau<S>,
        previous: Option<&PreviousStep<N, S>>,
        (t, h): (f64, f64),
        (q, v): (&[f64; N], &[f64; N]),
    ) -> Self {
        let v0 = SVector::<f64, N>::from(*v);
        let q0 = SVector::<f64, N>::from(*q);
        let p0 = match previous {
            Some(prev) if prev.q1 == q0 && prev.v1 == v0 => prev.p1,
            _ => SVector::<f64, N>::from(mechanism.momenta_at(t, q, v)),
        };
        Collocation {
            mechanism,
            tableau,
            t,
            h,
            q0,
            v0,
            p0,
            // Whether the field carries constraint forces is the declaration's
            // (Dynamics::CONSTRAINTS): every stage includes Jᵀλ unless the mechanism declares no
            // rows, whatever λ is at the start of the step.
            constrained: carries_constraint_forces::<M, N>(),
        }
    }
}

/// One collocation step: the simplified Newton iteration with the memory's matrix (or a fresh one),
/// falling back to the exact Newton iteration when even a fresh simplified one does not contract.
/// A mechanism with quasi-velocities is stepped in its coordinates' rates ([`step_in_rates`]),
/// the memory's matrices and predictor with them.
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
    if M::QUASI_VELOCITIES {
        return step_in_rates(mechanism, (q, v), |in_rates, rates| {
            collocation_step_on(in_rates, tableau, memory, (t, q, rates), h, stats)
        });
    }
    collocation_step_on(mechanism, tableau, memory, (t, q, v), h, stats)
}

/// [`collocation_step`] on a mechanism whose velocities are the coordinates' rates.
#[allow(clippy::type_complexity)]
fn collocation_step_on<M: Evaluate<N>, const N: usize, const S: usize>(
    mechanism: &M,
    tableau: &Tableau<S>,
    memory: &mut NewtonMemory<N, S>,
    (t, q, v): (f64, &[f64; N], &[f64; N]),
    h: f64,
    stats: &mut Stats,
) -> Result<([f64; N], [f64; N], ImplicitStepStats)> {
    // The previous step of this solver, if it ended where this one starts.
    let previous = memory.previous.filter(|prev| prev.t_end == t);
    let step = Collocation::start(mechanism, tableau, previous.as_ref(), (t, h), (q, v));
    // The extrapolation from the last step (same h), and the stages predicted from it.
    let extrapolated = previous
        .filter(|prev| prev.h == h)
        .map(|prev| prev.extrapolate(&tableau.c, &(step.v0 - prev.v1)));
    let predictor = predicted_stages(&step, previous.as_ref(), extrapolated.as_ref(), stats)?;
    memory.previous = None;
    let mut counts = ImplicitStepStats::default();
    for attempt in 0..2 {
        // The matrix: the memory's if it is still good (refactorised for a new h), else fresh.
        let reuse = attempt == 0 && memory.matrix.is_some_and(|m| m.reusable);
        let mass = refreshed_mass(memory, previous.as_ref(), reuse);
        let jacobians = match memory.matrix {
            Some(m) if reuse => FieldJacobians {
                p_v: mass.unwrap_or(m.jacobians.p_v),
                ..m.jacobians
            },
            _ => fresh_jacobians(&step, stats, &mut counts)?,
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
                NewtonMatrix::fresh(jacobians, lu, h)
            }
        };
        let mut stages = predictor;
        let mut rates = [SVector::<f64, N>::zeros(); S];
        let mut last = [SVector::<f64, N>::zeros(); S];
        let iterate = [&mut stages, &mut rates, &mut last];
        let end = simplified_newton(&step, &matrix, iterate, stats, &mut counts);
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
        carry_rates_to_last_iterate(&step, &last, &mut rates, |_| &matrix.jacobians);
        let (q1, v1, p1, mass1, counts) = finish(&step, &stages, &rates, stats, counts)?;
        let end = (q1.into(), v1.into(), p1, mass1);
        memory.previous = Some(remembered(&step, stages, extrapolated.as_ref(), end));
        return Ok((q1, v1, counts));
    }
    exact_collocation(&step, predictor, stats, counts)
}

/// The stages' starting values: the previous step's collocation polynomial extrapolated to this
/// step, corrected by that step's own extrapolation error, when there is one (the solver's
/// memory); else Vᵢ = v₀ + cᵢ h q̈(t₀, q₀, v₀), O(h²) from the solution: one plain evaluation.
#[inline(always)]
fn predicted_stages<M: Evaluate<N>, const N: usize, const S: usize>(
    step: &Collocation<'_, M, N, S>,
    previous: Option<&PreviousStep<N, S>>,
    extrapolated: Option<&[SVector<f64, N>; S]>,
    stats: &mut Stats,
) -> Result<[SVector<f64, N>; S]> {
    Ok(match (previous, extrapolated) {
        (Some(prev), Some(x)) => std::array::from_fn(|i| x[i] + prev.extrapolation_error[i]),
        _ => {
            stats.evaluations += 1;
            let (q, v) = (step.q0.into(), step.v0.into());
            let a0 = SVector::<f64, N>::from(step.mechanism.accelerations_at(step.t, &q, &v)?);
            std::array::from_fn(|i| step.v0 + a0 * (step.tableau.c[i] * step.h))
        }
    })
}

/// ∂p/∂v for a kept matrix that contracted slower than MASS_REFRESH_THETA: M(q₀) where the last
/// step left it (the block that goes stale fastest: the others are scaled by h or h²).
#[inline(always)]
fn refreshed_mass<const N: usize, const S: usize>(
    memory: &NewtonMemory<N, S>,
    previous: Option<&PreviousStep<N, S>>,
    reuse: bool,
) -> Option<SMatrix<f64, N, N>> {
    previous
        .and_then(|prev| prev.mass1)
        .filter(|_| reuse && memory.matrix.is_some_and(|m| m.theta > MASS_REFRESH_THETA))
}

/// The field's Jacobians at the step's middle (t + h/2, q₀, v₀) for a fresh simplified matrix,
/// counted.
#[inline(always)]
fn fresh_jacobians<M: Evaluate<N>, const N: usize, const S: usize>(
    step: &Collocation<'_, M, N, S>,
    stats: &mut Stats,
    counts: &mut ImplicitStepStats,
) -> Result<FieldJacobians<N>> {
    stats.jacobians += 1;
    counts.jacobian_evaluations += 1;
    let (q, v) = (step.q0.into(), step.v0.into());
    let t = step.t + 0.5 * step.h;
    field_jacobians(step.mechanism, t, &q, &v, step.constrained)
}

/// The simplified Newton iteration from the predicted stages in `stages` with the factorised
/// matrix: Vᵢ ← Vᵢ − δᵢ, δ = LU⁻¹ r(V), counted, the increments weighted by the matrix's
/// ∂p/∂v = M ([`step_scale`]); ends with the stages, their ṗⱼ as last evaluated, and the last
/// increment δ.
#[inline(always)]
fn simplified_newton<M: Evaluate<N>, const N: usize, const S: usize>(
    step: &Collocation<'_, M, N, S>,
    matrix: &NewtonMatrix<N, S>,
    [stages, rates, last]: [&mut [SVector<f64, N>; S]; 3],
    stats: &mut Stats,
    counts: &mut ImplicitStepStats,
) -> Result<NewtonEnd> {
    let mut evaluations = 0;
    let before = stats.newton_iterations;
    let predictor = *stages;
    let scale = || step_scale(step, &matrix.jacobians.p_v, &predictor);
    let end = newton(
        stages,
        MAX_NEWTON_ITERATIONS,
        true,
        stats,
        scale,
        |stages| {
            let mut residual = [SVector::<f64, N>::zeros(); S];
            let norm = simplified_residual(step, stages, rates, &mut residual, &mut evaluations)?;
            *last = matrix.lu.solve(&residual);
            Ok((*last, norm))
        },
    );
    stats.evaluations += evaluations;
    counts.field_evaluations += evaluations;
    counts.iterations += stats.newton_iterations - before;
    end
}

/// The simplified iteration's right-hand side: the collocation residual at the stages (one field
/// evaluation per stage, ṗⱼ into `rates`) into `residual`, its max norm returned; a residual
/// that is not finite is a breakdown.
#[inline(always)]
fn simplified_residual<M: Evaluate<N>, const N: usize, const S: usize>(
    step: &Collocation<'_, M, N, S>,
    stages: &[SVector<f64, N>; S],
    rates: &mut [SVector<f64, N>; S],
    residual: &mut [SVector<f64, N>; S],
    evaluations: &mut usize,
) -> Result<f64> {
    let mut p = [SVector::<f64, N>::zeros(); S];
    for j in 0..S {
        let qj = stage_position(step.tableau, &step.q0, stages, step.h, j);
        let tj = step.t + step.tableau.c[j] * step.h;
        let (pj, rj) = canonical_field(
            step.mechanism,
            tj,
            &qj.into(),
            &stages[j].into(),
            step.constrained,
        )?;
        *evaluations += 1;
        p[j] = pj.into();
        rates[j] = rj.into();
    }
    let norm = collocation_residual(step, &p, rates, residual);
    if !norm.is_finite() {
        let iteration = *evaluations / S;
        return Err(breakdown(
            step.tableau.name,
            step.t,
            step.h,
            iteration,
            NOT_FINITE,
        ));
    }
    Ok(norm)
}

/// The collocation residual on the momenta, rᵢ = pᵢ − p₀ − h Σⱼ aᵢⱼ ṗⱼ, into `residual`; returns
/// maxᵢ ‖rᵢ‖∞.
#[inline(always)]
fn collocation_residual<M, const N: usize, const S: usize>(
    step: &Collocation<'_, M, N, S>,
    p: &[SVector<f64, N>; S],
    rates: &[SVector<f64, N>; S],
    residual: &mut [SVector<f64, N>; S],
) -> f64 {
    let mut norm = 0.0f64;
    for i in 0..S {
        let mut r = p[i] - step.p0;
        for j in 0..S {
            r -= rates[j] * (step.h * step.tableau.a[i][j]);
        }
        norm = norm.max(max_norm(&r));
        residual[i] = r;
    }
    norm
}

/// ṗⱼ carried from the last evaluation to the final iterate, ṗⱼ −= ∂ṗ/∂q ΔQⱼ + ∂ṗ/∂v ΔVⱼ with
/// ΔQⱼ = h Σₖ aⱼₖ ΔVₖ and stage j's Jacobians `jacobians(j)` (first order in the last increment,
/// which is at the round-off floor: no extra evaluation).
#[inline(always)]
fn carry_rates_to_last_iterate<'j, M, const N: usize, const S: usize>(
    step: &Collocation<'_, M, N, S>,
    last: &[SVector<f64, N>; S],
    rates: &mut [SVector<f64, N>; S],
    jacobians: impl Fn(usize) -> &'j FieldJacobians<N>,
) {
    for j in 0..S {
        let mut dq = SVector::<f64, N>::zeros();
        for k in 0..S {
            dq += last[k] * (step.h * step.tableau.a[j][k]);
        }
        let jj = jacobians(j);
        rates[j] -= jj.rate_q * dq + jj.rate_v * last[j];
    }
}

/// What the next step predicts its stages from: this step's stages, their error against the
/// extrapolation from the step before (zero without one), and its end (q₁, v₁, p₁, M(q₁)).
#[inline(always)]
#[allow(clippy::type_complexity)]
fn remembered<M, const N: usize, const S: usize>(
    step: &Collocation<'_, M, N, S>,
    stages: [SVector<f64, N>; S],
    extrapolated: Option<&[SVector<f64, N>; S]>,
    (q1, v1, p1, mass1): (
        SVector<f64, N>,
        SVector<f64, N>,
        SVector<f64, N>,
        Option<SMatrix<f64, N, N>>,
    ),
) -> PreviousStep<N, S> {
    PreviousStep {
        t_end: step.t + step.h,
        h: step.h,
        v0: step.v0,
        stages,
        extrapolation_error: match extrapolated {
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
fn finish<M: Evaluate<N>, const N: usize, const S: usize>(
    step: &Collocation<'_, M, N, S>,
    stages: &[SVector<f64, N>; S],
    rates: &[SVector<f64, N>; S],
    stats: &mut Stats,
    mut counts: ImplicitStepStats,
) -> Result<StepEnd<N>> {
    let (tableau, h, v0) = (step.tableau, step.h, &step.v0);
    let mut q1 = step.q0;
    let mut p1 = step.p0;
    let mut guess = *v0;
    for j in 0..S {
        q1 += stages[j] * (h * tableau.b[j]);
        p1 += rates[j] * (h * tableau.b[j]);
        guess += (stages[j] - v0) * tableau.d[j];
    }
    let (v1, velocity_iterations, mass1) = velocities_and_mass_from_momenta(
        step.mechanism,
        step.t + h,
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
fn exact_collocation<M: Evaluate<N>, const N: usize, const S: usize>(
    step: &Collocation<'_, M, N, S>,
    mut stages: [SVector<f64, N>; S],
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
    let (tableau, t, h) = (step.tableau, step.t, step.h);
    let mut iteration = 0;
    let before = stats.newton_iterations;
    // Weighted by the first iterate's M = ∂p/∂v at the first stage (see `NewtonScale`).
    let predictor = stages;
    let mass = std::cell::Cell::new(zero);
    let scale = || step_scale(step, &mass.get(), &predictor);
    let end = newton(
        &mut stages,
        MAX_NEWTON_ITERATIONS,
        false,
        stats,
        scale,
        |stages| {
            iteration += 1;
            for j in 0..S {
                let qj = stage_position(tableau, &step.q0, stages, h, j);
                let tj = t + tableau.c[j] * h;
                let vj = stages[j].into();
                field[j] = field_jacobians(step.mechanism, tj, &qj.into(), &vj, step.constrained)?;
                rates[j] = field[j].rate;
            }
            if iteration == 1 {
                mass.set(field[0].p_v);
            }
            let mut residual = [SVector::<f64, N>::zeros(); S];
            let norm = collocation_residual(step, &field.map(|f| f.p), &rates, &mut residual);
            if !norm.is_finite() {
                return Err(breakdown(tableau.name, t, h, iteration, NOT_FINITE));
            }
            let jacobian = exact_newton_matrix(tableau, h, &field);
            let Some(lu) = BlockLu::factor(&jacobian) else {
                return Err(not_factorised(step, iteration, &jacobian));
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
    carry_rates_to_last_iterate(step, &last, &mut rates, |j| &field[j]);
    finish(step, &stages, &rates, stats, counts).map(|(q1, v1, _, _, counts)| (q1, v1, counts))
}

/// The exact Newton matrix of the collocation residual, block (i, k) = ∂rᵢ/∂Vₖ =
/// h aᵢₖ ∂pᵢ/∂q + δᵢₖ ∂pᵢ/∂v − h² Σⱼ aᵢⱼ aⱼₖ ∂ṗⱼ/∂q − h aᵢₖ ∂ṗₖ/∂v, from each stage's Jacobians.
fn exact_newton_matrix<const N: usize, const S: usize>(
    tableau: &Tableau<S>,
    h: f64,
    field: &[FieldJacobians<N>; S],
) -> [[SMatrix<f64, N, N>; S]; S] {
    std::array::from_fn(|i| {
        std::array::from_fn(|k| {
            let mut block = field[i].p_q * (h * tableau.a[i][k]);
            if i == k {
                block += field[i].p_v;
            }
            for j in 0..S {
                block -= field[j].rate_q * (h * h * tableau.a[i][j] * tableau.a[j][k]);
            }
            block - field[k].rate_v * (h * tableau.a[i][k])
        })
    })
}

/// The breakdown of an exact Newton matrix that does not factorise: singular, or not finite.
fn not_factorised<M, const N: usize, const S: usize>(
    step: &Collocation<'_, M, N, S>,
    iteration: usize,
    jacobian: &[[SMatrix<f64, N, N>; S]; S],
) -> Error {
    let finite = jacobian
        .iter()
        .flatten()
        .all(|b| b.iter().all(|x| x.is_finite()));
    let reason = if finite {
        "the Newton matrix is singular"
    } else {
        "the Newton matrix is not finite (h is too large for this mechanism)"
    };
    breakdown(step.tableau.name, step.t, step.h, iteration, reason)
}
