//! A whole simulation: RK4 steps of the double pendulum, generated (`sys.step::<Rk4>`, which checks
//! the state and parameters each step and leaves the state unchanged on error) against a
//! hand-written RK4 on the closed-form accelerations, in one run.
//!
//! ```text
//! cargo bench --bench simulation
//! ```
//!
//! Each iteration is 10⁴ steps (h = 10⁻³); the summary scales the mean to 10⁶ steps.

use lagrange_gallery::scenes::double_pendulum as double_pendulum_scene;

#[allow(dead_code)]
mod common;

use common::{interleave, load_average, mean_ns, print_interleaved};
use criterion::{criterion_group, Criterion};
use double_pendulum_scene::double_pendulum::{Coords, DoublePendulum, State};
use lagrange::prelude::*;
use std::hint::black_box;

const STEPS: usize = 10_000;
const H: f64 = 1e-3;

/// Classical RK4 on (q, q̇) with the closed-form accelerations.
fn hand_written_run(
    sys: &DoublePendulum,
    mut q: [f64; 2],
    mut v: [f64; 2],
) -> ([f64; 2], [f64; 2]) {
    let f = |q: [f64; 2], v: [f64; 2]| double_pendulum_scene::closed_form(sys, q, v);
    let axpy = |x: [f64; 2], a: f64, y: [f64; 2]| [x[0] + a * y[0], x[1] + a * y[1]];
    for _ in 0..STEPS {
        let a1 = f(q, v);
        let (q2, v2) = (axpy(q, 0.5 * H, v), axpy(v, 0.5 * H, a1));
        let a2 = f(q2, v2);
        let (q3, v3) = (axpy(q, 0.5 * H, v2), axpy(v, 0.5 * H, a2));
        let a3 = f(q3, v3);
        let (q4, v4) = (axpy(q, H, v3), axpy(v, H, a3));
        let a4 = f(q4, v4);
        for j in 0..2 {
            q[j] += H / 6.0 * (v[j] + 2.0 * v2[j] + 2.0 * v3[j] + v4[j]);
            v[j] += H / 6.0 * (a1[j] + 2.0 * a2[j] + 2.0 * a3[j] + a4[j]);
        }
    }
    (q, v)
}

fn generated_run<M: Mechanism<2, Coords = Coords>>(sys: &M, mut s: State) -> State {
    for _ in 0..STEPS {
        sys.step::<Rk4>(&mut s, H).unwrap();
    }
    s
}

fn simulation(c: &mut Criterion) {
    let sys = DoublePendulum {
        m1: 1.0,
        m2: 1.3,
        l1: 1.0,
        l2: 0.8,
        g: 9.81,
    };
    let (q, v) = ([0.7, -1.2], [1.1, -0.4]);
    let s = State::new(
        0.0,
        Coords {
            theta1: q[0],
            theta2: q[1],
        },
        Coords {
            theta1: v[0],
            theta2: v[1],
        },
    );
    // The two runs integrate the same equations: they agree to rounding.
    let (qh, _) = hand_written_run(&sys, q, v);
    let sg = generated_run(&sys, s);
    assert!((qh[0] - sg.q.theta1).abs() < 1e-8 && (qh[1] - sg.q.theta2).abs() < 1e-8);
    let mut group = c.benchmark_group("rk4_double_pendulum_1e4_steps");
    group.bench_function("hand_written", |b| {
        b.iter(|| hand_written_run(black_box(&sys), black_box(q), black_box(v)))
    });
    group.bench_function("generated", |b| {
        b.iter(|| generated_run(black_box(&sys), black_box(s)))
    });
    // The handle a simulation uses: parameters checked once, the state every step.
    let checked = sys.validated().unwrap();
    group.bench_function("generated_validated", |b| {
        b.iter(|| generated_run(black_box(&checked), black_box(s)))
    });
    group.finish();
    let hand = || {
        black_box(hand_written_run(
            black_box(&sys),
            black_box(q),
            black_box(v),
        ));
    };
    interleave("generated", hand, || {
        black_box(generated_run(black_box(&sys), black_box(s)));
    });
    interleave("  validated once", hand, || {
        black_box(generated_run(black_box(&checked), black_box(s)));
    });
}

criterion_group!(benches, simulation);

fn main() {
    benches();
    Criterion::default().configure_from_args().final_summary();
    // A smoke run (`-- --test`) measures nothing: earlier runs' estimates would be stale.
    if std::env::args().any(|a| a == "--test") {
        return;
    }
    let group = "rk4_double_pendulum_1e4_steps";
    match (mean_ns(group, "generated"), mean_ns(group, "hand_written")) {
        (Some(g), Some(h)) => {
            let scale = 1e6 / STEPS as f64 * 1e-9;
            println!(
                "\n10⁶ RK4 steps of the double pendulum (scaled from 10⁴-step runs, same run):"
            );
            println!(
                "  generated {:.3} s, hand-written {:.3} s, ratio {:.2}× (load average {})",
                g * scale,
                h * scale,
                g / h,
                load_average()
            );
            if let Some(gv) = mean_ns(group, "generated_validated") {
                println!("  validated once {:.3} s, ratio {:.2}×", gv * scale, gv / h);
            }
        }
        _ => println!("\n(no estimates: run without --test to measure)"),
    }
    print_interleaved("10⁴ RK4 steps, generated / hand-written");
}
