//! Scalars and the small geometric types positions are written with.
//!
//! Every position function of a mechanism is evaluated on several scalar types: `f64` for output,
//! a gradient dual number for Jacobians, a second-order dual number for the velocity-product and time
//! terms, and nested duals for the exact Jacobians of implicit integrators. [`Scalar`] is the one bound
//! all of them satisfy; [`Vec2`], [`Vec3`] and [`Rot3`] are generic over it.
//!
//! Arithmetic reads like the paper: a scalar multiplies a vector from either side, `v * s` or
//! `s * v`, on `f64` and on every dual number (the left product is part of [`Scalar`]).
//!
//! ```
//! use lagrange_core::geometry::{vec2, vec3, Scalar, Vec2};
//! let (l, theta) = (2.0_f64, 0.3_f64);
//! let bob: Vec2<f64> = vec2(theta.sin(), -theta.cos()) * l;
//! assert!((bob.norm() - l).abs() < 1e-15);
//! assert_eq!(l * vec2(theta.sin(), -theta.cos()), bob);
//! assert_eq!(0.5 * vec3(2.0, 4.0, 6.0), vec3(1.0, 2.0, 3.0));
//!
//! // In code generic over the scalar, as a declaration's functions are:
//! fn tip<D: Scalar>(l: D, theta: D) -> Vec2<D> {
//!     l * vec2(theta.sin(), -theta.cos())
//! }
//! let d = tip(num_dual::Dual64::from(l), num_dual::Dual64::new(theta, 1.0));
//! assert_eq!(d.x.re, bob.x);
//! assert!((d.x.eps - l * theta.cos()).abs() < 1e-15); // d/dθ (l sin θ)
//! ```
//!
//! # nalgebra
//!
//! `f64` vectors and matrices convert to and from [`nalgebra`]'s types with `From`/`Into`:
//! [`Vec2`] ↔ `Vector2`, [`Vec3`] ↔ `Vector3`, [`Rot3`] ↔ `Matrix3`, and `Rotation3` → [`Rot3`].
//! The way back to `Rotation3` is checked ([`Rot3::to_rotation3`]), since a `Rot3` may hold any
//! 3×3 matrix.
//!
//! ```
//! use lagrange_core::geometry::{rot_z, vec2, vec3, Rot3, Vec2, Vec3};
//! use nalgebra::{Matrix3, Rotation3, Vector2, Vector3};
//!
//! let v: Vector2<f64> = vec2(1.0, 2.0).into();
//! assert_eq!(v, Vector2::new(1.0, 2.0));
//! assert_eq!(Vec3::from(Vector3::new(1.0, 2.0, 3.0)), vec3(1.0, 2.0, 3.0));
//!
//! // A rotation acts the same way on either side.
//! let r = rot_z(0.4_f64);
//! let m: Matrix3<f64> = r.into();
//! let x = r * vec3(1.0, 0.0, 0.5);
//! assert_eq!(Vec3::from(m * Vector3::new(1.0, 0.0, 0.5)), x);
//!
//! // nalgebra's Rotation3 is a checked rotation: a Rot3 converts only if it is one.
//! let rot: Rotation3<f64> = r.to_rotation3().expect("rot_z is a rotation");
//! assert_eq!(Rot3::from(rot), r);
//! let shear = Rot3 { rows: [[1.0, 1.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]] };
//! assert!(shear.to_rotation3().is_none());
//! assert_eq!(Vec2::from(v), vec2(1.0, 2.0));
//! ```

use nalgebra::allocator::Allocator;
use nalgebra::{DefaultAllocator, Dim, U1};
use num_dual::DualNum;
use std::ops::{Add, AddAssign, Div, Mul, Neg, Sub, SubAssign};

pub(crate) mod charts;
mod rotations;
pub use charts::{
    body_angular_velocity, chart_rates, rot_mrp, rot_vector, rotation, switch_chart,
    switch_orientation, RotationChart,
};
pub use rotations::{rot3, rot_axis, rpy};

/// A real number or a dual number over `f64`: what positions, potentials and the dynamics are
/// generic over.
///
/// Besides the arithmetic of [`DualNum`], a scalar multiplies a vector from the left (`s * v`,
/// the same as `v * s`): that is part of the bound, so it also holds in code generic over the
/// scalar, such as every function of a `#[mechanism]` declaration. `f64` and every number type of
/// `num-dual` (nested to any depth) are scalars.
pub trait Scalar:
    DualNum<Primitive = f64>
    + Copy
    + Mul<Vec2<Self>, Output = Vec2<Self>>
    + Mul<Vec3<Self>, Output = Vec3<Self>>
{
}
impl<T> Scalar for T where
    T: DualNum<Primitive = f64>
        + Copy
        + Mul<Vec2<T>, Output = Vec2<T>>
        + Mul<Vec3<T>, Output = Vec3<T>>
{
}

/// `s * v` for a scalar type `S` of `num-dual`: Rust's orphan rules allow it type family by type
/// family (a generic `impl<D> Mul<Vec2<D>> for D` is not allowed, `D` being foreign).
macro_rules! scalar_times_vector {
    ([$($g:tt)*] $S:ty $(, $($w:tt)+)?) => {
        /// Scalar times vector (`s * v`, the same as `v * s`).
        impl<$($g)*> Mul<Vec2<$S>> for $S
        where
            $S: DualNum<Primitive = f64> + Copy,
            $($($w)+)?
        {
            type Output = Vec2<$S>;
            #[inline(always)]
            fn mul(self, v: Vec2<$S>) -> Vec2<$S> {
                vec2(v.x * self, v.y * self)
            }
        }
        /// Scalar times vector (`s * v`, the same as `v * s`).
        impl<$($g)*> Mul<Vec3<$S>> for $S
        where
            $S: DualNum<Primitive = f64> + Copy,
            $($($w)+)?
        {
            type Output = Vec3<$S>;
            #[inline(always)]
            fn mul(self, v: Vec3<$S>) -> Vec3<$S> {
                vec3(v.x * self, v.y * self, v.z * self)
            }
        }
    };
}
scalar_times_vector!([T] num_dual::Dual<T>);
scalar_times_vector!([T] num_dual::Dual2<T>);
scalar_times_vector!([T] num_dual::Dual3<T>);
scalar_times_vector!([T] num_dual::HyperDual<T>);
scalar_times_vector!([T] num_dual::HyperHyperDual<T>);
scalar_times_vector!([T] num_dual::Real<T>);
scalar_times_vector!(
    [T: nalgebra::Scalar, D: Dim] num_dual::DualVec<T, D>,
    DefaultAllocator: Allocator<D>
);
scalar_times_vector!(
    [T: nalgebra::Scalar, D: Dim] num_dual::Dual2Vec<T, D>,
    DefaultAllocator: Allocator<U1, D> + Allocator<D, D>
);
scalar_times_vector!(
    [T: nalgebra::Scalar, M: Dim, N: Dim] num_dual::HyperDualVec<T, M, N>,
    DefaultAllocator: Allocator<M> + Allocator<M, N> + Allocator<U1, N>
);

/// A plain number times a vector of any scalar type (`2.0 * v`, the same as `v * 2.0`).
impl<D: DualNum<Primitive = f64> + Copy> Mul<Vec2<D>> for f64 {
    type Output = Vec2<D>;
    #[inline(always)]
    fn mul(self, v: Vec2<D>) -> Vec2<D> {
        vec2(v.x * self, v.y * self)
    }
}

/// A plain number times a vector of any scalar type (`2.0 * v`, the same as `v * 2.0`).
impl<D: DualNum<Primitive = f64> + Copy> Mul<Vec3<D>> for f64 {
    type Output = Vec3<D>;
    #[inline(always)]
    fn mul(self, v: Vec3<D>) -> Vec3<D> {
        vec3(v.x * self, v.y * self, v.z * self)
    }
}

/// A vector in the plane.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Vec2<D> {
    /// Component along the x axis (horizontal, to the right, in the gallery's scenes).
    pub x: D,
    /// Component along the y axis (vertical, upwards, in the gallery's scenes).
    pub y: D,
}

/// A vector in space.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Vec3<D> {
    /// Component along the x axis.
    pub x: D,
    /// Component along the y axis.
    pub y: D,
    /// Component along the z axis (x, y, z right-handed: x × y = z).
    pub z: D,
}

/// `vec2(x, y)`.
#[inline(always)]
pub fn vec2<D>(x: D, y: D) -> Vec2<D> {
    Vec2 { x, y }
}

/// `vec3(x, y, z)`.
#[inline(always)]
pub fn vec3<D>(x: D, y: D, z: D) -> Vec3<D> {
    Vec3 { x, y, z }
}

impl<D: Scalar> Vec2<D> {
    /// The planar cross product `self.x * other.y - self.y * other.x` (a scalar).
    #[inline(always)]
    pub fn cross(&self, other: &Self) -> D {
        self.x * other.y - self.y * other.x
    }
    /// This vector rotated counter-clockwise by `angle`.
    #[inline(always)]
    pub fn rotated(&self, angle: D) -> Self {
        let (s, c) = angle.sin_cos();
        vec2(c * self.x - s * self.y, s * self.x + c * self.y)
    }
}

impl<D: Scalar> Vec3<D> {
    /// Vector product.
    #[inline(always)]
    pub fn cross(&self, o: &Self) -> Self {
        vec3(
            self.y * o.z - self.z * o.y,
            self.z * o.x - self.x * o.z,
            self.x * o.y - self.y * o.x,
        )
    }
}

/// What Vec2 and Vec3 share, component by component: the zero vector, the scalar product
/// Σ aᵢbᵢ (summed in component order), the Euclidean length, the array of components, and the
/// arithmetic operators.
macro_rules! vector_ops {
    ($V:ident { $first:ident $(, $f:ident)+ }, $len:literal) => {
        impl<D: Scalar> $V<D> {
            /// The zero vector.
            #[inline(always)]
            pub fn zero() -> Self {
                $V { $first: D::zero() $(, $f: D::zero())+ }
            }
            /// Scalar product.
            #[inline(always)]
            pub fn dot(&self, other: &Self) -> D {
                self.$first * other.$first $(+ self.$f * other.$f)+
            }
            /// Squared Euclidean length.
            #[inline(always)]
            pub fn norm_squared(&self) -> D {
                self.dot(self)
            }
            /// Euclidean length.
            #[inline(always)]
            pub fn norm(&self) -> D {
                self.norm_squared().sqrt()
            }
            /// The components as an array.
            #[inline(always)]
            pub fn to_array(self) -> [D; $len] {
                [self.$first $(, self.$f)+]
            }
        }
        vector_ops!(@ops $V { $first $(, $f)+ });
    };
    (@ops $V:ident { $($f:ident),+ }) => {
        impl<D: Scalar> Add for $V<D> {
            type Output = Self;
            #[inline(always)]
            fn add(self, o: Self) -> Self { $V { $($f: self.$f + o.$f),+ } }
        }
        impl<D: Scalar> Sub for $V<D> {
            type Output = Self;
            #[inline(always)]
            fn sub(self, o: Self) -> Self { $V { $($f: self.$f - o.$f),+ } }
        }
        impl<D: Scalar> AddAssign for $V<D> {
            #[inline(always)]
            fn add_assign(&mut self, o: Self) { $(self.$f += o.$f;)+ }
        }
        impl<D: Scalar> SubAssign for $V<D> {
            #[inline(always)]
            fn sub_assign(&mut self, o: Self) { $(self.$f -= o.$f;)+ }
        }
        impl<D: Scalar> Neg for $V<D> {
            type Output = Self;
            #[inline(always)]
            fn neg(self) -> Self { $V { $($f: -self.$f),+ } }
        }
        /// Vector times scalar (write `v * s`).
        impl<D: Scalar> Mul<D> for $V<D> {
            type Output = Self;
            #[inline(always)]
            fn mul(self, s: D) -> Self { $V { $($f: self.$f * s),+ } }
        }
        /// Vector divided by a scalar, component by component.
        impl<D: Scalar> Div<D> for $V<D> {
            type Output = Self;
            #[inline(always)]
            fn div(self, s: D) -> Self { $V { $($f: self.$f / s),+ } }
        }
    };
}
vector_ops!(Vec2 { x, y }, 2);
vector_ops!(Vec3 { x, y, z }, 3);

/// A rotation (or any 3×3 matrix) acting on [`Vec3`], stored by rows.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rot3<D> {
    /// `rows[i][j]` is the entry in row i, column j.
    pub rows: [[D; 3]; 3],
}

impl<D: Scalar> Rot3<D> {
    /// The identity rotation.
    pub fn identity() -> Self {
        let (o, z) = (D::one(), D::zero());
        Rot3 {
            rows: [[o, z, z], [z, o, z], [z, z, o]],
        }
    }
    /// Column `k`: the image of the k-th body axis in the world frame.
    #[inline(always)]
    pub fn column(&self, k: usize) -> Vec3<D> {
        vec3(self.rows[0][k], self.rows[1][k], self.rows[2][k])
    }
    /// The transpose (the inverse, for a rotation).
    pub fn transpose(&self) -> Self {
        let r = &self.rows;
        Rot3 {
            rows: [
                [r[0][0], r[1][0], r[2][0]],
                [r[0][1], r[1][1], r[2][1]],
                [r[0][2], r[1][2], r[2][2]],
            ],
        }
    }
}

/// Rotation by `angle` about the x axis.
pub fn rot_x<D: Scalar>(angle: D) -> Rot3<D> {
    let (s, c) = angle.sin_cos();
    let (o, z) = (D::one(), D::zero());
    Rot3 {
        rows: [[o, z, z], [z, c, -s], [z, s, c]],
    }
}

/// Rotation by `angle` about the y axis.
pub fn rot_y<D: Scalar>(angle: D) -> Rot3<D> {
    let (s, c) = angle.sin_cos();
    let (o, z) = (D::one(), D::zero());
    Rot3 {
        rows: [[c, z, s], [z, o, z], [-s, z, c]],
    }
}

/// Rotation by `angle` about the z axis.
pub fn rot_z<D: Scalar>(angle: D) -> Rot3<D> {
    let (s, c) = angle.sin_cos();
    let (o, z) = (D::one(), D::zero());
    Rot3 {
        rows: [[c, -s, z], [s, c, z], [z, z, o]],
    }
}

impl<D: Scalar> Mul for Rot3<D> {
    type Output = Self;
    fn mul(self, o: Self) -> Self {
        let mut rows = [[D::zero(); 3]; 3];
        for (i, row) in rows.iter_mut().enumerate() {
            for (j, e) in row.iter_mut().enumerate() {
                *e = self.rows[i][0] * o.rows[0][j]
                    + self.rows[i][1] * o.rows[1][j]
                    + self.rows[i][2] * o.rows[2][j];
            }
        }
        Rot3 { rows }
    }
}

impl<D: Scalar> Mul<Vec3<D>> for Rot3<D> {
    type Output = Vec3<D>;
    #[inline(always)]
    fn mul(self, v: Vec3<D>) -> Vec3<D> {
        let r = &self.rows;
        vec3(
            r[0][0] * v.x + r[0][1] * v.y + r[0][2] * v.z,
            r[1][0] * v.x + r[1][1] * v.y + r[1][2] * v.z,
            r[2][0] * v.x + r[2][1] * v.y + r[2][2] * v.z,
        )
    }
}

/// Where a planar rigid body is: a point of it and its angle (counter-clockwise). The point is the
/// centre of mass, unless the body is declared with `#[rigid_body(com = ..)]`: then it is the origin
/// of the body's frame, and the centre of mass lies at `com` in that frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Planar<D> {
    /// The centre of mass in the world frame (the point the moment of inertia is taken about), or
    /// the origin of the body's frame when its `com` is declared.
    pub position: Vec2<D>,
    /// The body's orientation: the angle in radians, counter-clockwise, from the world x axis to
    /// the body's x axis (0 when the body frame is the world frame).
    pub angle: D,
}

/// `planar(centre_of_mass, angle)` (or `planar(frame_origin, angle)` for a body declared with
/// its `com`).
#[inline(always)]
pub fn planar<D>(position: Vec2<D>, angle: D) -> Planar<D> {
    Planar { position, angle }
}

impl<D: Scalar> Planar<D> {
    /// The world position of a point fixed in the body at `offset` (body frame, from the body's
    /// position: its centre of mass, or the origin of its frame when its `com` is given).
    #[inline(always)]
    pub fn point(&self, offset: Vec2<D>) -> Vec2<D> {
        self.position + offset.rotated(self.angle)
    }

    /// A child's frame at the parent's point `origin`, turned by `angle` relative to the parent (a
    /// robot file's joint origin followed by the joint's own rotation):
    /// `planar(self.point(origin), self.angle + angle)`.
    ///
    /// ```
    /// use lagrange_core::geometry::{planar, vec2};
    /// let upper = planar(vec2(0.0, 0.0), -1.2_f64);
    /// let lower = upper.joint(vec2(0.5, 0.0), 0.3);
    /// assert_eq!(lower, planar(upper.point(vec2(0.5, 0.0)), upper.angle + 0.3));
    /// ```
    #[inline(always)]
    pub fn joint(&self, origin: Vec2<D>, angle: D) -> Planar<D> {
        planar(self.point(origin), self.angle + angle)
    }
}

/// Where a spatial rigid body is: a point of it and its orientation (body frame → world frame).
/// The point is the centre of mass, unless the body is declared with `#[rigid_body(com = ..)]`:
/// then it is the origin of the body's frame (a joint frame, say), and the centre of mass lies at
/// `com` in that frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Spatial<D> {
    /// The centre of mass in the world frame, or the origin of the body's frame when its `com` is
    /// declared.
    pub position: Vec3<D>,
    /// The rotation from the body frame to the world frame: column k is the body's k-th axis in
    /// world coordinates (the axes the principal moments `inertia = [I1, I2, I3]`, or the rows and
    /// columns of a full tensor `inertia = [[..], [..], [..]]`, refer to).
    pub rotation: Rot3<D>,
}

/// The velocity of a spatial rigid body: the velocity of its position (the centre of mass, or the
/// frame's origin for a body declared with its `com`) and its angular velocity, both in the world
/// frame. What a spatial body's `body_dot` is in forces, velocity constraints and friction.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct SpatialVelocity<D> {
    /// The velocity of the body's position (`Spatial::position`).
    pub linear: Vec3<D>,
    /// The angular velocity ω (Ṙ = \[ω\]× R).
    pub angular: Vec3<D>,
}

/// The world-frame angular velocity of a rotation R from its columns rₖ and their rates ṙₖ:
/// Ṙ = \[ω\]× R gives ṙₖ = ω × rₖ, and Σₖ rₖ × (ω × rₖ) = Σₖ (ω |rₖ|² − rₖ (rₖ·ω)) = 3ω − ω, so
/// ω = ½ Σₖ rₖ × ṙₖ.
#[inline(always)]
pub fn angular_velocity<D: Scalar>(columns: [Vec3<D>; 3], rates: [Vec3<D>; 3]) -> Vec3<D> {
    let sum =
        columns[0].cross(&rates[0]) + columns[1].cross(&rates[1]) + columns[2].cross(&rates[2]);
    sum * D::from(0.5)
}

/// `spatial(centre_of_mass, rotation)` (or `spatial(frame_origin, rotation)` for a body declared
/// with its `com`).
#[inline(always)]
pub fn spatial<D>(position: Vec3<D>, rotation: Rot3<D>) -> Spatial<D> {
    Spatial { position, rotation }
}

impl<D: Scalar> Spatial<D> {
    /// The world position of a point fixed in the body at `offset` (body frame, from the body's
    /// position: its centre of mass, or the origin of its frame when its `com` is given).
    #[inline(always)]
    pub fn point(&self, offset: Vec3<D>) -> Vec3<D> {
        self.position + self.rotation * offset
    }

    /// A child's frame at the parent's point `origin`, turned by `rotation` relative to the parent
    /// (a robot file's joint origin followed by the joint's own rotation):
    /// `spatial(self.point(origin), self.rotation * rotation)`.
    ///
    /// ```
    /// use lagrange_core::geometry::{rot_y, rpy, spatial, vec3, Rot3};
    /// let base = spatial(vec3(0.0, 0.0, 0.3), Rot3::identity());
    /// let q = 0.4_f64;
    /// let link = base.joint(vec3(0.0, 0.1, 0.2), rpy(0.0, 0.0, 1.5) * rot_y(q));
    /// let written_out = spatial(
    ///     base.point(vec3(0.0, 0.1, 0.2)),
    ///     base.rotation * (rpy(0.0, 0.0, 1.5) * rot_y(q)),
    /// );
    /// assert_eq!(link, written_out);
    /// ```
    #[inline(always)]
    pub fn joint(&self, origin: Vec3<D>, rotation: Rot3<D>) -> Spatial<D> {
        spatial(self.point(origin), self.rotation * rotation)
    }
}

// Conversions to and from nalgebra's types, for f64 values (see the module docs).
mod nalgebra_interop {
    use super::{vec2, vec3, Rot3, Vec2, Vec3};
    use nalgebra::{Matrix3, Rotation3, Vector2, Vector3};

    impl From<Vec2<f64>> for Vector2<f64> {
        fn from(v: Vec2<f64>) -> Self {
            Vector2::new(v.x, v.y)
        }
    }

    impl From<Vector2<f64>> for Vec2<f64> {
        fn from(v: Vector2<f64>) -> Self {
            vec2(v.x, v.y)
        }
    }

    impl From<Vec3<f64>> for Vector3<f64> {
        fn from(v: Vec3<f64>) -> Self {
            Vector3::new(v.x, v.y, v.z)
        }
    }

    impl From<Vector3<f64>> for Vec3<f64> {
        fn from(v: Vector3<f64>) -> Self {
            vec3(v.x, v.y, v.z)
        }
    }

    impl From<Rot3<f64>> for Matrix3<f64> {
        fn from(r: Rot3<f64>) -> Self {
            let m = &r.rows;
            Matrix3::new(
                m[0][0], m[0][1], m[0][2], m[1][0], m[1][1], m[1][2], m[2][0], m[2][1], m[2][2],
            )
        }
    }

    impl From<Matrix3<f64>> for Rot3<f64> {
        fn from(m: Matrix3<f64>) -> Self {
            Rot3 {
                rows: [
                    [m[(0, 0)], m[(0, 1)], m[(0, 2)]],
                    [m[(1, 0)], m[(1, 1)], m[(1, 2)]],
                    [m[(2, 0)], m[(2, 1)], m[(2, 2)]],
                ],
            }
        }
    }

    impl From<Rotation3<f64>> for Rot3<f64> {
        fn from(r: Rotation3<f64>) -> Self {
            Rot3::from(*r.matrix())
        }
    }

    impl Rot3<f64> {
        /// This matrix as nalgebra's [`Rotation3`], if it is a rotation: RᵀR = I to within 1e-12
        /// in every entry and det R > 0. `None` otherwise (a `Rot3` may hold any 3×3 matrix, and
        /// `Rotation3` promises orthogonality to every user of it, so there is no unchecked `From`).
        pub fn to_rotation3(&self) -> Option<Rotation3<f64>> {
            let m = Matrix3::from(*self);
            if !m.iter().all(|e| e.is_finite()) {
                return None;
            }
            let orthogonal = (m.transpose() * m - Matrix3::identity()).amax() <= 1e-12;
            (orthogonal && m.determinant() > 0.0).then(|| Rotation3::from_matrix_unchecked(m))
        }
    }
}

#[cfg(test)]
mod tests;
