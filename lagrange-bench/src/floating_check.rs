//! q̈ of floating-base robots against Pinocchio's (`scripts/peers/floating.sh`): the states and
//! Pinocchio's free-flyer accelerations that `scripts/peers/floating.py` wrote, converted to the
//! declaration's coordinates — base position, modified Rodrigues parameters σ of the base's
//! rotation, joints — and its q̈ converted back to Pinocchio's: the base's linear and angular
//! acceleration in the base frame. Exits 2 when an entry differs by more than 1e-10 (relative to
//! 1 + |Pinocchio's|).
//!
//! `floating-check ROBOT STATES` (ROBOT: `quadruped`, or `solo12` with the `example-robot-data`
//! feature).

use lagrange::geometry::{chart_rates, RotationChart};
use lagrange::prelude::*;
use num_dual::Dual2_64;

/// The tests' quadruped (12 joints) with a free-flying root.
#[lagrange::urdf("../tests/urdf/quadruped.urdf", floating)]
pub mod quadruped {}

/// Solo12 (the file `example_robots.py` prepares) with a free-flying root.
#[cfg(feature = "example-robot-data")]
#[lagrange::urdf("robots/example-robot-data/solo12.urdf", floating)]
pub mod solo12 {}

/// The skew part of Rᵀ R̈ as a vector, from R's values and its second derivatives.
fn skew_vee(value: &Rot3<f64>, derivative: &Rot3<f64>) -> [f64; 3] {
    let m = |i: usize, j: usize| {
        (0..3)
            .map(|k| value.rows[k][i] * derivative.rows[k][j])
            .sum::<f64>()
    };
    let skew = |i: usize, j: usize| -> f64 { (m(i, j) - m(j, i)) / 2.0 };
    [skew(2, 1), skew(0, 2), skew(1, 0)]
}

/// The body-frame angular acceleration along σ(t) = σ + σ̇ t + σ̈ t²/2: ω̇ = vee(RᵀR̈), ṘᵀṘ being
/// symmetric.
fn angular_acceleration(sigma: [f64; 3], rate: [f64; 3], acc: [f64; 3]) -> [f64; 3] {
    let d = |k: usize| Dual2_64::new(sigma[k], rate[k], acc[k]);
    let r = rot_mrp(vec3(d(0), d(1), d(2)));
    let re = Rot3 {
        rows: r.rows.map(|row| row.map(|x| x.re)),
    };
    let second = Rot3 {
        rows: r.rows.map(|row| row.map(|x| x.v2)),
    };
    skew_vee(&re, &second)
}

/// The rotation of a unit quaternion (x, y, z, w).
fn quaternion_rotation([x, y, z, w]: [f64; 4]) -> Rot3<f64> {
    Rot3 {
        rows: [
            [
                1.0 - 2.0 * (y * y + z * z),
                2.0 * (x * y - z * w),
                2.0 * (x * z + y * w),
            ],
            [
                2.0 * (x * y + z * w),
                1.0 - 2.0 * (x * x + z * z),
                2.0 * (y * z - x * w),
            ],
            [
                2.0 * (x * z - y * w),
                2.0 * (y * z + x * w),
                1.0 - 2.0 * (x * x + y * y),
            ],
        ],
    }
}

/// A joint's name as the macro makes it an identifier.
fn identifier(name: &str) -> String {
    let s = name.chars();
    s.map(|c| {
        if c.is_ascii_alphanumeric() {
            c.to_ascii_lowercase()
        } else {
            '_'
        }
    })
    .collect()
}

/// The largest difference of q̈ from Pinocchio's over the file's states, relative to
/// 1 + |Pinocchio's|.
fn check<M: Mechanism<N>, const N: usize>(sys: &M, path: &str) -> f64 {
    let text = std::fs::read_to_string(path).expect("the states file");
    let mut lines = text.lines();
    let header: Vec<&str> = lines
        .next()
        .expect("a header")
        .split('\t')
        .skip(1)
        .collect();
    let names = <M::Coords as Coordinates<N>>::NAMES;
    let ours: Vec<usize> = header
        .iter()
        .map(|n| {
            names
                .iter()
                .position(|m| *m == identifier(n))
                .expect("a joint of ours")
        })
        .collect();
    let nj = header.len();
    assert_eq!(N, 6 + nj, "the same joints");
    let mut worst = 0.0f64;
    for line in lines {
        let x: Vec<f64> = line.split('\t').map(|v| v.parse().unwrap()).collect();
        let (q, v, a) = (&x[..7 + nj], &x[7 + nj..13 + 2 * nj], &x[13 + 2 * nj..]);
        let quaternion = [q[3], q[4], q[5], q[6]];
        let r = quaternion_rotation(quaternion);
        // σ = (x, y, z)/(1 + w), in the chart's ball for w ≥ 0; R(σ) must be the quaternion's.
        let sigma = [0, 1, 2].map(|k| quaternion[k] / (1.0 + quaternion[3]));
        let r_sigma = rot_mrp(vec3(sigma[0], sigma[1], sigma[2]));
        for (row, other) in r.rows.iter().zip(r_sigma.rows) {
            assert!(row.iter().zip(other).all(|(a, b)| (a - b).abs() < 1e-13));
        }
        let (linear, omega) = ([v[0], v[1], v[2]], [v[3], v[4], v[5]]);
        let world = r * vec3(linear[0], linear[1], linear[2]);
        let rates = chart_rates(RotationChart::Mrp, sigma, omega).expect("σ in the chart's ball");
        let (mut qs, mut vs) = ([0.0; N], [0.0; N]);
        qs[..3].copy_from_slice(&q[..3]);
        qs[3..6].copy_from_slice(&sigma);
        vs[..3].copy_from_slice(&[world.x, world.y, world.z]);
        vs[3..6].copy_from_slice(&rates);
        for (k, &i) in ours.iter().enumerate() {
            (qs[i], vs[i]) = (q[7 + k], v[6 + k]);
        }
        let state = State::new(
            0.0,
            Coordinates::from_array(qs),
            Coordinates::from_array(vs),
        );
        let qdd = sys.accelerations(&state).expect("q̈").to_array();
        // Pinocchio's base acceleration: the derivative of the base-frame velocity,
        // Rᵀ p̈ − ω × v for the linear part, ω̇ for the angular.
        let body = r.transpose() * vec3(qdd[0], qdd[1], qdd[2]);
        let w = vec3(omega[0], omega[1], omega[2]);
        let coriolis = w.cross(&vec3(linear[0], linear[1], linear[2]));
        let rotational = angular_acceleration(sigma, rates, [qdd[3], qdd[4], qdd[5]]);
        let mut mine = vec![
            body.x - coriolis.x,
            body.y - coriolis.y,
            body.z - coriolis.z,
        ];
        mine.extend(rotational);
        mine.extend(ours.iter().map(|&i| qdd[i]));
        for (m, p) in mine.iter().zip(a) {
            worst = worst.max((m - p).abs() / (1.0 + p.abs()));
        }
    }
    worst
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let (robot, path) = (args[1].as_str(), args[2].as_str());
    let worst = match robot {
        "quadruped" => check(&quadruped::Quadruped::default(), path),
        #[cfg(feature = "example-robot-data")]
        "solo12" => check(&solo12::Solo12::default(), path),
        _ => panic!("unknown robot {robot}"),
    };
    println!("{robot}: max |q̈ − Pinocchio's| / (1 + |Pinocchio's|) = {worst:.1e}");
    if worst > 1e-10 {
        std::process::exit(2);
    }
}
