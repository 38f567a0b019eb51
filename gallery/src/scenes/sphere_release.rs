//! A particle slides on the outside of a frictionless sphere of radius R, started at the top with
//! speed v₀ > 0. It moves on a great circle (a vertical plane), so two Cartesian coordinates (x, y)
//! suffice; the sphere is a unilateral constraint |r| − R ≥ 0 whose force can only push.
//!
//! Closed form (Goldstein, Poole & Safko, *Classical Mechanics*, 3rd ed., §2.4, the particle on a
//! hemisphere; Kleppner & Kolenkow, 2nd ed., problem 5.x): with θ the angle from the top, energy gives
//! v² = v₀² + 2gR(1 − cos θ) and the radial component of Newton's law m v²/R = m g cos θ − N, so the
//! normal force is
//!   N(θ) = m g (3 cos θ − 2) − m v₀²/R,
//! which vanishes at cos θ* = (2 + v₀²/(gR))/3: there the particle leaves. The release time is
//! t* = ∫₀^θ* R dθ / v(θ), computed here by composite Gauss–Legendre quadrature (smooth integrand,
//! v ≥ v₀ > 0). After release the particle is a projectile: a parabola from the release state.
//!
//! The simulation knows none of this: a [`Stepper`] with RK4 integrates the constrained equations
//! with the contact mode held over each step, keeps the contact while its multiplier λ = N is
//! positive and locates the instant λ reaches 0.

use crate::plot::{self, Series};
use crate::Check;
use lagrange::animation::Recorder;
use lagrange::constraints::{constraint_forces, RowMode};
use lagrange::prelude::*;
use std::path::Path;

#[mechanism]
pub mod sphere_release {
    /// The particle's position in the plane of its great circle, sphere centre at the origin.
    pub struct Coords {
        pub x: f64,
        pub y: f64,
    }

    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct SphereRelease {
        pub m: f64,
        pub r: f64,
        pub g: f64,
    }

    #[particle(mass = m)]
    fn particle() -> Vec2 {
        vec2(x, y)
    }

    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }

    /// The sphere can only push the particle outwards.
    #[unilateral]
    fn surface() -> f64 {
        particle.norm() - r
    }
}

const SCENE: &str = "particle leaving a sphere";

/// ∫ₐᵇ f by composite 5-point Gauss–Legendre (Abramowitz & Stegun, Table 25.4), exact for
/// polynomials of degree 9 on each panel: for an analytic integrand the error with 400 panels is far
/// below round-off.
pub fn gauss_legendre(f: impl Fn(f64) -> f64, a: f64, b: f64, panels: usize) -> f64 {
    const X: [f64; 5] = [
        0.0,
        -0.538_469_310_105_683_1,
        0.538_469_310_105_683_1,
        -0.906_179_845_938_664,
        0.906_179_845_938_664,
    ];
    const W: [f64; 5] = [
        0.568_888_888_888_888_9,
        0.478_628_670_499_366_5,
        0.478_628_670_499_366_5,
        0.236_926_885_056_189_1,
        0.236_926_885_056_189_1,
    ];
    let width = (b - a) / panels as f64;
    let mut sum = 0.0;
    for p in 0..panels {
        let mid = a + (p as f64 + 0.5) * width;
        for (x, w) in X.iter().zip(W) {
            sum += w * f(mid + 0.5 * width * x);
        }
    }
    0.5 * width * sum
}

/// A start on the sphere and its closed-form release, for the tests that check a located release:
/// the particle at angle θ₀ from the top with speed v₀ along the sphere (radius r, gravity g).
#[derive(Clone, Copy, Debug)]
pub struct Release {
    /// The sphere's radius.
    pub r: f64,
    /// Gravity.
    pub g: f64,
    /// The start's angle from the top.
    pub theta0: f64,
    /// The start's speed along the sphere.
    pub v0: f64,
}

impl Release {
    /// (position, velocity) in the plane of the great circle, sphere centre at the origin.
    pub fn state(self) -> ([f64; 2], [f64; 2]) {
        let (sin, cos) = self.theta0.sin_cos();
        (
            [self.r * sin, self.r * cos],
            [self.v0 * cos, -self.v0 * sin],
        )
    }

    /// The speed at angle θ, by energy: v² = v₀² + 2gr(cos θ₀ − cos θ), the difference written
    /// 2 sin((θ + θ₀)/2) sin((θ − θ₀)/2) so that it keeps its relative accuracy near θ₀.
    pub fn speed(self, theta: f64) -> f64 {
        let drop = 2.0 * (0.5 * (theta + self.theta0)).sin() * (0.5 * (theta - self.theta0)).sin();
        (self.v0 * self.v0 + 2.0 * self.g * self.r * drop).sqrt()
    }

    /// The closed form of the release: (t*, cos θ*). The normal force m(g cos θ − v²/r) vanishes
    /// at cos θ* = (2 cos θ₀ + v₀²/(gr))/3, reached at t* = ∫_θ₀^θ* r dθ / v(θ). With θ = θ₀ + u²,
    /// dθ = 2u du: the integrand 2ur/v(θ₀ + u²) is analytic in u also from rest
    /// (v² = u²·(2gr sin θ₀ + O(u²)) then), so 400 panels of 5-point Gauss–Legendre are exact to
    /// round-off.
    pub fn release(self) -> (f64, f64) {
        let (r, g) = (self.r, self.g);
        let cos_star = (2.0 * self.theta0.cos() + self.v0 * self.v0 / (g * r)) / 3.0;
        let theta_star = cos_star.acos();
        let integrand = |u: f64| 2.0 * u * r / self.speed(self.theta0 + u * u);
        let end = (theta_star - self.theta0).sqrt();
        (gauss_legendre(integrand, 0.0, end, 400), cos_star)
    }
}

/// The scene's particle, its start and the closed form of its release.
struct Setup {
    sys: sphere_release::SphereRelease,
    s0: sphere_release::State,
    v0: f64,
    /// cos θ*, θ*, t*.
    cos_star: f64,
    theta_star: f64,
    t_star: f64,
}

impl Setup {
    fn new() -> Self {
        use sphere_release::{Coords, SphereRelease, State};
        let sys = SphereRelease {
            m: 0.7,
            r: 1.5,
            g: 9.81,
        };
        let (r, g) = (sys.r, sys.g);
        let v0 = 1.2f64;
        let cos_star = (2.0 + v0 * v0 / (g * r)) / 3.0;
        let theta_star = cos_star.acos();
        let speed = |th: f64| (v0 * v0 + 2.0 * g * r * (1.0 - th.cos())).sqrt();
        let t_star = gauss_legendre(|th| r / speed(th), 0.0, theta_star, 400);
        let s0 = State::new(0.0, Coords { x: 0.0, y: r }, Coords { x: v0, y: 0.0 });
        Setup {
            sys,
            s0,
            v0,
            cos_star,
            theta_star,
            t_star,
        }
    }

    /// The speed at angle θ, by energy.
    fn speed(&self, theta: f64) -> f64 {
        let (r, g, v0) = (self.sys.r, self.sys.g, self.v0);
        (v0 * v0 + 2.0 * g * r * (1.0 - theta.cos())).sqrt()
    }

    /// The normal force at cos θ: m g (3 cos θ − 2) − m v₀²/r.
    fn normal(&self, cos: f64) -> f64 {
        let (m, r, g, v0) = (self.sys.m, self.sys.r, self.sys.g, self.v0);
        m * g * (3.0 * cos - 2.0) - m * v0 * v0 / r
    }
}

/// What the run records: the path, the normal force against the closed form, the parabola
/// after release, and the worst departures.
#[derive(Default)]
struct Traces {
    path: Vec<(f64, f64)>,
    normal: Vec<(f64, f64)>,
    closed: Vec<(f64, f64)>,
    parabola: Vec<(f64, f64)>,
    worst_normal: f64,
    worst_parabola: f64,
    closest: f64,
}

pub fn run(plots: &Path) -> Vec<Check> {
    let setup = Setup::new();
    let sys = &setup.sys;
    let h = 1e-3;
    let mut stepper = Stepper::new(sys, Rk4::with_step(h), &setup.s0).expect("stepper");
    let in_contact = stepper.contacts().mode().rows == [RowMode::Active];
    let mut film = Recorder::new(sys).title(SCENE);
    film.fixed_point("centre", &[0.0, 0.0])
        .and_then(|f| f.trail("particle"))
        .expect("the sphere's centre");
    film.push(sys, &setup.s0).expect("a finite state");
    let mut traces = Traces {
        path: vec![(setup.s0.q.x, setup.s0.q.y)],
        closest: f64::INFINITY,
        ..Traces::default()
    };
    slide(&setup, &mut stepper, &mut film, &mut traces);
    let release = stepper.mode_changes()[0];
    let released = release.from == RowMode::Active && release.to == RowMode::Inactive;
    let cos_release = cos_at(&setup, h, release.t);
    fly(&setup, &mut stepper, &mut film, &mut traces);
    let _ = film.write_html(plots.join("sphere_release.html"));
    let (t_star, theta_star) = (setup.t_star, setup.theta_star);
    let release_error = (release.t - t_star).abs() / t_star;
    println!(
        "{SCENE}: released at t = {:.15} s (quadrature {t_star:.15}, rel. error {release_error:.1e}), \
         θ* = {theta_star:.6} rad; {} mode change(s); parabola within {:.1e} m",
        release.t,
        stepper.mode_changes().len(),
        traces.worst_parabola
    );
    let one_release = in_contact && released && stepper.mode_changes().len() == 1;
    let checks = checks(&setup, one_release, (release.t, cos_release), &traces);
    plot_traces(plots, sys.r, traces);
    checks
}

type Solver<'a> = Stepper<'a, sphere_release::SphereRelease, lagrange::Fixed<Rk4>, 2>;
type Film = Recorder<sphere_release::SphereRelease, 2>;

/// The contact phase, up to the located release: the path, and λ against N(θ) at every step.
fn slide(setup: &Setup, stepper: &mut Solver<'_>, film: &mut Film, traces: &mut Traces) {
    let (sys, r) = (&setup.sys, setup.sys.r);
    while stepper.mode_changes().is_empty() {
        stepper.step(f64::INFINITY).expect("contact step");
        let s = stepper.state();
        film.push(sys, &s).expect("a finite state");
        traces.path.push((s.q.x, s.q.y));
        if stepper.mode_changes().is_empty() {
            let lambda = constraint_forces(sys, &s).expect("forces").multipliers[0];
            let cos = s.q.y / r;
            let exact = setup.normal(cos);
            traces.worst_normal = traces.worst_normal.max((lambda - exact).abs());
            let theta = s.q.x.atan2(s.q.y);
            traces.normal.push((theta, lambda));
            traces.closed.push((theta, exact));
        }
    }
}

/// cos θ at the located release instant: the same integration, its last step shortened to end
/// at the event.
fn cos_at(setup: &Setup, h: f64, t_release: f64) -> f64 {
    let mut probe = Stepper::new(&setup.sys, Rk4::with_step(h), &setup.s0).expect("stepper");
    while probe.t() + h < t_release {
        probe.step(f64::INFINITY).expect("step");
    }
    probe.step(t_release).expect("step");
    let at_release = probe.state();
    at_release.q.y / at_release.q.x.hypot(at_release.q.y)
}

/// After release, for 0.4 s: a parabola from the exact release state, staying outside the sphere.
fn fly(setup: &Setup, stepper: &mut Solver<'_>, film: &mut Film, traces: &mut Traces) {
    let (sys, r, g) = (&setup.sys, setup.sys.r, setup.sys.g);
    let (cos_star, theta_star, t_star) = (setup.cos_star, setup.theta_star, setup.t_star);
    let r_star = [r * theta_star.sin(), r * cos_star];
    let v_star = [
        setup.speed(theta_star) * cos_star,
        -setup.speed(theta_star) * theta_star.sin(),
    ];
    let mut s = stepper.state();
    while s.t < t_star + 0.4 {
        stepper.step(f64::INFINITY).expect("free step");
        s = stepper.state();
        film.push(sys, &s).expect("a finite state");
        traces.path.push((s.q.x, s.q.y));
        let tau = s.t - t_star;
        let x = r_star[0] + v_star[0] * tau;
        let y = r_star[1] + v_star[1] * tau - 0.5 * g * tau * tau;
        traces.parabola.push((x, y));
        let off = (s.q.x - x).abs().max((s.q.y - y).abs());
        traces.worst_parabola = traces.worst_parabola.max(off);
        traces.closest = traces.closest.min(s.q.x.hypot(s.q.y) - r);
    }
}

/// The path with the sphere and the parabola, and the normal force against the closed form.
fn plot_traces(plots: &Path, r: f64, traces: Traces) {
    let circle: Vec<(f64, f64)> = (0..=90)
        .map(|k| {
            let a = std::f64::consts::FRAC_PI_2 * (1.0 - k as f64 / 45.0);
            (r * a.cos(), r * a.sin())
        })
        .collect();
    let _ = plot::lines(
        &plots.join("sphere_release_path.svg"),
        "Particle on a sphere: slides, leaves at cos θ* = (2 + v₀²/gR)/3, then a parabola",
        "x",
        "y",
        &[
            Series::new("sphere", circle),
            Series::new("simulated path", traces.path),
            Series::new("parabola from the release state", traces.parabola),
        ],
    );
    let _ = plot::lines(
        &plots.join("sphere_release_normal.svg"),
        "Particle on a sphere: normal force λ against mg(3cos θ − 2) − mv₀²/R",
        "θ",
        "N",
        &[
            Series::new("λ (KKT multiplier)", traces.normal),
            Series::new("closed form", traces.closed),
        ],
    );
}

/// The scene's checks: one release from contact, its time and angle against the closed form,
/// λ against N(θ), the parabola, and no return to the sphere.
fn checks(
    setup: &Setup,
    one_release: bool,
    (t_release, cos_release): (f64, f64),
    traces: &Traces,
) -> Vec<Check> {
    let (m, g) = (setup.sys.m, setup.sys.g);
    vec![
        Check::new(
            SCENE,
            "starts in contact, one mode change, contact → separated (1 = yes)",
            f64::from(u8::from(one_release)),
            1.0,
            0.0,
        ),
        // The event is located to 1e-13 relative on the step length; what remains is RK4's global
        // error over the contact phase (0.65 s, h = 1e-3, (hω)⁴ with ω = θ̇ ≲ 3/s): ~1e-11.
        Check::new(
            SCENE,
            "release time t* (vs Gauss–Legendre ∫ R dθ / v)",
            t_release,
            setup.t_star,
            1e-9,
        ),
        // cos θ at the located instant: RK4 error of the position, as for t*.
        Check::new(
            SCENE,
            "cos θ at release = (2 + v₀²/(gR))/3",
            cos_release,
            setup.cos_star,
            1e-9,
        ),
        // λ from the KKT solve at the RK4 state against the closed form at the same θ, which uses the
        // exact energy integral: they differ by the RK4 energy error, ≪ 1e-9·m g.
        Check::new(
            SCENE,
            "max |λ − N(θ)| / mg while in contact",
            traces.worst_normal / (m * g),
            0.0,
            1e-9,
        ),
        // Free flight is quadratic in t, which RK4 integrates exactly: only the release-state error
        // (~1e-11 m) remains.
        Check::new(
            SCENE,
            "max |r − parabola| over 0.4 s after release (m)",
            traces.worst_parabola,
            0.0,
            1e-8,
        ),
        // It never comes back: the parabola bends away from the sphere (checked: distance > 0).
        Check::new(
            SCENE,
            "outside the sphere after release (1 = yes)",
            f64::from(u8::from(traces.closest > 0.0)),
            1.0,
            0.0,
        ),
    ]
}
