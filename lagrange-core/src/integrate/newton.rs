//! Shared pieces of the implicit methods: exact Jacobians of the accelerations by dual numbers,
//! the one Newton loop with its convergence test, and the block LU factorisation the simplified
//! Newton iteration reuses.

// `!(a < b)` comparisons are deliberate (they also catch NaN).
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use super::Stats;
use crate::error::{Error, Result};
use crate::evaluation::Evaluate;
use nalgebra::{SMatrix, SVector};
use num_dual::DualSVec;

/// Most Newton iterations an implicit step may take before it reports
/// [`Error::NewtonDiverged`](crate::Error::NewtonDiverged). With exact Jacobians the iteration
/// converges quadratically from the explicit predictor, so a well-posed step needs 3–6.
pub const MAX_NEWTON_ITERATIONS: usize = 20;

/// q̈ and its exact Jacobians ∂q̈/∂q and ∂q̈/∂q̇ at (t, q, q̇): two passes of the accelerations with
/// gradient dual numbers, seeded on q and then on q̇.
#[allow(clippy::type_complexity)]
pub fn acceleration_jacobians<M: Evaluate<N>, const N: usize>(
    mechanism: &M,
    t: f64,
    q: &[f64; N],
    v: &[f64; N],
) -> Result<([f64; N], SMatrix<f64, N, N>, SMatrix<f64, N, N>)> {
    jacobians_by_duals(t, q, v, |t, q, v| mechanism.accelerations_at(t, q, v))
}

/// f(t, q, q̇) and its exact Jacobians ∂f/∂q and ∂f/∂q̇ for any f(t, q, q̇) ∈ Rᴺ evaluated
/// on gradient dual numbers (the accelerations of a mechanism, or of a constrained one with its
/// contact mode held): two passes, seeded on q and then on q̇.
#[allow(clippy::type_complexity)]
pub(crate) fn jacobians_by_duals<const N: usize>(
    t: f64,
    q: &[f64; N],
    v: &[f64; N],
    f: impl Fn(
        DualSVec<f64, N>,
        &[DualSVec<f64, N>; N],
        &[DualSVec<f64, N>; N],
    ) -> Result<[DualSVec<f64, N>; N]>,
) -> Result<([f64; N], SMatrix<f64, N, N>, SMatrix<f64, N, N>)> {
    let td = DualSVec::<f64, N>::from_re(t);
    let plain: [DualSVec<f64, N>; N] = std::array::from_fn(|j| DualSVec::from_re(v[j]));
    let by_q = f(td, &seeded(q), &plain)?;
    let plain_q: [DualSVec<f64, N>; N] = std::array::from_fn(|j| DualSVec::from_re(q[j]));
    let seeded_v = seeded(v);
    let by_v = f(td, &plain_q, &seeded_v)?;
    let value = std::array::from_fn(|i| by_q[i].re);
    Ok((value, jacobian_rows(&by_q), jacobian_rows(&by_v)))
}

/// `x` as gradient dual numbers, component j seeded with the j-th unit vector: evaluating a
/// function on them gives its value and, by [`jacobian_rows`], its exact Jacobian.
#[inline]
pub(crate) fn seeded<const N: usize>(x: &[f64; N]) -> [DualSVec<f64, N>; N] {
    std::array::from_fn(|j| DualSVec::from_re(x[j]).derivative(j))
}

/// The matrix whose row i is the gradient carried by `f[i]`.
pub fn jacobian_rows<const N: usize, const R: usize>(
    f: &[DualSVec<f64, N>; R],
) -> SMatrix<f64, R, N> {
    let mut m = SMatrix::<f64, R, N>::zeros();
    for (i, fi) in f.iter().enumerate() {
        if let Some(g) = &fi.eps.0 {
            for j in 0..N {
                m[(i, j)] = g[j];
            }
        }
    }
    m
}

/// ‖x‖∞.
pub fn max_norm<const N: usize>(x: &SVector<f64, N>) -> f64 {
    x.iter().fold(0.0f64, |m, v| m.max(v.abs()))
}

/// The unknowns of a Newton iteration: a vector, or the S stage vectors of a collocation method.
pub(crate) trait Unknowns: Copy {
    /// x ← x − δ, and the weighted norms (‖δ‖, ‖x‖) of the increment and of the new iterate (see
    /// [`weighted_norm`](Unknowns::weighted_norm)), in one pass.
    fn subtract_measured(&mut self, delta: &Self, weights: &Self) -> (f64, f64);
    /// maxᵢ |xᵢ|·wᵢ: the unknowns measured with weights w that make their components comparable
    /// (see [`NewtonScale`]).
    fn weighted_norm(&self, weights: &Self) -> f64;
}

impl<const N: usize> Unknowns for SVector<f64, N> {
    #[inline(always)]
    fn subtract_measured(&mut self, delta: &Self, weights: &Self) -> (f64, f64) {
        let (mut d, mut s) = (0.0f64, 0.0f64);
        for ((x, dx), w) in self.iter_mut().zip(delta.iter()).zip(weights.iter()) {
            *x -= dx;
            d = larger(d, dx.abs() * w);
            s = larger(s, x.abs() * w);
        }
        (d, s)
    }
    #[inline(always)]
    fn weighted_norm(&self, weights: &Self) -> f64 {
        self.iter()
            .zip(weights.iter())
            .fold(0.0f64, |m, (x, w)| larger(m, x.abs() * w))
    }
}

impl<const N: usize, const S: usize> Unknowns for [SVector<f64, N>; S] {
    #[inline(always)]
    fn subtract_measured(&mut self, delta: &Self, weights: &Self) -> (f64, f64) {
        let (mut d, mut s) = (0.0f64, 0.0f64);
        for ((x, dx), w) in self.iter_mut().zip(delta).zip(weights) {
            let (dj, sj) = x.subtract_measured(dx, w);
            d = larger(d, dj);
            s = larger(s, sj);
        }
        (d, s)
    }
    #[inline(always)]
    fn weighted_norm(&self, weights: &Self) -> f64 {
        self.iter()
            .zip(weights)
            .fold(0.0f64, |m, (x, w)| larger(m, x.weighted_norm(w)))
    }
}

/// max(m, x) for a running maximum m that is not NaN: a NaN x is passed over, as `f64::max`
/// passes it over, without that function's test of m.
#[inline(always)]
fn larger(m: f64, x: f64) -> f64 {
    if x > m {
        x
    } else {
        m
    }
}

/// What a Newton iteration's increments are measured against: weights wᵢ that give every
/// component of the unknowns the same unit (so the largest component is a meaningful size, and a
/// rescaled coordinate is measured alike), the least size the unknowns are measured against, and
/// the resolution of the equations: the size below which an increment is the rounding of the
/// residual's evaluation rather than an error of the iterate.
///
/// For velocity-like unknowns (stage velocities, the midpoint velocity) the weights are
/// wᵢ = √|Aᵢᵢ| with A the mass matrix or the Newton matrix whose leading part it is — wᵢ vᵢ then has
/// the unit √(kg)·m/s whatever coordinate i measures —, the size is that of the step's velocities
/// (at its start and the predictor's), and the resolution is [`position_floor`]: a step's
/// positions q₀ + h·v are computed to a rounding of the configuration's own size, and where the
/// equations contain positions (constraint rows g(q₁)/h) the velocities are resolved no better
/// than that over h.
#[derive(Clone, Copy, Debug)]
pub(crate) struct NewtonScale<U> {
    /// wᵢ.
    pub weights: U,
    /// The least size s the increments are measured against.
    pub size: f64,
    /// Increments below 1e-10 of this that stop shrinking are the residual's rounding.
    pub resolution: f64,
}

/// √|Mᵢᵢ| for each i: weights that make velocities of coordinates of any units comparable (see
/// [`NewtonScale`]).
pub(crate) fn mass_weights<const N: usize>(m: &SMatrix<f64, N, N>) -> SVector<f64, N> {
    SVector::from_fn(|i, _| m[(i, i)].abs().sqrt())
}

/// maxᵢ wᵢ|qᵢ| / |h|: with [`mass_weights`], the velocity (in those units) whose step h·v is the
/// size of the configuration q itself.
pub(crate) fn position_floor<const N: usize>(
    weights: &SVector<f64, N>,
    q: &SVector<f64, N>,
    h: f64,
) -> f64 {
    q.weighted_norm(weights) / h.abs()
}

/// How a Newton iteration ended.
#[derive(Clone, Copy, Debug)]
pub(crate) enum NewtonEnd {
    /// Converged: the iterations taken and the largest contraction factor θ = ‖δₖ‖/‖δₖ₋₁‖ seen
    /// above the round-off floor (0 when it converged in one iteration).
    Converged { iterations: usize, theta: f64 },
    /// The increments stopped shrinking (θ ≥ 1) or the iteration limit was reached, with this
    /// residual norm: the caller refreshes its Jacobian or reports
    /// [`Error::NewtonDiverged`](crate::Error::NewtonDiverged).
    Slow { iterations: usize, residual: f64 },
}

/// An increment below this multiple of the unknowns' size is the rounding of the residual's
/// evaluation (see [`newton`]).
const ROUNDING_INCREMENT: f64 = 64.0 * f64::EPSILON;

impl NewtonEnd {
    /// The iterations of a converged iteration; a slow one is [`Error::NewtonDiverged`] at t.
    pub(crate) fn converged(self, t: f64) -> Result<usize> {
        match self {
            NewtonEnd::Converged { iterations, .. } => Ok(iterations),
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
}

/// Counts the iterations of a Newton loop since `before` (`stats.newton_iterations` then) each of
/// which evaluated its exact Jacobian and factorised it.
pub(crate) fn count_exact_jacobians(stats: &mut Stats, before: usize) {
    let n = stats.newton_iterations - before;
    stats.jacobians += n;
    stats.factorizations += n;
}

/// [`Error::NewtonBreakdown`] of `method`'s step of h from t at Newton iteration `iteration`.
pub(crate) fn breakdown(
    method: &'static str,
    t: f64,
    h: f64,
    iteration: usize,
    reason: &str,
) -> Error {
    Error::NewtonBreakdown {
        method,
        t,
        h,
        iteration,
        reason: reason.to_string(),
    }
}

/// The one Newton loop of the implicit methods. `iteration(x)` evaluates the residual at x and
/// returns the increment δ (the solution of the Newton system, with an exact Jacobian or a reused
/// one) and the residual's norm; the loop applies x ← x − δ and tests convergence on the
/// increments (Hairer & Wanner, *Solving ODEs II*, §IV.8, (8.10)–(8.13)), with θₖ = ‖δₖ‖/‖δₖ₋₁‖,
/// every norm the weighted one of `scale` (asked for once, after the first iteration, so that a
/// driver can take its weights from the first Newton matrix):
///
/// - converged when ‖δₖ‖ ≤ 64ε·s (s = max(‖x‖, size), see [`NewtonScale`]: an increment within
///   the rounding of the residual's evaluation, which sums tens of terms — so an increment that
///   is that rounding, as when the predictor is exact, ends the iteration whatever its digits),
///   when the estimated remaining error θₖ/(1 − θₖ)·‖δₖ‖ is below 4ε·s, or when
///   ‖δₖ‖ ≤ 1e-10·max(s, resolution) and θₖ > ½ (the increments have reached the round-off floor
///   and only add noise): the methods are iterated to round-off, as their symmetry and
///   symplecticity require;
/// - the contraction θ it reports (the largest over the iterations) counts every θₖ whose
///   increment is above 1e-10·s, inside the floor too: a `resolution` far above the unknowns'
///   rounding (positions over a small h) must not hide a kept matrix that contracts slowly;
/// - slow when θₖ ≥ 1 above that floor (diverging, or a Jacobian too stale to contract) if
///   `stop_when_slow` (a simplified Newton iteration, whose caller then refreshes the Jacobian; an
///   exact Newton iteration may grow once before it converges quadratically), or after
///   `max_iterations`.
///
/// Every test compares quantities of one unit, so the iterations do not depend on the units the
/// mechanism is written in: rescaling a coordinate, the masses or time leaves them unchanged.
pub(crate) fn newton<U: Unknowns>(
    x: &mut U,
    max_iterations: usize,
    stop_when_slow: bool,
    stats: &mut super::Stats,
    mut scale: impl FnMut() -> NewtonScale<U>,
    mut iteration: impl FnMut(&U) -> Result<(U, f64)>,
) -> Result<NewtonEnd> {
    let mut test = ConvergenceTest {
        previous: f64::INFINITY,
        theta_max: 0.0,
        residual: f64::NAN,
        stop_when_slow,
    };
    let mut measure = None;
    for k in 1..=max_iterations {
        stats.newton_iterations += 1;
        // One call of `iteration` in the loop, which the compiler then inlines.
        let (delta, residual) = iteration(x)?;
        test.residual = residual;
        // The scale, asked for once, after the first iteration: a driver may take its weights
        // from it.
        let scale = &*measure.get_or_insert_with(&mut scale);
        if let Some(end) = test.end(k, x.subtract_measured(&delta, &scale.weights), scale) {
            return Ok(end);
        }
    }
    Ok(NewtonEnd::Slow {
        iterations: max_iterations,
        residual: test.residual,
    })
}

/// The state of [`newton`]'s tests between iterations: the last increment's norm, the largest
/// contraction measured, the last residual's norm.
struct ConvergenceTest {
    previous: f64,
    theta_max: f64,
    residual: f64,
    stop_when_slow: bool,
}

impl ConvergenceTest {
    /// The end of the iteration after iteration k, whose increment and new iterate have the
    /// weighted norms `(d, norm)`, if it ends there (see [`newton`]).
    #[inline(always)]
    fn end<U>(
        &mut self,
        k: usize,
        (d, norm): (f64, f64),
        scale: &NewtonScale<U>,
    ) -> Option<NewtonEnd> {
        let s = norm.max(scale.size);
        let theta = d / self.previous;
        let floor = d <= 1e-10 * s.max(scale.resolution);
        // An increment above 1e-10 of the unknowns' own size is far from their rounding: its θ
        // measures the contraction (what the caller's Jacobian reuse is decided on) even where the
        // equations' resolution already lets the iteration stop at the floor.
        let measured = d > 1e-10 * s;
        if d <= ROUNDING_INCREMENT * s
            || (k > 1 && theta < 1.0 && theta / (1.0 - theta) * d <= 4.0 * f64::EPSILON * s)
            || (floor && theta > 0.5)
        {
            // θ of an increment at the rounding level is that rounding over the last increment:
            // no measure of the contraction.
            if (!floor || theta <= 0.5) && d > ROUNDING_INCREMENT * s {
                self.theta_max = self.theta_max.max(if k == 1 { 0.0 } else { theta });
            }
            return Some(NewtonEnd::Converged {
                iterations: k,
                theta: self.theta_max,
            });
        }
        if k > 1 && !floor && self.stop_when_slow && !(theta < 1.0) {
            return Some(NewtonEnd::Slow {
                iterations: k,
                residual: self.residual,
            });
        }
        if k > 1 && measured {
            self.theta_max = self.theta_max.max(theta);
        }
        self.previous = d;
        None
    }
}

/// Whether the methods on the canonical equations (implicit midpoint, Gauss–Legendre) add the
/// generalized constraint force Jᵀλ = M q̈ − (𝓕 − b) to ṗ at every stage: unless the mechanism
/// declares no constraint rows (`Dynamics::CONSTRAINTS` = `Some(0)`). A constant of the
/// mechanism, never a test of λ at some state: a constraint whose force vanishes at the start of a
/// step (a pendulum released horizontally) still acts at the stages; for an implementation that
/// does not declare its constraints the term is added too (it is zero, to round-off, without
/// constraints).
pub(crate) const fn carries_constraint_forces<M: Evaluate<N>, const N: usize>() -> bool {
    !matches!(M::CONSTRAINTS, Some(0))
}

/// Refuses a declaration with unilateral or friction rows for a method stepped on raw arrays
/// ([`Integrator::advance`](super::Integrator::advance)) without its contact mode held: the mode
/// switches inside a step, where a collocation polynomial has no switch to follow, so the Newton
/// iteration would chase a discontinuous field. Decided by the declaration
/// (`Dynamics::CONSTRAINT_COUNTS`, a constant), never by a state. The time loops
/// ([`Stepper`](super::Stepper), `sys.step`) hold the mode over each step and hand the method the
/// mechanism in that mode, which has no such rows.
pub(crate) fn refuse_contacts<M: Evaluate<N>, const N: usize>(method: &'static str) -> Result<()> {
    match M::CONSTRAINT_COUNTS {
        Some(c) if c.unilateral + c.friction > 0 => Err(crate::Error::UnsuitableMethod {
            method,
            reason: format!(
                "the declaration has {} unilateral and {} friction rows, whose contact mode switches \
                 inside a step; a Stepper or sys.step holds the mode over each step and locates its \
                 switches",
                c.unilateral, c.friction
            ),
        }),
        _ => Ok(()),
    }
}

/// Refuses a mechanism with quasi-velocities (`quasi`: `Dynamics::QUASI_VELOCITIES`, a free or
/// ball joint whose velocities are its angular velocity) for a method built on q̇ = v that does not
/// convert: Störmer–Verlet advances q by v (and wants a constant mass matrix, which the rates of a
/// chart do not have). Decided by the declaration, never by a state. The explicit Runge–Kutta
/// methods step q̇ = G(q) v; the methods on momenta conjugate to q̇ and Radau5 step the rates
/// between conversions.
pub(crate) fn refuse_quasi_velocities(method: &'static str, quasi: bool) -> Result<()> {
    match quasi {
        true => Err(crate::Error::UnsuitableMethod {
            method,
            reason: "the declaration's velocities include a free or ball joint's angular velocity \
                     (`#[angular_velocity]`), which is not the rate of its coordinates; step it \
                     with Rk4, Dopri5, Dop853, Radau5, ImplicitMidpoint, GaussLegendre2 or \
                     Variational, \
                     or declare the coordinates without `#[angular_velocity]` (their velocities \
                     then are the chart's rates)"
                .to_string(),
        }),
        false => Ok(()),
    }
}

/// The simplified Newton iteration's factorised matrix, reused across its iterations and steps.
pub use crate::linalg::BlockLu;
