//! Driver for callgrind: `lagrange-callgrind MODE CALLS` runs `accelerations` of one mechanism
//! (generated, or `hw_*` for the hand-written closed form; `validated_*` through a validated handle;
//! `hot_*` the hook integrators call on that handle, `accelerations_at`) CALLS times; or
//! `project_cartesian_pendulum` (`validated_project_…` through the handle) the projection after a
//! step, from a state off the circle by a step's drift. See count.sh.

mod calls;
mod mechanisms;

use calls::{calls, Via};
use lagrange::prelude::*;
use mechanisms::*;
use std::hint::black_box;

// Constrained mechanisms, from the gallery's scenes.
use lagrange_gallery::scenes::cartesian_pendulum as cartesian_pendulum_scene;
use lagrange_gallery::scenes::four_bar as four_bar_scene;

fn hw_pendulum(p: &pendulum::Pendulum, q: [f64; 1], _v: [f64; 1]) -> [f64; 1] {
    [-p.g / p.l * q[0].sin()]
}
fn hw_double(p: &double_pendulum::DoublePendulum, q: [f64; 2], v: [f64; 2]) -> [f64; 2] {
    let double_pendulum::DoublePendulum { m1, m2, l1, l2, g } = *p;
    let d = q[0] - q[1];
    let den = m1 + m2 * d.sin().powi(2);
    let a1 = (m2 * g * q[1].sin() * d.cos()
        - m2 * d.sin() * (l1 * v[0] * v[0] * d.cos() + l2 * v[1] * v[1])
        - (m1 + m2) * g * q[0].sin())
        / (l1 * den);
    let a2 = ((m1 + m2) * (l1 * v[0] * v[0] * d.sin() - g * q[1].sin() + g * q[0].sin() * d.cos())
        + m2 * l2 * v[1] * v[1] * d.sin() * d.cos())
        / (l2 * den);
    [a1, a2]
}
/// The N-link chain's closed form, as in the chain benchmark: M_jk = m l² (N − max(j,k))
/// cos(θⱼ − θₖ), one sin_cos per link, the same LDLᵀ.
fn hw_chain<const N: usize>(m: f64, l: f64, g: f64, q: &[f64; N], v: &[f64; N]) -> [f64; N] {
    let sc: [(f64, f64); N] = std::array::from_fn(|j| q[j].sin_cos());
    let mut mass = nalgebra::SMatrix::<f64, N, N>::zeros();
    let mut force = nalgebra::SVector::<f64, N>::zeros();
    for j in 0..N {
        let (sj, cj) = sc[j];
        force[j] = -m * g * l * (N - j) as f64 * sj;
        for k in 0..N {
            let (sk, ck) = sc[k];
            let w = m * l * l * (N - j.max(k)) as f64;
            mass[(j, k)] = w * (cj * ck + sj * sk);
            force[j] -= w * (sj * ck - cj * sk) * v[k] * v[k];
        }
    }
    lagrange::linalg::Ldlt::new(&mass)
        .expect("positive definite")
        .solve(&force)
        .into()
}
/// `n` calls of the link-by-link chain of `links` links (1, 2, 4, …, 64), through a validated
/// handle, with the parameters checked on every call, or of the integrators' hook (see `calls`).
fn chain_links(links: &str, n: usize, via: Via) -> f64 {
    macro_rules! run {
        ($module:ident, $ty:ident, $n:literal) => {{
            use chains::$module::*;
            let sys = $ty {
                m: 1.0,
                l: 0.5,
                g: 9.81,
            };
            let (q, v) = chain_state::<$n>();
            let s = State::new(0.0, Coords::from_array(q), Coords::from_array(v));
            calls(sys, &s, n, via)
        }};
    }
    match links {
        "1" => run!(chain1, Chain1, 1),
        "2" => run!(chain2, Chain2, 2),
        "4" => run!(chain4, Chain4, 4),
        "8" => run!(chain8, Chain8, 8),
        "16" => run!(chain16, Chain16, 16),
        "32" => run!(chain32, Chain32, 32),
        "64" => run!(chain64, Chain64, 64),
        other => panic!("no chain of {other} links"),
    }
}
/// `calls` calls of the closed form of the chain of `links` links.
fn hw_chain_runs(links: &str, calls: usize) -> f64 {
    macro_rules! run {
        ($n:literal) => {{
            let (q, v) = chain_state::<$n>();
            let mut acc = 0.0;
            for _ in 0..calls {
                // Parameters opaque, as the generated side's (`black_box(&sys)`).
                let (m, l, g) = black_box((1.0, 0.5, 9.81));
                acc += hw_chain::<$n>(m, l, g, black_box(&q), black_box(&v))[0];
            }
            acc
        }};
    }
    match links {
        "1" => run!(1),
        "2" => run!(2),
        "4" => run!(4),
        "8" => run!(8),
        "16" => run!(16),
        "32" => run!(32),
        "64" => run!(64),
        other => panic!("no chain of {other} links"),
    }
}
/// θⱼ and θ̇ⱼ spread over the links, as in the chain benchmark.
fn chain_state<const N: usize>() -> ([f64; N], [f64; N]) {
    (
        std::array::from_fn(|j| 0.3 + 0.7 * ((j as f64) * 0.9).sin()),
        std::array::from_fn(|j| 0.5 * ((j as f64) * 1.3).cos()),
    )
}
fn hw_wedge(p: &wedge_block::WedgeBlock) -> [f64; 2] {
    let (s, c) = p.alpha.sin_cos();
    let den = p.wedge_mass + p.block_mass * s * s;
    [
        -p.block_mass * p.g * s * c / den,
        (p.wedge_mass + p.block_mass) * p.g * s / den,
    ]
}
/// The wedge by the generated code's method, written out by hand in f64 (rows [1, 0], [1, c],
/// [0, −s]; M = JᵀμJ; 𝓕 = Jᵀw; 2×2 solve; no checks): see benches/accelerations.rs.
fn assembled_wedge(p: &wedge_block::WedgeBlock) -> [f64; 2] {
    let (s, c) = p.alpha.sin_cos();
    let (big_m, m) = (p.wedge_mass, p.block_mass);
    let (m00, m10, m11) = (big_m + m, m * c, m * (c * c + s * s));
    let (f0, f1) = (0.0, m * p.g * s);
    let inv_det = 1.0 / (m00 * m11 - m10 * m10);
    [
        (m11 * f0 - m10 * f1) * inv_det,
        (m00 * f1 - m10 * f0) * inv_det,
    ]
}
fn hw_cart(p: &cart_pendulum::CartPendulum, q: [f64; 2], v: [f64; 2]) -> [f64; 2] {
    let (s, c) = q[1].sin_cos();
    let (mc, m, l, g) = (p.cart_mass, p.m, p.l, p.g);
    let den = mc + m * s * s;
    let xdd = (m * s * (l * v[1] * v[1] + g * c)) / den;
    let tdd = -(m * l * v[1] * v[1] * s * c + (mc + m) * g * s) / (l * den);
    [xdd, tdd]
}

fn main() {
    let arg = std::env::args().nth(1).unwrap();
    // `validated_NAME`: the generated mechanism NAME through `sys.validated()`; `hot_NAME`: the
    // hook the integrators call, on the same handle (see `calls`).
    let (via, which) = Via::read(&arg);
    let n: usize = std::env::args()
        .nth(2)
        .map(|s| s.parse().unwrap())
        .unwrap_or(1000);
    let mut acc = 0.0;
    match which {
        "pendulum" => {
            use pendulum::*;
            let sys = Pendulum {
                m: 1.0,
                l: 0.8,
                g: 9.81,
            };
            let s = State::new(0.0, Coords { theta: 0.7 }, Coords { theta: 1.1 });
            acc += calls(sys, &s, n, via);
        }
        "double_pendulum" => {
            let sys = DOUBLE_PENDULUM;
            let s = double_pendulum_start();
            acc += calls(sys, &s, n, via);
        }
        // One RK4 step (h = 10⁻³) per call: `sys.step::<Rk4>` on the parameters, through a
        // validated handle, and a hand-written RK4 on the closed form.
        "rk4_double_pendulum" | "rk4_validated_double_pendulum" => {
            let params = DOUBLE_PENDULUM;
            let mut s = double_pendulum_start();
            if which.starts_with("rk4_validated") {
                let sys = params.validated().unwrap();
                for _ in 0..n {
                    black_box(&sys).step::<Rk4>(&mut s, 1e-3).unwrap();
                }
            } else {
                for _ in 0..n {
                    black_box(&params).step::<Rk4>(&mut s, 1e-3).unwrap();
                }
            }
            acc += s.q.theta1;
        }
        // One RK4 step (h = 10⁻³) and one `Recorder::push` per call, at 30 frames per second of
        // simulated time (a frame kept every 34 steps), against `rk4_validated_double_pendulum`.
        "rk4_recorded_double_pendulum" => {
            let sys = DOUBLE_PENDULUM.validated().unwrap();
            let mut s = double_pendulum_start();
            let mut recorder = lagrange::animation::Recorder::new(&sys);
            for _ in 0..n {
                black_box(&sys).step::<Rk4>(&mut s, 1e-3).unwrap();
                recorder.push(&sys, &s).unwrap();
            }
            acc += s.q.theta1 + recorder.frames() as f64;
        }
        // One RK4 step (h = 10⁻³) per call on dual numbers seeded on 1, 2 or 4 initial values, or
        // on the lengths (`l1`, `l1_l2`, and both with two initial values: `l1_l2_4`)
        // (a `Stepper` with sensitivities), against `rk4_validated_double_pendulum`.
        mode if mode.starts_with("sensitivity_double_pendulum_") => {
            use lagrange::sensitivity::Seed;
            let sys = DOUBLE_PENDULUM.validated().unwrap();
            let s = double_pendulum_start();
            let (q1, q2) = (Seed::Coordinate("theta1"), Seed::Coordinate("theta2"));
            let (v1, v2) = (Seed::Velocity("theta1"), Seed::Velocity("theta2"));
            macro_rules! run {
                ($seeds:expr) => {{
                    let mut run = Stepper::new(&sys, Rk4::with_step(1e-3), &s)
                        .unwrap()
                        .with_sensitivities($seeds)
                        .unwrap();
                    for _ in 0..n {
                        black_box(&mut run).step(f64::INFINITY).unwrap();
                    }
                    acc += run.sensitivities().dq[0].theta1;
                }};
            }
            let (l1, l2) = (Seed::Parameter("l1"), Seed::Parameter("l2"));
            match &mode["sensitivity_double_pendulum_".len()..] {
                "1" => run!([q1]),
                "2" => run!([q1, q2]),
                "4" => run!([q1, q2, v1, v2]),
                // Seeded on parameters: the accelerations of the lifted model.
                "l1" => run!([l1]),
                "l1_l2" => run!([l1, l2]),
                "l1_l2_4" => run!([l1, l2, q1, q2]),
                other => panic!("no sensitivity run with {other} seeds"),
            }
        }
        // One implicit step (h = 10⁻³) per call, as a solver takes it: the Newton matrix and the
        // stage predictor kept from step to step (`step_with_memory`); `…_validated_…` through a
        // validated handle (the closed form's prepared coefficients).
        "midpoint_double_pendulum"
        | "gl2_double_pendulum"
        | "midpoint_validated_double_pendulum"
        | "gl2_validated_double_pendulum" => {
            use lagrange::integrate::NewtonMemory;
            use lagrange::{GaussLegendre2, ImplicitMidpoint};
            let params = DOUBLE_PENDULUM;
            let mut s = double_pendulum_start();
            macro_rules! run {
                ($sys:expr) => {
                    if which.starts_with("gl2") {
                        let mut memory = NewtonMemory::<2, 2>::default();
                        for _ in 0..n {
                            GaussLegendre2::step_with_memory(
                                black_box($sys),
                                &mut memory,
                                &mut s,
                                1e-3,
                            )
                            .unwrap();
                        }
                    } else {
                        let mut memory = NewtonMemory::<2, 1>::default();
                        for _ in 0..n {
                            ImplicitMidpoint::step_with_memory(
                                black_box($sys),
                                &mut memory,
                                &mut s,
                                1e-3,
                            )
                            .unwrap();
                        }
                    }
                };
            }
            if which.contains("_validated_") {
                let sys = params.validated().unwrap();
                run!(&sys);
            } else {
                run!(&params);
            }
            acc += s.q.theta1;
        }
        // One implicit step per call through `sys.step` (fresh memory: the field's Jacobians by
        // gradient duals and a factorisation at every step).
        "midpoint_fresh_double_pendulum" | "gl2_fresh_double_pendulum" => {
            use lagrange::{GaussLegendre2, ImplicitMidpoint};
            let params = DOUBLE_PENDULUM;
            let mut s = double_pendulum_start();
            for _ in 0..n {
                if which.starts_with("gl2") {
                    black_box(&params)
                        .step::<GaussLegendre2>(&mut s, 1e-3)
                        .unwrap();
                } else {
                    black_box(&params)
                        .step::<ImplicitMidpoint>(&mut s, 1e-3)
                        .unwrap();
                }
            }
            acc += s.q.theta1;
        }
        // One step (h = 10⁻⁵ s) per call of Andrews' squeezer from the state 20 steps after Hairer &
        // Wanner's start: RK4 (`sys.step`, the constrained accelerations and the projection after
        // the step), Gauss–Legendre 2 as a solver takes it (`step_with_memory`: the Newton
        // matrix and the stage predictor kept from step to step), through a `Stepper` (the
        // same, with its end-of-step q̈), through `sys.simulate` (the memory kept, n steps in one
        // call) and through `sys.step` (a fresh Newton matrix every step).
        "rk4_squeezer"
        | "rk4_simulate_squeezer"
        | "gl2_squeezer"
        | "gl2_fresh_squeezer"
        | "gl2_stepper_squeezer"
        | "gl2_simulate_squeezer" => {
            use lagrange::integrate::NewtonMemory;
            use lagrange::GaussLegendre2;
            let sys = squeezer_model::ANDREWS;
            let h = 1e-5;
            let mut s = squeezer_model::start();
            let mut memory = NewtonMemory::<7, 2>::default();
            for _ in 0..20 {
                GaussLegendre2::step_with_memory(&sys, &mut memory, &mut s, h).unwrap();
            }
            if which == "rk4_squeezer" {
                for _ in 0..n {
                    black_box(&sys).step::<Rk4>(&mut s, h).unwrap();
                }
            } else if which == "rk4_simulate_squeezer" {
                black_box(&sys)
                    .simulate::<Rk4>(&mut s, h, n, |_| {})
                    .unwrap();
            } else if which == "gl2_simulate_squeezer" {
                black_box(&sys)
                    .simulate::<GaussLegendre2>(&mut s, h, n, |_| {})
                    .unwrap();
            } else if which == "gl2_stepper_squeezer" {
                // The documented way to take repeated implicit steps: a Stepper (the Newton
                // memory kept, the projection and q̈ at the end of each step for dense output).
                use lagrange::integrate::Stepper;
                use lagrange::Integrator;
                let mut solver = Stepper::new(&sys, GaussLegendre2::with_step(h), &s).unwrap();
                for _ in 0..n {
                    black_box(&mut solver).step(f64::MAX).unwrap();
                }
                s = solver.state();
            } else if which == "gl2_fresh_squeezer" {
                for _ in 0..n {
                    black_box(&sys).step::<GaussLegendre2>(&mut s, h).unwrap();
                }
            } else {
                for _ in 0..n {
                    GaussLegendre2::step_with_memory(black_box(&sys), &mut memory, &mut s, h)
                        .unwrap();
                }
            }
            acc += s.q.beta;
        }
        "hw_rk4_double_pendulum" => {
            let sys = DOUBLE_PENDULUM;
            let (mut q, mut v) = ([0.7, -1.2], [1.1, -0.4]);
            let h = 1e-3;
            let axpy = |x: [f64; 2], a: f64, y: [f64; 2]| [x[0] + a * y[0], x[1] + a * y[1]];
            for _ in 0..n {
                let f = |q, v| hw_double(black_box(&sys), q, v);
                let a1 = f(q, v);
                let (q2, v2) = (axpy(q, 0.5 * h, v), axpy(v, 0.5 * h, a1));
                let a2 = f(q2, v2);
                let (q3, v3) = (axpy(q, 0.5 * h, v2), axpy(v, 0.5 * h, a2));
                let a3 = f(q3, v3);
                let (q4, v4) = (axpy(q, h, v3), axpy(v, h, a3));
                let a4 = f(q4, v4);
                for j in 0..2 {
                    q[j] += h / 6.0 * (v[j] + 2.0 * v2[j] + 2.0 * v3[j] + v4[j]);
                    v[j] += h / 6.0 * (a1[j] + 2.0 * a2[j] + 2.0 * a3[j] + a4[j]);
                }
            }
            acc += q[0];
        }
        // One step per call of the gallery's block sliding on a rough incline (a unilateral
        // contact and a friction cone, the contact mode held over the step): `sys.step::<Rk4>`
        // (h = 10⁻³; the mode inferred at every call) through a validated handle, or an accepted
        // step of a Dopri5 `Stepper` (the mode held across steps) up to the next 10⁻² of time.
        "rk4_pushed_block" | "dopri5_pushed_block" => {
            use lagrange_gallery::scenes::pushed_block::pushed_block::*;
            let sys = PushedBlock {
                m: 2.0,
                g: 9.81,
                alpha: 0.3,
                mu_k: 0.4,
                mu_s: 0.5,
                push: 12.0,
            }
            .validated()
            .unwrap();
            let mut s = State::at_rest(Coords {
                x: 0.0,
                y: 0.0,
                z: 0.0,
            });
            if which == "rk4_pushed_block" {
                for _ in 0..n {
                    black_box(&sys).step::<Rk4>(&mut s, 1e-3).unwrap();
                }
            } else {
                let mut stepper = Stepper::new(&sys, Dopri5::default(), &s).unwrap();
                for i in 0..n {
                    stepper.step(1e-2 * (i + 1) as f64).unwrap();
                }
                s = stepper.state();
            }
            acc += s.q.x;
        }
        "wedge_block" => {
            use wedge_block::*;
            let sys = WedgeBlock {
                wedge_mass: 3.0,
                block_mass: 1.0,
                alpha: 0.5,
                h: 1.0,
                g: 9.81,
            };
            let s = State::new(0.0, Coords { x: 0.1, d: 0.2 }, Coords { x: -0.3, d: 0.5 });
            acc += calls(sys, &s, n, via);
        }
        "cart_pendulum" => {
            use cart_pendulum::*;
            let sys = CartPendulum {
                cart_mass: 2.0,
                m: 1.0,
                l: 0.8,
                g: 9.81,
            };
            let s = State::new(
                0.0,
                Coords { x: 0.1, theta: 0.7 },
                Coords {
                    x: -0.3,
                    theta: 1.1,
                },
            );
            acc += calls(sys, &s, n, via);
        }
        "hw_pendulum" => {
            let sys = pendulum::Pendulum {
                m: 1.0,
                l: 0.8,
                g: 9.81,
            };
            for _ in 0..n {
                acc += hw_pendulum(black_box(&sys), black_box([0.7]), black_box([1.1]))[0];
            }
        }
        "hw_double_pendulum" => {
            let sys = DOUBLE_PENDULUM;
            for _ in 0..n {
                acc += hw_double(
                    black_box(&sys),
                    black_box([0.7, -1.2]),
                    black_box([1.1, -0.4]),
                )[0];
            }
        }
        "four_bar" => {
            let (sys, s) = four_bar_scene::linkage();
            acc += calls(sys, &s, n, via);
        }
        "hw_four_bar" => {
            let (sys, s) = four_bar_scene::linkage();
            let hand = constrained::FourBar {
                l: [sys.l1, sys.l2, sys.l3],
                m: [sys.m1, sys.m2, sys.m3],
                d: sys.d,
                g: sys.g,
            };
            let (q, v) = (s.q.to_array(), s.v.to_array());
            for _ in 0..n {
                acc += constrained::four_bar(black_box(&hand), black_box(q), black_box(v))[0];
            }
        }
        "fpu" => {
            let sys = fpu::Fpu {
                m: 1.0,
                omega: 50.0,
            };
            let s = State::new(
                0.0,
                fpu::Coords {
                    q: [0.1, 0.2, -0.3, 0.05, 0.4, -0.1],
                },
                fpu::Coords {
                    q: [0.3, -0.2, 0.1, 0.0, 0.5, 0.2],
                },
            );
            acc += calls(sys, &s, n, via);
        }
        "fpu_springs" => {
            let sys = fpu_chain::Fpu {
                m: 1.0,
                omega: 50.0,
            };
            let s = State::new(
                0.0,
                fpu_chain::Coords {
                    q: [0.1, 0.2, -0.3, 0.05, 0.4, -0.1],
                },
                fpu_chain::Coords {
                    q: [0.3, -0.2, 0.1, 0.0, 0.5, 0.2],
                },
            );
            acc += calls(sys, &s, n, via);
        }
        "kepler" => {
            let s = State::new(
                0.0,
                kepler::Coords { x: 0.4, y: 0.3 },
                kepler::Coords { x: -0.2, y: 1.7 },
            );
            acc += calls(KEPLER, &s, n, via);
        }
        "hw_kepler" => {
            let (q, v) = ([0.4, 0.3], [-0.2, 1.7]);
            // Both components consumed: with q̈₀ alone the compiler drops the second division.
            for _ in 0..n {
                let a = kepler_rhs(0.0, black_box(&q), black_box(&v));
                acc += a[0] + a[1];
            }
        }
        "hw_fpu" => {
            let q = [0.1, 0.2, -0.3, 0.05, 0.4, -0.1];
            for _ in 0..n {
                acc += fpu_forces(black_box(50.0), black_box(&q))
                    .iter()
                    .sum::<f64>();
            }
        }
        "hw_cartesian_pendulum" => {
            let hand = constrained::CartesianPendulum {
                m: 1.0,
                l: 0.8,
                g: 9.81,
            };
            let (th, w) = (0.7f64, 1.1f64);
            let q = [0.8 * th.sin(), -0.8 * th.cos()];
            let v = [0.8 * w * th.cos(), 0.8 * w * th.sin()];
            for _ in 0..n {
                acc +=
                    constrained::cartesian_pendulum(black_box(&hand), black_box(q), black_box(v))
                        [0];
            }
        }
        "project_cartesian_pendulum" => {
            use cartesian_pendulum_scene::cartesian_pendulum::*;
            let sys = CartesianPendulum {
                m: 1.0,
                l: 0.8,
                g: 9.81,
            };
            // Off the circle and its tangent by 1e-10, as an accepted step leaves it.
            let (th, w, drift) = (0.7f64, 1.1f64, 1.0 + 1e-10);
            let q = [0.8 * drift * th.sin(), -0.8 * drift * th.cos()];
            let v = [0.8 * w * th.cos() + 1e-10, 0.8 * w * th.sin()];
            fn project<M: Mechanism<2>>(sys: &M, q: [f64; 2], v: [f64; 2], n: usize) -> f64 {
                let mut acc = 0.0;
                for _ in 0..n {
                    let (mut q, mut v) = (black_box(q), black_box(v));
                    black_box(sys).project(0.0, &mut q, &mut v).unwrap();
                    acc += q[0] + v[0];
                }
                acc
            }
            acc += match via {
                Via::Parameters => project(&sys, q, v, n),
                _ => project(&sys.validated().unwrap(), q, v, n),
            };
        }
        "cartesian_pendulum" => {
            use cartesian_pendulum_scene::cartesian_pendulum::*;
            let sys = CartesianPendulum {
                m: 1.0,
                l: 0.8,
                g: 9.81,
            };
            let (th, w) = (0.7f64, 1.1f64);
            let s = State::new(
                0.0,
                Coords {
                    x: 0.8 * th.sin(),
                    y: -0.8 * th.cos(),
                },
                Coords {
                    x: 0.8 * w * th.cos(),
                    y: 0.8 * w * th.sin(),
                },
            );
            acc += calls(sys, &s, n, via);
        }
        "hw_wedge_block" | "assembled_wedge_block" => {
            let sys = wedge_block::WedgeBlock {
                wedge_mass: 3.0,
                block_mass: 1.0,
                alpha: 0.5,
                h: 1.0,
                g: 9.81,
            };
            // Two loops, not a function pointer: each side is inlined as in the bench.
            if which == "hw_wedge_block" {
                for _ in 0..n {
                    acc += hw_wedge(black_box(&sys))[0];
                }
            } else {
                for _ in 0..n {
                    acc += assembled_wedge(black_box(&sys))[0];
                }
            }
        }
        "hw_cart_pendulum" => {
            let sys = cart_pendulum::CartPendulum {
                cart_mass: 2.0,
                m: 1.0,
                l: 0.8,
                g: 9.81,
            };
            for _ in 0..n {
                acc += hw_cart(
                    black_box(&sys),
                    black_box([0.1, 0.7]),
                    black_box([-0.3, 1.1]),
                )[0];
            }
        }
        "check" => {
            use cart_pendulum::*;
            let sys = CartPendulum {
                cart_mass: 2.0,
                m: 1.0,
                l: 0.8,
                g: 9.81,
            };
            let s = State::new(
                0.0,
                Coords { x: 0.1, theta: 0.7 },
                Coords {
                    x: -0.3,
                    theta: 1.1,
                },
            );
            let a = sys.accelerations(&s).unwrap();
            println!("{:?} {:?}", a, hw_cart(&sys, [0.1, 0.7], [-0.3, 1.1]));
        }
        "chain32" => {
            use chain32::*;
            let sys = Chain {
                m: 1.0,
                l: 0.5,
                g: 9.81,
            };
            let s = State::new(
                0.0,
                Coords {
                    theta: std::array::from_fn(|j| 0.3 + 0.7 * ((j as f64) * 0.9).sin()),
                },
                Coords {
                    theta: std::array::from_fn(|j| 0.5 * ((j as f64) * 1.3).cos()),
                },
            );
            for _ in 0..n {
                acc += black_box(&sys).accelerations(black_box(&s)).unwrap().theta[0];
            }
        }
        mode if mode.starts_with("chain") && mode.ends_with("_links") => {
            acc += chain_links(&mode["chain".len()..mode.len() - "_links".len()], n, via);
        }
        mode if mode.starts_with("hw_chain") => {
            acc += hw_chain_runs(&mode["hw_chain".len()..], n);
        }
        "drag" => {
            use drag::*;
            let sys = Drag {
                m: 1.0,
                l: 0.8,
                g: 9.81,
                c: 0.3,
            };
            let s = State::new(0.2, Coords { theta: 0.7 }, Coords { theta: 1.1 });
            acc += calls(sys, &s, n, via);
        }
        "driven" => {
            use driven::*;
            let sys = Driven {
                m: 1.0,
                l: 0.8,
                g: 9.81,
                a: 0.1,
                w: 2.0,
            };
            let s = State::new(0.2, Coords { theta: 0.7 }, Coords { theta: 1.1 });
            acc += calls(sys, &s, n, via);
        }
        // The arm by its frames, by its principal axes; one eigen-decomposition of a tensor.
        "framed_arm" | "principal_arm" => {
            use framed_arms::{framed_arm as fa, principal_arm as pa};
            let (q, v) = ([0.3, 1.2, -0.8], [1.0, -0.5, 2.0]);
            if which == "framed_arm" {
                let s = fa::State::new(0.0, fa::Coords::from_array(q), fa::Coords::from_array(v));
                acc += calls(framed_arms::framed(), &s, n, via);
            } else {
                let s = pa::State::new(0.0, pa::Coords::from_array(q), pa::Coords::from_array(v));
                acc += calls(framed_arms::principal(), &s, n, via);
            }
        }
        "principal_axes" => {
            let tensor = [
                [0.02, 0.001, -0.002],
                [0.001, 0.03, 0.0005],
                [-0.002, 0.0005, 0.04],
            ];
            for _ in 0..n {
                acc += lagrange::inertia::principal_axes(black_box(&tensor)).0[0];
            }
        }
        "none" => {}
        _ => panic!(),
    }
    println!("{acc}");
}
