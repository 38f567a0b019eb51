//! The terms of Newton's method on the Lagrange conditions at rest: F(q, λ), its Jacobian (the
//! KKT matrix), the scales its criteria measure against, and the independence of the enforced rows.

use crate::analysis::{describe, max_abs, rest_residual, rest_terms, RestTerms};
use crate::constraints::Constraints;
use crate::error::{Error, Result};
use crate::mechanism::Mechanism;
use nalgebra::{DMatrix, DVector, SMatrix, SVector};
use num_dual::Dual2SVec;

/// g, G and the Hessians ∇²gᵢ of the position rows at (t, q), by one second-order dual pass.
#[allow(clippy::type_complexity)]
pub(super) fn position_terms<
    M: Constraints<N, K, C>,
    const N: usize,
    const K: usize,
    const C: usize,
>(
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
pub(super) struct Kkt<const N: usize> {
    pub(super) rest: RestTerms<N>,
    /// g of the enforced rows.
    pub(super) g: Vec<f64>,
    /// Their gradients (rows of G).
    pub(super) grad: Vec<SVector<f64, N>>,
    /// Their Hessians.
    pub(super) hess: Vec<SMatrix<f64, N, N>>,
}

impl<const N: usize> Kkt<N> {
    pub(super) fn finite(&self) -> bool {
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
    pub(super) fn residual(&self, lambda: &[f64]) -> DVector<f64> {
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
    pub(super) fn jacobian(&self, lambda: &[f64]) -> DMatrix<f64> {
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
    /// [`EquilibriumOptions::residual_tolerance`](crate::analysis::EquilibriumOptions::residual_tolerance)), the constraint forces included.
    pub(super) fn force_scale(&self, q: &[f64; N], lambda: &[f64]) -> f64 {
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
    pub(super) fn constraint_scale(&self, q: &[f64; N], a: usize) -> f64 {
        self.grad[a].abs().sum() * max_abs(q.iter()).max(1.0)
    }
    /// The force per unit multiplier (for the step criterion on λ).
    pub(super) fn multiplier_scale(&self, q: &[f64; N], lambda: &[f64]) -> f64 {
        let largest_row = self.grad.iter().map(|r| r.norm()).fold(0.0f64, f64::max);
        if largest_row > 0.0 {
            self.force_scale(q, lambda) / largest_row
        } else {
            1.0
        }
    }
}

/// The [`Kkt`] terms at q for the enforced rows `rows`.
pub(super) fn kkt_terms<M, const N: usize, const K: usize, const C: usize>(
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
pub(super) fn trial_residual<M, const N: usize, const K: usize, const C: usize>(
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
pub(super) fn check_independent<M, const N: usize, const K: usize, const C: usize>(
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
