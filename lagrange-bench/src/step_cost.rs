//! `cargo run --release -p lagrange-bench --bin step-cost`: the cost of one implicit step
//! (implicit midpoint, Gauss–Legendre 2) against one RK4 step on the double pendulum, the four-bar
//! linkage and the rolling wheel (the gallery's declarations and starts, h = 1e-3), in time and in
//! evaluations, Newton iterations, Jacobians and factorisations per step.
//!
//! Each method runs `STEPS` steps from the same start; the runs are repeated `ROUNDS` times,
//! interleaved (RK4, midpoint, Gauss–Legendre, RK4, …) so that a change of machine load hits every
//! method alike, and the minimum time per step over the rounds is reported with the ratio to RK4's
//! minimum. The implicit methods are timed twice: as a solver that keeps its Newton matrix between
//! steps (`step_with_memory`, what `FixedStepper` does), and through the one-step shorthand
//! `sys.step::<I>` (fresh memory: one Jacobian per step).

mod load;

use lagrange::constraints::consistent_state;
use lagrange::integrate::{ImplicitStepStats, NewtonMemory};
use lagrange::prelude::*;
use lagrange::{GaussLegendre2, ImplicitMidpoint};
use std::time::Instant;

#[mechanism]
pub mod double_pendulum {
    pub struct Coords {
        pub theta1: f64,
        pub theta2: f64,
    }

    pub struct DoublePendulum {
        pub m1: f64,
        pub m2: f64,
        pub l1: f64,
        pub l2: f64,
        pub g: f64,
    }

    #[particle(mass = m1)]
    fn bob1() -> Vec2 {
        vec2(theta1.sin(), -theta1.cos()) * l1
    }

    #[particle(mass = m2)]
    fn bob2() -> Vec2 {
        bob1 + vec2(theta2.sin(), -theta2.cos()) * l2
    }

    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
}

#[mechanism]
pub mod four_bar {
    pub struct Coords {
        pub theta1: f64,
        pub theta2: f64,
        pub theta3: f64,
    }

    pub struct FourBar {
        pub l1: f64,
        pub l2: f64,
        pub l3: f64,
        pub m1: f64,
        pub m2: f64,
        pub m3: f64,
        pub d: f64,
        pub g: f64,
    }

    #[rigid_body(mass = m1, inertia = m1 * l1 * l1 / 12.0)]
    fn crank() -> Planar {
        planar(vec2(theta1.cos(), theta1.sin()) * (0.5 * l1), theta1)
    }

    #[rigid_body(mass = m2, inertia = m2 * l2 * l2 / 12.0)]
    fn coupler() -> Planar {
        let tip = vec2(theta1.cos(), theta1.sin()) * l1;
        planar(tip + vec2(theta2.cos(), theta2.sin()) * (0.5 * l2), theta2)
    }

    #[rigid_body(mass = m3, inertia = m3 * l3 * l3 / 12.0)]
    fn rocker() -> Planar {
        planar(
            vec2(d, 0.0) + vec2(theta3.cos(), theta3.sin()) * (0.5 * l3),
            theta3,
        )
    }

    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }

    #[constraint]
    fn joint_b_x() -> f64 {
        coupler.point(vec2(0.5 * l2, 0.0)).x - rocker.point(vec2(0.5 * l3, 0.0)).x
    }

    #[constraint]
    fn joint_b_y() -> f64 {
        coupler.point(vec2(0.5 * l2, 0.0)).y - rocker.point(vec2(0.5 * l3, 0.0)).y
    }
}

#[mechanism]
pub mod rolling_wheel {
    pub struct Coords {
        pub x: f64,
        pub y: f64,
        pub phi: f64,
        pub theta: f64,
    }

    pub struct RollingWheel {
        pub m: f64,
        pub r: f64,
    }

    #[rigid_body(mass = m, inertia = [0.25 * m * r * r, 0.5 * m * r * r, 0.25 * m * r * r])]
    fn wheel() -> Spatial {
        spatial(vec3(x, y, r), rot_z(phi) * rot_y(theta))
    }

    #[velocity_constraint]
    fn roll_x() -> f64 {
        wheel_dot.linear.x - r * theta_dot * phi.cos()
    }

    #[velocity_constraint]
    fn roll_y() -> f64 {
        wheel_dot.linear.y - r * theta_dot * phi.sin()
    }
}

const STEPS: usize = 2000;
const ROUNDS: usize = 7;
const H: f64 = 1e-3;

/// Per-step averages of an implicit run.
#[derive(Default, Clone, Copy)]
struct Cost {
    iterations: f64,
    fields: f64,
    jacobians: f64,
    factorizations: f64,
    velocity: f64,
}

fn add(c: &mut Cost, s: ImplicitStepStats) {
    let n = STEPS as f64;
    c.iterations += s.iterations as f64 / n;
    c.fields += s.field_evaluations as f64 / n;
    c.jacobians += s.jacobian_evaluations as f64 / n;
    c.factorizations += s.factorizations as f64 / n;
    c.velocity += s.velocity_iterations as f64 / n;
}

/// `STEPS` implicit steps taken by `step`, and their statistics averaged per step.
fn implicit_steps(mut step: impl FnMut() -> ImplicitStepStats) -> Cost {
    let mut c = Cost::default();
    for _ in 0..STEPS {
        add(&mut c, step());
    }
    c
}

type Run<'a, C> = Box<dyn Fn(&mut State<C>) -> Cost + 'a>;

/// The five runs of the table, labelled: RK4, then the implicit methods with their Newton matrix
/// kept between steps (`step_with_memory`) and through the one-step shorthand (fresh memory).
fn runs<M: Mechanism<N>, const N: usize>(sys: &M) -> [(&'static str, Run<'_, M::Coords>); 5] {
    let rk4: Run<M::Coords> = Box::new(|s| {
        for _ in 0..STEPS {
            sys.step::<Rk4>(s, H).expect("RK4 step");
        }
        Cost::default()
    });
    let mid_kept: Run<M::Coords> = Box::new(|s| {
        let mut memory = NewtonMemory::<N, 1>::default();
        implicit_steps(|| ImplicitMidpoint::step_with_memory(sys, &mut memory, s, H).expect("step"))
    });
    let gl_kept: Run<M::Coords> = Box::new(|s| {
        let mut memory = NewtonMemory::<N, 2>::default();
        implicit_steps(|| GaussLegendre2::step_with_memory(sys, &mut memory, s, H).expect("step"))
    });
    let mid_fresh: Run<M::Coords> = Box::new(|s| {
        implicit_steps(|| ImplicitMidpoint::step_with_stats(sys, s, H).expect("step"))
    });
    let gl_fresh: Run<M::Coords> =
        Box::new(|s| implicit_steps(|| GaussLegendre2::step_with_stats(sys, s, H).expect("step")));
    [
        ("RK4", rk4),
        ("implicit midpoint, matrix kept", mid_kept),
        ("Gauss-Legendre 2, matrix kept", gl_kept),
        ("implicit midpoint, sys.step (fresh)", mid_fresh),
        ("Gauss-Legendre 2, sys.step (fresh)", gl_fresh),
    ]
}

/// `ROUNDS` interleaved rounds of `runs` from `start`: the minimum time per step of each run, and
/// its costs.
fn time_interleaved<C: Copy>(runs: &[(&str, Run<C>); 5], start: State<C>) -> ([f64; 5], [Cost; 5]) {
    let mut best = [f64::INFINITY; 5];
    let mut costs = [Cost::default(); 5];
    for _ in 0..ROUNDS {
        for (i, (_, run)) in runs.iter().enumerate() {
            let mut s = start;
            let t0 = Instant::now();
            costs[i] = std::hint::black_box(run(&mut s));
            best[i] = best[i].min(t0.elapsed().as_secs_f64() / STEPS as f64);
        }
    }
    (best, costs)
}

/// The markdown table of one mechanism: time per step, its ratio to RK4's, and costs per step.
fn print_table(name: &str, n: usize, labels: [&str; 5], best: [f64; 5], costs: [Cost; 5]) {
    println!(
        "\n### {name} (N = {n}, h = {H}, {STEPS} steps, min over {ROUNDS} interleaved rounds)\n"
    );
    println!("| method | µs per step | / RK4 | Newton iterations | field evaluations | Jacobians | factorisations | velocity-recovery iterations |");
    println!("|---|---|---|---|---|---|---|---|");
    for (i, label) in labels.iter().enumerate() {
        let c = costs[i];
        if i == 0 {
            println!(
                "| {label} | {:.2} | 1 | — | 4 (q̈) | — | — | — |",
                best[0] * 1e6
            );
        } else {
            println!(
                "| {label} | {:.2} | {:.2}× | {:.2} | {:.2} | {:.3} | {:.3} | {:.2} |",
                best[i] * 1e6,
                best[i] / best[0],
                c.iterations,
                c.fields,
                c.jacobians,
                c.factorizations,
                c.velocity
            );
        }
    }
}

fn measure<M: Mechanism<N>, const N: usize>(name: &str, sys: &M, start: State<M::Coords>) {
    let runs = runs(sys);
    let (best, costs) = time_interleaved(&runs, start);
    print_table(name, N, runs.map(|(label, _)| label), best, costs);
}

fn measure_double_pendulum() {
    use double_pendulum::{Coords, DoublePendulum, State};
    let sys = DoublePendulum {
        m1: 1.0,
        m2: 1.0,
        l1: 1.0,
        l2: 1.0,
        g: 9.81,
    };
    let s = State::at_rest(Coords {
        theta1: 1.0,
        theta2: 0.5,
    });
    measure("double pendulum", &sys, s);
}

fn measure_four_bar() {
    use four_bar::{Coords, FourBar, State};
    let sys = FourBar {
        l1: 1.0,
        l2: 3.0,
        l3: 2.0,
        m1: 1.0,
        m2: 2.0,
        m3: 1.5,
        d: 3.0,
        g: 9.81,
    };
    let guess = State::new(
        0.0,
        Coords {
            theta1: 1.0,
            theta2: 0.2,
            theta3: 1.6,
        },
        Coords {
            theta1: 3.0,
            theta2: 0.0,
            theta3: 0.0,
        },
    );
    let s = consistent_state(&sys, &guess).expect("consistent initial state");
    measure("four-bar linkage", &sys, s);
}

fn measure_rolling_wheel() {
    use rolling_wheel::{Coords, RollingWheel, State};
    let w = RollingWheel { m: 2.0, r: 0.3 };
    let (big_omega, phi0, omega) = (5.0f64, 0.4f64, 2.0f64);
    let q0 = Coords {
        x: 0.1,
        y: -0.2,
        phi: phi0,
        theta: 0.0,
    };
    let v0 = Coords {
        x: w.r * big_omega * phi0.cos(),
        y: w.r * big_omega * phi0.sin(),
        phi: omega,
        theta: big_omega,
    };
    measure("rolling wheel", &w, State::new(0.0, q0, v0));
}

fn main() {
    println!(
        "load average (1, 5, 15 min) at start: {}",
        load::load_averages(" ").unwrap_or_default()
    );
    measure_double_pendulum();
    measure_four_bar();
    measure_rolling_wheel();
    println!(
        "\nload average at end: {}",
        load::load_averages(" ").unwrap_or_default()
    );
}
