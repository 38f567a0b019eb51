//! A four-bar linkage swinging under gravity: a closed kinematic loop, which no choice of three
//! independent angles can describe without constraints. The crank (length l₁) is pivoted at
//! O = (0, 0), the rocker (l₃) at D = (d, 0), and the coupler (l₂) joins their tips; the coordinates
//! are the three bars' absolute angles (θ₁, θ₂, θ₃), each bar a uniform rod (I = m l²/12 about its
//! centre). Closing the loop — the coupler's far end B on the rocker's tip — is two holonomic
//! constraints, written on the bodies, which leave one degree of freedom.
//!
//! The bars are Grashof's crank–rocker (s + l = 1 + 3 ≤ p + q = 2 + 3: the shortest link, the
//! crank, turns fully; Grashof's criterion, e.g. Norton, *Design of Machinery*, 5th ed., §2.12), so
//! the motion never reaches a toggle position where the two rows would become dependent.
//!
//! What is checked is what has a closed form over a long run: the constraint forces do no work
//! (the joint moves with both bars), so E = T + V is conserved (Goldstein, Poole & Safko, 3rd ed.,
//! §2.4 and §2.7), and the loop must stay closed, g = ġ = 0. Newton's third law at the joint B is
//! checked too: the force of the constraint on the coupler's end is minus the one on the rocker's.

use crate::plot::{self, Series};
use crate::Check;
use lagrange::animation::Recorder;
use lagrange::constraints::{consistent_state, constraint_forces, constraint_rows};
use lagrange::prelude::*;
use std::path::Path;

#[mechanism]
pub mod four_bar {
    /// Absolute angles of the crank, the coupler and the rocker, from the x axis.
    pub struct Coords {
        pub theta1: f64,
        pub theta2: f64,
        pub theta3: f64,
    }

    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct FourBar {
        pub l1: f64,
        pub l2: f64,
        pub l3: f64,
        pub m1: f64,
        pub m2: f64,
        pub m3: f64,
        /// Distance between the two fixed pivots.
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

    /// Joint B, x: the coupler's far end on the rocker's tip.
    #[constraint]
    fn joint_b_x() -> f64 {
        coupler.point(vec2(0.5 * l2, 0.0)).x - rocker.point(vec2(0.5 * l3, 0.0)).x
    }

    /// Joint B, y.
    #[constraint]
    fn joint_b_y() -> f64 {
        coupler.point(vec2(0.5 * l2, 0.0)).y - rocker.point(vec2(0.5 * l3, 0.0)).y
    }
}

const SCENE: &str = "four-bar linkage";

/// Steps of the long run: 10⁵ in optimized builds (the gallery), 10⁴ in debug builds
/// (the tests), where 10⁵ would take minutes. The projection after every step keeps the loop
/// closed to round-off whatever the run length.
const LONG_RUN: usize = if cfg!(debug_assertions) {
    10_000
} else {
    100_000
};

/// The linkage of this scene (the crank–rocker of the module docs) and its consistent starting
/// state, shared with the benchmarks.
pub fn linkage() -> (four_bar::FourBar, four_bar::State) {
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
    // A rough guess: consistent_state closes the loop (mass-weighted least-norm correction) and
    // removes the velocity components that would open it.
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
    (sys, s)
}

pub fn run(plots: &Path) -> Vec<Check> {
    let (sys, mut s) = linkage();
    let e0 = sys.energy(&s).expect("energy");
    let h = 1e-3;
    let (mut closure, mut closure_rate, mut energy) = (0.0f64, 0.0f64, 0.0f64);
    let (mut energy_trace, mut coupler_curve) = (Vec::new(), Vec::new());
    // Each bar drawn as its two ends, marked on it; the fixed pivots O and D.
    let mut film = Recorder::new(&sys).title(SCENE);
    for (bar, half) in [("crank", sys.l1), ("coupler", sys.l2), ("rocker", sys.l3)] {
        film.mark(&format!("{bar} −"), bar, &[-0.5 * half, 0.0])
            .and_then(|f| f.mark(&format!("{bar} +"), bar, &[0.5 * half, 0.0]))
            .expect("a bar's ends");
    }
    film.fixed_point("O", &[0.0, 0.0])
        .and_then(|f| f.fixed_point("D", &[sys.d, 0.0])?.trail("coupler"))
        .expect("the fixed pivots");
    film.push(&sys, &s).expect("a finite state");
    for step in 1..=LONG_RUN {
        sys.step::<Rk4>(&mut s, h).expect("step");
        film.push(&sys, &s).expect("a finite state");
        let rows = constraint_rows(&sys, s.t, &s.q.to_array(), &s.v.to_array());
        for i in 0..2 {
            closure = closure.max(rows.value[i].abs());
            closure_rate = closure_rate.max(rows.rate[i].abs());
        }
        let de = sys.energy(&s).expect("energy") - e0;
        energy = energy.max(de.abs());
        if step % 100 == 0 {
            energy_trace.push((s.t, de / e0.abs()));
        }
        if step <= 10_000 && step % 10 == 0 {
            // The coupler's midpoint traces the linkage's coupler curve.
            let c = sys.bodies(&s).coupler.position;
            coupler_curve.push((c.x, c.y));
        }
    }
    let _ = film.write_html(plots.join("four_bar.html"));
    let f = constraint_forces(&sys, &s).expect("forces");
    // The joint's Cartesian force on each body's centre: entries (x, y, angle) per planar body, in
    // declaration order (crank 0–2, coupler 3–5, rocker 6–8).
    let third_law = (0..2).fold(0.0f64, |acc, i| {
        let on_coupler = f.cartesian[i][3 + i];
        let on_rocker = f.cartesian[i][6 + i];
        acc.max((on_coupler + on_rocker).abs() / on_coupler.abs().max(1.0))
    });
    println!(
        "{SCENE}, {LONG_RUN} RK4 steps h = {h}: loop closure |g| ≤ {closure:.2e} m, |ġ| ≤ {closure_rate:.2e} m/s, \
         energy drift {energy:.2e} J (E₀ = {e0:.4} J, relative {:.2e}); joint force at the end λ = ({:.4}, {:.4}) N, \
         crank angle {:.3} rad",
        energy / e0.abs(),
        f.multipliers[0],
        f.multipliers[1],
        s.q.theta1
    );
    let _ = plot::lines(
        &plots.join("four_bar_energy.svg"),
        "Four-bar linkage under gravity: relative energy error (RK4, h = 1e-3, projected)",
        "t",
        "(E − E₀)/|E₀|",
        &[Series::new("(E − E₀)/|E₀|", energy_trace)],
    );
    let _ = plot::lines(
        &plots.join("four_bar_coupler_curve.svg"),
        "Four-bar linkage: path of the coupler's midpoint over 10 s",
        "x",
        "y",
        &[Series::new("coupler midpoint", coupler_curve)],
    );
    let steps = format!(
        "{LONG_RUN} steps{}",
        if cfg!(debug_assertions) {
            " (debug build; 10⁵ in release)"
        } else {
            ""
        }
    );
    vec![
        // Projection onto g = 0 (Newton, to round-off) and ġ = 0 after every step: round-off of
        // positions ~ 3 m, independent of the run length; the bar is ≤ 1e-10.
        Check::new(
            SCENE,
            format!("max |g| loop closure over {steps} (m)"),
            closure,
            0.0,
            1e-10,
        ),
        Check::new(
            SCENE,
            format!("max |ġ| over {steps} (m/s)"),
            closure_rate,
            0.0,
            1e-10,
        ),
        // RK4's energy error per step ~ (hω)⁵·E with ω ≲ 6/s, and the velocity projection removes
        // the kinetic energy of an O(h⁵) drift: accumulated over 1e5 steps ≲ 1e-7·|E|.
        Check::new(
            SCENE,
            format!("max |E − E₀| / |E₀| over {steps}"),
            energy / e0.abs(),
            0.0,
            1e-7,
        ),
        // Both forces come from one multiplier times ±1 entries of the same gradient: exact up to
        // round-off of the dual-number gradient.
        Check::new(
            SCENE,
            "joint force on coupler + on rocker (third law, / max(|F|, 1 N))",
            third_law,
            0.0,
            1e-12,
        ),
    ]
}
