//! A variational integrator: the discrete Euler–Lagrange equations of the midpoint discrete
//! Lagrangian, forced by the discrete Lagrange–d'Alembert principle (Marsden & West, *Discrete
//! mechanics and variational integrators*, Acta Numerica 10 (2001), §1.2, §3.2 and §3.5.3).
//!
//! ```text
//! L_d(q₀, q₁) = h · L(t + h/2, q_m, v_m),     q_m = (q₀ + q₁)/2,   v_m = (q₁ − q₀)/h,
//! F_d^±(q₀, q₁) = (h/2) · F_nc(t + h/2, q_m, v_m)                 (midpoint quadrature of the forcing),
//! p₀ = −D₁L_d(q₀, q₁) − F_d^−(q₀, q₁),   p₁ = D₂L_d(q₀, q₁) + F_d^+(q₀, q₁)   (M&W (3.2.7) with forcing).
//! ```
//!
//! With D₁L_d = (h/2) ∂L/∂q − ∂L/∂v and D₂L_d = (h/2) ∂L/∂q + ∂L/∂v at the midpoint, and
//! ∂L/∂q + F_nc = ∂T/∂q + 𝓕 =: G (𝓕 the generalized forces of the equations of motion, which
//! already contain −∇V, so the non-conservative part need not be separated), this is
//!
//! ```text
//! R(v_m) = p(t_m, q₀ + (h/2) v_m, v_m) − (h/2) G(t_m, q₀ + (h/2) v_m, v_m) − p₀ = 0,
//! q₁ = q₀ + h v_m,     p₁ = p₀ + h G(t_m, q_m, v_m),
//! ```
//!
//! solved for v_m by Newton's method with the exact Jacobian dR/dv_m, obtained by evaluating R with
//! v_m seeded as a gradient dual number (∂T/∂q inside G is itself a gradient, so this nests dual
//! numbers: exact second derivatives of T). [`Variational::step_arrays`] starts from the predictor
//! v_m = v₀ + (h/2) q̈(t₀, q₀, v₀).
//!
//! **State and momenta.** The method lives on (q, p). [`Variational`] implements
//! [`Integrator`] on the (q, v) [`State`] by a Legendre transform at both ends of a step:
//! p₀ = ∂L/∂v(t₀, q₀, v₀) before, and after it v₁ solves ∂L/∂v(t₁, q₁, v₁) = p₁: T is quadratic
//! in v for every mechanism, so v₁ = M⁻¹(p₁ − p(t₁, q₁, 0)), one solve with the mass matrix
//! M(q₁, t₁) (see `canonical::velocities_from_momenta`). Because the Legendre
//! transform at t₁ is inverted exactly (to round-off), the next step's p₀ is this step's p₁ and
//! the sequence of (q, p) is that of the discrete flow: the step map is symplectic in (q, p) for any
//! Lagrangian, second order, symmetric. [`Variational::step_momenta`] works on (q, p) directly.
//!
//! **Constraints: RATTLE.** Holonomic constraints g(q, t) = 0 (`#[constraint]` rows) enter the
//! discrete Euler–Lagrange equations with multipliers, split between the two ends of the step as in
//! RATTLE (Hairer, Lubich & Wanner, *Geometric Numerical Integration*, 2nd ed., §VI.6 and
//! §VII.1.4, (1.26); see [`rattle`](super::rattle)), with Dg = ∂g/∂q the constraint Jacobian (G
//! stays the momentum rate above), Λ = (h/2)λ and Λ₁ = (h/2)μ:
//!
//! ```text
//! R(v_m) − Dg(q₀, t₀)ᵀΛ = 0,     g(q₀ + h v_m, t₁) / h = 0                  (R as above),
//! q₁ = q₀ + h v_m,     p₁ = p₀ + Dg(q₀, t₀)ᵀΛ + h G(t_m, q_m, v_m) + Dg(q₁, t₁)ᵀΛ₁,
//! ```
//!
//! the first line solved for (v_m, Λ) together by the same Newton iteration (the 2N-square Jacobian
//! [[∂R/∂v_m, −Dg(q₀)ᵀ], [Dg(q₁), 0]], exact from the same dual seeding of v_m), Λ₁ such that v₁
//! satisfies Dg(q₁, t₁) v₁ + ∂g/∂t = 0: the mass-weighted velocity projection
//! `Dynamics::project` applied to the velocity recovered from p₁ without Λ₁. Velocity rows and
//! friction are refused by the declaration (`Dynamics::CONSTRAINT_COUNTS`, see
//! [`holonomic_rows`](super::holonomic_rows)), whatever the state. Unilateral contacts are
//! integrated with the contact mode held over each step (the fixed-step loop of a
//! [`Stepper`](super::Stepper), and a single `sys.step`): a closed contact is a RATTLE row for the
//! step (see [`rattle`](super::rattle)).

use super::canonical::{self, momentum_rate};
use super::newton::MAX_NEWTON_ITERATIONS;
use super::newton::{breakdown, count_exact_jacobians, jacobian_rows, max_norm, newton, seeded};
use super::newton::{mass_weights, position_floor, NewtonScale, Unknowns as _};
use super::rates::step_in_rates;
use super::rattle::{rows_and_jacobian, rows_in_force, rows_on};
use super::validated_step;
use super::{Integrator, Stats};
use crate::error::Result;
use crate::evaluation::Evaluate;
use crate::geometry::Scalar;
use crate::linalg::{lu_solve, lu_solve_blocks};
use crate::model::State;
use nalgebra::{SMatrix, SVector};
use num_dual::DualSVec;

/// The midpoint variational integrator (see the [module docs](self)).
///
/// ```
/// use lagrange_core::{Mechanism, State, Variational};
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
///     Pendulum.step::<Variational>(&mut s, 1e-2)?;
///     worst = worst.max((Pendulum.energy(&s)? - e0).abs());
/// }
/// // Symplectic, order 2: the energy error oscillates, O(h²ω²E) ≈ 1e-3·E = 4e-3, without drift.
/// assert!(worst < 1e-2);
/// # Ok::<(), lagrange_core::Error>(())
/// ```
#[derive(Clone, Copy, Debug, Default)]
pub struct Variational;

/// R(v_m) of the module docs, for any scalar.
#[inline]
fn residual<M: Evaluate<N>, S: Scalar, const N: usize>(
    mechanism: &M,
    tm: f64,
    q0: &[f64; N],
    p0: &[f64; N],
    vm: &[S; N],
    h: f64,
) -> [S; N] {
    let qm: [S; N] = std::array::from_fn(|j| vm[j] * (0.5 * h) + q0[j]);
    let t = S::from(tm);
    let p = mechanism.momenta_at(t, &qm, vm);
    let g = momentum_rate(mechanism, t, &qm, vm);
    std::array::from_fn(|k| p[k] - g[k] * (0.5 * h) - p0[k])
}

/// The discrete flow's update from the converged midpoint velocity v_m: q₁ = q₀ + h v_m, and
/// ṗ at the midpoint (t_m, q₀ + (h/2) v_m, v_m) (one evaluation), for p₁ = p₀ + h ṗ (plus RATTLE's
/// Dg(q₀)ᵀΛ on a constrained step).
fn midpoint_update<M: Evaluate<N>, const N: usize>(
    mechanism: &M,
    tm: f64,
    q0: &[f64; N],
    vm: &[f64; N],
    h: f64,
    stats: &mut Stats,
) -> ([f64; N], [f64; N]) {
    let qm: [f64; N] = std::array::from_fn(|j| q0[j] + 0.5 * h * vm[j]);
    let rate = momentum_rate(mechanism, tm, &qm, vm);
    stats.evaluations += 1;
    (std::array::from_fn(|j| q0[j] + h * vm[j]), rate)
}

/// The weights of the constrained step's unknowns (v_m, Λ) (see `NewtonScale`): v_m by √|Aᵢᵢ| of
/// the Newton matrix's velocity block A (M to leading order), Λ by the velocity-weighted impulse
/// −Dg(q₀)ᵀΛ it gives each coordinate, maxₖ |Dgₗₖ|/√Aₖₖ per unit Λₗ (the padding rows beyond
/// `rows`, held at zero, not at all).
fn constrained_weights<const N: usize>(
    velocity_block: &SMatrix<f64, N, N>,
    g0: &SMatrix<f64, N, N>,
    rows: usize,
) -> [SVector<f64, N>; 2] {
    let velocity = mass_weights(velocity_block);
    let impulse = SVector::<f64, N>::from_fn(|l, _| {
        (0..N)
            .filter(|&k| l < rows && velocity[k] > 0.0)
            .fold(0.0f64, |m, k| m.max(g0[(l, k)].abs() / velocity[k]))
    });
    [velocity, impulse]
}

/// What a variational step cost.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct VariationalStepStats {
    /// Newton iterations of the discrete Euler–Lagrange equation.
    pub iterations: usize,
    /// Solves of the velocity recovery ∂L/∂v = p₁ (one: T is quadratic in q̇).
    pub velocity_iterations: usize,
}

impl Variational {
    /// One step of the discrete flow on (q, p): returns (q₁, p₁) and the midpoint velocity v_m
    /// (a good starting guess for recovering v₁). No validation. p is conjugate to q̇, so a
    /// mechanism with quasi-velocities (whose momenta are dual to v) is refused
    /// ([`Error::UnsuitableMethod`](crate::Error::UnsuitableMethod)); its steps are
    /// [`Integrator::step`]'s, which convert.
    #[allow(clippy::type_complexity)]
    pub fn step_momenta<M: Evaluate<N>, const N: usize>(
        mechanism: &M,
        t: f64,
        q0: &[f64; N],
        p0: &[f64; N],
        v_guess: &[f64; N],
        h: f64,
    ) -> Result<([f64; N], [f64; N], [f64; N], usize)> {
        super::newton::refuse_quasi_velocities(Self::NAME, M::QUASI_VELOCITIES)?;
        let mut stats = Stats::default();
        let rows = rows_in_force(mechanism, Self::NAME)?;
        let (q1, p1, vm, iterations) =
            Self::momenta_step(mechanism, rows, t, q0, p0, v_guess, h, &mut stats)?;
        if rows == 0 {
            return Ok((q1, p1, vm, iterations));
        }
        // RATTLE's μ on the momenta: p₁ + Dg(q₁)ᵀΛ₁ is the momentum of the velocity recovered from
        // p₁ and projected (mass-weighted) onto Dg(q₁) v₁ + ∂g/∂t = 0.
        let (t1, mut q1) = (t + h, q1);
        let (mut v1, _) =
            canonical::velocities_from_momenta(mechanism, t1, &q1, &p1, &vm, &mut stats)?;
        mechanism.project(t1, &mut q1, &mut v1)?;
        Ok((q1, mechanism.momenta_at(t1, &q1, &v1), vm, iterations))
    }

    /// One step of the discrete flow with `rows` holonomic rows: (q₁, p₁ before RATTLE's μ, v_m,
    /// iterations).
    #[allow(clippy::type_complexity, clippy::too_many_arguments)]
    fn momenta_step<M: Evaluate<N>, const N: usize>(
        mechanism: &M,
        rows: usize,
        t: f64,
        q0: &[f64; N],
        p0: &[f64; N],
        v_guess: &[f64; N],
        h: f64,
        stats: &mut Stats,
    ) -> Result<([f64; N], [f64; N], [f64; N], usize)> {
        if rows > 0 {
            return Self::constrained_momenta_step(mechanism, rows, t, q0, p0, v_guess, h, stats);
        }
        let tm = t + 0.5 * h;
        let mut vm = SVector::<f64, N>::from(*v_guess);
        let mut iteration = 0;
        let before = stats.newton_iterations;
        // v_m weighted by √|Aᵢᵢ| of the first Newton matrix A = ∂R/∂v_m (M to leading order),
        // sized by the predictor, resolved to the positions' size over h (see `NewtonScale`).
        let q0_vector = SVector::<f64, N>::from(*q0);
        let weights = std::cell::Cell::new(SVector::<f64, N>::zeros());
        let guess = vm;
        let scale = || NewtonScale {
            weights: weights.get(),
            size: guess.weighted_norm(&weights.get()),
            resolution: position_floor(&weights.get(), &q0_vector, h),
        };
        let end = newton(&mut vm, MAX_NEWTON_ITERATIONS, false, stats, scale, |vm| {
            iteration += 1;
            let r = residual(mechanism, tm, q0, p0, &seeded(&(*vm).into()), h);
            let value = SVector::<f64, N>::from_fn(|i, _| r[i].re);
            let residual_norm = max_norm(&value);
            let broke = |reason: &str| breakdown(Self::NAME, t, h, iteration, reason);
            if !residual_norm.is_finite() {
                return Err(broke(
                    "the discrete Euler-Lagrange residual is not finite (the midpoint left the \
                     region where the equations of motion are finite; reduce h)",
                ));
            }
            let jac = jacobian_rows(&r);
            if iteration == 1 {
                weights.set(mass_weights(&jac));
            }
            let Some(delta) = lu_solve(&jac, &value) else {
                return Err(broke(if jac.iter().all(|x| x.is_finite()) {
                    "the Newton matrix is singular"
                } else {
                    "the Newton matrix is not finite (h is too large for this mechanism)"
                }));
            };
            Ok((delta, residual_norm))
        })?;
        // Every iteration evaluated the residual with its exact Jacobian and factorised it.
        count_exact_jacobians(stats, before);
        let iterations = end.converged(t)?;
        let vm: [f64; N] = vm.into();
        let (q1, g) = midpoint_update(mechanism, tm, q0, &vm, h, stats);
        let p1 = std::array::from_fn(|j| p0[j] + h * g[j]);
        Ok((q1, p1, vm, iterations))
    }

    /// The position stage of RATTLE on the discrete Euler–Lagrange equations (see the
    /// [module docs](self)): Newton on (v_m, Λ) together, the 2N-square Jacobian exact from one
    /// dual seeding of v_m through both R and g(q₀ + h v_m, t₁); the multipliers beyond `rows` are
    /// held at zero by identity rows. Returns (q₁, p₁ before μ, v_m, iterations).
    #[allow(clippy::type_complexity, clippy::too_many_arguments)]
    fn constrained_momenta_step<M: Evaluate<N>, const N: usize>(
        mechanism: &M,
        rows: usize,
        t: f64,
        q0: &[f64; N],
        p0: &[f64; N],
        v_guess: &[f64; N],
        h: f64,
        stats: &mut Stats,
    ) -> Result<([f64; N], [f64; N], [f64; N], usize)> {
        let (tm, t1) = (t + 0.5 * h, t + h);
        let (_, g0) = rows_and_jacobian(mechanism, Self::NAME, t, q0)?;
        // Λ enters R linearly through −Dg(q₀)ᵀΛ; the padding rows are Λᵢ = 0.
        let minus_g0t = -g0.transpose();
        let padding =
            SMatrix::<f64, N, N>::from_fn(|i, j| if i == j && i >= rows { 1.0 } else { 0.0 });
        let mut x = [
            SVector::<f64, N>::from(*v_guess),
            SVector::<f64, N>::zeros(),
        ];
        let mut iteration = 0;
        let before = stats.newton_iterations;
        // v_m as in the unconstrained step; Λ by the velocity-weighted impulse −Dg(q₀)ᵀΛ it gives
        // each coordinate, maxₖ |Dgₗₖ|/√Mₖₖ per unit Λₗ (the padding, held at zero, not at all).
        let q0_vector = SVector::<f64, N>::from(*q0);
        let weights = std::cell::Cell::new([SVector::<f64, N>::zeros(); 2]);
        let guess = x[0];
        let scale = || NewtonScale {
            weights: weights.get(),
            size: guess.weighted_norm(&weights.get()[0]),
            resolution: position_floor(&weights.get()[0], &q0_vector, h),
        };
        let end = newton(&mut x, MAX_NEWTON_ITERATIONS, false, stats, scale, |x| {
            iteration += 1;
            let vm = seeded(&x[0].into());
            let r = residual(mechanism, tm, q0, p0, &vm, h);
            let q1: [DualSVec<f64, N>; N] = std::array::from_fn(|j| vm[j] * h + q0[j]);
            let g = rows_on(mechanism, Self::NAME, t1, &q1)?;
            let momentum = SVector::<f64, N>::from_fn(|i, _| r[i].re) + minus_g0t * x[1];
            let position =
                SVector::<f64, N>::from_fn(|i, _| if i < rows { g[i].re / h } else { x[1][i] });
            let norm = max_norm(&momentum).max(max_norm(&position));
            if !norm.is_finite() {
                return Err(breakdown(
                    Self::NAME,
                    t,
                    h,
                    iteration,
                    "the discrete Euler-Lagrange residual is not finite (the midpoint left the \
                     region where the equations of motion are finite; reduce h)",
                ));
            }
            let jacobian = [
                [jacobian_rows(&r), minus_g0t],
                [jacobian_rows(&g) / h, padding],
            ];
            if iteration == 1 {
                weights.set(constrained_weights(&jacobian[0][0], &g0, rows));
            }
            let Some(delta) = lu_solve_blocks(&jacobian, &[momentum, position]) else {
                return Err(breakdown(
                    Self::NAME,
                    t,
                    h,
                    iteration,
                    "the Newton matrix is singular or not finite (redundant constraints, or h too \
                     large for this mechanism)",
                ));
            };
            Ok((delta, norm))
        })?;
        count_exact_jacobians(stats, before);
        let iterations = end.converged(t)?;
        let vm: [f64; N] = x[0].into();
        let (q1, rate) = midpoint_update(mechanism, tm, q0, &vm, h, stats);
        let push = g0.transpose() * x[1];
        let p1 = std::array::from_fn(|j| p0[j] + push[j] + h * rate[j]);
        Ok((q1, p1, vm, iterations))
    }

    /// The velocities v with ∂L/∂v(t, q, v) = p (inverse Legendre transform), one solve with the
    /// mass matrix (see `canonical::velocities_from_momenta`). Returns v and the solves (1).
    pub fn velocities_from_momenta<M: Evaluate<N>, const N: usize>(
        mechanism: &M,
        t: f64,
        q: &[f64; N],
        p: &[f64; N],
        guess: &[f64; N],
    ) -> Result<([f64; N], usize)> {
        canonical::velocities_from_momenta(mechanism, t, q, p, guess, &mut Stats::default())
    }

    /// One step on (q, v) arrays through the Legendre transform at both ends. No validation.
    #[allow(clippy::type_complexity)]
    pub fn step_arrays<M: Evaluate<N>, const N: usize>(
        mechanism: &M,
        t: f64,
        q: &[f64; N],
        v: &[f64; N],
        h: f64,
    ) -> Result<([f64; N], [f64; N], VariationalStepStats)> {
        let mut stats = Stats::default();
        let mut stats_out = VariationalStepStats::default();
        let (q1, v1) = Self::advance_counted(mechanism, t, q, v, h, &mut stats, &mut stats_out)?;
        Ok((q1, v1, stats_out))
    }

    /// A step and its counts; a mechanism with quasi-velocities stepped in its coordinates'
    /// rates ([`step_in_rates`]).
    #[allow(clippy::type_complexity)]
    fn advance_counted<M: Evaluate<N>, const N: usize>(
        mechanism: &M,
        t: f64,
        q: &[f64; N],
        v: &[f64; N],
        h: f64,
        stats: &mut Stats,
        counts: &mut VariationalStepStats,
    ) -> Result<([f64; N], [f64; N])> {
        if !M::QUASI_VELOCITIES {
            return Self::advance_counted_on(mechanism, t, (q, v), h, stats, counts);
        }
        let step = step_in_rates(mechanism, (q, v), |in_rates, rates| {
            let (q1, rates1) = Self::advance_counted_on(in_rates, t, (q, rates), h, stats, counts)?;
            Ok((q1, rates1, ()))
        })?;
        Ok((step.0, step.1))
    }

    /// [`advance_counted`](Self::advance_counted) on a mechanism whose velocities are the
    /// coordinates' rates.
    #[allow(clippy::type_complexity)]
    fn advance_counted_on<M: Evaluate<N>, const N: usize>(
        mechanism: &M,
        t: f64,
        (q, v): (&[f64; N], &[f64; N]),
        h: f64,
        stats: &mut Stats,
        counts: &mut VariationalStepStats,
    ) -> Result<([f64; N], [f64; N])> {
        // Which constraints are enforced is the declaration's, decided before anything is evaluated.
        let rows = rows_in_force(mechanism, Self::NAME)?;
        let p0 = mechanism.momenta_at(t, q, v);
        // Predictor v_m = v₀ + (h/2) q̈(t₀, q₀, v₀), O(h²) from the solution (q̈ with the constraint
        // forces, for a constrained mechanism).
        let a0 = mechanism.accelerations_at(t, q, v)?;
        stats.evaluations += 1;
        let guess: [f64; N] = std::array::from_fn(|j| v[j] + 0.5 * h * a0[j]);
        let (mut q1, p1, vm, iterations) =
            Self::momenta_step(mechanism, rows, t, q, &p0, &guess, h, stats)?;
        // v₁ ≈ 2 v_m − v₀ to first order: where the inverse Legendre transform evaluates M.
        let guess: [f64; N] = std::array::from_fn(|j| 2.0 * vm[j] - v[j]);
        let (mut v1, velocity_iterations) =
            canonical::velocities_from_momenta(mechanism, t + h, &q1, &p1, &guess, stats)?;
        if rows > 0 {
            // RATTLE's μ: the mass-weighted velocity projection at (t₁, q₁).
            mechanism.project(t + h, &mut q1, &mut v1)?;
        }
        *counts = VariationalStepStats {
            iterations,
            velocity_iterations,
        };
        Ok((q1, v1))
    }

    /// A validated step that also reports its Newton cost; the state is unchanged on error.
    pub fn step_with_stats<M: Evaluate<N>, const N: usize>(
        mechanism: &M,
        state: &mut State<M::Coords>,
        h: f64,
    ) -> Result<VariationalStepStats> {
        let mut counts = VariationalStepStats::default();
        let mut stats = Stats::default();
        validated_step(mechanism, state, h, |t, q, v| {
            Self::advance_counted(mechanism, t, q, v, h, &mut stats, &mut counts)
        })?;
        Ok(counts)
    }
}

impl Integrator for Variational {
    const NAME: &'static str = "variational midpoint";
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
        Self::advance_counted(
            mechanism,
            t,
            q,
            v,
            h,
            stats,
            &mut VariationalStepStats::default(),
        )
    }
}
