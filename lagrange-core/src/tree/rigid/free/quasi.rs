//! Quasi-velocities: the maps between the velocities v of a tree whose free or ball joints have
//! the angular velocity for velocities ([`Velocities::AngularVelocity`]) and the coordinates'
//! rates q̇ = G(q) v. On such a joint's orientation c, v is ω_b = B(c) ċ (the chart's map, see
//! `charts`), so G = B⁻¹ there and the identity everywhere else; a joint whose velocities are
//! the chart's rates is the identity too. The integrators advance the positions by G v; what
//! reads the velocities as rates (a declaration's forces, the methods on momenta conjugate to q̇)
//! converts by the others:
//!
//! ```text
//! q̇ = G v,   v = B q̇,   v̇ = B q̈ + Ḃ q̇,   τ_v = Gᵀ τ_q̇,   τ_q̇ = Bᵀ τ_v,
//! ```
//!
//! forces and momenta dual to the velocities by the power τ_q̇ · q̇ = τ_v · v.

use super::{orientation_at, Orientation};
use crate::dynamics::EquationsOfMotion;
use crate::geometry::{RotationChart, Scalar};
use crate::tree::rigid::{Joint, JointKind, Velocities};
use nalgebra::{SMatrix, SVector};

/// Whether some free or ball joint among `joints` has the angular velocity for velocities.
#[inline(always)]
pub const fn has_angular_velocities(joints: &[Joint]) -> bool {
    let mut i = 0;
    while i < joints.len() {
        if matches!(joints[i].velocities(), Some(Velocities::AngularVelocity)) {
            return true;
        }
        i += 1;
    }
    false
}

/// The slots whose velocities are components of an angular velocity, in order.
pub fn angular_velocity_slots(joints: &[Joint]) -> Vec<usize> {
    angular_orientations(joints)
        .flat_map(|(at, _)| at..at + 3)
        .collect()
}

/// Where each orientation with the angular velocity for velocities starts, and its chart.
#[inline(always)]
fn angular_orientations(joints: &[Joint]) -> impl Iterator<Item = (usize, RotationChart)> + '_ {
    joints.iter().filter_map(|joint| match joint.kind {
        JointKind::Free(chart, Velocities::AngularVelocity)
        | JointKind::Ball(chart, Velocities::AngularVelocity) => {
            Some((orientation_at(joint), chart))
        }
        _ => None,
    })
}

/// `base` with its three entries of every orientation with the angular velocity for velocities
/// replaced by `map` of the orientation at `q` (in its chart's rates maps) and `x`'s three.
#[inline(always)]
fn on_orientations<S: Scalar, const N: usize>(
    joints: &[Joint],
    q: &[S; N],
    (x, base): (&[S; N], [S; N]),
    map: impl Fn(&Orientation<S>, [S; 3]) -> [S; 3],
) -> [S; N] {
    let mut out = base;
    for (at, chart) in angular_orientations(joints) {
        let c = Orientation::new(chart, [q[at], q[at + 1], q[at + 2]]);
        let y = map(&c, [x[at], x[at + 1], x[at + 2]]);
        out[at..at + 3].copy_from_slice(&y);
    }
    out
}

/// q̇ = G(q) v: ċ = B(c)⁻¹ ω_b on every orientation with the angular velocity for velocities.
#[inline]
pub fn position_rates<S: Scalar, const N: usize>(
    joints: &[Joint],
    q: &[S; N],
    v: &[S; N],
) -> [S; N] {
    on_orientations(joints, q, (v, *v), |c, w| c.rates_of(w))
}

/// v = B(q) q̇, the inverse of [`position_rates`]: ω_b = B(c) ċ.
#[inline]
pub fn velocities_from_rates<S: Scalar, const N: usize>(
    joints: &[Joint],
    q: &[S; N],
    rates: &[S; N],
) -> [S; N] {
    on_orientations(joints, q, (rates, *rates), |c, r| c.angular_velocity(r))
}

/// Gᵀ τ: generalized forces dual to the rates made dual to the velocities, B⁻ᵀ τ_c (the moment
/// whose generalized forces on c are τ_c).
#[inline]
pub fn velocity_forces<S: Scalar, const N: usize>(
    joints: &[Joint],
    q: &[S; N],
    tau: &[S; N],
) -> [S; N] {
    on_orientations(joints, q, (tau, *tau), |c, t| c.moment_of(t))
}

/// Bᵀ τ: generalized forces (or momenta) dual to the velocities made dual to the rates, the
/// inverse of [`velocity_forces`].
#[inline]
pub fn rate_forces<S: Scalar, const N: usize>(
    joints: &[Joint],
    q: &[S; N],
    tau: &[S; N],
) -> [S; N] {
    on_orientations(joints, q, (tau, *tau), |c, n| c.generalized_moment(n))
}

/// Ḃ q̇ (q̈ held): what v̇ = B q̈ + Ḃ q̇ adds to B q̈, zero off the orientations with the angular
/// velocity for velocities.
#[inline]
pub fn velocity_bias<S: Scalar, const N: usize>(
    joints: &[Joint],
    q: &[S; N],
    rates: &[S; N],
) -> [S; N] {
    let bias = |c: &Orientation<S>, r| c.angular_bias(r, c.angular_velocity(r));
    on_orientations(joints, q, (rates, [S::zero(); N]), bias)
}

/// v̇ = B q̈ + Ḃ q̇: the velocities' rates of change from the coordinates' accelerations q̈ at
/// (q, q̇).
#[inline]
pub fn velocity_accelerations<S: Scalar, const N: usize>(
    joints: &[Joint],
    q: &[S; N],
    rates: &[S; N],
    qdd: &[S; N],
) -> [S; N] {
    let (b_qdd, bias) = (
        velocities_from_rates(joints, q, qdd),
        velocity_bias(joints, q, rates),
    );
    std::array::from_fn(|i| b_qdd[i] + bias[i])
}

/// q̈ = G (v̇ − Ḃ q̇), the inverse of [`velocity_accelerations`].
#[inline]
pub fn rate_accelerations<S: Scalar, const N: usize>(
    joints: &[Joint],
    q: &[S; N],
    rates: &[S; N],
    v_dot: &[S; N],
) -> [S; N] {
    let bias = velocity_bias(joints, q, rates);
    let less: [S; N] = std::array::from_fn(|i| v_dot[i] - bias[i]);
    position_rates(joints, q, &less)
}

/// Bᵀ M B: a matrix on the velocities made one on the rates (column j is Bᵀ M B eⱼ).
pub(crate) fn congruent<S: Scalar, const N: usize>(
    joints: &[Joint],
    q: &[S; N],
    m: &SMatrix<S, N, N>,
) -> SMatrix<S, N, N> {
    let mut out = SMatrix::<S, N, N>::zeros();
    for j in 0..N {
        let unit: [S; N] = std::array::from_fn(|i| if i == j { S::one() } else { S::zero() });
        let column = *m * SVector::from(velocities_from_rates(joints, q, &unit));
        out.set_column(j, &SVector::from(rate_forces(joints, q, &column.into())));
    }
    out
}

/// M, 𝓕 and b on the velocities v = B q̇ made those on the rates q̇:
///
/// ```text
/// M = Bᵀ M_v B,   𝓕 = Bᵀ 𝓕_v,   b = Bᵀ (b_v + M_v Ḃ q̇),
/// ```
///
/// from M_v v̇ + b_v = 𝓕_v with v̇ = B q̈ + Ḃ q̇, multiplied by Bᵀ. The equations as they are where
/// no joint has the angular velocity for velocities.
pub fn equations_in_rates<S: Scalar, const N: usize>(
    joints: &[Joint],
    q: &[S; N],
    rates: &[S; N],
    on_velocities: EquationsOfMotion<S, N>,
) -> EquationsOfMotion<S, N> {
    if !has_angular_velocities(joints) {
        return on_velocities;
    }
    let EquationsOfMotion {
        mass_matrix,
        generalized_forces,
        inertial_terms,
    } = on_velocities;
    let bias = SVector::from(velocity_bias(joints, q, rates));
    let to_rates = |x: SVector<S, N>| SVector::from(rate_forces(joints, q, &x.into()));
    EquationsOfMotion {
        mass_matrix: congruent(joints, q, &mass_matrix),
        generalized_forces: to_rates(generalized_forces),
        inertial_terms: to_rates(inertial_terms + mass_matrix * bias),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_dual::Dual64;

    /// A free joint with the angular velocity for velocities (coordinates 0..6), a hinge (6) and a
    /// ball joint in its chart's rates (7..10), which every map leaves as it is.
    fn joints(chart: RotationChart) -> [Joint; 3] {
        let joint = |kind, coordinate| Joint {
            parent: None,
            kind,
            coordinate,
            rotated: false,
            offset: [false; 3],
        };
        [
            joint(JointKind::Free(chart, Velocities::AngularVelocity), 0),
            joint(JointKind::Revolute(crate::tree::rigid::spatial::Axis::Z), 6),
            joint(JointKind::Ball(chart, Velocities::ChartRates), 7),
        ]
    }

    const Q: [f64; 10] = [0.3, -0.2, 0.5, 0.4, -0.7, 0.5, 1.1, 0.2, 0.1, -0.3];
    const X: [f64; 10] = [0.7, -1.1, 0.2, 1.0, 2.0, -0.5, 0.4, -0.6, 0.9, 0.3];

    fn close(a: &[f64], b: &[f64]) {
        let worst = a
            .iter()
            .zip(b)
            .map(|(x, y)| (x - y).abs())
            .fold(0.0, f64::max);
        assert!(worst < 1e-14, "{a:?} against {b:?}");
    }

    /// B and G undo each other, Bᵀ and Gᵀ too, and power is kept: (Gᵀ τ) · v = τ · (G v) and
    /// (Bᵀ τ) · q̇ = τ · (B q̇). Each a few dozen operations on numbers of order one: 1e-14.
    #[test]
    fn the_maps_are_inverse_and_dual() {
        for chart in [RotationChart::Mrp, RotationChart::Vector] {
            let joints = joints(chart);
            let rates = position_rates(&joints, &Q, &X);
            close(&velocities_from_rates(&joints, &Q, &rates), &X);
            close(
                &rate_forces(&joints, &Q, &velocity_forces(&joints, &Q, &X)),
                &X,
            );
            // τ ≠ v, so that a map and its transpose are told apart.
            let tau: [f64; 10] = std::array::from_fn(|i| 0.3 - 0.2 * i as f64);
            let power = |a: &[f64; 10], b: &[f64; 10]| a.iter().zip(b).map(|(x, y)| x * y).sum();
            let forces = velocity_forces(&joints, &Q, &tau);
            close(&[power(&forces, &X)], &[power(&tau, &rates)]);
            let back = rate_forces(&joints, &Q, &tau);
            close(&[power(&back, &rates)], &[power(&tau, &X)]);
            // Off the angular orientation every map is the identity.
            close(&rates[6..], &X[6..]);
            close(&forces[..3], &tau[..3]);
        }
    }

    /// Ḃ q̇ is the derivative of B(q) q̇ along q̇ with q̇ held: one dual pass.
    #[test]
    fn the_bias_is_b_s_derivative() {
        for chart in [RotationChart::Mrp, RotationChart::Vector] {
            let joints = joints(chart);
            let q: [Dual64; 10] = std::array::from_fn(|i| Dual64::new(Q[i], X[i]));
            let rates = X.map(Dual64::from);
            let moved = velocities_from_rates(&joints, &q, &rates).map(|x| x.eps);
            let mut expected = moved;
            expected[6..].iter_mut().for_each(|x| *x = 0.0);
            expected[..3].iter_mut().for_each(|x| *x = 0.0);
            close(&velocity_bias(&joints, &Q, &X), &expected);
        }
    }
}
