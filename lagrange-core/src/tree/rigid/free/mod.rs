//! The free joint: a root body's six coordinates, its origin p in the world and its orientation c
//! in a rotation chart (R = R(c), body to world; the private module `charts` gives the chart's maps), as the
//! recursions take it (Featherstone, *Rigid Body Dynamics Algorithms*, 2008, §4.4 and §9.3: a
//! floating base is a six-degree-of-freedom joint to the ground).
//!
//! In the body's frame its velocity is v_b = S(q) q̇ with q̇ = (ṗ, ċ):
//!
//! ```text
//! S q̇ = (B(c) ċ ; Rᵀ ṗ),
//! ```
//!
//! B the body angular velocity's map of the chart (ω_b = B ċ). S is invertible wherever the chart
//! is regular, so the articulated-body algorithm solves the root's whole 6 × 6 articulated
//! inertia, and its rates follow from the root's acceleration by S⁻¹ = diag(R, B⁻¹). The joint's
//! bias acceleration c_J = Ṡ q̇ (the root has no parent velocity to cross with):
//!
//! ```text
//! Ṡ q̇ = (Ḃ ċ ; −ω_b × Rᵀ ṗ),
//! ```
//!
//! from Ṙᵀ = −\[ω_b\]× Rᵀ and d/dt of B with c̈ held (the chart's, see `charts`).
//!
//! A ball joint is the free joint with its origin held: three coordinates c, ṗ = 0, the body's
//! origin at the constant offset r. Its functions here are the free joint's with p's rates zero
//! and p's entries left out (`rates`, `store`); its articulated equation keeps only the
//! angular rows (`pivot_acceleration`).

mod charts;
mod quasi;

use super::inertia::Inertia;
use super::spatial::{cross, scale3, sub3, Force, Motion, M3, V3};
use super::{Joint, JointKind, Velocities};
use crate::geometry::RotationChart;
use crate::geometry::Scalar;
use crate::linalg::{cholesky_solve, NotPositiveDefinite};
pub(crate) use charts::Orientation;
use nalgebra::{SMatrix, SVector};
pub(crate) use quasi::congruent;
pub use quasi::{
    angular_velocity_slots, equations_in_rates, has_angular_velocities, position_rates,
    rate_accelerations, rate_forces, velocities_from_rates, velocity_accelerations, velocity_bias,
    velocity_forces,
};

/// Whether the joint translates too: a free joint (six coordinates, p then c), not a ball joint
/// (three, c).
#[inline(always)]
pub(crate) fn translates(joint: &Joint) -> bool {
    matches!(joint.kind, JointKind::Free(..))
}

/// The index of c's first coordinate.
#[inline(always)]
pub(crate) fn orientation_at(joint: &Joint) -> usize {
    joint.coordinate + if translates(joint) { 3 } else { 0 }
}

/// The orientation in `chart` of the coordinates `q[at..at + 3]`, of a joint with `velocities`.
#[inline(always)]
pub(crate) fn orientation<S: Scalar, const N: usize>(
    (chart, velocities): (RotationChart, Velocities),
    q: &[S; N],
    at: usize,
) -> Orientation<S> {
    Orientation::of(chart, velocities, [q[at], q[at + 1], q[at + 2]])
}

/// Where entry `l` of the six (p, c) is among the coordinates: a ball joint has no p.
#[inline(always)]
pub(crate) fn index(joint: &Joint, l: usize) -> Option<usize> {
    match translates(joint) {
        true => Some(joint.coordinate + l),
        false => (l >= 3).then(|| joint.coordinate + l - 3),
    }
}

/// The six rates (ṗ, ċ) of the joint in `v`: a ball joint's ṗ is zero.
#[inline(always)]
pub(crate) fn rates<S: Scalar, const N: usize>(v: &[S; N], joint: &Joint) -> [S; 6] {
    std::array::from_fn(|l| index(joint, l).map_or(S::zero(), |i| v[i]))
}

/// Writes the six (p, c) entries `six` to the joint's coordinates of `out` (a ball joint's c).
#[inline(always)]
pub(crate) fn store<S: Copy>(out: &mut [S], joint: &Joint, six: [S; 6]) {
    for (l, x) in six.into_iter().enumerate() {
        if let Some(i) = index(joint, l) {
            out[i] = x;
        }
    }
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

/// The last three of six.
#[inline(always)]
fn angular<S: Copy>(x: [S; 6]) -> V3<S> {
    [x[3], x[4], x[5]]
}

/// The first three of six.
#[inline(always)]
fn linear<S: Copy>(x: [S; 6]) -> V3<S> {
    [x[0], x[1], x[2]]
}

/// (p, c) as six, p first.
#[inline(always)]
fn six<S: Copy>(p: V3<S>, c: V3<S>) -> [S; 6] {
    [p[0], p[1], p[2], c[0], c[1], c[2]]
}

/// X m for a motion of the ground: (Rᵀ ω ; Rᵀ v). The ground's motions the recursions pass (rest,
/// and the uniform field's a₀ = (0; −g)) have no angular part, so the shift to the origin p, the
/// term Rᵀ (ω × p), is zero and p is not needed.
#[inline(always)]
pub(crate) fn from_ground<S: Scalar>(o: Orientation<S>, m: &Motion<S>) -> Motion<S> {
    let r = o.rotation();
    Motion {
        angular: rotate_back(&r, m.angular),
        linear: rotate_back(&r, m.linear),
    }
}

/// (S q̇, Ṡ q̇): the body's velocity and the joint's bias acceleration (see the module docs).
#[inline(always)]
pub(crate) fn velocity<S: Scalar>(o: Orientation<S>, q_dot: [S; 6]) -> (Motion<S>, Motion<S>) {
    let omega = o.angular_velocity(angular(q_dot));
    let linear = rotate_back(&o.rotation(), linear(q_dot));
    let velocity = Motion {
        angular: omega,
        linear,
    };
    let bias = Motion {
        angular: o.angular_bias(angular(q_dot), omega),
        linear: scale3(cross(omega, linear), -S::one()),
    };
    (velocity, bias)
}

/// S⁻¹ m: the rates (ṗ, ċ) whose joint motion is m = (ω; v), ṗ = R v, ċ = B⁻¹ ω.
#[inline(always)]
pub(crate) fn rates_of<S: Scalar>(o: Orientation<S>, m: &Motion<S>) -> [S; 6] {
    six(rotate(&o.rotation(), m.linear), o.rates_of(m.angular))
}

/// S m for joint rates `rates` = (ṗ, ċ) (or accelerations): (B ċ ; Rᵀ ṗ).
#[inline(always)]
pub(crate) fn motion_of<S: Scalar>(o: Orientation<S>, rates: [S; 6]) -> Motion<S> {
    Motion {
        angular: o.angular_velocity(angular(rates)),
        linear: rotate_back(&o.rotation(), linear(rates)),
    }
}

/// Sᵀ f: the generalized forces of a force f = (n; F) on the body, (R F, Bᵀ n).
#[inline(always)]
pub(crate) fn forces_of<S: Scalar>(o: Orientation<S>, f: &Force<S>) -> [S; 6] {
    six(
        rotate(&o.rotation(), f.force),
        o.generalized_moment(f.moment),
    )
}

/// S⁻ᵀ τ: the force on the body whose generalized forces are τ = (τ_p, τ_c): (B⁻ᵀ τ_c ; Rᵀ τ_p).
#[inline(always)]
pub(crate) fn force_of<S: Scalar>(o: Orientation<S>, tau: [S; 6]) -> Force<S> {
    Force {
        moment: o.moment_of(angular(tau)),
        force: rotate_back(&o.rotation(), linear(tau)),
    }
}

/// The root's acceleration from its articulated inertia and bias force under the joint's
/// generalized forces τ: I^A a + p^A = S⁻ᵀ τ (Featherstone §9.3, the floating base's articulated
/// equation), solved by Cholesky on the 6 × 6 (angular block first).
#[inline(always)]
pub(crate) fn root_acceleration<S: Scalar>(
    o: Orientation<S>,
    inertia: &Inertia<S>,
    bias: &Force<S>,
    tau: [S; 6],
) -> Result<Motion<S>, NotPositiveDefinite> {
    let f = force_of(o, tau);
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

/// A ball root's acceleration: its origin held, the linear part is the ground's, a_v = Rᵀ a₀_v
/// (the uniform field's, in the body's frame); the angular part solves the articulated equation's
/// angular rows Sᵀ (I^A a + p^A) = τ with S = (B; 0): I^A_ωω a_ω = B⁻ᵀ τ_c − p^A_n − I^A_ωv a_v
/// (Featherstone §7.3's projection, S of three columns), by Cholesky on the 3 × 3.
#[inline(always)]
pub(crate) fn pivot_acceleration<S: Scalar>(
    o: Orientation<S>,
    inertia: &Inertia<S>,
    bias: &Force<S>,
    tau: [S; 6],
    ground: &Motion<S>,
) -> Result<Motion<S>, NotPositiveDefinite> {
    let linear = rotate_back(&o.rotation(), ground.linear);
    let coupling = inertia.apply(&Motion {
        angular: [S::zero(); 3],
        linear,
    });
    let n = o.moment_of(angular(tau));
    let rhs = SVector::<S, 3>::from_fn(|i, _| n[i] - bias.moment[i] - coupling.moment[i]);
    let block = SMatrix::<S, 3, 3>::from_fn(|i, j| inertia.a.at(i, j));
    let a = cholesky_solve(&block, &rhs)?;
    Ok(Motion {
        angular: [a[0], a[1], a[2]],
        linear,
    })
}

/// q̈ of the joint from the root's acceleration a: S q̈ = a − X a₀ − Ṡ q̇, with X a₀ the ground's
/// acceleration (the uniform field's) in the body's frame and Ṡ q̇ the joint's bias:
/// p̈ = R (a_v − c_v) − R Rᵀ a₀_v = R (a_v − c_v) − a₀_v (a₀ has no angular part),
/// c̈ = B⁻¹ (a_ω − c_ω).
#[inline(always)]
pub(crate) fn accelerations<S: Scalar>(
    o: Orientation<S>,
    a: &Motion<S>,
    ground: &Motion<S>,
    bias: &Motion<S>,
) -> [S; 6] {
    let joint = Motion {
        angular: sub3(a.angular, bias.angular),
        linear: sub3(a.linear, bias.linear),
    };
    let mut rates = rates_of(o, &joint);
    for k in 0..3 {
        rates[k] -= ground.linear[k];
    }
    rates
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::body_angular_velocity;
    use num_dual::Dual64;

    const RATES: [f64; 6] = [0.7, -1.1, 0.2, 1.0, 2.0, -0.5];

    /// Both charts at orientations where each of their branches is taken: inside the rotation
    /// vector's series (θ² < 10⁻²), at the chart's ordinary points, near and at θ = π (where the
    /// rotation vector's chart switches) and past the modified Rodrigues parameters' unit sphere.
    fn orientations() -> Vec<Orientation<f64>> {
        let pi = std::f64::consts::PI;
        let points = [
            [0.02, -0.05, 0.04],
            [0.3, -0.5, 0.4],
            [1.2, -1.9, 1.6],
            [0.0, pi * 0.6, pi * 0.8],
        ];
        let charts = [RotationChart::Mrp, RotationChart::Vector];
        charts
            .into_iter()
            .flat_map(|chart| points.map(|c| Orientation::new(chart, c)))
            .collect()
    }

    /// Relative to the scale 1 + |b|: the maps are a few dozen operations on numbers of order one,
    /// so agreement is to a small multiple of the rounding unit.
    fn close(a: &[f64], b: &[f64]) {
        for (x, y) in a.iter().zip(b) {
            assert!(
                (x - y).abs() < 1e-13 * (1.0 + y.abs()),
                "{a:?} against {b:?}"
            );
        }
    }

    #[test]
    fn the_angular_velocity_is_the_charts() {
        for o in orientations() {
            let (v, _) = velocity(o, RATES);
            let omega = body_angular_velocity(o.chart, o.c, angular(RATES));
            close(&v.angular, &omega);
        }
    }

    #[test]
    fn the_inverse_maps_undo_the_joint() {
        let tau = [1.5, -0.3, 0.8, 0.2, -1.0, 0.6];
        let f = Force {
            moment: [0.4, 0.1, -0.9],
            force: [1.0, -2.0, 0.5],
        };
        for o in orientations() {
            close(&rates_of(o, &motion_of(o, RATES)), &RATES);
            // Sᵀ (S⁻ᵀ τ) = τ.
            close(&forces_of(o, &force_of(o, tau)), &tau);
            // Power: (S q̇)·f = q̇·(Sᵀ f).
            let power = motion_of(o, RATES).dot(&f);
            let generalized: f64 = forces_of(o, &f).iter().zip(RATES).map(|(a, b)| a * b).sum();
            close(&[power], &[generalized]);
        }
    }

    /// Ṡ q̇ is d/dt (S(q(t)) q̇) with q̈ = 0: the velocity along q(t) = q + t q̇ on dual numbers.
    #[test]
    fn the_bias_is_the_joint_motions_derivative() {
        for o in orientations() {
            let moving = Orientation::new(
                o.chart,
                std::array::from_fn(|k| Dual64::new(o.c[k], RATES[3 + k])),
            );
            let (v, _) = velocity(moving, RATES.map(Dual64::from));
            let (_, c) = velocity(o, RATES);
            close(&c.angular, &v.angular.map(|x| x.eps));
            // The linear part: d/dt (Rᵀ ṗ) in the body's components.
            close(&c.linear, &v.linear.map(|x| x.eps));
        }
    }

    /// The rotation vector's series and closed forms meet at θ² = 10⁻²: the maps just below and
    /// just above agree to the series' truncation (below 10⁻¹⁸) and the closed forms' cancellation
    /// (up to 10⁻¹⁰ relative in b′, which the maps multiply by θ³ ≈ 10⁻³ and φ·φ̇).
    #[test]
    fn the_series_meet_the_closed_forms() {
        let direction = [0.6, -0.48, 0.64];
        let at = |theta2: f64| {
            Orientation::new(RotationChart::Vector, direction.map(|x| x * theta2.sqrt()))
        };
        let (below, above) = (at(1e-2 * (1.0 - 1e-12)), at(1e-2 * (1.0 + 1e-12)));
        let omega = [0.3, 1.1, -0.7];
        close(&below.rates_of(omega), &above.rates_of(omega));
        close(
            &below.angular_velocity(omega),
            &above.angular_velocity(omega),
        );
        close(
            &below.angular_bias(omega, omega),
            &above.angular_bias(omega, omega),
        );
    }
}
