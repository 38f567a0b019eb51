//! M of a rigid tree by the composite-rigid-body algorithm (Featherstone, *Rigid Body Dynamics
//! Algorithms*, 2008, §6.2, Table 6.2), and the momenta p = M q̇ from the composite momenta.
//!
//! ```text
//! leaf → root:  I^C_b = I_b + Σ_children X_cᵀ I^C_c X_c,
//!               F = I^C_b S_b,   M_bb = S_bᵀ F,
//!               up the ancestors j of b:  F ← X_jᵀ F,   M_jb = M_bj = S_jᵀ F.
//! ```
//!
//! The momenta p_j = S_jᵀ h^C_j with h^C_b = I_b v_b + Σ_children X_cᵀ h^C_c, the composite
//! spatial momentum of b's subtree: p = ∂T/∂q̇ for T = ½ Σ v_bᵀ I_b v_b.

use super::inertia::Inertia;
use super::kinematics::{force_to_parent, inertia_to_parent, velocity, JointState};
use super::newton_euler::{along_joint, project};
use super::spatial::{Force, Motion};
use super::{free, Joint, JointKind, RigidConstants};
use crate::geometry::Scalar;
use nalgebra::SMatrix;

/// M(q) by the composite-rigid-body algorithm (Featherstone §6.2, Table 6.2).
pub fn mass_matrix<S: Scalar, const N: usize, const B: usize>(
    joints: &[Joint; B],
    k: &RigidConstants<B>,
    q: &[S; N],
) -> SMatrix<S, N, N> {
    let state: [JointState<S>; B] = std::array::from_fn(|b| JointState::of(&joints[b], q));
    let mut composite: [Inertia<S>; B] = std::array::from_fn(|b| k.bodies[b].inertia.as_inertia());
    let mut m = SMatrix::<S, N, N>::zeros();
    for b in (0..B).rev() {
        let joint = &joints[b];
        let column = match joint.kind {
            JointKind::Revolute(axis) => Some(composite[b].angular_column(axis)),
            JointKind::Prismatic(axis) => Some(composite[b].linear_column(axis)),
            JointKind::Fixed => None,
            JointKind::Free(..) | JointKind::Ball(..) => {
                free_block(joint, state[b], &composite[b], &mut m);
                None
            }
        };
        if let Some(mut f) = column {
            let i = joint.coordinate;
            m[(i, i)] = along_joint(joint, &f).expect("a moving joint has an axis");
            let mut j = b;
            while let Some(p) = joints[j].parent {
                f = force_to_parent(&joints[j], &k.bodies[j], state[j], &f);
                j = p;
                if let Some(entry) = along_joint(&joints[j], &f) {
                    let c = joints[j].coordinate;
                    m[(i, c)] = entry;
                    m[(c, i)] = entry;
                } else if let JointState::Free(o) = state[j] {
                    // A free or ball root: M_jb = S_jᵀ F, six or three entries.
                    for (l, entry) in free::forces_of(o, &f).into_iter().enumerate() {
                        if let Some(c) = free::index(&joints[j], l) {
                            m[(i, c)] = entry;
                            m[(c, i)] = entry;
                        }
                    }
                }
            }
        }
        if let Some(p) = joint.parent {
            let mut passed = composite[b];
            inertia_to_parent(joint, &k.bodies[b], state[b], &mut passed);
            composite[p].add(&passed);
        }
    }
    m
}

/// A free root's 6 × 6 block Sᵀ I^C S (a ball root's 3 × 3, its rows and columns of c): column k
/// is Sᵀ (I^C S e_k).
fn free_block<S: Scalar, const N: usize>(
    joint: &Joint,
    state: JointState<S>,
    composite: &Inertia<S>,
    m: &mut SMatrix<S, N, N>,
) {
    let JointState::Free(o) = state else {
        return;
    };
    for k in 0..6 {
        let Some(ck) = free::index(joint, k) else {
            continue;
        };
        let unit = std::array::from_fn(|l| if l == k { S::one() } else { S::zero() });
        let column = composite.apply(&free::motion_of(o, unit));
        // The upper triangle, mirrored: M symmetric to the last bit.
        for (l, entry) in free::forces_of(o, &column)
            .into_iter()
            .enumerate()
            .take(k + 1)
        {
            if let Some(cl) = free::index(joint, l) {
                m[(cl, ck)] = entry;
                m[(ck, cl)] = entry;
            }
        }
    }
}

/// p = M q̇ at (q, q̇) from the composite momenta: p_j = S_jᵀ h^C_j, h^C_b the spatial momentum
/// of b's subtree.
pub fn momenta<S: Scalar, const N: usize, const B: usize>(
    joints: &[Joint; B],
    k: &RigidConstants<B>,
    q: &[S; N],
    v: &[S; N],
) -> [S; N] {
    let mut state = [JointState::Welded; B];
    let mut vel = [Motion::zero(); B];
    let mut momentum = [Force::zero(); B];
    for b in 0..B {
        let (joint, kb) = (&joints[b], &k.bodies[b]);
        state[b] = JointState::of(joint, q);
        let parent = joint.parent.map(|p| &vel[p]);
        vel[b] = velocity(joint, kb, state[b], parent, v).0;
        momentum[b] = kb.inertia.apply(&vel[b]);
    }
    let mut p = [S::zero(); N];
    for b in (0..B).rev() {
        let joint = &joints[b];
        project(joint, state[b], &momentum[b], &mut p);
        if let Some(parent) = joint.parent {
            let pushed = force_to_parent(joint, &k.bodies[b], state[b], &momentum[b]);
            momentum[parent] = momentum[parent] + pushed;
        }
    }
    p
}
