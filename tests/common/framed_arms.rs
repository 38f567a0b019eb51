//! A three-link spatial arm declared twice: by its joint frames with each link's centre of mass
//! and full inertia tensor in its frame (`framed_arm`), and by centres of mass and principal axes
//! written out (`principal_arm`, today's form). The same physics; `tests/body_frames.rs` checks
//! that, and `scripts/callgrind` counts what declaring by frames costs.

use lagrange::prelude::*;
use nalgebra::Matrix3;

/// A three-link spatial arm placed link by link from joint frames, as a robot file reads: a base
/// joint about z, a joint about y behind a fixed roll-pitch-yaw turn, a joint about the diagonal
/// (1, 1, 0); each link's centre of mass offset in its frame and its full inertia tensor there.
/// A spring pulls the second joint towards a fixed point, a constant force pushes the last link,
/// a constant torque twists the second.
#[mechanism]
pub mod framed_arm {
    pub struct Coords {
        pub q1: f64,
        pub q2: f64,
        pub q3: f64,
    }

    pub struct FramedArm {
        pub m1: f64,
        pub m2: f64,
        pub m3: f64,
        pub l1: f64,
        pub l2: f64,
        pub c1x: f64,
        pub c1y: f64,
        pub c1z: f64,
        pub c2x: f64,
        pub c2y: f64,
        pub c2z: f64,
        pub c3x: f64,
        pub c3y: f64,
        pub c3z: f64,
        pub t1xx: f64,
        pub t1xy: f64,
        pub t1xz: f64,
        pub t1yy: f64,
        pub t1yz: f64,
        pub t1zz: f64,
        pub t2xx: f64,
        pub t2xy: f64,
        pub t2xz: f64,
        pub t2yy: f64,
        pub t2yz: f64,
        pub t2zz: f64,
        pub t3xx: f64,
        pub t3xy: f64,
        pub t3xz: f64,
        pub t3yy: f64,
        pub t3yz: f64,
        pub t3zz: f64,
        pub k: f64,
        pub f: f64,
        pub tau: f64,
        pub g: f64,
    }

    #[rigid_body(mass = m1, com = vec3(c1x, c1y, c1z), inertia = [[t1xx, t1xy, t1xz], [t1xy, t1yy, t1yz], [t1xz, t1yz, t1zz]])]
    fn link1() -> Spatial {
        spatial(vec3(0.0, 0.0, 0.0), rot_z(q1))
    }

    #[rigid_body(mass = m2, com = vec3(c2x, c2y, c2z), inertia = [[t2xx, t2xy, t2xz], [t2xy, t2yy, t2yz], [t2xz, t2yz, t2zz]])]
    fn link2() -> Spatial {
        link1.joint(vec3(0.0, 0.1, l1), rpy(0.3, -0.2, 0.1) * rot_y(q2))
    }

    #[rigid_body(mass = m3, com = vec3(c3x, c3y, c3z), inertia = [[t3xx, t3xy, t3xz], [t3xy, t3yy, t3yz], [t3xz, t3yz, t3zz]])]
    fn link3() -> Spatial {
        link2.joint(vec3(0.05, 0.0, l2), rot_axis(vec3(1.0, 1.0, 0.0), q3))
    }

    /// Pulls the second joint (the origin of `link2`'s frame) towards (0.3, 0, 0).
    #[potential]
    fn spring() -> f64 {
        let d = link2.position - vec3(0.3, 0.0, 0.0);
        0.5 * k * d.norm_squared()
    }

    #[force(on = link3)]
    fn push() -> Vec3 {
        vec3(f, 0.0, 0.5 * f)
    }

    #[torque(on = link2)]
    fn twist() -> Vec3 {
        vec3(0.0, tau, 0.0)
    }

    #[gravity]
    fn down() -> Vec3 {
        vec3(0.0, 0.0, -g)
    }
}

/// The same arm declared by centres of mass and principal axes, with the rotations of today's
/// constructors only: link k's principal axes are the columns of R_k V_k, V_k = Rz(γ)·Ry(β)·Rx(α),
/// its centre of mass at o_k + R_k c_k, its frame (o_k, R_k) recomputed from the coordinates.
#[mechanism]
pub mod principal_arm {
    use lagrange::prelude::*;
    use lagrange::Scalar;

    pub struct Coords {
        pub q1: f64,
        pub q2: f64,
        pub q3: f64,
    }

    pub struct PrincipalArm {
        pub m1: f64,
        pub m2: f64,
        pub m3: f64,
        pub l1: f64,
        pub l2: f64,
        pub c1x: f64,
        pub c1y: f64,
        pub c1z: f64,
        pub c2x: f64,
        pub c2y: f64,
        pub c2z: f64,
        pub c3x: f64,
        pub c3y: f64,
        pub c3z: f64,
        pub i11: f64,
        pub i12: f64,
        pub i13: f64,
        pub i21: f64,
        pub i22: f64,
        pub i23: f64,
        pub i31: f64,
        pub i32: f64,
        pub i33: f64,
        pub a1: f64,
        pub b1: f64,
        pub g1: f64,
        pub a2: f64,
        pub b2: f64,
        pub g2: f64,
        pub a3: f64,
        pub b3: f64,
        pub g3: f64,
        pub k: f64,
        pub f: f64,
        pub tau: f64,
        pub g: f64,
    }

    /// Rz(γ)·Ry(β)·Rx(α).
    pub fn axes<D: Scalar>(alpha: D, beta: D, gamma: D) -> Rot3<D> {
        rot_z(gamma) * rot_y(beta) * rot_x(alpha)
    }

    /// The frame of link 2: origin and rotation.
    pub fn frame2<D: Scalar>(q1: D, q2: D, l1: D) -> (Vec3<D>, Rot3<D>) {
        let r1 = rot_z(q1);
        let o2 = r1 * vec3(D::zero(), D::from(0.1), l1);
        let turn = rot_z(D::from(0.1)) * rot_y(D::from(-0.2)) * rot_x(D::from(0.3));
        (o2, r1 * turn * rot_y(q2))
    }

    /// The frame of link 3: a turn about (1, 1, 0)/√2 is Rz(π/4)·Rx(q)·Rz(−π/4).
    pub fn frame3<D: Scalar>(q1: D, q2: D, q3: D, l1: D, l2: D) -> (Vec3<D>, Rot3<D>) {
        let (o2, r2) = frame2(q1, q2, l1);
        let quarter = D::from(std::f64::consts::FRAC_PI_4);
        let o3 = o2 + r2 * vec3(D::from(0.05), D::zero(), l2);
        (o3, r2 * rot_z(quarter) * rot_x(q3) * rot_z(-quarter))
    }

    #[rigid_body(mass = m1, inertia = [i11, i12, i13])]
    fn link1() -> Spatial {
        let r1 = rot_z(q1);
        spatial(r1 * vec3(c1x, c1y, c1z), r1 * axes(a1, b1, g1))
    }

    #[rigid_body(mass = m2, inertia = [i21, i22, i23])]
    fn link2() -> Spatial {
        let (o2, r2) = frame2(q1, q2, l1);
        spatial(o2 + r2 * vec3(c2x, c2y, c2z), r2 * axes(a2, b2, g2))
    }

    #[rigid_body(mass = m3, inertia = [i31, i32, i33])]
    fn link3() -> Spatial {
        let (o3, r3) = frame3(q1, q2, q3, l1, l2);
        spatial(o3 + r3 * vec3(c3x, c3y, c3z), r3 * axes(a3, b3, g3))
    }

    #[potential]
    fn spring() -> f64 {
        let (o2, _) = frame2(q1, q2, l1);
        let d = o2 - vec3(0.3, 0.0, 0.0);
        0.5 * k * d.norm_squared()
    }

    #[force(on = link3)]
    fn push() -> Vec3 {
        vec3(f, 0.0, 0.5 * f)
    }

    #[torque(on = link2)]
    fn twist() -> Vec3 {
        vec3(0.0, tau, 0.0)
    }

    #[gravity]
    fn down() -> Vec3 {
        vec3(0.0, 0.0, -g)
    }
}

/// Principal moments and the angles (α, β, γ) of the principal axes, link by link: distinct
/// moments (gaps ≥ 10% of the largest), so the eigenvectors are well conditioned.
const MOMENTS: [[f64; 3]; 3] = [
    [0.02, 0.035, 0.045],
    [0.011, 0.016, 0.019],
    [0.004, 0.0065, 0.008],
];
const ANGLES: [[f64; 3]; 3] = [[0.4, -0.7, 1.1], [-1.3, 0.2, 0.5], [0.9, 0.35, -2.0]];
const COMS: [[f64; 3]; 3] = [[0.01, -0.02, 0.15], [0.03, 0.01, 0.2], [-0.02, 0.04, 0.1]];

/// I = V diag(I₁, I₂, I₃) Vᵀ with V = Rz(γ)·Ry(β)·Rx(α): the tensor in the frame's axes.
fn tensor(link: usize) -> [[f64; 3]; 3] {
    let [a, b, c] = ANGLES[link];
    let v = Matrix3::from(rot_z(c) * rot_y(b) * rot_x(a));
    let i = v * Matrix3::from_diagonal(&MOMENTS[link].into()) * v.transpose();
    std::array::from_fn(|r| std::array::from_fn(|s| i[(r, s)]))
}

/// The arm by its frames, its tensors from [`MOMENTS`] and [`ANGLES`].
pub fn framed() -> framed_arm::FramedArm {
    let [t1, t2, t3] = [tensor(0), tensor(1), tensor(2)];
    let [c1, c2, c3] = COMS;
    framed_arm::FramedArm {
        m1: 1.2,
        m2: 0.8,
        m3: 0.5,
        l1: 0.4,
        l2: 0.35,
        c1x: c1[0],
        c1y: c1[1],
        c1z: c1[2],
        c2x: c2[0],
        c2y: c2[1],
        c2z: c2[2],
        c3x: c3[0],
        c3y: c3[1],
        c3z: c3[2],
        t1xx: t1[0][0],
        t1xy: t1[0][1],
        t1xz: t1[0][2],
        t1yy: t1[1][1],
        t1yz: t1[1][2],
        t1zz: t1[2][2],
        t2xx: t2[0][0],
        t2xy: t2[0][1],
        t2xz: t2[0][2],
        t2yy: t2[1][1],
        t2yz: t2[1][2],
        t2zz: t2[2][2],
        t3xx: t3[0][0],
        t3xy: t3[0][1],
        t3xz: t3[0][2],
        t3yy: t3[1][1],
        t3yz: t3[1][2],
        t3zz: t3[2][2],
        k: 3.0,
        f: 0.7,
        tau: -0.4,
        g: 9.81,
    }
}

/// The same arm by its principal axes.
pub fn principal() -> principal_arm::PrincipalArm {
    let a = framed();
    let [[i11, i12, i13], [i21, i22, i23], [i31, i32, i33]] = MOMENTS;
    let [[a1, b1, g1], [a2, b2, g2], [a3, b3, g3]] = ANGLES;
    principal_arm::PrincipalArm {
        m1: a.m1,
        m2: a.m2,
        m3: a.m3,
        l1: a.l1,
        l2: a.l2,
        c1x: a.c1x,
        c1y: a.c1y,
        c1z: a.c1z,
        c2x: a.c2x,
        c2y: a.c2y,
        c2z: a.c2z,
        c3x: a.c3x,
        c3y: a.c3y,
        c3z: a.c3z,
        i11,
        i12,
        i13,
        i21,
        i22,
        i23,
        i31,
        i32,
        i33,
        a1,
        b1,
        g1,
        a2,
        b2,
        g2,
        a3,
        b3,
        g3,
        k: a.k,
        f: a.f,
        tau: a.tau,
        g: a.g,
    }
}
