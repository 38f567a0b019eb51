//! Equilibria: q* with 𝓕 − b = 0 at rest, by Newton's method with a backtracking line search.

use super::line_search::{backtrack, descent_direction};
use super::{check_configuration, describe, max_abs, rest_residual, rest_terms};
use crate::error::{Error, Result};
use crate::mechanism::Mechanism;
use crate::model::Coordinates;
use nalgebra::{SMatrix, SVector};

/// How [`equilibrium`] iterates and when it stops.
///
/// ```
/// use lagrange_core::analysis::{equilibrium, EquilibriumOptions};
/// use lagrange_core::Error;
/// # use lagrange_core::analysis::doc_models::Pendulum;
/// let p = Pendulum { m: 1.0, l: 1.0, g: 9.81 };
/// let one_step = EquilibriumOptions { max_iterations: 1, ..Default::default() };
/// assert!(matches!(equilibrium(&p, 0.0, &[1.0], &one_step), Err(Error::EquilibriumNotFound { .. })));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EquilibriumOptions {
    /// At most this many Newton iterations (each one Jacobian and a few residuals).
    pub max_iterations: usize,
    /// Converged when ‖𝓕 − b‖∞ ≤ `residual_tolerance` · (‖𝓕‖∞ + ‖b‖∞ + (‖∂𝓕/∂q‖∞ + ‖∂b/∂q‖∞)·max(1,
    /// ‖q‖∞)) at rest (or exactly zero): the residual is as small as the terms that cancel in it, and
    /// the force a displacement of the size of q would bring, allow to resolve. Near a regular root
    /// q is then within about `residual_tolerance`·max(1, ‖q‖∞) times the ratio of those terms'
    /// stiffness to the net stiffness K (which is small where K nearly cancels, near a bifurcation).
    pub residual_tolerance: f64,
    /// Converged when the Newton step δq has ‖δq‖∞ ≤ `step_tolerance` · max(1, ‖q‖∞); the step is
    /// taken. Near a regular root Newton converges quadratically, so the error left after such a
    /// step is of order δq². (This also ends the iteration when the residual is at rounding level
    /// and the line search can no longer decrease it.)
    pub step_tolerance: f64,
}

impl EquilibriumOptions {
    /// Checks the tolerances ([`Error::InvalidSetting`] naming the first one out of range): each
    /// finite and in [0, 1). Both are relative, so a tolerance of 1 or more would accept a residual
    /// as large as the forces it is measured against, or a Newton step as large as q itself: a
    /// point that is not an equilibrium. (Zero is allowed: then only an exactly zero residual or
    /// step ends the iteration, or `max_iterations` does.)
    ///
    /// ```
    /// use lagrange_core::analysis::EquilibriumOptions;
    /// assert!(EquilibriumOptions::default().validate().is_ok());
    /// let loose = EquilibriumOptions { residual_tolerance: f64::INFINITY, ..Default::default() };
    /// assert!(loose.validate().is_err());
    /// ```
    pub fn validate(&self) -> Result<()> {
        for (setting, value) in [
            ("residual_tolerance", self.residual_tolerance),
            ("step_tolerance", self.step_tolerance),
        ] {
            if !(0.0..1.0).contains(&value) {
                return Err(Error::InvalidSetting {
                    method: "equilibrium",
                    setting,
                    value,
                    requirement: "finite and in [0, 1)",
                });
            }
        }
        Ok(())
    }
}

impl Default for EquilibriumOptions {
    /// 100 iterations; residual tolerance 1e-14 (some tens of ulps of the terms it is measured
    /// against: an early exit when the residual is at rounding level); step tolerance 1e-12 (the
    /// criterion that usually ends the iteration, one step before the residual is at rounding level).
    fn default() -> Self {
        EquilibriumOptions {
            max_iterations: 100,
            residual_tolerance: 1e-14,
            step_tolerance: 1e-12,
        }
    }
}

/// An equilibrium found by [`equilibrium`].
///
/// ```
/// use lagrange_core::analysis::{equilibrium, EquilibriumOptions};
/// # use lagrange_core::analysis::doc_models::Pendulum;
/// let p = Pendulum { m: 2.0, l: 0.5, g: 9.81 };
/// let eq = equilibrium(&p, 0.0, &[3.0], &EquilibriumOptions::default())?;
/// // The top: K = −m g l (a maximum of V).
/// assert!((eq.q[0] - std::f64::consts::PI).abs() < 1e-12);
/// assert!((eq.stiffness[(0, 0)] + 2.0 * 9.81 * 0.5).abs() < 1e-12);
/// assert!(eq.iterations > 0 && eq.residual < 1e-12);
/// # Ok::<(), lagrange_core::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Equilibrium<C, const N: usize> {
    /// The time it is an equilibrium at (matters for rheonomic mechanisms only).
    pub t: f64,
    /// q*.
    pub q: C,
    /// ‖𝓕 − b‖∞ at q*, at rest.
    pub residual: f64,
    /// Newton iterations taken (0 when the guess already was an equilibrium).
    pub iterations: usize,
    /// The stiffness matrix K = ∂(b − 𝓕)/∂q at q*, at rest (the Hessian of V for conservative
    /// forces on a scleronomic mechanism); see [`stability`](super::stability()) for what it means.
    pub stiffness: SMatrix<f64, N, N>,
}

/// The generalized forces left unbalanced at rest: 𝓕(q, 0, t) − b(q, 0, t), by name.
///
/// By the principle of virtual work (lecture eq. (5)) every component vanishes exactly at an
/// equilibrium. For a rheonomic mechanism −b at rest is the generalized inertial force of the moving
/// frame (centrifugal force on a bead on a spinning hoop, the d'Alembert force in an accelerating
/// frame), so this is the virtual work per unit δqₖ in that frame.
///
/// ```
/// use lagrange_core::analysis::unbalanced_forces;
/// # use lagrange_core::analysis::doc_models::Pendulum;
/// let p = Pendulum { m: 2.0, l: 1.5, g: 9.81 };
/// // 𝓕_θ = −m g l sin θ.
/// let f = unbalanced_forces(&p, 0.0, &[0.3])?;
/// assert!((f[0] + 2.0 * 9.81 * 1.5 * 0.3f64.sin()).abs() < 1e-12);
/// # Ok::<(), lagrange_core::Error>(())
/// ```
pub fn unbalanced_forces<M: Mechanism<N>, const N: usize>(
    mechanism: &M,
    t: f64,
    q: &M::Coords,
) -> Result<M::Coords> {
    let q = check_configuration(mechanism, t, q)?;
    let r = rest_residual(mechanism, t, &q);
    if r.iter().all(|x| x.is_finite()) {
        Ok(M::Coords::from_array(r.into()))
    } else {
        Err(Error::NonFiniteDynamics {
            t,
            configuration: describe::<M, N>(&q),
        })
    }
}

/// Finds an equilibrium q* near `q_guess` at time `t`: all generalized forces balanced at rest,
/// 𝓕(q*, 0, t) − b(q*, 0, t) = 0 (see [`unbalanced_forces`]).
///
/// The method is Newton's method on r(q) = 𝓕 − b with the exact Jacobian ∂r/∂q = −K from dual
/// numbers, globalized by a backtracking (Armijo) line search on the merit function ½‖r‖²
/// (Nocedal & Wright, *Numerical Optimization*, 2nd ed., 2006, Alg. 3.1 and §11.2, line-search
/// Newton with the merit function ½‖r‖²). The Newton direction p = −J⁻¹r is always a descent direction of ½‖r‖²
/// (its slope is −‖r‖²); where J is singular (a fold, a bifurcation point, a neutral direction) the
/// steepest-descent direction −Jᵀr is used instead. Which equilibrium is found depends on the
/// guess — minima and maxima of V alike; classify it with [`stability`](super::stability()).
///
/// Errors: invalid options ([`EquilibriumOptions::validate`]); non-finite parameters or guess;
/// [`Error::NonFiniteDynamics`] when the forces are not
/// finite at the guess; [`Error::EquilibriumNotFound`] (naming the last iterate and its residual)
/// when the iteration does not converge in `options.max_iterations`, the line search stalls (a
/// local minimum of ½‖r‖² that is not a root, or a singular Jacobian with Jᵀr = 0), or the
/// iterates run into a configuration where the forces are not finite. The guess is never modified.
///
/// ```
/// use lagrange_core::analysis::{equilibrium, EquilibriumOptions};
/// # use lagrange_core::analysis::doc_models::SpinningHoop;
/// // A bead on a hoop (radius R) spinning about its vertical diameter at ω with ω² > g/R sits at
/// // cos θ* = g/(ω²R).
/// let hoop = SpinningHoop { m: 0.1, r: 0.5, g: 9.81, omega: 6.0 };
/// let eq = equilibrium(&hoop, 0.0, &[1.0], &EquilibriumOptions::default())?;
/// assert!((eq.q[0].cos() - 9.81 / (36.0 * 0.5)).abs() < 1e-12);
/// # Ok::<(), lagrange_core::Error>(())
/// ```
pub fn equilibrium<M: Mechanism<N>, const N: usize>(
    mechanism: &M,
    t: f64,
    q_guess: &M::Coords,
    options: &EquilibriumOptions,
) -> Result<Equilibrium<M::Coords, N>> {
    options.validate()?;
    let mut q = SVector::<f64, N>::from(check_configuration(mechanism, t, q_guess)?);
    let not_found =
        |iterations: usize, residual: f64, q: &SVector<f64, N>| Error::EquilibriumNotFound {
            t,
            iterations,
            residual,
            configuration: describe::<M, N>(&(*q).into()),
        };
    let mut terms = rest_terms(mechanism, t, &q.into());
    let finite = |r: &SVector<f64, N>| r.iter().all(|x| x.is_finite());
    if !finite(&terms.residual) || !terms.stiffness.iter().all(|x| x.is_finite()) {
        return Err(Error::NonFiniteDynamics {
            t,
            configuration: describe::<M, N>(&q.into()),
        });
    }
    let done = |q: &SVector<f64, N>, terms: &super::RestTerms<N>, iterations: usize| Equilibrium {
        t,
        q: M::Coords::from_array((*q).into()),
        residual: max_abs(terms.residual.iter()),
        iterations,
        stiffness: terms.stiffness,
    };
    let mut iterations = 0;
    loop {
        let r = terms.residual;
        let r_norm = max_abs(r.iter());
        if r_norm == 0.0 || r_norm <= options.residual_tolerance * terms.residual_scale {
            return Ok(done(&q, &terms, iterations));
        }
        if iterations >= options.max_iterations {
            return Err(not_found(iterations, r_norm, &q));
        }
        iterations += 1;

        // J = ∂r/∂q = −K; the merit function f = ½‖r‖² has gradient Jᵀr.
        let jac = -terms.stiffness;
        let grad = jac.transpose() * r;
        let merit = 0.5 * r.norm_squared();
        let newton =
            crate::linalg::lu_solve(&jac, &(-r)).filter(|p| p.iter().all(|x| x.is_finite()));
        let Some((direction, slope, is_newton)) =
            descent_direction(newton, &grad, r.norm_squared())
        else {
            return Err(not_found(iterations, r_norm, &q));
        };

        if is_newton
            && max_abs(direction.iter()) <= options.step_tolerance * max_abs(q.iter()).max(1.0)
        {
            q += direction;
            terms = rest_terms(mechanism, t, &q.into());
            return Ok(done(&q, &terms, iterations));
        }

        let accepted = backtrack(merit, slope, |alpha| {
            let trial = q + direction * alpha;
            (trial, rest_residual(mechanism, t, &trial.into()))
        });
        let Some(next) = accepted else {
            return Err(not_found(iterations, r_norm, &q));
        };
        q = next;
        terms = rest_terms(mechanism, t, &q.into());
        if !finite(&terms.residual) || !terms.stiffness.iter().all(|x| x.is_finite()) {
            return Err(not_found(iterations, f64::NAN, &q));
        }
    }
}
