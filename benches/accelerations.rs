//! `accelerations` of generated mechanisms against hand-written closed forms, in one run: the simple
//! pendulum, the double pendulum, the wedge and block, and the pendulum on a cart; and two
//! constrained mechanisms (the four-bar, the Cartesian pendulum) against their KKT systems written
//! out by hand (`common/constrained.rs`).
//!
//! ```text
//! cargo bench --bench accelerations
//! ```
//!
//! After criterion's own report this prints, per mechanism, the ratio of the generated code's mean
//! time to the hand-written closed form's (the baseline), from the same run's estimates; and an
//! interleaved ratio that is steadier on a shared machine: 41 rounds, each timing a batch of calls of
//! one side and then the same number of calls of the other (the order alternating from round to
//! round), reported as the median of the per-round ratios with its interquartile range. A drift of the
//! machine's speed between criterion's two measurements (seconds apart) moves the first figure; within
//! a round (milliseconds) it hits both sides alike. "validated once" is the same call through
//! `sys.validated()`, the handle a simulation uses: parameters checked when it was made, the state
//! on every call.

use lagrange_gallery::scenes::cartesian_pendulum as cartesian_pendulum_scene;
use lagrange_gallery::scenes::double_pendulum as double_pendulum_scene;
use lagrange_gallery::scenes::four_bar as four_bar_scene;
use lagrange_gallery::scenes::wedge_block as wedge_block_scene;

#[allow(dead_code)]
mod common;

use common::{interleave, mean_ns, print_interleaved, smoke_run};
use criterion::{criterion_group, Criterion};
use lagrange::evaluation::Evaluate as _;
use lagrange::prelude::*;
use std::hint::black_box;

#[mechanism]
pub mod pendulum {
    pub struct Coords {
        pub theta: f64,
    }

    pub struct Pendulum {
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
pub mod cart_pendulum {
    /// x: the cart's position on its rail; theta: the pendulum's angle from the downward vertical.
    pub struct Coords {
        pub x: f64,
        pub theta: f64,
    }

    pub struct CartPendulum {
        pub cart_mass: f64,
        pub m: f64,
        pub l: f64,
        pub g: f64,
    }

    #[particle(mass = cart_mass)]
    fn cart() -> Vec2 {
        vec2(x, 0.0)
    }

    #[particle(mass = m)]
    fn bob() -> Vec2 {
        cart + vec2(theta.sin(), -theta.cos()) * l
    }

    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
}

/// The simple pendulum by hand: θ̈ = −(g/l) sin θ.
fn pendulum_closed_form(p: &pendulum::Pendulum, q: [f64; 1]) -> [f64; 1] {
    [-p.g / p.l * q[0].sin()]
}

/// The pendulum on a cart by hand (cart mass M, bob m on a massless rod l; e.g. Tedrake,
/// *Underactuated Robotics*, ch. 3, with no applied force):
/// ẍ = m s (l θ̇² + g c) / (M + m s²),  θ̈ = −(m l θ̇² s c + (M + m) g s) / (l (M + m s²)).
fn cart_pendulum_closed_form(
    p: &cart_pendulum::CartPendulum,
    q: [f64; 2],
    v: [f64; 2],
) -> [f64; 2] {
    let (s, c) = q[1].sin_cos();
    let (big_m, m, l, g) = (p.cart_mass, p.m, p.l, p.g);
    let den = big_m + m * s * s;
    [
        m * s * (l * v[1] * v[1] + g * c) / den,
        -(m * l * v[1] * v[1] * s * c + (big_m + m) * g * s) / (l * den),
    ]
}

/// The hand-written `baseline` against the generated `accelerations` of `checked`'s parameters at
/// `s`, and through the validated handle itself: criterion's group `name` (benches `hand_written` and
/// `generated`), then the interleaved ratios.
fn compare<M: lagrange::mechanism::Dynamics<N>, const N: usize, R>(
    c: &mut Criterion,
    name: &'static str,
    checked: &Validated<M>,
    s: &State<M::Coords>,
    baseline: impl Fn() -> R + Copy,
) {
    let sys = checked.get();
    let mut group = c.benchmark_group(name);
    group.bench_function("hand_written", |b| b.iter(baseline));
    group.bench_function("generated", |b| {
        b.iter(|| black_box(sys).accelerations(black_box(s)).unwrap())
    });
    group.finish();
    let baseline = move || {
        black_box(baseline());
    };
    interleave(name, baseline, || {
        black_box(black_box(sys).accelerations(black_box(s)).unwrap());
    });
    interleave("  validated once", baseline, || {
        black_box(black_box(checked).accelerations(black_box(s)).unwrap());
    });
}

fn simple_pendulum(c: &mut Criterion) {
    use pendulum::{Coords, Pendulum, State};
    let checked = Pendulum {
        m: 1.0,
        l: 0.8,
        g: 9.81,
    }
    .validated()
    .unwrap();
    let sys = checked.get();
    let s = State::new(0.0, Coords { theta: 0.7 }, Coords { theta: 1.1 });
    let generated = sys.accelerations(&s).unwrap().theta;
    assert!((generated - pendulum_closed_form(sys, [0.7])[0]).abs() < 1e-12);
    compare(c, "pendulum", &checked, &s, || {
        pendulum_closed_form(black_box(sys), black_box([0.7]))
    });
}

fn pendulum_on_cart(c: &mut Criterion) {
    use cart_pendulum::{CartPendulum, Coords, State};
    let checked = CartPendulum {
        cart_mass: 2.0,
        m: 1.0,
        l: 0.8,
        g: 9.81,
    }
    .validated()
    .unwrap();
    let sys = checked.get();
    let (q, v) = ([0.1, 0.7], [-0.3, 1.1]);
    let s = State::new(0.0, Coords::from_array(q), Coords::from_array(v));
    let generated = sys.accelerations(&s).unwrap();
    let hand = cart_pendulum_closed_form(sys, q, v);
    assert!((generated.x - hand[0]).abs() < 1e-12 && (generated.theta - hand[1]).abs() < 1e-12);
    compare(c, "cart_pendulum", &checked, &s, || {
        cart_pendulum_closed_form(black_box(sys), black_box(q), black_box(v))
    });
}

fn double_pendulum(c: &mut Criterion) {
    use double_pendulum_scene::double_pendulum::{Coords, DoublePendulum, State};
    let checked = DoublePendulum {
        m1: 1.0,
        m2: 1.3,
        l1: 1.0,
        l2: 0.8,
        g: 9.81,
    }
    .validated()
    .unwrap();
    let sys = checked.get();
    let (q, v) = ([0.7, -1.2], [1.1, -0.4]);
    let s = State::new(0.0, Coords::from_array(q), Coords::from_array(v));
    compare(c, "double_pendulum", &checked, &s, || {
        double_pendulum_scene::closed_form(black_box(sys), black_box(q), black_box(v))
    });
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

/// The wedge and block by the generated code's own method, written out by hand in `f64`: the
/// Jacobian rows of wedge (X, 0) and block (X + d cos α, h − d sin α), M = Jᵀ diag(μ) J,
/// 𝓕 = Jᵀ w for the weights w = (0, −M g, 0, −m g), and the 2×2 solve — with every zero of J known
/// and skipped, no dual numbers and no checks. The floor for any code that assembles and solves
/// M q̈ = 𝓕 rather than using the closed form; its ratio to the closed form says how much of the
/// generated code's ratio is the method and how much is the machinery.
fn wedge_block_assembled(p: &wedge_block_scene::wedge_block::WedgeBlock) -> [f64; 2] {
    let (s, c) = p.alpha.sin_cos();
    let (big_m, m) = (p.wedge_mass, p.block_mass);
    // Rows: wedge x = [1, 0]; block x = [1, c]; block y = [0, −s].
    let m00 = big_m + m;
    let m10 = m * c;
    let m11 = m * (c * c + s * s);
    let (f0, f1) = (0.0, m * p.g * s);
    let inv_det = 1.0 / (m00 * m11 - m10 * m10);
    [
        (m11 * f0 - m10 * f1) * inv_det,
        (m00 * f1 - m10 * f0) * inv_det,
    ]
}

fn wedge_block(c: &mut Criterion) {
    use wedge_block_scene::wedge_block::{Coords, State, WedgeBlock};
    let checked = WedgeBlock {
        wedge_mass: 3.0,
        block_mass: 1.0,
        alpha: 0.5,
        h: 1.0,
        g: 9.81,
    }
    .validated()
    .unwrap();
    let sys = checked.get();
    let (q, v) = ([0.1, 0.2], [-0.3, 0.5]);
    let s = State::new(0.0, Coords::from_array(q), Coords::from_array(v));
    let closed_form = || wedge_block_closed_form(black_box(sys));
    compare(c, "wedge_block", &checked, &s, closed_form);
    // Without the parameter and state checks (what integrators call between their once-a-step
    // checks), and the method by hand: where the ratio above comes from.
    let unchecked = || {
        black_box(
            black_box(sys)
                .accelerations_at(0.0, black_box(&q), black_box(&v))
                .unwrap(),
        );
    };
    let assembled = || {
        black_box(wedge_block_assembled(black_box(sys)));
    };
    let mut group = c.benchmark_group("wedge_block_parts");
    group.bench_function("hand_written", |b| b.iter(closed_form));
    group.bench_function("generated_unchecked", |b| b.iter(unchecked));
    group.bench_function("hand_assembled", |b| b.iter(assembled));
    group.finish();
    let closed_form = move || {
        black_box(closed_form());
    };
    interleave("  unchecked", closed_form, unchecked);
    interleave("  hand-assembled", closed_form, assembled);
}

/// The four-bar of the gallery at its consistent start, against its KKT system by hand.
fn four_bar(c: &mut Criterion) {
    use common::constrained;
    let (params, s) = four_bar_scene::linkage();
    let checked = params.validated().unwrap();
    let sys = checked.get();
    let hand = constrained::FourBar {
        l: [sys.l1, sys.l2, sys.l3],
        m: [sys.m1, sys.m2, sys.m3],
        d: sys.d,
        g: sys.g,
    };
    let (q, v) = (s.q.to_array(), s.v.to_array());
    let generated = sys.accelerations(&s).unwrap().to_array();
    let by_hand = constrained::four_bar(&hand, q, v);
    // Two solves of the same KKT system: a few ulps of the condition number times |q̈| ≈ 10.
    for j in 0..3 {
        assert!(
            (generated[j] - by_hand[j]).abs() < 1e-10,
            "{generated:?} vs {by_hand:?}"
        );
    }
    compare(c, "four_bar", &checked, &s, || {
        constrained::four_bar(black_box(&hand), black_box(q), black_box(v))
    });
}

/// The Cartesian pendulum, against its KKT system by hand.
fn cartesian_pendulum(c: &mut Criterion) {
    use cartesian_pendulum_scene::cartesian_pendulum::{CartesianPendulum, Coords, State};
    use common::constrained;
    let checked = CartesianPendulum {
        m: 1.0,
        l: 0.8,
        g: 9.81,
    }
    .validated()
    .unwrap();
    let sys = checked.get();
    let hand = constrained::CartesianPendulum {
        m: sys.m,
        l: sys.l,
        g: sys.g,
    };
    let (th, w) = (0.7f64, 1.1f64);
    let (q, v) = (
        [sys.l * th.sin(), -sys.l * th.cos()],
        [sys.l * w * th.cos(), sys.l * w * th.sin()],
    );
    let s = State::new(0.0, Coords::from_array(q), Coords::from_array(v));
    let generated = sys.accelerations(&s).unwrap();
    let by_hand = constrained::cartesian_pendulum(&hand, q, v);
    // The same formula rounded differently: a few ulps of |q̈| ≈ 10. The validated handle's q̈
    // (from the constants it prepared: M's factors, M⁻¹Aᵀw) is held to the same.
    let validated = checked.accelerations(&s).unwrap();
    for a in [generated, validated] {
        assert!((a.x - by_hand[0]).abs() < 1e-12 && (a.y - by_hand[1]).abs() < 1e-12);
    }
    compare(c, "cartesian_pendulum", &checked, &s, || {
        constrained::cartesian_pendulum(black_box(&hand), black_box(q), black_box(v))
    });
}

criterion_group!(
    benches,
    simple_pendulum,
    double_pendulum,
    wedge_block,
    pendulum_on_cart,
    four_bar,
    cartesian_pendulum
);

fn main() {
    benches();
    Criterion::default().configure_from_args().final_summary();
    // A smoke run (`-- --test`) measures nothing: earlier runs' estimates would be stale.
    if smoke_run() {
        return;
    }
    println!("\nratio generated / hand-written (mean time, same run):");
    for group in [
        "pendulum",
        "double_pendulum",
        "wedge_block",
        "cart_pendulum",
        "four_bar",
        "cartesian_pendulum",
    ] {
        match (mean_ns(group, "generated"), mean_ns(group, "hand_written")) {
            (Some(g), Some(h)) => println!("  {group:<16} {g:8.1} ns / {h:8.1} ns = {:.2}×", g / h),
            _ => println!("  {group:<16} (no estimates: run without --test to measure)"),
        }
    }
    for variant in ["generated_unchecked", "hand_assembled"] {
        if let (Some(g), Some(h)) = (
            mean_ns("wedge_block_parts", variant),
            mean_ns("wedge_block_parts", "hand_written"),
        ) {
            println!("    {variant:<20} {g:8.1} ns / {h:8.1} ns = {:.2}×", g / h);
        }
    }
    print_interleaved("ratio to the hand-written closed form");
}
