//! Unilateral contacts and friction with the fixed-step implicit methods, implicit midpoint and
//! Gauss–Legendre 2, in the fixed-step loop holding the contact mode (a step in the held mode, the
//! event located on the method's own steps, the step cut there and the rest taken as a shorter
//! step in the new mode):
//!
//! - a particle sliding off a sphere declared `#[unilateral]` (the gallery's `sphere_release`):
//!   its release time against the closed form (Goldstein, Poole & Safko, *Classical Mechanics*,
//!   3rd ed., §2.4), converging at the methods' orders;
//! - a ball dropped on a `#[unilateral]` floor (plastic and with restitution) and a block sent up a
//!   rough ramp (`#[friction]`, the gallery's `rough_ramp`): landings and stop at the closed-form
//!   times.

use lagrange::constraints::{ContactOptions, RowMode};
use lagrange::prelude::*;
use lagrange_gallery::scenes::rough_ramp::rough_ramp;
use lagrange_gallery::scenes::sphere_release::{sphere_release as unilateral, Release};

mod contact_scenes;
use contact_scenes::{ball, G, M, R, STARTS};

/// The release time as a function of the step size.
type ReleaseTime<'a> = dyn Fn(f64) -> f64 + 'a;

/// Fixed-step implicit methods with contacts: a solver with Gauss–Legendre 2 or implicit midpoint
/// holds the contact mode over its steps as it does with RK4.
fn release_with_fixed_step<I: lagrange::Integrator>(start: Release, h: f64) -> f64 {
    use unilateral::{Coords, SphereRelease, State};
    let sys = SphereRelease { m: M, r: R, g: G };
    let ([x, y], [vx, vy]) = start.state();
    let s = State::new(0.0, Coords { x, y }, Coords { x: vx, y: vy });
    let mut contact = Stepper::new(&sys, I::with_step(h), &s).expect("stepper");
    while contact.mode_changes().is_empty() {
        contact.step(f64::INFINITY).expect("step");
    }
    let change = contact.mode_changes()[0];
    assert_eq!(
        (change.constraint, change.from, change.to),
        ("surface", RowMode::Active, RowMode::Inactive)
    );
    change.t
}

#[test]
fn unilateral_sphere_with_gauss_legendre_and_implicit_midpoint_releases_at_their_order() {
    // The release time's error is the method's global error carried to λ (its event is located
    // on the method's own steps, to the event tolerance 1e-13·(|t| + h)): O(h⁴) for Gauss–Legendre
    // 2, O(h²) for implicit midpoint. Checked: halving h from 1e-2 divides the error by 2⁴ and 2²
    // (within [0.6, 1.6] of it: the next term of the error expansion at these h), and at h = 1e-3
    // the error is within what h = 1e-2's error, scaled by the order, predicts (×2 for the next
    // term) plus the event tolerance (2.2e-13).
    for start in STARTS {
        let (t_star, _) = start.release();
        let gauss = |h| release_with_fixed_step::<GaussLegendre2>(start, h);
        let midpoint = |h| release_with_fixed_step::<ImplicitMidpoint>(start, h);
        let methods: [(&str, i32, &ReleaseTime); 2] = [
            ("Gauss-Legendre 2", 4, &gauss),
            ("implicit midpoint", 2, &midpoint),
        ];
        for (name, order, error) in methods {
            let [e1, e2, e3] = [1e-2, 5e-3, 1e-3].map(|h| error(h) - t_star);
            let ratio = e1 / e2;
            let expected = 2f64.powi(order);
            eprintln!(
                "{name}, {start:?}: release error {e1:+.2e} (h = 1e-2), {e2:+.2e} (5e-3), \
                 {e3:+.2e} (1e-3); ratio {ratio:.2} (2^{order} = {expected})"
            );
            assert!(
                ratio > 0.6 * expected && ratio < 1.6 * expected,
                "{name}: ratio {ratio}"
            );
            let predicted = 2.0 * e1.abs() * 0.1f64.powi(order) + 2.2e-13;
            assert!(e3.abs() < predicted, "{name}: {e3:e} against {predicted:e}");
        }
    }
}

#[test]
fn ball_lands_and_block_stops_on_time_with_the_fixed_step_implicit_methods() {
    // Constant accelerations between events: q is quadratic in t and p linear, which both Gauss
    // methods on (q, p) integrate exactly; the events are located to the event tolerance
    // 1e-13·(|t| + h) on exact steps. Asserted to 1e-12 (landing and stop times, positions).
    fn ball_run<I: lagrange::Integrator>(restitution: f64) -> (Vec<f64>, ball::State) {
        use ball::{Ball, Coords, State};
        let sys = Ball { m: 0.3, g: G };
        let s = State::new(0.0, Coords { x: 0.2, y: 1.3 }, Coords { x: 0.5, y: 0.0 });
        let options = ContactOptions {
            restitution,
            ..Default::default()
        };
        let mut contact = Stepper::new(&sys, I::with_step(1e-2), &s)
            .and_then(|solver| solver.with_contact_options(options))
            .expect("stepper");
        for _ in 0..150 {
            contact.step(f64::INFINITY).expect("step");
        }
        let landings = contact.mode_changes().iter().map(|c| c.t).collect();
        (landings, contact.state())
    }
    let t1 = (2.0 * 1.3 / G).sqrt();
    for (name, run) in [
        (
            "Gauss-Legendre 2",
            ball_run::<GaussLegendre2> as fn(f64) -> (Vec<f64>, ball::State),
        ),
        ("implicit midpoint", ball_run::<ImplicitMidpoint>),
    ] {
        let (landings, s) = run(0.0);
        assert_eq!(landings.len(), 1, "{name}: {landings:?}");
        assert!((landings[0] - t1).abs() < 1e-12, "{name}: {landings:?}");
        assert!(s.q.y.abs() < 1e-12 && s.v.y.abs() < 1e-12 && (s.q.x - 0.95).abs() < 1e-12);
        // Bounces with e = 0.6: landings at t₁(1 + 2e + … + 2eᵏ⁻¹).
        let (landings, _) = run(0.6);
        let (mut landing, mut flight) = (t1, 1.2 * t1);
        for t in landings.iter().take(3) {
            assert!((t - landing).abs() < 1e-12, "{name}: {t} against {landing}");
            landing += flight;
            flight *= 0.6;
        }
    }
    // The block sent up the rough ramp stops at u/(g(sin α + μₖ cos α)) and sticks.
    use rough_ramp::{Coords, RoughRamp, State};
    let (alpha, u) = (0.5f64, 2.0);
    let (sn, cs) = alpha.sin_cos();
    let sys = RoughRamp {
        m: 2.0,
        alpha,
        g: G,
        mu_k: 0.5,
        mu_s: 0.6,
    };
    let t_stop = u / (G * (sn + 0.5 * cs));
    let s = State::new(
        0.0,
        Coords { x: 0.0, y: 0.0 },
        Coords {
            x: u * cs,
            y: u * sn,
        },
    );
    let mut contact = Stepper::new(&sys, GaussLegendre2::with_step(1e-2), &s).expect("stepper");
    for _ in 0..50 {
        contact.step(f64::INFINITY).expect("step");
    }
    let changes = contact.mode_changes();
    assert_eq!(changes.len(), 1, "{changes:?}");
    assert_eq!(changes[0].to, RowMode::Stick);
    assert!((changes[0].t - t_stop).abs() < 1e-12);
    let s = contact.state();
    assert!(s.v.x.hypot(s.v.y) < 1e-12);
}

#[test]
fn a_single_step_of_the_fixed_step_implicit_methods_holds_the_contact_mode() {
    // `sys.step::<I>` on a declaration with unilateral or friction rows takes one step with the
    // state's own mode held (default options: plastic impacts).
    // The ball's fall is a quadratic, integrated exactly by both Gauss methods, and its landing is
    // located to the event tolerance: after 1.5 s it rests on the floor at x = 0.2 + 0.5·1.5,
    // to 1e-12, as the persistent stepper's run above.
    fn ball_steps<I: lagrange::Integrator>() -> ball::State {
        use ball::{Ball, Coords, State};
        let sys = Ball { m: 0.3, g: G };
        let mut s = State::new(0.0, Coords { x: 0.2, y: 1.3 }, Coords { x: 0.5, y: 0.0 });
        for _ in 0..150 {
            sys.step::<I>(&mut s, 1e-2).expect("step");
        }
        s
    }
    for (name, s) in [
        ("Gauss-Legendre 2", ball_steps::<GaussLegendre2>()),
        ("implicit midpoint", ball_steps::<ImplicitMidpoint>()),
    ] {
        assert!((s.t - 1.5).abs() < 1e-12, "{name}: t = {}", s.t);
        assert!(
            s.q.y.abs() < 1e-12 && s.v.y.abs() < 1e-12 && (s.q.x - 0.95).abs() < 1e-12,
            "{name}: {s:?}"
        );
    }
    // The block sent up the rough ramp stops at u/(g(sin α + μₖ cos α)) and sticks: after 0.5 s
    // (past the stop at 0.316 s) it is at rest where the closed form puts it,
    // s = u²/(2g(sin α + μₖ cos α)) along the slope, to 1e-12 (exact steps, located stop).
    use rough_ramp::{Coords, RoughRamp, State};
    let (alpha, u) = (0.5f64, 2.0);
    let (sn, cs) = alpha.sin_cos();
    let sys = RoughRamp {
        m: 2.0,
        alpha,
        g: G,
        mu_k: 0.5,
        mu_s: 0.6,
    };
    let mut s = State::new(
        0.0,
        Coords { x: 0.0, y: 0.0 },
        Coords {
            x: u * cs,
            y: u * sn,
        },
    );
    for _ in 0..50 {
        sys.step::<GaussLegendre2>(&mut s, 1e-2).expect("step");
    }
    let reach = u * u / (2.0 * G * (sn + 0.5 * cs));
    assert!(
        (s.q.x - reach * cs).abs() < 1e-12 && (s.q.y - reach * sn).abs() < 1e-12,
        "{s:?}"
    );
    assert!(s.v.x.abs() < 1e-12 && s.v.y.abs() < 1e-12, "{s:?}");
}
