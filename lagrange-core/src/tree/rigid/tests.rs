//! The three recursions against each other and against the Lagrangian of the same tree built from
//! its world frames with dual numbers — an evaluation that shares no spatial algebra with them.

use super::spatial::{Axis, RigidInertia};
use super::*;
use crate::geometry::{rot_x, rot_y, rot_z};
use nalgebra::{SMatrix, SVector};
use num_dual::Dual64;

const B: usize = 7;
const N: usize = 6;

/// A tree of seven bodies over six coordinates: revolute joints about each axis, a slide, a
/// welded body, branches, constant rotations and offsets, full inertia tensors.
fn tree() -> ([Joint; B], RigidConstants<B>) {
    use JointKind::*;
    let kinds = [
        (None, Revolute(Axis::Z)),
        (Some(0), Revolute(Axis::Y)),
        (Some(1), Prismatic(Axis::X)),
        (Some(1), Fixed),
        (Some(0), Revolute(Axis::X)),
        (Some(4), Revolute(Axis::Z)),
        (Some(3), Revolute(Axis::Y)),
    ];
    let mut coordinate = 0;
    let joints = kinds.map(|(parent, kind)| {
        let c = coordinate;
        if kind != Fixed {
            coordinate += 1;
        }
        Joint {
            parent,
            kind,
            coordinate: c,
            rotated: true,
            offset: [true; 3],
        }
    });
    let bodies = std::array::from_fn(|b| {
        let x = b as f64;
        BodyConstants {
            rotation: (rot_z(0.3 * x - 0.4) * rot_y(0.7 - 0.2 * x) * rot_x(0.1 * x + 0.2)).rows,
            offset: [0.1 + 0.05 * x, -0.2 + 0.1 * x, 0.3 - 0.04 * x],
            inertia: RigidInertia::about_origin(
                1.0 + 0.3 * x,
                [0.05 * x - 0.1, 0.2 - 0.03 * x, 0.15],
                [
                    [0.30 + 0.01 * x, 0.010, -0.020],
                    [0.010, 0.25, 0.005 * x],
                    [-0.020, 0.005 * x, 0.20 + 0.02 * x],
                ],
            ),
        }
    });
    (
        joints,
        RigidConstants {
            bodies,
            gravity: [0.3, -0.5, -9.81],
        },
    )
}

/// The same tree with its root free: six coordinates (origin, then the orientation in `chart`)
/// before the other five, the root's E the identity and r zero as a free joint has them.
fn floating_tree(chart: RotationChart) -> ([Joint; B], RigidConstants<B>) {
    let (mut joints, mut k) = tree();
    for joint in joints.iter_mut().skip(1) {
        if joint.kind != JointKind::Fixed {
            joint.coordinate += 5;
        }
    }
    joints[0] = Joint {
        parent: None,
        kind: JointKind::Free(chart, Velocities::ChartRates),
        coordinate: 0,
        rotated: false,
        offset: [false; 3],
    };
    k.bodies[0].rotation = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    k.bodies[0].offset = [0.0; 3];
    (joints, k)
}

/// A state of the floating tree: the orientation's coordinates of norm 0.877 (as modified Rodrigues
/// parameters a turn by 4 tan⁻¹(0.877) ≈ 166°, near the switch; as a rotation vector by 50°), the
/// root moving and spinning.
fn floating_state() -> ([f64; N + 5], [f64; N + 5]) {
    let (q, v) = state();
    let root_q = [0.4, -0.2, 1.1, 0.5, -0.6, 0.4];
    let root_v = [0.3, 1.2, -0.8, 0.7, -0.4, 1.1];
    (
        std::array::from_fn(|j| if j < 6 { root_q[j] } else { q[j - 5] }),
        std::array::from_fn(|j| if j < 6 { root_v[j] } else { v[j - 5] }),
    )
}

/// The same tree with its root on a ball joint: three coordinates (the orientation in `chart`)
/// before the other five, the root's origin held at a constant offset, E the identity.
fn ball_tree(chart: RotationChart) -> ([Joint; B], RigidConstants<B>) {
    let (mut joints, mut k) = floating_tree(chart);
    for joint in joints.iter_mut().skip(1) {
        if joint.kind != JointKind::Fixed {
            joint.coordinate -= 3;
        }
    }
    joints[0].kind = JointKind::Ball(chart, Velocities::ChartRates);
    joints[0].offset = [true; 3];
    k.bodies[0].offset = [0.2, -0.1, 0.4];
    (joints, k)
}

/// A state of the ball tree: the floating state without the root's position.
fn ball_state() -> ([f64; N + 2], [f64; N + 2]) {
    let (q, v) = floating_state();
    (
        std::array::from_fn(|j| q[j + 3]),
        std::array::from_fn(|j| v[j + 3]),
    )
}

fn state() -> ([f64; N], [f64; N]) {
    (
        [0.3, -1.1, 0.25, 0.8, -0.4, 2.0],
        [1.2, -0.7, 0.4, -1.5, 0.9, 0.3],
    )
}

/// The world-frame Lagrangian's pieces at q on any scalar: each body's centre of mass and
/// orientation from [`world_frames`].
fn centres_and_rotations<S: crate::geometry::Scalar, const N: usize, const B: usize>(
    joints: &[Joint; B],
    k: &RigidConstants<B>,
    q: &[S; N],
) -> [([S; 3], [[S; 3]; 3]); B] {
    let frames = world_frames(joints, k, q);
    std::array::from_fn(|b| {
        let inertia = &k.bodies[b].inertia;
        let c = inertia.first_moment.map(|h| h / inertia.mass);
        let f = &frames[b];
        let com = std::array::from_fn(|i| {
            f.origin[i]
                + f.rotation[i][0] * c[0]
                + f.rotation[i][1] * c[1]
                + f.rotation[i][2] * c[2]
        });
        (com, f.rotation)
    })
}

/// T at (q, q̇) from the world frames: ½ m |ċ|² + ½ ωᵀ R Ī_c Rᵀ ω per body, with ċ and Ṙ the
/// derivatives along q̇ (dual numbers) and ω from Ṙ Rᵀ.
fn reference_kinetic_energy<const N: usize, const B: usize>(
    joints: &[Joint; B],
    k: &RigidConstants<B>,
    q: &[f64; N],
    v: &[f64; N],
) -> f64 {
    let qd: [Dual64; N] = std::array::from_fn(|j| Dual64::new(q[j], v[j]));
    let bodies = centres_and_rotations(joints, k, &qd);
    let mut t = 0.0;
    for (b, (com, rot)) in bodies.iter().enumerate() {
        let inertia = &k.bodies[b].inertia;
        let m = inertia.mass;
        t += 0.5 * m * com.iter().map(|x| x.eps * x.eps).sum::<f64>();
        // ω× = Ṙ Rᵀ; the body-frame ω_b = Rᵀ ω, and Ī_c = Ī − m(|c|² − c cᵀ).
        let r = rot.map(|row| row.map(|x| x.re));
        let rd = rot.map(|row| row.map(|x| x.eps));
        let w = |i: usize, j: usize| (0..3).map(|l| rd[i][l] * r[j][l]).sum::<f64>();
        let omega = [w(2, 1), w(0, 2), w(1, 0)];
        let body_omega: [f64; 3] =
            std::array::from_fn(|j| (0..3).map(|i| r[i][j] * omega[i]).sum());
        let c = inertia.first_moment.map(|h| h / m);
        let c2: f64 = c.iter().map(|x| x * x).sum();
        let about_com = |i: usize, j: usize| {
            inertia.rotational[i][j] - m * (if i == j { c2 } else { 0.0 } - c[i] * c[j])
        };
        for i in 0..3 {
            for j in 0..3 {
                t += 0.5 * body_omega[i] * about_com(i, j) * body_omega[j];
            }
        }
    }
    t
}

fn reference_potential<S: crate::geometry::Scalar, const N: usize, const B: usize>(
    joints: &[Joint; B],
    k: &RigidConstants<B>,
    q: &[S; N],
) -> S {
    let bodies = centres_and_rotations(joints, k, q);
    let mut v = S::zero();
    for (b, (com, _)) in bodies.iter().enumerate() {
        for i in 0..3 {
            v -= com[i] * (k.bodies[b].inertia.mass * k.gravity[i]);
        }
    }
    v
}

fn mass_matrix_is_the_hessian<const N: usize, const B: usize>(
    (joints, k): ([Joint; B], RigidConstants<B>),
    (q, v): ([f64; N], [f64; N]),
) {
    let m = mass_matrix(&joints, &k, &q);
    let t = kinetic_energy(&joints, &k, &q, &v);
    let qdot = SVector::<f64, N>::from(v);
    assert!((0.5 * qdot.dot(&(m * qdot)) - t).abs() < 1e-12 * t);
    assert!((reference_kinetic_energy(&joints, &k, &q, &v) - t).abs() < 1e-12 * t);
    // M_ij from the reference energy by polarisation: T(e_i + e_j) − T(e_i) − T(e_j).
    let unit = |i: usize| std::array::from_fn::<f64, N, _>(|j| if i == j { 1.0 } else { 0.0 });
    for i in 0..N {
        for j in 0..N {
            let both: [f64; N] = std::array::from_fn(|l| unit(i)[l] + unit(j)[l]);
            let t_ij = reference_kinetic_energy(&joints, &k, &q, &both)
                - reference_kinetic_energy(&joints, &k, &q, &unit(i))
                - reference_kinetic_energy(&joints, &k, &q, &unit(j));
            let reference = match i == j {
                true => 2.0 * reference_kinetic_energy(&joints, &k, &q, &unit(i)),
                false => t_ij,
            };
            let m_ij = m[(i, j)];
            assert!(
                (m_ij - reference).abs() < 1e-12,
                "M[{i},{j}] = {m_ij}, reference {reference}"
            );
        }
    }
    assert_eq!(m, m.transpose());
}

fn momenta_are_m_q_dot<const N: usize, const B: usize>(
    (joints, k): ([Joint; B], RigidConstants<B>),
    (q, v): ([f64; N], [f64; N]),
) {
    let p = momenta(&joints, &k, &q, &v);
    let expected = mass_matrix(&joints, &k, &q) * SVector::<f64, N>::from(v);
    for j in 0..N {
        assert!((p[j] - expected[j]).abs() < 1e-12);
    }
}

fn gravity_is_minus_grad_v<const N: usize, const B: usize>(
    (joints, k): ([Joint; B], RigidConstants<B>),
    (q, v): ([f64; N], [f64; N]),
) {
    let (_, gravity) = bias_and_gravity(&joints, &k, &q, &v);
    for j in 0..N {
        let qd: [Dual64; N] =
            std::array::from_fn(|l| Dual64::new(q[l], if l == j { 1.0 } else { 0.0 }));
        let dv = reference_potential(&joints, &k, &qd).eps;
        assert!(
            (gravity[j] + dv).abs() < 1e-12,
            "𝓕_g[{j}] = {}, −∂V = {}",
            gravity[j],
            -dv
        );
    }
}

/// b = Ṁ q̇ − ∂T/∂q (Lagrange's equations at q̈ = 0), Ṁ along q̇ and ∂T/∂q by dual numbers.
fn inertial_terms_are_lagrange_s<const N: usize, const B: usize>(
    (joints, k): ([Joint; B], RigidConstants<B>),
    (q, v): ([f64; N], [f64; N]),
) {
    let (bias, _) = bias_and_gravity(&joints, &k, &q, &v);
    let along: [Dual64; N] = std::array::from_fn(|j| Dual64::new(q[j], v[j]));
    let m_dot = mass_matrix(&joints, &k, &along).map(|x| x.eps);
    let m_dot_v = m_dot * SVector::<f64, N>::from(v);
    let vd = v.map(Dual64::from);
    for j in 0..N {
        let qd: [Dual64; N] =
            std::array::from_fn(|l| Dual64::new(q[l], if l == j { 1.0 } else { 0.0 }));
        let dt = kinetic_energy(&joints, &k, &qd, &vd).eps;
        let expected = m_dot_v[j] - dt;
        assert!(
            (bias[j] - expected).abs() < 1e-11,
            "b[{j}] = {}, Lagrange {expected}",
            bias[j]
        );
    }
}

/// q̈ = M⁻¹ (τ + 𝓕_g − b), undone by inverse dynamics; on dual numbers ∂q̈/∂τ₀ = M⁻¹ e₀.
fn articulated_solves_the_equations<const N: usize, const B: usize>(
    (joints, k): ([Joint; B], RigidConstants<B>),
    (q, v): ([f64; N], [f64; N]),
) where
    [f64; N]: Default,
{
    type Names<const N: usize> = [f64; N];
    let tau: [f64; N] =
        std::array::from_fn(|j| [0.5, -1.0, 2.0, 0.1, -0.3, 0.7][j % 6] + 0.1 * j as f64);
    let qdd = accelerations::<Names<N>, f64, N, B>(&joints, &k, 0.0, &q, &v, &tau).unwrap();
    let m = mass_matrix(&joints, &k, &q);
    let (bias, gravity) = bias_and_gravity(&joints, &k, &q, &v);
    let rhs = SVector::<f64, N>::from(tau) + gravity - bias;
    let expected = m.cholesky().unwrap().solve(&rhs);
    for j in 0..N {
        assert!((qdd[j] - expected[j]).abs() < 1e-11 * (1.0 + expected[j].abs()));
    }
    // Inverse dynamics undoes it.
    let back = joint_torques(&joints, &k, &q, &v, &qdd);
    for j in 0..N {
        assert!((back[j] - tau[j]).abs() < 1e-11);
    }
    // On dual numbers: ∂q̈/∂τ₀ is the first column of M⁻¹.
    let taud: [Dual64; N] =
        std::array::from_fn(|j| Dual64::new(tau[j], if j == 0 { 1.0 } else { 0.0 }));
    let (qd, vd) = (q.map(Dual64::from), v.map(Dual64::from));
    let qdd_d =
        accelerations::<Names<N>, Dual64, N, B>(&joints, &k, Dual64::from(0.0), &qd, &vd, &taud)
            .unwrap();
    let column = m.try_inverse().unwrap().column(0).into_owned();
    for j in 0..N {
        assert!((qdd_d[j].eps - column[j]).abs() < 1e-11);
        assert!((qdd_d[j].re - qdd[j]).abs() < 1e-12);
    }
}

#[test]
fn the_mass_matrix_is_the_kinetic_energy_s_hessian() {
    mass_matrix_is_the_hessian(tree(), state());
    for chart in [RotationChart::Mrp, RotationChart::Vector] {
        mass_matrix_is_the_hessian(floating_tree(chart), floating_state());
        mass_matrix_is_the_hessian(ball_tree(chart), ball_state());
    }
}

#[test]
fn momenta_are_m_times_the_velocities() {
    momenta_are_m_q_dot(tree(), state());
    for chart in [RotationChart::Mrp, RotationChart::Vector] {
        momenta_are_m_q_dot(floating_tree(chart), floating_state());
        momenta_are_m_q_dot(ball_tree(chart), ball_state());
    }
}

#[test]
fn gravity_is_minus_the_potential_s_gradient() {
    gravity_is_minus_grad_v(tree(), state());
    for chart in [RotationChart::Mrp, RotationChart::Vector] {
        gravity_is_minus_grad_v(floating_tree(chart), floating_state());
        gravity_is_minus_grad_v(ball_tree(chart), ball_state());
    }
}

#[test]
fn the_inertial_terms_are_lagrange_s() {
    inertial_terms_are_lagrange_s(tree(), state());
    for chart in [RotationChart::Mrp, RotationChart::Vector] {
        inertial_terms_are_lagrange_s(floating_tree(chart), floating_state());
        inertial_terms_are_lagrange_s(ball_tree(chart), ball_state());
    }
}

#[test]
fn the_articulated_body_algorithm_solves_m_qdd_equals_tau_plus_f_minus_b() {
    articulated_solves_the_equations(tree(), state());
    for chart in [RotationChart::Mrp, RotationChart::Vector] {
        articulated_solves_the_equations(floating_tree(chart), floating_state());
        articulated_solves_the_equations(ball_tree(chart), ball_state());
    }
}

#[test]
fn a_tree_with_no_inertia_about_a_joint_is_singular() {
    type Names = [f64; 1];
    // A point mass on the axis of its own revolute joint: nothing resists q̈.
    let joints = [Joint {
        parent: None,
        kind: JointKind::Revolute(Axis::Z),
        coordinate: 0,
        rotated: false,
        offset: [false; 3],
    }];
    let k = RigidConstants {
        bodies: [BodyConstants {
            rotation: [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
            offset: [0.0; 3],
            inertia: RigidInertia::about_origin(2.0, [0.0, 0.0, 0.5], [[0.0; 3]; 3]),
        }],
        gravity: [0.0, 0.0, -9.81],
    };
    let err =
        accelerations::<Names, f64, 1, 1>(&joints, &k, 0.0, &[0.2], &[0.0], &[0.0]).unwrap_err();
    assert!(
        matches!(
            err,
            crate::Error::SingularMassMatrix {
                coordinate: "q0",
                ..
            }
        ),
        "{err}"
    );
}

#[test]
fn structural_zeros_left_out_change_nothing() {
    // The same tree with E = 1 and offsets along one axis, declared as such or not.
    let (joints, mut k) = tree();
    let mut declared = joints;
    for b in 0..B {
        k.bodies[b].rotation = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
        k.bodies[b].offset = [0.0, 0.0, 0.2 + 0.1 * b as f64];
        declared[b].rotated = false;
        declared[b].offset = [false, false, true];
    }
    let (q, v) = state();
    let tau = [0.5, -1.0, 2.0, 0.1, -0.3, 0.7];
    type Names = [f64; N];
    let full = accelerations::<Names, f64, N, B>(&joints, &k, 0.0, &q, &v, &tau).unwrap();
    let folded = accelerations::<Names, f64, N, B>(&declared, &k, 0.0, &q, &v, &tau).unwrap();
    for j in 0..N {
        assert!((full[j] - folded[j]).abs() < 1e-12 * (1.0 + full[j].abs()));
    }
    let m: SMatrix<f64, N, N> = mass_matrix(&declared, &k, &q);
    assert!(m.cholesky().is_some());
}

#[test]
fn a_joint_s_code_holds_its_kind() {
    use RotationChart::{Mrp, Vector};
    use Velocities::{AngularVelocity, ChartRates};
    let kinds = [
        JointKind::Revolute(Axis::Z),
        JointKind::Prismatic(Axis::Y),
        JointKind::Fixed,
        JointKind::Free(Mrp, ChartRates),
        JointKind::Free(Vector, ChartRates),
        JointKind::Ball(Mrp, ChartRates),
        JointKind::Ball(Vector, ChartRates),
        JointKind::Free(Mrp, AngularVelocity),
        JointKind::Free(Vector, AngularVelocity),
        JointKind::Ball(Mrp, AngularVelocity),
        JointKind::Ball(Vector, AngularVelocity),
    ];
    for kind in kinds {
        let joint = Joint {
            parent: None,
            kind,
            coordinate: 4,
            rotated: true,
            offset: [true, false, true],
        };
        assert_eq!(joint.decoded(joint.code()), joint);
    }
}
