//! Inverse dynamics of a rigid tree by the recursive Newton–Euler algorithm (Featherstone, *Rigid
//! Body Dynamics Algorithms*, 2008, §5.3, Table 5.1):
//!
//! ```text
//! root → leaf:  v_b = X_b v_p + S_b q̇_b,   a_b = X_b a_p + S_b q̈_b + v_b × S_b q̇_b,
//!               f_b = I_b a_b + v_b ×* I_b v_b,
//! leaf → root:  τ_b = S_bᵀ f_b,   f_p += X_bᵀ f_b,
//! ```
//!
//! with a₀ = (0; −g) for the uniform field: τ = M q̈ + b − 𝓕_g, the generalized forces the joints
//! must add to the field's for the bodies to move with q̈.

use super::kinematics::{
    force_to_parent, ground_acceleration, motion_to_child, velocity, JointState,
};
use super::spatial::{Force, Motion};
use super::{free, joint_at, Joint, JointKind, RigidConstants, RUNTIME};
use crate::geometry::Scalar;
use nalgebra::SVector;

/// The recursive Newton–Euler algorithm's working memory for `B` bodies, swept body by body:
/// [`forward`](Self::forward) root to leaf, [`backward`](Self::backward) leaf to root.
/// [`inverse_dynamics`] runs the sweeps as loops; `#[mechanism]` writes one call per body with a
/// constant index, so that each call is compiled for its own joint.
///
/// As in [`Articulated`](super::Articulated), a body's slot is empty until its forward step fills
/// it (nothing is zeroed first), and a step called out of sweep order panics.
pub struct NewtonEuler<S, const B: usize> {
    body: [Option<Moved<S>>; B],
}

/// A body after the forward sweep: its joint, v_b, a_b and the force f_b (which the backward
/// sweep adds its children's to).
#[derive(Clone, Copy)]
struct Moved<S> {
    state: JointState<S>,
    velocity: Motion<S>,
    acceleration: Motion<S>,
    force: Force<S>,
}

impl<S: Scalar, const B: usize> Default for NewtonEuler<S, B> {
    fn default() -> Self {
        Self::new()
    }
}

#[cold]
#[inline(never)]
fn out_of_order(sweep: &str) -> ! {
    panic!("Newton–Euler sweeps called out of order: {sweep}")
}

impl<S: Scalar, const B: usize> NewtonEuler<S, B> {
    /// Empty working memory.
    #[inline(always)]
    pub fn new() -> Self {
        NewtonEuler { body: [None; B] }
    }

    /// Body `b`, root to leaf: its velocity, acceleration and the force its motion takes,
    /// f_b = I_b a_b + v_b ×* I_b v_b.
    #[inline(always)]
    pub fn forward<const CODE: u16, const N: usize>(
        &mut self,
        joints: &[Joint; B],
        k: &RigidConstants<B>,
        (q, v, qdd): (&[S; N], &[S; N], &[S; N]),
        b: usize,
    ) {
        let (joint, kb) = (&joint_at::<CODE, B>(joints, b), &k.bodies[b]);
        let state = JointState::of(joint, q);
        let parent = match joint.parent {
            Some(p) => match &self.body[p] {
                Some(m) => Some((m.velocity, m.acceleration)),
                None => out_of_order("a child before its parent"),
            },
            None => None,
        };
        let (vb, c) = velocity(joint, kb, state, parent.as_ref().map(|m| &m.0), v);
        let above = match parent {
            Some((_, a)) => a,
            None => ground_acceleration(k),
        };
        let mut ab = motion_to_child(joint, kb, state, &above) + c;
        add_along_joint(joint, state, &mut ab, qdd);
        let inertia = &kb.inertia;
        self.body[b] = Some(Moved {
            state,
            velocity: vb,
            acceleration: ab,
            force: inertia.apply(&ab) + vb.cross_force(&inertia.apply(&vb)),
        });
    }

    /// Body `b`, leaf to root: τ_b = S_bᵀ f_b, and f_b passed to its parent.
    #[inline(always)]
    pub fn backward<const CODE: u16, const N: usize>(
        &mut self,
        joints: &[Joint; B],
        k: &RigidConstants<B>,
        tau: &mut [S; N],
        b: usize,
    ) {
        let joint = &joint_at::<CODE, B>(joints, b);
        let Some(moved) = self.body[b] else {
            out_of_order("a body backward before forward")
        };
        project(joint, moved.state, &moved.force, tau);
        if let Some(p) = joint.parent {
            let pushed = force_to_parent(joint, &k.bodies[b], moved.state, &moved.force);
            match &mut self.body[p] {
                Some(parent) => parent.force = parent.force + pushed,
                None => out_of_order("a parent before its child"),
            }
        }
    }
}

/// τ = M q̈ + b − 𝓕_g at (q, q̇, q̈): what the joints must supply beyond the uniform field, by
/// the two sweeps as loops.
pub fn inverse_dynamics<S: Scalar, const N: usize, const B: usize>(
    joints: &[Joint; B],
    k: &RigidConstants<B>,
    q: &[S; N],
    v: &[S; N],
    qdd: &[S; N],
) -> [S; N] {
    let mut ws = NewtonEuler::<S, B>::new();
    for b in 0..B {
        ws.forward::<RUNTIME, N>(joints, k, (q, v, qdd), b);
    }
    let mut tau = [S::zero(); N];
    for b in (0..B).rev() {
        ws.backward::<RUNTIME, N>(joints, k, &mut tau, b);
    }
    tau
}

/// b and 𝓕_g at (q, q̇) in one sweep: the inertial terms b = RNEA(q, q̇, 0) without the field and
/// the field's generalized forces 𝓕_g = −RNEA(q, 0, 0) — two chains of accelerations and forces
/// over the same joints and velocities.
pub fn bias_and_gravity<S: Scalar, const N: usize, const B: usize>(
    joints: &[Joint; B],
    k: &RigidConstants<B>,
    q: &[S; N],
    v: &[S; N],
) -> (SVector<S, N>, SVector<S, N>) {
    let mut state = [JointState::Welded; B];
    let mut vel = [Motion::zero(); B];
    let (mut acc, mut fall) = ([Motion::zero(); B], [Motion::zero(); B]);
    let (mut force, mut weight) = ([Force::zero(); B], [Force::zero(); B]);
    for b in 0..B {
        let (joint, kb) = (&joints[b], &k.bodies[b]);
        state[b] = JointState::of(joint, q);
        let parent = joint.parent.map(|p| &vel[p]);
        let (vb, c) = velocity(joint, kb, state[b], parent, v);
        let (above, falling) = match joint.parent {
            Some(p) => (acc[p], fall[p]),
            None => (Motion::zero(), ground_acceleration(k)),
        };
        let ab = motion_to_child(joint, kb, state[b], &above) + c;
        let gb = motion_to_child(joint, kb, state[b], &falling);
        let inertia = &kb.inertia;
        force[b] = inertia.apply(&ab) + vb.cross_force(&inertia.apply(&vb));
        weight[b] = inertia.apply(&gb);
        (vel[b], acc[b], fall[b]) = (vb, ab, gb);
    }
    let (mut bias, mut gravity) = ([S::zero(); N], [S::zero(); N]);
    for b in (0..B).rev() {
        let (joint, kb) = (&joints[b], &k.bodies[b]);
        project(joint, state[b], &force[b], &mut bias);
        project(joint, state[b], &weight[b].scale(-S::one()), &mut gravity);
        if let Some(p) = joint.parent {
            force[p] = force[p] + force_to_parent(joint, kb, state[b], &force[b]);
            weight[p] = weight[p] + force_to_parent(joint, kb, state[b], &weight[b]);
        }
    }
    (SVector::from(bias), SVector::from(gravity))
}

/// a += S q̈ for the joint's accelerations in `qdd`.
#[inline(always)]
fn add_along_joint<S: Scalar, const N: usize>(
    joint: &Joint,
    state: JointState<S>,
    a: &mut Motion<S>,
    qdd: &[S; N],
) {
    match (joint.kind, state) {
        (JointKind::Revolute(axis), _) => a.angular[axis.indices().0] += qdd[joint.coordinate],
        (JointKind::Prismatic(axis), _) => a.linear[axis.indices().0] += qdd[joint.coordinate],
        (JointKind::Free(..) | JointKind::Ball(..), JointState::Free(o)) => {
            *a = *a + free::motion_of(o, free::rates(qdd, joint))
        }
        _ => {}
    }
}

/// Sᵀ f: the force's component along a one-coordinate joint (`None` for a fixed joint and for a
/// free or a ball one, whose six or three [`project`] writes).
#[inline(always)]
pub(crate) fn along_joint<S: Scalar>(joint: &Joint, f: &Force<S>) -> Option<S> {
    match joint.kind {
        JointKind::Revolute(axis) => Some(f.moment[axis.indices().0]),
        JointKind::Prismatic(axis) => Some(f.force[axis.indices().0]),
        JointKind::Fixed | JointKind::Free(..) | JointKind::Ball(..) => None,
    }
}

/// Sᵀ f written to the joint's coordinates of `out` (nothing for a fixed joint).
#[inline(always)]
pub(crate) fn project<S: Scalar, const N: usize>(
    joint: &Joint,
    state: JointState<S>,
    f: &Force<S>,
    out: &mut [S; N],
) {
    match along_joint(joint, f) {
        Some(x) => out[joint.coordinate] = x,
        None => {
            if let JointState::Free(o) = state {
                free::store(out, joint, free::forces_of(o, f));
            }
        }
    }
}
