//! Scalars and the small geometric types positions are written with.
//!
//! Every position function of a mechanism is evaluated on several scalar types: `f64` for output,
//! a gradient dual number for Jacobians, a second-order dual number for the velocity-product and time
//! terms, and nested duals for the exact Jacobians of implicit integrators. [`Scalar`] is the one bound
//! all of them satisfy; [`Vec2`], [`Vec3`] and [`Rot3`] are generic over it.
//!
//! Arithmetic reads like the paper, with one Rust-imposed rule: a vector times a scalar is written
//! `v * s`, not `s * v` (a foreign scalar type cannot be the left operand of our vector).
//!
//! ```
//! use lagrange_core::geometry::{vec2, Vec2};
//! let (l, theta) = (2.0_f64, 0.3_f64);
//! let bob: Vec2<f64> = vec2(theta.sin(), -theta.cos()) * l;
//! assert!((bob.norm() - l).abs() < 1e-15);
//! ```

use num_dual::DualNum;
use std::ops::{Add, AddAssign, Mul, Neg, Sub, SubAssign};

/// A real number or a dual number over `f64`: what positions, potentials and the dynamics are
/// generic over.
pub trait Scalar: DualNum<Primitive = f64> + Copy {}
impl<T: DualNum<Primitive = f64> + Copy> Scalar for T {}

/// A vector in the plane.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Vec2<D> {
    pub x: D,
    pub y: D,
}

/// A vector in space.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Vec3<D> {
    pub x: D,
    pub y: D,
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
    /// The zero vector.
    #[inline(always)]
    pub fn zero() -> Self {
        vec2(D::zero(), D::zero())
    }
    /// Scalar product.
    #[inline(always)]
    pub fn dot(&self, other: &Self) -> D {
        self.x * other.x + self.y * other.y
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
    /// The components as an array.
    #[inline(always)]
    pub fn to_array(self) -> [D; 2] {
        [self.x, self.y]
    }
}

impl<D: Scalar> Vec3<D> {
    /// The zero vector.
    #[inline(always)]
    pub fn zero() -> Self {
        vec3(D::zero(), D::zero(), D::zero())
    }
    /// Scalar product.
    #[inline(always)]
    pub fn dot(&self, other: &Self) -> D {
        self.x * other.x + self.y * other.y + self.z * other.z
    }
    /// Vector product.
    #[inline(always)]
    pub fn cross(&self, o: &Self) -> Self {
        vec3(
            self.y * o.z - self.z * o.y,
            self.z * o.x - self.x * o.z,
            self.x * o.y - self.y * o.x,
        )
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
    pub fn to_array(self) -> [D; 3] {
        [self.x, self.y, self.z]
    }
}

macro_rules! vector_ops {
    ($V:ident { $($f:ident),+ }) => {
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
    };
}
vector_ops!(Vec2 { x, y });
vector_ops!(Vec3 { x, y, z });

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

/// Where a planar rigid body is: its centre of mass and its angle (counter-clockwise).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Planar<D> {
    pub position: Vec2<D>,
    pub angle: D,
}

/// `planar(centre_of_mass, angle)`.
#[inline(always)]
pub fn planar<D>(position: Vec2<D>, angle: D) -> Planar<D> {
    Planar { position, angle }
}

impl<D: Scalar> Planar<D> {
    /// The world position of a point fixed in the body at `offset` (body frame, from the centre of
    /// mass).
    #[inline(always)]
    pub fn point(&self, offset: Vec2<D>) -> Vec2<D> {
        self.position + offset.rotated(self.angle)
    }
}

/// Where a spatial rigid body is: its centre of mass and its orientation (body frame → world frame).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Spatial<D> {
    pub position: Vec3<D>,
    pub rotation: Rot3<D>,
}

/// `spatial(centre_of_mass, rotation)`.
#[inline(always)]
pub fn spatial<D>(position: Vec3<D>, rotation: Rot3<D>) -> Spatial<D> {
    Spatial { position, rotation }
}

impl<D: Scalar> Spatial<D> {
    /// The world position of a point fixed in the body at `offset` (body frame, from the centre of
    /// mass).
    #[inline(always)]
    pub fn point(&self, offset: Vec3<D>) -> Vec3<D> {
        self.position + self.rotation * offset
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rotations_are_orthogonal_and_compose() {
        let r = rot_z(0.3f64) * rot_x(-1.1) * rot_y(0.7);
        let p = r.transpose() * r;
        for i in 0..3 {
            for j in 0..3 {
                let expect = if i == j { 1.0 } else { 0.0 };
                assert!((p.rows[i][j] - expect).abs() < 1e-15);
            }
        }
        // rot_z(a) maps the x axis to (cos a, sin a, 0).
        let e = rot_z(0.4f64) * vec3(1.0, 0.0, 0.0);
        assert!((e.x - 0.4f64.cos()).abs() < 1e-16 && (e.y - 0.4f64.sin()).abs() < 1e-16);
    }

    #[test]
    fn planar_point_rotates_offset() {
        let b = planar(vec2(1.0f64, 2.0), std::f64::consts::FRAC_PI_2);
        let p = b.point(vec2(1.0, 0.0));
        assert!((p.x - 1.0).abs() < 1e-15 && (p.y - 3.0).abs() < 1e-15);
    }
}
