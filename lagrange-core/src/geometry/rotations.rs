//! The rotations a robot file is written with: roll, pitch and yaw ([`rpy`]), a turn about an
//! axis ([`rot_axis`]), a matrix by its rows ([`rot3`]).

use super::{Rot3, Scalar, Vec3};

/// The rotation of a robot file's roll, pitch and yaw: Rz(yaw)·Ry(pitch)·Rx(roll), a turn by
/// `roll` about the x axis, then by `pitch` about the (fixed) y axis, then by `yaw` about the
/// (fixed) z axis.
///
/// This is the convention of the URDF specification's `<origin xyz=".." rpy=".."/>` element of a
/// joint or link ("represents the rotation around fixed axis: first roll around x, then pitch around
/// y and finally yaw around z"; ROS URDF XML specification, `joint` element,
/// <http://wiki.ros.org/urdf/XML/joint>).
///
/// ```
/// use lagrange_core::geometry::{rot_x, rot_y, rot_z, rpy};
/// let (roll, pitch, yaw) = (0.1_f64, -0.4, 1.3);
/// let r = rpy(roll, pitch, yaw);
/// let product = rot_z(yaw) * rot_y(pitch) * rot_x(roll);
/// for (row, expected) in r.rows.iter().zip(product.rows) {
///     for (a, b) in row.iter().zip(expected) {
///         assert!((a - b).abs() < 1e-15);
///     }
/// }
/// ```
pub fn rpy<D: Scalar>(roll: D, pitch: D, yaw: D) -> Rot3<D> {
    let (sr, cr) = roll.sin_cos();
    let (sp, cp) = pitch.sin_cos();
    let (sy, cy) = yaw.sin_cos();
    // Rz(y)·Ry(p)·Rx(r) multiplied out.
    Rot3 {
        rows: [
            [cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
            [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
            [-sp, cp * sr, cp * cr],
        ],
    }
}

/// Rotation by `angle` (right-handed) about the direction of `axis`, by Rodrigues' formula
/// R = cos θ I + sin θ \[k\]× + (1 − cos θ) k kᵀ with k = axis/|axis| (Murray, Li & Sastry,
/// *A Mathematical Introduction to Robotic Manipulation*, 1994, eq. (2.14)).
///
/// The axis is normalised, so any non-zero vector along it may be given (a robot file's
/// `<axis xyz="0 0.7071 0.7071"/>` as written). In a declaration, an axis written from literals
/// and parameters that has no direction (zero length, or not finite) is refused when the mechanism
/// is validated (`Error::InvalidRotation` naming the function); an axis that depends on the state
/// is used as it comes, and a zero one makes the equations of motion non-finite.
///
/// ```
/// use lagrange_core::geometry::{rot_axis, rot_y, vec3};
/// let r = rot_axis(vec3(0.0, 2.0, 0.0), 0.7_f64);
/// for (row, expected) in r.rows.iter().zip(rot_y(0.7).rows) {
///     for (a, b) in row.iter().zip(expected) {
///         assert!((a - b).abs() < 1e-15);
///     }
/// }
/// ```
pub fn rot_axis<D: Scalar>(axis: Vec3<D>, angle: D) -> Rot3<D> {
    let k = axis / axis.norm();
    let (s, c) = angle.sin_cos();
    let c1 = D::one() - c;
    let (x, y, z) = (k.x, k.y, k.z);
    Rot3 {
        rows: [
            [c + c1 * x * x, c1 * x * y - s * z, c1 * x * z + s * y],
            [c1 * y * x + s * z, c + c1 * y * y, c1 * y * z - s * x],
            [c1 * z * x - s * y, c1 * z * y + s * x, c + c1 * z * z],
        ],
    }
}

/// A rotation from its rows: `rot3([[r00, r01, r02], [r10, r11, r12], [r20, r21, r22]])`, entry
/// (i, j) in row i, column j (column j is the image of the body's j-th axis).
///
/// In a declaration, a matrix written from literals and parameters must be a rotation —
/// orthonormal to 1e-9 in every entry of RᵀR − I, and det R = +1 — or the mechanism is refused
/// when it is validated (`Error::InvalidRotation` naming the function). A matrix whose entries
/// depend on the state is used as it comes.
///
/// ```
/// use lagrange_core::geometry::{rot3, rot_z};
/// let c = std::f64::consts::FRAC_1_SQRT_2;
/// assert_eq!(rot3([[c, -c, 0.0], [c, c, 0.0], [0.0, 0.0, 1.0]]).rows[1][0], c);
/// let quarter = rot_z(std::f64::consts::FRAC_PI_4);
/// assert!((quarter.rows[0][1] + c).abs() < 1e-15);
/// ```
#[inline(always)]
pub fn rot3<D>(rows: [[D; 3]; 3]) -> Rot3<D> {
    Rot3 { rows }
}
