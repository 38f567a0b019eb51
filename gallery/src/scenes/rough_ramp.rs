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
use lagrange::Fixed;
use rough_ramp::{Coords, RoughRamp, State};
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

// Gravity, the ramp's angle (tan α = 0.546) and the RK4 step of every run.
const G: f64 = 9.81;
const ALPHA: f64 = 0.5;
const STEP: f64 = 1e-3;
/// The speed up the ramp the block is sent with.
const SENT_UP_SPEED: f64 = 2.0;

pub fn run(plots: &Path) -> Vec<Check> {
    // tan α > μₛ: the block cannot rest on this ramp.
    let slippery = RoughRamp {
        m: 2.0,
        alpha: ALPHA,
        g: G,
        mu_k: 0.3,
        mu_s: 0.4,
    };
    let mut checks = slides_from_rest(&slippery);
    checks.extend(rests(&RoughRamp {
        mu_k: 0.5,
        mu_s: 0.6,
        ..slippery
    }));
    let mut series = Vec::new();
    for (mu_k, mu_s, sticks) in [(0.5, 0.6, true), (0.2, 0.3, false)] {
        let sys = RoughRamp {
            mu_k,
            mu_s,
            ..slippery
        };
        checks.extend(sent_up(&sys, sticks, plots, &mut series));
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

/// The block's distance up the ramp, t̂·r.
fn distance_up(s: &State) -> f64 {
    let (sn, cs) = ALPHA.sin_cos();
    s.q.x * cs + s.q.y * sn
}

/// A stepper for `sys` from `s0`, with the RK4 step of every run.
fn stepper(sys: &RoughRamp, s0: State) -> Stepper<'_, RoughRamp, Fixed<Rk4>, 2> {
    Stepper::new(sys, Rk4::with_step(STEP), &s0).expect("stepper")
}

/// Takes `steps` steps, calling `observe` with the step's number (from 1) and the state it reaches;
/// returns the last state.
fn advance(
    stepper: &mut Stepper<'_, RoughRamp, Fixed<Rk4>, 2>,
    steps: usize,
    mut observe: impl FnMut(usize, &State),
) -> State {
    let mut s = stepper.state();
    for step in 1..=steps {
        stepper.step(f64::INFINITY).expect("step");
        s = stepper.state();
        observe(step, &s);
    }
    s
}

/// Released from rest with tan α > μₛ: slides down at a = g (sin α − μₖ cos α), N = m g cos α.
fn slides_from_rest(sys: &RoughRamp) -> Vec<Check> {
    let (sn, cs) = ALPHA.sin_cos();
    let mut stepper = stepper(sys, State::at_rest(Coords { x: 0.0, y: 0.0 }));
    let starts_sliding = stepper.contacts().mode().rows == [RowMode::Active, RowMode::SlipNegative];
    let s = advance(&mut stepper, 1000, |_, _| {});
    let a = G * (sn - sys.mu_k * cs);
    let d = distance_up(&s);
    let f = constraint_forces(sys, &s).expect("forces");
    let normal = sys.m * G * cs;
    vec![
        // Constant acceleration: RK4 is exact, round-off over 1000 steps only.
        Check::new(
            SCENE,
            format!(
                "from rest, μₛ < tan α: distance down the ramp at t = {:.0} s",
                s.t
            ),
            -d,
            0.5 * a * s.t * s.t,
            1e-12,
        ),
        // λ from the KKT solve against the closed forms at the same state: round-off.
        Check::new(
            SCENE,
            "sliding: normal force λ = m g cos α",
            f.multipliers[0],
            normal,
            1e-12,
        ),
        Check::new(
            SCENE,
            "sliding: friction force up the ramp μₖ m g cos α",
            f.multipliers[1],
            sys.mu_k * normal,
            1e-12,
        ),
        Check::new(
            SCENE,
            "sliding from rest: starts sliding and never changes mode (1 = yes)",
            f64::from(u8::from(
                starts_sliding && stepper.mode_changes().is_empty(),
            )),
            1.0,
            0.0,
        ),
    ]
}

/// Released from rest with tan α ≤ μₛ: static friction holds the block.
fn rests(sys: &RoughRamp) -> Vec<Check> {
    let mut stepper = stepper(sys, State::at_rest(Coords { x: 0.0, y: 0.0 }));
    let starts_stuck = stepper.contacts().mode().rows == [RowMode::Active, RowMode::Stick];
    let s = advance(&mut stepper, 2000, |_, _| {});
    vec![
        // Sticking is enforced as a velocity constraint: the block does not move, to round-off.
        Check::new(
            SCENE,
            "from rest, tan α ≤ μₛ: |r| after 2 s (m)",
            s.q.x.hypot(s.q.y),
            0.0,
            1e-15,
        ),
        Check::new(
            SCENE,
            "from rest, tan α ≤ μₛ: stuck, no mode change (1 = yes)",
            f64::from(u8::from(starts_stuck && stepper.mode_changes().is_empty())),
            1.0,
            0.0,
        ),
    ]
}

/// The closed-form distance up the ramp after sending the block up at speed u: decelerating at
/// g (sin α + μₖ cos α) until t_s, then held (`sticks`) or sliding back at g (sin α − μₖ cos α).
/// Returns t_s and d(t).
fn sent_up_closed_form(sys: &RoughRamp, sticks: bool) -> (f64, impl Fn(f64) -> f64) {
    let (sn, cs) = ALPHA.sin_cos();
    let u = SENT_UP_SPEED;
    let up = G * (sn + sys.mu_k * cs);
    let down = G * (sn - sys.mu_k * cs);
    let (t_stop, d_stop) = (u / up, u * u / (2.0 * up));
    let distance = move |t: f64| {
        if t <= t_stop {
            u * t - 0.5 * up * t * t
        } else if sticks {
            d_stop
        } else {
            d_stop - 0.5 * down * (t - t_stop).powi(2)
        }
    };
    (t_stop, distance)
}

/// What a run sent up the ramp measured.
struct SentUp {
    starts_up: bool,
    mode_changes: usize,
    /// The first mode change: its time (NaN if none) and the mode it enters.
    stop: f64,
    stops_into: Option<RowMode>,
    /// Distance up the ramp every 10 steps, simulated and closed form.
    trace: Vec<(f64, f64)>,
    closed: Vec<(f64, f64)>,
    /// max |d − closed form| over every step.
    worst: f64,
}

/// Sends the block up the ramp for 3 s against the closed form; the sliding-back run is filmed.
fn simulate_sent_up(sys: &RoughRamp, sticks: bool, plots: &Path) -> SentUp {
    let (sn, cs) = ALPHA.sin_cos();
    let u = SENT_UP_SPEED;
    let label = if sticks { "sticks" } else { "slides back" };
    let s0 = State::new(
        0.0,
        Coords { x: 0.0, y: 0.0 },
        Coords {
            x: u * cs,
            y: u * sn,
        },
    );
    let mut stepper = stepper(sys, s0);
    let starts_up = stepper.contacts().mode().rows == [RowMode::Active, RowMode::SlipPositive];
    let (_, exact) = sent_up_closed_form(sys, sticks);
    let mut worst = 0.0f64;
    let (mut trace, mut closed) = (vec![(0.0, 0.0)], vec![(0.0, 0.0)]);
    let mut film = Recorder::new(sys).title(format!("{SCENE}: sent up, {label}"));
    film.push(sys, &s0).expect("a finite state");
    advance(&mut stepper, 3000, |step, s| {
        film.push(sys, s).expect("a finite state");
        let d = distance_up(s);
        worst = worst.max((d - exact(s.t)).abs());
        if step % 10 == 0 {
            trace.push((s.t, d));
            closed.push((s.t, exact(s.t)));
        }
    });
    if !sticks {
        write_film(&mut film, &trace, plots);
    }
    let events = stepper.mode_changes();
    SentUp {
        starts_up,
        mode_changes: events.len(),
        stop: events.first().map_or(f64::NAN, |e| e.t),
        stops_into: events.first().map(|e| e.to),
        trace,
        closed,
        worst,
    }
}

/// Sent up the ramp: stops once, then sticks (`sticks`) or slides back. Adds the simulated and
/// closed-form distances to `series`.
fn sent_up(sys: &RoughRamp, sticks: bool, plots: &Path, series: &mut Vec<Series>) -> Vec<Check> {
    let mu_s = sys.mu_s;
    let label = if sticks { "sticks" } else { "slides back" };
    let (t_stop, _) = sent_up_closed_form(sys, sticks);
    let run = simulate_sent_up(sys, sticks, plots);
    let (stop, worst) = (run.stop, run.worst);
    println!(
        "{SCENE} (sent up, μₛ = {mu_s}, {label}): {} mode change(s) in 3000 steps, stop at t = {stop:.15} s \
         (exact {t_stop:.15}), |d − exact| ≤ {worst:.1e} m",
        run.mode_changes,
    );
    let after = if sticks {
        RowMode::Stick
    } else {
        RowMode::SlipNegative
    };
    series.push(Series::new(
        format!("μₛ = {mu_s}, simulated ({label})"),
        run.trace,
    ));
    series.push(Series::new(format!("μₛ = {mu_s}, closed form"), run.closed));
    vec![
        // The count of mode changes is the chattering test: one stop, decided once.
        Check::new(
            SCENE,
            format!("sent up, μₛ = {mu_s} ({label}): mode changes in 3 s"),
            run.mode_changes as f64,
            1.0,
            0.0,
        ),
        Check::new(
            SCENE,
            format!("sent up, μₛ = {mu_s}: slip up, then {after:?} (1 = yes)"),
            f64::from(u8::from(run.starts_up && run.stops_into == Some(after))),
            1.0,
            0.0,
        ),
        // The event is located to 1e-13 relative on the step length, and the motion before it is
        // quadratic in t, which RK4 integrates exactly.
        Check::new(
            SCENE,
            format!("sent up, μₛ = {mu_s}: stop time u / (g(sin α + μₖ cos α))"),
            stop,
            t_stop,
            1e-12,
        ),
        // Piecewise quadratic motion, exact for RK4 on each piece: round-off only.
        Check::new(
            SCENE,
            format!("sent up, μₛ = {mu_s}: max |d − closed form| over 3 s (m)"),
            worst,
            0.0,
            1e-11,
        ),
    ]
}

/// Draws the ramp over the stretch the block covers (`trace`: (t, distance up)) and writes the film.
fn write_film(film: &mut Recorder<RoughRamp, 2>, trace: &[(f64, f64)], plots: &Path) {
    let (sn, cs) = ALPHA.sin_cos();
    let (lo, hi) = trace
        .iter()
        .fold((0.0f64, 0.0f64), |(lo, hi), &(_, d)| (lo.min(d), hi.max(d)));
    outline(
        film,
        "ramp",
        &[&[lo * cs, lo * sn], &[hi * cs, hi * sn]],
        false,
    )
    .expect("the ramp");
    let _ = film.write_html(plots.join("rough_ramp.html"));
}
