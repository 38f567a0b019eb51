//! Equilibria of constrained mechanisms: q* and the constraint forces λ that hold it, from the
//! Lagrange conditions at rest, and their stability on the tangent space of the constraints.
//!
//! The method, which constraint rows take part and the stability criterion are documented on
//! [`constrained_equilibrium`].

use super::{check_configuration, describe, max_abs, rest_residual, rest_terms};
use super::{rest_velocity_matrix, EquilibriumOptions, Stability, MARGINAL_TOLERANCE};
use crate::constraints::{rows_and_scales, ConstraintKind, Constraints, CONSISTENCY_TOLERANCE};
use crate::error::{Error, Result};
use crate::mechanism::Mechanism;
use crate::model::Coordinates;
use nalgebra::{DMatrix, DVector, SMatrix, SVector};
use num_dual::Dual2SVec;

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

/// g, G and the Hessians ∇²gᵢ of the position rows at (t, q), by one second-order dual pass.
#[allow(clippy::type_complexity)]
fn position_terms<M: Constraints<N, K, C>, const N: usize, const K: usize, const C: usize>(
    model: &M,
    t: f64,
    q: &[f64; N],
) -> ([f64; C], [SVector<f64, N>; C], [SMatrix<f64, N, N>; C]) {
    let qd: [Dual2SVec<f64, N>; N] =
        std::array::from_fn(|j| Dual2SVec::from_re(q[j]).derivative(j));
    let td = Dual2SVec::from_re(t);
    let x = model.cartesian(td, &qd);
    let g = model.position_constraints(td, &qd, &x);
    let mut value = [0.0; C];
    let mut rows = [SVector::zeros(); C];
    let mut hessians = [SMatrix::zeros(); C];
    for i in 0..C {
        if M::KINDS[i].is_position() {
            value[i] = g[i].re;
            if let Some(v1) = g[i].v1.0 {
                rows[i] = v1.transpose();
            }
            if let Some(v2) = g[i].v2.0 {
                hessians[i] = v2;
            }
        }
    }
    (value, rows, hessians)
}

/// Everything one Newton iteration needs at q for the enforced rows `rows`.
struct Kkt<const N: usize> {
    rest: super::RestTerms<N>,
    /// g of the enforced rows.
    g: Vec<f64>,
    /// Their gradients (rows of G).
    grad: Vec<SVector<f64, N>>,
    /// Their Hessians.
    hess: Vec<SMatrix<f64, N, N>>,
}

impl<const N: usize> Kkt<N> {
    fn finite(&self) -> bool {
        self.rest
            .residual
            .iter()
            .chain(self.rest.stiffness.iter())
            .chain(self.g.iter())
            .chain(self.grad.iter().flat_map(|r| r.iter()))
            .chain(self.hess.iter().flat_map(|h| h.iter()))
            .all(|x| x.is_finite())
    }
    /// F(q, λ) = [r + Gᵀλ; g].
    fn residual(&self, lambda: &[f64]) -> DVector<f64> {
        let m = self.g.len();
        let mut f = DVector::zeros(N + m);
        let mut top = self.rest.residual;
        for (a, l) in lambda.iter().enumerate() {
            top += self.grad[a] * *l;
        }
        f.rows_mut(0, N).copy_from(&top);
        for a in 0..m {
            f[N + a] = self.g[a];
        }
        f
    }
    /// J = [−K + Σλ∇²g, Gᵀ; G, 0].
    fn jacobian(&self, lambda: &[f64]) -> DMatrix<f64> {
        let m = self.g.len();
        let mut j = DMatrix::zeros(N + m, N + m);
        let mut top = -self.rest.stiffness;
        for (a, l) in lambda.iter().enumerate() {
            top += self.hess[a] * *l;
        }
        j.view_mut((0, 0), (N, N)).copy_from(&top);
        for a in 0..m {
            for k in 0..N {
                j[(k, N + a)] = self.grad[a][k];
                j[(N + a, k)] = self.grad[a][k];
            }
        }
        j
    }
    /// The size the force residual is measured against: the terms that cancel in it (see
    /// [`EquilibriumOptions::residual_tolerance`]), the constraint forces included.
    fn force_scale(&self, q: &[f64; N], lambda: &[f64]) -> f64 {
        let qn = max_abs(q.iter()).max(1.0);
        let row_sum =
            |h: &SMatrix<f64, N, N>| (0..N).map(|i| h.row(i).abs().sum()).fold(0.0f64, f64::max);
        self.rest.residual_scale
            + lambda
                .iter()
                .enumerate()
                .map(|(a, l)| {
                    l.abs() * (max_abs(self.grad[a].iter()) + row_sum(&self.hess[a]) * qn)
                })
                .sum::<f64>()
    }
    /// The size each constraint residual is measured against: the change of g over a displacement
    /// of the size of q.
    fn constraint_scale(&self, q: &[f64; N], a: usize) -> f64 {
        self.grad[a].abs().sum() * max_abs(q.iter()).max(1.0)
    }
    /// The force per unit multiplier (for the step criterion on λ).
    fn multiplier_scale(&self, q: &[f64; N], lambda: &[f64]) -> f64 {
        let largest_row = self.grad.iter().map(|r| r.norm()).fold(0.0f64, f64::max);
        if largest_row > 0.0 {
            self.force_scale(q, lambda) / largest_row
        } else {
            1.0
        }
    }
}

fn kkt_terms<M, const N: usize, const K: usize, const C: usize>(
    mechanism: &M,
    t: f64,
    q: &[f64; N],
    rows: &[usize],
) -> Kkt<N>
where
    M: Constraints<N, K, C> + Mechanism<N>,
{
    let rest = rest_terms(mechanism, t, q);
    let (g, grad, hess) = position_terms(mechanism, t, q);
    Kkt {
        rest,
        g: rows.iter().map(|&i| g[i]).collect(),
        grad: rows.iter().map(|&i| grad[i]).collect(),
        hess: rows.iter().map(|&i| hess[i]).collect(),
    }
}

/// F at a trial point, values only (r from one f64 pass, g and G from the dual pass).
fn trial_residual<M, const N: usize, const K: usize, const C: usize>(
    mechanism: &M,
    t: f64,
    q: &[f64; N],
    lambda: &[f64],
    rows: &[usize],
) -> DVector<f64>
where
    M: Constraints<N, K, C> + Mechanism<N>,
{
    let r = rest_residual(mechanism, t, q);
    let (g, grad, _) = position_terms(mechanism, t, q);
    let m = rows.len();
    let mut f = DVector::zeros(N + m);
    let mut top = r;
    for (a, &i) in rows.iter().enumerate() {
        top += grad[i] * lambda[a];
        f[N + a] = g[i];
    }
    f.rows_mut(0, N).copy_from(&top);
    f
}

/// Relative size of a squared pivot of G Gᵀ under which the enforced rows count as dependent
/// (as [`crate::linalg::SINGULAR_PIVOT`] for the mass matrix: the rows are then parallel to about
/// √(1e3 ε) ≈ 5e-7 rad).
const SINGULAR_ROWS: f64 = crate::linalg::SINGULAR_PIVOT;

/// Checks that the enforced rows are independent at q (G Gᵀ positive definite), by a Cholesky
/// factorisation that names the row at which it breaks down and the earlier rows it depends on.
// `!(d > tol)` rather than `d <= tol`: it also rejects NaN.
#[allow(clippy::neg_cmp_op_on_partial_ord)]
fn check_independent<M, const N: usize, const K: usize, const C: usize>(
    kkt: &Kkt<N>,
    rows: &[usize],
    t: f64,
    q: &[f64; N],
) -> Result<()>
where
    M: Constraints<N, K, C> + Mechanism<N>,
{
    let m = rows.len();
    let s = DMatrix::from_fn(m, m, |a, b| kkt.grad[a].dot(&kkt.grad[b]));
    let mut l = DMatrix::<f64>::zeros(m, m);
    for p in 0..m {
        let mut d = s[(p, p)];
        for k in 0..p {
            d -= l[(p, k)] * l[(p, k)];
        }
        if !(d > SINGULAR_ROWS * s[(p, p)]) || s[(p, p)] == 0.0 {
            // Row p is (numerically) Σ cₖ·row k over the earlier rows, with S₁₁ c = S[0..p, p]
            // (S₁₁ is positive definite: the factorisation got past it). Name the rows that take
            // part, with a coefficient that matters, as `constraints::solve` does for the KKT solve.
            // (The first row has no earlier rows: it depends on none, its gradient vanishes.)
            let c = if p == 0 {
                DMatrix::zeros(0, 1)
            } else {
                s.view((0, 0), (p, p))
                    .into_owned()
                    .lu()
                    .solve(&s.view((0, p), (p, 1)).into_owned())
                    .unwrap_or_else(|| DMatrix::from_element(p, 1, 1.0))
            };
            let weight = |k: usize| c[k].abs() * s[(k, k)].sqrt();
            let largest = (0..p).map(weight).fold(0.0f64, f64::max);
            let mut names: Vec<String> = (0..p)
                .filter(|&k| weight(k) > 1e-6 * largest.max(f64::MIN_POSITIVE))
                .map(|k| format!("`{}`", M::NAMES[rows[k]]))
                .collect();
            names.push(format!("`{}`", M::NAMES[rows[p]]));
            return Err(Error::SingularConstraints {
                t,
                configuration: describe::<M, N>(q),
                constraints: names.join(", "),
                pivot: d,
            });
        }
        l[(p, p)] = d.sqrt();
        for i in p + 1..m {
            let mut v = s[(i, p)];
            for k in 0..p {
                v -= l[(i, k)] * l[(p, k)];
            }
            l[(i, p)] = v / l[(p, p)];
        }
    }
    Ok(())
}

/// Armijo constant, backtracking factor and smallest step, as for the unconstrained search
/// (Nocedal & Wright, Alg. 3.1).
const ARMIJO: f64 = 1e-4;
const BACKTRACK: f64 = 0.5;
const MIN_STEP: f64 = 1e-12;

/// The result of one Newton solve with a fixed set of enforced rows.
struct Solved<const N: usize> {
    q: [f64; N],
    lambda: Vec<f64>,
    kkt: Kkt<N>,
    iterations: usize,
}

/// Newton's method with line search on F(q, λ) = 0 for the enforced rows `rows`, from q0.
fn newton<M, const N: usize, const K: usize, const C: usize>(
    mechanism: &M,
    t: f64,
    q0: [f64; N],
    rows: &[usize],
    options: &EquilibriumOptions,
    iterations_before: usize,
) -> Result<Solved<N>>
where
    M: Constraints<N, K, C> + Mechanism<N>,
{
    let m = rows.len();
    let mut q = q0;
    let not_found = |iterations: usize, residual: f64, q: &[f64; N]| Error::EquilibriumNotFound {
        t,
        iterations,
        residual,
        configuration: describe::<M, N>(q),
    };
    let mut kkt = kkt_terms(mechanism, t, &q, rows);
    if !kkt.finite() {
        return Err(Error::NonFiniteDynamics {
            t,
            configuration: describe::<M, N>(&q),
        });
    }
    check_independent::<M, N, K, C>(&kkt, rows, t, &q)?;
    // Initial multipliers: least squares on the force balance, (G Gᵀ) λ = −G r.
    let g_mat = DMatrix::from_fn(m, N, |a, k| kkt.grad[a][k]);
    let mut lambda: Vec<f64> = if m == 0 {
        Vec::new()
    } else {
        let normal = &g_mat * g_mat.transpose();
        let rhs = -(&g_mat * DVector::from_column_slice(kkt.rest.residual.as_slice()));
        normal
            .lu()
            .solve(&rhs)
            .map(|v| v.iter().copied().collect())
            .unwrap_or_else(|| vec![0.0; m])
    };
    let finite_vec = |f: &DVector<f64>| f.iter().all(|x| x.is_finite());
    let mut iterations = 0;
    loop {
        let f = kkt.residual(&lambda);
        let force_residual = max_abs(f.rows(0, N).iter());
        let force_ok = force_residual == 0.0
            || force_residual <= options.residual_tolerance * kkt.force_scale(&q, &lambda);
        let constraints_ok = (0..m).all(|a| {
            kkt.g[a] == 0.0
                || kkt.g[a].abs() <= options.residual_tolerance * kkt.constraint_scale(&q, a)
        });
        if force_ok && constraints_ok {
            return Ok(Solved {
                q,
                lambda,
                kkt,
                iterations,
            });
        }
        let total = iterations_before + iterations;
        let f_norm = max_abs(f.iter());
        if iterations >= options.max_iterations {
            return Err(not_found(total, f_norm, &q));
        }
        iterations += 1;

        let jac = kkt.jacobian(&lambda);
        let grad = jac.transpose() * &f;
        let merit = 0.5 * f.norm_squared();
        let newton = jac.clone().lu().solve(&(-&f)).filter(finite_vec);
        let (direction, slope, is_newton) = match newton {
            Some(p) if grad.dot(&p) < 0.0 => {
                let s = grad.dot(&p);
                (p, s, true)
            }
            _ => {
                // Steepest descent on ½‖F‖², scaled like a Newton step (see `equilibrium`).
                let g2 = grad.norm_squared();
                if g2 == 0.0 {
                    return Err(not_found(total + 1, f_norm, &q));
                }
                let p = -&grad * (f.norm_squared() / g2);
                let s = grad.dot(&p);
                (p, s, false)
            }
        };

        let q_step = max_abs(direction.rows(0, N).iter());
        let l_step = max_abs(direction.rows(N, m).iter());
        let l_scale = max_abs(lambda.iter()).max(kkt.multiplier_scale(&q, &lambda));
        if is_newton
            && q_step <= options.step_tolerance * max_abs(q.iter()).max(1.0)
            && l_step <= options.step_tolerance * l_scale
        {
            for k in 0..N {
                q[k] += direction[k];
            }
            for a in 0..m {
                lambda[a] += direction[N + a];
            }
            kkt = kkt_terms(mechanism, t, &q, rows);
            if !kkt.finite() {
                return Err(not_found(total + 1, f64::NAN, &q));
            }
            return Ok(Solved {
                q,
                lambda,
                kkt,
                iterations,
            });
        }

        // Backtracking line search on ½‖F‖² (Nocedal & Wright, Alg. 3.1).
        let mut alpha = 1.0;
        let accepted = loop {
            let trial_q: [f64; N] = std::array::from_fn(|k| q[k] + alpha * direction[k]);
            let trial_l: Vec<f64> = (0..m)
                .map(|a| lambda[a] + alpha * direction[N + a])
                .collect();
            let f_trial = trial_residual(mechanism, t, &trial_q, &trial_l, rows);
            if finite_vec(&f_trial)
                && 0.5 * f_trial.norm_squared() <= merit + ARMIJO * alpha * slope
            {
                break Some((trial_q, trial_l));
            }
            alpha *= BACKTRACK;
            if alpha < MIN_STEP {
                break None;
            }
        };
        let Some((next_q, next_l)) = accepted else {
            return Err(not_found(total, f_norm, &q));
        };
        q = next_q;
        lambda = next_l;
        kkt = kkt_terms(mechanism, t, &q, rows);
        if !kkt.finite() {
            return Err(not_found(total, f64::NAN, &q));
        }
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
    q_guess: &<M as crate::mechanism::Dynamics<N>>::Coords,
    options: &EquilibriumOptions,
) -> Result<ConstrainedEquilibrium<<M as crate::mechanism::Dynamics<N>>::Coords, N, C>>
where
    M: Constraints<N, K, C> + Mechanism<N>,
{
    options.validate()?;
    let q0 = check_configuration(mechanism, t, q_guess)?;
    mechanism.validate_constraints()?;
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
    let (c0, _, _) = position_terms(mechanism, t, &q0);
    // Contact closed within CONSISTENCY_TOLERANCE of each row's size at the configuration.
    let sizes = |q: &[f64; N]| rows_and_scales(mechanism, t, q, &[0.0; N]).1.position;
    let sizes0 = sizes(&q0);
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
        let kkt = &solved.kkt;
        // Release the contact that pulls hardest, or close the one penetrated deepest.
        let l_scale = kkt.multiplier_scale(&q, &solved.lambda);
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
            active[i] = false;
            continue;
        }
        let (c, _, _) = position_terms(mechanism, t, &q);
        let size = sizes(&q);
        let penetrated = unilateral
            .iter()
            .copied()
            .filter(|&i| !active[i] && c[i] < -CONSISTENCY_TOLERANCE * size[i])
            .min_by(|&x, &y| c[x].total_cmp(&c[y]));
        if let Some(i) = penetrated {
            active[i] = true;
            continue;
        }
        check_independent::<M, N, K, C>(kkt, &rows, t, &q)?;
        let mut multipliers = [0.0; C];
        for (a, &i) in rows.iter().enumerate() {
            multipliers[i] = solved.lambda[a];
        }
        let residual = max_abs(kkt.residual(&solved.lambda).rows(0, N).iter());
        let constraint_residual = max_abs(kkt.g.iter());
        let (stability, tangent_eigenvalues) =
            tangent_stability::<M, N, K, C>(mechanism, t, &q, kkt, &solved.lambda)?;
        return Ok(ConstrainedEquilibrium {
            t,
            q: <M as crate::mechanism::Dynamics<N>>::Coords::from_array(q),
            multipliers,
            names: M::NAMES,
            active,
            residual,
            constraint_residual,
            iterations,
            stiffness: kkt.rest.stiffness,
            stability,
            tangent_eigenvalues,
        });
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

/// Iteration cap for nalgebra's symmetric eigen-solver (it loops forever with 0).
const EIGEN_ITERATIONS: usize = 100_000;

/// Eigen-decomposition of a symmetric `DMatrix`, eigenvalues ascending with their vectors.
fn symmetric_eigen(m: DMatrix<f64>) -> Option<(Vec<f64>, DMatrix<f64>)> {
    let n = m.nrows();
    let eig = nalgebra::SymmetricEigen::try_new(m, f64::EPSILON, EIGEN_ITERATIONS)?;
    let mut order: Vec<usize> = (0..n).collect();
    order.sort_by(|&a, &b| eig.eigenvalues[a].total_cmp(&eig.eigenvalues[b]));
    let values = order.iter().map(|&i| eig.eigenvalues[i]).collect();
    let vectors = DMatrix::from_fn(n, n, |r, c| eig.eigenvectors[(r, order[c])]);
    Some((values, vectors))
}

/// Why ZᵀMZ (the mass matrix on the tangent space of the enforced rows) has no Cholesky factor. When
/// M itself is singular or not finite, the error of M's own factorisation: the coordinate it stops
/// at and its pivot. Otherwise (M positive definite, ZᵀMZ singular only by rounding) the first
/// failing pivot of ZᵀMZ, named by the coordinate that dominates that tangent direction.
#[cold]
fn tangent_mass_error<M, const N: usize, const K: usize, const C: usize>(
    mz: &DMatrix<f64>,
    z: &DMatrix<f64>,
    kkt: &Kkt<N>,
    t: f64,
    q: &[f64; N],
) -> Error
where
    M: Constraints<N, K, C> + Mechanism<N>,
{
    let names = <M as crate::mechanism::Dynamics<N>>::Coords::NAMES;
    if !kkt.rest.mass_matrix.iter().all(|x| x.is_finite()) {
        return Error::NonFiniteDynamics {
            t,
            configuration: describe::<M, N>(q),
        };
    }
    if let Err(e) = super::mass_cholesky::<M, N>(&kkt.rest.mass_matrix, t, q) {
        return e;
    }
    // Unpivoted Cholesky of ZᵀMZ by hand, to find where it breaks down.
    let n = mz.nrows();
    let mut l = DMatrix::<f64>::zeros(n, n);
    let (mut index, mut pivot) = (0, f64::NAN);
    for j in 0..n {
        let mut d = mz[(j, j)];
        for k in 0..j {
            d -= l[(j, k)] * l[(j, k)];
        }
        (index, pivot) = (j, d);
        if d.is_nan() || d <= 0.0 {
            break;
        }
        l[(j, j)] = d.sqrt();
        for i in j + 1..n {
            let mut v = mz[(i, j)];
            for k in 0..j {
                v -= l[(i, k)] * l[(j, k)];
            }
            l[(i, j)] = v / l[(j, j)];
        }
    }
    let direction = z.column(index);
    let coordinate = (0..N)
        .max_by(|&a, &b| direction[a].abs().total_cmp(&direction[b].abs()))
        .unwrap_or(0);
    Error::SingularMassMatrix {
        t,
        configuration: describe::<M, N>(q),
        coordinate: names[coordinate.min(N.saturating_sub(1))],
        pivot,
    }
}

/// The tangent-space stability analysis of the module docs.
fn tangent_stability<M, const N: usize, const K: usize, const C: usize>(
    mechanism: &M,
    t: f64,
    q: &[f64; N],
    kkt: &Kkt<N>,
    lambda: &[f64],
) -> Result<(Stability, Vec<f64>)>
where
    M: Constraints<N, K, C> + Mechanism<N>,
{
    let m = kkt.g.len();
    let eigen_failure = || Error::EigenvalueFailure {
        t,
        configuration: describe::<M, N>(q),
    };
    if m >= N {
        // No freedom left: the constraints hold the mechanism rigidly.
        return Ok((Stability::Stable, Vec::new()));
    }
    let dm = |x: &SMatrix<f64, N, N>| DMatrix::from_column_slice(N, N, x.as_slice());
    // Z: the eigenvectors of the projector P = I − Gᵀ(GGᵀ)⁻¹G with eigenvalue 1 (the N − m
    // largest; the other m are 0).
    let g_mat = DMatrix::from_fn(m, N, |a, k| kkt.grad[a][k]);
    let ggt = &g_mat * g_mat.transpose();
    let ggt_inv = ggt.try_inverse().ok_or_else(eigen_failure)?;
    let p = DMatrix::<f64>::identity(N, N) - g_mat.transpose() * ggt_inv * &g_mat;
    let (_, vectors) = symmetric_eigen((&p + p.transpose()) * 0.5).ok_or_else(eigen_failure)?;
    let z = vectors.columns(m, N - m).into_owned();

    let mut curvature = SMatrix::<f64, N, N>::zeros();
    for (a, l) in lambda.iter().enumerate() {
        curvature += kkt.hess[a] * *l;
    }
    let k_l = kkt.rest.stiffness - curvature;
    let mz = z.transpose() * dm(&kkt.rest.mass_matrix) * &z;
    let chol = match mz.clone().cholesky() {
        Some(chol) => chol,
        None => return Err(tangent_mass_error::<M, N, K, C>(&mz, &z, kkt, t, q)),
    };
    let l_inv = chol
        .l()
        .solve_lower_triangular(&DMatrix::identity(N - m, N - m))
        .ok_or_else(eigen_failure)?;
    let normalized = |x: &SMatrix<f64, N, N>| {
        let xs = (dm(x) + dm(x).transpose()) * 0.5;
        &l_inv * (z.transpose() * xs * &z) * l_inv.transpose()
    };
    let reduced = normalized(&k_l);
    let (values, _) = symmetric_eigen(reduced).ok_or_else(eigen_failure)?;

    // Scale: the parts of the tangent stiffness before they cancel (forces, inertial terms,
    // constraint curvature), mass-normalized, as in `stability`.
    let s2 = normalized(&kkt.rest.stiffness_parts[0]).norm()
        + normalized(&kkt.rest.stiffness_parts[1]).norm()
        + normalized(&curvature).norm();
    let (velocity, velocity_parts) = rest_velocity_matrix(mechanism, t, q);
    let d_scale = normalized(&velocity_parts[0]).norm() + normalized(&velocity_parts[1]).norm();
    let s = s2.sqrt() + d_scale;
    let tol = MARGINAL_TOLERANCE;
    let lowest = values.first().copied().unwrap_or(0.0);
    let has_velocity_terms = {
        let dz = &l_inv * (z.transpose() * dm(&velocity) * &z) * l_inv.transpose();
        dz.norm() > tol * s
    };
    let stability = if s == 0.0 {
        Stability::Marginal
    } else if lowest > tol * s * s {
        Stability::Stable
    } else if lowest < -tol * s * s && !has_velocity_terms {
        Stability::Unstable
    } else {
        Stability::Marginal
    };
    Ok((stability, values))
}
