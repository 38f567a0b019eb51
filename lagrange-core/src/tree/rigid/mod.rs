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
//! free (a root only):      R_b = R(c),            o_b = p,
//! ball (a root only):      R_b = R(c),            o_b = r,
//! ```
//!
//! with (R_b, o_b) the body's frame (orientation and origin) in the world, a a coordinate axis of
//! the joint's frame (so the joint's motion subspace S = (e_a; 0) or (0; e_a) has one non-zero
//! entry; a free root's six coordinates (p, c) enter by S(q) = diag(B(c), Rᵀ), a ball root's three by
//! S(q) = (B(c); 0), c in a rotation chart, see [`free`]) and
//! the body's inertia constant in its frame ([`spatial::RigidInertia`]: mass, centre of mass,
//! rotational inertia). Everything that does not depend on the state — E, r, the inertias and
//! the uniform field g — is prepared once ([`RigidConstants`], computed by the validated handle);
//! what the declaration shows to be structurally zero ([`Joint::rotated`], [`Joint::offset`]) is
//! left out where the per-body steps are compiled with a constant body index, as `#[mechanism]`
//! writes them (one call per body, see the facade's "How it works"). The drivers here loop over the
//! bodies and are the reference the generated sequences are tested against.
//!
//! Gravity enters as an acceleration of the ground, a₀ = (0; −g) (Featherstone §5.3), so it costs
//! nothing per body. Every other force reaches the recursion as generalized forces τ.

#![allow(clippy::needless_range_loop, clippy::neg_cmp_op_on_partial_ord)]

pub mod inertia;
pub mod spatial;

mod articulated;
mod composite;
mod declared;
pub mod free;
mod kinematics;
mod newton_euler;

pub use articulated::{accelerations, singular, Articulated, Pivot};
pub use composite::{mass_matrix, momenta};
pub use declared::inverse_dynamics;
pub use declared::{
    axis_frame, body_constants, diagonal, equations_of_motion, equations_of_motion_in_rates,
    finished, flip, less_other_forces, other_generalized_forces, turned_tensor,
};
pub use kinematics::{kinetic_energy, world_frames, Frame};
/// τ = M q̈ + b − 𝓕_g of the bodies alone (see [`declared::inverse_dynamics`] for a declaration's).
pub use newton_euler::inverse_dynamics as joint_torques;
pub use newton_euler::{bias_and_gravity, NewtonEuler};

use crate::geometry::RotationChart;
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
    /// A free body (six coordinates from `coordinate` on): its origin p in the world by three,
    /// then its orientation R(c) by three coordinates of the chart
    /// ([`rot_mrp`](crate::geometry::rot_mrp) or [`rot_vector`](crate::geometry::rot_vector)).
    /// Only a root (no parent) is free, with E the identity and r zero: R_b = R(c), o_b = p (see
    /// [`free`]). Its velocities are (ṗ, ċ) or (ṗ, ω_b), as the [`Velocities`] say.
    Free(RotationChart, Velocities),
    /// A ball joint (three coordinates from `coordinate` on): the body turns about its origin,
    /// fixed at the offset r in the world, by R(c) of the chart. Only a root has one, with E the
    /// identity: R_b = R(c), o_b = r (see [`free`]). Its velocities are ċ or ω_b, as the
    /// [`Velocities`] say.
    Ball(RotationChart, Velocities),
}

/// What the velocities of a free or ball joint's orientation are.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Velocities {
    /// The chart's rates ċ: the coordinates' time derivatives, as for every other joint.
    ChartRates,
    /// The body's angular velocity ω_b (in its own frame), quasi-velocities: the coordinates
    /// move by ċ = B(c)⁻¹ ω_b ([`free::position_rates`]), and the joint's motion subspace on them
    /// is the identity (no B, no Ḃ in the recursions).
    AngularVelocity,
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

impl Joint {
    /// What the compiler knows of the joint apart from its place in the tree, as one number: the
    /// const parameter of the per-body steps (`Articulated::velocity_of::<CODE>` …) that
    /// `#[mechanism]` calls, so each distinct kind of joint is compiled once, its structural zeros
    /// folded, however many bodies have it.
    pub const fn code(&self) -> u16 {
        // A joint that turns freely has no axis: the two bits say whether it translates and its
        // chart, bit 9 whether its velocities are the angular velocity.
        let (kind, axis) = match self.kind {
            JointKind::Revolute(a) => (0, axis_bits(a)),
            JointKind::Prismatic(a) => (1, axis_bits(a)),
            JointKind::Fixed => (2, 0),
            JointKind::Free(c, _) => (3, chart_bit(c)),
            JointKind::Ball(c, _) => (3, 2 + chart_bit(c)),
        };
        kind | axis << 2
            | bit(self.rotated, 4)
            | bit(self.offset[0], 5)
            | bit(self.offset[1], 6)
            | bit(self.offset[2], 7)
            | bit(self.parent.is_some(), 8)
            | bit(
                matches!(self.velocities(), Some(Velocities::AngularVelocity)),
                9,
            )
    }

    /// A free or ball joint's velocities, `None` for another joint.
    pub const fn velocities(&self) -> Option<Velocities> {
        match self.kind {
            JointKind::Free(_, v) | JointKind::Ball(_, v) => Some(v),
            _ => None,
        }
    }

    /// The joint with what `code` holds taken from it (known where the code is a constant) and
    /// its parent's index and coordinate from `self`.
    #[inline(always)]
    pub const fn decoded(&self, code: u16) -> Joint {
        let bits = (code >> 2) & 3;
        let axis = match bits {
            0 => Axis::X,
            1 => Axis::Y,
            _ => Axis::Z,
        };
        let chart = match bits & 1 {
            0 => RotationChart::Mrp,
            _ => RotationChart::Vector,
        };
        let velocities = match on(code, 9) {
            false => Velocities::ChartRates,
            true => Velocities::AngularVelocity,
        };
        let kind = match (code & 3, bits >> 1) {
            (0, _) => JointKind::Revolute(axis),
            (1, _) => JointKind::Prismatic(axis),
            (2, _) => JointKind::Fixed,
            (_, 0) => JointKind::Free(chart, velocities),
            (_, _) => JointKind::Ball(chart, velocities),
        };
        let parent = match (on(code, 8), self.parent) {
            (true, Some(p)) => Some(p),
            // A parent the code promises: a constant `Some` whatever the index.
            (true, None) => Some(0),
            (false, _) => None,
        };
        Joint {
            parent,
            kind,
            coordinate: self.coordinate,
            rotated: on(code, 4),
            offset: [on(code, 5), on(code, 6), on(code, 7)],
        }
    }
}

/// An axis in two bits.
const fn axis_bits(a: Axis) -> u16 {
    match a {
        Axis::X => 0,
        Axis::Y => 1,
        Axis::Z => 2,
    }
}

/// A chart in one bit.
const fn chart_bit(c: RotationChart) -> u16 {
    match c {
        RotationChart::Mrp => 0,
        RotationChart::Vector => 1,
    }
}

/// 1 at bit `at` when `b` holds.
const fn bit(b: bool, at: u16) -> u16 {
    if b {
        1 << at
    } else {
        0
    }
}

/// Whether bit `at` of `code` is set.
const fn on(code: u16, at: u16) -> bool {
    code & (1 << at) != 0
}

/// The code that stands for "no code": the per-body steps read the whole joint from the table
/// (what the loops over the bodies pass).
pub const RUNTIME: u16 = u16::MAX;

/// Joint `b` of the table, with what `CODE` holds taken from the code (see [`Joint::code`]).
#[inline(always)]
pub(crate) fn joint_at<const CODE: u16, const B: usize>(joints: &[Joint; B], b: usize) -> Joint {
    match CODE {
        RUNTIME => joints[b],
        code => joints[b].decoded(code),
    }
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
