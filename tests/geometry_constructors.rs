//! The rotation constructors a robot file is written with — `rpy`, `rot_axis`, `rot3` — and the
//! joint placements `Spatial::joint`, `Planar::joint`, each against a hand computation: matrices
//! whose entries are 0 and ±1 (quarter turns, the turn by 2π/3 about the diagonal), a column
//! worked out by hand, and the expansions the methods are defined by.

use lagrange::prelude::*;
use num_dual::Dual64;
use std::f64::consts::{FRAC_PI_2, PI};

/// Every entry of `a` within `tol` of `b`'s.
fn assert_matrix(a: Rot3<f64>, b: [[f64; 3]; 3], tol: f64) {
    for (row, expected) in a.rows.iter().zip(b) {
        for (x, y) in row.iter().zip(expected) {
            assert!((x - y).abs() <= tol, "{:?} vs {b:?}", a.rows);
        }
    }
}

/// The quarter turns are exact up to cos(π/2) ≈ 6e-17 in the entries that should be 0.
const QUARTER: f64 = 1e-15;

#[test]
fn rpy_rolls_then_pitches_then_yaws_about_fixed_axes() {
    // Roll alone, pitch alone, yaw alone are the elementary rotations.
    assert_matrix(
        rpy(FRAC_PI_2, 0.0, 0.0),
        [[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]],
        QUARTER,
    );
    assert_matrix(
        rpy(0.0, FRAC_PI_2, 0.0),
        [[0.0, 0.0, 1.0], [0.0, 1.0, 0.0], [-1.0, 0.0, 0.0]],
        QUARTER,
    );
    assert_matrix(
        rpy(0.0, 0.0, FRAC_PI_2),
        [[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]],
        QUARTER,
    );
    // Roll by π/2 about x, then pitch by π/2 about the fixed y: the body's x axis goes to −z
    // (x stays, then x → −z), its y axis to +x (y → z, then z → x), its z axis to −y
    // (z → −y, which the pitch leaves). Ry(π/2)·Rx(π/2) by hand: columns (0, 0, −1), (1, 0, 0),
    // (0, −1, 0). The other order, Rx·Ry, would send x to +y.
    assert_matrix(
        rpy(FRAC_PI_2, FRAC_PI_2, 0.0),
        [[0.0, 1.0, 0.0], [0.0, 0.0, -1.0], [-1.0, 0.0, 0.0]],
        QUARTER,
    );
    // The image of the body's x axis for any angles, by hand: Rz(y)Ry(p)Rx(r) e_x = Rz(y)Ry(p) e_x
    // = Rz(y) (cos p, 0, −sin p) = (cos y cos p, sin y cos p, −sin p).
    let (r, p, y) = (0.7, -0.4, 2.9);
    let x_axis = rpy(r, p, y) * vec3(1.0, 0.0, 0.0);
    let hand = [y.cos() * p.cos(), y.sin() * p.cos(), -p.sin()];
    for (a, b) in x_axis.to_array().iter().zip(hand) {
        assert!((a - b).abs() < 1e-15);
    }
}

#[test]
fn rot_axis_turns_right_handed_about_the_normalised_axis() {
    // About a coordinate axis, the elementary rotations (any length of axis, any sign of angle).
    for angle in [0.3, -2.1, PI] {
        let same = |a: Rot3<f64>, b: Rot3<f64>| assert_matrix(a, b.rows, 1e-15);
        same(rot_axis(vec3(3.0, 0.0, 0.0), angle), rot_x(angle));
        same(rot_axis(vec3(0.0, 0.5, 0.0), angle), rot_y(angle));
        same(rot_axis(vec3(0.0, 0.0, 1.0), angle), rot_z(angle));
        // About −z by θ is about z by −θ.
        same(rot_axis(vec3(0.0, 0.0, -1.0), angle), rot_z(-angle));
    }
    // A third of a turn about the diagonal (1, 1, 1) cycles the axes x → y → z → x: columns
    // e_y, e_z, e_x. By Rodrigues with k = (1,1,1)/√3, cos = −½, sin = √3/2: the diagonal is
    // −½ + (3/2)(1/3) = 0, the entry (1, 0) is (3/2)(1/3) + (√3/2)(1/√3) = 1.
    assert_matrix(
        rot_axis(vec3(2.0, 2.0, 2.0), 2.0 * PI / 3.0),
        [[0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]],
        1e-15,
    );
    // On dual numbers: dR/dθ = [k]× R (here k = e_z, so the derivative of rot_z).
    let r = rot_axis(vec3(0.0, 0.0, 1.0).map_dual(), Dual64::new(0.4, 1.0));
    let (s, c) = 0.4_f64.sin_cos();
    let derivative = [[-s, -c, 0.0], [c, -s, 0.0], [0.0, 0.0, 0.0]];
    for (row, expected) in r.rows.iter().zip(derivative) {
        for (x, d) in row.iter().zip(expected) {
            assert!((x.eps - d).abs() < 1e-15);
        }
    }
}

#[test]
fn rot3_takes_rows() {
    // Rows as written: column j is the image of the j-th axis.
    let r = rot3([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]);
    assert_eq!(r * vec3(1.0, 0.0, 0.0), vec3(0.0, 1.0, 0.0));
    assert_eq!(r * vec3(0.0, 1.0, 0.0), vec3(-1.0, 0.0, 0.0));
    assert_eq!(r.rows[0][1], -1.0);
    assert_matrix(r, rot_z(FRAC_PI_2).rows, QUARTER);
}

#[test]
fn joints_are_their_expansions() {
    let base = spatial(vec3(0.2, -0.1, 0.5), rpy(0.1, 0.2, 0.3));
    let q = 0.8;
    let turn = rpy(0.0, 0.0, FRAC_PI_2) * rot_y(q);
    let link = base.joint(vec3(0.0, 0.3, 0.1), turn);
    assert_eq!(
        link.position,
        base.position + base.rotation * vec3(0.0, 0.3, 0.1)
    );
    assert_eq!(link.rotation, base.rotation * turn);
    // A joint at the origin without a turn is the parent's frame.
    let same = base.joint(vec3(0.0, 0.0, 0.0), Rot3::identity());
    assert_eq!(same.position, base.position);
    assert_matrix(same.rotation, base.rotation.rows, 1e-16);

    // In the plane: the elbow of a two-link arm, by hand. The upper arm at angle π/2 from the
    // origin, its frame's x axis pointing up; the joint 0.5 along it is at (0, 0.5), and the
    // lower arm's angle is π/2 + 0.3.
    let upper = planar(vec2(0.0, 0.0), FRAC_PI_2);
    let lower = upper.joint(vec2(0.5, 0.0), 0.3);
    assert!((lower.position.x).abs() < 1e-16 && (lower.position.y - 0.5).abs() < 1e-16);
    assert_eq!(lower.angle, FRAC_PI_2 + 0.3);
    assert_eq!(
        lower,
        planar(upper.point(vec2(0.5, 0.0)), upper.angle + 0.3)
    );
}

/// `v` on dual numbers with zero derivative.
trait MapDual {
    fn map_dual(self) -> Vec3<Dual64>;
}

impl MapDual for Vec3<f64> {
    fn map_dual(self) -> Vec3<Dual64> {
        vec3(self.x.into(), self.y.into(), self.z.into())
    }
}
