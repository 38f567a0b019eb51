//! A rigid body declared by its frame, and the constants a declaration writes that must be checked
//! once: a full inertia tensor, a rotation matrix, a rotation axis.
//!
//! `#[rigid_body(mass = m, com = c, inertia = [[ixx, ixy, ixz], [ixy, iyy, iyz], [ixz, iyz, izz]])]`
//! declares a body by the pose of its frame (r, R) — a joint frame, as a robot file gives it — with
//! the centre of mass at c in that frame and the inertia tensor I about the centre of mass in the
//! frame's axes. The Cartesian model ([`crate::model`]) takes a body by its centre of mass and its
//! principal axes. With I = V diag(I₁, I₂, I₃) Vᵀ, V a rotation whose columns are the principal axes
//! in the body frame ([`principal_axes`]), those are
//!
//! ```text
//! centre of mass  r + R c,        principal axes  the columns of R V,
//! ```
//!
//! and the frame is recovered from them as R = (R V) Vᵀ, r = (r + R c) − (R V)(Vᵀ c).
//! [`SpatialMassFrame`] and [`PlanarMassFrame`] map between the two, for positions and velocities.
//!
//! ```
//! use lagrange_core::geometry::{rot_z, spatial, vec3, Rot3};
//! use lagrange_core::inertia::{principal_axes, SpatialMassFrame};
//!
//! // A tensor with a product of inertia: its principal axes are turned about z.
//! let tensor = [[2.0, 0.5, 0.0], [0.5, 2.0, 0.0], [0.0, 0.0, 3.0]];
//! let (moments, axes) = principal_axes(&tensor);
//! let mut sorted = moments;
//! sorted.sort_by(f64::total_cmp);
//! assert!((sorted[0] - 1.5).abs() < 1e-14 && (sorted[1] - 2.5).abs() < 1e-14);
//!
//! let mass = SpatialMassFrame { com: Some(vec3(0.0, 0.0, 0.25)), axes: Some(axes) };
//! let frame = spatial(vec3(1.0, 0.0, 0.0), rot_z(0.3_f64));
//! let principal = mass.principal(frame);
//! assert_eq!(principal.position, frame.point(vec3(0.0, 0.0, 0.25)));
//! let back = mass.frame(principal);
//! assert!((back.position - frame.position).norm() < 1e-15);
//! ```

use crate::error::{Error, Result};
use crate::geometry::{planar, spatial, vec2, vec3, Planar, Rot3, Scalar, Spatial};
use crate::geometry::{SpatialVelocity, Vec2, Vec3};
use nalgebra::{Matrix3, SymmetricEigen};

/// Relative tolerance of the checks of constants written in a declaration: a tensor's symmetry
/// and its triangle inequality are compared to this times its size, a rotation's RᵀR to the
/// identity entry by entry. Round-off of constants written to 15 digits passes; a typo does not.
const SYMMETRY_TOLERANCE: f64 = 1e-12;
/// How far RᵀR of a `rot3` may be from the identity in any entry.
const ROTATION_TOLERANCE: f64 = 1e-9;

/// The principal moments of a symmetric 3×3 inertia tensor and its principal axes: the moments
/// I₁, I₂, I₃ and a rotation V whose column k is the axis of Iₖ, so that
/// `tensor = V diag(I₁, I₂, I₃) Vᵀ` to round-off. V is a proper rotation (det V = +1); the order
/// of the moments is the eigen-decomposition's own, the same on every call with the same tensor.
///
/// The symmetric part ½(I + Iᵀ) is decomposed (nalgebra's [`SymmetricEigen`]: Householder
/// tridiagonalisation and implicit QR). A tensor with a non-finite entry, or one the iteration does
/// not resolve, gives NaN moments and axes, which the checks of [`check_inertia_tensor`] refuse
/// before any evaluation.
pub fn principal_axes(tensor: &[[f64; 3]; 3]) -> ([f64; 3], Rot3<f64>) {
    let symmetric = Matrix3::from_fn(|i, j| 0.5 * (tensor[i][j] + tensor[j][i]));
    let finite = symmetric.iter().all(|e| e.is_finite());
    // 0 would iterate without bound; 1000 sweeps are far past what a 3×3 needs.
    let eigen = finite
        .then(|| SymmetricEigen::try_new(symmetric, f64::EPSILON, 1000))
        .flatten();
    let Some(eigen) = eigen else {
        let nan = f64::NAN;
        return (
            [nan; 3],
            Rot3 {
                rows: [[nan; 3]; 3],
            },
        );
    };
    let mut axes = eigen.eigenvectors;
    if axes.determinant() < 0.0 {
        // A reflection: the opposite of one axis is as much an eigenvector.
        axes.column_mut(2).neg_mut();
    }
    let m = eigen.eigenvalues;
    ([m[0], m[1], m[2]], Rot3::from(axes))
}

/// Checks a full inertia tensor about the centre of mass: every entry finite, symmetric (each
/// off-diagonal pair equal to 1e-12 of the largest entry), positive definite (every principal
/// moment positive), and its principal moments satisfy the triangle inequality Iₖ ≤ Iᵢ + Iⱼ (to
/// 1e-12 of their sum; equality is a flat body). Otherwise [`Error::InvalidInertia`] naming `body`.
///
/// ```
/// use lagrange_core::inertia::check_inertia_tensor;
/// assert!(check_inertia_tensor("link", &[[2.0, 0.1, 0.0], [0.1, 2.0, 0.0], [0.0, 0.0, 3.0]]).is_ok());
/// // Positive definite, but I₃ = 5 exceeds I₁ + I₂ = 2: no body has these moments.
/// let err = check_inertia_tensor("link", &[[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 5.0]]);
/// assert!(err.unwrap_err().to_string().contains("triangle inequality"));
/// ```
pub fn check_inertia_tensor(body: &'static str, tensor: &[[f64; 3]; 3]) -> Result<()> {
    let invalid = |reason: String| Err(Error::InvalidInertia { body, reason });
    if !tensor.iter().flatten().all(|e| e.is_finite()) {
        return invalid(format!(
            "inertia tensor {tensor:?} has an entry that is not finite"
        ));
    }
    let size = tensor.iter().flatten().fold(0.0_f64, |m, e| m.max(e.abs()));
    for (i, j) in [(0, 1), (0, 2), (1, 2)] {
        if (tensor[i][j] - tensor[j][i]).abs() > SYMMETRY_TOLERANCE * size {
            return invalid(format!(
                "inertia tensor {tensor:?} is not symmetric: entry ({i}, {j}) is {}, entry ({j}, {i}) is {}",
                tensor[i][j], tensor[j][i]
            ));
        }
    }
    let (moments, _) = principal_axes(tensor);
    if !moments.iter().all(|&m| m > 0.0) {
        return invalid(format!(
            "inertia tensor {tensor:?} is not positive definite: its principal moments are {moments:?}"
        ));
    }
    let sum: f64 = moments.iter().sum();
    for (k, &moment) in moments.iter().enumerate() {
        if moment > sum - moment + SYMMETRY_TOLERANCE * sum {
            return invalid(format!(
                "the principal moments {moments:?} of inertia tensor {tensor:?} violate the triangle inequality: I{} exceeds the sum of the other two",
                k + 1
            ));
        }
    }
    Ok(())
}

/// Checks a centre of mass offset `com` (its components): finite. Otherwise
/// [`Error::InvalidInertia`] naming `body`.
pub fn check_centre_of_mass(body: &'static str, com: &[f64]) -> Result<()> {
    match com.iter().all(|c| c.is_finite()) {
        true => Ok(()),
        false => Err(Error::InvalidInertia {
            body,
            reason: format!("centre of mass offset {com:?} is not finite"),
        }),
    }
}

/// Checks a matrix written with `rot3`: finite, orthonormal (every entry of RᵀR − I within 1e-9)
/// and det R > 0 (a rotation, not a reflection). Otherwise [`Error::InvalidRotation`] naming the
/// function `body` that writes it.
///
/// ```
/// use lagrange_core::geometry::{rot3, rpy};
/// use lagrange_core::inertia::check_rotation;
/// assert!(check_rotation("link", &rpy(0.1, 0.2, 0.3)).is_ok());
/// let mirror = rot3([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, -1.0]]);
/// assert!(check_rotation("link", &mirror).is_err());
/// ```
pub fn check_rotation(body: &'static str, rotation: &Rot3<f64>) -> Result<()> {
    let m = Matrix3::from(*rotation);
    let invalid = |why: &str| {
        Err(Error::InvalidRotation {
            body,
            reason: format!("rot3({:?}) is not a rotation: {why}", rotation.rows),
        })
    };
    if !m.iter().all(|e| e.is_finite()) {
        return invalid("an entry is not finite");
    }
    let deviation = (m.transpose() * m - Matrix3::identity()).amax();
    if deviation > ROTATION_TOLERANCE {
        return invalid(&format!(
            "its columns are not orthonormal (RᵀR − I has an entry of {deviation:e})"
        ));
    }
    if m.determinant() <= 0.0 {
        return invalid("its determinant is −1 (a reflection)");
    }
    Ok(())
}

/// Checks the axis of a `rot_axis` written from constants: finite and of non-zero length (it is
/// normalised where it is used). Otherwise [`Error::InvalidRotation`] naming the function `body`.
pub fn check_axis(body: &'static str, axis: &Vec3<f64>) -> Result<()> {
    let length = axis.norm();
    match length.is_finite() && length > 0.0 {
        true => Ok(()),
        false => Err(Error::InvalidRotation {
            body,
            reason: format!(
                "rot_axis about {:?} has no direction (length {length})",
                axis.to_array()
            ),
        }),
    }
}

/// `v` on the scalar `D`.
#[inline(always)]
fn lift3<D: Scalar>(v: Vec3<f64>) -> Vec3<D> {
    vec3(D::from(v.x), D::from(v.y), D::from(v.z))
}

/// Where a spatial body's mass lies in the frame its position function returns: what a
/// `#[rigid_body(com = .., inertia = [[..], [..], [..]])]` declares. `None` where the frame already
/// serves: no `com` (the frame's origin is the centre of mass), principal moments `[I1, I2, I3]`
/// (the frame's axes are principal).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpatialMassFrame {
    /// The centre of mass in the body frame.
    pub com: Option<Vec3<f64>>,
    /// The principal axes in the body frame: column k is the axis of the k-th principal moment of
    /// [`principal_axes`].
    pub axes: Option<Rot3<f64>>,
}

impl SpatialMassFrame {
    /// The centre of mass and principal axes (what the Cartesian model holds) of a body whose frame
    /// is at `frame`: `spatial(frame.point(com), frame.rotation * axes)`.
    #[inline(always)]
    pub fn principal<D: Scalar>(&self, frame: Spatial<D>) -> Spatial<D> {
        let position = match self.com {
            Some(c) => frame.point(lift3(c)),
            None => frame.position,
        };
        let rotation = match self.axes {
            Some(v) => frame.rotation * lift_rotation(v),
            None => frame.rotation,
        };
        spatial(position, rotation)
    }

    /// The body's frame from its centre of mass and principal axes: the inverse of
    /// [`principal`](Self::principal).
    #[inline(always)]
    pub fn frame<D: Scalar>(&self, principal: Spatial<D>) -> Spatial<D> {
        let rotation = match self.axes {
            Some(v) => principal.rotation * lift_rotation(v.transpose()),
            None => principal.rotation,
        };
        let position = match self.com_in_principal_axes() {
            Some(c) => principal.position - principal.rotation * lift3(c),
            None => principal.position,
        };
        spatial(position, rotation)
    }

    /// The velocity of the frame's origin and the angular velocity, from the centre of mass's
    /// `velocity` and the pose `principal` it is taken at: ṙ = ċ − ω × (R c), ω unchanged.
    #[inline(always)]
    pub fn frame_velocity<D: Scalar>(
        &self,
        principal: &Spatial<D>,
        velocity: SpatialVelocity<D>,
    ) -> SpatialVelocity<D> {
        match self.com_in_principal_axes() {
            Some(c) => {
                let offset = principal.rotation * lift3(c);
                SpatialVelocity {
                    linear: velocity.linear - velocity.angular.cross(&offset),
                    angular: velocity.angular,
                }
            }
            None => velocity,
        }
    }

    /// Vᵀ c: the centre of mass in the principal axes (so that R c = (R V)(Vᵀ c)).
    #[inline(always)]
    fn com_in_principal_axes(&self) -> Option<Vec3<f64>> {
        let c = self.com?;
        Some(match self.axes {
            Some(v) => v.transpose() * c,
            None => c,
        })
    }
}

/// `r` on the scalar `D`.
#[inline(always)]
fn lift_rotation<D: Scalar>(r: Rot3<f64>) -> Rot3<D> {
    Rot3 {
        rows: r.rows.map(|row| row.map(D::from)),
    }
}

/// Where a planar body's centre of mass lies in the frame its position function returns: what a
/// `#[rigid_body(com = vec2(..))]` declares.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlanarMassFrame {
    /// The centre of mass in the body frame.
    pub com: Vec2<f64>,
}

impl PlanarMassFrame {
    /// The centre of mass and the angle of a body whose frame is at `frame`:
    /// `planar(frame.point(com), frame.angle)`.
    #[inline(always)]
    pub fn principal<D: Scalar>(&self, frame: Planar<D>) -> Planar<D> {
        planar(frame.point(self.com_on()), frame.angle)
    }

    /// The body's frame from its centre of mass and angle: the inverse of
    /// [`principal`](Self::principal).
    #[inline(always)]
    pub fn frame<D: Scalar>(&self, principal: Planar<D>) -> Planar<D> {
        let offset = self.com_on().rotated(principal.angle);
        planar(principal.position - offset, principal.angle)
    }

    /// The velocity of the frame's origin and the angular velocity (as a `Planar`, like a planar
    /// body's `_dot`), from the centre of mass's `velocity` at the pose `principal`:
    /// ṙ = ċ − θ̇ ẑ × (R c), θ̇ unchanged.
    #[inline(always)]
    pub fn frame_velocity<D: Scalar>(
        &self,
        principal: &Planar<D>,
        velocity: Planar<D>,
    ) -> Planar<D> {
        let offset = self.com_on().rotated(principal.angle);
        let omega = velocity.angle;
        // ẑ × (x, y) = (−y, x).
        let swept: Vec2<D> = vec2(-offset.y, offset.x) * omega;
        planar(velocity.position - swept, omega)
    }

    #[inline(always)]
    fn com_on<D: Scalar>(&self) -> Vec2<D> {
        vec2(D::from(self.com.x), D::from(self.com.y))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::{rot_x, rot_y, rot_z};

    /// V diag(I) Vᵀ from the decomposition, entry by entry.
    fn reassembled(moments: [f64; 3], axes: Rot3<f64>) -> Matrix3<f64> {
        let v = Matrix3::from(axes);
        v * Matrix3::from_diagonal(&moments.into()) * v.transpose()
    }

    #[test]
    fn principal_axes_reassemble_the_tensor_and_form_a_rotation() {
        let v = Matrix3::from(rot_z(0.7) * rot_y(-1.1) * rot_x(2.0));
        let tensor = v * Matrix3::from_diagonal(&[0.3, 0.5, 0.6].into()) * v.transpose();
        let rows = std::array::from_fn(|i| std::array::from_fn(|j| tensor[(i, j)]));
        // A diagonal tensor, a tensor with a double moment (a symmetric top), a sphere.
        let cases = [
            rows,
            [[1.0, 0.0, 0.0], [0.0, 2.0, 0.0], [0.0, 0.0, 3.0]],
            [[2.0, 0.5, 0.0], [0.5, 2.0, 0.0], [0.0, 0.0, 1.5]],
            [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
        ];
        for tensor in cases {
            let (moments, axes) = principal_axes(&tensor);
            let back = reassembled(moments, axes);
            // Backward stable: V diag(I) Vᵀ within a small multiple of ε‖I‖ (measured: up to 9 ε,
            // the reassembly's own two products included).
            let size = tensor.iter().flatten().fold(0.0_f64, |m, e| m.max(e.abs()));
            for i in 0..3 {
                for j in 0..3 {
                    let error = (back[(i, j)] - tensor[i][j]).abs() / (f64::EPSILON * size);
                    assert!(error < 32.0, "{tensor:?}: {error} ε");
                }
            }
            assert!(axes.to_rotation3().is_some(), "{axes:?} is a rotation");
        }
    }

    #[test]
    fn a_tensor_that_is_not_finite_gives_nan_not_a_hang() {
        let (moments, axes) =
            principal_axes(&[[f64::NAN, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]);
        assert!(moments.iter().all(|m| m.is_nan()));
        assert!(axes.rows.iter().flatten().all(|e| e.is_nan()));
        assert!(check_inertia_tensor(
            "b",
            &[[f64::INFINITY, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
        )
        .is_err());
    }

    #[test]
    fn mass_frames_map_back_and_forth() {
        let (_, axes) = principal_axes(&[[2.0, 0.3, -0.1], [0.3, 2.5, 0.2], [-0.1, 0.2, 3.0]]);
        let mass = SpatialMassFrame {
            com: Some(vec3(0.1, -0.2, 0.3)),
            axes: Some(axes),
        };
        let frame = spatial(vec3(1.0, 2.0, 3.0), rot_z(0.4) * rot_x(-0.9));
        let principal = mass.principal(frame);
        let back = mass.frame(principal);
        assert!((back.position - frame.position).norm() < 1e-15);
        let deviation = Matrix3::from(back.rotation) - Matrix3::from(frame.rotation);
        assert!(deviation.amax() < 1e-15);
        // The frame's origin moves as ċ − ω × (R c).
        let omega = vec3(0.3, -1.0, 2.0);
        let centre = vec3(0.5, 0.0, -0.25);
        let velocity = mass.frame_velocity(
            &principal,
            SpatialVelocity {
                linear: centre,
                angular: omega,
            },
        );
        let expected = centre - omega.cross(&(frame.rotation * vec3(0.1, -0.2, 0.3)));
        assert!((velocity.linear - expected).norm() < 1e-15);
        assert_eq!(velocity.angular, omega);

        let planar_mass = PlanarMassFrame {
            com: vec2(0.4, 0.1),
        };
        let frame = planar(vec2(1.0, -1.0), 0.8);
        let principal = planar_mass.principal(frame);
        assert_eq!(principal.position, frame.point(vec2(0.4, 0.1)));
        let back = planar_mass.frame(principal);
        assert!((back.position - frame.position).norm() < 1e-15);
        // ẑ × (R c) with θ̇ = 2: the centre's velocity less that is the origin's.
        let velocity = planar_mass.frame_velocity(&principal, planar(vec2(0.0, 0.0), 2.0));
        let offset = vec2(0.4, 0.1).rotated(0.8);
        assert!((velocity.position - vec2(2.0 * offset.y, -2.0 * offset.x)).norm() < 1e-15);
    }
}
