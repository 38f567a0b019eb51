//! A block (a point mass) on a rough ramp fixed at angle α, with Coulomb friction: kinetic μₖ while
//! it slides, static μₛ ≥ μₖ while it sticks. The block is free in the plane, (x, y); the ramp is a
//! unilateral contact c = n·r ≥ 0 with n = (−sin α, cos α), and friction acts on that contact with
//! the slip velocity s = t̂·ṙ, t̂ = (cos α, sin α) (positive up the ramp). As in the lecture, the
//! friction force is part of the contact's constraint force and does virtual work.
//!
//! Closed form (any first course; Kleppner & Kolenkow, 2nd ed., §3.x, the block on a rough
//! incline): the normal force is N = m g cos α, so
//! - sliding down: a = g (sin α − μₖ cos α) down the ramp;
//! - from rest: it stays at rest when tan α ≤ μₛ (static friction m g sin α ≤ μₛ N is enough);
//! - sent up the ramp with speed u: it decelerates at g (sin α + μₖ cos α), stops at
//!   t_s = u / (g (sin α + μₖ cos α)) after d_s = u² / (2 g (sin α + μₖ cos α)), and then sticks if
//!   tan α ≤ μₛ, or slides back with a = g (sin α − μₖ cos α).
//!
//! A [`Stepper`] locates the stop (slip velocity reaching 0) and then decides stick or slide once:
//! exactly one mode change, no chattering at the stick/slip boundary.

use crate::page::outline;
use crate::plot::{self, Series};
use crate::Check;
use lagrange::animation::Recorder;
use lagrange::constraints::{constraint_forces, RowMode};
use lagrange::prelude::*;
use std::path::Path;

#[mechanism]
pub mod rough_ramp {
    /// The block's position; the ramp's surface passes through the origin.
    pub struct Coords {
        pub x: f64,
        pub y: f64,
    }

    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct RoughRamp {
        pub m: f64,
        pub alpha: f64,
        pub g: f64,
        pub mu_k: f64,
        pub mu_s: f64,
    }

    #[particle(mass = m)]
    fn block() -> Vec2 {
        vec2(x, y)
    }

    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }

    /// The ramp pushes along its normal (−sin α, cos α) and cannot pull.
    #[unilateral]
    fn ramp() -> f64 {
        block.y * alpha.cos() - block.x * alpha.sin()
    }

    /// Coulomb friction on the ramp contact; slip velocity positive up the ramp.
    #[friction(on = ramp, kinetic = mu_k, stiction = mu_s)]
    fn ramp_friction() -> f64 {
        block_dot.x * alpha.cos() + block_dot.y * alpha.sin()
    }
}

const SCENE: &str = "block on a rough ramp";

pub fn run(plots: &Path) -> Vec<Check> {
    use rough_ramp::{Coords, RoughRamp, State};
    let (g, alpha, h) = (9.81, 0.5f64, 1e-3); // tan α = 0.546
    let (sn, cs) = alpha.sin_cos();
    let along = |s: &State| (s.q.x * cs + s.q.y * sn, s.v.x * cs + s.v.y * sn);
    let mut checks = Vec::new();

    // Sliding down from rest, tan α > μₛ.
    let sys = RoughRamp {
        m: 2.0,
        alpha,
        g,
        mu_k: 0.3,
        mu_s: 0.4,
    };
    let mut s = State::at_rest(Coords { x: 0.0, y: 0.0 });
    let mut stepper = Stepper::new(&sys, Rk4::with_step(h), &s).expect("stepper");
    let starts_sliding = stepper.contacts().mode().rows == [RowMode::Active, RowMode::SlipNegative];
    for _ in 0..1000 {
        stepper.step(f64::INFINITY).expect("step");
        s = stepper.state();
    }
    let a = g * (sn - sys.mu_k * cs);
    let (d, _) = along(&s);
    let f = constraint_forces(&sys, &s).expect("forces");
    let normal = sys.m * g * cs;
    // Constant acceleration: RK4 is exact, round-off over 1000 steps only.
    checks.push(Check::new(
        SCENE,
        format!(
            "from rest, μₛ < tan α: distance down the ramp at t = {:.0} s",
            s.t
        ),
        -d,
        0.5 * a * s.t * s.t,
        1e-12,
    ));
    // λ from the KKT solve against the closed forms at the same state: round-off.
    checks.push(Check::new(
        SCENE,
        "sliding: normal force λ = m g cos α",
        f.multipliers[0],
        normal,
        1e-12,
    ));
    checks.push(Check::new(
        SCENE,
        "sliding: friction force up the ramp μₖ m g cos α",
        f.multipliers[1],
        sys.mu_k * normal,
        1e-12,
    ));
    checks.push(Check::new(
        SCENE,
        "sliding from rest: starts sliding and never changes mode (1 = yes)",
        f64::from(u8::from(
            starts_sliding && stepper.mode_changes().is_empty(),
        )),
        1.0,
        0.0,
    ));

    // At rest, tan α ≤ μₛ.
    let sticky = RoughRamp {
        mu_k: 0.5,
        mu_s: 0.6,
        ..sys
    };
    let mut s = State::at_rest(Coords { x: 0.0, y: 0.0 });
    let mut stepper = Stepper::new(&sticky, Rk4::with_step(h), &s).expect("stepper");
    let starts_stuck = stepper.contacts().mode().rows == [RowMode::Active, RowMode::Stick];
    for _ in 0..2000 {
        stepper.step(f64::INFINITY).expect("step");
        s = stepper.state();
    }
    // Sticking is enforced as a velocity constraint: the block does not move, to round-off.
    checks.push(Check::new(
        SCENE,
        "from rest, tan α ≤ μₛ: |r| after 2 s (m)",
        s.q.x.hypot(s.q.y),
        0.0,
        1e-15,
    ));
    checks.push(Check::new(
        SCENE,
        "from rest, tan α ≤ μₛ: stuck, no mode change (1 = yes)",
        f64::from(u8::from(starts_stuck && stepper.mode_changes().is_empty())),
        1.0,
        0.0,
    ));

    // Sent up the ramp: stops, then sticks or slides back.
    let u = 2.0;
    let mut series = Vec::new();
    for (mu_k, mu_s, sticks) in [(0.5, 0.6, true), (0.2, 0.3, false)] {
        let sys = RoughRamp { mu_k, mu_s, ..sys };
        let label = if sticks { "sticks" } else { "slides back" };
        let mut s = State::new(
            0.0,
            Coords { x: 0.0, y: 0.0 },
            Coords {
                x: u * cs,
                y: u * sn,
            },
        );
        let mut stepper = Stepper::new(&sys, Rk4::with_step(h), &s).expect("stepper");
        let starts_up = stepper.contacts().mode().rows == [RowMode::Active, RowMode::SlipPositive];
        let up = g * (sn + mu_k * cs);
        let down = g * (sn - mu_k * cs);
        let (t_stop, d_stop) = (u / up, u * u / (2.0 * up));
        let exact = |t: f64| {
            if t <= t_stop {
                u * t - 0.5 * up * t * t
            } else if sticks {
                d_stop
            } else {
                d_stop - 0.5 * down * (t - t_stop).powi(2)
            }
        };
        let mut worst = 0.0f64;
        let (mut trace, mut closed) = (vec![(0.0, 0.0)], vec![(0.0, 0.0)]);
        let mut film = Recorder::new(&sys).title(format!("{SCENE}: sent up, {label}"));
        film.push(&sys, &s).expect("a finite state");
        for step in 1..=3000 {
            stepper.step(f64::INFINITY).expect("step");
            s = stepper.state();
            film.push(&sys, &s).expect("a finite state");
            let (d, _) = along(&s);
            worst = worst.max((d - exact(s.t)).abs());
            if step % 10 == 0 {
                trace.push((s.t, d));
                closed.push((s.t, exact(s.t)));
            }
        }
        if !sticks {
            // The ramp, over the stretch the block covers.
            let (lo, hi) = trace
                .iter()
                .fold((0.0f64, 0.0f64), |(lo, hi), &(_, d)| (lo.min(d), hi.max(d)));
            outline(
                &mut film,
                "ramp",
                &[&[lo * cs, lo * sn], &[hi * cs, hi * sn]],
                false,
            )
            .expect("the ramp");
            let _ = film.write_html(plots.join("rough_ramp.html"));
        }
        let events = stepper.mode_changes();
        println!(
            "{SCENE} (sent up, μₛ = {mu_s}, {label}): {} mode change(s) in 3000 steps, stop at t = {:.15} s \
             (exact {t_stop:.15}), |d − exact| ≤ {worst:.1e} m",
            events.len(),
            events.first().map_or(f64::NAN, |e| e.t)
        );
        let after = if sticks {
            RowMode::Stick
        } else {
            RowMode::SlipNegative
        };
        // The count of mode changes is the chattering test: one stop, decided once.
        checks.push(Check::new(
            SCENE,
            format!("sent up, μₛ = {mu_s} ({label}): mode changes in 3 s"),
            events.len() as f64,
            1.0,
            0.0,
        ));
        checks.push(Check::new(
            SCENE,
            format!("sent up, μₛ = {mu_s}: slip up, then {after:?} (1 = yes)"),
            f64::from(u8::from(
                starts_up && events.first().is_some_and(|e| e.to == after),
            )),
            1.0,
            0.0,
        ));
        // The event is located to 1e-13 relative on the step length, and the motion before it is
        // quadratic in t, which RK4 integrates exactly.
        checks.push(Check::new(
            SCENE,
            format!("sent up, μₛ = {mu_s}: stop time u / (g(sin α + μₖ cos α))"),
            events.first().map_or(f64::NAN, |e| e.t),
            t_stop,
            1e-12,
        ));
        // Piecewise quadratic motion, exact for RK4 on each piece: round-off only.
        checks.push(Check::new(
            SCENE,
            format!("sent up, μₛ = {mu_s}: max |d − closed form| over 3 s (m)"),
            worst,
            0.0,
            1e-11,
        ));
        series.push(Series::new(
            format!("μₛ = {mu_s}, simulated ({label})"),
            trace,
        ));
        series.push(Series::new(format!("μₛ = {mu_s}, closed form"), closed));
    }
    let _ = plot::lines(
        &plots.join("rough_ramp.svg"),
        "Block sent up a rough ramp (tan α = 0.55): stops, then sticks or slides back",
        "t",
        "distance up the ramp",
        &series,
    );
    checks
}
