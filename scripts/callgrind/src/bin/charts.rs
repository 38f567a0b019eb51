//! The cost of a free body's orientation, per `accelerations` call and per RK4 step: the same
//! torque-free body (moments 1, 2, 3) with its orientation written as the rotation vector
//! (`rot_vector`), as modified Rodrigues parameters (`rot_mrp`), as a unit quaternion (four
//! coordinates and the norm as a `#[constraint]`) and as z-x-z Euler angles (the chart with a
//! singularity, for reference); a body thrown free in either chart (`thrown_vector`, `thrown_mrp`:
//! the rigid tree's free joint); each chart's body again with `#[angular_velocity]`
//! (`vector_omega`, `mrp_omega`, their `_step`s, `thrown_vector_omega`, `thrown_mrp_omega`); and a
//! quadruped's q̈ with a floating base (whose velocities are its angular velocity), with its
//! root fixed, and floating above a ground row (`quadruped_standing`: the constrained solve).
//! `charts MODE CALLS`; count.sh takes the difference of two call counts under callgrind
//! (`BIN=charts MODES="vector mrp quaternion euler vector_step mrp_step quaternion_step
//! euler_step" scripts/callgrind/count.sh`). `charts accuracy` prints each orientation's largest
//! error in ω against Euler's closed form over 1000 s of RK4 at two steps.

use lagrange::prelude::*;
use lagrange_gallery::scenes::tumbling_body::{closed_form, OMEGA0};
use std::hint::black_box;

/// The torque-free body turned by `$chart` about its centre; with `#[angular_velocity]`, its
/// velocities the body's angular velocity rather than the chart's rates.
macro_rules! spinning {
    ($module:ident, $chart:ident $(, #[$marker:ident])?) => {
        #[mechanism]
        pub mod $module {
            pub struct Coords {
                $(#[$marker])?
                pub a: f64,
                $(#[$marker])?
                pub b: f64,
                $(#[$marker])?
                pub c: f64,
            }
            pub struct Body {
                pub i1: f64,
                pub i2: f64,
                pub i3: f64,
            }
            #[rigid_body(mass = 1.0, inertia = [i1, i2, i3])]
            fn body() -> Spatial {
                spatial(vec3(0.0, 0.0, 0.0), $chart(vec3(a, b, c)))
            }
        }
    };
}
spinning!(by_vector, rot_vector);
spinning!(by_mrp, rot_mrp);
spinning!(by_vector_omega, rot_vector, #[angular_velocity]);
spinning!(by_mrp_omega, rot_mrp, #[angular_velocity]);

/// A body thrown in a uniform field, free in both charts: six coordinates, position first (the
/// rigid tree's free joint).
macro_rules! thrown {
    ($module:ident, $chart:ident $(, #[$marker:ident])?) => {
        #[mechanism]
        pub mod $module {
            pub struct Coords {
                pub p: [f64; 3],
                $(#[$marker])?
                pub c: [f64; 3],
            }
            pub struct Body {
                pub i1: f64,
                pub i2: f64,
                pub i3: f64,
            }
            #[rigid_body(mass = 1.0, inertia = [i1, i2, i3])]
            fn body() -> Spatial {
                spatial(vec3(p[0], p[1], p[2]), $chart(vec3(c[0], c[1], c[2])))
            }
            #[gravity]
            fn field() -> Vec3 {
                vec3(0.0, 0.0, -9.81)
            }
        }
    };
}
thrown!(thrown_vector, rot_vector);
thrown!(thrown_mrp, rot_mrp);
thrown!(thrown_vector_omega, rot_vector, #[angular_velocity]);
thrown!(thrown_mrp_omega, rot_mrp, #[angular_velocity]);

/// q̈ of a thrown body at the charts' state of `run!`, moving along all six coordinates.
macro_rules! thrown_calls {
    ($m:ident, $calls:expr) => {{
        let sys = $m::Body {
            i1: 1.0,
            i2: 2.0,
            i3: 3.0,
        }
        .validated()
        .unwrap();
        let s = $m::State::new(
            0.0,
            $m::Coords {
                p: [0.1, 0.2, 0.3],
                c: [0.4, -0.7, 1.1],
            },
            $m::Coords {
                p: [1.0, -0.5, 2.0],
                c: [0.3, 0.5, -0.2],
            },
        );
        let mut sum = 0.0;
        for _ in 0..$calls {
            sum += sys.accelerations(black_box(&s)).unwrap().c[0];
        }
        sum
    }};
}

// The quaternion e = (w, x, y, z) of the tests: the rotation homogeneous of degree two in e, the
// norm a holonomic constraint.
#[path = "../../../../tests/common/quaternion_body.rs"]
mod quaternion_declaration;
use quaternion_declaration::quaternion_body as by_quaternion;

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
/// The floating quadruped with a ground its base stays above (a unilateral row, separated at the
/// state below): the constrained solve.
#[lagrange::urdf("../../tests/urdf/quadruped.urdf", floating)]
pub mod standing_quadruped {
    #[unilateral]
    fn above_ground() -> f64 {
        base_position[2] + 1.0
    }
}

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
        let sys = $m::Body {
            i1: 1.0,
            i2: 2.0,
            i3: 3.0,
        }
        .validated()
        .unwrap();
        // A generic state away from every chart's origin and from gimbal lock.
        let mut s = $m::State::new(
            0.0,
            $m::Coords {
                a: 0.4,
                b: -0.7,
                c: 1.1,
            },
            $m::Coords {
                a: 0.3,
                b: 0.5,
                c: -0.2,
            },
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

/// The quaternion of the rotation vector `phi` (as `run!` starts the charts), moving at the
/// body-frame angular velocity `omega`: e = (cos θ/2, sin θ/2 n), ė = ½ e ⊗ (0, ω).
fn quaternion_state(phi: [f64; 3], omega: [f64; 3]) -> by_quaternion::State {
    let theta = phi.iter().map(|x| x * x).sum::<f64>().sqrt();
    let (s, c) = (0.5 * theta).sin_cos();
    // sin(θ/2)/θ, ½ at θ = 0.
    let k = if theta > 0.0 { s / theta } else { 0.5 };
    let e = [c, k * phi[0], k * phi[1], k * phi[2]];
    let v = [e[1], e[2], e[3]];
    let cross = [
        v[1] * omega[2] - v[2] * omega[1],
        v[2] * omega[0] - v[0] * omega[2],
        v[0] * omega[1] - v[1] * omega[0],
    ];
    let dot = v[0] * omega[0] + v[1] * omega[1] + v[2] * omega[2];
    let rate = [
        -0.5 * dot,
        0.5 * (e[0] * omega[0] + cross[0]),
        0.5 * (e[0] * omega[1] + cross[1]),
        0.5 * (e[0] * omega[2] + cross[2]),
    ];
    by_quaternion::State::new(
        0.0,
        by_quaternion::Coords { e },
        by_quaternion::Coords { e: rate },
    )
}

/// `accelerations` (or an RK4 step) of the quaternion body, at the charts' state of `run!`.
fn quaternion(calls: usize, step: bool) -> f64 {
    let sys = by_quaternion::QuaternionBody {
        i1: 1.0,
        i2: 2.0,
        i3: 3.0,
    }
    .validated()
    .unwrap();
    let mut s = quaternion_state([0.4, -0.7, 1.1], [0.3, 0.5, -0.2]);
    let mut sum = 0.0;
    for _ in 0..calls {
        if step {
            sys.step::<Rk4>(black_box(&mut s), 1e-6).unwrap();
            sum += s.q.e[0];
        } else {
            sum += sys.accelerations(black_box(&s)).unwrap().e[0];
        }
    }
    sum
}

/// The largest error of the body-frame angular velocity Rᵀω against Euler's closed form, sampled
/// every second over 1000 s of RK4 at step `h`, from the start state `s`.
macro_rules! omega_error {
    ($m:ident :: $body:ident, $s:expr, $h:expr) => {{
        let sys = $m::$body {
            i1: 1.0,
            i2: 2.0,
            i3: 3.0,
        }
        .validated()
        .unwrap();
        let mut s = $s;
        let h: f64 = $h;
        let per_second = (1.0 / h).round() as usize;
        let mut error: f64 = 0.0;
        for step in 1..=1000 * per_second {
            sys.step::<Rk4>(&mut s, h).unwrap();
            if step % per_second == 0 {
                let r = sys.bodies(&s).body.rotation;
                let w = r.transpose() * sys.body_velocities(&s).body.angular;
                let exact = closed_form(s.t);
                let e = [w.x - exact[0], w.y - exact[1], w.z - exact[2]];
                error = e.iter().fold(error, |a, x| a.max(x.abs()));
            }
        }
        error
    }};
}

/// Each orientation's error over 1000 s, RK4 at 10 ms and 5 ms, from the identity spinning at
/// ω(0) = (1, 0, 2): the rotation vector's rates are ω there, the parameters' ω/4, the
/// quaternion's (0, ω/2).
fn accuracy() {
    let w = OMEGA0;
    for h in [0.01, 0.005] {
        let vector = by_vector::State::new(
            0.0,
            by_vector::Coords {
                a: 0.0,
                b: 0.0,
                c: 0.0,
            },
            by_vector::Coords {
                a: w[0],
                b: w[1],
                c: w[2],
            },
        );
        let mrp = by_mrp::State::new(
            0.0,
            by_mrp::Coords {
                a: 0.0,
                b: 0.0,
                c: 0.0,
            },
            by_mrp::Coords {
                a: w[0] / 4.0,
                b: w[1] / 4.0,
                c: w[2] / 4.0,
            },
        );
        let quaternion = quaternion_state([0.0; 3], w);
        // With the angular velocity for velocities, ω itself in every chart.
        let vector_omega = by_vector_omega::State::new(
            0.0,
            by_vector_omega::Coords { a: 0.0, b: 0.0, c: 0.0 },
            by_vector_omega::Coords { a: w[0], b: w[1], c: w[2] },
        );
        let mrp_omega = by_mrp_omega::State::new(
            0.0,
            by_mrp_omega::Coords { a: 0.0, b: 0.0, c: 0.0 },
            by_mrp_omega::Coords { a: w[0], b: w[1], c: w[2] },
        );
        println!(
            "h = {h}: rotation vector {:.1e}, modified Rodrigues parameters {:.1e}, quaternion {:.1e}; \
             with the angular velocity for velocities: rotation vector {:.1e}, modified Rodrigues \
             parameters {:.1e}",
            omega_error!(by_vector::Body, vector, h),
            omega_error!(by_mrp::Body, mrp, h),
            omega_error!(by_quaternion::QuaternionBody, quaternion, h),
            omega_error!(by_vector_omega::Body, vector_omega, h),
            omega_error!(by_mrp_omega::Body, mrp_omega, h),
        );
    }
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    if args[1] == "accuracy" {
        return accuracy();
    }
    let calls: usize = args[2].parse().unwrap();
    let sum = match args[1].as_str() {
        "vector" => run!(by_vector, calls, false),
        "mrp" => run!(by_mrp, calls, false),
        "euler" => run!(by_euler, calls, false),
        "vector_step" => run!(by_vector, calls, true),
        "mrp_step" => run!(by_mrp, calls, true),
        "euler_step" => run!(by_euler, calls, true),
        "quaternion" => quaternion(calls, false),
        "thrown_vector" => thrown_calls!(thrown_vector, calls),
        "thrown_mrp" => thrown_calls!(thrown_mrp, calls),
        "vector_omega" => run!(by_vector_omega, calls, false),
        "mrp_omega" => run!(by_mrp_omega, calls, false),
        "vector_omega_step" => run!(by_vector_omega, calls, true),
        "mrp_omega_step" => run!(by_mrp_omega, calls, true),
        "thrown_vector_omega" => thrown_calls!(thrown_vector_omega, calls),
        "thrown_mrp_omega" => thrown_calls!(thrown_mrp_omega, calls),
        "quaternion_step" => quaternion(calls, true),
        "quadruped_floating" => quadruped(
            &floating_quadruped::FloatingQuadruped::default()
                .validated()
                .unwrap(),
            calls,
        ),
        "quadruped_fixed" => quadruped(
            &fixed_quadruped::FixedQuadruped::default()
                .validated()
                .unwrap(),
            calls,
        ),
        "quadruped_standing" => quadruped(
            &standing_quadruped::StandingQuadruped::default()
                .validated()
                .unwrap(),
            calls,
        ),
        mode => panic!("unknown mode {mode}"),
    };
    println!("{sum}");
}
