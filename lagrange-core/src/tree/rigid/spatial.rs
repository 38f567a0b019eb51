//! The spatial algebra of the rigid-body tree, written out on 3-vectors and 3×3 blocks so that every
//! product the joints make structurally zero can be left out where it is compiled.
//!
//! Conventions (Featherstone, *Rigid Body Dynamics Algorithms*, 2008, ch. 2): a motion vector is
//! m = (ω; v), the angular velocity and the velocity of the body-fixed point at the frame's origin;
//! a force vector is f = (n; f), the moment about the origin and the force. A spatial inertia is the
//! symmetric 6×6 matrix
//!
//! ```text
//! I = [ A  B ]        n = A ω + B v,
//!     [ Bᵀ C ],       f = Bᵀ ω + C v,
//! ```
//!
//! which for one rigid body of mass m, first moment h = m c (c its centre of mass) and rotational
//! inertia Ī about the origin is A = Ī, B = h×, C = m 1 (Featherstone eq. 2.63); an articulated
//! inertia has the same shape with general blocks.
//!
//! A frame change from a parent frame P to a child frame C is a rotation Q (C's axes in P's
//! coordinates, by columns) and the child's origin r (in P's coordinates). Motion vectors go from
//! P to C, forces and inertias from C back to P (Featherstone eq. 2.24 and its dual):
//!
//! ```text
//! ω_C = Qᵀ ω_P,            v_C = Qᵀ (v_P + ω_P × r),
//! f_P = Q f_C,             n_P = Q n_C + r × f_P,
//! I_P = Xᵀ I_C X:          C_P = C',  B_P = B' + r× C',  A_P = A' − T − Tᵀ − r× C' r×,
//!                          with (A', B', C') = Q (A, B, C) Qᵀ and T = B' r×.
//! ```
//!
//! A joint's frame change is split into a constant part (a rotation E and an offset r fixed in the
//! parent) and the joint's own part (a rotation about a coordinate axis, or a slide along one), each
//! with its own routine: a rotation about a coordinate axis mixes two rows and columns, not three.

use crate::geometry::Scalar;

/// A 3-vector.
pub type V3<S> = [S; 3];
/// A 3×3 matrix by rows.
pub type M3<S> = [[S; 3]; 3];

/// A coordinate axis of a frame: the axis of a joint, a rotation about it or a slide along it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Axis {
    /// The frame's x axis.
    X,
    /// The frame's y axis.
    Y,
    /// The frame's z axis.
    Z,
}

impl Axis {
    /// The axis' index, and the two indices (u, v) of the plane a positive rotation about it turns
    /// u towards v in: (y, z) about x, (z, x) about y, (x, y) about z.
    #[inline(always)]
    pub const fn indices(self) -> (usize, usize, usize) {
        match self {
            Axis::X => (0, 1, 2),
            Axis::Y => (1, 2, 0),
            Axis::Z => (2, 0, 1),
        }
    }
}

/// (0, 0, 0).
#[inline(always)]
pub fn zero3<S: Scalar>() -> V3<S> {
    [S::zero(); 3]
}

/// a + b.
#[inline(always)]
pub fn add3<S: Scalar>(a: V3<S>, b: V3<S>) -> V3<S> {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

/// a − b.
#[inline(always)]
pub fn sub3<S: Scalar>(a: V3<S>, b: V3<S>) -> V3<S> {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// a s.
#[inline(always)]
pub fn scale3<S: Scalar>(a: V3<S>, s: S) -> V3<S> {
    [a[0] * s, a[1] * s, a[2] * s]
}

/// a · b.
#[inline(always)]
pub fn dot3<S: Scalar>(a: V3<S>, b: V3<S>) -> S {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// a × b.
#[inline(always)]
pub fn cross<S: Scalar>(a: V3<S>, b: V3<S>) -> V3<S> {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// r × b for a constant r whose structurally zero components (`mask[k]` false) are left out.
#[inline(always)]
pub fn cross_const<S: Scalar>(r: &V3<f64>, mask: [bool; 3], b: V3<S>) -> V3<S> {
    let term = |k: usize, x: S| if mask[k] { x * r[k] } else { S::zero() };
    [
        term(1, b[2]) - term(2, b[1]),
        term(2, b[0]) - term(0, b[2]),
        term(0, b[1]) - term(1, b[0]),
    ]
}

/// M x.
#[inline(always)]
pub fn mul3<S: Scalar>(m: &M3<f64>, x: V3<S>) -> V3<S> {
    [
        x[0] * m[0][0] + x[1] * m[0][1] + x[2] * m[0][2],
        x[0] * m[1][0] + x[1] * m[1][1] + x[2] * m[1][2],
        x[0] * m[2][0] + x[1] * m[2][1] + x[2] * m[2][2],
    ]
}

/// Mᵀ x.
#[inline(always)]
pub fn mul3_transpose<S: Scalar>(m: &M3<f64>, x: V3<S>) -> V3<S> {
    [
        x[0] * m[0][0] + x[1] * m[1][0] + x[2] * m[2][0],
        x[0] * m[0][1] + x[1] * m[1][1] + x[2] * m[2][1],
        x[0] * m[0][2] + x[1] * m[1][2] + x[2] * m[2][2],
    ]
}

/// The rotation by (cos θ, sin θ) about `axis` applied to x (`sign` = 1), or its transpose
/// (`sign` = −1): only the two components in the plane of the rotation change.
#[inline(always)]
pub fn turn<S: Scalar>(axis: Axis, (c, s): (S, S), x: V3<S>) -> V3<S> {
    let (_, u, v) = axis.indices();
    let mut out = x;
    out[u] = c * x[u] - s * x[v];
    out[v] = s * x[u] + c * x[v];
    out
}

/// The transpose of [`turn`]: the rotation by −θ.
#[inline(always)]
pub fn turn_back<S: Scalar>(axis: Axis, (c, s): (S, S), x: V3<S>) -> V3<S> {
    let (_, u, v) = axis.indices();
    let mut out = x;
    out[u] = c * x[u] + s * x[v];
    out[v] = c * x[v] - s * x[u];
    out
}

/// A motion vector (ω; v).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Motion<S> {
    /// ω.
    pub angular: V3<S>,
    /// v: the velocity of the body-fixed point at the frame's origin.
    pub linear: V3<S>,
}

/// A force vector (n; f).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Force<S> {
    /// n: the moment about the frame's origin.
    pub moment: V3<S>,
    /// f.
    pub force: V3<S>,
}

impl<S: Scalar> Motion<S> {
    /// At rest.
    #[inline(always)]
    pub fn zero() -> Self {
        Motion {
            angular: zero3(),
            linear: zero3(),
        }
    }
    /// The spatial cross product m × (e_axis s; 0) for a revolute rate s = q̇ (Featherstone eq.
    /// 2.31): (ω × e s; v × e s).
    #[inline(always)]
    pub fn cross_angular_axis(&self, axis: Axis, s: S) -> Motion<S> {
        Motion {
            angular: cross_axis(self.angular, axis, s),
            linear: cross_axis(self.linear, axis, s),
        }
    }
    /// m × (0; e_axis s) for a prismatic rate s: (0; ω × e s).
    #[inline(always)]
    pub fn cross_linear_axis(&self, axis: Axis, s: S) -> Motion<S> {
        Motion {
            angular: zero3(),
            linear: cross_axis(self.angular, axis, s),
        }
    }
    /// m ×* f (Featherstone eq. 2.32): (ω × n + v × f; ω × f).
    #[inline(always)]
    pub fn cross_force(&self, f: &Force<S>) -> Force<S> {
        Force {
            moment: add3(cross(self.angular, f.moment), cross(self.linear, f.force)),
            force: cross(self.angular, f.force),
        }
    }
    /// m · f: the power of f on m.
    #[inline(always)]
    pub fn dot(&self, f: &Force<S>) -> S {
        dot3(self.angular, f.moment) + dot3(self.linear, f.force)
    }
}

impl<S: Scalar> Force<S> {
    /// No force.
    #[inline(always)]
    pub fn zero() -> Self {
        Force {
            moment: zero3(),
            force: zero3(),
        }
    }
    /// f s.
    #[inline(always)]
    pub fn scale(self, s: S) -> Self {
        Force {
            moment: scale3(self.moment, s),
            force: scale3(self.force, s),
        }
    }
}

impl<S: Scalar> std::ops::Add for Motion<S> {
    type Output = Self;
    #[inline(always)]
    fn add(self, o: Self) -> Self {
        Motion {
            angular: add3(self.angular, o.angular),
            linear: add3(self.linear, o.linear),
        }
    }
}

impl<S: Scalar> std::ops::Add for Force<S> {
    type Output = Self;
    #[inline(always)]
    fn add(self, o: Self) -> Self {
        Force {
            moment: add3(self.moment, o.moment),
            force: add3(self.force, o.force),
        }
    }
}

/// x × (e_axis s): a cross product with a scaled coordinate axis, two products.
#[inline(always)]
pub fn cross_axis<S: Scalar>(x: V3<S>, axis: Axis, s: S) -> V3<S> {
    let (a, u, v) = axis.indices();
    let mut out = zero3();
    // x × e_a = x_u (e_u × e_a) + x_v (e_v × e_a) = x_v e_u − x_u e_v (cyclic u, v, a).
    out[u] = x[v] * s;
    out[v] = -(x[u] * s);
    let _ = a;
    out
}

/// A rigid body's spatial inertia in its own frame: mass m, first moment h = m c about the frame's
/// origin, rotational inertia Ī about the origin (symmetric, by rows). Constant: prepared once.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RigidInertia {
    /// m.
    pub mass: f64,
    /// h = m c.
    pub first_moment: V3<f64>,
    /// Ī: the rotational inertia about the frame's origin.
    pub rotational: M3<f64>,
}

impl RigidInertia {
    /// From the mass, the centre of mass c in the frame and the rotational inertia Ī_c about the
    /// centre of mass, in the frame's axes: Ī = Ī_c + m (|c|² 1 − c cᵀ) (the parallel-axis theorem,
    /// Featherstone eq. 2.63).
    pub fn about_origin(mass: f64, com: V3<f64>, about_com: M3<f64>) -> Self {
        let c2 = com[0] * com[0] + com[1] * com[1] + com[2] * com[2];
        let mut rotational = about_com;
        for (i, row) in rotational.iter_mut().enumerate() {
            for (j, e) in row.iter_mut().enumerate() {
                let delta = if i == j { c2 } else { 0.0 };
                *e += mass * (delta - com[i] * com[j]);
            }
        }
        RigidInertia {
            mass,
            first_moment: [mass * com[0], mass * com[1], mass * com[2]],
            rotational,
        }
    }

    /// I m: (Ī ω + h × v; m v − h × ω).
    #[inline(always)]
    pub fn apply<S: Scalar>(&self, m: &Motion<S>) -> Force<S> {
        let h = &self.first_moment;
        let all = [true; 3];
        Force {
            moment: add3(
                mul3(&self.rotational, m.angular),
                cross_const(h, all, m.linear),
            ),
            force: sub3(
                scale3(m.linear, S::from(self.mass)),
                cross_const(h, all, m.angular),
            ),
        }
    }
}

#[cfg(test)]
mod tests;
