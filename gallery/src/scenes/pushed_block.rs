//! A block (a point mass) on a rough incline, pushed sideways: a constant horizontal force P along
//! the incline's level direction. Friction acts in the incline's tangent plane (`#[friction]` with a
//! `Vec2` slip velocity: the Coulomb cone).
//!
//! Closed form: in the tangent plane (level direction e₁, up-slope direction e₂) the applied force
//! is (P, −m g sin α), of magnitude R = √(P² + (m g sin α)²), and the normal force is
//! N = m g cos α. Static friction can supply any tangential force up to μₛ N, so
//! - R ≤ μₛ N: the block stays at rest;
//! - R > μₛ N: it slides from rest along R's direction (friction, −μₖ N along the slip, is then
//!   parallel to the applied force, so the direction never changes) with acceleration
//!   a = (R − μₖ N)/m.
//!
//! Coulomb's law in the cone form: Stewart, "Rigid-body dynamics with friction and impact", SIAM
//! Review 42(1), 2000 (|F_t| ≤ μN; F_t = −μN v_t/|v_t| while sliding).

use crate::page::outline;
use crate::plot::{self, Series};
use crate::Check;
use lagrange::animation::Recorder;
use lagrange::constraints::RowMode;
use lagrange::prelude::*;
use lagrange::Fixed;
use std::path::Path;

#[mechanism]
pub mod pushed_block {
    /// The block's position; the incline's surface passes through the origin.
    pub struct Coords {
        pub x: f64,
        pub y: f64,
        pub z: f64,
    }

    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct PushedBlock {
        pub m: f64,
        pub g: f64,
        /// The incline rises along y at angle α; x is level.
        pub alpha: f64,
        pub mu_k: f64,
        pub mu_s: f64,
        /// The push, along the level direction x.
        pub push: f64,
    }

    #[particle(mass = m)]
    fn block() -> Vec3 {
        vec3(x, y, z)
    }

    #[gravity]
    fn down() -> Vec3 {
        vec3(0.0, 0.0, -g)
    }

    #[force(on = block)]
    fn sideways() -> Vec3 {
        vec3(push, 0.0, 0.0)
    }

    /// The incline pushes along its normal (0, −sin α, cos α) and cannot pull.
    #[unilateral]
    fn incline() -> f64 {
        block.z * alpha.cos() - block.y * alpha.sin()
    }

    /// Friction in the incline's plane: slip along the level direction and up the slope.
    #[friction(on = incline, kinetic = mu_k, stiction = mu_s)]
    fn rub() -> Vec2 {
        vec2(
            block_dot.x,
            block_dot.y * alpha.cos() + block_dot.z * alpha.sin(),
        )
    }
}

use pushed_block::{Coords, PushedBlock, State};

const SCENE: &str = "block pushed sideways on a rough incline";

/// The closed form: `None` if the block sticks, else its acceleration and its direction (level,
/// up-slope components of the unit vector).
pub fn slides(sys: &PushedBlock) -> Option<(f64, (f64, f64))> {
    let (sn, cs) = sys.alpha.sin_cos();
    let (along, up) = (sys.push, -sys.m * sys.g * sn);
    let resultant = along.hypot(up);
    let normal = sys.m * sys.g * cs;
    (resultant > sys.mu_s * normal).then(|| {
        (
            (resultant - sys.mu_k * normal) / sys.m,
            (along / resultant, up / resultant),
        )
    })
}

/// The block from rest for `steps` steps of `h`: its displacement in the plane (level, up-slope)
/// over time, and the stepper.
#[allow(clippy::type_complexity)]
pub fn push(
    sys: &PushedBlock,
    h: f64,
    steps: usize,
) -> (
    Vec<(f64, f64, f64)>,
    Stepper<'_, PushedBlock, Fixed<Rk4>, 3>,
) {
    push_observed(sys, h, steps, |_| {})
}

/// [`push`], with `observe` called on every state from the first.
#[allow(clippy::type_complexity)]
pub fn push_observed(
    sys: &PushedBlock,
    h: f64,
    steps: usize,
    mut observe: impl FnMut(&State),
) -> (
    Vec<(f64, f64, f64)>,
    Stepper<'_, PushedBlock, Fixed<Rk4>, 3>,
) {
    let (sn, cs) = sys.alpha.sin_cos();
    let mut s = State::at_rest(Coords {
        x: 0.0,
        y: 0.0,
        z: 0.0,
    });
    let mut stepper = Stepper::new(sys, Rk4::with_step(h), &s).expect("stepper");
    let mut trace = vec![(0.0, 0.0, 0.0)];
    observe(&s);
    for _ in 0..steps {
        stepper.step(f64::INFINITY).expect("step");
        s = stepper.state();
        observe(&s);
        trace.push((s.t, s.q.x, s.q.y * cs + s.q.z * sn));
    }
    (trace, stepper)
}

/// The scene's checks against the closed form; the plot of the distance slid.
pub fn run(plots: &Path) -> Vec<Check> {
    let h = 1e-3;
    let base = PushedBlock {
        m: 2.0,
        g: 9.81,
        alpha: 0.3, // tan α = 0.31 < μₛ: without the push it sticks
        mu_k: 0.4,
        mu_s: 0.5,
        push: 0.0,
    };
    let normal = base.m * base.g * base.alpha.cos();
    let downslope = base.m * base.g * base.alpha.sin();
    // The push at which the resultant reaches μₛ N.
    let threshold = ((base.mu_s * normal).powi(2) - downslope.powi(2)).sqrt();
    let mut checks = Vec::new();
    let mut series = Vec::new();
    for (factor, label) in [(0.95, "below threshold"), (1.3, "above threshold")] {
        let sys = PushedBlock {
            push: factor * threshold,
            ..base
        };
        let mut film = Recorder::new(&sys).title(SCENE);
        film.trail("block").expect("the block's path");
        let (trace, stepper) = push_observed(&sys, h, 2000, film.observer(&sys));
        if factor > 1.0 {
            draw_incline(&mut film, sys.alpha, &trace);
            let _ = film.write_html(plots.join("pushed_block.html"));
        }
        let &(t, level, up) = trace.last().unwrap();
        let rows = stepper.contacts().mode().rows;
        println!(
            "{SCENE} ({label}, P = {:.4} N, threshold {threshold:.4} N): after {t:.1} s at \
             (level {level:.9}, up-slope {up:.9}) m, mode {rows:?}",
            sys.push
        );
        let settled = stepper.mode_changes().is_empty().then_some(rows[1]);
        let (case, closed) = case_checks(&sys, label, &trace, settled);
        checks.extend(case);
        series.extend(closed);
        let slid = trace
            .iter()
            .step_by(20)
            .map(|&(t, l, u)| (t, l.hypot(u)))
            .collect();
        series.push(Series::new(format!("{label}, simulated"), slid));
    }
    let _ = plot::lines(
        &plots.join("pushed_block.svg"),
        "Block on a rough incline pushed sideways: sticks below μₛN, slides along the resultant above",
        "t",
        "distance slid",
        &series,
    );
    checks
}

/// The incline under the path, 0.2 m beyond it each way: level direction (1, 0, 0), up-slope
/// (0, cos α, sin α).
fn draw_incline(film: &mut Recorder<PushedBlock, 3>, alpha: f64, trace: &[(f64, f64, f64)]) {
    let (sn, cs) = alpha.sin_cos();
    let (mut lo, mut hi) = ((-0.2f64, -0.2f64), (0.2f64, 0.2f64));
    for &(_, level, up) in trace {
        lo = (lo.0.min(level - 0.2), lo.1.min(up - 0.2));
        hi = (hi.0.max(level + 0.2), hi.1.max(up + 0.2));
    }
    let at = |level: f64, up: f64| [level, up * cs, up * sn];
    let (a, b, c, d) = (
        at(lo.0, lo.1),
        at(hi.0, lo.1),
        at(hi.0, hi.1),
        at(lo.0, hi.1),
    );
    outline(film, "incline", &[&a, &b, &c, &d], true).expect("the incline");
}

/// One push's checks against the closed form ([`slides`]): stuck, or sliding along the
/// resultant with constant acceleration; `settled` is the friction row's mode when the run had
/// no mode change. With the closed form's distance to plot where it slides.
fn case_checks(
    sys: &PushedBlock,
    label: &str,
    trace: &[(f64, f64, f64)],
    settled: Option<RowMode>,
) -> (Vec<Check>, Option<Series>) {
    let &(t, level, up) = trace.last().unwrap();
    match slides(sys) {
        // Sticking is enforced as a velocity constraint: no motion, to round-off.
        None => (
            vec![
                Check::new(
                    SCENE,
                    format!("{label}: distance moved in 2 s (m)"),
                    level.hypot(up),
                    0.0,
                    1e-14,
                ),
                Check::new(
                    SCENE,
                    format!("{label}: stuck throughout (1 = yes)"),
                    f64::from(u8::from(settled == Some(RowMode::Stick))),
                    1.0,
                    0.0,
                ),
            ],
            None,
        ),
        Some((a, (e1, e2))) => {
            // Constant acceleration along a fixed direction: RK4 is exact, round-off only.
            let d = 0.5 * a * t * t;
            let checks = vec![
                Check::new(
                    SCENE,
                    format!("{label}: distance along the level direction (m)"),
                    level,
                    d * e1,
                    1e-12,
                ),
                Check::new(
                    SCENE,
                    format!("{label}: distance up the slope (m)"),
                    up,
                    d * e2,
                    1e-12,
                ),
                Check::new(
                    SCENE,
                    format!("{label}: slides from the start, no mode change (1 = yes)"),
                    f64::from(u8::from(settled == Some(RowMode::Sliding))),
                    1.0,
                    0.0,
                ),
            ];
            let closed = trace
                .iter()
                .step_by(20)
                .map(|&(t, _, _)| (t, 0.5 * a * t * t))
                .collect();
            let series = Series::new(format!("{label}, closed form"), closed);
            (checks, Some(series))
        }
    }
}
