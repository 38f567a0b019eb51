//! q̈ of a rigid tree by the articulated-body algorithm (Featherstone, *Rigid Body Dynamics
//! Algorithms*, 2008, §7.3, Table 7.1), in three sweeps over the bodies:
//!
//! ```text
//! root → leaf:  v_b = X_b v_p + S_b q̇_b,   c_b = v_b × S_b q̇_b,
//!               I^A_b = I_b,               p^A_b = v_b ×* I_b v_b,
//! leaf → root:  U_b = I^A_b S_b,  D_b = S_bᵀ U_b,  u_b = τ_b − S_bᵀ p^A_b,
//!               I^A_p += X_bᵀ (I^A_b − U_b U_bᵀ / D_b) X_b,
//!               p^A_p += X_bᵀ (p^A_b + I^a_b c_b + U_b u_b / D_b),
//! root → leaf:  a' = X_b a_p + c_b,   q̈_b = (u_b − U_bᵀ a') / D_b,   a_b = a' + S_b q̈_b,
//! ```
//!
//! with the ground's acceleration a₀ = (0; −g) standing for the uniform field. S_b has one
//! non-zero entry (the joint's axis), so U_b is a column of I^A_b and D_b one of its diagonal
//! entries. A fixed joint passes its inertia and bias force to its parent unchanged.
//!
//! The D_b are the pivots of a factorisation of M taken leaves first: M is singular exactly where
//! one of them vanishes. Each is tested against the largest diagonal entry of its own block of I^A_b
//! (rotational for a revolute joint, translational for a slide): the same units, so the test does
//! not depend on the units a mechanism is written in.

use super::inertia::Inertia;
use super::kinematics::{
    force_to_parent, ground_acceleration, inertia_to_parent, motion_to_child, rate_of, velocity,
    JointState,
};
use super::spatial::{Force, Motion};
use super::{joint_at, Joint, JointKind, RigidConstants, RUNTIME};
use crate::dynamics::{finite_accelerations, non_finite_dynamics, singular_mass_matrix};
use crate::error::{Error, Result};
use crate::geometry::Scalar;
use crate::linalg::{NotPositiveDefinite, SINGULAR_PIVOT};
use crate::model::Coordinates;
use nalgebra::SVector;

/// The articulated-body algorithm's working memory for `B` bodies, swept body by body:
/// [`velocity`](Self::velocity) root to leaf, [`articulate`](Self::articulate) leaf to root,
/// [`accelerate`](Self::accelerate) root to leaf. [`accelerations`] runs the sweeps as loops;
/// `#[mechanism]` writes one call per body with a constant index, so that each call is compiled for
/// its own joint.
pub struct Articulated<S, const B: usize> {
    state: [JointState<S>; B],
    velocity: [Motion<S>; B],
    bias_acceleration: [Motion<S>; B],
    inertia: [Inertia<S>; B],
    bias_force: [Force<S>; B],
    /// U_b.
    column: [Force<S>; B],
    /// 1 / D_b.
    inverse_pivot: [S; B],
    /// u_b.
    free: [S; B],
    acceleration: [Motion<S>; B],
}

/// A pivot D_b that is not clearly positive: the body, and the pivot's value.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pivot {
    /// The body whose joint's pivot failed.
    pub body: usize,
    /// D_b (its real part).
    pub value: f64,
    /// The scale it was tested against.
    pub scale: f64,
}

impl<S: Scalar, const B: usize> Default for Articulated<S, B> {
    fn default() -> Self {
        Self::new()
    }
}

impl<S: Scalar, const B: usize> Articulated<S, B> {
    /// Empty working memory.
    #[inline(always)]
    pub fn new() -> Self {
        Articulated {
            state: [JointState::Welded; B],
            velocity: [Motion::zero(); B],
            bias_acceleration: [Motion::zero(); B],
            inertia: [Inertia::zero(); B],
            bias_force: [Force::zero(); B],
            column: [Force::zero(); B],
            inverse_pivot: [S::zero(); B],
            free: [S::zero(); B],
            acceleration: [Motion::zero(); B],
        }
    }

    /// Body `b`, root to leaf: its joint, velocity, c_b, and I^A_b, p^A_b started from its own
    /// inertia.
    #[inline(always)]
    pub fn velocity<const CODE: u16, const N: usize>(
        &mut self,
        joints: &[Joint; B],
        k: &RigidConstants<B>,
        q: &[S; N],
        v: &[S; N],
        b: usize,
    ) {
        let (joint, kb) = (&joint_at::<CODE, B>(joints, b), &k.bodies[b]);
        let state = JointState::of(joint, q);
        let parent = joint.parent.map(|p| &self.velocity[p]);
        let (vb, c) = velocity(joint, kb, state, parent, rate_of(joint, v));
        self.state[b] = state;
        self.velocity[b] = vb;
        self.bias_acceleration[b] = c;
        self.inertia[b] = kb.inertia.as_inertia();
        self.bias_force[b] = vb.cross_force(&kb.inertia.apply(&vb));
    }

    /// Body `b`, leaf to root: U_b, D_b, u_b, and what the body passes to its parent. Fails on a
    /// pivot that is not clearly positive.
    #[inline(always)]
    pub fn articulate<const CODE: u16, const N: usize>(
        &mut self,
        joints: &[Joint; B],
        k: &RigidConstants<B>,
        tau: &[S; N],
        b: usize,
    ) -> core::result::Result<(), Pivot> {
        let joint = &joint_at::<CODE, B>(joints, b);
        let mut inertia = self.inertia[b];
        let mut bias = self.bias_force[b];
        let projected = match joint.kind {
            JointKind::Revolute(axis) => Some((axis, inertia.angular_column(axis), true)),
            JointKind::Prismatic(axis) => Some((axis, inertia.linear_column(axis), false)),
            JointKind::Fixed => None,
        };
        if let Some((axis, column, angular)) = projected {
            let a = axis.indices().0;
            let (pivot, along) = match angular {
                true => (column.moment[a], bias.moment[a]),
                false => (column.force[a], bias.force[a]),
            };
            let scale = inertia.diagonal_scale(angular);
            if !(pivot.re() > SINGULAR_PIVOT * scale) {
                return Err(Pivot {
                    body: b,
                    value: pivot.re(),
                    scale,
                });
            }
            let inverse = S::one() / pivot;
            let free = tau[joint.coordinate] - along;
            self.column[b] = column;
            self.inverse_pivot[b] = inverse;
            self.free[b] = free;
            if joint.parent.is_some() {
                inertia.sub_outer(&column, inverse);
                let pushed = inertia.apply(&self.bias_acceleration[b]);
                bias = bias + pushed + column.scale(free * inverse);
            }
        }
        if let Some(p) = joint.parent {
            let (kb, state) = (&k.bodies[b], self.state[b]);
            inertia_to_parent(joint, kb, state, &mut inertia);
            let pushed = force_to_parent(joint, kb, state, &bias);
            self.inertia[p].add(&inertia);
            self.bias_force[p] = self.bias_force[p] + pushed;
        }
        Ok(())
    }

    /// Body `b`, root to leaf: q̈_b and the body's acceleration.
    #[inline(always)]
    pub fn accelerate<const CODE: u16, const N: usize>(
        &mut self,
        joints: &[Joint; B],
        k: &RigidConstants<B>,
        qdd: &mut [S; N],
        b: usize,
    ) {
        let (joint, kb) = (&joint_at::<CODE, B>(joints, b), &k.bodies[b]);
        let above = match joint.parent {
            Some(p) => self.acceleration[p],
            None => ground_acceleration(k),
        };
        let mut a = motion_to_child(joint, kb, self.state[b], &above) + self.bias_acceleration[b];
        let (axis, angular) = match joint.kind {
            JointKind::Revolute(axis) => (axis, true),
            JointKind::Prismatic(axis) => (axis, false),
            JointKind::Fixed => {
                self.acceleration[b] = a;
                return;
            }
        };
        let column = &self.column[b];
        let along = Motion {
            angular: column.moment,
            linear: column.force,
        };
        // Uᵀ a' = (n; f)·(ω'; v'), the column read as a force paired with a motion.
        let coupling = a.dot(&Force {
            moment: along.angular,
            force: along.linear,
        });
        let joint_acceleration = (self.free[b] - coupling) * self.inverse_pivot[b];
        let index = axis.indices().0;
        match angular {
            true => a.angular[index] += joint_acceleration,
            false => a.linear[index] += joint_acceleration,
        }
        qdd[joint.coordinate] = joint_acceleration;
        self.acceleration[b] = a;
    }
}

/// q̈ at (t, q, q̇) under the generalized forces τ, by the three sweeps as loops (see the
/// [module docs](self)). Errors name the coordinates `C`: a singular mass matrix (a pivot D_b not
/// clearly positive), non-finite dynamics.
pub fn accelerations<C: Coordinates<N>, S: Scalar, const N: usize, const B: usize>(
    joints: &[Joint; B],
    k: &RigidConstants<B>,
    t: S,
    q: &[S; N],
    v: &[S; N],
    tau: &[S; N],
) -> Result<[S; N]> {
    let mut ws = Articulated::<S, B>::new();
    for b in 0..B {
        ws.velocity::<RUNTIME, N>(joints, k, q, v, b);
    }
    for b in (0..B).rev() {
        if let Err(pivot) = ws.articulate::<RUNTIME, N>(joints, k, tau, b) {
            return Err(singular::<C, S, N, B>(joints, pivot, t, q));
        }
    }
    let mut qdd = [S::zero(); N];
    for b in 0..B {
        ws.accelerate::<RUNTIME, N>(joints, k, &mut qdd, b);
    }
    finite_accelerations::<C, S, N>(SVector::from(qdd), t, q)
}

/// The error for a pivot that failed: non-finite dynamics when the pivot or its scale is not
/// finite, otherwise a singular mass matrix named by the joint's coordinate.
#[cold]
#[inline(never)]
pub fn singular<C: Coordinates<N>, S: Scalar, const N: usize, const B: usize>(
    joints: &[Joint; B],
    pivot: Pivot,
    t: S,
    q: &[S; N],
) -> Error {
    if !pivot.value.is_finite() || !pivot.scale.is_finite() {
        return non_finite_dynamics::<C, S, N>(t, q);
    }
    singular_mass_matrix::<C, S, N>(
        NotPositiveDefinite {
            index: joints[pivot.body].coordinate,
            pivot: pivot.value,
        },
        t,
        q,
    )
}
