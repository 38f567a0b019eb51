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

#[test]
fn nalgebra_vectors_round_trip_component_by_component() {
    use nalgebra::{Vector2, Vector3};
    let v = vec2(1.5f64, -2.25);
    let n: Vector2<f64> = v.into();
    assert_eq!((n.x, n.y), (1.5, -2.25));
    assert_eq!(Vec2::from(n), v);
    let w = vec3(0.1f64, -0.2, 0.3);
    let n: Vector3<f64> = w.into();
    assert_eq!((n.x, n.y, n.z), (0.1, -0.2, 0.3));
    assert_eq!(Vec3::from(n), w);
    // Arithmetic agrees on both sides.
    let u = vec3(-1.0f64, 4.0, 2.0);
    assert_eq!(
        Vec3::from(Vector3::from(w).cross(&Vector3::from(u))),
        w.cross(&u)
    );
}

#[test]
fn nalgebra_matrices_keep_rows_and_columns() {
    use nalgebra::{Matrix3, Rotation3, Vector3};
    let r = Rot3 {
        rows: [[1.0f64, 2.0, 3.0], [4.0, 5.0, 6.0], [7.0, 8.0, 9.0]],
    };
    let m: Matrix3<f64> = r.into();
    // Row 0, column 2 on both sides (a transposed conversion would give 7).
    assert_eq!(m[(0, 2)], 3.0);
    assert_eq!(Rot3::from(m), r);
    let x = vec3(0.5f64, -1.0, 2.0);
    assert_eq!(Vec3::from(m * Vector3::from(x)), r * x);
    // nalgebra's rotation about z by a maps x to (cos a, sin a, 0), as rot_z does.
    let a = 0.7f64;
    let nz = Rotation3::from_axis_angle(&Vector3::z_axis(), a);
    let ours = Rot3::from(nz);
    let mine = rot_z(a);
    for i in 0..3 {
        for j in 0..3 {
            assert!((ours.rows[i][j] - mine.rows[i][j]).abs() < 1e-15);
        }
    }
}

#[test]
fn only_rotations_become_rotation3() {
    let r = rot_z(0.3f64) * rot_x(-1.1) * rot_y(0.7);
    let rot = r
        .to_rotation3()
        .expect("a product of rotations is a rotation");
    assert_eq!(Rot3::from(rot), r);
    let reflection = Rot3 {
        rows: [[-1.0f64, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
    };
    assert!(reflection.to_rotation3().is_none(), "det = -1");
    let scaled = Rot3 {
        rows: [[2.0f64, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
    };
    assert!(scaled.to_rotation3().is_none(), "not orthogonal");
    let mut nan = Rot3::<f64>::identity();
    nan.rows[1][1] = f64::NAN;
    assert!(nan.to_rotation3().is_none(), "NaN entries");
}
