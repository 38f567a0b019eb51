//! Implicit midpoint and the 2-stage Gauss–Legendre method: Gauss collocation methods (Hairer,
//! Nørsett & Wanner, *Solving ODEs I*, §II.7, Table 7.4; Hairer, Lubich & Wanner, *Geometric
//! Numerical Integration* (HLW), §II.1.3) on the canonical equations in y = (q, p), p = ∂L/∂q̇:
//!
//! ```text
//! q̇ = v(t, q, p),     ṗ = G(t, q, v) = ∂L/∂q + F_nc     (v(t, q, p) solves ∂L/∂q̇(t, q, v) = p),
//! ```
//!
//! with ∂L/∂q from a gradient dual pass of T over q at fixed v and the generalized forces of the
//! equations of motion (which contain −∇V and the non-conservative forces F_nc; see
//! [`momentum_rate`](super::momentum_rate)).
//!
//! **Stage equations.** With s stages, coefficients (aᵢⱼ, bᵢ, cᵢ), stage values (Qᵢ, Pᵢ) and the
//! stage velocities Vᵢ = v(tᵢ, Qᵢ, Pᵢ), the collocation equations Qᵢ = q₀ + h Σⱼ aᵢⱼ Vⱼ,
//! Pᵢ = p₀ + h Σⱼ aᵢⱼ G(tⱼ, Qⱼ, Vⱼ) are solved with the Vᵢ as the unknowns: Qᵢ is then explicit and
//! Pᵢ = ∂L/∂q̇(tᵢ, Qᵢ, Vᵢ), so no inverse Legendre transform is needed inside the iteration:
//!
//! ```text
//! Rᵢ(V) = p(tᵢ, Qᵢ, Vᵢ) − p₀ − h Σⱼ aᵢⱼ G(tⱼ, Qⱼ, Vⱼ) = 0,     Qᵢ = q₀ + h Σⱼ aᵢⱼ Vⱼ,
//! ∂Rᵢ/∂Vₖ = δᵢₖ ∂p/∂v|ᵢ + h aᵢₖ ∂p/∂q|ᵢ − h² Σⱼ aᵢⱼ aⱼₖ ∂G/∂q|ⱼ − h aᵢₖ ∂G/∂v|ₖ,
//! ```
//!
//! an (s·N)-dimensional system. It is solved by the **simplified Newton iteration** (Hairer & Wanner,
//! *Solving ODEs II*, §IV.8): the Jacobians ∂p/∂q, ∂p/∂v, ∂G/∂q, ∂G/∂v are evaluated once, exactly,
//! from gradient dual numbers (nested inside G, whose ∂T/∂q is itself a gradient) at one point
//! (t₀ + h/2, q₀, v₀) and used for every stage; the (s·N)-square matrix built from them is
//! LU-factorised once, and each iteration costs s plain evaluations of (p, ṗ) and one solve. In a
//! solver ([`FixedStepper`](super::FixedStepper), or [`GaussLegendre2::step_with_memory`]) the
//! Jacobian and its factorisation are kept for the next steps while the iteration contracts by at
//! least [`JACOBIAN_REUSE_THETA`] (θ = ‖δₖ‖/‖δₖ₋₁‖), and refreshed when it contracts slower or
//! not at all. Its block ∂p/∂v = M, the one not scaled by h, is taken anew, and the matrix
//! refactorised, whenever the last step contracted slower than θ = 10⁻³: from the mass matrix
//! the previous step's velocity recovery solved with (a scleronomic mechanism: M(q₀) at no extra
//! evaluation) — with a matrix kept over many steps M would be what makes θ large. The stages
//! start from the previous step's velocities,
//! extrapolated, plus that extrapolation's error on the previous step (see `PreviousStep`).
//! Without a previous step they start from Vᵢ = v₀ + cᵢ h q̈(t₀, q₀, v₀). The
//! iteration is run to round-off, as the methods' symmetry and symplecticity need; when even a
//! fresh matrix does not contract, the step falls back to Newton's method with exact Jacobians at
//! every iterate (quadratic convergence). Then q₁ = q₀ + h Σ bⱼ Vⱼ,
//! p₁ = p₀ + h Σ bⱼ G(tⱼ, Qⱼ, Vⱼ). This is exactly the Gauss method applied to the system in (q, p)
//! (given its stage values, Vᵢ := v(tᵢ, Qᵢ, Pᵢ) solves R = 0, and conversely).
//!
//! **State.** [`ImplicitMidpoint`] and [`GaussLegendre2`] implement [`Integrator`] on the (q, v)
//! [`State`] as the [`Variational`](super::Variational) integrator does: p₀ = ∂L/∂q̇(t₀, q₀, v₀)
//! before the step (in a solver, the previous step's p₁ when the state is exactly where that step
//! left it), and after it v₁ solves ∂L/∂q̇(t₁, q₁, v₁) = p₁ by Newton's method with the exact
//! Jacobian M (one iteration for a Lagrangian quadratic in q̇, v₁ = M⁻¹(p₁ − p(t₁, q₁, 0)); a second
//! confirms it). The Legendre transform is inverted to round-off, so the next step starts from this
//! step's p₁: the sequence of (q, p) is that of the Gauss method.
//!
//! **Geometric properties.** Gauss collocation methods are symplectic for Hamiltonian systems
//! (HLW Theorem VI.4.2, via the conservation of quadratic invariants, §IV.2.1) and symmetric. Applied
//! to the canonical equations, the step map (q₀, p₀) ↦ (q₁, p₁) is therefore symplectic for any
//! Lagrangian without non-conservative forces — also when the mass matrix depends on q (the double
//! pendulum), where the same method applied to (q, q̇) would not be (p = M(q) q̇ is then a nonlinear
//! change of variables, and Gauss methods are not invariant under those). Implicit midpoint on
//! (q, p) coincides with the midpoint [`Variational`](super::Variational) integrator (both are
//! p(t_m, Q, V) = p₀ + (h/2) G(t_m, Q, V), q₁ = q₀ + hV, p₁ = p₀ + h G with Q = q₀ + (h/2) V),
//! including its treatment of forcing, the midpoint quadrature of the discrete Lagrange–d'Alembert
//! principle (Marsden & West, *Discrete mechanics and variational integrators*, Acta Numerica 10
//! (2001), §3.2). Both methods are A-stable and conserve every quadratic invariant of the system in
//! (q, p) (HLW §IV.2.1), e.g. angular momentum.
//!
//! **Constraints.** As every integrator, a step first checks that the state satisfies the
//! mechanism's constraints (`Dynamics::check_constraints`) and ends by projecting onto them
//! (`Dynamics::project`; a no-op without constraints). Unless the mechanism declares no
//! constraint rows (`Dynamics::CONSTRAINTS` = `Some(0)`), G includes the generalized constraint
//! force Jᵀλ = M q̈ − (𝓕 − b), with q̈ the constrained accelerations, at every stage — a constant
//! of the mechanism, never a test of λ, so also where λ vanishes at the start of the step (a
//! pendulum released horizontally at rest). Projection is not symplectic: on a constrained
//! mechanism these methods are projection methods (HLW §IV.4), symmetric only up to it.
//!
//! A Newton iteration that does not converge in [`MAX_NEWTON_ITERATIONS`] is
//! [`Error::NewtonDiverged`]; the caller's state is unchanged on every error.

// `!(a <= b)` comparisons are deliberate (they also catch NaN); stage loops index several arrays.
#![allow(clippy::neg_cmp_op_on_partial_ord, clippy::needless_range_loop)]

use super::canonical::{
    canonical_field, field_jacobians, velocities_and_mass_from_momenta, FieldJacobians,
};
use super::newton::{
    carries_constraint_forces, max_norm, newton, BlockLu, NewtonEnd, MAX_NEWTON_ITERATIONS,
};
use super::solver::validated_step;
use super::{Integrator, Stats};
use crate::error::{Error, Result};
use crate::mechanism::Mechanism;
use crate::model::State;
use nalgebra::{SMatrix, SVector};

/// An s-stage Gauss collocation tableau with d = bᵀA⁻¹.
struct Tableau<const S: usize> {
    /// The method's name, for errors.
    name: &'static str,
    a: [[f64; S]; S],
    b: [f64; S],
    c: [f64; S],
    d: [f64; S],
}

/// Implicit midpoint: a = ½, b = 1, c = ½ (the 1-stage Gauss method), so d = 2.
const MIDPOINT: Tableau<1> = Tableau {
    name: "implicit midpoint",
    a: [[0.5]],
    b: [1.0],
    c: [0.5],
    d: [2.0],
};

/// √3/6.
const R36: f64 = 0.288_675_134_594_812_9;
/// √3.
const R3: f64 = 1.732_050_807_568_877_2;

/// 2-stage Gauss–Legendre (HNW I, Table 7.4): c = ½ ∓ √3/6, A = [[¼, ¼ − √3/6], [¼ + √3/6, ¼]],
/// b = (½, ½). A⁻¹ = [[3, 2√3 − 3], [−2√3 − 3, 3]] (det A = 1/12), so d = bᵀA⁻¹ = (−√3, √3).
const GAUSS2: Tableau<2> = Tableau {
    name: "Gauss-Legendre 2",
    a: [[0.25, 0.25 - R36], [0.25 + R36, 0.25]],
    b: [0.5, 0.5],
    c: [0.5 - R36, 0.5 + R36],
    d: [-R3, R3],
};

/// What an implicit step cost.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ImplicitStepStats {
    /// Newton iterations of the collocation equations.
    pub iterations: usize,
    /// Evaluations of the canonical vector field (p, ṗ) with their Jacobians (each is two passes
    /// with gradient dual numbers, nested inside ṗ): one per stage for a fresh simplified-Newton
    /// matrix, or one per stage and iteration in the exact Newton fallback.
    pub jacobian_evaluations: usize,
    /// Plain evaluations of the canonical vector field (p, ṗ) (one per stage and simplified-Newton
    /// iteration).
    pub field_evaluations: usize,
    /// LU factorisations of the (S·N)-square Newton matrix.
    pub factorizations: usize,
    /// Newton iterations of the velocity recovery ∂L/∂v(t₁, q₁, v₁) = p₁ (each one dual pass of the
    /// momenta).
    pub velocity_iterations: usize,
}

/// The contraction factor θ of a simplified Newton iteration above which the next step
/// recomputes the Jacobian instead of reusing it (Hairer & Wanner, *Solving ODEs II*, §IV.8: the
/// Jacobian is kept while convergence is fast; a refreshed Jacobian costs S dual evaluations of
/// the field, about as much as two or three plain iterations, which a θ below 0.1 does not save).
pub const JACOBIAN_REUSE_THETA: f64 = 0.1;

/// The contraction factor θ of a kept simplified Newton matrix above which the next step takes its
/// ∂p/∂v block anew (M where the step starts) and refactorises it. With the corrected predictor
/// the first increment is ~10⁻¹⁰ of the velocities at h = 10⁻³, and the iteration stops after the
/// second when θ²·10⁻¹⁰ ≲ 4ε, θ ≲ 3·10⁻³; below 10⁻³ a refactorisation would not save an
/// iteration.
const MASS_REFRESH_THETA: f64 = 1e-3;

/// The reused part of a simplified Newton iteration: the field's Jacobians at a reference point
/// and the factorised Newton matrix built from them for one step size.
#[derive(Clone, Copy, Debug)]
struct NewtonMatrix<const N: usize, const S: usize> {
    jacobians: FieldJacobians<N>,
    lu: BlockLu<N, S>,
    h: f64,
    /// Whether the last step converged fast enough to keep the Jacobian.
    reusable: bool,
    /// The last step's contraction factor θ.
    theta: f64,
}

/// Working memory of [`ImplicitMidpoint`] (S = 1) and [`GaussLegendre2`] (S = 2) in a solver
/// ([`FixedStepper`](super::FixedStepper)): the Jacobian and the factorised Newton matrix of the
/// simplified Newton iteration, kept from step to step while the iteration contracts by at least
/// [`JACOBIAN_REUSE_THETA`] per iteration (refactorised with a new h, or with the mass matrix at
/// the step's start), and the last step's end, stages and momenta.
#[derive(Clone, Copy, Debug)]
pub struct NewtonMemory<const N: usize, const S: usize> {
    matrix: Option<NewtonMatrix<N, S>>,
    previous: Option<PreviousStep<N, S>>,
}

impl<const N: usize, const S: usize> Default for NewtonMemory<N, S> {
    fn default() -> Self {
        NewtonMemory {
            matrix: None,
            previous: None,
        }
    }
}

/// The last step's end and velocities, from which the next step's stages are predicted.
#[derive(Clone, Copy, Debug)]
struct PreviousStep<const N: usize, const S: usize> {
    t_end: f64,
    h: f64,
    v0: SVector<f64, N>,
    stages: [SVector<f64, N>; S],
    /// The stages minus their extrapolation from the step before (zero without one). With h
    /// fixed, the extrapolation error is a smooth function of the state, O(h^(S+1)), that changes
    /// by O(h) of itself from one step to the next: added to the next extrapolation, it leaves a
    /// predictor O(h^(S+2)) from the stages (on the double pendulum at h = 10⁻³, Gauss–Legendre 2's
    /// first Newton increment drops from 4·10⁻⁸ to ~10⁻¹⁰).
    extrapolation_error: [SVector<f64, N>; S],
    /// The end state (q₁, v₁, p₁) before any projection: when the next step starts from exactly
    /// (q₁, v₁), its p₀ is p₁, the Gauss method's own sequence on (q, p), not re-evaluated.
    q1: SVector<f64, N>,
    v1: SVector<f64, N>,
    p1: SVector<f64, N>,
    /// M(q₁), which the velocity recovery solved with (a scleronomic mechanism): the next step's
    /// Newton matrix takes it as its ∂p/∂v block.
    mass1: Option<SMatrix<f64, N, N>>,
}

/// What [`finish`] gives: q₁, v₁, p₁, M(q₁) if the velocity recovery solved with it, and the
/// step's cost.
type StepEnd<const N: usize> = (
    [f64; N],
    [f64; N],
    SVector<f64, N>,
    Option<SMatrix<f64, N, N>>,
    ImplicitStepStats,
);

impl<const N: usize, const S: usize> PreviousStep<N, S> {
    /// The next step's stage velocities, extrapolated by the polynomial of degree S + 1 through the
    /// last step's velocities v₀, Vᵢ (at cᵢ) and v₁ (at 1) to 1 + cⱼ (Hairer & Wanner, *Solving
    /// ODEs II*, §IV.8, "starting values"): O(h^(S+1)) from the solution (the stage order), where
    /// v₀ + cⱼ h q̈₀ is O(h²). `shift` moves it by the projection's change of v₁.
    fn extrapolate(&self, c: &[f64; S], shift: &SVector<f64, N>) -> [SVector<f64, N>; S] {
        // Nodes 0, c₁…c_S, 1 and their values; Lagrange weights at x.
        let node = |k: usize| match k {
            0 => 0.0,
            k if k <= S => c[k - 1],
            _ => 1.0,
        };
        let value = |k: usize| match k {
            0 => self.v0,
            k if k <= S => self.stages[k - 1],
            _ => self.v1,
        };
        std::array::from_fn(|j| {
            let x = 1.0 + c[j];
            let mut sum = *shift;
            for k in 0..S + 2 {
                let mut w = 1.0;
                for l in 0..S + 2 {
                    if l != k {
                        w *= (x - node(l)) / (node(k) - node(l));
                    }
                }
                sum += value(k) * w;
            }
            sum
        })
    }
}

/// The simplified Newton matrix of the collocation equations with every stage's Jacobians replaced
/// by one reference point's `j`: blocks δᵢₖ ∂p/∂v + h aᵢₖ ∂p/∂q − h² (A²)ᵢₖ ∂ṗ/∂q − h aᵢₖ ∂ṗ/∂v
/// (Hairer & Wanner, *Solving ODEs II*, §IV.8, (8.4), for these unknowns).
fn simplified_matrix<const N: usize, const S: usize>(
    tableau: &Tableau<S>,
    j: &FieldJacobians<N>,
    h: f64,
) -> [[SMatrix<f64, N, N>; S]; S] {
    std::array::from_fn(|i| {
        std::array::from_fn(|k| {
            let a2: f64 = (0..S).map(|l| tableau.a[i][l] * tableau.a[l][k]).sum();
            let mut block = j.p_q * (h * tableau.a[i][k])
                - j.rate_q * (h * h * a2)
                - j.rate_v * (h * tableau.a[i][k]);
            if i == k {
                block += j.p_v;
            }
            block
        })
    })
}

fn breakdown(tableau_name: &'static str, t: f64, h: f64, iteration: usize, reason: &str) -> Error {
    Error::NewtonBreakdown {
        method: tableau_name,
        t,
        h,
        iteration,
        reason: reason.to_string(),
    }
}

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

/// One collocation step: the simplified Newton iteration with the memory's matrix (or a fresh one),
/// falling back to the exact Newton iteration when even a fresh simplified one does not contract.
#[allow(clippy::too_many_arguments, clippy::type_complexity)]
fn collocation_step<M: Mechanism<N>, const N: usize, const S: usize>(
    mechanism: &M,
    tableau: &Tableau<S>,
    memory: &mut NewtonMemory<N, S>,
    t: f64,
    q: &[f64; N],
    v: &[f64; N],
    h: f64,
    stats: &mut Stats,
) -> Result<([f64; N], [f64; N], ImplicitStepStats)> {
    super::newton::refuse_contacts::<M, N>(tableau.name, super::newton::CONTACT_METHODS)?;
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
        let end = newton(&mut stages, MAX_NEWTON_ITERATIONS, true, stats, |stages| {
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
        });
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
fn finish<M: Mechanism<N>, const N: usize, const S: usize>(
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
fn exact_collocation<M: Mechanism<N>, const N: usize, const S: usize>(
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
    let end = newton(&mut stages, MAX_NEWTON_ITERATIONS, false, stats, |stages| {
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
    });
    let n = stats.newton_iterations - before;
    stats.jacobians += S * iteration;
    stats.factorizations += n;
    counts.iterations += n;
    counts.jacobian_evaluations += S * iteration;
    counts.factorizations += n;
    match end? {
        NewtonEnd::Converged { .. } => {
            // ṗⱼ carried to the final iterate by its own Jacobians (first order in the last
            // increment, which is at the round-off floor: no extra evaluation).
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
        NewtonEnd::Slow {
            iterations,
            residual,
        } => Err(Error::NewtonDiverged {
            t,
            iterations,
            residual,
        }),
    }
}

/// The implicit midpoint rule y₁ = y₀ + h f(t₀ + h/2, (y₀ + y₁)/2) on y = (q, p): order 2,
/// symmetric, A-stable, symplectic for any Lagrangian, conserves quadratic invariants (see the
/// [module docs](self)). Per step: N unknowns, a simplified Newton iteration with one plain
/// evaluation of (p, ṗ) per iteration.
///
/// On a declaration with `#[unilateral]` or `#[friction]` rows, whose contact mode switches
/// inside a step, a single `sys.step::<ImplicitMidpoint>` holds the mode of the step's start and
/// locates its switches (one step of `ContactRk4::step_with`, below); its solver
/// ([`FixedStepper`](super::FixedStepper), which keeps the Newton matrix between steps) refuses
/// such a declaration up front ([`Error::UnsuitableMethod`], the state unchanged). Such a
/// declaration is integrated with the mode held per step and its switches located by
/// [`ContactRk4::step_with::<ImplicitMidpoint, …>`](crate::ContactRk4::step_with) (this method in
/// the contact stepper's event loop: a step cut at an event and the rest taken as a shorter step),
/// by [`ContactRk4`](crate::ContactRk4) with RK4, and by the adaptive [`Dopri5`](super::Dopri5),
/// [`Dop853`](super::Dop853) and [`Radau5`](super::Radau5) (their `integrate` takes
/// [`ContactAdaptive`](crate::constraints::ContactAdaptive)).
///
/// ```
/// use lagrange_core::{ImplicitMidpoint, Mechanism, State};
/// # use lagrange_core::{vec2, Model, Scalar};
/// # struct Pendulum;
/// # impl Model<1, 2> for Pendulum {
/// #     type Coords = [f64; 1];
/// #     const RHEONOMIC: bool = false;
/// #     const HAS_POTENTIAL: bool = true;
/// #     const HAS_FORCES: bool = false;
/// #     fn validate(&self) -> lagrange_core::Result<()> { Ok(()) }
/// #     fn masses(&self) -> [f64; 2] { [1.0, 1.0] }
/// #     fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 1]) -> [D; 2] {
/// #         vec2(q[0].sin(), -q[0].cos()).to_array()
/// #     }
/// #     fn potential<D: Scalar>(&self, _t: D, _q: &[D; 1], x: &[D; 2]) -> D { x[1] * 9.81 }
/// # }
/// # lagrange_core::impl_mechanism!(Pendulum, 1, 2);
/// let mut s = State::new(0.0, [0.5], [0.0]);
/// let e0 = Pendulum.energy(&s)?;
/// let mut worst = 0.0f64;
/// for _ in 0..10_000 {
///     Pendulum.step::<ImplicitMidpoint>(&mut s, 1e-2)?;
///     worst = worst.max((Pendulum.energy(&s)? - e0).abs());
/// }
/// // Symplectic, order 2: the energy error oscillates, O(h²ω²E) ≈ 1e-3·E = 4e-3, without drift.
/// assert!(worst < 1e-2);
/// # Ok::<(), lagrange_core::Error>(())
/// ```
#[derive(Clone, Copy, Debug, Default)]
pub struct ImplicitMidpoint;

/// The 2-stage Gauss–Legendre method on y = (q, p): order 4, symmetric, A-stable, symplectic for
/// any Lagrangian, conserves quadratic invariants (see the [module docs](self)). Per step: 2N
/// unknowns, a simplified Newton iteration with two plain evaluations of (p, ṗ) per iteration.
///
/// On a declaration with `#[unilateral]` or `#[friction]` rows a single `sys.step` holds the
/// contact mode over the step and its solver refuses the declaration, as for [`ImplicitMidpoint`];
/// [`ContactRk4::step_with::<GaussLegendre2, …>`](crate::ContactRk4::step_with) integrates them
/// (see [`ImplicitMidpoint`] for the other methods that do).
///
/// ```
/// use lagrange_core::{GaussLegendre2, Mechanism, State};
/// # use lagrange_core::{vec2, Model, Scalar};
/// # struct Pendulum;
/// # impl Model<1, 2> for Pendulum {
/// #     type Coords = [f64; 1];
/// #     const RHEONOMIC: bool = false;
/// #     const HAS_POTENTIAL: bool = true;
/// #     const HAS_FORCES: bool = false;
/// #     fn validate(&self) -> lagrange_core::Result<()> { Ok(()) }
/// #     fn masses(&self) -> [f64; 2] { [1.0, 1.0] }
/// #     fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 1]) -> [D; 2] {
/// #         vec2(q[0].sin(), -q[0].cos()).to_array()
/// #     }
/// #     fn potential<D: Scalar>(&self, _t: D, _q: &[D; 1], x: &[D; 2]) -> D { x[1] * 9.81 }
/// # }
/// # lagrange_core::impl_mechanism!(Pendulum, 1, 2);
/// let mut s = State::new(0.0, [0.5], [0.0]);
/// let e0 = Pendulum.energy(&s)?;
/// let mut worst = 0.0f64;
/// for _ in 0..10_000 {
///     Pendulum.step::<GaussLegendre2>(&mut s, 1e-2)?;
///     worst = worst.max((Pendulum.energy(&s)? - e0).abs());
/// }
/// // Symplectic, order 4: the energy error oscillates, O((hω)⁴E) ≈ 1e-6·E, without drift.
/// assert!(worst < 1e-5);
/// # Ok::<(), lagrange_core::Error>(())
/// ```
#[derive(Clone, Copy, Debug, Default)]
pub struct GaussLegendre2;

macro_rules! collocation_method {
    ($ty:ident, $tableau:ident, $stages:literal) => {
        impl $ty {
            /// One step on raw (q, v) arrays through the Legendre transform at both ends, with
            /// fresh working memory, no validation: (q₁, v₁) and the Newton cost.
            #[allow(clippy::type_complexity)]
            pub fn step_arrays<M: Mechanism<N>, const N: usize>(
                mechanism: &M,
                t: f64,
                q: &[f64; N],
                v: &[f64; N],
                h: f64,
            ) -> Result<([f64; N], [f64; N], ImplicitStepStats)> {
                let mut memory = NewtonMemory::default();
                collocation_step(
                    mechanism,
                    &$tableau,
                    &mut memory,
                    t,
                    q,
                    v,
                    h,
                    &mut Stats::default(),
                )
            }

            /// A validated step with fresh working memory that also reports its Newton cost; the
            /// state is unchanged on error.
            pub fn step_with_stats<M: Mechanism<N>, const N: usize>(
                mechanism: &M,
                state: &mut State<M::Coords>,
                h: f64,
            ) -> Result<ImplicitStepStats> {
                Self::step_with_memory(mechanism, &mut NewtonMemory::default(), state, h)
            }

            /// A validated step with the working memory of the previous ones (the Newton matrix
            /// is reused while it contracts well), reporting its Newton cost; the state is
            /// unchanged on error.
            pub fn step_with_memory<M: Mechanism<N>, const N: usize>(
                mechanism: &M,
                memory: &mut NewtonMemory<N, $stages>,
                state: &mut State<M::Coords>,
                h: f64,
            ) -> Result<ImplicitStepStats> {
                let mut counts = ImplicitStepStats::default();
                let mut stats = Stats::default();
                validated_step(mechanism, state, h, |t, q, v| {
                    let (q1, v1, c) =
                        collocation_step(mechanism, &$tableau, memory, t, q, v, h, &mut stats)?;
                    counts = c;
                    Ok((q1, v1))
                })?;
                Ok(counts)
            }
        }

        impl Integrator for $ty {
            const NAME: &'static str = $tableau.name;
            type Memory<const N: usize> = NewtonMemory<N, $stages>;
            const HOLDS_CONTACT_MODE: bool = true;

            fn advance<M: Mechanism<N>, const N: usize>(
                mechanism: &M,
                memory: &mut NewtonMemory<N, $stages>,
                t: f64,
                q: &[f64; N],
                v: &[f64; N],
                h: f64,
                stats: &mut Stats,
            ) -> Result<([f64; N], [f64; N])> {
                collocation_step(mechanism, &$tableau, memory, t, q, v, h, stats)
                    .map(|(q1, v1, _)| (q1, v1))
            }
        }
    };
}

collocation_method!(ImplicitMidpoint, MIDPOINT, 1);
collocation_method!(GaussLegendre2, GAUSS2, 2);

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gauss_tableau_is_consistent() {
        // Row sums equal c (HNW I (7.2)); d·(1, 1) = bᵀA⁻¹·𝟙 = 1/c-weighted identity check:
        // d = bᵀA⁻¹ ⇔ dᵀA = bᵀ.
        for i in 0..2 {
            assert!((GAUSS2.a[i][0] + GAUSS2.a[i][1] - GAUSS2.c[i]).abs() < 1e-15);
            let da = GAUSS2.d[0] * GAUSS2.a[0][i] + GAUSS2.d[1] * GAUSS2.a[1][i];
            assert!((da - GAUSS2.b[i]).abs() < 1e-15);
        }
        assert!((R36 - 3f64.sqrt() / 6.0).abs() < 1e-16 && (R3 - 3f64.sqrt()).abs() < 1e-15);
    }
}
