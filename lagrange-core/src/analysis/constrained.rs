//! Equilibria of constrained mechanisms: q* and the constraint forces λ that hold it, from the
//! Lagrange conditions at rest, and their stability on the tangent space of the constraints.
//!
//! The method, which constraint rows take part and the stability criterion are documented on
//! [`constrained_equilibrium`].

mod kkt;
mod newton;
mod tangent;

use super::MARGINAL_TOLERANCE;
use super::{check_configuration, describe, max_abs, EquilibriumOptions, Stability};
use crate::constraints::{rows_and_scales, ConstraintKind, Constraints, CONSISTENCY_TOLERANCE};
use crate::error::{Error, Result};
use crate::mechanism::Mechanism;
use crate::model::Coordinates;
use kkt::{check_independent, position_terms, trial_residual};
use nalgebra::SMatrix;
use newton::{newton, Solved};
use tangent::tangent_stability;

/// An equilibrium of a constrained mechanism, found by [`constrained_equilibrium`].
///
/// ```
/// use lagrange_core::analysis::{constrained_equilibrium, EquilibriumOptions, Stability};
/// # use lagrange_core::analysis::doc_models::CartesianPendulum;
/// // A pendulum in Cartesian coordinates (x, y), the rod |r| − l = 0 as a constraint.
/// let p = CartesianPendulum { m: 2.0, l: 0.5, g: 9.81 };
/// let eq = constrained_equilibrium(&p, 0.0, &[0.1, -0.3], &EquilibriumOptions::default())?;
/// assert!(eq.q[0].abs() < 1e-12 && (eq.q[1] + 0.5).abs() < 1e-12);
/// // The multiplier of |r| − l is minus the rod tension m g.
/// assert!((eq.multiplier("rod").unwrap() + 2.0 * 9.81).abs() < 1e-12);
/// assert_eq!(eq.stability, Stability::Stable);
/// assert!((eq.tangent_eigenvalues[0] - 9.81 / 0.5).abs() < 1e-10); // ω² = g/l
/// # Ok::<(), lagrange_core::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct ConstrainedEquilibrium<Q, const N: usize, const C: usize> {
    /// The time it is an equilibrium at.
    pub t: f64,
    /// q*.
    pub q: Q,
    /// λᵢ, in declaration order: the generalized constraint force of row i is λᵢ·∇gᵢ, in the sign
    /// convention of [`crate::constraints`] (a unilateral row pushes with λ ≥ 0). Zero for rows not
    /// enforced (released contacts, friction rows).
    pub multipliers: [f64; C],
    /// The row names ([`Constraints::NAMES`]), in the same order.
    pub names: [&'static str; C],
    /// Which rows were enforced at q*.
    pub active: [bool; C],
    /// ‖𝓕 − b + Gᵀλ‖∞ at q*, at rest: the generalized forces left unbalanced.
    pub residual: f64,
    /// max |gᵢ(q*, t)| over the enforced rows.
    pub constraint_residual: f64,
    /// Newton iterations taken, summed over the active-set passes.
    pub iterations: usize,
    /// K = ∂(b − 𝓕)/∂q at q*, at rest, without the constraint curvature.
    pub stiffness: SMatrix<f64, N, N>,
    /// The verdict of the tangent-space analysis (see the docs of [`constrained_equilibrium`]).
    pub stability: Stability,
    /// Eigenvalues of Zᵀ(K − Σλᵢ∇²gᵢ)Z relative to ZᵀMZ, ascending, one per degree of freedom left
    /// by the enforced rows (N − m of them): the squared frequencies ω² of small oscillations
    /// about a stable equilibrium.
    pub tangent_eigenvalues: Vec<f64>,
}

impl<Q, const N: usize, const C: usize> ConstrainedEquilibrium<Q, N, C> {
    /// The multiplier of the row called `name`, or `None` when there is no such row.
    ///
    /// ```
    /// use lagrange_core::analysis::{constrained_equilibrium, EquilibriumOptions};
    /// # use lagrange_core::analysis::doc_models::CartesianPendulum;
    /// let p = CartesianPendulum { m: 1.0, l: 1.0, g: 9.81 };
    /// // Near the top the rod is compressed: λ = +m g.
    /// let eq = constrained_equilibrium(&p, 0.0, &[0.2, 0.9], &EquilibriumOptions::default())?;
    /// assert!((eq.multiplier("rod").unwrap() - 9.81).abs() < 1e-12);
    /// assert_eq!(eq.multiplier("string"), None);
    /// # Ok::<(), lagrange_core::Error>(())
    /// ```
    pub fn multiplier(&self, name: &str) -> Option<f64> {
        self.names
            .iter()
            .position(|n| *n == name)
            .map(|i| self.multipliers[i])
    }
}

/// Finds an equilibrium of a constrained mechanism near `q_guess` at time `t`: q* on the enforced
/// constraints and multipliers λ with 𝓕(q*, 0, t) − b(q*, 0, t) + G(q*, t)ᵀλ = 0, g(q*, t) = 0.
///
/// Newton's method on (q, λ) with exact derivatives from dual numbers and a backtracking line
/// search on ½‖F‖²; the initial λ is the least-squares balance at the guess. The guess need not lie
/// on the constraints. Which rows are enforced (holonomic always; unilateral by an active-set loop;
/// friction ignored; velocity rows refused) and what the stability verdict means: see below. The
/// options are those of [`equilibrium`](super::equilibrium()), with the residual criterion
/// applied to the force rows (against the terms that cancel in them, the constraint forces
/// included) and to each constraint row (against ‖∇gᵢ‖₁·max(1, ‖q‖∞), the change of gᵢ over a
/// displacement of the size of q), and the step criterion to δq and to δλ (against
/// max(‖λ‖∞, force scale / ‖∇g‖)).
///
/// # Equations
///
/// With the constraint forces of [`crate::constraints`] (M q̈ = 𝓕 − b + Gᵀλ, G = ∂g/∂q), a
/// configuration q* is an equilibrium of the constrained mechanism when, at rest (q̇ = 0),
///
/// ```text
/// F(q, λ) = [ 𝓕(q, 0, t) − b(q, 0, t) + G(q, t)ᵀ λ ]  = 0      (N equations: the forces balance)
///           [ g(q, t)                              ]         (m equations: on the constraints)
/// ```
///
/// for some multipliers λ, one per enforced row: the principle of virtual work with the virtual
/// displacements restricted to G δq = 0 (the lecture's eq. (5) with the constraint forces doing no
/// virtual work), written with Lagrange multipliers (Goldstein, Poole & Safko, *Classical
/// Mechanics*, 3rd ed., §2.4; Lanczos, *The Variational Principles of Mechanics*, 4th ed., ch. II
/// on auxiliary conditions and ch. III on virtual work). It is solved by Newton's method on (q, λ) with the exact Jacobian
///
/// ```text
/// J = [ −K + Σᵢ λᵢ ∇²gᵢ   Gᵀ ]        K = ∂(b − 𝓕)/∂q at rest,
///     [  G                0  ]
/// ```
///
/// (the KKT matrix of Newton's method on the Lagrange conditions: Nocedal & Wright, *Numerical
/// Optimization*, 2nd ed., §18.1),
/// whose entries all come from dual numbers: K from one gradient pass of the equations of motion
/// (as for [`equilibrium`](super::equilibrium())), and g, G and every Hessian ∇²gᵢ from one
/// second-order pass (`num_dual::Dual2SVec`) of [`Model::cartesian`](crate::Model::cartesian) and
/// [`Constraints::position_constraints`]. The (N + m)-sized system is solved densely with
/// nalgebra's `DMatrix` LU (`N + m` is not a type on stable Rust; this is not a per-step path, so
/// the allocation does not matter). The iteration is globalized by a backtracking (Armijo) line
/// search on ½‖F‖², as for the unconstrained [`equilibrium`](super::equilibrium()).
///
/// # Which rows
///
/// | kind | treatment |
/// |---|---|
/// | holonomic | always enforced |
/// | unilateral c ≥ 0 | enforced when the contact is closed, chosen by an active-set loop: a row is enforced from the start when c(q_guess) ≤ [`CONSISTENCY_TOLERANCE`]; after a solve, an enforced row whose multiplier pulls (λ < 0) is released, and a released row that the equilibrium penetrates (c < −[`CONSISTENCY_TOLERANCE`]) is enforced, one at a time, and the solve is repeated from the last equilibrium |
/// | velocity | refused with [`Error::UnsuitableMethod`]: at rest a velocity row A q̇ + a = 0 only adds a force Aᵀμ and no equation for q, so its equilibria are not isolated (a rolling disc rests anywhere on its plane) |
/// | friction | ignored, multiplier 0: a frictionless equilibrium is also one with friction (f = 0 satisfies \|f\| ≤ μₛ\|λₙ\|); the equilibria that need static friction form a continuum (every slope angle up to arctan μₛ) and are not searched |
///
/// A holonomic row that depends explicitly on t (a moving guide) gives a force balance at the
/// instant t, but rest is then not consistent with it (ġ = ∂g/∂t ≠ 0); the result is only an
/// equilibrium when the row is at rest at t.
///
/// # Stability
///
/// Small motions about (q*, λ*) stay on the constraints to first order, G δq = 0, so they live on
/// the tangent space spanned by the columns of Z (an orthonormal basis of the null space of G), and
/// the stiffness they feel is the Hessian of the Lagrangian of the statics problem projected there:
///
/// ```text
/// K_Z = Zᵀ (K − Σᵢ λᵢ ∇²gᵢ) Z,      M_Z = Zᵀ M Z,      K_Z u = ω² M_Z u,
/// ```
///
/// (the reduced Hessian of the second-order conditions, Nocedal & Wright, §12.4, with the null-space
/// basis Z of §16.2; the
/// curvature term −Σλᵢ∇²gᵢ is what makes a pendulum in Cartesian coordinates, whose potential m g y
/// has no curvature at all, stable at the bottom and unstable at the top). All eigenvalues of the
/// pencil positive: stable, with small-oscillation frequencies ω = √(eigenvalue); one negative
/// without velocity terms on the tangent space: unstable; otherwise marginal (the same criterion
/// and tolerance as [`stability`](super::stability()), see [`MARGINAL_TOLERANCE`]). For an enforced
/// unilateral row this treats the contact as held, which is the linear behaviour while λ > 0.
///
/// Errors: invalid options ([`EquilibriumOptions::validate`]); non-finite parameters or guess;
/// invalid constraint declarations;
/// [`Error::UnsuitableMethod`] for a mechanism with velocity rows; [`Error::NonFiniteDynamics`] at
/// the guess; [`Error::SingularConstraints`] when the enforced rows are dependent at the guess or
/// at the solution (redundant constraints: the multipliers are then not determined), naming them;
/// [`Error::EquilibriumNotFound`] when Newton does not converge in `options.max_iterations` per
/// pass, the line search stalls, or the active-set loop does not settle. The guess is never
/// modified.
///
/// ```
/// use lagrange_core::analysis::{constrained_equilibrium, EquilibriumOptions, Stability};
/// # use lagrange_core::analysis::doc_models::CartesianPendulum;
/// let p = CartesianPendulum { m: 1.0, l: 2.0, g: 9.81 };
/// // From a guess off the circle and off the bottom.
/// let guess = [0.7, -1.2];
/// let eq = constrained_equilibrium(&p, 0.0, &guess, &EquilibriumOptions::default())?;
/// assert!(eq.q[0].abs() < 1e-12 && (eq.q[1] + 2.0).abs() < 1e-12);
/// assert!((eq.multipliers[0] + 9.81).abs() < 1e-12); // λ = −(rod tension)
/// assert!(eq.residual < 1e-12 && eq.constraint_residual < 1e-12);
/// assert_eq!(guess, [0.7, -1.2]);
/// // The top is an equilibrium too, unstable.
/// let top = constrained_equilibrium(&p, 0.0, &[0.3, 1.5], &EquilibriumOptions::default())?;
/// assert!((top.q[1] - 2.0).abs() < 1e-12);
/// assert_eq!(top.stability, Stability::Unstable);
/// # Ok::<(), lagrange_core::Error>(())
/// ```
pub fn constrained_equilibrium<M, const N: usize, const K: usize, const C: usize>(
    mechanism: &M,
    t: f64,
    q_guess: &<M as crate::evaluation::Evaluate<N>>::Coords,
    options: &EquilibriumOptions,
) -> Result<ConstrainedEquilibrium<<M as crate::evaluation::Evaluate<N>>::Coords, N, C>>
where
    M: Constraints<N, K, C> + Mechanism<N>,
{
    options.validate()?;
    let q0 = check_configuration(mechanism, t, q_guess)?;
    mechanism.validate_constraints()?;
    refuse_velocity_rows::<M, N, K, C>()?;
    let (c0, _, _) = position_terms(mechanism, t, &q0);
    // Contact closed within CONSISTENCY_TOLERANCE of each row's size at the configuration.
    let sizes0 = rows_and_scales(mechanism, t, &q0, &[0.0; N]).1.position;
    let mut active: [bool; C] = std::array::from_fn(|i| match M::KINDS[i] {
        ConstraintKind::Holonomic => true,
        ConstraintKind::Unilateral => c0[i] <= CONSISTENCY_TOLERANCE * sizes0[i],
        _ => false,
    });
    let unilateral: Vec<usize> = (0..C)
        .filter(|&i| M::KINDS[i] == ConstraintKind::Unilateral)
        .collect();
    let mut q = q0;
    let mut iterations = 0;
    // Each pass changes one unilateral row; 2·(number of unilateral rows) + 1 passes are enough
    // unless the active set cycles.
    let passes = 2 * unilateral.len() + 1;
    for _ in 0..passes {
        let rows: Vec<usize> = (0..C).filter(|&i| active[i]).collect();
        let solved = newton::<M, N, K, C>(mechanism, t, q, &rows, options, iterations)?;
        iterations += solved.iterations;
        q = solved.q;
        if let Some((i, enforce)) =
            active_set_change(mechanism, t, &rows, &solved, &unilateral, &active)
        {
            active[i] = enforce;
            continue;
        }
        return settled(mechanism, t, &rows, &solved, active, iterations);
    }
    let f = trial_residual(
        mechanism,
        t,
        &q,
        &vec![0.0; active.iter().filter(|a| **a).count()],
        &(0..C).filter(|&i| active[i]).collect::<Vec<_>>(),
    );
    Err(Error::EquilibriumNotFound {
        t,
        iterations,
        residual: max_abs(f.iter()),
        configuration: describe::<M, N>(&q),
    })
}

/// [`Error::UnsuitableMethod`] for a mechanism with a velocity row: at rest it adds a force but no
/// equation for q.
fn refuse_velocity_rows<M, const N: usize, const K: usize, const C: usize>() -> Result<()>
where
    M: Constraints<N, K, C> + Mechanism<N>,
{
    if let Some(i) = (0..C).find(|&i| M::KINDS[i] == ConstraintKind::Velocity) {
        return Err(Error::UnsuitableMethod {
            method: "constrained_equilibrium",
            reason: format!(
                "velocity constraint `{}`: at rest it adds a force but no equation for q, so \
                 its equilibria are not isolated",
                M::NAMES[i]
            ),
        });
    }
    Ok(())
}

/// The active-set step after a solve: release the contact that pulls hardest (λ < 0), or else
/// enforce the released one penetrated deepest (c < 0), as `(row, enforced)`; `None` when the set
/// is settled.
fn active_set_change<M, const N: usize, const K: usize, const C: usize>(
    mechanism: &M,
    t: f64,
    rows: &[usize],
    solved: &Solved<N>,
    unilateral: &[usize],
    active: &[bool; C],
) -> Option<(usize, bool)>
where
    M: Constraints<N, K, C> + Mechanism<N>,
{
    let q = &solved.q;
    let l_scale = solved.kkt.multiplier_scale(q, &solved.lambda);
    let pulling = rows
        .iter()
        .enumerate()
        .filter(|&(a, &i)| {
            M::KINDS[i] == ConstraintKind::Unilateral
                && solved.lambda[a] < -MARGINAL_TOLERANCE * l_scale
        })
        .min_by(|x, y| solved.lambda[x.0].total_cmp(&solved.lambda[y.0]))
        .map(|(_, &i)| i);
    if let Some(i) = pulling {
        return Some((i, false));
    }
    let (c, _, _) = position_terms(mechanism, t, q);
    // Penetrated beyond CONSISTENCY_TOLERANCE of each row's size at q.
    let size = rows_and_scales(mechanism, t, q, &[0.0; N]).1.position;
    let penetrated = unilateral
        .iter()
        .copied()
        .filter(|&i| !active[i] && c[i] < -CONSISTENCY_TOLERANCE * size[i])
        .min_by(|&x, &y| c[x].total_cmp(&c[y]));
    penetrated.map(|i| (i, true))
}

/// The equilibrium of a settled active set: the multipliers in declaration order, the residuals
/// and the tangent-space stability, once the enforced rows are checked independent at q*.
fn settled<M, const N: usize, const K: usize, const C: usize>(
    mechanism: &M,
    t: f64,
    rows: &[usize],
    solved: &Solved<N>,
    active: [bool; C],
    iterations: usize,
) -> Result<ConstrainedEquilibrium<<M as crate::evaluation::Evaluate<N>>::Coords, N, C>>
where
    M: Constraints<N, K, C> + Mechanism<N>,
{
    let (q, kkt) = (&solved.q, &solved.kkt);
    check_independent::<M, N, K, C>(kkt, rows, t, q)?;
    let mut multipliers = [0.0; C];
    for (a, &i) in rows.iter().enumerate() {
        multipliers[i] = solved.lambda[a];
    }
    let residual = max_abs(kkt.residual(&solved.lambda).rows(0, N).iter());
    let constraint_residual = max_abs(kkt.g.iter());
    let (stability, tangent_eigenvalues) =
        tangent_stability::<M, N, K, C>(mechanism, t, q, kkt, &solved.lambda)?;
    Ok(ConstrainedEquilibrium {
        t,
        q: <M as crate::evaluation::Evaluate<N>>::Coords::from_array(*q),
        multipliers,
        names: M::NAMES,
        active,
        residual,
        constraint_residual,
        iterations,
        stiffness: kkt.rest.stiffness,
        stability,
        tangent_eigenvalues,
    })
}
