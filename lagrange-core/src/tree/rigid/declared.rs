//! What a declared mechanism's tree pass needs beyond the recursions: the generalized forces of
//! everything but the uniform field, M, 𝓕 and b together, and the constants' building blocks that
//! `#[mechanism]` prepares them from.

use super::spatial::RigidInertia;
use super::{composite, free, newton_euler, BodyConstants, Joint, RigidConstants, RigidTree};
use crate::dynamics::{self, finite_accelerations, EquationsOfMotion};
use crate::error::Result;
use crate::geometry::{Rot3, Scalar, Vec3};
use crate::model::{Coordinates, Model};
use nalgebra::SVector;

/// 𝓕 − 𝓕_g: the generalized forces of the applied forces, the direct generalized forces and the
/// potentials — everything the declaration adds to the uniform field, which the recursions take as
/// the ground's acceleration. Jᵀ F + Q − ∇V from one gradient pass over x (the tree's positions do
/// not depend on t, so ẋ = J q̇). Zero, with no pass, when nothing of the kind is declared.
///
/// The declaration's forces are functions of (q, q̇); where some of the tree's joints have the
/// angular velocity for velocities (q̇ = G(q) v,
/// [`free::position_rates`](super::free::position_rates)), they are evaluated at q̇ = G v and
/// returned dual to v: Gᵀ (Jᵀ F + Q − ∇V), the power τ_q · q̇ = (Gᵀ τ_q) · v
/// ([`free::velocity_forces`](super::free::velocity_forces)).
pub fn other_generalized_forces<
    M: Model<N, K>,
    S: Scalar,
    const N: usize,
    const K: usize,
    const B: usize,
>(
    model: &M,
    joints: &[Joint; B],
    t: S,
    q: &[S; N],
    v: &[S; N],
) -> SVector<S, N> {
    if !M::HAS_FORCES && !M::HAS_POTENTIAL {
        return SVector::<S, N>::zeros();
    }
    if !free::has_angular_velocities(joints) {
        return rate_forces(model, t, q, v);
    }
    let rates = free::position_rates(joints, q, v);
    let forces: [S; N] = rate_forces(model, t, q, &rates).into();
    free::velocity_forces(joints, q, &forces).into()
}

/// [`other_generalized_forces`] at (t, q, q̇): Jᵀ F + Q − ∇V, dual to q̇.
fn rate_forces<M: Model<N, K>, S: Scalar, const N: usize, const K: usize>(
    model: &M,
    t: S,
    q: &[S; N],
    v: &[S; N],
) -> SVector<S, N> {
    let mut forces = SVector::<S, N>::zeros();
    // Motors and joint damping alone: no x, no Jacobian (the forces read neither).
    if M::GENERALIZED_FORCES_ONLY && !M::HAS_POTENTIAL {
        let mut direct = [S::zero(); N];
        model.coordinate_forces(t, q, v, &mut direct);
        return SVector::from(direct);
    }
    let (x1, _, _) = dynamics::cartesian_with_jacobian(model, t, q);
    let x: [S; K] = std::array::from_fn(|i| x1[i].re);
    let rows: [Option<SVector<S, N>>; K] = std::array::from_fn(|i| x1[i].eps.0);
    if M::HAS_FORCES {
        let velocity = SVector::from(*v);
        let x_dot: [S; K] =
            std::array::from_fn(|i| rows[i].map_or(S::zero(), |row| row.dot(&velocity)));
        let mut cartesian = [S::zero(); K];
        let mut direct = [S::zero(); N];
        model.applied_forces(t, q, v, &x, &x_dot, &mut cartesian, &mut direct);
        forces += SVector::from(direct);
        for i in 0..K {
            if let Some(row) = &rows[i] {
                forces += row * cartesian[i];
            }
        }
    }
    if let Some(potential) = dynamics::potential_forces(model, t, q, &x, &rows) {
        forces += potential;
    }
    forces
}

/// M, 𝓕 and b at (t, q, q̇) of a declared tree: M by the composite-rigid-body algorithm, b and
/// the uniform field's 𝓕_g by one Newton–Euler sweep, the other forces as
/// [`other_generalized_forces`].
pub fn equations_of_motion<
    M: Model<N, K> + RigidTree<N, B>,
    S: Scalar,
    const N: usize,
    const K: usize,
    const B: usize,
>(
    model: &M,
    k: &RigidConstants<B>,
    t: S,
    q: &[S; N],
    v: &[S; N],
) -> EquationsOfMotion<S, N> {
    equations_on_joints(model, &M::JOINTS, k, t, q, v)
}

/// [`equations_of_motion`] at the coordinates' rates q̇, the forces those of `forces` (the
/// declaration, or the declaration with its inputs held) and the tree `joints`: where a joint has
/// the angular velocity for velocities, evaluated at v = B q̇ and converted
/// ([`free::equations_in_rates`]). What the constrained solve takes instead of the Cartesian pass
/// (`Constraints::tree_equations`), whose rows are written on the rates.
pub fn equations_of_motion_in_rates<
    F: Model<N, K>,
    S: Scalar,
    const N: usize,
    const K: usize,
    const B: usize,
>(
    forces: &F,
    joints: &[Joint; B],
    k: &RigidConstants<B>,
    t: S,
    q: &[S; N],
    rates: &[S; N],
) -> EquationsOfMotion<S, N> {
    let v = free::velocities_from_rates(joints, q, rates);
    let on_velocities = equations_on_joints(forces, joints, k, t, q, &v);
    free::equations_in_rates(joints, q, rates, on_velocities)
}

/// [`equations_of_motion`] on the tree `joints`, the forces those of `model`.
#[inline(always)]
fn equations_on_joints<
    M: Model<N, K>,
    S: Scalar,
    const N: usize,
    const K: usize,
    const B: usize,
>(
    model: &M,
    joints: &[Joint; B],
    k: &RigidConstants<B>,
    t: S,
    q: &[S; N],
    v: &[S; N],
) -> EquationsOfMotion<S, N> {
    let (inertial_terms, gravity) = newton_euler::bias_and_gravity(joints, k, q, v);
    EquationsOfMotion {
        mass_matrix: composite::mass_matrix(joints, k, q),
        generalized_forces: gravity + other_generalized_forces(model, joints, t, q, v),
        inertial_terms,
    }
}

/// τ = M q̈ + b − 𝓕 at (t, q, q̇, q̈) of a declared tree: Newton–Euler for the bodies and the
/// field, less the other forces.
pub fn inverse_dynamics<
    M: Model<N, K> + RigidTree<N, B>,
    S: Scalar,
    const N: usize,
    const K: usize,
    const B: usize,
>(
    model: &M,
    k: &RigidConstants<B>,
    t: S,
    q: &[S; N],
    v: &[S; N],
    qdd: &[S; N],
) -> [S; N] {
    let tau = newton_euler::inverse_dynamics(&M::JOINTS, k, q, v, qdd);
    less_other_forces(model, &M::JOINTS, tau, t, q, v)
}

/// τ − (𝓕 − 𝓕_g): the bodies' joint torques less what the declaration's other forces supply.
#[inline(always)]
pub fn less_other_forces<
    M: Model<N, K>,
    S: Scalar,
    const N: usize,
    const K: usize,
    const B: usize,
>(
    model: &M,
    joints: &[Joint; B],
    tau: [S; N],
    t: S,
    q: &[S; N],
    v: &[S; N],
) -> [S; N] {
    (SVector::from(tau) - other_generalized_forces(model, joints, t, q, v)).into()
}

/// q̈ from the last sweep of the articulated-body algorithm, checked finite (the error names the
/// configuration).
#[inline(always)]
pub fn finished<C: Coordinates<N>, S: Scalar, const N: usize>(
    qdd: [S; N],
    t: S,
    q: &[S; N],
) -> Result<[S; N]> {
    finite_accelerations::<C, S, N>(SVector::from(qdd), t, q)
}

/// A body's constants from what a declaration writes: its joint frame's rotation E and offset r in
/// the parent's frame, its mass, its centre of mass c in the joint frame and its rotational inertia
/// about c in the joint frame's axes.
pub fn body_constants(
    rotation: Rot3<f64>,
    offset: Vec3<f64>,
    mass: f64,
    centre_of_mass: Vec3<f64>,
    about_centre: [[f64; 3]; 3],
) -> BodyConstants {
    BodyConstants {
        rotation: rotation.rows,
        offset: offset.to_array(),
        inertia: RigidInertia::about_origin(mass, centre_of_mass.to_array(), about_centre),
    }
}

/// C T Cᵀ: a tensor given in a frame turned by C, in the unturned frame's axes.
pub fn turned_tensor(c: &Rot3<f64>, tensor: [[f64; 3]; 3]) -> [[f64; 3]; 3] {
    let c = &c.rows;
    std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            let mut sum = 0.0;
            for k in 0..3 {
                for l in 0..3 {
                    sum += c[i][k] * tensor[k][l] * c[j][l];
                }
            }
            sum
        })
    })
}

/// diag(d).
pub fn diagonal(d: [f64; 3]) -> [[f64; 3]; 3] {
    [[d[0], 0.0, 0.0], [0.0, d[1], 0.0], [0.0, 0.0, d[2]]]
}

/// A half turn about an axis across `axis` (about z for x, about x for y and z), exactly: it maps
/// `axis` to its opposite and is its own inverse, so a joint about (or along) −a is one about a
/// between two of them.
pub fn flip(axis: super::spatial::Axis) -> Rot3<f64> {
    use super::spatial::Axis;
    let d = match axis {
        Axis::X => [-1.0, -1.0, 1.0],
        Axis::Y | Axis::Z => [1.0, -1.0, -1.0],
    };
    Rot3 { rows: diagonal(d) }
}

/// A rotation whose third column is the unit vector along `axis`: a rotation about `axis` by θ is
/// F R_z(θ) Fᵀ, so a joint about any constant axis is one about z between two constant rotations.
/// The first column is the unit vector along the component of the coordinate axis least aligned
/// with `axis` that is orthogonal to it. (A zero axis, which validation refuses, gives a frame of
/// NaN.)
pub fn axis_frame(axis: Vec3<f64>) -> Rot3<f64> {
    let n = axis.norm();
    let z = [axis.x / n, axis.y / n, axis.z / n];
    let least = (0..3)
        .min_by(|&a, &b| z[a].abs().total_cmp(&z[b].abs()))
        .unwrap_or(0);
    let mut e = [0.0; 3];
    e[least] = 1.0;
    // x = e − (e·z) z, normalised; y = z × x.
    let d = e[0] * z[0] + e[1] * z[1] + e[2] * z[2];
    let x = [e[0] - d * z[0], e[1] - d * z[1], e[2] - d * z[2]];
    let xn = (x[0] * x[0] + x[1] * x[1] + x[2] * x[2]).sqrt();
    let x = [x[0] / xn, x[1] / xn, x[2] / xn];
    let y = [
        z[1] * x[2] - z[2] * x[1],
        z[2] * x[0] - z[0] * x[2],
        z[0] * x[1] - z[1] * x[0],
    ];
    Rot3 {
        rows: [[x[0], y[0], z[0]], [x[1], y[1], z[1]], [x[2], y[2], z[2]]],
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::{rot_z, vec3};

    #[test]
    fn a_rotation_about_any_axis_is_one_about_z_between_the_axis_frames() {
        for axis in [
            vec3(0.3, -0.5, 0.8),
            vec3(1.0, 0.0, 0.0),
            vec3(0.0, 0.0, -2.0),
        ] {
            let f = axis_frame(axis);
            let turned = f * rot_z(0.7) * f.transpose();
            // Rodrigues: R = cos θ 1 + sin θ [n]× + (1 − cos θ) n nᵀ.
            let n = axis * (1.0 / axis.norm());
            let n = [n.x, n.y, n.z];
            let (s, c) = 0.7f64.sin_cos();
            let nx = [[0.0, -n[2], n[1]], [n[2], 0.0, -n[0]], [-n[1], n[0], 0.0]];
            for i in 0..3 {
                for j in 0..3 {
                    let delta = if i == j { 1.0 } else { 0.0 };
                    let r = c * delta + s * nx[i][j] + (1.0 - c) * n[i] * n[j];
                    assert!((turned.rows[i][j] - r).abs() < 1e-15);
                }
            }
            // Orthonormal with determinant +1.
            let t = f * f.transpose();
            for i in 0..3 {
                for j in 0..3 {
                    assert!((t.rows[i][j] - if i == j { 1.0 } else { 0.0 }).abs() < 1e-15);
                }
            }
            let col = |k: usize| vec3(f.rows[0][k], f.rows[1][k], f.rows[2][k]);
            assert!((col(0).cross(&col(1)).dot(&col(2)) - 1.0).abs() < 1e-15);
        }
    }

    #[test]
    fn a_turned_tensor_is_c_t_c_transpose() {
        let c = rot_z(0.4);
        let t = turned_tensor(&c, diagonal([1.0, 2.0, 3.0]));
        let (s, co) = 0.4f64.sin_cos();
        assert!((t[0][0] - (co * co + 2.0 * s * s)).abs() < 1e-15);
        assert!((t[0][1] - (co * s - 2.0 * s * co)).abs() < 1e-15);
        assert!((t[2][2] - 3.0).abs() < 1e-15);
    }
}
