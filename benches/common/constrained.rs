//! Constrained mechanisms' accelerations written out by hand: M, the constraint Jacobian G, the
//! velocity-product terms and a Schur-complement solve of the KKT system in `f64`,
//!
//! ```text
//! M q̈ + Gᵀλ = 𝓕 − b,   G q̈ = −γ   ⇒   (G M⁻¹ Gᵀ) λ = G M⁻¹ (𝓕 − b) + γ,   q̈ = M⁻¹ (𝓕 − b − Gᵀλ),
//! ```
//!
//! with γ = d²/ds² g(q + s q̇)|₀ (e.g. Featherstone, *Rigid Body Dynamics Algorithms*, 2008, §8.1).
//! The baselines for the generated code's constrained `accelerations`.

use lagrange::linalg::Ldlt;
use nalgebra::{SMatrix, SVector};

/// The four-bar of the gallery (absolute bar angles θ₁, θ₂, θ₃; uniform bars, I = m l²/12; crank
/// pivoted at the origin, rocker at (d, 0); the coupler's far end on the rocker's tip).
#[derive(Clone, Copy, Debug)]
pub struct FourBar {
    pub l: [f64; 3],
    pub m: [f64; 3],
    pub d: f64,
    pub g: f64,
}

/// q̈ of the four-bar at (q, q̇).
pub fn four_bar(p: &FourBar, q: [f64; 3], v: [f64; 3]) -> [f64; 3] {
    let [l1, l2, l3] = p.l;
    let [m1, m2, m3] = p.m;
    let (s1, c1) = q[0].sin_cos();
    let (s2, c2) = q[1].sin_cos();
    let (s3, c3) = q[2].sin_cos();
    // T = ½ Σ (m |ċ|² + I θ̇²): bar k about its pivot m l²/3, the coupler's centre carried by the
    // crank's tip, coupled through k cos(θ₁ − θ₂).
    let k = m2 * l1 * 0.5 * l2;
    let (sd, cd) = (s1 * c2 - c1 * s2, c1 * c2 + s1 * s2);
    let mass = SMatrix::<f64, 3, 3>::new(
        (m1 / 3.0 + m2) * l1 * l1,
        k * cd,
        0.0,
        k * cd,
        m2 * l2 * l2 / 3.0,
        0.0,
        0.0,
        0.0,
        m3 * l3 * l3 / 3.0,
    );
    // 𝓕 − b: gravity on the centres, and the coupling's velocity products.
    let force = SVector::<f64, 3>::new(
        -p.g * c1 * (0.5 * m1 + m2) * l1 - k * sd * v[1] * v[1],
        -p.g * c2 * 0.5 * m2 * l2 + k * sd * v[0] * v[0],
        -p.g * c3 * 0.5 * m3 * l3,
    );
    // g = l₁(c₁, s₁) + l₂(c₂, s₂) − (d, 0) − l₃(c₃, s₃): G and γ.
    let jac = SMatrix::<f64, 2, 3>::new(-l1 * s1, -l2 * s2, l3 * s3, l1 * c1, l2 * c2, -l3 * c3);
    let (w1, w2, w3) = (v[0] * v[0], v[1] * v[1], v[2] * v[2]);
    let gamma = SVector::<f64, 2>::new(
        -l1 * c1 * w1 - l2 * c2 * w2 + l3 * c3 * w3,
        -l1 * s1 * w1 - l2 * s2 * w2 + l3 * s3 * w3,
    );
    schur_solve(&mass, &force, &jac, &gamma).into()
}

/// The pendulum in Cartesian coordinates (x, y), pivot at the origin, |x| = l enforced.
#[derive(Clone, Copy, Debug)]
pub struct CartesianPendulum {
    pub m: f64,
    pub l: f64,
    pub g: f64,
}

/// q̈ of the Cartesian pendulum at (q, q̇): M = m I, G = xᵀ/|x|, γ = (|ẋ|² − (x·ẋ/|x|)²)/|x|.
pub fn cartesian_pendulum(p: &CartesianPendulum, q: [f64; 2], v: [f64; 2]) -> [f64; 2] {
    let r = (q[0] * q[0] + q[1] * q[1]).sqrt();
    let n = [q[0] / r, q[1] / r];
    let radial = n[0] * v[0] + n[1] * v[1];
    let gamma = (v[0] * v[0] + v[1] * v[1] - radial * radial) / r;
    // G M⁻¹ Gᵀ = 1/m: λ = m (G 𝓕/m + γ), q̈ = (𝓕 − Gᵀλ)/m.
    let force = [0.0, -p.m * p.g];
    let lambda = n[0] * force[0] + n[1] * force[1] + p.m * gamma;
    [
        (force[0] - n[0] * lambda) / p.m,
        (force[1] - n[1] * lambda) / p.m,
    ]
}

/// q̈ from the KKT system by the Schur complement on M's LDLᵀ factorisation.
fn schur_solve<const N: usize, const C: usize>(
    mass: &SMatrix<f64, N, N>,
    force: &SVector<f64, N>,
    jac: &SMatrix<f64, C, N>,
    gamma: &SVector<f64, C>,
) -> SVector<f64, N> {
    let factor = Ldlt::new(mass).expect("positive definite");
    let free = factor.solve(force);
    // M⁻¹ Gᵀ, column by column.
    let mut inv_jt = SMatrix::<f64, N, C>::zeros();
    for c in 0..C {
        inv_jt.set_column(c, &factor.solve(&jac.row(c).transpose()));
    }
    let schur = jac * inv_jt;
    let lambda = Ldlt::new(&schur)
        .expect("independent constraints")
        .solve(&(jac * free + gamma));
    free - inv_jt * lambda
}
