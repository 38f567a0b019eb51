//! Floating mechanisms take the rigid tree pass: a root body placed by six consecutive coordinates,
//! `spatial(vec3(p..), rot_mrp(vec3(σ..)))` or `spatial(vec3(p..), rot_vector(vec3(φ..)))`, is the
//! runtime's free joint (`lagrange::tree::rigid::JointKind::Free`), and one turned by a chart about
//! a fixed point its ball joint (`JointKind::Ball`; the generated `RigidTree` impls below are the
//! proof). Every result must equal the dense pass's (`lagrange::dynamics`, over the
//! same declaration's Cartesian model, which shares no code with the recursions) at random states,
//! among them orientations at and near a rotation by π, where the charts switch.
//!
//! Tolerance: both passes are exact formulas evaluated in double precision, so they differ by
//! rounding: a few hundred operations per body on quantities of order one, and for q̈ the solve
//! with M, whose relative error is about 1e-16 times M's condition number (below 1e4 at these
//! states, see `tests/floating.rs`). 1e-12 relative to the result's size covers that (the largest
//! difference seen is below 1e-13) while catching any wrong term.

use lagrange::geometry::RotationChart;
use lagrange::prelude::*;
use lagrange::tree::rigid::{JointKind, RigidTree, Velocities};

#[path = "common/tree_vs_dense.rs"]
mod tree_vs_dense;
use tree_vs_dense::{agrees_with_dense_at, states};

const TOLERANCE: f64 = 1e-12;

/// A free base with an arm on a hinge and a block on a slide, its orientation in the chart `$chart`.
/// The base's frame as written is turned from its joint frame by a constant rotation and its centre
/// of mass is off the joint's origin (C_b and s_b of the tree reader), so the children start from
/// both.
macro_rules! floater {
    ($module:ident, $chart:ident) => {
        #[mechanism]
        pub mod $module {
            pub struct Coords {
                pub position: [f64; 3],
                pub attitude: [f64; 3],
                pub hinge: f64,
                pub slide: f64,
            }
            pub struct Floater {
                pub m: f64,
                pub l: f64,
                pub push: f64,
                pub g: f64,
            }
            #[rigid_body(mass = m, inertia = [0.3, 0.2, 0.12])]
            fn base() -> Spatial {
                let r = $chart(vec3(attitude[0], attitude[1], attitude[2]));
                spatial(
                    vec3(position[0], position[1], position[2]) + r * vec3(0.05, -0.02, 0.01),
                    r * rot_x(0.3),
                )
            }
            #[rigid_body(mass = 0.4 * m, inertia = [0.02, 0.02, 0.004])]
            fn arm() -> Spatial {
                let r = base.rotation * rot_z(0.2) * rot_y(hinge);
                spatial(
                    base.point(vec3(0.2, 0.0, 0.1)) + r * vec3(0.0, 0.0, 0.5 * l),
                    r,
                )
            }
            #[rigid_body(mass = 0.25 * m, inertia = [0.01, 0.015, 0.012])]
            fn block() -> Spatial {
                spatial(
                    base.point(vec3(-0.1, 0.15, slide - 0.05)),
                    base.rotation * rot_y(-0.4),
                )
            }
            #[gravity]
            fn down() -> Vec3 {
                vec3(0.0, 0.0, -g)
            }
            #[force(on = arm)]
            fn shove() -> Vec3 {
                vec3(push, 0.0, 0.5 * push)
            }
            #[torque(on = base)]
            fn twist() -> Vec3 {
                vec3(0.0, 0.1 * push, 0.2 * push)
            }
        }
    };
}

floater!(floater, rot_mrp);
floater!(vector_floater, rot_vector);

/// A top: a body turning about a fixed point (the pivot at a constant offset, its centre of mass
/// off the pivot along its own axis), in the chart `$chart`, with a pendulum hinged on it and a
/// torque about its axis: the runtime's ball joint.
macro_rules! top {
    ($module:ident, $chart:ident) => {
        #[mechanism]
        pub mod $module {
            pub struct Coords {
                pub attitude: [f64; 3],
                pub swing: f64,
            }
            pub struct Top {
                pub m: f64,
                pub spin: f64,
                pub g: f64,
            }
            #[rigid_body(mass = m, inertia = [0.3, 0.3, 0.5])]
            fn top() -> Spatial {
                let r = $chart(vec3(attitude[0], attitude[1], attitude[2]));
                spatial(vec3(0.1, -0.2, 0.5) + r * vec3(0.0, 0.0, 0.3), r)
            }
            #[rigid_body(mass = 0.2 * m, inertia = [0.01, 0.01, 0.002])]
            fn bob() -> Spatial {
                top.joint(vec3(0.2, 0.0, 0.3), rot_x(swing))
            }
            #[gravity]
            fn down() -> Vec3 {
                vec3(0.0, 0.0, -g)
            }
            #[torque(on = top)]
            fn drive() -> Vec3 {
                top.rotation * vec3(0.0, 0.0, spin)
            }
        }
    };
}

top!(mrp_top, rot_mrp);
top!(vector_top, rot_vector);

const FLOATER: floater::Floater = floater::Floater {
    m: 3.0,
    l: 0.6,
    push: 1.5,
    g: 9.81,
};
const VECTOR_FLOATER: vector_floater::Floater = vector_floater::Floater {
    m: 3.0,
    l: 0.6,
    push: 1.5,
    g: 9.81,
};

/// The URDF quadruped with a floating base (6 base coordinates and 12 joints, 13 bodies: the base
/// and its moving links, the fixed ones merged into them).
#[lagrange::urdf("tests/urdf/quadruped.urdf", floating)]
pub mod quadruped {}

/// The random states of `tree_vs_dense`, then the same with the orientation's coordinates
/// (3 to 5) scaled to each norm of `norms`.
fn floating_states<const N: usize>(norms: &[f64]) -> Vec<([f64; N], [f64; N])> {
    let random = states::<N>(6);
    let mut out = random.clone();
    for (k, &norm) in norms.iter().enumerate() {
        let (mut q, v) = random[k];
        let size = q[3..6].iter().map(|s| s * s).sum::<f64>().sqrt();
        q[3..6].iter_mut().for_each(|s| *s *= norm / size);
        out.push((q, v));
    }
    out
}

/// |σ| = 0.5, 0.99, 1 and 1.01: a rotation by 2.2 rad, by nearly π, by π (the chart's edge), and
/// just past it in the shadow set.
const MRP_NORMS: [f64; 4] = [0.5, 0.99, 1.0, 1.01];

#[test]
fn a_free_base_with_a_hinge_and_a_slide_takes_the_tree_pass_and_agrees_with_the_dense_one() {
    let joints = <floater::Floater as RigidTree<8, 3>>::JOINTS;
    assert_eq!(
        joints[0].kind,
        JointKind::Free(RotationChart::Mrp, Velocities::ChartRates)
    );
    assert_eq!((joints[0].parent, joints[0].coordinate), (None, 0));
    assert!(!joints[0].rotated && joints[0].offset == [false; 3]);
    assert_eq!(joints[1].parent, Some(0));
    assert!(matches!(joints[1].kind, JointKind::Revolute(_)));
    assert_eq!(joints[2].parent, Some(0));
    assert!(matches!(joints[2].kind, JointKind::Prismatic(_)));
    let states = floating_states::<8>(&MRP_NORMS);
    agrees_with_dense_at::<_, _, 8, 36>(&FLOATER, &FLOATER, &states, TOLERANCE);
    let handle = FLOATER.validated().unwrap();
    agrees_with_dense_at::<_, _, 8, 36>(&FLOATER, &handle, &states, TOLERANCE);
}

/// |φ| = 0.05 (inside the maps' series), 2.2, π − 10⁻³, π (where the chart switches) and π + 0.05
/// (just past it, as a step may end).
#[test]
fn a_free_base_in_the_rotation_vector_takes_the_tree_pass_and_agrees_with_the_dense_one() {
    let joints = <vector_floater::Floater as RigidTree<8, 3>>::JOINTS;
    assert_eq!(
        joints[0].kind,
        JointKind::Free(RotationChart::Vector, Velocities::ChartRates)
    );
    let pi = std::f64::consts::PI;
    let states = floating_states::<8>(&[0.05, 2.2, pi - 1e-3, pi, pi + 0.05]);
    agrees_with_dense_at::<_, _, 8, 36>(&VECTOR_FLOATER, &VECTOR_FLOATER, &states, TOLERANCE);
    let handle = VECTOR_FLOATER.validated().unwrap();
    agrees_with_dense_at::<_, _, 8, 36>(&VECTOR_FLOATER, &handle, &states, TOLERANCE);
}

#[test]
fn the_floating_quadruped_takes_the_tree_pass_and_agrees_with_the_dense_one() {
    // A URDF floating base's velocities are its angular velocity: the dense pass runs at the
    // rates those give, the tree's results converted (`tree_vs_dense`).
    let joints = <quadruped::Quadruped as RigidTree<18, 13>>::JOINTS;
    assert_eq!(
        joints[0].kind,
        JointKind::Free(RotationChart::Mrp, Velocities::AngularVelocity)
    );
    assert_eq!((joints[0].parent, joints[0].coordinate), (None, 0));
    assert!(joints[1..].iter().all(|j| j.parent.is_some()));
    let sys = quadruped::Quadruped::default();
    let states = floating_states::<18>(&MRP_NORMS);
    agrees_with_dense_at::<_, _, 18, 156>(&sys, &sys, &states, TOLERANCE);
    let handle = quadruped::Quadruped::default().validated().unwrap();
    agrees_with_dense_at::<_, _, 18, 156>(&sys, &handle, &states, TOLERANCE);
}

const MRP_TOP: mrp_top::Top = mrp_top::Top {
    m: 2.0,
    spin: 0.4,
    g: 9.81,
};
const VECTOR_TOP: vector_top::Top = vector_top::Top {
    m: 2.0,
    spin: 0.4,
    g: 9.81,
};

/// The random states of `tree_vs_dense`, then the same with the orientation's coordinates (0 to
/// 2) scaled to each norm of `norms`.
fn turning_states<const N: usize>(norms: &[f64]) -> Vec<([f64; N], [f64; N])> {
    let random = states::<N>(6);
    let mut out = random.clone();
    for (k, &norm) in norms.iter().enumerate() {
        let (mut q, v) = random[k];
        let size = q[0..3].iter().map(|s| s * s).sum::<f64>().sqrt();
        q[0..3].iter_mut().for_each(|s| *s *= norm / size);
        out.push((q, v));
    }
    out
}

#[test]
fn a_top_on_a_ball_joint_takes_the_tree_pass_and_agrees_with_the_dense_one() {
    let joints = <mrp_top::Top as RigidTree<4, 2>>::JOINTS;
    assert_eq!(
        joints[0].kind,
        JointKind::Ball(RotationChart::Mrp, Velocities::ChartRates)
    );
    assert_eq!((joints[0].parent, joints[0].coordinate), (None, 0));
    assert_eq!(joints[1].parent, Some(0));
    let states = turning_states::<4>(&MRP_NORMS);
    agrees_with_dense_at::<_, _, 4, 24>(&MRP_TOP, &MRP_TOP, &states, TOLERANCE);
    let handle = MRP_TOP.validated().unwrap();
    agrees_with_dense_at::<_, _, 4, 24>(&MRP_TOP, &handle, &states, TOLERANCE);

    let joints = <vector_top::Top as RigidTree<4, 2>>::JOINTS;
    assert_eq!(
        joints[0].kind,
        JointKind::Ball(RotationChart::Vector, Velocities::ChartRates)
    );
    // The gallery's torque-free body, turning about its centre of mass, is one too.
    let tumbling =
        <lagrange_gallery::scenes::tumbling_body::tumbling::Tumbling as RigidTree<3, 1>>::JOINTS;
    assert_eq!(
        tumbling[0].kind,
        JointKind::Ball(RotationChart::Vector, Velocities::ChartRates)
    );
    let pi = std::f64::consts::PI;
    let states = turning_states::<4>(&[0.05, 2.2, pi - 1e-3, pi, pi + 0.05]);
    agrees_with_dense_at::<_, _, 4, 24>(&VECTOR_TOP, &VECTOR_TOP, &states, TOLERANCE);
    let handle = VECTOR_TOP.validated().unwrap();
    agrees_with_dense_at::<_, _, 4, 24>(&VECTOR_TOP, &handle, &states, TOLERANCE);
}
