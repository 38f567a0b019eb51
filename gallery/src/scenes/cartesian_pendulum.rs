//! The planar pendulum written in Cartesian coordinates: the bob's (x, y) are the coordinates and a
//! holonomic constraint |r| − L = 0 keeps it on the circle. The rod is no longer absorbed by the
//! choice of coordinates, so its force comes out as a Lagrange multiplier λ.
//!
//! Closed form: the motion is that of the angle form θ̈ = −(g/L) sin θ (the same mechanism, declared
//! here with one coordinate θ); the radial component of Newton's law for the bob,
//! m L θ̇² = T − m g cos θ (θ from the downward vertical), gives the rod tension
//!   T = m (g cos θ + L θ̇²)
//! (Taylor, *Classical Mechanics*, §7.10, example 7.9; Goldstein, Poole & Safko, 3rd ed., §2.4,
//! "Lagrange multipliers"). The constraint's gradient ∂(|r| − L)/∂r is the outward unit vector, so the
//! multiplier is the outward force: λ = −T.

use crate::plot::{self, Series};
use crate::Check;
use lagrange::animation::Recorder;
use lagrange::constraints::{constraint_forces, constraint_rows};
use lagrange::prelude::*;
use std::path::Path;

#[mechanism]
pub mod cartesian_pendulum {
    /// The bob's position, pivot at the origin.
    pub struct Coords {
        pub x: f64,
        pub y: f64,
    }

    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct CartesianPendulum {
        pub m: f64,
        pub l: f64,
        pub g: f64,
    }

    #[particle(mass = m)]
    fn bob() -> Vec2 {
        vec2(x, y)
    }

    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }

    /// The rod keeps the bob at distance l from the pivot.
    #[constraint]
    fn rod() -> f64 {
        bob.norm() - l
    }
}

#[mechanism]
pub mod angle_pendulum {
    /// The angle from the downward vertical.
    pub struct Coords {
        pub theta: f64,
    }

    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct AnglePendulum {
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

const SCENE: &str = "Cartesian pendulum";

/// Steps of the long run: 10⁵ in optimized builds (the gallery), 10⁴ in debug builds
/// (the tests), where 10⁵ would take minutes. The projection after every step keeps the constraint
/// error at round-off whatever the run length.
const LONG_RUN: usize = if cfg!(debug_assertions) {
    10_000
} else {
    100_000
};

/// The worst departures over the long run, and the tension's traces.
#[derive(Default)]
struct Departures {
    /// From the angle form's position (the first 10⁴ steps).
    position: f64,
    /// −λ from the rod tension, relative to m g.
    tension: f64,
    /// |g| and |ġ|.
    g: f64,
    gdot: f64,
    /// |E − E₀|.
    energy: f64,
    lambda_trace: Vec<(f64, f64)>,
    tension_trace: Vec<(f64, f64)>,
}

pub fn run(plots: &Path) -> Vec<Check> {
    use angle_pendulum::AnglePendulum;
    use cartesian_pendulum::{CartesianPendulum, Coords, State};
    let sys = CartesianPendulum {
        m: 1.3,
        l: 0.8,
        g: 9.81,
    };
    let angle = AnglePendulum {
        m: sys.m,
        l: sys.l,
        g: sys.g,
    };
    let l = sys.l;
    let (th0, w0) = (1.2f64, 0.5f64);
    let s = State::new(
        0.0,
        Coords {
            x: l * th0.sin(),
            y: -l * th0.cos(),
        },
        Coords {
            x: l * w0 * th0.cos(),
            y: l * w0 * th0.sin(),
        },
    );
    let a = angle_pendulum::State::new(
        0.0,
        angle_pendulum::Coords { theta: th0 },
        angle_pendulum::Coords { theta: w0 },
    );
    let h = 1e-3;
    let e0 = sys.energy(&s).expect("energy");
    let d = long_run(plots, (&sys, s), (&angle, a), h, e0);
    println!(
        "{SCENE}: {LONG_RUN} RK4 steps h = {h}: |g| ≤ {:.2e}, |ġ| ≤ {:.2e}, \
         energy drift {:.2e} J, position vs angle form (1e4 steps) {:.2e}, \
         tension rel. error {:.2e}",
        d.g, d.gdot, d.energy, d.position, d.tension
    );
    let checks = checks(&d, e0);
    let _ = plot::lines(
        &plots.join("cartesian_pendulum_tension.svg"),
        "Cartesian pendulum: −λ against the rod tension m(g cos θ + Lθ̇²)",
        "t",
        "N",
        &[
            Series::new("−λ (KKT multiplier)", d.lambda_trace),
            Series::new("m(g cos θ + Lθ̇²)", d.tension_trace),
        ],
    );
    checks
}

/// [`LONG_RUN`] RK4 steps of `h` of the Cartesian pendulum from `s` (energy `e0`) and of the
/// angle form from `a`, recorded: the departures, and the tension every 100 steps.
fn long_run(
    plots: &Path,
    (sys, mut s): (
        &cartesian_pendulum::CartesianPendulum,
        cartesian_pendulum::State,
    ),
    (angle, mut a): (&angle_pendulum::AnglePendulum, angle_pendulum::State),
    h: f64,
    e0: f64,
) -> Departures {
    let (m, l, g) = (sys.m, sys.l, sys.g);
    let mut d = Departures::default();
    let mut film = Recorder::new(sys).title(SCENE);
    film.fixed_point("pivot", &[0.0, 0.0])
        .and_then(|f| f.link("pivot", "bob"))
        .expect("the pivot");
    film.push(sys, &s).expect("a finite state");
    for step in 1..=LONG_RUN {
        sys.step::<Rk4>(&mut s, h).expect("Cartesian step");
        film.push(sys, &s).expect("a finite state");
        angle.step::<Rk4>(&mut a, h).expect("angle step");
        let rows = constraint_rows(sys, s.t, &s.q.to_array(), &s.v.to_array());
        d.g = d.g.max(rows.value[0].abs());
        d.gdot = d.gdot.max(rows.rate[0].abs());
        d.energy = d.energy.max((sys.energy(&s).expect("energy") - e0).abs());
        if step <= 10_000 {
            let th = a.q.theta;
            d.position = d
                .position
                .max((s.q.x - l * th.sin()).abs())
                .max((s.q.y + l * th.cos()).abs());
        }
        if step % 100 == 0 {
            let (x, y, vx, vy) = (s.q.x, s.q.y, s.v.x, s.v.y);
            let theta = x.atan2(-y);
            let theta_dot = (x * vy - y * vx) / (l * l);
            let tension = m * (g * theta.cos() + l * theta_dot * theta_dot);
            let lambda = constraint_forces(sys, &s).expect("forces").multipliers[0];
            d.tension = d
                .tension
                .max((-lambda - tension).abs() / tension.abs().max(m * g));
            if s.t <= 5.0 {
                d.lambda_trace.push((s.t, -lambda));
                d.tension_trace.push((s.t, tension));
            }
        }
    }
    let _ = film.write_html(plots.join("cartesian_pendulum.html"));
    d
}

/// The scene's checks, `e0` the starting energy.
fn checks(d: &Departures, e0: f64) -> Vec<Check> {
    let steps = format!(
        "{LONG_RUN} steps{}",
        if cfg!(debug_assertions) {
            " (debug build; 10⁵ in release)"
        } else {
            ""
        }
    );
    vec![
        // Two RK4 solutions of the same motion, each with global error O(h⁴): (hω)⁴ with
        // ω ≈ √(g/L) ≈ 3.5/s is ~1.5e-10 per unit time, ≲ 1e-9 m over 10 s; 1e-8 m leaves a margin.
        Check::new(
            SCENE,
            "max |r − L(sin θ, −cos θ)| over 10 s vs the angle form (m)",
            d.position,
            0.0,
            1e-8,
        ),
        // The multiplier and the closed form are evaluated at the same state: they agree to the
        // round-off of the KKT solve, relative to the tension scale m g.
        Check::new(
            SCENE,
            format!("max |−λ − m(g cos θ + Lθ̇²)| / mg over {steps}"),
            d.tension,
            0.0,
            1e-10,
        ),
        // Projection onto |r| = L and r·ṙ = 0 after every step: round-off of |r| ~ 1, independent
        // of the run length; the bar is ≤ 1e-10.
        Check::new(
            SCENE,
            format!("max |g| = ||r| − L| over {steps} (m)"),
            d.g,
            0.0,
            1e-10,
        ),
        Check::new(
            SCENE,
            format!("max |ġ| over {steps} (m/s)"),
            d.gdot,
            0.0,
            1e-10,
        ),
        // RK4's energy error accumulates about linearly: 1e5 steps × (hω)⁵·E ≈ 1e-8·E at worst.
        Check::new(
            SCENE,
            format!("max |E − E₀| / |E₀| over {steps}"),
            d.energy / e0.abs(),
            0.0,
            1e-7,
        ),
    ]
}
