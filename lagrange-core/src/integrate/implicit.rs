//! Implicit midpoint and the 2-stage Gauss–Legendre method: Gauss collocation methods (Hairer,
//! Nørsett & Wanner, *Solving ODEs I*, §II.7, Table 7.4; Hairer, Lubich & Wanner, *Geometric
//! Numerical Integration*, §II.1.3) on the first-order system y = (q, v), y' = (v, q̈(t, q, v)).
//!
//! With s stages, coefficients (aᵢⱼ, bᵢ, cᵢ) and stage velocities Vᵢ as the unknowns (the stage
//! positions are eliminated: Qᵢ = q₀ + h Σⱼ aᵢⱼ Vⱼ), the stage equations are
//!
//! ```text
//! Rᵢ(V) = Vᵢ − v₀ − h Σⱼ aᵢⱼ q̈(t₀ + cⱼh, Qⱼ, Vⱼ) = 0,
//! ∂Rᵢ/∂Vₖ = δᵢₖ I − h² Σⱼ aᵢⱼ aⱼₖ ∂q̈/∂q|ⱼ − h aᵢₖ ∂q̈/∂v|ₖ,
//! ```
//!
//! an (s·N)-dimensional system solved by Newton's method with the exact Jacobians ∂q̈/∂q, ∂q̈/∂v from
//! gradient dual numbers (re-evaluated at every iterate), starting from the predictor
//! Vᵢ = v₀ + cᵢ h q̈(t₀, q₀, v₀). Then q₁ = q₀ + h Σ bⱼ Vⱼ and, since h Σⱼ aᵢⱼ q̈ⱼ = Vᵢ − v₀ at the solution, v₁ = v₀ + Σᵢ dᵢ (Vᵢ − v₀)
//! with dᵀ = bᵀA⁻¹ (no extra evaluation).
//!
//! **Geometric properties.** Both methods are symmetric (time-reversible) and conserve every
//! quadratic invariant of y' = f(y) (HLW §IV.2.1). They are symplectic for the canonical
//! variables (q, p); applied to (q, v) they are symplectic exactly when p = M v is a linear change of
//! variables, i.e. the mass matrix is constant (Cartesian particles, the stiff spring chain, Kepler).
//! For a mass matrix that depends on q they remain symmetric but not symplectic: the
//! [`Variational`](super::Variational) integrator is symplectic for any Lagrangian.
//!
//! **Constraints.** As every integrator, a step first checks that the state satisfies the
//! mechanism's constraints ([`Mechanism::check_constraints`]) and ends by projecting onto them
//! ([`Mechanism::project`]; a no-op without constraints). Projection is not symplectic: on a
//! constrained mechanism these methods are projection methods (HLW §IV.4), symmetric only up to it.
//!
//! A Newton iteration that does not converge in [`MAX_NEWTON_ITERATIONS`] is
//! [`Error::NewtonDiverged`]; the caller's state is unchanged on every error.

// `!(a <= b)` comparisons are deliberate (they also catch NaN); stage loops index several arrays.
#![allow(clippy::neg_cmp_op_on_partial_ord, clippy::needless_range_loop)]

use super::newton::{acceleration_jacobians, max_norm, Convergence, MAX_NEWTON_ITERATIONS};
use super::Integrator;
use crate::error::{Error, Result};
use crate::linalg::lu_solve_blocks;
use crate::mechanism::{check_step, Mechanism};
use crate::model::{check_state, Coordinates, State};
use nalgebra::{SMatrix, SVector};

/// An s-stage Gauss collocation tableau with d = bᵀA⁻¹.
struct Tableau<const S: usize> {
    a: [[f64; S]; S],
    b: [f64; S],
    c: [f64; S],
    d: [f64; S],
}

/// Implicit midpoint: a = ½, b = 1, c = ½ (the 1-stage Gauss method), so d = 2.
const MIDPOINT: Tableau<1> = Tableau {
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
    a: [[0.25, 0.25 - R36], [0.25 + R36, 0.25]],
    b: [0.5, 0.5],
    c: [0.5 - R36, 0.5 + R36],
    d: [-R3, R3],
};

/// What an implicit step cost.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ImplicitStepStats {
    /// Newton iterations.
    pub iterations: usize,
    /// Evaluations of the accelerations with their Jacobians (each is two dual-number passes).
    pub jacobian_evaluations: usize,
}

#[allow(clippy::type_complexity)]
fn collocation_step<M: Mechanism<N>, const N: usize, const S: usize>(
    mechanism: &M,
    tableau: &Tableau<S>,
    t: f64,
    q: &[f64; N],
    v: &[f64; N],
    h: f64,
) -> Result<([f64; N], [f64; N], ImplicitStepStats)> {
    let v0 = SVector::<f64, N>::from(*v);
    let q0 = SVector::<f64, N>::from(*q);
    // Predictor Vᵢ = v₀ + cᵢ h q̈(t₀, q₀, v₀), O(h²) from the solution: one plain evaluation that
    // saves about one Newton iteration (each costing S evaluations with Jacobians).
    let a0 = SVector::<f64, N>::from(mechanism.accelerations_at(t, q, v)?);
    let stages_init: [SVector<f64, N>; S] = std::array::from_fn(|i| v0 + a0 * (tableau.c[i] * h));
    let mut stages = stages_init;
    let mut conv = Convergence::new();
    let mut stats = ImplicitStepStats::default();
    let mut residual_norm = f64::NAN;
    for _ in 0..MAX_NEWTON_ITERATIONS {
        stats.iterations += 1;
        let mut acc = [SVector::<f64, N>::zeros(); S];
        let mut jq = [SMatrix::<f64, N, N>::zeros(); S];
        let mut jv = [SMatrix::<f64, N, N>::zeros(); S];
        for j in 0..S {
            let mut qj = q0;
            for k in 0..S {
                qj += stages[k] * (h * tableau.a[j][k]);
            }
            let (a, aq, av) = acceleration_jacobians(
                mechanism,
                t + tableau.c[j] * h,
                &qj.into(),
                &stages[j].into(),
            )?;
            stats.jacobian_evaluations += 1;
            acc[j] = a.into();
            jq[j] = aq;
            jv[j] = av;
        }
        let mut residual = [SVector::<f64, N>::zeros(); S];
        let mut jac = [[SMatrix::<f64, N, N>::zeros(); S]; S];
        residual_norm = 0.0;
        for i in 0..S {
            let mut r = stages[i] - v0;
            for j in 0..S {
                r -= acc[j] * (h * tableau.a[i][j]);
            }
            residual_norm = residual_norm.max(max_norm(&r));
            residual[i] = r;
            for k in 0..S {
                let mut block = if i == k {
                    SMatrix::identity()
                } else {
                    SMatrix::zeros()
                };
                for j in 0..S {
                    block -= jq[j] * (h * h * tableau.a[i][j] * tableau.a[j][k]);
                }
                block -= jv[k] * (h * tableau.a[i][k]);
                jac[i][k] = block;
            }
        }
        if !residual_norm.is_finite() {
            break;
        }
        let Some(delta) = lu_solve_blocks(&jac, &residual) else {
            break;
        };
        let mut increment = 0.0f64;
        let mut scale = 0.0f64;
        for i in 0..S {
            stages[i] -= delta[i];
            increment = increment.max(max_norm(&delta[i]));
            scale = scale.max(max_norm(&stages[i]));
        }
        if conv.converged(increment, scale) {
            let mut q1 = q0;
            let mut v1 = v0;
            for i in 0..S {
                q1 += stages[i] * (h * tableau.b[i]);
                v1 += (stages[i] - v0) * tableau.d[i];
            }
            return Ok((q1.into(), v1.into(), stats));
        }
    }
    Err(Error::NewtonDiverged {
        t,
        iterations: stats.iterations,
        residual: residual_norm,
    })
}

fn step_state<M: Mechanism<N>, const N: usize, const S: usize>(
    mechanism: &M,
    tableau: &Tableau<S>,
    state: &mut State<M::Coords>,
    h: f64,
) -> Result<ImplicitStepStats> {
    check_step(h)?;
    let (q, v) = mechanism.check(state)?;
    mechanism.check_constraints(state.t, &q, &v)?;
    let (mut q1, mut v1, stats) = collocation_step(mechanism, tableau, state.t, &q, &v, h)?;
    mechanism.project(state.t + h, &mut q1, &mut v1)?;
    check_state(&M::Coords::NAMES, state.t + h, &q1, &v1)?;
    state.t += h;
    state.q = M::Coords::from_array(q1);
    state.v = M::Coords::from_array(v1);
    Ok(stats)
}

/// The implicit midpoint rule y₁ = y₀ + h f(t₀ + h/2, (y₀ + y₁)/2): order 2, symmetric, A-stable,
/// conserves quadratic invariants (see the [module docs](self) for when it is symplectic).
/// Per step: N unknowns, each Newton iteration one evaluation of q̈ with its Jacobians.
#[derive(Clone, Copy, Debug, Default)]
pub struct ImplicitMidpoint;

impl ImplicitMidpoint {
    /// One step on raw arrays, no validation: (q₁, v₁) and the Newton cost.
    #[allow(clippy::type_complexity)]
    pub fn step_arrays<M: Mechanism<N>, const N: usize>(
        mechanism: &M,
        t: f64,
        q: &[f64; N],
        v: &[f64; N],
        h: f64,
    ) -> Result<([f64; N], [f64; N], ImplicitStepStats)> {
        collocation_step(mechanism, &MIDPOINT, t, q, v, h)
    }

    /// A validated step that also reports its Newton cost; the state is unchanged on error.
    pub fn step_with_stats<M: Mechanism<N>, const N: usize>(
        mechanism: &M,
        state: &mut State<M::Coords>,
        h: f64,
    ) -> Result<ImplicitStepStats> {
        step_state(mechanism, &MIDPOINT, state, h)
    }
}

impl Integrator for ImplicitMidpoint {
    const NAME: &'static str = "implicit midpoint";

    fn step<M: Mechanism<N>, const N: usize>(
        mechanism: &M,
        state: &mut State<M::Coords>,
        h: f64,
    ) -> Result<()> {
        step_state(mechanism, &MIDPOINT, state, h).map(|_| ())
    }
}

/// The 2-stage Gauss–Legendre method: order 4, symmetric, A-stable, conserves quadratic invariants
/// (see the [module docs](self) for when it is symplectic). Per step: 2N unknowns, each Newton
/// iteration two evaluations of q̈ with their Jacobians.
#[derive(Clone, Copy, Debug, Default)]
pub struct GaussLegendre2;

impl GaussLegendre2 {
    /// One step on raw arrays, no validation: (q₁, v₁) and the Newton cost.
    #[allow(clippy::type_complexity)]
    pub fn step_arrays<M: Mechanism<N>, const N: usize>(
        mechanism: &M,
        t: f64,
        q: &[f64; N],
        v: &[f64; N],
        h: f64,
    ) -> Result<([f64; N], [f64; N], ImplicitStepStats)> {
        collocation_step(mechanism, &GAUSS2, t, q, v, h)
    }

    /// A validated step that also reports its Newton cost; the state is unchanged on error.
    pub fn step_with_stats<M: Mechanism<N>, const N: usize>(
        mechanism: &M,
        state: &mut State<M::Coords>,
        h: f64,
    ) -> Result<ImplicitStepStats> {
        step_state(mechanism, &GAUSS2, state, h)
    }
}

impl Integrator for GaussLegendre2 {
    const NAME: &'static str = "Gauss-Legendre 2";

    fn step<M: Mechanism<N>, const N: usize>(
        mechanism: &M,
        state: &mut State<M::Coords>,
        h: f64,
    ) -> Result<()> {
        step_state(mechanism, &GAUSS2, state, h).map(|_| ())
    }
}

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
