//! What each effect costs: the same pendulum bare, with linear drag (a velocity-dependent force:
//! one more pass over the forces), and with a time-dependent support (rheonomic: the two-pass
//! kinematics with ∂x/∂t). Each `accelerations` call is timed in one run; the summary prints the
//! increment of each variant over the bare pendulum.
//!
//! ```text
//! cargo bench --bench effects
//! ```

#[allow(dead_code)]
mod common;

use common::mean_ns;
use criterion::{criterion_group, Criterion};
use lagrange::prelude::*;
use std::hint::black_box;

#[mechanism]
pub mod bare {
    pub struct Coords {
        pub theta: f64,
    }

    pub struct Bare {
        pub m: f64,
        pub l: f64,
        pub g: f64,
    }

    #[particle(mass = m)]
    fn bob() -> Vec2 {
        vec2(theta.sin(), -theta.cos()) * l
    }

    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
}

#[mechanism]
pub mod drag {
    pub struct Coords {
        pub theta: f64,
    }

    pub struct Drag {
        pub m: f64,
        pub l: f64,
        pub g: f64,
        pub c: f64,
    }

    #[particle(mass = m)]
    fn bob() -> Vec2 {
        vec2(theta.sin(), -theta.cos()) * l
    }

    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }

    #[force(on = bob)]
    fn air() -> Vec2 {
        bob_dot * (-c)
    }
}

#[mechanism]
pub mod driven {
    pub struct Coords {
        pub theta: f64,
    }

    pub struct Driven {
        pub m: f64,
        pub l: f64,
        pub g: f64,
        pub a: f64,
        pub w: f64,
    }

    /// The support moves horizontally as a cos(w t).
    #[particle(mass = m)]
    fn bob() -> Vec2 {
        vec2(a * (w * t).cos() + l * theta.sin(), -l * theta.cos())
    }

    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
}

const VARIANTS: [&str; 3] = ["bare", "drag", "driven_support"];

fn effects(c: &mut Criterion) {
    let (m, l, g) = (1.0, 0.8, 9.81);
    let bare = bare::Bare { m, l, g };
    let drag = drag::Drag { m, l, g, c: 0.3 };
    let driven = driven::Driven {
        m,
        l,
        g,
        a: 0.1,
        w: 2.0,
    };
    let s_bare = bare::State::new(
        0.2,
        bare::Coords { theta: 0.7 },
        bare::Coords { theta: 1.1 },
    );
    let s_drag = drag::State::new(
        0.2,
        drag::Coords { theta: 0.7 },
        drag::Coords { theta: 1.1 },
    );
    let s_driven = driven::State::new(
        0.2,
        driven::Coords { theta: 0.7 },
        driven::Coords { theta: 1.1 },
    );
    let mut group = c.benchmark_group("pendulum_effects");
    group.bench_function(VARIANTS[0], |b| {
        b.iter(|| black_box(&bare).accelerations(black_box(&s_bare)).unwrap())
    });
    group.bench_function(VARIANTS[1], |b| {
        b.iter(|| black_box(&drag).accelerations(black_box(&s_drag)).unwrap())
    });
    group.bench_function(VARIANTS[2], |b| {
        b.iter(|| {
            black_box(&driven)
                .accelerations(black_box(&s_driven))
                .unwrap()
        })
    });
    group.finish();
}

criterion_group!(benches, effects);

fn main() {
    benches();
    Criterion::default().configure_from_args().final_summary();
    // A smoke run (`-- --test`) measures nothing: earlier runs' estimates would be stale.
    if std::env::args().any(|a| a == "--test") {
        return;
    }
    println!("\npendulum accelerations, mean ns per call and increment over bare (same run):");
    let Some(base) = mean_ns("pendulum_effects", VARIANTS[0]) else {
        println!("  (no estimates: run without --test to measure)");
        return;
    };
    for variant in VARIANTS {
        if let Some(t) = mean_ns("pendulum_effects", variant) {
            println!("  {variant:<15} {t:8.1} ns  (+{:.1} ns)", t - base);
        }
    }
}
