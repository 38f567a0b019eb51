//! `accelerations` of an N-link planar pendulum (equal links, gravity) for N = 1, 2, 4, 8, 16, 32, 64:
//! the generated code against a hand-written O(N²) closed form (M_jk = m l² (N − max(j,k))
//! cos(θⱼ − θₖ), solved with the library's general LDLᵀ, `Ldlt`; the generated code solves with
//! `linalg::solve_spd`, which takes closed forms up to four coordinates), in one run.
//!
//! ```text
//! cargo bench --bench chain
//! ```
//!
//! After criterion's report this prints ns per call, the ratio generated / hand-written and the
//! growth exponent log(t₂/t₁)/log(N₂/N₁) between successive N.

#[allow(dead_code)]
mod chains;

#[allow(dead_code)]
mod common;

use common::{interleave, load_average, mean_ns, print_interleaved};
use criterion::{criterion_group, Criterion};
use lagrange::linalg::Ldlt;
use lagrange::prelude::*;
use nalgebra::{SMatrix, SVector};
use std::hint::black_box;

const SIZES: [usize; 7] = [1, 2, 4, 8, 16, 32, 64];

/// The chain by hand: M q̈ = −∂V/∂q − (velocity products), O(N²) entries, one sin_cos per link.
fn closed_form<const N: usize>(m: f64, l: f64, g: f64, q: &[f64; N], v: &[f64; N]) -> [f64; N] {
    let sc: [(f64, f64); N] = std::array::from_fn(|j| q[j].sin_cos());
    let mut mass = SMatrix::<f64, N, N>::zeros();
    let mut force = SVector::<f64, N>::zeros();
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
    Ldlt::new(&mass)
        .expect("positive definite")
        .solve(&force)
        .into()
}

/// A configuration away from symmetry: θⱼ and θ̇ⱼ spread over links.
fn state<const N: usize>() -> ([f64; N], [f64; N]) {
    (
        std::array::from_fn(|j| 0.3 + 0.7 * ((j as f64) * 0.9).sin()),
        std::array::from_fn(|j| 0.5 * ((j as f64) * 1.3).cos()),
    )
}

macro_rules! chain_bench {
    ($name:ident, $module:ident, $ty:ident, $n:literal) => {
        fn $name(c: &mut Criterion) {
            use chains::$module::{$ty, Coords, State};
            let (m, l, g) = (1.0, 0.5, 9.81);
            let sys = $ty { m, l, g };
            let (q, v) = state::<$n>();
            let s = State::new(
                0.0,
                <Coords as Coordinates<$n>>::from_array(q),
                <Coords as Coordinates<$n>>::from_array(v),
            );
            let generated = sys.accelerations(&s).unwrap().to_array();
            let hand = closed_form::<$n>(m, l, g, &q, &v);
            for j in 0..$n {
                assert!(
                    (generated[j] - hand[j]).abs() <= 1e-8 * (1.0 + hand[j].abs()),
                    "link {j}: generated {} vs hand-written {}",
                    generated[j],
                    hand[j]
                );
            }
            // The parameters are opaque to the compiler on both sides (`black_box(&sys)` on the
            // generated one), so neither folds m, l, g into its constants.
            let hand_written = || {
                let (m, l, g) = black_box((m, l, g));
                closed_form::<$n>(m, l, g, black_box(&q), black_box(&v))
            };
            let mut group = c.benchmark_group(concat!("chain_", $n));
            group.bench_function("hand_written", |b| b.iter(hand_written));
            group.bench_function("generated", |b| {
                b.iter(|| black_box(&sys).accelerations(black_box(&s)).unwrap())
            });
            group.finish();
            interleave(
                concat!("N = ", $n),
                || {
                    black_box(hand_written());
                },
                || {
                    black_box(black_box(&sys).accelerations(black_box(&s)).unwrap());
                },
            );
            // Through the handle a simulation uses: parameters checked once.
            let checked = sys.validated().unwrap();
            interleave(
                "  validated once",
                || {
                    black_box(hand_written());
                },
                || {
                    black_box(black_box(&checked).accelerations(black_box(&s)).unwrap());
                },
            );
        }
    };
}

chain_bench!(chain1, chain1, Chain1, 1);
chain_bench!(chain2, chain2, Chain2, 2);
chain_bench!(chain4, chain4, Chain4, 4);
chain_bench!(chain8, chain8, Chain8, 8);
chain_bench!(chain16, chain16, Chain16, 16);
chain_bench!(chain32, chain32, Chain32, 32);
chain_bench!(chain64, chain64, Chain64, 64);

criterion_group!(benches, chain1, chain2, chain4, chain8, chain16, chain32, chain64);

fn main() {
    benches();
    Criterion::default().configure_from_args().final_summary();
    // A smoke run (`-- --test`) measures nothing: earlier runs' estimates would be stale.
    if std::env::args().any(|a| a == "--test") {
        return;
    }
    println!(
        "\nN-link pendulum, mean ns per accelerations call (same run; load average {}):",
        load_average()
    );
    println!(
        "  {:>3} {:>10} {:>10} {:>7} {:>9} {:>9}",
        "N", "generated", "by hand", "ratio", "exp gen", "exp hand"
    );
    let mut previous: Option<(usize, f64, f64)> = None;
    for n in SIZES {
        let group = format!("chain_{n}");
        let (Some(g), Some(h)) = (
            mean_ns(&group, "generated"),
            mean_ns(&group, "hand_written"),
        ) else {
            println!("  {n:>3} (no estimates: run without --test to measure)");
            continue;
        };
        let exponents = previous.map(|(n0, g0, h0)| {
            let r = (n as f64 / n0 as f64).ln();
            ((g / g0).ln() / r, (h / h0).ln() / r)
        });
        match exponents {
            Some((eg, eh)) => println!(
                "  {n:>3} {g:>10.1} {h:>10.1} {:>6.2}× {eg:>9.2} {eh:>9.2}",
                g / h
            ),
            None => println!(
                "  {n:>3} {g:>10.1} {h:>10.1} {:>6.2}× {:>9} {:>9}",
                g / h,
                "",
                ""
            ),
        }
        previous = Some((n, g, h));
    }
    if let (Some(g8), Some(g32)) = (
        mean_ns("chain_8", "generated"),
        mean_ns("chain_32", "generated"),
    ) {
        println!(
            "  exponent 8 → 32 (generated): {:.2}",
            (g32 / g8).ln() / 4f64.ln()
        );
    }
    if let (Some(h8), Some(h32)) = (
        mean_ns("chain_8", "hand_written"),
        mean_ns("chain_32", "hand_written"),
    ) {
        println!(
            "  exponent 8 → 32 (by hand):   {:.2}",
            (h32 / h8).ln() / 4f64.ln()
        );
    }
    print_interleaved("generated / hand-written");
}
