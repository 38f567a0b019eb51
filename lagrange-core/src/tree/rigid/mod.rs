//! The equations of motion of a **kinematic tree of rigid bodies** by Featherstone's recursive
//! algorithms (*Rigid Body Dynamics Algorithms*, 2008): q̈ by the articulated-body algorithm (ch. 7),
//! inverse dynamics and the bias forces by the recursive Newton–Euler algorithm (ch. 5), M by the
//! composite-rigid-body algorithm (ch. 6) — each work proportional to the bodies (M: to the bodies
//! times the depth), none forming M to solve with it.
//!
//! A body of the tree is placed from its parent (or from the ground) by a constant rotation E and
//! offset r fixed in the parent, then by its joint:
//!
//! ```text
//! revolute about axis a:   R_b = R_p E R_a(q),    o_b = o_p + R_p r,
//! prismatic along axis a:  R_b = R_p E,           o_b = o_p + R_p (r + E e_a q),
//! fixed:                   R_b = R_p E,           o_b = o_p + R_p r,
//! ```
//!
//! with (R_b, o_b) the body's frame (orientation and origin) in the world, a a coordinate axis of
//! the joint's frame (so the joint's motion subspace S = (e_a; 0) or (0; e_a) has one non-zero
//! entry) and the body's inertia constant in its frame ([`spatial::RigidInertia`]: mass, centre of
//! mass, rotational inertia). Everything that does not depend on the state — E, r, the inertias and
//! the uniform field g — is prepared once ([`RigidConstants`], computed by the validated handle);
//! what the declaration shows to be structurally zero ([`Joint::rotated`], [`Joint::offset`]) is
//! left out where the per-body steps are compiled with a constant body index, as `#[mechanism]`
//! writes them (one call per body, see the facade's "How it works"). The drivers here loop over the
//! bodies and are the reference the generated sequences are tested against.
//!
//! Gravity enters as an acceleration of the ground, a₀ = (0; −g) (Featherstone §5.3), so it costs
//! nothing per body. Every other force reaches the recursion as generalized forces τ.

#![allow(clippy::needless_range_loop, clippy::neg_cmp_op_on_partial_ord)]

pub mod spatial;

mod articulated;
mod composite;
mod declared;
mod kinematics;
mod newton_euler;

pub use articulated::{accelerations, singular, Articulated, Pivot};
pub use composite::{mass_matrix, momenta};
pub use declared::inverse_dynamics;
pub use declared::{
    axis_frame, body_constants, diagonal, equations_of_motion, finished, flip,
    other_generalized_forces, turned_tensor,
};
pub use kinematics::{kinetic_energy, world_frames, Frame};
pub use newton_euler::bias_and_gravity;
/// τ = M q̈ + b − 𝓕_g of the bodies alone (see [`declared::inverse_dynamics`] for a declaration's).
pub use newton_euler::inverse_dynamics as joint_torques;

use spatial::{Axis, RigidInertia, M3, V3};

/// How a body moves relative to its parent's frame (after the constant rotation and offset).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum JointKind {
    /// A rotation about an axis of the joint's frame by the joint's coordinate.
    Revolute(Axis),
    /// A slide along an axis of the joint's frame by the joint's coordinate.
    Prismatic(Axis),
    /// No motion: the body is welded to its parent (no coordinate).
    Fixed,
}

/// A body's joint, as the declaration states it: what the compiler knows of the tree.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Joint {
    /// The body it is placed from (an earlier one), or `None` for a body placed from the ground.
    pub parent: Option<usize>,
    /// Its motion.
    pub kind: JointKind,
    /// The generalized coordinate that moves it (ignored for a fixed joint).
    pub coordinate: usize,
    /// Whether a constant rotation E stands between the parent's frame and the joint's (`false`:
    /// E is the identity and its products are left out).
    pub rotated: bool,
    /// Which components of the offset r can be non-zero.
    pub offset: [bool; 3],
}

/// A body's constants, in the frames of [the module docs](self).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BodyConstants {
    /// E: the joint frame's axes in the parent's frame, by columns (rows stored).
    pub rotation: M3<f64>,
    /// r: the joint frame's origin in the parent's frame (at q = 0 for a slide).
    pub offset: V3<f64>,
    /// The body's inertia in its own frame.
    pub inertia: RigidInertia,
}

/// Everything of a rigid tree that the parameters decide: prepared once by a validated handle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RigidConstants<const B: usize> {
    /// The bodies' constants, in the order of [`RigidTree::JOINTS`].
    pub bodies: [BodyConstants; B],
    /// The uniform field's acceleration g in the world frame (zero without one).
    pub gravity: V3<f64>,
}

/// A mechanism whose `B` bodies form a kinematic tree of rigid bodies over `N` coordinates (see the
/// [module docs](self)). `#[mechanism]` implements it when it recognises the tree in a
/// declaration. Parents come before their children.
pub trait RigidTree<const N: usize, const B: usize> {
    /// The joints, one per body, in declaration order.
    const JOINTS: [Joint; B];
}

#[cfg(test)]
mod tests;
