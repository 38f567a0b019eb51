//! RATTLE: holonomic constraints g(q, t) = 0 in the symplectic methods built on the Lagrangian
//! itself, [`StormerVerlet`](super::StormerVerlet) and [`Variational`](super::Variational)
//! (Andersen, "Rattle: a 'velocity' version of the Shake algorithm for molecular dynamics
//! calculations", J. Comput. Phys. 52 (1983); Hairer, Lubich & Wanner, *Geometric Numerical
//! Integration*, 2nd ed. (HLW), §VII.1.4, (1.26), and the variational form with multipliers,
//! §VI.6 and §VII.1.4).
//!
//! With G = ∂g/∂q and the generalized constraint force Gᵀλ (the sign convention of
//! [`crate::constraints`]: M q̈ = 𝓕 − b + Gᵀλ), a step splits the constraint impulse at each end:
//!
//! ```text
//! p₀⁺ = p₀ + (h/2) G(q₀, t₀)ᵀ λ        λ such that g(q₁, t₁) = 0            (position stage)
//! (q₀, p₀⁺) ↦ (q₁, p₁⁻)                the unconstrained method's step
//! p₁  = p₁⁻ + (h/2) G(q₁, t₁)ᵀ μ        μ such that G(q₁, t₁) q̇₁ + ∂g/∂t = 0   (velocity stage)
//! ```
//!
//! The position stage is a nonlinear system for λ (Störmer–Verlet: C unknowns, q₁ depending on λ
//! through M⁻¹G(q₀)ᵀλ) or for (v_m, λ) together (the variational integrator's discrete
//! Euler–Lagrange equations with the multiplier term), solved by the one Newton driver of the
//! implicit methods with exact Jacobians from dual numbers. The velocity stage is linear in μ: with
//! p affine in q̇ with slope M(q₁) (every [`Model`](crate::Model)), q̇₁ = q̂̇₁ + M⁻¹Gᵀμ with
//! μ = −(G M⁻¹ Gᵀ)⁻¹(G q̂̇₁ + ∂g/∂t) — the mass-weighted velocity projection the constraints module
//! already implements, `Dynamics::project` (whose position part finds g(q₁) = 0 to round-off
//! already and moves q₁ at most by round-off). Without non-conservative forces the step map
//! (q₀, p₀) ↦ (q₁, p₁) is symplectic on the constraint manifold {g = 0, G q̇ + ∂g/∂t = 0},
//! symmetric and of order 2 (HLW §VII.1.4, for RATTLE and for the discrete Euler–Lagrange
//! equations with multipliers); with any forces it keeps g and its time derivative at the Newton
//! tolerance (round-off) at every step, without drift.
//!
//! **Which constraints.** Only holonomic rows: the choice is the declaration's,
//! `Dynamics::CONSTRAINT_COUNTS`, never the state's ([`holonomic_rows`]). Velocity rows,
//! unilateral contacts and friction are refused with [`Error::UnsuitableMethod`], and so is an
//! implementation that does not declare its constraints. Unilateral contacts are integrated with
//! the contact mode held over each step (the fixed-step loop of a [`Stepper`](super::Stepper), and
//! a single `sys.step`): with the mode held, a closed contact c(q, t) ≥ 0 is the holonomic row
//! c(q, t) = 0 for that step, and the held mode hands RATTLE its holonomic rows and its closed
//! contacts (`Evaluate::enforced_holonomic_rows` says how many); the loop releases a
//! contact where its multiplier crosses 0 and closes one where its gap does. Friction is refused
//! there too: a sticking friction row constrains q̇, not q, and cannot be a RATTLE row.
//!
//! **Rows as an N-vector.** The methods are generic over `Evaluate<N>`, which cannot name the
//! number of rows C; the rows come from `Dynamics::holonomic_constraints_at` padded with zeros
//! to N entries (independent holonomic rows number at most N), and the multipliers are an
//! N-vector whose entries beyond the declared rows are held at zero by identity rows in the Newton
//! systems.

// `!(a <= b)` comparisons are deliberate (they also catch NaN).
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use super::newton::{breakdown, count_exact_jacobians, jacobian_rows, max_norm, newton, seeded};
use super::newton::{mass_weights, NewtonScale, Unknowns as _, MAX_NEWTON_ITERATIONS};
use super::Stats;
use crate::error::{Error, Result};
use crate::evaluation::Evaluate;
use crate::linalg::lu_solve;
use nalgebra::{SMatrix, SVector};
use num_dual::DualSVec;

/// The number of holonomic rows `method` enforces by RATTLE, from the declaration
/// (`Dynamics::CONSTRAINT_COUNTS`, or `Dynamics::CONSTRAINTS` = `Some(0)`) alone: 0 for an
/// unconstrained mechanism. Refused with [`Error::UnsuitableMethod`]: velocity rows, unilateral
/// contacts, friction, more holonomic rows than coordinates, and a mechanism that does not declare
/// its constraints.
///
/// ```
/// use lagrange_core::integrate::holonomic_rows;
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
/// // `impl_mechanism!` declares that the pendulum in its angle has no constraint rows.
/// assert_eq!(holonomic_rows::<Pendulum, 1>("RATTLE")?, 0);
/// # Ok::<(), lagrange_core::Error>(())
/// ```
pub fn holonomic_rows<M: Evaluate<N>, const N: usize>(method: &'static str) -> Result<usize> {
    at_most_coordinates::<N>(method, declared_rows::<M, N>(method)?)
}

/// [`Error::UnsuitableMethod`] for a mechanism RATTLE cannot integrate, saying what can.
fn unsuitable(method: &'static str, reason: &str) -> Error {
    Error::UnsuitableMethod {
        method,
        reason: format!(
            "{reason}; use RK4, Dopri5, Dop853, Radau5, implicit midpoint or Gauss-Legendre, which \
             integrate the constrained accelerations and project (and hold the contact mode over a \
             step for contacts and friction); unilateral contacts (without friction) are integrated \
             by {method} in a Stepper or a single sys.step, which hold the contact mode over a step"
        ),
    }
}

/// The holonomic rows the declaration has, refusing every other kind of row and an
/// implementation that does not declare its constraints (see [`holonomic_rows`]).
fn declared_rows<M: Evaluate<N>, const N: usize>(method: &'static str) -> Result<usize> {
    match (M::CONSTRAINT_COUNTS, M::CONSTRAINTS) {
        (_, Some(0)) => Ok(0),
        (Some(c), _) if c.only_holonomic() => Ok(c.holonomic),
        (Some(c), _) => Err(unsuitable(
            method,
            &format!(
                "only holonomic constraints are enforced (by RATTLE), and the mechanism declares {} velocity, {} \
                 unilateral and {} friction rows",
                c.velocity, c.unilateral, c.friction
            ),
        )),
        (None, _) => Err(unsuitable(
            method,
            "the mechanism does not declare its constraints (Dynamics::CONSTRAINT_COUNTS; impl_mechanism! and \
             #[mechanism] declare it), and whether constraint forces act is decided by the declaration, \
             never by a state",
        )),
    }
}

/// `rows` if at most N (more holonomic rows than coordinates cannot be independent).
fn at_most_coordinates<const N: usize>(method: &'static str, rows: usize) -> Result<usize> {
    if rows <= N {
        return Ok(rows);
    }
    Err(unsuitable(
        method,
        &format!(
            "it enforces {rows} holonomic constraints on {N} coordinates (at most {N} can be independent)"
        ),
    ))
}

/// The number of holonomic rows `method` enforces over the coming step: [`holonomic_rows`] of the
/// declaration, or fewer when the mechanism holds a contact mode over the step
/// (`Dynamics::enforced_holonomic_rows`: the contact loop's held mode, whose leading rows are its
/// holonomic rows and its closed unilateral contacts; it may declare more contacts than
/// coordinates, a particle in a box, as long as those closed at once are at most N).
pub(crate) fn rows_in_force<M: Evaluate<N>, const N: usize>(
    mechanism: &M,
    method: &'static str,
) -> Result<usize> {
    let declared = declared_rows::<M, N>(method)?;
    let enforced = mechanism
        .enforced_holonomic_rows()
        .map_or(declared, |held| held.min(declared));
    at_most_coordinates::<N>(method, enforced)
}

/// The error for a mechanism that declares holonomic rows but does not provide them
/// (`Dynamics::holonomic_constraints_at` returns `None`).
fn rows_not_provided(method: &'static str) -> Error {
    Error::UnsuitableMethod {
        method,
        reason: "the mechanism declares holonomic constraints but does not provide them \
                 (Dynamics::holonomic_constraints_at)"
            .to_string(),
    }
}

/// g and G = ∂g/∂q of the holonomic rows at (t, q), padded to N rows (see the [module docs](self)):
/// one pass with q seeded as gradient dual numbers.
pub(crate) fn rows_and_jacobian<M: Evaluate<N>, const N: usize>(
    mechanism: &M,
    method: &'static str,
    t: f64,
    q: &[f64; N],
) -> Result<(SVector<f64, N>, SMatrix<f64, N, N>)> {
    let g = mechanism
        .holonomic_constraints_at(DualSVec::<f64, N>::from_re(t), &seeded(q))
        .ok_or_else(|| rows_not_provided(method))?;
    Ok((SVector::from_fn(|i, _| g[i].re), jacobian_rows(&g)))
}

/// g at (t, q) of the holonomic rows as gradient dual numbers along the seeds q carries (the
/// variational integrator's position stage seeds the midpoint velocity).
pub(crate) fn rows_on<M: Evaluate<N>, const N: usize>(
    mechanism: &M,
    method: &'static str,
    t: f64,
    q: &[DualSVec<f64, N>; N],
) -> Result<[DualSVec<f64, N>; N]> {
    mechanism
        .holonomic_constraints_at(DualSVec::<f64, N>::from_re(t), q)
        .ok_or_else(|| rows_not_provided(method))
}

/// What [`position_stage`]'s increments of Λ are measured against: the displacement h W δΛ each
/// makes, weighted by √Mⱼⱼ (`mass` is M(q₀)), resolved to the size of the unconstrained position
/// q̂ itself (see `NewtonScale`).
fn stage_scale<const N: usize>(
    mass: &SMatrix<f64, N, N>,
    directions: &SMatrix<f64, N, N>,
    unconstrained: &SVector<f64, N>,
) -> NewtonScale<SVector<f64, N>> {
    let position = mass_weights(mass);
    NewtonScale {
        weights: SVector::from_fn(|l, _| {
            (0..N).fold(0.0f64, |m, j| m.max(position[j] * directions[(j, l)].abs()))
        }),
        size: 0.0,
        resolution: unconstrained.weighted_norm(&position),
    }
}

/// Störmer–Verlet's position stage: Λ (= (h/2)λ, entries beyond `rows` zero) with
/// g(q̂ + h W Λ, t₁) = 0, W = M⁻¹G(q₀)ᵀ given as `directions` = h W, q̂ the unconstrained position.
/// Newton on r(Λ) = g(q₁(Λ), t₁)/h with the exact Jacobian G(q₁) W (from dual numbers at each
/// iterate), identity rows for the padding. An increment of Λ is measured by the displacement
/// h W δΛ it makes, weighted by √Mⱼⱼ (`mass` is M(q₀)), against that of Λ, resolved to the size
/// of q̂ itself. Returns q₁ and Λ.
#[allow(clippy::too_many_arguments, clippy::type_complexity)]
pub(crate) fn position_stage<M: Evaluate<N>, const N: usize>(
    mechanism: &M,
    method: &'static str,
    rows: usize,
    t: f64,
    h: f64,
    unconstrained: &SVector<f64, N>,
    directions: &SMatrix<f64, N, N>,
    mass: &SMatrix<f64, N, N>,
    stats: &mut Stats,
) -> Result<(SVector<f64, N>, SVector<f64, N>)> {
    let t1 = t + h;
    let mut lambda = SVector::<f64, N>::zeros();
    let mut iteration = 0;
    let before = stats.newton_iterations;
    let end = newton(
        &mut lambda,
        MAX_NEWTON_ITERATIONS,
        false,
        stats,
        || stage_scale(mass, directions, unconstrained),
        |lambda| {
            iteration += 1;
            let q1 = unconstrained + directions * lambda;
            let (g, jac) = rows_and_jacobian(mechanism, method, t1, &q1.into())?;
            let mut residual = g / h;
            let mut matrix = jac * directions / h;
            for i in rows..N {
                residual[i] = lambda[i];
                matrix.row_mut(i).fill(0.0);
                matrix[(i, i)] = 1.0;
            }
            let norm = max_norm(&residual);
            if !norm.is_finite() {
                return Err(breakdown(
                    method,
                    t,
                    h,
                    iteration,
                    "the constraint residual is not finite (reduce h)",
                ));
            }
            let Some(delta) = lu_solve(&matrix, &residual) else {
                return Err(breakdown(
                method,
                t,
                h,
                iteration,
                "the constraint Jacobian G M⁻¹ Gᵀ is singular (redundant constraints, or h too large)",
            ));
            };
            Ok((delta, norm))
        },
    )?;
    count_exact_jacobians(stats, before);
    end.converged(t)?;
    Ok((unconstrained + directions * lambda, lambda))
}
