//! The cost of a free body's orientation, per `accelerations` call and per RK4 step: the same
//! torque-free body (moments 1, 2, 3) with its orientation written as the rotation vector
//! (`rot_vector`), as modified Rodrigues parameters (`rot_mrp`) and as z-x-z Euler angles (the
//! chart with a singularity, for reference). `charts MODE CALLS`; count.sh takes the difference of
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
        mode => panic!("unknown mode {mode}"),
    };
    println!("{sum}");
}
