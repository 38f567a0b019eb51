//! A body's frame change from its parent (the constant part E, r and the joint's own part), applied
//! to motion vectors, forces and inertias; the bodies' velocities and world frames; the kinetic
//! energy.

use super::inertia::Inertia;
use super::spatial::{
    add3, cross_axis, cross_const, mul3, mul3_transpose, scale3, turn, turn_back, Force, Motion,
    M3, V3,
};
use super::{free, BodyConstants, Joint, JointKind, RigidConstants};
use crate::geometry::Scalar;

/// The joint's own part of a body's frame change at the body's coordinate: the rotation's
/// (cos θ, sin θ), a slide's displacement, or nothing.
#[derive(Clone, Copy, Debug)]
pub enum JointState<S> {
    Turned(S, S),
    Slid(S),
    Welded,
    /// A free joint's orientation (its origin p enters no frame change the recursions make).
    Free(free::Orientation<S>),
}

impl<S: Scalar> JointState<S> {
    /// At the coordinates `q`.
    #[inline(always)]
    pub fn of<const N: usize>(joint: &Joint, q: &[S; N]) -> Self {
        match joint.kind {
            JointKind::Revolute(_) => {
                let (s, c) = q[joint.coordinate].sin_cos();
                JointState::Turned(c, s)
            }
            JointKind::Prismatic(_) => JointState::Slid(q[joint.coordinate]),
            JointKind::Fixed => JointState::Welded,
            JointKind::Free(chart, velocities) | JointKind::Ball(chart, velocities) => {
                // The recursions take these joints as a root's, with E the identity (and a free
                // joint's r zero).
                debug_assert!(joint.parent.is_none() && !joint.rotated);
                debug_assert!(joint.offset == [false; 3] || !free::translates(joint));
                JointState::Free(free::orientation(
                    (chart, velocities),
                    q,
                    free::orientation_at(joint),
                ))
            }
        }
    }
}

/// X m: a motion vector of the parent's frame in the body's (see [`super::spatial`]): first the
/// constant part, ω' = Eᵀ ω, v' = Eᵀ (v + ω × r), then the joint's.
#[inline(always)]
pub(crate) fn motion_to_child<S: Scalar>(
    joint: &Joint,
    k: &BodyConstants,
    state: JointState<S>,
    m: &Motion<S>,
) -> Motion<S> {
    if let JointState::Free(o) = state {
        return free::from_ground(o, m);
    }
    // ω × r = −(r × ω).
    let r_cross_w = cross_const(&k.offset, joint.offset, m.angular);
    let v_at = [
        m.linear[0] - r_cross_w[0],
        m.linear[1] - r_cross_w[1],
        m.linear[2] - r_cross_w[2],
    ];
    let (w, v) = match joint.rotated {
        true => (
            mul3_transpose(&k.rotation, m.angular),
            mul3_transpose(&k.rotation, v_at),
        ),
        false => (m.angular, v_at),
    };
    match (joint.kind, state) {
        (JointKind::Revolute(axis), JointState::Turned(c, s)) => Motion {
            angular: turn_back(axis, (c, s), w),
            linear: turn_back(axis, (c, s), v),
        },
        // v + ω × (e_a d).
        (JointKind::Prismatic(axis), JointState::Slid(d)) => Motion {
            angular: w,
            linear: add3(v, cross_axis(w, axis, d)),
        },
        _ => Motion {
            angular: w,
            linear: v,
        },
    }
}

/// Xᵀ f: a force of the body's frame in its parent's: first the joint's part, then the constant
/// one, f_P = E f', n_P = E n' + r × f_P.
#[inline(always)]
pub(crate) fn force_to_parent<S: Scalar>(
    joint: &Joint,
    k: &BodyConstants,
    state: JointState<S>,
    f: &Force<S>,
) -> Force<S> {
    let (n, force) = match (joint.kind, state) {
        (JointKind::Revolute(axis), JointState::Turned(c, s)) => {
            (turn(axis, (c, s), f.moment), turn(axis, (c, s), f.force))
        }
        // n + (e_a d) × f = n − f × (e_a d).
        (JointKind::Prismatic(axis), JointState::Slid(d)) => {
            let x = cross_axis(f.force, axis, d);
            (
                [f.moment[0] - x[0], f.moment[1] - x[1], f.moment[2] - x[2]],
                f.force,
            )
        }
        _ => (f.moment, f.force),
    };
    let (n, force) = match joint.rotated {
        true => (mul3(&k.rotation, n), mul3(&k.rotation, force)),
        false => (n, force),
    };
    Force {
        moment: add3(n, cross_const(&k.offset, joint.offset, force)),
        force,
    }
}

/// Xᵀ I X: an inertia of the body's frame in its parent's.
#[inline(always)]
pub(crate) fn inertia_to_parent<S: Scalar>(
    joint: &Joint,
    k: &BodyConstants,
    state: JointState<S>,
    inertia: &mut Inertia<S>,
) {
    match (joint.kind, state) {
        (JointKind::Revolute(axis), JointState::Turned(c, s)) => inertia.turn(axis, (c, s)),
        (JointKind::Prismatic(axis), JointState::Slid(d)) => {
            let (a, _, _) = axis.indices();
            let mut r = [S::zero(); 3];
            let mut mask = [false; 3];
            r[a] = d;
            mask[a] = true;
            inertia.shift(r, mask);
        }
        _ => {}
    }
    if joint.rotated {
        inertia.rotate(&k.rotation);
    }
    inertia.shift(k.offset, joint.offset);
}

/// The body's velocity from its parent's (`None` for the ground, at rest) and its joint's rates
/// in `q_dot`, v_b = X v_p + S q̇, and the velocity-product acceleration c = v_b × S q̇
/// (Featherstone eq. 7.31, S constant in the body's frame; a free root's c = Ṡ q̇, see [`free`]).
#[inline(always)]
pub(crate) fn velocity<S: Scalar, const N: usize>(
    joint: &Joint,
    k: &BodyConstants,
    state: JointState<S>,
    parent: Option<&Motion<S>>,
    q_dot: &[S; N],
) -> (Motion<S>, Motion<S>) {
    if let JointState::Free(o) = state {
        return free::velocity(o, free::rates(q_dot, joint));
    }
    let rate = rate_of(joint, q_dot);
    let mut v = match parent {
        Some(m) => motion_to_child(joint, k, state, m),
        None => Motion::zero(),
    };
    let c = match joint.kind {
        JointKind::Revolute(axis) => {
            let c = v.cross_angular_axis(axis, rate);
            v.angular[axis.indices().0] += rate;
            c
        }
        JointKind::Prismatic(axis) => {
            let c = v.cross_linear_axis(axis, rate);
            v.linear[axis.indices().0] += rate;
            c
        }
        JointKind::Fixed | JointKind::Free(..) | JointKind::Ball(..) => Motion::zero(),
    };
    (v, c)
}

/// The ground's acceleration that stands for the uniform field: a₀ = (0; −g).
#[inline(always)]
pub(crate) fn ground_acceleration<S: Scalar, const B: usize>(k: &RigidConstants<B>) -> Motion<S> {
    Motion {
        angular: [S::zero(); 3],
        linear: k.gravity.map(|g| S::from(-g)),
    }
}

/// T = ½ Σ_b v_bᵀ I_b v_b at (q, q̇).
pub fn kinetic_energy<S: Scalar, const N: usize, const B: usize>(
    joints: &[Joint; B],
    k: &RigidConstants<B>,
    q: &[S; N],
    v: &[S; N],
) -> S {
    let mut velocities = [Motion::zero(); B];
    let mut energy = S::zero();
    for b in 0..B {
        let joint = &joints[b];
        let state = JointState::of(joint, q);
        let parent = joint.parent.map(|p| &velocities[p]);
        let (vb, _) = velocity(joint, &k.bodies[b], state, parent, v);
        velocities[b] = vb;
        energy += vb.dot(&k.bodies[b].inertia.apply(&vb));
    }
    energy * 0.5
}

/// A one-coordinate joint's rate q̇ (zero for a fixed joint and, as they have six or three, a free
/// or a ball joint).
#[inline(always)]
pub(crate) fn rate_of<S: Scalar, const N: usize>(joint: &Joint, v: &[S; N]) -> S {
    match joint.kind {
        JointKind::Fixed | JointKind::Free(..) | JointKind::Ball(..) => S::zero(),
        _ => v[joint.coordinate],
    }
}

/// A body's frame in the world: its orientation (the body's axes in world coordinates, by
/// columns) and its origin.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frame<S> {
    /// The body's axes in world coordinates, by columns (rows stored).
    pub rotation: M3<S>,
    /// The frame's origin in the world.
    pub origin: V3<S>,
}

/// Every body's frame in the world at q: R_b = R_p E R_a(q), o_b = o_p + R_p (r + slide); a
/// free root's R(c) and p, a ball root's R(c) and r.
pub fn world_frames<S: Scalar, const N: usize, const B: usize>(
    joints: &[Joint; B],
    k: &RigidConstants<B>,
    q: &[S; N],
) -> [Frame<S>; B] {
    let identity = {
        let (o, z) = (S::one(), S::zero());
        [[o, z, z], [z, o, z], [z, z, o]]
    };
    let mut frames = [Frame {
        rotation: identity,
        origin: [S::zero(); 3],
    }; B];
    for b in 0..B {
        let (joint, kb) = (&joints[b], &k.bodies[b]);
        if let JointState::Free(o) = JointState::of(joint, q) {
            let c = joint.coordinate;
            frames[b] = Frame {
                rotation: o.rotation(),
                origin: match free::translates(joint) {
                    true => [q[c], q[c + 1], q[c + 2]],
                    false => kb.offset.map(S::from),
                },
            };
            continue;
        }
        let parent = match joint.parent {
            Some(p) => frames[p],
            None => Frame {
                rotation: identity,
                origin: [S::zero(); 3],
            },
        };
        let mut offset = kb.offset.map(S::from);
        let mut rotation = times_constant(&parent.rotation, &kb.rotation);
        match (joint.kind, JointState::of(joint, q)) {
            (JointKind::Revolute(axis), JointState::Turned(c, s)) => {
                // R E R_a: columns u, v of R E turned.
                let (_, u, v) = axis.indices();
                for row in rotation.iter_mut() {
                    let (ru, rv) = (row[u], row[v]);
                    row[u] = c * ru + s * rv;
                    row[v] = c * rv - s * ru;
                }
            }
            (JointKind::Prismatic(axis), JointState::Slid(d)) => {
                let e = column(&kb.rotation, axis.indices().0);
                offset = add3(offset, scale3(e.map(S::from), d));
            }
            _ => {}
        }
        let origin = add3(parent.origin, rotate(&parent.rotation, offset));
        frames[b] = Frame { rotation, origin };
    }
    frames
}

/// R E for a rotation R of any scalar and a constant E.
#[inline(always)]
fn times_constant<S: Scalar>(r: &M3<S>, e: &M3<f64>) -> M3<S> {
    let mut out = [[S::zero(); 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            out[i][j] = r[i][0] * e[0][j] + r[i][1] * e[1][j] + r[i][2] * e[2][j];
        }
    }
    out
}

/// R x.
#[inline(always)]
pub(crate) fn rotate<S: Scalar>(r: &M3<S>, x: V3<S>) -> V3<S> {
    [
        r[0][0] * x[0] + r[0][1] * x[1] + r[0][2] * x[2],
        r[1][0] * x[0] + r[1][1] * x[1] + r[1][2] * x[2],
        r[2][0] * x[0] + r[2][1] * x[1] + r[2][2] * x[2],
    ]
}

fn column(m: &M3<f64>, k: usize) -> V3<f64> {
    [m[0][k], m[1][k], m[2][k]]
}
