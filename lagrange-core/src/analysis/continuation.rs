//! Equilibrium branches over a parameter, by natural-parameter continuation.

use super::equilibrium::{equilibrium, Equilibrium, EquilibriumOptions};
use super::stability::{stability, Stability};
use crate::error::Error;
use crate::mechanism::Mechanism;

/// One point of an equilibrium branch.
///
/// ```
/// use lagrange_core::analysis::{continuation, EquilibriumOptions, Stability};
/// # use lagrange_core::analysis::doc_models::SpinningHoop;
/// // The bottom of the hoop (g/R = 19.62) loses stability as the spin passes √(g/R) ≈ 4.43.
/// let branch = continuation(
///     |omega| SpinningHoop { m: 0.1, r: 0.5, g: 9.81, omega },
///     &[3.0, 6.0], 0.0, &[0.0], &EquilibriumOptions::default(),
/// );
/// let verdicts: Vec<Stability> = branch.points.iter().map(|p| p.stability).collect();
/// assert_eq!(verdicts, [Stability::Stable, Stability::Unstable]);
/// assert_eq!(branch.points[1].equilibrium.q, [0.0]);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BranchPoint<C, const N: usize> {
    /// The parameter value.
    pub parameter: f64,
    /// The equilibrium found for it.
    pub equilibrium: Equilibrium<C, N>,
    /// Its stability (see [`stability`](super::stability())).
    pub stability: Stability,
}

/// An equilibrium branch traced by [`continuation`].
///
/// ```
/// use lagrange_core::analysis::{continuation, EquilibriumOptions};
/// use lagrange_core::Error;
/// # use lagrange_core::analysis::doc_models::SpinningHoop;
/// // Following the off-bottom equilibrium to slower spins: it merges into the bottom at √(g/R),
/// // and the branch goes on there.
/// let branch = continuation(
///     |omega| SpinningHoop { m: 0.1, r: 0.5, g: 9.81, omega },
///     &[6.0, 5.0, 4.0], 0.0, &[1.0], &EquilibriumOptions::default(),
/// );
/// assert!(branch.stopped.is_none());
/// assert!(branch.points[2].equilibrium.q[0].abs() < 1e-12);
/// // A branch that cannot start reports where and why.
/// let none = continuation(
///     |omega| SpinningHoop { m: 0.1, r: 0.5, g: f64::NAN, omega },
///     &[6.0], 0.0, &[1.0], &EquilibriumOptions::default(),
/// );
/// assert!(matches!(none.stopped, Some((6.0, Error::NonFiniteParameter { .. }))));
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Branch<C, const N: usize> {
    /// The points found, in the order of the parameter values given.
    pub points: Vec<BranchPoint<C, N>>,
    /// Where and why the branch stopped early: the first parameter value for which no equilibrium
    /// (or no stability verdict) was found, and the error. `None` when every value was reached.
    /// A branch typically ends at a fold (turning point), where no nearby equilibrium exists.
    pub stopped: Option<(f64, Error)>,
}

/// Traces a branch of equilibria over a parameter: for each value p in `parameters`, in order,
/// builds the mechanism with `build(p)` and solves for its equilibrium with [`equilibrium`],
/// warm-started from the previous point of the branch (the first from `q_start`). This is
/// natural-parameter continuation with the trivial predictor (E. L. Allgower & K. Georg,
/// *Introduction to Numerical Continuation Methods*, SIAM, 2003); steps must be small enough
/// that the previous equilibrium lies in the basin of Newton's method for the next one, and the
/// branch cannot be followed around a fold in the parameter. Each point carries its
/// [`Stability`], so an exchange of stability (a pitchfork bifurcation) is visible in the result.
///
/// Stops at the first failure and reports it in [`Branch::stopped`], keeping the points found.
///
/// ```
/// use lagrange_core::analysis::{continuation, EquilibriumOptions, Stability};
/// # use lagrange_core::analysis::doc_models::SpinningHoop;
/// // The off-bottom equilibrium of a bead on a hoop (g/R = 19.62) as the spin slows from ω = 8 to 4.5.
/// let omegas: Vec<f64> = (0..8).map(|i| 8.0 - 0.5 * i as f64).collect();
/// let branch = continuation(
///     |omega| SpinningHoop { m: 0.1, r: 0.5, g: 9.81, omega },
///     &omegas, 0.0, &[1.2], &EquilibriumOptions::default(),
/// );
/// assert!(branch.stopped.is_none());
/// for point in &branch.points {
///     let cos_theta = 9.81 / (point.parameter.powi(2) * 0.5);
///     assert!((point.equilibrium.q[0].cos() - cos_theta).abs() < 1e-12);
///     assert_eq!(point.stability, Stability::Stable);
/// }
/// ```
pub fn continuation<M, F, const N: usize>(
    mut build: F,
    parameters: &[f64],
    t: f64,
    q_start: &M::Coords,
    options: &EquilibriumOptions,
) -> Branch<M::Coords, N>
where
    M: Mechanism<N>,
    F: FnMut(f64) -> M,
{
    let mut points: Vec<BranchPoint<M::Coords, N>> = Vec::with_capacity(parameters.len());
    let mut guess = *q_start;
    for &parameter in parameters {
        let mechanism = build(parameter);
        let point = equilibrium(&mechanism, t, &guess, options)
            .and_then(|eq| stability(&mechanism, t, &eq.q).map(|s| (eq, s.stability)));
        match point {
            Ok((equilibrium, stability)) => {
                guess = equilibrium.q;
                points.push(BranchPoint {
                    parameter,
                    equilibrium,
                    stability,
                });
            }
            Err(error) => {
                return Branch {
                    points,
                    stopped: Some((parameter, error)),
                }
            }
        }
    }
    Branch {
        points,
        stopped: None,
    }
}
