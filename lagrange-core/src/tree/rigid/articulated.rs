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
    force_to_parent, ground_acceleration, inertia_to_parent, motion_to_child, velocity, JointState,
};
use super::spatial::{Force, Motion};
use super::{free, joint_at, Joint, JointKind, RigidConstants, RUNTIME};
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
///
/// Each body's slots are empty until its step of a sweep fills them, so nothing is zeroed first
/// (for a tree of thirty bodies, zeroing the memory cost about a fifth of a call). A step that
/// reads a slot its sweep order has not filled (a child's step before its parent's on the way
/// down, a body articulated twice) panics: the order of the calls is a programming error, never
/// a property of the state.
pub struct Articulated<S, const B: usize> {
    /// What the first sweep leaves: the joint, v_b and c_b.
    moving: [Option<Moving<S>>; B],
    /// I^A_b and p^A_b, started by the first sweep and completed by the children's articulation.
    articulated: [Option<(Inertia<S>, Force<S>)>; B],
    /// What the second sweep leaves for the third.
    projected: [Option<Projected<S>>; B],
    /// a_b.
    acceleration: [Option<Motion<S>>; B],
}

/// A body after the first sweep.
#[derive(Clone, Copy)]
struct Moving<S> {
    state: JointState<S>,
    velocity: Motion<S>,
    bias_acceleration: Motion<S>,
}

/// A body's joint after the second sweep: U_b, 1 / D_b and u_b (nothing for a fixed joint; a
/// free root's acceleration, its whole articulated equation solved).
#[derive(Clone, Copy)]
enum Projected<S> {
    Moved {
        column: Force<S>,
        inverse_pivot: S,
        free: S,
    },
    Welded,
    Root(Motion<S>),
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

/// A slot the sweep order should have filled.
#[inline(always)]
fn filled<T: Copy>(slot: &Option<T>, sweep: &str) -> T {
    match slot {
        Some(x) => *x,
        None => out_of_order(sweep),
    }
}

#[cold]
#[inline(never)]
fn out_of_order(sweep: &str) -> ! {
    panic!("articulated-body sweeps called out of order: {sweep}")
}

impl<S: Scalar, const B: usize> Articulated<S, B> {
    /// Empty working memory.
    #[inline(always)]
    pub fn new() -> Self {
        Articulated {
            moving: [None; B],
            articulated: [None; B],
            projected: [None; B],
            acceleration: [None; B],
        }
    }

    /// Body `b`, root to leaf: its joint, velocity, c_b, and I^A_b, p^A_b started from its own
    /// inertia, I^A_b = I_b, p^A_b = v_b ×* I_b v_b.
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
        let parent = joint
            .parent
            .map(|p| filled(&self.moving[p], "a parent's velocity").velocity);
        let (vb, c) = velocity(joint, kb, state, parent.as_ref(), v);
        self.moving[b] = Some(Moving {
            state,
            velocity: vb,
            bias_acceleration: c,
        });
        let bias = vb.cross_force(&kb.inertia.apply(&vb));
        self.articulated[b] = Some((kb.inertia.as_inertia(), bias));
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
        let moving = filled(&self.moving[b], "a body articulated before its velocity");
        let Some((mut inertia, mut bias)) = self.articulated[b].take() else {
            out_of_order("a body articulated twice")
        };
        let projected = match joint.kind {
            JointKind::Revolute(axis) => Some((axis, inertia.angular_column(axis), true)),
            JointKind::Prismatic(axis) => Some((axis, inertia.linear_column(axis), false)),
            JointKind::Fixed => None,
            JointKind::Free(..) | JointKind::Ball(..) => {
                let ground = ground_acceleration(k);
                return self.articulate_root(joint, moving.state, (inertia, bias), tau, &ground, b);
            }
        };
        self.projected[b] = Some(Projected::Welded);
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
            self.projected[b] = Some(Projected::Moved {
                column,
                inverse_pivot: inverse,
                free,
            });
            if joint.parent.is_some() {
                inertia.sub_outer(&column, inverse);
                let pushed = inertia.apply(&moving.bias_acceleration);
                bias = bias + pushed + column.scale(free * inverse);
            }
        }
        if let Some(p) = joint.parent {
            let (kb, state) = (&k.bodies[b], moving.state);
            inertia_to_parent(joint, kb, state, &mut inertia);
            let pushed = force_to_parent(joint, kb, state, &bias);
            match &mut self.articulated[p] {
                Some((parent_inertia, parent_bias)) => {
                    parent_inertia.add(&inertia);
                    *parent_bias = *parent_bias + pushed;
                }
                None => out_of_order("a parent articulated before its child"),
            }
        }
        Ok(())
    }

    /// A free or ball root (no parent): its articulated equation solved for its acceleration.
    #[inline(always)]
    fn articulate_root<const N: usize>(
        &mut self,
        joint: &Joint,
        state: JointState<S>,
        (inertia, bias): (Inertia<S>, Force<S>),
        tau: &[S; N],
        ground: &Motion<S>,
        b: usize,
    ) -> core::result::Result<(), Pivot> {
        let JointState::Free(o) = state else {
            out_of_order("a free joint without its orientation")
        };
        let tau = free::rates(tau, joint);
        let acceleration = match free::translates(joint) {
            true => free::root_acceleration(o, &inertia, &bias, tau),
            false => free::pivot_acceleration(o, &inertia, &bias, tau, ground),
        };
        match acceleration {
            Ok(a) => {
                self.projected[b] = Some(Projected::Root(a));
                Ok(())
            }
            Err(e) => Err(Pivot {
                body: b,
                value: e.pivot,
                scale: inertia.diagonal_scale(e.index < 3),
            }),
        }
    }

    /// Body `b`, root to leaf: q̈_b and the body's acceleration,
    /// a' = X_b a_p + c_b, q̈_b = (u_b − U_bᵀ a') / D_b, a_b = a' + S_b q̈_b.
    #[inline(always)]
    pub fn accelerate<const CODE: u16, const N: usize>(
        &mut self,
        joints: &[Joint; B],
        k: &RigidConstants<B>,
        qdd: &mut [S; N],
        b: usize,
    ) {
        let (joint, kb) = (&joint_at::<CODE, B>(joints, b), &k.bodies[b]);
        let moving = filled(&self.moving[b], "a body accelerated before its velocity");
        let above = match joint.parent {
            Some(p) => filled(
                &self.acceleration[p],
                "a child accelerated before its parent",
            ),
            None => ground_acceleration(k),
        };
        let projected = filled(
            &self.projected[b],
            "a body accelerated before its articulation",
        );
        // A free or ball root's acceleration is its articulated equation's solution already.
        if let (Projected::Root(a), JointState::Free(o)) = (projected, moving.state) {
            let rates = free::accelerations(o, &a, &above, &moving.bias_acceleration);
            free::store(qdd, joint, rates);
            self.acceleration[b] = Some(a);
            return;
        }
        let mut a = motion_to_child(joint, kb, moving.state, &above) + moving.bias_acceleration;
        let (axis, angular, column, inverse_pivot, free) = match (joint.kind, projected) {
            (
                JointKind::Revolute(axis),
                Projected::Moved {
                    column,
                    inverse_pivot,
                    free,
                },
            ) => (axis, true, column, inverse_pivot, free),
            (
                JointKind::Prismatic(axis),
                Projected::Moved {
                    column,
                    inverse_pivot,
                    free,
                },
            ) => (axis, false, column, inverse_pivot, free),
            _ => {
                self.acceleration[b] = Some(a);
                return;
            }
        };
        // Uᵀ a' = (n; f)·(ω'; v'), the column read as a force paired with a motion.
        let coupling = a.dot(&column);
        let joint_acceleration = (free - coupling) * inverse_pivot;
        let index = axis.indices().0;
        match angular {
            true => a.angular[index] += joint_acceleration,
            false => a.linear[index] += joint_acceleration,
        }
        qdd[joint.coordinate] = joint_acceleration;
        self.acceleration[b] = Some(a);
    }
}

/// q̈ at (t, q, q̇) under the generalized forces τ, by the three sweeps as loops (Featherstone
/// §7.3, Table 7.1). Errors name the coordinates `C`: a singular mass matrix (a pivot D_b not
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
