//! Robots read from URDF files the repository writes (`tests/urdf/`) by `#[lagrange::urdf]`: a
//! two-link arm against its closed form, a branched tree and a file with every supported joint
//! type against the dense pass of the same declaration and against a declaration written by hand
//! from the file's table. Each takes the rigid tree pass: the generated `RigidTree` impl is the
//! proof. (The five robots of `lagrange-robots` are held to their hand-written declarations by
//! that crate's `tests/urdf.rs`.)

use lagrange::prelude::*;
use lagrange::tree::rigid::RigidTree;

#[path = "common/tree_vs_dense.rs"]
mod tree_vs_dense;
use tree_vs_dense::{agrees_with_dense, close, states};

#[lagrange::urdf("tests/urdf/two_link_arm.urdf")]
pub mod two_link_arm {}

#[lagrange::urdf("tests/urdf/branched.urdf")]
pub mod branched {}

/// The file's declaration with an item of the user's beside it: a spring on the neck.
#[lagrange::urdf("tests/urdf/branched.urdf")]
pub mod sprung {
    #[generalized_force(on = neck)]
    fn neck_spring() -> f64 {
        -2.0 * neck
    }
}

#[lagrange::urdf("tests/urdf/every_joint.urdf")]
pub mod every_joint {}

/// `every_joint.urdf` written by hand from its table, without the macro's merging: each link's
/// inertial frame a body of its own (centre of mass at its origin, the file's tensor in its axes),
/// placed through the chain of the file's origins from the ground; the links fixed to a moving
/// link are bodies welded to it. Shares with the macro only the geometry functions.
#[mechanism]
pub mod every_joint_by_hand {
    pub struct Coords {
        pub yaw: f64,
        pub reach: f64,
        pub spin: f64,
        pub slide: f64,
        pub tilt: f64,
    }
    pub struct ByHand {
        pub g: f64,
    }
    #[rigid_body(mass = 2.5, com = vec3(0.0, 0.0, 0.0),
                 inertia = [[0.03, 0.001, -0.002], [0.001, 0.028, 0.0005], [-0.002, 0.0005, 0.02]])]
    fn turret() -> Spatial {
        let pedestal = spatial(vec3(0.1, 0.0, 0.05), rpy(0.0, 0.0, 0.7));
        let turret = pedestal.joint(vec3(0.0, 0.0, 0.2), rpy(0.05, -0.03, 0.0) * rot_z(yaw));
        turret.joint(vec3(0.02, 0.01, 0.08), rpy(0.2, 0.0, -0.1))
    }
    #[rigid_body(mass = 0.8, com = vec3(0.0, 0.0, 0.0),
                 inertia = [[0.004, 0.0, 0.0003], [0.0, 0.005, 0.0], [0.0003, 0.0, 0.003]])]
    fn mount() -> Spatial {
        let pedestal = spatial(vec3(0.1, 0.0, 0.05), rpy(0.0, 0.0, 0.7));
        let turret = pedestal.joint(vec3(0.0, 0.0, 0.2), rpy(0.05, -0.03, 0.0) * rot_z(yaw));
        let mount = turret.joint(vec3(0.1, 0.0, 0.15), rpy(0.3, -0.4, 0.2));
        mount.joint(vec3(0.05, 0.0, 0.02), rpy(0.0, 0.3, 0.0))
    }
    #[rigid_body(mass = 1.2, com = vec3(0.0, 0.03, 0.0),
                 inertia = [[0.006, 0.0, 0.0], [0.0, 0.004, 0.0002], [0.0, 0.0002, 0.005]])]
    fn carriage() -> Spatial {
        let pedestal = spatial(vec3(0.1, 0.0, 0.05), rpy(0.0, 0.0, 0.7));
        let turret = pedestal.joint(vec3(0.0, 0.0, 0.2), rpy(0.05, -0.03, 0.0) * rot_z(yaw));
        let mount = turret.joint(vec3(0.1, 0.0, 0.15), rpy(0.3, -0.4, 0.2));
        let joint = mount.joint(vec3(0.05, 0.02, 0.0), rpy(0.0, 0.0, 0.25));
        // The axis (0, 3, 4) normalised.
        spatial(
            joint.point(vec3(0.0, 0.6 * reach, 0.8 * reach)),
            joint.rotation,
        )
    }
    #[rigid_body(mass = 0.6, com = vec3(0.0, 0.0, 0.0),
                 inertia = [[0.002, 0.0, 0.0], [0.0, 0.002, 0.0], [0.0, 0.0, 0.0035]])]
    fn wheel() -> Spatial {
        let axis = vec3(1.0, 1.0, 1.0);
        let wheel = carriage.joint(
            vec3(0.0, 0.1, 0.05),
            rpy(0.0, 0.2, 0.0) * rot_axis(axis, spin),
        );
        wheel.joint(vec3(0.0, 0.0, 0.01), rpy(0.1, 0.2, 0.0))
    }
    #[rigid_body(mass = 0.3, com = vec3(0.0, 0.0, 0.04),
                 inertia = [[0.0004, 0.0, 0.0], [0.0, 0.0004, 0.0], [0.0, 0.0, 0.0002]])]
    fn tool() -> Spatial {
        let axis = vec3(1.0, 1.0, 1.0);
        let wheel = carriage.joint(
            vec3(0.0, 0.1, 0.05),
            rpy(0.0, 0.2, 0.0) * rot_axis(axis, spin),
        );
        wheel.joint(vec3(0.03, 0.0, 0.02), rpy(0.0, 0.0, 0.5))
    }
    #[rigid_body(mass = 0.9, com = vec3(0.02, 0.0, 0.0),
                 inertia = [[0.001, 0.0, 0.0], [0.0, 0.003, 0.0], [0.0, 0.0, 0.003]])]
    fn slider() -> Spatial {
        let pedestal = spatial(vec3(0.1, 0.0, 0.05), rpy(0.0, 0.0, 0.7));
        let turret = pedestal.joint(vec3(0.0, 0.0, 0.2), rpy(0.05, -0.03, 0.0) * rot_z(yaw));
        // Along −x.
        spatial(turret.point(vec3(-0.1 - slide, 0.0, 0.1)), turret.rotation)
    }
    #[rigid_body(mass = 0.4, com = vec3(0.04, 0.0, 0.0),
                 inertia = [[0.0003, 0.0, 0.0], [0.0, 0.0008, 0.0], [0.0, 0.0, 0.0009]])]
    fn flap() -> Spatial {
        slider.joint(vec3(0.05, 0.0, 0.0), rpy(1.2, 0.0, 0.0) * rot_z(-tilt))
    }
    #[gravity]
    fn down() -> Vec3 {
        vec3(0.0, 0.0, -g)
    }
    #[generalized_force(on = slide)]
    fn slide_joint() -> f64 {
        -0.4 * slide_dot - 0.05 * slide_dot.signum()
    }
    #[generalized_force(on = tilt)]
    fn tilt_joint() -> f64 {
        -0.02 * tilt_dot
    }
}

/// The two-link arm's q̈ in closed form: M(q) q̈ + C(q, q̇) q̇ + φ(q) = τ, with τ the joints'
/// damping −cᵢ q̇ᵢ. For links of mass mᵢ, centre of mass lcᵢ along the link, moment Iᵢ about the
/// joint axis through the centre, upper link length l₁ (Spong, Hutchinson & Vidyasagar, *Robot
/// Modeling and Control*, 2006, ch. 7, "planar elbow manipulator"):
/// M₁₁ = m₁lc₁² + m₂(l₁² + lc₂² + 2l₁lc₂ cos q₂) + I₁ + I₂, M₁₂ = m₂(lc₂² + l₁lc₂ cos q₂) + I₂,
/// M₂₂ = m₂lc₂² + I₂; h = −m₂l₁lc₂ sin q₂, C q̇ = (2h q̇₁q̇₂ + h q̇₂², −h q̇₁²);
/// φ = ((m₁lc₁ + m₂l₁) g cos q₁ + m₂lc₂ g cos(q₁+q₂), m₂lc₂ g cos(q₁+q₂)).
fn two_link_closed_form(q: [f64; 2], v: [f64; 2]) -> [f64; 2] {
    // The file's numbers: I is iyy, the axis being ∓y.
    let (m1, m2, l1, lc1, lc2, i1, i2, g) = (2.0, 1.5, 0.6, 0.3, 0.25, 0.06, 0.03, 9.81);
    let (c1, c2) = (0.3, 0.1);
    let m11 = m1 * lc1 * lc1 + m2 * (l1 * l1 + lc2 * lc2 + 2.0 * l1 * lc2 * q[1].cos()) + i1 + i2;
    let m12 = m2 * (lc2 * lc2 + l1 * lc2 * q[1].cos()) + i2;
    let m22 = m2 * lc2 * lc2 + i2;
    let h = -m2 * l1 * lc2 * q[1].sin();
    let phi1 = (m1 * lc1 + m2 * l1) * g * q[0].cos() + m2 * lc2 * g * (q[0] + q[1]).cos();
    let phi2 = m2 * lc2 * g * (q[0] + q[1]).cos();
    let r1 = -c1 * v[0] - (2.0 * h * v[0] * v[1] + h * v[1] * v[1]) - phi1;
    let r2 = -c2 * v[1] + h * v[0] * v[0] - phi2;
    let det = m11 * m22 - m12 * m12;
    [(m22 * r1 - m12 * r2) / det, (m11 * r2 - m12 * r1) / det]
}

#[test]
fn two_link_arm_matches_its_closed_form() {
    use two_link_arm::{Coords, State, TwoLinkArm};
    assert_eq!(<TwoLinkArm as RigidTree<2, 2>>::JOINTS.len(), 2);
    let p = TwoLinkArm::default();
    assert_eq!((p.g, p.shoulder_damping, p.elbow_damping), (9.81, 0.3, 0.1));
    let sys = p.validated().unwrap();
    for (q, v) in states::<2>(8) {
        let s = State::new(0.0, Coords::from_array(q), Coords::from_array(v));
        let qdd = sys.accelerations(&s).unwrap().to_array();
        let exact = two_link_closed_form(q, v);
        // Both sides are exact formulas in double precision (the closed form a few dozen
        // operations on quantities of order one to ten): they differ by rounding, ~1e-15.
        let scale = exact[0].abs().max(exact[1].abs());
        for j in 0..2 {
            close(qdd[j], exact[j], scale, "q̈ against the closed form");
        }
    }
    agrees_with_dense::<_, _, 2, 24>(&TwoLinkArm::default(), &TwoLinkArm::default());
}

#[test]
fn branched_tree_takes_the_tree_pass_and_equals_the_dense_pass() {
    assert_eq!(<branched::Branched as RigidTree<5, 5>>::JOINTS.len(), 5);
    agrees_with_dense::<_, _, 5, 60>(
        &branched::Branched::default(),
        &branched::Branched::default(),
    );
    agrees_with_dense::<_, _, 5, 60>(&sprung::Sprung::default(), &sprung::Sprung::default());
    // The user's spring is there: at rest with the neck turned, it changes the neck's q̈ by
    // −2 q / M's share, so the two differ.
    let s = |q| branched::State::at_rest(branched::Coords::from_array(q));
    let t = |q| sprung::State::at_rest(sprung::Coords::from_array(q));
    let q = [0.1, 0.2, 0.3, 0.4, 0.5];
    let a = branched::Branched::default()
        .accelerations(&s(q))
        .unwrap()
        .to_array();
    let b = sprung::Sprung::default()
        .accelerations(&t(q))
        .unwrap()
        .to_array();
    assert!((a[4] - b[4]).abs() > 1e-3, "{a:?} {b:?}");
}

#[test]
fn every_joint_type_takes_the_tree_pass_and_equals_the_dense_pass() {
    use every_joint::{Coords, EveryJoint};
    use every_joint_by_hand::{ByHand, Coords as HandCoords};
    assert_eq!(<EveryJoint as RigidTree<5, 5>>::JOINTS.len(), 5);
    let p = EveryJoint::default();
    assert_eq!(
        (p.slide_damping, p.slide_friction, p.tilt_damping),
        (0.4, 0.05, 0.02)
    );
    agrees_with_dense::<_, _, 5, 60>(&p, &p);
    // The same file by hand, at states with every joint moving (the friction's sign defined).
    let (sys, hand) = (
        p.validated().unwrap(),
        ByHand { g: 9.81 }.validated().unwrap(),
    );
    for (q, v) in states::<5>(6) {
        let a = every_joint::State::new(0.0, Coords::from_array(q), Coords::from_array(v));
        let b = every_joint_by_hand::State::new(
            0.0,
            HandCoords::from_array(q),
            HandCoords::from_array(v),
        );
        let (x, y) = (
            sys.accelerations(&a).unwrap().to_array(),
            hand.accelerations(&b).unwrap().to_array(),
        );
        let scale = y.iter().fold(0.0_f64, |m, e| m.max(e.abs()));
        for j in 0..5 {
            close(x[j], y[j], scale, "q̈ against the declaration by hand");
        }
    }
}
