use super::super::inertia::Inertia;
use super::*;

/// A dense 6×6 from the blocks, for checking the structured routines against plain products.
fn dense(i: &Inertia<f64>) -> [[f64; 6]; 6] {
    let mut out = [[0.0; 6]; 6];
    for r in 0..3 {
        for c in 0..3 {
            out[r][c] = i.a.at(r, c);
            out[r][c + 3] = i.b[r][c];
            out[r + 3][c] = i.b[c][r];
            out[r + 3][c + 3] = i.c.at(r, c);
        }
    }
    out
}

/// The 6×6 motion transform X from P to C for rotation q and origin r (Featherstone eq. 2.24).
fn transform(q: &M3<f64>, r: V3<f64>) -> [[f64; 6]; 6] {
    let mut x = [[0.0; 6]; 6];
    let rx = [[0.0, -r[2], r[1]], [r[2], 0.0, -r[0]], [-r[1], r[0], 0.0]];
    for i in 0..3 {
        for j in 0..3 {
            let e = q[j][i]; // Qᵀ
            x[i][j] = e;
            x[i + 3][j + 3] = e;
            // −Qᵀ r×
            x[i + 3][j] = -(0..3).map(|k| q[k][i] * rx[k][j]).sum::<f64>();
        }
    }
    x
}

fn mat6_mul(a: &[[f64; 6]; 6], b: &[[f64; 6]; 6]) -> [[f64; 6]; 6] {
    let mut out = [[0.0; 6]; 6];
    for i in 0..6 {
        for j in 0..6 {
            out[i][j] = (0..6).map(|k| a[i][k] * b[k][j]).sum();
        }
    }
    out
}

fn transpose6(a: &[[f64; 6]; 6]) -> [[f64; 6]; 6] {
    let mut out = [[0.0; 6]; 6];
    for i in 0..6 {
        for j in 0..6 {
            out[i][j] = a[j][i];
        }
    }
    out
}

fn rotation(a: f64, b: f64, c: f64) -> M3<f64> {
    use crate::geometry::{rot_x, rot_y, rot_z};
    (rot_z(a) * rot_y(b) * rot_x(c)).rows
}

fn sample_inertia() -> Inertia<f64> {
    let body = RigidInertia::about_origin(
        2.0,
        [0.1, -0.3, 0.2],
        [[0.5, 0.02, -0.01], [0.02, 0.4, 0.03], [-0.01, 0.03, 0.3]],
    );
    let mut i = body.as_inertia::<f64>();
    // Make it a general articulated inertia: take out one rank-one term.
    let u = i.angular_column(Axis::Y);
    i.sub_outer(&u, 0.5 / u.moment[1]);
    i
}

#[test]
fn congruence_matches_the_dense_product() {
    let q = rotation(0.3, -0.7, 1.1);
    let r = [0.4, -0.2, 0.9];
    let i_c = sample_inertia();
    let mut i_p = i_c;
    i_p.rotate(&q);
    i_p.shift(r, [true; 3]);
    let x = transform(&q, r);
    let expected = mat6_mul(&transpose6(&x), &mat6_mul(&dense(&i_c), &x));
    let got = dense(&i_p);
    for i in 0..6 {
        for j in 0..6 {
            assert!((got[i][j] - expected[i][j]).abs() < 1e-14, "{i} {j}");
        }
    }
}

#[test]
fn a_joint_turn_is_the_rotation_about_its_axis() {
    let i_c = sample_inertia();
    for (axis, rot) in [
        (Axis::X, rotation(0.0, 0.0, 0.8)),
        (Axis::Y, rotation(0.0, 0.8, 0.0)),
        (Axis::Z, rotation(0.8, 0.0, 0.0)),
    ] {
        let mut turned = i_c;
        turned.turn(axis, (0.8f64.cos(), 0.8f64.sin()));
        let mut rotated = i_c;
        rotated.rotate(&rot);
        let (a, b) = (dense(&turned), dense(&rotated));
        for i in 0..6 {
            for j in 0..6 {
                assert!((a[i][j] - b[i][j]).abs() < 1e-15);
            }
        }
        let x = [0.3, -1.2, 0.7];
        let (t, r) = (turn(axis, (0.8f64.cos(), 0.8f64.sin()), x), mul3(&rot, x));
        let back = turn_back(axis, (0.8f64.cos(), 0.8f64.sin()), t);
        for k in 0..3 {
            assert!((t[k] - r[k]).abs() < 1e-15);
            assert!((back[k] - x[k]).abs() < 1e-15);
        }
    }
}

#[test]
fn a_rigid_inertia_applied_is_its_dense_product() {
    let body = RigidInertia::about_origin(
        1.5,
        [0.2, 0.1, -0.4],
        [[0.3, 0.01, 0.0], [0.01, 0.2, -0.02], [0.0, -0.02, 0.25]],
    );
    let m = Motion {
        angular: [0.3, -0.5, 0.8],
        linear: [1.0, 0.2, -0.7],
    };
    let (f, g) = (body.apply(&m), body.as_inertia::<f64>().apply(&m));
    for k in 0..3 {
        assert!((f.moment[k] - g.moment[k]).abs() < 1e-15);
        assert!((f.force[k] - g.force[k]).abs() < 1e-15);
    }
}

#[test]
fn axis_cross_products() {
    let x = [0.3, -1.2, 0.7];
    for (axis, e) in [
        (Axis::X, [1.0, 0.0, 0.0]),
        (Axis::Y, [0.0, 1.0, 0.0]),
        (Axis::Z, [0.0, 0.0, 1.0]),
    ] {
        let expected = cross(x, scale3(e, 2.5));
        assert_eq!(cross_axis(x, axis, 2.5), expected);
    }
}
