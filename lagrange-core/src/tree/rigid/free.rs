//! The free joint: a root body's six coordinates, its origin p in the world and its orientation in
//! modified Rodrigues parameters σ (R = [`rot_mrp`]\(σ\), body to world;
//! Schaub & Junkins, *Analytical Mechanics of Space Systems*, 2nd ed., 2009, §3.8), as the
//! recursions take it (Featherstone, *Rigid Body Dynamics Algorithms*, 2008, §4.4 and §9.3: a
//! floating base is a six-degree-of-freedom joint to the ground).
//!
//! In the body's frame its velocity is v_b = S(q) q̇ with q̇ = (ṗ, σ̇):
//!
//! ```text
//! S q̇ = (B(σ) σ̇ ; Rᵀ ṗ),   B(σ) = 4/(1+s)² A₋(σ),   A±(σ) x = (1 − s) x ± 2 σ × x + 2 σ (σ·x),
//! ```
//!
//! s = |σ|², B the body angular velocity's map (ω_b = B σ̇; its inverse B⁻¹ = A₊/4, Schaub &
//! Junkins eq. 3.155). S is invertible wherever the chart is regular, so the articulated-body
//! algorithm solves the root's whole 6 × 6 articulated inertia, and its rates follow from the
//! root's acceleration by S⁻¹ = diag(R, B⁻¹). The joint's bias acceleration c = Ṡ q̇ (the root
//! has no parent velocity to cross with):
//!
//! ```text
//! Ṡ q̇ = (Ḃ σ̇ ; −ω_b × Rᵀ ṗ),   Ḃ σ̇ = 8 |σ̇|² σ / (1+s)² − 4 (σ·σ̇) ω_b / (1+s),
//! ```
//!
//! from Ṙᵀ = −\[ω_b\]× Rᵀ and d/dt of B with σ̈ held (derived for this module; the unit tests
//! check both against dual-number derivatives of R(σ(t))).

use super::inertia::Inertia;
use super::spatial::{add3, cross, dot3, scale3, sub3, Force, Motion, M3, V3};
use crate::geometry::{rot_mrp, vec3, Scalar};
use crate::linalg::{cholesky_solve, NotPositiveDefinite};
use nalgebra::SVector;

/// σ, the free joint's orientation coordinates, from the joint's first coordinate.
#[inline(always)]
pub(crate) fn orientation<S: Scalar, const N: usize>(q: &[S; N], first: usize) -> V3<S> {
    [q[first + 3], q[first + 4], q[first + 5]]
}

/// The six rates (ṗ, σ̇) from the joint's first coordinate.
#[inline(always)]
pub(crate) fn rates<S: Scalar, const N: usize>(v: &[S; N], first: usize) -> [S; 6] {
    std::array::from_fn(|k| v[first + k])
}

/// R(σ), by rows: the body's axes in the world by columns.
#[inline(always)]
pub(crate) fn rotation<S: Scalar>(sigma: V3<S>) -> M3<S> {
    rot_mrp(vec3(sigma[0], sigma[1], sigma[2])).rows
}

/// A±(σ) x = (1 − s) x ± 2 σ × x + 2 σ (σ·x).
#[inline(always)]
fn a_map<S: Scalar>(sigma: V3<S>, x: V3<S>, plus: bool) -> V3<S> {
    let s = dot3(sigma, sigma);
    let turn = scale3(cross(sigma, x), if plus { 2.0 } else { -2.0 }.into());
    let along = scale3(sigma, dot3(sigma, x) * 2.0);
    add3(add3(scale3(x, S::one() - s), turn), along)
}

/// 4/(1+s)², the factor of B and Bᵀ.
#[inline(always)]
fn b_factor<S: Scalar>(sigma: V3<S>) -> S {
    let d = S::one() + dot3(sigma, sigma);
    (d * d).recip() * 4.0
}

/// Rᵀ x.
#[inline(always)]
fn rotate_back<S: Scalar>(r: &M3<S>, x: V3<S>) -> V3<S> {
    std::array::from_fn(|j| r[0][j] * x[0] + r[1][j] * x[1] + r[2][j] * x[2])
}

/// R x.
#[inline(always)]
fn rotate<S: Scalar>(r: &M3<S>, x: V3<S>) -> V3<S> {
    std::array::from_fn(|i| r[i][0] * x[0] + r[i][1] * x[1] + r[i][2] * x[2])
}

/// X m for a motion of the ground: (Rᵀ ω ; Rᵀ v). The ground's motions the recursions pass (rest,
/// and the uniform field's a₀ = (0; −g)) have no angular part, so the shift to the origin p, the
/// term Rᵀ (ω × p), is zero and p is not needed.
#[inline(always)]
pub(crate) fn from_ground<S: Scalar>(sigma: V3<S>, m: &Motion<S>) -> Motion<S> {
    let r = rotation(sigma);
    Motion {
        angular: rotate_back(&r, m.angular),
        linear: rotate_back(&r, m.linear),
    }
}

/// (S q̇, Ṡ q̇): the body's velocity and the joint's bias acceleration (see the module docs).
#[inline(always)]
pub(crate) fn velocity<S: Scalar>(sigma: V3<S>, q_dot: [S; 6]) -> (Motion<S>, Motion<S>) {
    let r = rotation(sigma);
    let p_dot = [q_dot[0], q_dot[1], q_dot[2]];
    let sigma_dot = [q_dot[3], q_dot[4], q_dot[5]];
    let omega = scale3(a_map(sigma, sigma_dot, false), b_factor(sigma));
    let linear = rotate_back(&r, p_dot);
    let d = S::one() + dot3(sigma, sigma);
    let b_dot = sub3(
        scale3(sigma, dot3(sigma_dot, sigma_dot) * 8.0 / (d * d)),
        scale3(omega, dot3(sigma, sigma_dot) * 4.0 / d),
    );
    let velocity = Motion {
        angular: omega,
        linear,
    };
    let bias = Motion {
        angular: b_dot,
        linear: scale3(cross(omega, linear), -S::one()),
    };
    (velocity, bias)
}

/// S⁻¹ m: the rates (p̈, σ̈) whose joint motion is m = (ω; v), p̈ = R v, σ̈ = A₊(σ) ω / 4, with
/// R = R(σ) given.
#[inline(always)]
pub(crate) fn rates_of<S: Scalar>(r: &M3<S>, sigma: V3<S>, m: &Motion<S>) -> [S; 6] {
    let p = rotate(r, m.linear);
    let s = scale3(a_map(sigma, m.angular, true), S::from(0.25));
    [p[0], p[1], p[2], s[0], s[1], s[2]]
}

/// S m for joint rates `rates` = (ṗ, σ̇) (or accelerations): (B σ̇ ; Rᵀ ṗ).
#[inline(always)]
pub(crate) fn motion_of<S: Scalar>(sigma: V3<S>, rates: [S; 6]) -> Motion<S> {
    let r = rotation(sigma);
    Motion {
        angular: scale3(
            a_map(sigma, [rates[3], rates[4], rates[5]], false),
            b_factor(sigma),
        ),
        linear: rotate_back(&r, [rates[0], rates[1], rates[2]]),
    }
}

/// Sᵀ f: the generalized forces of a force f = (n; F) on the body, (R F, Bᵀ n) with
/// Bᵀ n = 4/(1+s)² A₊(σ) n.
#[inline(always)]
pub(crate) fn forces_of<S: Scalar>(sigma: V3<S>, f: &Force<S>) -> [S; 6] {
    let r = rotation(sigma);
    let p = rotate(&r, f.force);
    let s = scale3(a_map(sigma, f.moment, true), b_factor(sigma));
    [p[0], p[1], p[2], s[0], s[1], s[2]]
}

/// S⁻ᵀ τ: the force on the body whose generalized forces are τ = (τ_p, τ_σ):
/// (B⁻ᵀ τ_σ ; Rᵀ τ_p), B⁻ᵀ = A₋(σ)/4.
#[inline(always)]
pub(crate) fn force_of<S: Scalar>(sigma: V3<S>, tau: [S; 6]) -> Force<S> {
    let r = rotation(sigma);
    Force {
        moment: scale3(a_map(sigma, [tau[3], tau[4], tau[5]], false), S::from(0.25)),
        force: rotate_back(&r, [tau[0], tau[1], tau[2]]),
    }
}

/// The root's acceleration from its articulated inertia and bias force under the joint's
/// generalized forces τ: I^A a + p^A = S⁻ᵀ τ (Featherstone §9.3, the floating base's articulated
/// equation), solved by Cholesky on the 6 × 6 (angular block first).
#[inline(always)]
pub(crate) fn root_acceleration<S: Scalar>(
    sigma: V3<S>,
    inertia: &Inertia<S>,
    bias: &Force<S>,
    tau: [S; 6],
) -> Result<Motion<S>, NotPositiveDefinite> {
    let f = force_of(sigma, tau);
    let rhs = SVector::<S, 6>::from_fn(|i, _| match i {
        0..=2 => f.moment[i] - bias.moment[i],
        _ => f.force[i - 3] - bias.force[i - 3],
    });
    let a = cholesky_solve(&inertia.matrix(), &rhs)?;
    Ok(Motion {
        angular: [a[0], a[1], a[2]],
        linear: [a[3], a[4], a[5]],
    })
}

/// q̈ of the joint from the root's acceleration a: S q̈ = a − X a₀ − Ṡ q̇, with X a₀ the ground's
/// acceleration (the uniform field's) in the body's frame and Ṡ q̇ the joint's bias. R is formed
/// once for X and S⁻¹: p̈ = R (a_v − c_v) − R Rᵀ a₀_v = R (a_v − c_v) − a₀_v (a₀ has no angular
/// part), σ̈ = A₊(σ)(a_ω − c_ω)/4.
#[inline(always)]
pub(crate) fn accelerations<S: Scalar>(
    sigma: V3<S>,
    a: &Motion<S>,
    ground: &Motion<S>,
    bias: &Motion<S>,
) -> [S; 6] {
    let joint = Motion {
        angular: sub3(a.angular, bias.angular),
        linear: sub3(a.linear, bias.linear),
    };
    let mut rates = rates_of(&rotation(sigma), sigma, &joint);
    for k in 0..3 {
        rates[k] -= ground.linear[k];
    }
    rates
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::{body_angular_velocity, RotationChart};
    use num_dual::Dual64;

    const SIGMA: V3<f64> = [0.3, -0.5, 0.4];
    const RATES: [f64; 6] = [0.7, -1.1, 0.2, 1.0, 2.0, -0.5];

    fn close(a: &[f64], b: &[f64], tol: f64) {
        for (x, y) in a.iter().zip(b) {
            assert!((x - y).abs() < tol, "{a:?} against {b:?}");
        }
    }

    #[test]
    fn the_angular_velocity_is_the_charts() {
        let (v, _) = velocity(SIGMA, RATES);
        let omega = body_angular_velocity(RotationChart::Mrp, SIGMA, [1.0, 2.0, -0.5]);
        close(&v.angular, &omega, 1e-14);
    }

    #[test]
    fn the_inverse_maps_undo_the_joint() {
        let back = rates_of(&rotation(SIGMA), SIGMA, &motion_of(SIGMA, RATES));
        close(&back, &RATES, 1e-14);
        // Sᵀ (S⁻ᵀ τ) = τ.
        let tau = [1.5, -0.3, 0.8, 0.2, -1.0, 0.6];
        close(&forces_of(SIGMA, &force_of(SIGMA, tau)), &tau, 1e-14);
        // Power: (S q̇)·f = q̇·(Sᵀ f).
        let f = Force {
            moment: [0.4, 0.1, -0.9],
            force: [1.0, -2.0, 0.5],
        };
        let power = motion_of(SIGMA, RATES).dot(&f);
        let generalized: f64 = forces_of(SIGMA, &f)
            .iter()
            .zip(RATES)
            .map(|(a, b)| a * b)
            .sum();
        assert!((power - generalized).abs() < 1e-14);
    }

    /// Ṡ q̇ is d/dt (S(q(t)) q̇) with q̈ = 0: the velocity along q(t) = q + t q̇ on dual numbers.
    #[test]
    fn the_bias_is_the_joint_motions_derivative() {
        let sigma = std::array::from_fn(|k| Dual64::new(SIGMA[k], RATES[3 + k]));
        let rates = RATES.map(Dual64::from);
        let (v, _) = velocity(sigma, rates);
        let (_, c) = velocity(SIGMA, RATES);
        close(&c.angular, &v.angular.map(|x| x.eps), 1e-14);
        // The linear part: d/dt (Rᵀ ṗ) in the body's components.
        close(&c.linear, &v.linear.map(|x| x.eps), 1e-14);
    }
}
