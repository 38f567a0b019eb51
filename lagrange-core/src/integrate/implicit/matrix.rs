//! The simplified Newton matrix of the collocation equations, kept from step to step.

use super::tableau::Tableau;
use crate::integrate::canonical::FieldJacobians;
use crate::integrate::newton::BlockLu;
use nalgebra::SMatrix;

/// The contraction factor θ of a kept simplified Newton matrix above which the next step takes its
/// ∂p/∂v block anew (M where the step starts) and refactorises it. With the corrected predictor
/// the first increment is ~10⁻¹⁰ of the velocities at h = 10⁻³, and the iteration stops after the
/// second when θ²·10⁻¹⁰ ≲ 4ε, θ ≲ 3·10⁻³; below 10⁻³ a refactorisation would not save an
/// iteration.
pub(super) const MASS_REFRESH_THETA: f64 = 1e-3;

/// The reused part of a simplified Newton iteration: the field's Jacobians at a reference point
/// and the factorised Newton matrix built from them for one step size.
#[derive(Clone, Copy, Debug)]
pub(super) struct NewtonMatrix<const N: usize, const S: usize> {
    pub(super) jacobians: FieldJacobians<N>,
    pub(super) lu: BlockLu<N, S>,
    pub(super) h: f64,
    /// Whether the last step converged fast enough to keep the Jacobian.
    pub(super) reusable: bool,
    /// The last step's contraction factor θ.
    pub(super) theta: f64,
}

impl<const N: usize, const S: usize> NewtonMatrix<N, S> {
    /// A matrix just factorised for step size h, reusable until an iteration says otherwise.
    #[inline(always)]
    pub(super) fn fresh(jacobians: FieldJacobians<N>, lu: BlockLu<N, S>, h: f64) -> Self {
        NewtonMatrix {
            jacobians,
            lu,
            h,
            reusable: true,
            theta: 0.0,
        }
    }
}

/// The simplified Newton matrix of the collocation equations with every stage's Jacobians replaced
/// by one reference point's `j`: blocks δᵢₖ ∂p/∂v + h aᵢₖ ∂p/∂q − h² (A²)ᵢₖ ∂ṗ/∂q − h aᵢₖ ∂ṗ/∂v
/// (Hairer & Wanner, *Solving ODEs II*, §IV.8, (8.4), for these unknowns).
pub(super) fn simplified_matrix<const N: usize, const S: usize>(
    tableau: &Tableau<S>,
    j: &FieldJacobians<N>,
    h: f64,
) -> [[SMatrix<f64, N, N>; S]; S] {
    std::array::from_fn(|i| {
        std::array::from_fn(|k| {
            let a2: f64 = (0..S).map(|l| tableau.a[i][l] * tableau.a[l][k]).sum();
            let mut block = j.p_q * (h * tableau.a[i][k])
                - j.rate_q * (h * h * a2)
                - j.rate_v * (h * tableau.a[i][k]);
            if i == k {
                block += j.p_v;
            }
            block
        })
    })
}
