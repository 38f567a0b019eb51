//! Kinematic trees of rigid bodies, declared as the README writes them, take the recursive pass
//! (`lagrange::tree::rigid`: the generated `RigidTree` impl below is the proof); every result must
//! equal the dense pass's (`lagrange::dynamics`, over the same declaration's Cartesian model, which
//! shares no code with the recursions) at random states.
//!
//! Tolerances: both passes are exact formulas evaluated in double precision; they differ by the
//! rounding of a few hundred operations on quantities of order one (lengths ~0.3–1, masses ~1–3,
//! velocities ≤ 2), so 1e-10 relative to the size of the result leaves a margin of about 10⁴ over
//! the observed differences (~1e-14) while catching any wrong term.

use lagrange::dynamics::{equations_of_motion, kinetic_energy, momenta};
use lagrange::model::Model;
use lagrange::prelude::*;
use lagrange::tree::rigid::RigidTree;
use nalgebra::SVector;

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

/// Random states, the same every run (a linear congruential sequence in [−1, 1)).
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

fn states<const N: usize>(count: usize) -> Vec<([f64; N], [f64; N])> {
    let mut seed: u64 = 0x2545_f491_4f6c_dd1d;
    let mut next = move || {
        seed = seed
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (seed >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    };
    (0..count)
        .map(|_| {
            let q = std::array::from_fn(|_| 1.5 * next());
            let v = std::array::from_fn(|_| 2.0 * next());
            (q, v)
        })
        .collect()
}

fn close(a: f64, b: f64, scale: f64, what: &str) {
    assert!(
        (a - b).abs() <= 1e-10 * scale.max(1.0),
        "{what}: tree {a}, dense {b}"
    );
}

type Named<M, const N: usize> = <M as lagrange::mechanism::Dynamics<N>>::Coords;

/// Every evaluation through the tree pass against the dense pass of the same declaration.
fn agrees_with_dense<M, const N: usize, const K: usize>(sys: &M)
where
    M: Mechanism<N> + Model<N, K>,
{
    for (q, v) in states::<N>(6) {
        let s = State::new(
            0.0,
            Named::<M, N>::from_array(q),
            Named::<M, N>::from_array(v),
        );
        let dense = equations_of_motion::<M, f64, N, K>(sys, 0.0, &q, &v);
        let m = sys.mass_matrix(&s).unwrap();
        let scale = dense.mass_matrix.abs().max();
        for (a, b) in m.iter().zip(dense.mass_matrix.iter()) {
            close(*a, *b, scale, "M");
        }
        let f = sys.generalized_forces(&s).unwrap().to_array();
        let rhs = dense.generalized_forces - dense.inertial_terms;
        let expected = dense.mass_matrix.cholesky().unwrap().solve(&rhs);
        let qdd = sys.accelerations(&s).unwrap().to_array();
        let scale = expected.abs().max();
        for j in 0..N {
            close(
                f[j],
                dense.generalized_forces[j],
                dense.generalized_forces.abs().max(),
                "𝓕",
            );
            close(qdd[j], expected[j], scale, "q̈");
        }
        // Inverse dynamics of a q̈ that is not the free motion's: M q̈ + b − 𝓕.
        let wanted = SVector::<f64, N>::from_fn(|j, _| 0.3 * j as f64 - 0.5);
        let tau = sys
            .inverse_dynamics(&s, &Named::<M, N>::from_array(wanted.into()))
            .unwrap()
            .to_array();
        let expected = dense.mass_matrix * wanted + dense.inertial_terms - dense.generalized_forces;
        for j in 0..N {
            close(tau[j], expected[j], expected.abs().max(), "τ");
        }
        let t_dense = kinetic_energy::<M, f64, N, K>(sys, 0.0, &q, &v);
        close(sys.kinetic_energy(&s).unwrap(), t_dense, t_dense, "T");
        let p_dense = momenta::<M, f64, N, K>(sys, 0.0, &q, &v);
        let p = sys.momenta(&s).unwrap().to_array();
        for j in 0..N {
            close(p[j], p_dense[j], 1.0, "p");
        }
    }
}

#[test]
fn a_spatial_arm_takes_the_tree_pass_and_agrees_with_the_dense_one() {
    // The generated impl is the proof the recursion is taken: 4 bodies (the payload among them).
    assert_eq!(<arm::Arm as RigidTree<3, 4>>::JOINTS.len(), 4);
    agrees_with_dense::<_, 3, 39>(&arm_params());
    agrees_with_dense::<_, 3, 39>(&arm_params().validated().unwrap());
}

#[test]
fn a_branched_tree_with_slides_forces_and_turned_axes_agrees_with_the_dense_pass() {
    assert_eq!(<walker::Walker as RigidTree<6, 6>>::JOINTS.len(), 6);
    agrees_with_dense::<_, 6, 72>(&walker_params());
    agrees_with_dense::<_, 6, 72>(&walker_params().validated().unwrap());
}

#[test]
fn a_planar_chain_of_bars_agrees_with_the_dense_pass() {
    assert_eq!(<bars::Bars as RigidTree<3, 3>>::JOINTS.len(), 3);
    let sys = bars::Bars {
        m: 1.0,
        l: 0.8,
        g: 9.81,
    };
    agrees_with_dense::<_, 3, 9>(&sys);
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
    lagrange::Dop853::new(1e-12, 1e-12)
        .integrate(&sys, &mut s, 5.0, &mut events, |_| {})
        .unwrap();
    assert!((sys.energy(&s).unwrap() - e0).abs() < 1e-8 * e0.abs().max(1.0));
}

#[test]
fn links_declared_by_their_frames_with_full_tensors_agree_with_the_dense_pass() {
    assert_eq!(<framed::Framed as RigidTree<2, 2>>::JOINTS.len(), 2);
    let sys = framed::Framed {
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
    agrees_with_dense::<_, 2, 24>(&sys);
    agrees_with_dense::<_, 2, 24>(&sys.validated().unwrap());
}
