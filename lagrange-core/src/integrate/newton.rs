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
    /// x ← x − δ.
    fn subtract(&mut self, delta: &Self);
    /// ‖x‖∞.
    fn max_norm(&self) -> f64;
}

impl<const N: usize> Unknowns for SVector<f64, N> {
    fn subtract(&mut self, delta: &Self) {
        *self -= delta;
    }
    fn max_norm(&self) -> f64 {
        max_norm(self)
    }
}

impl<const N: usize, const S: usize> Unknowns for [SVector<f64, N>; S] {
    fn subtract(&mut self, delta: &Self) {
        for (x, d) in self.iter_mut().zip(delta) {
            *x -= d;
        }
    }
    fn max_norm(&self) -> f64 {
        self.iter().fold(0.0f64, |m, x| m.max(max_norm(x)))
    }
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
/// increments (Hairer & Wanner, *Solving ODEs II*, §IV.8, (8.10)–(8.13)), with θₖ = ‖δₖ‖/‖δₖ₋₁‖:
///
/// - converged when ‖δₖ‖ ≤ 4ε·s (s = max(1, ‖x‖)), when the estimated remaining error
///   θₖ/(1 − θₖ)·‖δₖ‖ is below 4ε·s, or when ‖δₖ‖ ≤ 1e-10·s and θₖ > ½ (the increments have reached
///   the round-off floor of the residual evaluation and only add noise): the methods are iterated
///   to round-off, as their symmetry and symplecticity require;
/// - slow when θₖ ≥ 1 above that floor (diverging, or a Jacobian too stale to contract) if
///   `stop_when_slow` (a simplified Newton iteration, whose caller then refreshes the Jacobian; an
///   exact Newton iteration may grow once before it converges quadratically), or after
///   `max_iterations`.
pub(crate) fn newton<U: Unknowns>(
    x: &mut U,
    max_iterations: usize,
    stop_when_slow: bool,
    stats: &mut super::Stats,
    mut iteration: impl FnMut(&U) -> Result<(U, f64)>,
) -> Result<NewtonEnd> {
    let mut previous = f64::INFINITY;
    let mut theta_max = 0.0f64;
    let mut residual = f64::NAN;
    for k in 1..=max_iterations {
        stats.newton_iterations += 1;
        let (delta, r) = iteration(x)?;
        residual = r;
        x.subtract(&delta);
        let d = delta.max_norm();
        let s = x.max_norm().max(1.0);
        let theta = d / previous;
        let floor = d <= 1e-10 * s;
        if d <= 4.0 * f64::EPSILON * s
            || (k > 1 && theta < 1.0 && theta / (1.0 - theta) * d <= 4.0 * f64::EPSILON * s)
            || (floor && theta > 0.5)
        {
            if !floor || theta <= 0.5 {
                theta_max = theta_max.max(if k == 1 { 0.0 } else { theta });
            }
            return Ok(NewtonEnd::Converged {
                iterations: k,
                theta: theta_max,
            });
        }
        if k > 1 && !floor {
            if stop_when_slow && !(theta < 1.0) {
                return Ok(NewtonEnd::Slow {
                    iterations: k,
                    residual,
                });
            }
            theta_max = theta_max.max(theta);
        }
        previous = d;
    }
    Ok(NewtonEnd::Slow {
        iterations: max_iterations,
        residual,
    })
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

/// An LU factorisation with partial pivoting of a matrix of S×S blocks of size N×N (an
/// (S·N)-square matrix; stable Rust cannot name S·N as an array length, so the blocks are
/// indexed through r ↦ (r / N, r % N)): factorised once, solved many times — the simplified Newton
/// iteration's matrix.
#[derive(Clone, Copy, Debug)]
pub struct BlockLu<const N: usize, const S: usize> {
    lu: [[SMatrix<f64, N, N>; S]; S],
    pivots: [[usize; N]; S],
}

impl<const N: usize, const S: usize> BlockLu<N, S> {
    #[inline(always)]
    fn get(&self, r: usize, c: usize) -> f64 {
        self.lu[r / N][c / N][(r % N, c % N)]
    }

    #[inline(always)]
    fn set(&mut self, r: usize, c: usize, x: f64) {
        self.lu[r / N][c / N][(r % N, c % N)] = x;
    }

    /// Factorises `a`; `None` when it is not finite or a pivot is below
    /// [`SINGULAR_PIVOT`](crate::linalg::SINGULAR_PIVOT) times its largest entry.
    pub fn factor(a: &[[SMatrix<f64, N, N>; S]; S]) -> Option<Self> {
        let mut f = BlockLu {
            lu: *a,
            pivots: [[0; N]; S],
        };
        let dim = N * S;
        let mut scale = 0.0f64;
        for r in 0..dim {
            for c in 0..dim {
                scale = scale.max(f.get(r, c).abs());
            }
        }
        if !scale.is_finite() {
            return None;
        }
        let tol = crate::linalg::SINGULAR_PIVOT * scale;
        for c in 0..dim {
            let mut p = c;
            for r in (c + 1)..dim {
                if f.get(r, c).abs() > f.get(p, c).abs() {
                    p = r;
                }
            }
            let pivot = f.get(p, c);
            if !(pivot.abs() > tol) {
                return None;
            }
            f.pivots[c / N][c % N] = p;
            // Rows are swapped from column c on only (LINPACK's convention): the multipliers of
            // the earlier columns stay where they were made, in the order in which `solve`
            // applies the interchanges, interleaved with the elimination.
            if p != c {
                for k in c..dim {
                    let (u, w) = (f.get(p, k), f.get(c, k));
                    f.set(p, k, w);
                    f.set(c, k, u);
                }
            }
            let inv = 1.0 / pivot;
            for r in (c + 1)..dim {
                let m = f.get(r, c) * inv;
                f.set(r, c, m);
                if m != 0.0 {
                    for k in (c + 1)..dim {
                        let x = f.get(r, k) - m * f.get(c, k);
                        f.set(r, k, x);
                    }
                }
            }
        }
        Some(f)
    }

    /// Solves A x = b with the factorisation.
    pub fn solve(&self, b: &[SVector<f64, N>; S]) -> [SVector<f64, N>; S] {
        let dim = N * S;
        let mut x = *b;
        for c in 0..dim {
            let p = self.pivots[c / N][c % N];
            if p != c {
                let (u, w) = (x[p / N][p % N], x[c / N][c % N]);
                x[p / N][p % N] = w;
                x[c / N][c % N] = u;
            }
            let xc = x[c / N][c % N];
            if xc != 0.0 {
                for r in (c + 1)..dim {
                    x[r / N][r % N] -= self.get(r, c) * xc;
                }
            }
        }
        for r in (0..dim).rev() {
            let mut s = x[r / N][r % N];
            for k in (r + 1)..dim {
                s -= self.get(r, k) * x[k / N][k % N];
            }
            x[r / N][r % N] = s / self.get(r, r);
        }
        x
    }
}

#[cfg(test)]
mod tests {
    use super::BlockLu;
    use nalgebra::{SMatrix, SVector};

    #[test]
    fn block_lu_solves_with_interchanges_in_several_columns() {
        // A 4×4 matrix (2×2 blocks of 2×2) whose partial pivoting swaps rows at columns 0 and 1
        // (pivots 1, 3, 2, 3): the solve must apply the interchanges in the order the
        // factorisation made them. Checked against nalgebra's dense LU.
        let a = [
            [
                SMatrix::<f64, 2, 2>::new(992660.25, -1000031.54, -999952.69, 992611.94),
                SMatrix::<f64, 2, 2>::new(-56580.37, 35.89, -53.83, -56526.54),
            ],
            [
                SMatrix::<f64, 2, 2>::new(56580.37, -35.89, 53.83, 56526.54),
                SMatrix::<f64, 2, 2>::new(992660.25, -1000031.54, -999952.69, 992611.94),
            ],
        ];
        let mut dense = SMatrix::<f64, 4, 4>::zeros();
        for r in 0..4 {
            for c in 0..4 {
                dense[(r, c)] = a[r / 2][c / 2][(r % 2, c % 2)];
            }
        }
        let b = [SVector::from([1.0, 2.0]), SVector::from([3.0, 4.0])];
        let x = BlockLu::factor(&a).unwrap().solve(&b);
        let expected = dense
            .lu()
            .solve(&SVector::<f64, 4>::from([1.0, 2.0, 3.0, 4.0]))
            .unwrap();
        for r in 0..4 {
            // The matrix's condition number is about 40: both solves agree to ~1e-14 relative.
            let got = x[r / 2][r % 2];
            assert!(
                (got - expected[r]).abs() < 1e-12 * expected.amax(),
                "{got} vs {}",
                expected[r]
            );
        }
    }
}
