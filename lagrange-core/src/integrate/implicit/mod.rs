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
//! solver ([`Stepper`](super::Stepper), or [`GaussLegendre2::step_with_memory`]) the
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
//! **Taking repeated steps.** A single `sys.step::<GaussLegendre2>(&mut s, h)` has no memory: it
//! evaluates the Jacobians on dual numbers and factorises the Newton matrix at every step, and the
//! Jacobians dominate its cost (for a constrained mechanism they are taken through the constrained
//! solve; BENCHMARKS.md has the profile). Repeated steps are taken by a solver,
//! [`Stepper`](super::Stepper) with `GaussLegendre2::with_step(h)` (or
//! [`GaussLegendre2::step_with_memory`] with a [`NewtonMemory`]), which keeps the Jacobians and
//! the factorisation while they contract, as the examples below do.
//!
//! **State.** [`ImplicitMidpoint`] and [`GaussLegendre2`] implement [`Integrator`] on the (q, v)
//! [`State`] as the [`Variational`](super::Variational) integrator does: p₀ = ∂L/∂q̇(t₀, q₀, v₀)
//! before the step (in a solver, the previous step's p₁ when the state is exactly where that step
//! left it), and after it v₁ solves ∂L/∂q̇(t₁, q₁, v₁) = p₁: T is quadratic in q̇, so
//! v₁ = M⁻¹(p₁ − p(t₁, q₁, 0)), one solve with the mass matrix. The Legendre transform is inverted
//! to round-off, so the next step starts from this
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
//! A Newton iteration that does not converge in
//! [`MAX_NEWTON_ITERATIONS`](super::MAX_NEWTON_ITERATIONS) is
//! [`Error::NewtonDiverged`](crate::Error::NewtonDiverged); the caller's state is unchanged on
//! every error.

// `!(a <= b)` comparisons are deliberate (they also catch NaN); stage loops index several arrays.
#![allow(clippy::neg_cmp_op_on_partial_ord, clippy::needless_range_loop)]

mod collocation;
mod matrix;
mod predictor;
mod tableau;

use super::validated_step;
use super::{Integrator, Stats};
use crate::error::Result;
use crate::evaluation::Evaluate;
use crate::model::State;
use collocation::collocation_step;
use matrix::NewtonMatrix;
use predictor::PreviousStep;
use tableau::{GAUSS2, MIDPOINT};

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
    /// Solves of the velocity recovery ∂L/∂v(t₁, q₁, v₁) = p₁ (one: T is quadratic in q̇).
    pub velocity_iterations: usize,
}

/// The contraction factor θ of a simplified Newton iteration above which the next step
/// recomputes the Jacobian instead of reusing it (Hairer & Wanner, *Solving ODEs II*, §IV.8: the
/// Jacobian is kept while convergence is fast; a refreshed Jacobian costs S dual evaluations of
/// the field, about as much as two or three plain iterations, which a θ below 0.1 does not save).
pub const JACOBIAN_REUSE_THETA: f64 = 0.1;

/// Working memory of [`ImplicitMidpoint`] (S = 1) and [`GaussLegendre2`] (S = 2) in a solver
/// ([`Stepper`](super::Stepper)): the Jacobian and the factorised Newton matrix of the
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

/// The implicit midpoint rule y₁ = y₀ + h f(t₀ + h/2, (y₀ + y₁)/2) on y = (q, p): order 2,
/// symmetric, A-stable, symplectic for any Lagrangian, conserves quadratic invariants (see the
/// [module docs](self)). Per step: N unknowns, a simplified Newton iteration with one plain
/// evaluation of (p, ṗ) per iteration.
///
/// On a declaration with `#[unilateral]` or `#[friction]` rows, whose contact mode switches
/// inside a step, a single `sys.step::<ImplicitMidpoint>` and a [`Stepper`](super::Stepper) hold
/// the mode of the step's start over the step (the method steps the mechanism in that mode, with
/// fresh working memory) and locate its switches: a step cut at an event and the rest taken as a
/// shorter step in the new mode. Its [`advance`](super::Integrator::advance) on raw arrays refuses
/// such a declaration ([`Error::UnsuitableMethod`](crate::Error::UnsuitableMethod)).
///
/// ```
/// use lagrange_core::integrate::Stepper;
/// use lagrange_core::{ImplicitMidpoint, Integrator, Mechanism, State};
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
/// let start = State::new(0.0, [0.5], [0.0]);
/// let e0 = Pendulum.energy(&start)?;
/// // A solver keeps the Newton matrix from step to step (see the module docs).
/// let mut solver = Stepper::new(&Pendulum, ImplicitMidpoint::with_step(1e-2), &start)?;
/// let mut worst = 0.0f64;
/// for _ in 0..10_000 {
///     solver.step(f64::MAX)?;
///     worst = worst.max((Pendulum.energy(&solver.state())? - e0).abs());
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
/// On a declaration with `#[unilateral]` or `#[friction]` rows a single `sys.step` and a
/// [`Stepper`](super::Stepper) hold the contact mode over each step, as for [`ImplicitMidpoint`].
///
/// ```
/// use lagrange_core::integrate::Stepper;
/// use lagrange_core::{GaussLegendre2, Integrator, Mechanism, State};
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
/// let start = State::new(0.0, [0.5], [0.0]);
/// let e0 = Pendulum.energy(&start)?;
/// // A solver keeps the Newton matrix from step to step (see the module docs).
/// let mut solver = Stepper::new(&Pendulum, GaussLegendre2::with_step(1e-2), &start)?;
/// let mut worst = 0.0f64;
/// for _ in 0..10_000 {
///     solver.step(f64::MAX)?;
///     worst = worst.max((Pendulum.energy(&solver.state())? - e0).abs());
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
            pub fn step_arrays<M: Evaluate<N>, const N: usize>(
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
            pub fn step_with_stats<M: Evaluate<N>, const N: usize>(
                mechanism: &M,
                state: &mut State<M::Coords>,
                h: f64,
            ) -> Result<ImplicitStepStats> {
                Self::step_with_memory(mechanism, &mut NewtonMemory::default(), state, h)
            }

            /// A validated step with the working memory of the previous ones (the Newton matrix
            /// is reused while it contracts well), reporting its Newton cost; the state is
            /// unchanged on error.
            pub fn step_with_memory<M: Evaluate<N>, const N: usize>(
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

            fn advance<M: Evaluate<N>, const N: usize>(
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
