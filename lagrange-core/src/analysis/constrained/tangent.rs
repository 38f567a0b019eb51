//! The stability of a constrained equilibrium on the tangent space of its enforced rows: the
//! pencil K_Z u = ω² M_Z u (see [`constrained_equilibrium`](super::constrained_equilibrium)).

use super::kkt::Kkt;
use crate::analysis::stability::symmetric_eigen_dynamic;
use crate::analysis::{
    describe, mass_cholesky, rest_velocity_matrix, Stability, MARGINAL_TOLERANCE,
};
use crate::constraints::Constraints;
use crate::error::{Error, Result};
use crate::mechanism::Mechanism;
use crate::model::Coordinates;
use nalgebra::{DMatrix, SMatrix};

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
    let names = <M as crate::evaluation::Evaluate<N>>::Coords::NAMES;
    if !kkt.rest.mass_matrix.iter().all(|x| x.is_finite()) {
        return Error::NonFiniteDynamics {
            t,
            configuration: describe::<M, N>(q),
        };
    }
    if let Err(e) = mass_cholesky::<M, N>(&kkt.rest.mass_matrix, t, q) {
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
pub(super) fn tangent_stability<M, const N: usize, const K: usize, const C: usize>(
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
    let (_, vectors) =
        symmetric_eigen_dynamic((&p + p.transpose()) * 0.5).ok_or_else(eigen_failure)?;
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
    let (values, _) = symmetric_eigen_dynamic(reduced).ok_or_else(eigen_failure)?;

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
