//! The constant geometry the macro computes from a file's numbers: rotations, rigid transforms
//! and the inertia of links welded together by fixed joints, in plain `f64` (3×3 matrices by rows).

use super::parse::Origin;

pub type Mat3 = [[f64; 3]; 3];
pub type Vec3 = [f64; 3];

pub const IDENTITY: Mat3 = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];

/// Rz(yaw)·Ry(pitch)·Rx(roll), URDF's convention for `rpy`.
pub fn rpy(r: Vec3) -> Mat3 {
    let (sr, cr) = r[0].sin_cos();
    let (sp, cp) = r[1].sin_cos();
    let (sy, cy) = r[2].sin_cos();
    [
        [cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
        [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
        [-sp, cp * sr, cp * cr],
    ]
}

pub fn mul(a: &Mat3, b: &Mat3) -> Mat3 {
    std::array::from_fn(|i| std::array::from_fn(|j| (0..3).map(|k| a[i][k] * b[k][j]).sum()))
}

pub fn transpose(a: &Mat3) -> Mat3 {
    std::array::from_fn(|i| std::array::from_fn(|j| a[j][i]))
}

pub fn apply(a: &Mat3, v: &Vec3) -> Vec3 {
    std::array::from_fn(|i| (0..3).map(|k| a[i][k] * v[k]).sum())
}

/// A rigid transform: a frame at `position` with axes `rotation`, both in the frame it is
/// measured from.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Transform {
    pub rotation: Mat3,
    pub position: Vec3,
}

impl Transform {
    pub const IDENTITY: Transform = Transform {
        rotation: IDENTITY,
        position: [0.0; 3],
    };

    pub fn of(origin: &Origin) -> Transform {
        Transform {
            rotation: rpy(origin.rpy),
            position: origin.xyz,
        }
    }

    /// `self` followed by `next` (next measured in self's frame).
    pub fn then(&self, next: &Transform) -> Transform {
        let moved = apply(&self.rotation, &next.position);
        Transform {
            rotation: mul(&self.rotation, &next.rotation),
            position: std::array::from_fn(|i| self.position[i] + moved[i]),
        }
    }
}

/// The unit axis and the angle of the turn that maps z to the unit vector `a` (not ±z): about
/// z × a, by the angle between them.
pub fn turn_z_to(a: Vec3) -> (Vec3, f64) {
    let u = cross([0.0, 0.0, 1.0], a);
    let n = norm(u);
    (u.map(|c| c / n), n.atan2(a[2]))
}

pub fn norm(v: Vec3) -> f64 {
    (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt()
}

fn cross(a: Vec3, b: Vec3) -> Vec3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// A mass with its centre and its inertia tensor about the centre, in one frame.
#[derive(Clone, Copy, Debug)]
pub struct MassPart {
    pub mass: f64,
    pub centre: Vec3,
    pub inertia: Mat3,
}

impl MassPart {
    /// The part seen from a frame in which its own frame sits at `t`: centre t.p + t.R c, tensor
    /// t.R I t.Rᵀ (made exactly symmetric: rounding leaves it so only to ~1e-16).
    pub fn moved(&self, t: &Transform) -> MassPart {
        let c = apply(&t.rotation, &self.centre);
        let i = mul(&mul(&t.rotation, &self.inertia), &transpose(&t.rotation));
        MassPart {
            mass: self.mass,
            centre: std::array::from_fn(|k| t.position[k] + c[k]),
            inertia: std::array::from_fn(|r| std::array::from_fn(|s| 0.5 * (i[r][s] + i[s][r]))),
        }
    }
}

/// Parts welded into one body: total mass, centre of mass, and the tensor about it by the
/// parallel-axis theorem, I = Σₖ [Iₖ + mₖ(|dₖ|² E − dₖ dₖᵀ)], dₖ = cₖ − c (Featherstone, *Rigid
/// Body Dynamics Algorithms*, 2008, §2.13). One part is returned as it is.
pub fn combine(parts: &[MassPart]) -> Option<MassPart> {
    match parts {
        [] => None,
        [one] => Some(*one),
        _ => {
            let mass: f64 = parts.iter().map(|p| p.mass).sum();
            let centre: Vec3 = std::array::from_fn(|i| {
                parts.iter().map(|p| p.mass * p.centre[i]).sum::<f64>() / mass
            });
            let mut inertia = [[0.0; 3]; 3];
            for p in parts {
                let d: Vec3 = std::array::from_fn(|i| p.centre[i] - centre[i]);
                let dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
                for i in 0..3 {
                    for j in 0..3 {
                        let e = if i == j { dd } else { 0.0 };
                        inertia[i][j] += p.inertia[i][j] + p.mass * (e - d[i] * d[j]);
                    }
                }
            }
            Some(MassPart {
                mass,
                centre,
                inertia,
            })
        }
    }
}
