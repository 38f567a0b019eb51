//! The cost of a free body's orientation, per `accelerations` call and per RK4 step: the same
//! torque-free body (moments 1, 2, 3) with its orientation written as the rotation vector
//! (`rot_vector`), as modified Rodrigues parameters (`rot_mrp`) and as z-x-z Euler angles (the
//! chart with a singularity, for reference); and a quadruped's q̈ with a floating base and with its
//! root fixed. `charts MODE CALLS`; count.sh takes the difference of
//! two call counts under callgrind (`BIN=charts MODES="vector mrp euler vector_step mrp_step
//! euler_step" scripts/callgrind/count.sh`).

use lagrange::prelude::*;
use std::hint::black_box;

#[mechanism]
pub mod by_vector {
    pub struct Coords {
        pub a: f64,
        pub b: f64,
        pub c: f64,
    }
    pub struct Body {
        pub i1: f64,
        pub i2: f64,
        pub i3: f64,
    }
    #[rigid_body(mass = 1.0, inertia = [i1, i2, i3])]
    fn body() -> Spatial {
        spatial(vec3(0.0, 0.0, 0.0), rot_vector(vec3(a, b, c)))
    }
}

#[mechanism]
pub mod by_mrp {
    pub struct Coords {
        pub a: f64,
        pub b: f64,
        pub c: f64,
    }
    pub struct Body {
        pub i1: f64,
        pub i2: f64,
        pub i3: f64,
    }
    #[rigid_body(mass = 1.0, inertia = [i1, i2, i3])]
    fn body() -> Spatial {
        spatial(vec3(0.0, 0.0, 0.0), rot_mrp(vec3(a, b, c)))
    }
}

#[mechanism]
pub mod by_euler {
    pub struct Coords {
        pub a: f64,
        pub b: f64,
        pub c: f64,
    }
    pub struct Body {
        pub i1: f64,
        pub i2: f64,
        pub i3: f64,
    }
    #[rigid_body(mass = 1.0, inertia = [i1, i2, i3])]
    fn body() -> Spatial {
        spatial(vec3(0.0, 0.0, 0.0), rot_z(a) * rot_x(b) * rot_z(c))
    }
}

/// The tests' quadruped with its root link flying free (18 coordinates: the rigid tree pass, its
/// root a free joint), and the same file with its root fixed to the ground (12: the rigid tree pass).
#[lagrange::urdf("../../tests/urdf/quadruped.urdf", floating)]
pub mod floating_quadruped {}
#[lagrange::urdf("../../tests/urdf/quadruped.urdf")]
pub mod fixed_quadruped {}

/// q̈ of a quadruped at a bent, moving state.
fn quadruped<M: Mechanism<N>, const N: usize>(sys: &M, calls: usize) -> f64 {
    let q = std::array::from_fn(|k| 0.3 * ((k as f64) * 0.7).sin());
    let v = std::array::from_fn(|k| 0.5 * ((k as f64) * 1.3).cos());
    let s = State::new(0.0, Coordinates::from_array(q), Coordinates::from_array(v));
    let mut sum = 0.0;
    for _ in 0..calls {
        sum += sys.accelerations(black_box(&s)).unwrap().to_array()[N - 1];
    }
    sum
}

macro_rules! run {
    ($m:ident, $calls:expr, $step:expr) => {{
        let sys = $m::Body { i1: 1.0, i2: 2.0, i3: 3.0 }.validated().unwrap();
        // A generic state away from every chart's origin and from gimbal lock.
        let mut s = $m::State::new(
            0.0,
            $m::Coords { a: 0.4, b: -0.7, c: 1.1 },
            $m::Coords { a: 0.3, b: 0.5, c: -0.2 },
        );
        let mut sum = 0.0;
        for _ in 0..$calls {
            if $step {
                sys.step::<Rk4>(black_box(&mut s), 1e-6).unwrap();
                sum += s.q.a;
            } else {
                sum += sys.accelerations(black_box(&s)).unwrap().a;
            }
        }
        sum
    }};
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let calls: usize = args[2].parse().unwrap();
    let sum = match args[1].as_str() {
        "vector" => run!(by_vector, calls, false),
        "mrp" => run!(by_mrp, calls, false),
        "euler" => run!(by_euler, calls, false),
        "vector_step" => run!(by_vector, calls, true),
        "mrp_step" => run!(by_mrp, calls, true),
        "euler_step" => run!(by_euler, calls, true),
        "quadruped_floating" => quadruped(
            &floating_quadruped::FloatingQuadruped::default().validated().unwrap(),
            calls,
        ),
        "quadruped_fixed" => quadruped(
            &fixed_quadruped::FixedQuadruped::default().validated().unwrap(),
            calls,
        ),
        mode => panic!("unknown mode {mode}"),
    };
    println!("{sum}");
}
