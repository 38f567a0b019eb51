//! Störmer–Verlet in velocity form (Hairer, Lubich & Wanner, *Geometric Numerical Integration*,
//! §I.1.4, (1.17); Hairer, Lubich & Wanner, Acta Numerica 12 (2003), "Geometric numerical integration
//! illustrated by the Störmer–Verlet method"):
//!
//! ```text
//! v_{1/2} = v₀ + (h/2) q̈(t₀, q₀, v₀),   q₁ = q₀ + h v_{1/2},   v₁ = v_{1/2} + (h/2) q̈(t₁, q₁, v_{1/2}).
//! ```
//!
//! Explicit, order 2 (two evaluations of the dynamics per step), symplectic and symmetric for
//! q̈ = −M⁻¹∇V(q) with a **constant** mass matrix M (then (q, Mv) are canonical and the method is the composition of two symplectic Euler steps).
//! With forces that depend on the velocity the last evaluation uses v_{1/2} in place of the unknown
//! v₁ (which keeps the method explicit, but it is then neither symmetric nor symplectic — use
//! [`Variational`](super::Variational) for forced mechanisms).
//!
//! **The constant-mass-matrix test.** Every step evaluates the equations of motion at the old and
//! the new configuration anyway (for q̈), so it compares the two mass matrices: if
//! max|M(q₁, t₁) − M(q₀, t₀)| > 1e-12 · max|M(q₀, t₀)| the step is refused with
//! [`Error::UnsuitableMethod`] and the state is left as it was. The threshold is 4500 ε: far above
//! the round-off of assembling M = Jᵀ diag(μ) J for small systems, far below the change of any mass
//! matrix that actually depends on q over a step that moves it. So a mechanism whose mass matrix
//! varies (a double pendulum, polar coordinates, a time-dependent M) is refused at its first step
//! that moves; one whose M is constant up to round-off (a pendulum in its angle, Cartesian
//! particles) is accepted. A step that does not move (v = q̈ = 0) cannot see the difference and
//! is allowed, harmlessly: it is exact for any M.
//!
//! **Constraints: RATTLE.** Holonomic constraints g(q, t) = 0 (`#[constraint]` rows) are enforced
//! by RATTLE (Andersen, J. Comput. Phys. 52 (1983); Hairer, Lubich & Wanner, *Geometric Numerical
//! Integration*, §VII.1.4, (1.26)), in the velocity form above with M q̈ = 𝓕 − b + Gᵀλ:
//!
//! ```text
//! v_{1/2} = v₀ + (h/2) (q̈₀ + M⁻¹G(q₀, t₀)ᵀλ),   q₁ = q₀ + h v_{1/2},   g(q₁, t₁) = 0,
//! v₁ = v_{1/2} + (h/2) (q̈₁ + M⁻¹G(q₁, t₁)ᵀμ),   G(q₁, t₁) v₁ + ∂g/∂t(q₁, t₁) = 0,
//! ```
//!
//! q̈ the unconstrained accelerations M⁻¹(𝓕 − b). λ solves the nonlinear position stage by Newton
//! with the exact Jacobian G(q₁) M⁻¹ G(q₀)ᵀ (dual numbers); μ is the mass-weighted velocity
//! projection, `Dynamics::project` (see [`rattle`](super::rattle)). Symplectic and symmetric
//! for a constant M and conservative forces, order 2, g and ġ kept at round-off. Velocity
//! constraints and friction are refused, by the declaration (`Dynamics::CONSTRAINT_COUNTS`, see
//! [`holonomic_rows`](super::holonomic_rows)), as is an implementation that does not declare its
//! constraints: whatever the state, never by testing the multipliers. Unilateral contacts are
//! integrated with the contact mode held over each step (the fixed-step loop of a
//! [`Stepper`](super::Stepper), and a single `sys.step`): a closed contact is a RATTLE row for the
//! step (see [`rattle`](super::rattle)).

// `!(a <= b)` comparisons are deliberate (they also catch NaN); stage loops index several arrays.
#![allow(clippy::neg_cmp_op_on_partial_ord, clippy::needless_range_loop)]

use super::newton::refuse_quasi_velocities;
use super::rattle::{position_stage, rows_and_jacobian, rows_in_force};
use super::{Integrator, Stats};
use crate::dynamics::{mass_matrix_failure, solve_accelerations};
use crate::error::{Error, Result};
use crate::evaluation::Evaluate;
use crate::linalg::{cholesky, cholesky_substitute};
use crate::model::Coordinates;
use nalgebra::{SMatrix, SVector};

/// Relative change of the mass matrix over one step above which [`StormerVerlet`] refuses the
/// mechanism (see the [module docs](self)): each entry's change against √(MᵢᵢMⱼⱼ), a ratio that
/// rescaling a coordinate does not change (entry (i, j) scales as the geometric mean of the two
/// diagonal entries).
pub const MASS_MATRIX_VARIATION: f64 = 1e-12;

/// Störmer–Verlet, velocity form (see the [module docs](self)): two evaluations of q̈ per step.
///
/// ```
/// use lagrange_core::{Mechanism, State, StormerVerlet};
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
/// // The pendulum in its angle has the constant mass matrix m l² = 1: Verlet applies.
/// let mut s = State::new(0.0, [0.5], [0.0]);
/// let e0 = Pendulum.energy(&s)?;
/// let mut worst = 0.0f64;
/// for _ in 0..10_000 {
///     Pendulum.step::<StormerVerlet>(&mut s, 1e-2)?;
///     worst = worst.max((Pendulum.energy(&s)? - e0).abs());
/// }
/// // Symplectic, order 2: the energy error oscillates, O(h²ω²E) ≈ 1e-3·E = 4e-3, without drift.
/// assert!(worst < 1e-2);
/// # Ok::<(), lagrange_core::Error>(())
/// ```
#[derive(Clone, Copy, Debug, Default)]
pub struct StormerVerlet;

impl StormerVerlet {
    /// One step on raw arrays: (q₁, v₁), or [`Error::UnsuitableMethod`] when the mass matrix
    /// changed over the step or the mechanism has constraints RATTLE does not enforce. No
    /// validation of the inputs.
    pub fn step_arrays<M: Evaluate<N>, const N: usize>(
        mechanism: &M,
        t: f64,
        q: &[f64; N],
        v: &[f64; N],
        h: f64,
    ) -> Result<([f64; N], [f64; N])> {
        Self::step_counted(mechanism, t, q, v, h, &mut Stats::default())
    }

    fn step_counted<M: Evaluate<N>, const N: usize>(
        mechanism: &M,
        t: f64,
        q: &[f64; N],
        v: &[f64; N],
        h: f64,
        stats: &mut Stats,
    ) -> Result<([f64; N], [f64; N])> {
        refuse_quasi_velocities(Self::NAME, M::QUASI_VELOCITIES)?;
        // Which constraints are enforced is the declaration's, decided before anything is evaluated.
        let rows = rows_in_force(mechanism, Self::NAME)?;
        let eom0 = mechanism.equations_of_motion_at(t, q, v);
        let a0 = solve_accelerations::<M::Coords, f64, N>(&eom0, t, q)?;
        stats.evaluations += 1;
        let t1 = t + h;
        let (mut q1, vh): ([f64; N], [f64; N]) = if rows == 0 {
            let vh: [f64; N] = std::array::from_fn(|i| v[i] + 0.5 * h * a0[i]);
            (std::array::from_fn(|i| q[i] + h * vh[i]), vh)
        } else {
            // RATTLE's position stage: v_{1/2} = v₀ + (h/2) q̈₀ + W Λ and q₁ = q̂ + h W Λ with
            // W = M⁻¹G(q₀)ᵀ, Λ = (h/2) λ, q̂ = q₀ + h v₀ + (h²/2) q̈₀, and g(q₁, t₁) = 0.
            let (_, g0) = rows_and_jacobian(mechanism, Self::NAME, t, q)?;
            let l = cholesky(&eom0.mass_matrix).map_err(|e| {
                mass_matrix_failure::<M::Coords, f64, N>(&eom0.mass_matrix, e, t, q)
            })?;
            let mut w = SMatrix::<f64, N, N>::zeros();
            for i in 0..rows {
                w.set_column(i, &cholesky_substitute(&l, &g0.row(i).transpose()));
            }
            let unconstrained =
                SVector::<f64, N>::from_fn(|i, _| q[i] + h * v[i] + 0.5 * h * h * a0[i]);
            let (q1, lambda) = position_stage(
                mechanism,
                Self::NAME,
                rows,
                t,
                h,
                &unconstrained,
                &(w * h),
                &eom0.mass_matrix,
                stats,
            )?;
            let push = w * lambda;
            (
                q1.into(),
                std::array::from_fn(|i| v[i] + 0.5 * h * a0[i] + push[i]),
            )
        };
        let eom1 = mechanism.equations_of_motion_at(t1, &q1, &vh);
        stats.evaluations += 1;
        constant_mass::<M::Coords, N>((t, &eom0.mass_matrix), (t1, &eom1.mass_matrix), &q1)?;
        let a1 = solve_accelerations::<M::Coords, f64, N>(&eom1, t1, &q1)?;
        let mut v1 = std::array::from_fn(|i| vh[i] + 0.5 * h * a1[i]);
        if rows > 0 {
            // RATTLE's velocity stage: v₁ += M⁻¹G(q₁)ᵀμ with G(q₁) v₁ + ∂g/∂t = 0, the mass-weighted
            // velocity projection (g(q₁) is at round-off already).
            mechanism.project(t1, &mut q1, &mut v1)?;
        }
        Ok((q1, v1))
    }
}

impl Integrator for StormerVerlet {
    const NAME: &'static str = "Stormer-Verlet";
    type Memory<const N: usize> = ();
    // With the contact mode held, a closed contact is a RATTLE row for the step.
    const POSITION_ROWS_ONLY: bool = true;

    fn advance<M: Evaluate<N>, const N: usize>(
        mechanism: &M,
        _memory: &mut (),
        t: f64,
        q: &[f64; N],
        v: &[f64; N],
        h: f64,
        stats: &mut Stats,
    ) -> Result<([f64; N], [f64; N])> {
        // Two solves with the mass matrix, and RATTLE's Newton iterations (counted there).
        Self::step_counted(mechanism, t, q, v, h, stats)
    }
}

/// Refuses a step over which the mass matrix changed (M(q₁) against M(q₀), relative to M(q₀)'s
/// largest entry) by more than [`MASS_MATRIX_VARIATION`] ([`Error::UnsuitableMethod`]), and a
/// mass matrix that overflowed at q₁ ([`Error::NonFiniteDynamics`]).
fn constant_mass<C: Coordinates<N>, const N: usize>(
    (t, m0): (f64, &SMatrix<f64, N, N>),
    (t1, m1): (f64, &SMatrix<f64, N, N>),
    q1: &[f64; N],
) -> Result<()> {
    // A step that blew up (M overflowing at q₁) is non-finite dynamics there, not a mass matrix
    // that "changed by NaN".
    if !m1.iter().all(|x| x.is_finite()) {
        return Err(Error::NonFiniteDynamics {
            t: t1,
            configuration: crate::error::describe_configuration(&C::NAMES, q1),
        });
    }
    let mut change = 0.0f64;
    let mut relative = 0.0f64;
    for i in 0..N {
        for j in 0..N {
            let d = (m1[(i, j)] - m0[(i, j)]).abs();
            let r = d / (m0[(i, i)] * m0[(j, j)]).abs().sqrt();
            // NaN (a zero diagonal entry, M singular) counts as a change, and stays.
            if r.is_nan() || r > relative {
                (change, relative) = (d, r);
            }
        }
    }
    // `!(a <= b)` also refuses NaN.
    if !(relative <= MASS_MATRIX_VARIATION) {
        return Err(Error::UnsuitableMethod {
            method: StormerVerlet::NAME,
            reason: format!(
                "the mass matrix is not constant: an entry changed by {change:e} (relative {relative:e}) over \
                 the step from t = {t} to t = {t1}; use a method for general mass matrices (implicit midpoint, \
                 Gauss-Legendre, variational, RK4, Dopri5)"
            ),
        });
    }
    Ok(())
}
