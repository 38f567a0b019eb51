//! Kinematic trees of rigid bodies, declared as the README writes them, take the recursive pass
//! (`lagrange::tree::rigid`: the generated `RigidTree` impl below is the proof); every result must
//! equal the dense pass's (`lagrange::dynamics`, over the same declaration's Cartesian model, which
//! shares no code with the recursions) at random states.
//!
//! Tolerances: both passes are exact formulas evaluated in double precision; they differ by the
//! rounding of a few hundred operations on quantities of order one (lengths ~0.3–1, masses ~1–3,
//! velocities ≤ 2), so 1e-10 relative to the size of the result leaves a margin of about 10⁴ over
//! the observed differences (~1e-14) while catching any wrong term.

use lagrange::dynamics::equations_of_motion;
use lagrange::prelude::*;
use lagrange::tree::rigid::RigidTree;

#[path = "common/tree_vs_dense.rs"]
mod tree_vs_dense;
use tree_vs_dense::{agrees_with_dense, close};

/// A spatial arm of three links, revolute about z, y, y, declared as the README teaches (each
/// body's pose is its centre of mass and principal axes), with a payload welded to the last link.
#[mechanism]
pub mod arm {
    pub struct Coords {
        pub q1: f64,
        pub q2: f64,
        pub q3: f64,
    }
    pub struct Arm {
        pub m1: f64,
        pub m2: f64,
        pub m3: f64,
        pub mp: f64,
        pub d1: f64,
        pub d2: f64,
        pub d3: f64,
        pub e: f64,
        pub ix: f64,
        pub iy: f64,
        pub iz: f64,
        pub tilt: f64,
        pub g: f64,
    }
    #[rigid_body(mass = m1, inertia = [ix, iy, iz])]
    fn link1() -> Spatial {
        let r = rot_z(q1);
        spatial(r * vec3(0.0, 0.0, 0.5 * d1), r)
    }
    #[rigid_body(mass = m2, inertia = [ix, iy * 1.2, iz * 0.8])]
    fn link2() -> Spatial {
        let r = link1.rotation * rot_x(tilt) * rot_y(q2);
        let joint = link1.point(vec3(-e, 0.0, 0.5 * d1));
        spatial(joint + r * vec3(e, 0.0, 0.5 * d2), r)
    }
    #[rigid_body(mass = m3, inertia = [ix * 0.7, iy, iz])]
    fn link3() -> Spatial {
        let r = link2.rotation * rot_y(q3) * rot_z(0.3);
        spatial(
            link2.point(vec3(0.0, 0.1, 0.5 * d2)) + r * vec3(0.0, 0.0, 0.5 * d3),
            r,
        )
    }
    #[particle(mass = mp)]
    fn payload() -> Vec3 {
        link3.point(vec3(0.05, 0.0, 0.5 * d3))
    }
    #[gravity]
    fn down() -> Vec3 {
        vec3(0.0, 0.0, -g)
    }
}

fn arm_params() -> arm::Arm {
    arm::Arm {
        m1: 2.0,
        m2: 1.5,
        m3: 1.0,
        mp: 0.4,
        d1: 0.5,
        d2: 0.4,
        d3: 0.3,
        e: 0.07,
        ix: 0.03,
        iy: 0.025,
        iz: 0.01,
        tilt: 0.2,
        g: 9.81,
    }
}

/// A branched tree: a torso turning about z, two legs (hip about x then y, knee slides along the
/// shin), a head about a turned constant axis, damping at the hips, a spring on the knee's slide,
/// a push on the head and a torque on the torso.
#[mechanism]
pub mod walker {
    pub struct Coords {
        pub yaw: f64,
        pub hip_l: f64,
        pub knee_l: f64,
        pub hip_r: f64,
        pub knee_r: f64,
        pub nod: f64,
    }
    pub struct Walker {
        pub m: f64,
        pub w: f64,
        pub l: f64,
        pub k: f64,
        pub c: f64,
        pub push: f64,
        pub g: f64,
    }
    #[rigid_body(mass = m * 4.0, inertia = [0.2, 0.15, 0.1])]
    fn torso() -> Spatial {
        spatial(vec3(0.0, 0.0, 1.0), rot_z(yaw) * rot_x(0.1))
    }
    #[rigid_body(mass = m, inertia = [0.05, 0.05, 0.01])]
    fn thigh_l() -> Spatial {
        let r = torso.rotation * rot_x(hip_l);
        spatial(
            torso.point(vec3(w, 0.0, -0.3)) + r * vec3(0.0, 0.0, -0.5 * l),
            r,
        )
    }
    #[rigid_body(mass = m * 0.5, inertia = [0.02, 0.02, 0.005])]
    fn shin_l() -> Spatial {
        spatial(
            thigh_l.point(vec3(0.0, 0.0, -0.5 * l - knee_l)),
            thigh_l.rotation,
        )
    }
    #[rigid_body(mass = m, inertia = [0.05, 0.05, 0.01])]
    fn thigh_r() -> Spatial {
        let r = torso.rotation * rot_y(0.05) * rot_x(hip_r);
        spatial(
            torso.point(vec3(-w, 0.0, -0.3)) + r * vec3(0.0, 0.0, -0.5 * l),
            r,
        )
    }
    #[rigid_body(mass = m * 0.5, inertia = [0.02, 0.02, 0.005])]
    fn shin_r() -> Spatial {
        spatial(
            thigh_r.point(vec3(0.0, 0.0, -0.5 * l - knee_r)),
            thigh_r.rotation,
        )
    }
    #[rigid_body(mass = m * 0.8, inertia = [0.01, 0.012, 0.009])]
    fn head() -> Spatial {
        let r = torso.rotation * rot_x(0.4) * rot_z(0.3) * rot_y(nod) * rot_x(-0.4);
        spatial(
            torso.point(vec3(0.0, 0.0, 0.4)) + r * vec3(0.0, 0.05, 0.1),
            r,
        )
    }
    #[gravity]
    fn down() -> Vec3 {
        vec3(0.0, 0.0, -g)
    }
    #[potential]
    fn knees() -> f64 {
        (knee_l * knee_l + knee_r * knee_r) * (0.5 * k)
    }
    #[generalized_force(on = hip_l)]
    fn damp_l() -> f64 {
        -c * hip_l_dot
    }
    #[generalized_force(on = hip_r)]
    fn damp_r() -> f64 {
        -c * hip_r_dot
    }
    #[force(on = head)]
    fn shove() -> Vec3 {
        vec3(push, 0.0, 0.0)
    }
    #[torque(on = torso)]
    fn twist() -> Vec3 {
        vec3(0.0, 0.0, push * 0.1)
    }
}

fn walker_params() -> walker::Walker {
    walker::Walker {
        m: 1.2,
        w: 0.15,
        l: 0.45,
        k: 30.0,
        c: 0.4,
        push: 2.0,
        g: 9.81,
    }
}

/// A planar chain of three bars (a triple pendulum of rigid bodies), relative angles.
#[mechanism]
pub mod bars {
    pub struct Coords {
        pub a: f64,
        pub b: f64,
        pub c: f64,
    }
    pub struct Bars {
        pub m: f64,
        pub l: f64,
        pub g: f64,
    }
    #[rigid_body(mass = m, inertia = m * l * l / 12.0)]
    fn bar1() -> Planar {
        planar(vec2(0.5 * l, 0.0).rotated(a), a)
    }
    #[rigid_body(mass = m * 1.5, inertia = m * l * l / 8.0)]
    fn bar2() -> Planar {
        let angle = bar1.angle + b;
        planar(
            bar1.point(vec2(0.5 * l, 0.0)) + vec2(0.5 * l, 0.0).rotated(angle),
            angle,
        )
    }
    #[rigid_body(mass = m * 0.7, inertia = m * l * l / 10.0)]
    fn bar3() -> Planar {
        let angle = bar2.angle + c + 0.2;
        planar(
            bar2.point(vec2(0.5 * l, 0.0)) + vec2(0.4 * l, 0.05).rotated(angle),
            angle,
        )
    }
    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
}

/// A root link turned by a constant rotation written out as a matrix (`rot3([[..]; 3])`) and one
/// given by roll, pitch and yaw, each before its joint: both constants of the tree pass.
#[mechanism]
pub mod turned {
    pub struct Coords {
        pub q1: f64,
        pub q2: f64,
    }
    pub struct Turned {
        pub m: f64,
        pub l: f64,
        pub g: f64,
    }
    #[rigid_body(mass = m, inertia = [0.03, 0.02, 0.01])]
    fn upper() -> Spatial {
        let r = rot3([[0.0, -1.0, 0.0], [0.6, 0.0, 0.8], [-0.8, 0.0, 0.6]]) * rot_x(q1);
        spatial(r * vec3(0.0, 0.0, -0.5 * l), r)
    }
    #[rigid_body(mass = m * 0.5, inertia = [0.02, 0.02, 0.005])]
    fn lower() -> Spatial {
        let r = upper.rotation * rpy(0.1, -0.2, 0.3) * rot_y(q2);
        spatial(
            upper.point(vec3(0.0, 0.0, -0.5 * l)) + r * vec3(0.0, 0.0, -0.5 * l),
            r,
        )
    }
    #[gravity]
    fn down() -> Vec3 {
        vec3(0.0, 0.0, -g)
    }
}

#[test]
fn constant_rotations_written_as_a_matrix_or_by_roll_pitch_yaw_keep_the_tree_pass() {
    assert_eq!(<turned::Turned as RigidTree<2, 2>>::JOINTS.len(), 2);
    let sys = || turned::Turned {
        m: 1.3,
        l: 0.6,
        g: 9.81,
    };
    agrees_with_dense::<_, _, 2, 24>(&sys(), &sys());
    agrees_with_dense::<_, _, 2, 24>(&sys(), &sys().validated().unwrap());
}

/// An arm whose links are declared by their joint frames, each with its centre of mass and a
/// full inertia tensor in that frame (`com`, `inertia = [[..]; 3]`): the tree pass places the
/// centre of mass and turns the tensor itself, the dense pass maps the frames to principal axes.
#[mechanism]
pub mod framed {
    pub struct Coords {
        pub q1: f64,
        pub q2: f64,
    }
    pub struct Framed {
        pub m1: f64,
        pub m2: f64,
        pub l: f64,
        pub c: f64,
        pub ixx: f64,
        pub ixy: f64,
        pub iyz: f64,
        pub izz: f64,
        pub g: f64,
    }
    #[rigid_body(mass = m1, com = vec3(0.02, -0.01, c), inertia = [[ixx, ixy, 0.0], [ixy, ixx * 1.3, iyz], [0.0, iyz, izz]])]
    fn upper() -> Spatial {
        spatial(vec3(0.0, 0.0, 0.0), rot_z(q1))
    }
    #[rigid_body(mass = m2, com = vec3(0.05, 0.0, c), inertia = [[ixx, 0.0, ixy], [0.0, ixx, iyz], [ixy, iyz, izz * 1.5]])]
    fn lower() -> Spatial {
        let r = upper.rotation * rot_y(q2);
        spatial(upper.point(vec3(0.0, 0.1, l)), r)
    }
    #[gravity]
    fn down() -> Vec3 {
        vec3(0.0, 0.0, -g)
    }
}

#[test]
fn a_spatial_arm_takes_the_tree_pass_and_agrees_with_the_dense_one() {
    // The generated impl is the proof the recursion is taken: 4 bodies (the payload among them).
    assert_eq!(<arm::Arm as RigidTree<3, 4>>::JOINTS.len(), 4);
    agrees_with_dense::<_, _, 3, 39>(&arm_params(), &arm_params());
    agrees_with_dense::<_, _, 3, 39>(&arm_params(), &arm_params().validated().unwrap());
}

#[test]
fn a_branched_tree_with_slides_forces_and_turned_axes_agrees_with_the_dense_pass() {
    assert_eq!(<walker::Walker as RigidTree<6, 6>>::JOINTS.len(), 6);
    agrees_with_dense::<_, _, 6, 72>(&walker_params(), &walker_params());
    agrees_with_dense::<_, _, 6, 72>(&walker_params(), &walker_params().validated().unwrap());
}

#[test]
fn a_planar_chain_of_bars_agrees_with_the_dense_pass() {
    assert_eq!(<bars::Bars as RigidTree<3, 3>>::JOINTS.len(), 3);
    let sys = bars::Bars {
        m: 1.0,
        l: 0.8,
        g: 9.81,
    };
    agrees_with_dense::<_, _, 3, 9>(&sys, &sys);
}

#[test]
fn a_free_swinging_arm_keeps_its_energy() {
    // Dop853 at tolerance 1e-12 over 5 s of chaotic swinging: the energy error is the method's
    // (≈ tol per unit time), far below 1e-8 of the energy's scale (≈ 10 J).
    let sys = arm_params().validated().unwrap();
    let mut s = arm::State::new(
        0.0,
        arm::Coords {
            q1: 0.3,
            q2: 1.2,
            q3: -0.7,
        },
        arm::Coords {
            q1: 2.0,
            q2: 0.0,
            q3: 1.0,
        },
    );
    let e0 = sys.energy(&s).unwrap();
    let mut events = [];
    sys.integrate(
        lagrange::Dop853::new(1e-12, 1e-12),
        &mut s,
        5.0,
        &mut events,
        |_| {},
    )
    .unwrap();
    assert!((sys.energy(&s).unwrap() - e0).abs() < 1e-8 * e0.abs().max(1.0));
}

#[test]
fn links_declared_by_their_frames_with_full_tensors_agree_with_the_dense_pass() {
    assert_eq!(<framed::Framed as RigidTree<2, 2>>::JOINTS.len(), 2);
    let sys = || framed::Framed {
        m1: 1.5,
        m2: 0.9,
        l: 0.6,
        c: 0.25,
        ixx: 0.04,
        ixy: 0.006,
        iyz: -0.004,
        izz: 0.02,
        g: 9.81,
    };
    agrees_with_dense::<_, _, 2, 24>(&sys(), &sys());
    agrees_with_dense::<_, _, 2, 24>(&sys(), &sys().validated().unwrap());
}

/// The chain of bars with its last link's end held at a point: two loop-closure rows (a
/// four-bar linkage with the ground as the fourth bar). The tree pass gives M and b, the rows are
/// solved on top of them.
#[mechanism]
pub mod bars_loop {
    pub struct Coords {
        pub a: f64,
        pub b: f64,
        pub c: f64,
    }
    pub struct BarsLoop {
        pub m: f64,
        pub l: f64,
        pub g: f64,
        pub px: f64,
        pub py: f64,
    }
    #[rigid_body(mass = m, inertia = m * l * l / 12.0)]
    fn bar1() -> Planar {
        planar(vec2(0.5 * l, 0.0).rotated(a), a)
    }
    #[rigid_body(mass = m * 1.5, inertia = m * l * l / 8.0)]
    fn bar2() -> Planar {
        let angle = bar1.angle + b;
        planar(
            bar1.point(vec2(0.5 * l, 0.0)) + vec2(0.5 * l, 0.0).rotated(angle),
            angle,
        )
    }
    #[rigid_body(mass = m * 0.7, inertia = m * l * l / 10.0)]
    fn bar3() -> Planar {
        let angle = bar2.angle + c;
        planar(
            bar2.point(vec2(0.5 * l, 0.0)) + vec2(0.5 * l, 0.0).rotated(angle),
            angle,
        )
    }
    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
    /// The far end of bar 3, l (cos a + cos(a + b) + cos(a + b + c)) along x, held at px.
    #[constraint]
    fn end_x() -> f64 {
        l * (a.cos() + (a + b).cos() + (a + b + c).cos()) - px
    }
    #[constraint]
    fn end_y() -> f64 {
        l * (a.sin() + (a + b).sin() + (a + b + c).sin()) - py
    }
}

#[test]
fn a_closed_loop_on_a_tree_takes_the_tree_pass_under_its_constraint_rows() {
    assert_eq!(<bars_loop::BarsLoop as RigidTree<3, 3>>::JOINTS.len(), 3);
    let (m, l, g) = (1.0, 0.8, 9.81);
    // A closed configuration: the end's place at q0 is where it is held.
    let q0 = [0.3, 0.9, -1.2];
    let angles = |q: &[f64; 3]| [q[0], q[0] + q[1], q[0] + q[1] + q[2]];
    let phi = angles(&q0);
    let (px, py) = (
        l * phi.iter().map(|p| p.cos()).sum::<f64>(),
        l * phi.iter().map(|p| p.sin()).sum::<f64>(),
    );
    let sys = bars_loop::BarsLoop { m, l, g, px, py };
    // J of the two rows: ∂/∂q_j of l Σ_i (cos φ_i, sin φ_i) sums the bars at and beyond joint j.
    let jacobian = |q: &[f64; 3]| {
        let phi = angles(q);
        nalgebra::SMatrix::<f64, 2, 3>::from_fn(|r, j| {
            (j..3)
                .map(|i| match r {
                    0 => -l * phi[i].sin(),
                    _ => l * phi[i].cos(),
                })
                .sum()
        })
    };
    let jac = jacobian(&q0);
    // q̇ along the loop's one freedom: the null direction of J (the rows' cross product).
    let (r0, r1) = (jac.row(0).transpose(), jac.row(1).transpose());
    let v0: [f64; 3] = (0.7 * r0.cross(&r1) / r0.cross(&r1).norm()).into();
    // J̇ q̇ = −l Σ_i (cos φ_i, sin φ_i) φ̇_i².
    let rates = [v0[0], v0[0] + v0[1], v0[0] + v0[1] + v0[2]];
    let jdot_v = nalgebra::Vector2::new(
        -l * (0..3)
            .map(|i| phi[i].cos() * rates[i] * rates[i])
            .sum::<f64>(),
        -l * (0..3)
            .map(|i| phi[i].sin() * rates[i] * rates[i])
            .sum::<f64>(),
    );
    // The reference: the KKT system [M Jᵀ; J 0] [q̈; −λ] = [𝓕 − b; −J̇ q̇] on the dense pass's M, 𝓕, b.
    let dense = equations_of_motion::<_, f64, 3, 9>(&sys, 0.0, &q0, &v0);
    let mut kkt = nalgebra::SMatrix::<f64, 5, 5>::zeros();
    kkt.fixed_view_mut::<3, 3>(0, 0)
        .copy_from(&dense.mass_matrix);
    kkt.fixed_view_mut::<2, 3>(3, 0).copy_from(&jac);
    kkt.fixed_view_mut::<3, 2>(0, 3).copy_from(&jac.transpose());
    let mut rhs = nalgebra::SVector::<f64, 5>::zeros();
    rhs.fixed_rows_mut::<3>(0)
        .copy_from(&(dense.generalized_forces - dense.inertial_terms));
    rhs.fixed_rows_mut::<2>(3).copy_from(&(-jdot_v));
    let expected = kkt.lu().solve(&rhs).unwrap();
    let scale = expected.fixed_rows::<3>(0).abs().max();
    let s = State::new(
        0.0,
        bars_loop::Coords::from_array(q0),
        bars_loop::Coords::from_array(v0),
    );
    for qdd in [
        sys.accelerations(&s).unwrap().to_array(),
        bars_loop::BarsLoop { m, l, g, px, py }
            .validated()
            .unwrap()
            .accelerations(&s)
            .unwrap()
            .to_array(),
    ] {
        for j in 0..3 {
            close(qdd[j], expected[j], scale, "q̈ under the loop's rows");
        }
    }
    // And M, 𝓕 from the tree pass equal the dense pass's under the rows too.
    let tree_m = sys.mass_matrix(&s).unwrap();
    for (a, b) in tree_m.iter().zip(dense.mass_matrix.iter()) {
        close(*a, *b, dense.mass_matrix.abs().max(), "M");
    }
}
