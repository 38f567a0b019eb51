//! `accelerations` of generated mechanisms against hand-written closed forms, in one run.
//!
//! ```text
//! cargo bench --bench accelerations
//! ```
//!
//! After criterion's own report this prints, per mechanism, the ratio of the generated code's mean
//! time to the hand-written closed form's (the baseline), from the same run's estimates.

#[path = "../examples/double_pendulum.rs"]
#[allow(dead_code)]
mod double_pendulum_scene;
#[path = "../examples/wedge_block.rs"]
#[allow(dead_code)]
mod wedge_block_scene;

use criterion::{criterion_group, Criterion};
use lagrange::prelude::*;
use std::hint::black_box;

fn double_pendulum(c: &mut Criterion) {
    use double_pendulum_scene::double_pendulum::{Coords, DoublePendulum, State};
    let sys = DoublePendulum {
        m1: 1.0,
        m2: 1.3,
        l1: 1.0,
        l2: 0.8,
        g: 9.81,
    };
    let s = State::new(
        0.0,
        Coords {
            theta1: 0.7,
            theta2: -1.2,
        },
        Coords {
            theta1: 1.1,
            theta2: -0.4,
        },
    );
    let mut group = c.benchmark_group("double_pendulum");
    group.bench_function("hand_written", |b| {
        b.iter(|| {
            double_pendulum_scene::closed_form(
                black_box(&sys),
                black_box([0.7, -1.2]),
                black_box([1.1, -0.4]),
            )
        })
    });
    group.bench_function("generated", |b| {
        b.iter(|| black_box(&sys).accelerations(black_box(&s)).unwrap())
    });
    group.finish();
}

/// The wedge and block by hand: the closed-form constant accelerations (Ẍ, d̈) from the parameters.
fn wedge_block_closed_form(p: &wedge_block_scene::wedge_block::WedgeBlock) -> [f64; 2] {
    let (s, c) = p.alpha.sin_cos();
    let den = p.wedge_mass + p.block_mass * s * s;
    [
        -p.block_mass * p.g * s * c / den,
        (p.wedge_mass + p.block_mass) * p.g * s / den,
    ]
}

fn wedge_block(c: &mut Criterion) {
    use wedge_block_scene::wedge_block::{Coords, State, WedgeBlock};
    let sys = WedgeBlock {
        wedge_mass: 3.0,
        block_mass: 1.0,
        alpha: 0.5,
        h: 1.0,
        g: 9.81,
    };
    let s = State::new(0.0, Coords { x: 0.1, d: 0.2 }, Coords { x: -0.3, d: 0.5 });
    let mut group = c.benchmark_group("wedge_block");
    group.bench_function("hand_written", |b| {
        b.iter(|| wedge_block_closed_form(black_box(&sys)))
    });
    group.bench_function("generated", |b| {
        b.iter(|| black_box(&sys).accelerations(black_box(&s)).unwrap())
    });
    group.finish();
}

criterion_group!(benches, double_pendulum, wedge_block);

/// Mean time of one benchmark from criterion's estimates of this run, in ns.
fn mean_ns(group: &str, bench: &str) -> Option<f64> {
    let dir = std::env::var_os("CARGO_TARGET_DIR")
        .map(std::path::PathBuf::from)
        .unwrap_or_else(|| std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("target"));
    let path = dir
        .join("criterion")
        .join(group)
        .join(bench)
        .join("new")
        .join("estimates.json");
    let text = std::fs::read_to_string(path).ok()?;
    let json: serde_json::Value = serde_json::from_str(&text).ok()?;
    json["mean"]["point_estimate"].as_f64()
}

fn main() {
    benches();
    Criterion::default().configure_from_args().final_summary();
    println!("\nratio generated / hand-written (mean time, same run):");
    for group in ["double_pendulum", "wedge_block"] {
        match (mean_ns(group, "generated"), mean_ns(group, "hand_written")) {
            (Some(g), Some(h)) => println!("  {group:<16} {g:8.1} ns / {h:8.1} ns = {:.2}×", g / h),
            _ => println!("  {group:<16} (no estimates: run without --test to measure)"),
        }
    }
}
