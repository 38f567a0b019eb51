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
//! an (s·N)-dimensional system solved by Newton's method with exact Jacobians from gradient dual
//! numbers (nested inside G, whose ∂T/∂q is itself a gradient; re-evaluated at every iterate),
//! starting from the predictor Vᵢ = v₀ + cᵢ h q̈(t₀, q₀, v₀). Then q₁ = q₀ + h Σ bⱼ Vⱼ,
//! p₁ = p₀ + h Σ bⱼ G(tⱼ, Qⱼ, Vⱼ). This is exactly the Gauss method applied to the system in (q, p)
//! (given its stage values, Vᵢ := v(tᵢ, Qᵢ, Pᵢ) solves R = 0, and conversely).
//!
//! **State.** [`ImplicitMidpoint`] and [`GaussLegendre2`] implement [`Integrator`] on the (q, v)
//! [`State`] as the [`Variational`](super::Variational) integrator does: p₀ = ∂L/∂q̇(t₀, q₀, v₀)
//! before the step, and after it v₁ solves ∂L/∂q̇(t₁, q₁, v₁) = p₁ by Newton's method with the exact
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
//! mechanism's constraints ([`Mechanism::check_constraints`]) and ends by projecting onto them
//! ([`Mechanism::project`]; a no-op without constraints). When the mechanism's accelerations carry
//! constraint forces at the start of the step (the test of
//! [`refuse_constrained`](super::refuse_constrained): one plain evaluation), G includes the
//! generalized constraint force Jᵀλ = M q̈ − (𝓕 − b), with q̈ the constrained accelerations, at every
//! stage. Projection is not symplectic: on a constrained mechanism these methods are projection
//! methods (HLW §IV.4), symmetric only up to it.
//!
//! A Newton iteration that does not converge in [`MAX_NEWTON_ITERATIONS`] is
//! [`Error::NewtonDiverged`]; the caller's state is unchanged on every error.

// `!(a <= b)` comparisons are deliberate (they also catch NaN); stage loops index several arrays.
#![allow(clippy::neg_cmp_op_on_partial_ord, clippy::needless_range_loop)]

use super::canonical::{field_jacobians, velocities_from_momenta, FieldJacobians};
use super::newton::{constraint_forces_act, max_norm, Convergence, MAX_NEWTON_ITERATIONS};
use super::Integrator;
use crate::error::{Error, Result};
use crate::linalg::lu_solve_blocks;
use crate::mechanism::{check_step_at, Mechanism};
use crate::model::{check_state, Coordinates, State};
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
    /// Newton iterations.
    pub iterations: usize,
    /// Evaluations of the canonical vector field (p, ṗ) with their Jacobians (each is two passes
    /// with gradient dual numbers, nested inside ṗ).
    pub jacobian_evaluations: usize,
    /// Newton iterations of the velocity recovery ∂L/∂v(t₁, q₁, v₁) = p₁ (each one dual pass of the
    /// momenta).
    pub velocity_iterations: usize,
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
    let p0 = SVector::<f64, N>::from(mechanism.momenta_at(t, q, v));
    // Predictor Vᵢ = v₀ + cᵢ h q̈(t₀, q₀, v₀), O(h²) from the solution: one plain evaluation that
    // saves about one Newton iteration (each costing S evaluations with Jacobians). The same q̈
    // tells whether constraint forces act (one more plain evaluation).
    let a = mechanism.accelerations_at(t, q, v)?;
    let constrained = constraint_forces_act(mechanism, t, q, v, &a)?;
    let a0 = SVector::<f64, N>::from(a);
    let mut stages: [SVector<f64, N>; S] = std::array::from_fn(|i| v0 + a0 * (tableau.c[i] * h));
    let mut conv = Convergence::new();
    let mut stats = ImplicitStepStats::default();
    let mut residual_norm = f64::NAN;
    let zero = SMatrix::<f64, N, N>::zeros();
    for _ in 0..MAX_NEWTON_ITERATIONS {
        stats.iterations += 1;
        let mut field: [FieldJacobians<N>; S] = std::array::from_fn(|_| FieldJacobians {
            p: SVector::zeros(),
            rate: SVector::zeros(),
            p_q: zero,
            p_v: zero,
            rate_q: zero,
            rate_v: zero,
        });
        for j in 0..S {
            let mut qj = q0;
            for k in 0..S {
                qj += stages[k] * (h * tableau.a[j][k]);
            }
            field[j] = field_jacobians(
                mechanism,
                t + tableau.c[j] * h,
                &qj.into(),
                &stages[j].into(),
                constrained,
            )?;
            stats.jacobian_evaluations += 1;
        }
        let mut residual = [SVector::<f64, N>::zeros(); S];
        let mut jac = [[zero; S]; S];
        residual_norm = 0.0;
        for i in 0..S {
            let mut r = field[i].p - p0;
            for j in 0..S {
                r -= field[j].rate * (h * tableau.a[i][j]);
            }
            residual_norm = residual_norm.max(max_norm(&r));
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
        let breakdown = |reason: &str| Error::NewtonBreakdown {
            method: tableau.name,
            t,
            h,
            iteration: stats.iterations,
            reason: reason.to_string(),
        };
        if !residual_norm.is_finite() {
            return Err(breakdown(
                "the collocation residual is not finite (the stages left the region where the \
                 equations of motion are finite; reduce h)",
            ));
        }
        let Some(delta) = lu_solve_blocks(&jac, &residual) else {
            let finite = jac
                .iter()
                .flatten()
                .all(|b| b.iter().all(|x| x.is_finite()));
            return Err(breakdown(if finite {
                "the Newton matrix is singular"
            } else {
                "the Newton matrix is not finite (h is too large for this mechanism)"
            }));
        };
        let mut increment = 0.0f64;
        let mut scale = 0.0f64;
        for i in 0..S {
            stages[i] -= delta[i];
            increment = increment.max(max_norm(&delta[i]));
            scale = scale.max(max_norm(&stages[i]));
        }
        if conv.converged(increment, scale) {
            // q₁ = q₀ + h Σ bⱼ Vⱼ and p₁ = p₀ + h Σ bⱼ ṗⱼ, with ṗⱼ carried from the last evaluation
            // to the final iterate by its Jacobians (first order in the last increment, which is at
            // the round-off floor: no extra evaluation).
            let mut q1 = q0;
            let mut p1 = p0;
            for j in 0..S {
                q1 += stages[j] * (h * tableau.b[j]);
                let mut dq = SVector::<f64, N>::zeros();
                for k in 0..S {
                    dq += delta[k] * (h * tableau.a[j][k]);
                }
                let rate = field[j].rate - field[j].rate_q * dq - field[j].rate_v * delta[j];
                p1 += rate * (h * tableau.b[j]);
            }
            // v₁ from p₁ (inverse Legendre transform at t₁), starting from the collocation
            // polynomial's end velocity v₀ + Σ dᵢ (Vᵢ − v₀), dᵀ = bᵀA⁻¹, which is exact when p = M v
            // with M constant.
            let mut guess = v0;
            for i in 0..S {
                guess += (stages[i] - v0) * tableau.d[i];
            }
            let (v1, velocity_iterations) =
                velocities_from_momenta(mechanism, t + h, &q1.into(), &p1.into(), &guess.into())?;
            stats.velocity_iterations = velocity_iterations;
            return Ok((q1.into(), v1, stats));
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
    check_step_at(state.t, h)?;
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

/// The implicit midpoint rule y₁ = y₀ + h f(t₀ + h/2, (y₀ + y₁)/2) on y = (q, p): order 2,
/// symmetric, A-stable, symplectic for any Lagrangian, conserves quadratic invariants (see the
/// [module docs](self)). Per step: N unknowns, each Newton iteration one evaluation of (p, ṗ) with
/// their Jacobians.
#[derive(Clone, Copy, Debug, Default)]
pub struct ImplicitMidpoint;

impl ImplicitMidpoint {
    /// One step on raw (q, v) arrays through the Legendre transform at both ends, no validation:
    /// (q₁, v₁) and the Newton cost.
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

/// The 2-stage Gauss–Legendre method on y = (q, p): order 4, symmetric, A-stable, symplectic for
/// any Lagrangian, conserves quadratic invariants (see the [module docs](self)). Per step: 2N
/// unknowns, each Newton iteration two evaluations of (p, ṗ) with their Jacobians.
#[derive(Clone, Copy, Debug, Default)]
pub struct GaussLegendre2;

impl GaussLegendre2 {
    /// One step on raw (q, v) arrays through the Legendre transform at both ends, no validation:
    /// (q₁, v₁) and the Newton cost.
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
