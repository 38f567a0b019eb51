//! Contact mechanisms several contact tests share (the unilateral sphere is the gallery's
//! `sphere_release`), with the sphere's parameters, its starts, and its release located on the
//! bilateral declaration's multiplier; and the checks the adaptive methods share: their
//! `integrate` routed to the contact solver, the ball, the gallery's rough ramp and its puck on a
//! rough plane.
#![allow(dead_code)]

use lagrange::constraints::{constraint_forces, ContactOptions, ModeChange, RowMode};
use lagrange::integrate::{Direction, Event, Outcome, Stats, StopReason};
use lagrange::prelude::*;
use lagrange_gallery::scenes::rough_plane::{rough_plane, stop};
use lagrange_gallery::scenes::rough_ramp::rough_ramp;
use lagrange_gallery::scenes::sphere_release::{sphere_release, Release};

/// `method` from `s` to `t_end` with the contact options, events and observer given: the outcome
/// and the mode changes, `s` moved to where the integration ended (unchanged on error).
pub fn integrate_contacts<M: Mechanism<N>, Me: lagrange::integrate::Method<N>, const N: usize>(
    sys: &M,
    method: Me,
    s: &mut State<M::Coords>,
    t_end: f64,
    options: ContactOptions,
    events: &mut [Event<'_, M::Coords>],
    observer: impl FnMut(lagrange::integrate::Observation<'_, M::Coords, N>),
) -> lagrange::Result<(Outcome<M::Coords>, Vec<ModeChange>)> {
    let mut solver = Stepper::new(sys, method, s)?.with_contact_options(options)?;
    let outcome = solver.integrate(t_end, events, observer)?;
    *s = outcome.state;
    Ok((outcome, solver.mode_changes().to_vec()))
}

/// The particle's mass on the sphere.
pub const M: f64 = 0.7;
/// The sphere's radius.
pub const R: f64 = 1.5;
/// Gravity, in every contact scene.
pub const G: f64 = 9.81;

/// Where the particle starts (at angle θ₀ from the top, with speed v₀ along the sphere), with the
/// closed form of its release: the gallery's `sphere_release::Release`.
pub type Start = Release;

/// A start on this sphere (radius R, gravity G).
pub const fn on_sphere(theta0: f64, v0: f64) -> Start {
    Release {
        r: R,
        g: G,
        theta0,
        v0,
    }
}

/// Released at rest near the top (cos θ* = ⅔ cos θ₀), and from the top at two speeds.
pub const STARTS: [Start; 3] = [
    on_sphere(0.1, 0.0),
    on_sphere(0.0, 0.5),
    on_sphere(0.0, 1.2),
];

/// The bilateral sphere from `start`, integrated by `integrate` (an adaptive method to t = 10 with
/// the events given) and stopped where its multiplier falls through 0: the release time and the
/// cost.
pub fn bilateral_release_in(
    start: Start,
    integrate: impl FnOnce(
        &bilateral::Sphere,
        &mut bilateral::State,
        &mut [Event<'_, bilateral::Coords>],
    ) -> lagrange::Result<Outcome<bilateral::Coords>>,
) -> (f64, Stats) {
    use bilateral::{Coords, Sphere, State};
    let sys = Sphere { m: M, r: R, g: G };
    let ([x, y], [vx, vy]) = start.state();
    let mut s = State::new(0.0, Coords { x, y }, Coords { x: vx, y: vy });
    let normal = |s: &State| constraint_forces(&sys, s).expect("forces").multipliers[0];
    let mut events = [Event::new(&normal).direction(Direction::Falling).terminal()];
    let outcome = integrate(&sys, &mut s, &mut events).expect("integration");
    let StopReason::Event(hit) = outcome.reason else {
        panic!("the particle did not leave: {:?}", outcome.reason)
    };
    (hit.state.t, outcome.stats)
}

/// The sphere of the gallery's `sphere_release` as a bilateral constraint: its multiplier is the
/// normal force it would need.
#[mechanism]
pub mod bilateral {
    pub struct Coords {
        pub x: f64,
        pub y: f64,
    }

    pub struct Sphere {
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

    #[constraint]
    fn surface() -> f64 {
        particle.norm() - r
    }
}

/// A ball above a floor y ≥ 0.
#[mechanism]
pub mod ball {
    pub struct Coords {
        pub x: f64,
        pub y: f64,
    }

    pub struct Ball {
        pub m: f64,
        pub g: f64,
    }

    #[particle(mass = m)]
    fn ball() -> Vec2 {
        vec2(x, y)
    }

    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }

    #[unilateral]
    fn floor() -> f64 {
        y
    }
}

/// One interface: a method's `integrate` on a declaration with a unilateral row takes the contact
/// solver, so it is the same run as its `integrate_contacts` — same steps, same evaluations, same
/// end state, bit for bit. Checked on the unilateral sphere from the top at 0.5 m/s to t = 2.5,
/// past its one release (within 2 s). `integrate` and `integrate_contacts` run the method at the
/// same tolerances to the end time given.
pub fn check_integrate_takes_the_contact_solver(
    integrate: impl Fn(
        &sphere_release::SphereRelease,
        &mut sphere_release::State,
        f64,
    ) -> lagrange::Result<Outcome<sphere_release::Coords>>,
    integrate_contacts: impl Fn(
        &sphere_release::SphereRelease,
        &mut sphere_release::State,
        f64,
    )
        -> lagrange::Result<(Outcome<sphere_release::Coords>, Vec<ModeChange>)>,
) {
    use sphere_release::{Coords, SphereRelease, State};
    let sys = SphereRelease { m: M, r: R, g: G };
    let start = State::new(0.0, Coords { x: 0.0, y: R }, Coords { x: 0.5, y: 0.0 });
    let t_end = 2.5;
    let mut routed = start;
    let via_integrate = integrate(&sys, &mut routed, t_end).expect("integrate");
    let mut direct = start;
    let (via_contacts, changes) =
        integrate_contacts(&sys, &mut direct, t_end).expect("integrate_contacts");
    assert_eq!(changes.len(), 1, "one release");
    assert_eq!(via_integrate.stats, via_contacts.stats);
    assert_eq!(routed, direct);
}

/// The ball (m = 0.3) dropped from 1.3 m, moving at 0.5 m/s along the floor, run to t = 2 by
/// `integrate_contacts` (a method's `integrate_contacts` with the options given), plastic (e = 0)
/// and with restitution (e = 0.6): its landings at the closed-form times, asserted to 1e-12 — the
/// caller says why its method integrates the free fall, a quadratic in t, exactly, leaving the root
/// finder's 1e-13 and round-off over a few steps.
pub fn check_ball_dropped_on_the_floor(
    integrate_contacts: impl Fn(
        &ball::Ball,
        &mut ball::State,
        ContactOptions,
    ) -> lagrange::Result<(Outcome<ball::Coords>, Vec<ModeChange>)>,
) {
    use ball::{Ball, Coords, State};
    let sys = Ball { m: 0.3, g: G };
    let height = 1.3;
    let t1 = (2.0 * height / G).sqrt();
    for restitution in [0.0, 0.6] {
        let mut s = State::new(0.0, Coords { x: 0.2, y: height }, Coords { x: 0.5, y: 0.0 });
        let options = ContactOptions {
            restitution,
            ..Default::default()
        };
        let (outcome, changes) = integrate_contacts(&sys, &mut s, options).expect("integration");
        eprintln!(
            "e = {restitution}: {:?}, mode changes at {:?}",
            outcome.stats,
            changes.iter().map(|c| c.t).collect::<Vec<_>>()
        );
        assert!(
            (changes[0].t - t1).abs() < 1e-12,
            "landed at {}, closed form {t1}",
            changes[0].t
        );
        assert_eq!(changes[0].from, RowMode::Inactive);
        if restitution == 0.0 {
            // A plastic impact: it stays on the floor, sliding on at 0.5 m/s (frictionless).
            assert_eq!((changes.len(), changes[0].to), (1, RowMode::Active));
            assert!(s.q.y.abs() < 1e-12 && s.v.y.abs() < 1e-12);
            assert!((s.q.x - (0.2 + 0.5 * 2.0)).abs() < 1e-12);
        } else {
            // Bounces: leaves at e·g·t₁, so the k-th landing is at t₁(1 + 2e + … + 2eᵏ⁻¹).
            assert_eq!(changes[0].to, RowMode::Inactive);
            let mut landing = t1;
            let mut flight = 2.0 * restitution * t1;
            for change in changes.iter().take_while(|c| c.t < 1.5) {
                assert!(
                    (change.t - landing).abs() < 1e-12,
                    "landed at {}, closed form {landing}",
                    change.t
                );
                landing += flight;
                flight *= restitution;
            }
            assert!(changes.len() >= 3);
        }
        // Few steps: a polynomial motion has no error to control, and each landing cuts one step.
        assert!(outcome.stats.accepted < 20 * changes.len().max(1));
    }
}

/// A block (m = 2) sent up the gallery's rough ramp (α = 0.5) at u = 2 m/s, run to t = 1.5 by
/// `run` (a contact solver from the start given: its mode changes, end state and cost), with
/// (μₖ, μₛ) = (0.5, 0.6) and (0.3, 0.4): it stops at t_s = u/(g(sin α + μₖ cos α)), then sticks
/// or slides back with a = g(sin α − μₖ cos α), as μₛ decides. Piecewise constant accelerations:
/// each phase is a quadratic in t, which the caller's method integrates exactly (it says why); the
/// stop is located to the root finder's 1e-13 and round-off. Asserted to 1e-12 (the position
/// after sliding back to 1e-11).
pub fn check_block_sent_up_the_rough_ramp(
    run: impl Fn(
        &rough_ramp::RoughRamp,
        &rough_ramp::State,
    ) -> (Vec<ModeChange>, rough_ramp::State, Stats),
) {
    use rough_ramp::{Coords, RoughRamp, State};
    let (alpha, u) = (0.5f64, 2.0);
    let (sn, cs) = alpha.sin_cos();
    let up = Coords {
        x: u * cs,
        y: u * sn,
    };
    for (mu_k, mu_s) in [(0.5, 0.6), (0.3, 0.4)] {
        let sys = RoughRamp {
            m: 2.0,
            alpha,
            g: G,
            mu_k,
            mu_s,
        };
        let start = State::new(0.0, Coords { x: 0.0, y: 0.0 }, up);
        let (events, s, stats) = run(&sys, &start);
        let t_stop = u / (G * (sn + mu_k * cs));
        let d_stop = u * u / (2.0 * G * (sn + mu_k * cs));
        let distance = s.q.x * cs + s.q.y * sn;
        eprintln!("μₖ = {mu_k}, μₛ = {mu_s}: {events:?}; {stats:?}");
        let stop = events[0];
        assert!(
            (stop.t - t_stop).abs() < 1e-12,
            "stopped at {}, closed form {t_stop}",
            stop.t
        );
        if alpha.tan() <= mu_s {
            // Sticks where it stopped, for good: one mode change.
            assert_eq!(events.len(), 1);
            assert_eq!(stop.to, RowMode::Stick);
            assert!(
                (distance - d_stop).abs() < 1e-12,
                "{distance} against {d_stop}"
            );
        } else {
            // Slides back down from the stop with a = g(sin α − μₖ cos α).
            assert_eq!(stop.to, RowMode::SlipNegative);
            let tau = 1.5 - t_stop;
            let back = d_stop - 0.5 * G * (sn - mu_k * cs) * tau * tau;
            assert!((distance - back).abs() < 1e-11, "{distance} against {back}");
        }
        assert!(stats.rejected == 0 && stats.accepted < 20);
    }
}

/// The gallery's puck (m = 1.5, μₖ = 0.5, μₛ = 0.6) on its rough plane (the friction cone:
/// `#[friction]` with a `Vec2` slip velocity), sent at 3 m/s along x and pushed sideways by
/// `push`, run to t = 1.5 by `integrate_contacts` (a method's `integrate_contacts` at the tolerance
/// given). It stops once, decided once (no chattering), from sliding to sticking for good, and is
/// at rest to round-off (sticking is enforced as a velocity constraint). Returns the errors of the
/// stop time and point against the closed forms of the gallery's `rough_plane::stop`, and the cost.
pub fn puck_stop_errors(
    push: f64,
    tol: f64,
    integrate_contacts: impl Fn(
        &rough_plane::RoughPlane,
        &mut rough_plane::State,
        f64,
    )
        -> lagrange::Result<(Outcome<rough_plane::Coords>, Vec<ModeChange>)>,
) -> ([f64; 3], Stats) {
    use rough_plane::{Coords, RoughPlane, State};
    let sys = RoughPlane {
        m: 1.5,
        g: G,
        mu_k: 0.5,
        mu_s: 0.6,
        push,
    };
    let v0 = 3.0;
    let zero = Coords {
        x: 0.0,
        y: 0.0,
        z: 0.0,
    };
    let mut s = State::new(0.0, zero, Coords { x: v0, ..zero });
    let (outcome, changes) = integrate_contacts(&sys, &mut s, tol).expect("integration");
    assert_eq!(changes.len(), 1, "{changes:?}");
    assert_eq!(
        (changes[0].from, changes[0].to),
        (RowMode::Sliding, RowMode::Stick)
    );
    assert!(s.v.x.hypot(s.v.y) < 1e-12, "{:?}", s.v);
    let (t_s, x_s, y_s) = stop(&sys, v0);
    let errors = [
        (changes[0].t - t_s).abs(),
        (s.q.x - x_s).abs(),
        (s.q.y - y_s).abs(),
    ];
    eprintln!(
        "push {push}, tol {tol:.0e}: stop time {:.1e}, point ({:.1e}, {:.1e}) off; {:?}",
        errors[0], errors[1], errors[2], outcome.stats
    );
    (errors, outcome.stats)
}

/// The puck of [`puck_stop_errors`] pushed sideways by 3 N (< μₛmg) at tolerances 1e-6, 1e-8 and
/// 1e-10: each 100× smaller tolerance must divide the errors of the stop time and point by at
/// least 30. The caller says why its method's errors fall in proportion to the tolerance.
pub fn check_pushed_puck_errors_fall_with_the_tolerance(
    integrate_contacts: impl Fn(
        &rough_plane::RoughPlane,
        &mut rough_plane::State,
        f64,
    )
        -> lagrange::Result<(Outcome<rough_plane::Coords>, Vec<ModeChange>)>,
) {
    let mut previous: Option<[f64; 3]> = None;
    for tol in [1e-6, 1e-8, 1e-10] {
        let (errors, _) = puck_stop_errors(3.0, tol, &integrate_contacts);
        if let Some(p) = previous {
            for (e, p) in errors.iter().zip(p) {
                assert!(
                    *e < p / 30.0,
                    "tol {tol:.0e}: errors {errors:?} after {p:?}"
                );
            }
        }
        previous = Some(errors);
    }
}
