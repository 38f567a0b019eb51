//! The lecture's vertical wheel rolling without slipping on a horizontal plane (Hand & Finch,
//! *Analytical Mechanics*, Appendix 1A; Goldstein, Poole & Safko, 3rd ed., §1.3, fig. 1.5). Four
//! configuration variables — the centre (x, y), the heading φ and the rolling angle θ — and two
//! velocity constraints that cannot be integrated into constraints on the configuration
//! (nonholonomic): the contact point does not slip,
//!   ẋ = R θ̇ cos φ,   ẏ = R θ̇ sin φ,
//! leaving 2 degrees of freedom of velocity. The wheel is a uniform disk held vertical (a spatial
//! rigid body whose rotation is rot_z(φ)·rot_y(θ)): moment ½mR² about the axle, ¼mR² about a
//! diameter.
//!
//! Closed form: with multipliers λ₁, λ₂ on the two rows, m ẍ = λ₁, m ÿ = λ₂, I_d φ̈ = 0 and
//! I_a θ̈ = −R(λ₁ cos φ + λ₂ sin φ); differentiating the constraints gives (I_a + mR²) θ̈ = 0
//! (Greenwood, *Advanced Dynamics*, 2003, §3.4, the rolling disk, vertical case). So φ = φ₀ + ωt,
//! θ̇ = Ω is constant, and the centre moves on a straight line (ω = 0) or on a circle of radius
//! RΩ/ω, at constant kinetic energy.

use crate::plot::{self, Series};
use crate::Check;
use lagrange::animation::Recorder;
use lagrange::prelude::*;
use std::path::Path;

#[mechanism]
pub mod rolling_wheel {
    /// Centre (x, y), heading φ, rolling angle θ.
    pub struct Coords {
        pub x: f64,
        pub y: f64,
        pub phi: f64,
        pub theta: f64,
    }

    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct RollingWheel {
        pub m: f64,
        pub r: f64,
    }

    /// A uniform disk, axle along its body y axis, held vertical.
    #[rigid_body(mass = m, inertia = [0.25 * m * r * r, 0.5 * m * r * r, 0.25 * m * r * r])]
    fn wheel() -> Spatial {
        spatial(vec3(x, y, r), rot_z(phi) * rot_y(theta))
    }

    /// No slip along x at the contact point.
    #[velocity_constraint]
    fn roll_x() -> f64 {
        wheel_dot.linear.x - r * theta_dot * phi.cos()
    }

    /// No slip along y at the contact point.
    #[velocity_constraint]
    fn roll_y() -> f64 {
        wheel_dot.linear.y - r * theta_dot * phi.sin()
    }
}

const SCENE: &str = "rolling wheel";

/// Steps of the long run: 10⁵ in optimized builds (the gallery), 3·10³ in debug builds
/// (the tests: the spatial body's dual-number passes cost ~1.7 ms per unoptimized step, so even 10⁴
/// would take half a minute). The projection after every step keeps the no-slip residual at
/// round-off whatever the run length.
const LONG_RUN: usize = if cfg!(debug_assertions) {
    3_000
} else {
    100_000
};

struct Run {
    slip: f64,
    worst: f64,
    energy: f64,
    path: Vec<(f64, f64)>,
    exact_path: Vec<(f64, f64)>,
    film: Recorder<rolling_wheel::RollingWheel, 4>,
}

fn run_wheel(omega: f64) -> Run {
    use rolling_wheel::{Coords, RollingWheel, State};
    let w = RollingWheel { m: 2.0, r: 0.3 };
    let (big_omega, phi0) = (5.0f64, 0.4f64);
    let q0 = Coords {
        x: 0.1,
        y: -0.2,
        phi: phi0,
        theta: 0.0,
    };
    let closed_form = |t: f64| -> [f64; 4] {
        let phi = phi0 + omega * t;
        let theta = big_omega * t;
        if omega == 0.0 {
            let s = w.r * big_omega * t;
            [q0.x + s * phi0.cos(), q0.y + s * phi0.sin(), phi, theta]
        } else {
            let rho = w.r * big_omega / omega;
            [
                q0.x + rho * (phi.sin() - phi0.sin()),
                q0.y - rho * (phi.cos() - phi0.cos()),
                phi,
                theta,
            ]
        }
    };
    let v0 = Coords {
        x: w.r * big_omega * phi0.cos(),
        y: w.r * big_omega * phi0.sin(),
        phi: omega,
        theta: big_omega,
    };
    let mut s = State::new(0.0, q0, v0);
    let e0 = w.energy(&s).expect("energy");
    let h = 1e-3;
    let mut slip = 0.0f64;
    let (mut path, mut exact_path) = (Vec::new(), Vec::new());
    // A point on the rim (the wheel turns about its body y axis) and the centre leave trails.
    let mut film = Recorder::new(&w)
        .title(SCENE)
        .trail_length(3.0)
        .expect("a trail of 3 s");
    film.mark("rim", "wheel", &[w.r, 0.0, 0.0])
        .and_then(|f| f.trail("rim")?.trail("wheel"))
        .expect("a point on the rim");
    film.push(&w, &s).expect("a finite state");
    for step in 1..=LONG_RUN {
        w.step::<Rk4>(&mut s, h).expect("step");
        film.push(&w, &s).expect("a finite state");
        slip = slip
            .max((s.v.x - w.r * s.v.theta * s.q.phi.cos()).abs())
            .max((s.v.y - w.r * s.v.theta * s.q.phi.sin()).abs());
        if step % 20 == 0 && s.t <= 10.0 {
            let e = closed_form(s.t);
            path.push((s.q.x, s.q.y));
            exact_path.push((e[0], e[1]));
        }
    }
    let exact = closed_form(s.t);
    let q = s.q.to_array();
    let worst = (0..4).fold(0.0f64, |acc, k| acc.max((q[k] - exact[k]).abs()));
    let energy = (w.energy(&s).expect("energy") - e0).abs() / e0;
    Run {
        slip,
        worst,
        energy,
        path,
        exact_path,
        film,
    }
}

pub fn run(plots: &Path) -> Vec<Check> {
    let t_end = LONG_RUN as f64 * 1e-3;
    let steps = format!(
        "{LONG_RUN} steps{}",
        if cfg!(debug_assertions) {
            " (debug build; 10⁵ in release)"
        } else {
            ""
        }
    );
    let mut checks = Vec::new();
    let mut series = Vec::new();
    for (omega, label) in [(0.0, "straight"), (0.7, "circle")] {
        let r = run_wheel(omega);
        println!(
            "{SCENE} ({label}), {LONG_RUN} RK4 steps h = 1e-3: no-slip residual {:.2e} m/s, \
             |q − closed form| {:.2e} at t = {t_end} s, relative energy change {:.2e}",
            r.slip, r.worst, r.energy
        );
        // Velocities are projected onto A q̇ = 0 after every step: the residual is the round-off of
        // velocities of size RΩ = 1.5 m/s, a few ε; 1e-13 m/s leaves a margin (the bar is
        // ≤ 1e-10).
        checks.push(Check::new(
            SCENE,
            format!(
                "{label}: max no-slip residual |ẋ − Rθ̇ cos φ|, |ẏ − Rθ̇ sin φ| over {steps} (m/s)"
            ),
            r.slip,
            0.0,
            1e-13,
        ));
        // θ̇ and φ̇ are constant along the exact motion, so RK4 integrates φ and θ exactly and the
        // centre to O((hω)⁴) per unit time (≪ 1e-10 over 100 s); what remains is the round-off of
        // 1e5 additions to θ, which reaches 500 rad: ≲ 1e5·ε·|θ| ≈ 1e-8, measured ~1e-9: tolerance 5e-11 per second of run.
        checks.push(Check::new(
            SCENE,
            format!("{label}: max |q − closed form| at t = {t_end} s (m, rad)"),
            r.worst,
            0.0,
            1e-11 * 5.0 * t_end,
        ));
        // No work is done (the constraint forces act at a contact point at rest): T is constant, and
        // RK4 is exact for the constant velocities; round-off only.
        checks.push(Check::new(
            SCENE,
            format!("{label}: relative change of T at t = {t_end} s"),
            r.energy,
            0.0,
            1e-12,
        ));
        if omega != 0.0 {
            let _ = r.film.write_html(plots.join("rolling_wheel.html"));
        }
        series.push(Series::new(format!("{label}, simulated"), r.path));
        series.push(Series::new(format!("{label}, closed form"), r.exact_path));
    }
    let _ = plot::lines(
        &plots.join("rolling_wheel.svg"),
        "Rolling wheel: centre's path over 10 s, straight (ω = 0) and circle of radius RΩ/ω",
        "x",
        "y",
        &series,
    );
    checks
}
