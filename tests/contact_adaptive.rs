//! Unilateral contacts inside the adaptive Dormand–Prince method ([`ContactDopri5`]): the mode is
//! frozen over each step and mode changes are located on the dense output, so a contact costs about
//! what the same mechanism declared bilateral costs, and its events land on their closed forms.
//!
//! - A particle sliding off a sphere declared `#[unilateral]`, against the same sphere declared
//!   `#[constraint]` (an event on its multiplier): release time against the closed form of
//!   `tests/sphere_event.rs` (Goldstein, Poole & Safko, *Classical Mechanics*, 3rd ed., §2.4:
//!   cos θ* = (2 + v₀²/(gR))/3, t* = ∫₀^θ* R dθ / v(θ)), then the parabola after it; steps and
//!   evaluations in contact against the bilateral declaration's.
//! - A ball dropped on a floor declared `#[unilateral]`: impact at √(2h/g), bounces with Newton's
//!   restitution law, and comes to rest at the accumulation point of its bounces.
//! - A block sent up a rough ramp (`#[friction]`): it stops at t_s = u/(g(sin α + μₖ cos α)) and
//!   sticks or slides back, as μₛ decides.
//! - A puck on a rough plane (`#[friction]` with a `Vec2` slip velocity, the friction cone),
//!   straight and pushed sideways: its stop time and point against the closed forms of the
//!   gallery's `rough_plane`.
//! - Dop853 shares the solver: the sphere again.

use lagrange::constraints::{constraint_forces, ContactOptions, RowMode};
use lagrange::integrate::{Direction, EmbeddedPair, Event, Stats, StopReason};
use lagrange::prelude::*;
use lagrange_gallery::scenes::sphere_release::sphere_release as unilateral;

mod contact_scenes;
use contact_scenes::{
    ball, bilateral, bilateral_release_in, check_ball_dropped_on_the_floor,
    check_block_sent_up_the_rough_ramp, check_integrate_takes_the_contact_solver,
    check_pushed_puck_errors_fall_with_the_tolerance, on_sphere, puck_stop_errors, Start, G, M, R,
    STARTS,
};

/// Cost of a run: (steps = accepted + rejected, evaluations of q̈).
fn cost(stats: Stats) -> (usize, usize) {
    (stats.accepted + stats.rejected, stats.evaluations)
}

/// The bilateral sphere in Dopri5 from `start`, stopped where its multiplier falls through 0: the
/// release time and the cost.
fn bilateral_release(start: Start, tol: f64) -> (f64, Stats) {
    bilateral_release_in(start, |sys, s, events| {
        sys.integrate(Dopri5::new(tol, tol), s, 10.0, events, |_| {})
    })
}

#[test]
fn unilateral_sphere_releases_on_time_at_the_cost_of_the_bilateral_one() {
    sphere_release_against_closed_form(Dopri5::new(1e-13, 1e-13), 1e-13, |start| {
        bilateral_release(start, 1e-13)
    });
}

#[test]
fn unilateral_sphere_in_dop853() {
    // Dop853 shares the contact solver: the same checks, with its error bounded as below.
    let tol = 1e-13;
    sphere_release_against_closed_form(Dop853::new(tol, tol), tol, |start| {
        bilateral_release_in(start, |sys, s, events| {
            sys.integrate(Dop853::new(tol, tol), s, 10.0, events, |_| {})
        })
    });
}

/// The sphere declared unilateral in `method` (at tolerance `tol`), released from each of the
/// [`STARTS`]: release time and position against the closed form, cost in contact against
/// `bilateral` (the bilateral declaration in the same method), the parabola after.
fn sphere_release_against_closed_form<P: EmbeddedPair>(
    method: P,
    tol: f64,
    bilateral: impl Fn(Start) -> (f64, Stats),
) {
    use unilateral::{Coords, SphereRelease as Sphere, State};
    let sys = Sphere { m: M, r: R, g: G };
    // What bounds the located release time |t − t*| (the analysis of tests/sphere_event.rs,
    // for Dopri5): the root finder stops within 1e-13, and λ on the dense output is off by the
    // solution's error δ in (q, q̇) (max norm), which moves the root by δ·|∇λ|₁/|λ̇|. With
    // λ = m(g cos θ − v²/R): |∇λ|₁ ≤ √2·m(g + 2v)/R and |λ̇| = 3 m g v sin θ*/R at release, a
    // ratio ≤ 0.34 for every start (v ≈ 3.1 there). δ: each accepted step commits a local error
    // ≤ 2·tol·(1 + |y|) ≤ 8.4 tol per component (error norm ≤ 1 over 2N = 4 components,
    // |y| ≤ 3.2), grown at most like e^{λ₊(t* − s)}, λ₊ = √(g/R) (the rate off the unstable top);
    // with the n steps spread over [0, t*], δ ≤ (n/t*)·(e^{λ₊t*} − 1)/λ₊ · 8.4 tol, and the
    // dense output adds one more local error (n + 1 below). tol = 1e-13 makes the bound ~1e-10
    // for Dopri5 (and ~1e-11 for Dop853, which takes fewer steps).
    let rate = (G / R).sqrt();
    for start in STARTS {
        let Start { theta0, v0, .. } = start;
        let (t_star, cos_star) = start.release();
        let ([x, y], [vx, vy]) = start.state();
        let state = State::new(0.0, Coords { x, y }, Coords { x: vx, y: vy });
        let mut solver = Stepper::new(&sys, method, &state).expect("solver");
        assert_eq!(solver.contacts().mode().rows, [RowMode::Active]);
        while solver.mode_changes().is_empty() {
            solver.step(10.0).expect("step");
        }
        let in_contact = solver.stats();
        let change = solver.mode_changes()[0];
        let (t_bil, bil) = bilateral(start);
        let (steps_u, evals_u) = cost(in_contact);
        let (steps_b, evals_b) = cost(bil);
        eprintln!(
            "{}, θ₀ = {theta0}, v₀ = {v0}: released at t = {:.15} (closed form {t_star:.15}, {:+.1e}; bilateral \
             {:+.1e}); in contact, unilateral {steps_u} steps ({} rejected) {evals_u} evaluations \
             {} event evaluations, bilateral {steps_b} steps ({} rejected) {evals_b} evaluations",
            P::NAME,
            change.t,
            change.t - t_star,
            t_bil - t_star,
            in_contact.rejected,
            in_contact.event_evaluations,
            bil.rejected,
        );
        assert_eq!(
            (change.constraint, change.from, change.to),
            ("surface", RowMode::Active, RowMode::Inactive)
        );
        let delta =
            (steps_u + 1) as f64 / t_star * ((rate * t_star).exp() - 1.0) / rate * 8.4 * tol;
        let bound = 1e-13 + 0.34 * delta;
        eprintln!("    bound on |t − t*|: {bound:.1e} (δ ≤ {delta:.1e})");
        assert!(
            (change.t - t_star).abs() < bound,
            "θ₀ = {theta0}, v₀ = {v0}: released at {}, closed form {t_star}",
            change.t
        );
        // The position at the release: cos θ = y/|r| against cos θ*, off by δ/R plus
        // |d cos θ/dt| = v sin θ*/R ≤ 2 s⁻¹ times the time error.
        let s = solver.state();
        let cos = s.q.y / s.q.x.hypot(s.q.y);
        assert!(
            (cos - cos_star).abs() < delta / R + 2.0 * bound,
            "θ₀ = {theta0}, v₀ = {v0}: cos θ = {cos}, cos θ* = {cos_star}"
        );
        // The cost in contact: within 2× of the bilateral declaration's (which stops at the same
        // instant by a user event on its multiplier).
        assert!(
            steps_u as f64 <= 2.0 * steps_b as f64 && evals_u as f64 <= 2.0 * evals_b as f64,
            "θ₀ = {theta0}, v₀ = {v0}: unilateral {steps_u} steps / {evals_u} evaluations, bilateral {steps_b} / \
             {evals_b}"
        );

        // After the release: a projectile from the closed-form release state, x* = R(sin θ*,
        // cos θ*) with speed v* = √(v₀² + 2gR(cos θ₀ − cos θ*)) along the tangent (cos θ*, −sin θ*),
        // 0.3 s later. Both methods integrate the parabola exactly (quadratic in t), so the error
        // is the release state's: δ in (q, q̇), carried to (1 + τ)·δ over τ = 0.3 s of free flight
        // (at the release λ = 0, so leaving the sphere a time Δt early or late changes the path by
        // O(|λ̇|Δt²/m) ≈ 1e-18 only).
        let t_flight = t_star + 0.3;
        let outcome = solver.integrate(t_flight, &mut [], |_| {}).expect("flight");
        assert_eq!(outcome.reason, StopReason::Reached);
        assert_eq!(
            solver.mode_changes().len(),
            1,
            "no second contact: it flies off the sphere"
        );
        let sin_star = (1.0 - cos_star * cos_star).sqrt();
        let v_star = start.speed(cos_star.acos());
        let tau = t_flight - t_star;
        let x = R * sin_star + v_star * cos_star * tau;
        let y = R * cos_star - v_star * sin_star * tau - 0.5 * G * tau * tau;
        let s = solver.state();
        eprintln!(
            "    flight: at t* + 0.3 s, ({:.12}, {:.12}) against ({x:.12}, {y:.12})",
            s.q.x, s.q.y
        );
        let flight_bound = 1.3 * delta + 1e-13;
        assert!((s.q.x - x).abs() < flight_bound && (s.q.y - y).abs() < flight_bound);
    }
}

#[test]
fn ball_dropped_on_a_unilateral_floor_lands_at_the_closed_form_time() {
    // Free fall and flight are quadratic in t, which Dopri5 (order 5) integrates exactly: the only
    // errors are the root finder's 1e-13 and round-off over a few steps. Asserted to 1e-12.
    check_ball_dropped_on_the_floor(|sys, s, options| {
        contact_scenes::integrate_contacts(
            sys,
            Dopri5::new(1e-10, 1e-10),
            s,
            2.0,
            options,
            &mut [],
            |_| {},
        )
    });
}

#[test]
fn block_sent_up_a_rough_ramp_stops_then_sticks_or_slides_back() {
    // Piecewise constant accelerations: each phase is a quadratic in t, integrated exactly by
    // Dopri5; the stop is located to the root finder's 1e-13 and round-off. Asserted to 1e-12.
    check_block_sent_up_the_rough_ramp(|sys, start| {
        let mut solver = Stepper::new(sys, Dopri5::new(1e-10, 1e-10), start).expect("solver");
        assert_eq!(
            solver.contacts().mode().rows,
            [RowMode::Active, RowMode::SlipPositive]
        );
        let outcome = solver.integrate(1.5, &mut [], |_| {}).expect("integration");
        (
            solver.mode_changes().to_vec(),
            solver.state(),
            outcome.stats,
        )
    });
}

/// One interface: `Dopri5::integrate` and `Dop853::integrate` on a declaration with a unilateral
/// row take the contact solver (the mechanism's hidden hook decides from the declaration), so they
/// are the same run as `integrate_contacts`: same steps, same evaluations, same end state, bit for
/// bit.
#[test]
fn integrate_takes_the_contact_solver_on_a_unilateral_declaration() {
    check_integrate_takes_the_contact_solver(
        |sys, s, t_end| sys.integrate(Dopri5::new(1e-9, 1e-9), s, t_end, &mut [], |_| {}),
        |sys, s, t_end| {
            contact_scenes::integrate_contacts(
                sys,
                Dopri5::new(1e-9, 1e-9),
                s,
                t_end,
                ContactOptions::default(),
                &mut [],
                |_| {},
            )
        },
    );
    check_integrate_takes_the_contact_solver(
        |sys, s, t_end| sys.integrate(Dop853::new(1e-9, 1e-9), s, t_end, &mut [], |_| {}),
        |sys, s, t_end| {
            contact_scenes::integrate_contacts(
                sys,
                Dop853::new(1e-9, 1e-9),
                s,
                t_end,
                ContactOptions::default(),
                &mut [],
                |_| {},
            )
        },
    );
}

/// The figures of BENCHMARKS.md: steps and evaluations in contact, up to the release, for the
/// sphere declared unilateral (in [`ContactDopri5`], and through `Dopri5::integrate`, which takes
/// the same solver) and bilateral (Dopri5 with an event on its multiplier).
/// `cargo test --release --test contact_adaptive -- --ignored --nocapture`
#[test]
#[ignore = "prints the cost table of BENCHMARKS.md"]
fn cost_in_contact_table() {
    use unilateral::{Coords, SphereRelease as Sphere, State};
    let sys = Sphere { m: M, r: R, g: G };
    let v0 = 0.5;
    println!(
        "| tol | unilateral, ContactDopri5 | unilateral, `Dopri5::integrate` | bilateral, Dopri5 |"
    );
    println!("|---|---|---|---|");
    for tol in [1e-6, 1e-10, 1e-13] {
        let start = State::new(0.0, Coords { x: 0.0, y: R }, Coords { x: v0, y: 0.0 });
        let mut solver = Stepper::new(&sys, Dopri5::new(tol, tol), &start).expect("solver");
        while solver.mode_changes().is_empty() {
            solver.step(10.0).expect("step");
        }
        let frozen = solver.stats();
        let normal = |s: &State| constraint_forces(&sys, s).expect("forces").multipliers[0];
        let mut events = [Event::new(&normal).direction(Direction::Falling).terminal()];
        let mut s = start;
        let plain = sys
            .integrate(Dopri5::new(tol, tol), &mut s, 10.0, &mut events, |_| {})
            .expect("integration")
            .stats;
        let (_, bil) = bilateral_release(on_sphere(0.0, v0), tol);
        let show = |s: Stats| {
            format!(
                "{} accepted + {} rejected, {} evaluations",
                s.accepted, s.rejected, s.evaluations
            )
        };
        println!(
            "| {tol:.0e} | {} | {} | {} |",
            show(frozen),
            show(plain),
            show(bil)
        );
    }
}

#[test]
fn puck_on_a_rough_plane_stops_at_the_closed_form_point() {
    // The friction cone (`#[friction]` with a `Vec2` slip velocity) in the adaptive method: the
    // puck of the gallery's `rough_plane` from 3 m/s, straight and pushed sideways; closed forms of
    // the stop (time and point) in `stop`.
    let run = |sys: &_, s: &mut _, tol: f64| {
        contact_scenes::integrate_contacts(
            sys,
            Dopri5::new(tol, tol),
            s,
            1.5,
            ContactOptions::default(),
            &mut [],
            |_| {},
        )
    };
    // Straight: a constant deceleration, integrated exactly (quadratic in t); the stop is located
    // to the root finder's 1e-13 and round-off. Asserted to 1e-12.
    let (errors, _) = puck_stop_errors(0.0, 1e-10, run);
    assert!(errors.iter().all(|e| *e < 1e-12), "{errors:?}");
    // Pushed sideways: the path curves and the slip direction turns ever faster near the stop, so
    // the errors are the integration's, which Dopri5 keeps proportional to the tolerance (HNW I
    // §II.4: the global error of a tolerance-controlled method is proportional to tol), plus the
    // direction held along the step's initial slip in the step that reaches the stop, O(h·θ(h)),
    // which falls faster than h. Asserted: each 100× smaller tolerance divides the errors of the
    // stop time and point by at least 30 (proportionality with a margin of 3 for its constant).
    check_pushed_puck_errors_fall_with_the_tolerance(run);
}

#[test]
fn bouncing_ball_comes_to_rest_at_the_accumulation_point() {
    use ball::{Ball, Coords, State};
    use lagrange::constraints::CONSISTENCY_TOLERANCE;
    let sys = Ball { m: 0.3, g: G };
    let height = 1.3;
    let t1 = (2.0 * height / G).sqrt();
    for e in [0.6, 0.9] {
        // Newton's law ċ⁺ = −e ċ⁻: flights of 2e·v/g, 2e²·v/g, … after the first landing at t₁
        // with v = g t₁, so the bounces accumulate at t∞ = t₁ (1 + e)/(1 − e) (a Zeno sequence).
        // The impact law stops bouncing once the rebound speed e·v would be below
        // CONSISTENCY_TOLERANCE, which leaves out flights summing to at most
        // 2·tol/(g(1 − e)); each landing is located to 1e-13, an error that shortens or lengthens
        // each later flight by 2e per unit, at most n·1e-13·(1 + e)/(1 − e) over n landings.
        let t_inf = t1 * (1.0 + e) / (1.0 - e);
        let mut s = State::new(0.0, Coords { x: 0.2, y: height }, Coords { x: 0.5, y: 0.0 });
        let options = ContactOptions {
            restitution: e,
            ..Default::default()
        };
        let (outcome, changes) = contact_scenes::integrate_contacts(
            &sys,
            Dopri5::new(1e-10, 1e-10),
            &mut s,
            30.0,
            options,
            &mut [],
            |_| {},
        )
        .expect("integration");
        let last = *changes.last().expect("landings");
        let bound = 2.0 * CONSISTENCY_TOLERANCE / (G * (1.0 - e))
            + changes.len() as f64 * 1e-13 * (1.0 + e) / (1.0 - e);
        eprintln!(
            "e = {e}: {} landings, at rest from t = {:.12} (closed form {t_inf:.12}, bound \
             {bound:.1e}); {} steps, {} evaluations",
            changes.len(),
            last.t,
            outcome.stats.accepted + outcome.stats.rejected,
            outcome.stats.evaluations
        );
        assert_eq!(last.to, RowMode::Active);
        assert!((last.t - t_inf).abs() < bound, "{} against {t_inf}", last.t);
        // At rest on the floor from then on (the contact projected to round-off), still sliding at
        // 0.5 m/s exactly: impulses and projections act along the floor's normal (0, 1) only.
        assert!(s.q.y.abs() < 1e-12 && s.v.y.abs() < 1e-12 && s.v.x == 0.5);
        // One step per flight, and a few more: the motion is polynomial.
        assert!(outcome.stats.accepted < changes.len() + 10);
    }
}

/// The fixed-step implicit methods and the plain Radau5 stepper refuse a declaration with a
/// unilateral row up front (its mode switches inside a step, where a collocation polynomial has
/// nothing to follow), by the declaration, with the state unchanged; the same sphere declared
/// bilateral steps.
#[test]
fn raw_implicit_steps_refuse_unilateral_declarations() {
    let start = on_sphere(0.0, 0.5);
    let ([x, y], [vx, vy]) = start.state();
    let sys = unilateral::SphereRelease { m: M, r: R, g: G };
    let s0 = unilateral::State::new(
        0.0,
        unilateral::Coords { x, y },
        unilateral::Coords { x: vx, y: vy },
    );
    let refused = |result: lagrange::Result<()>, method: &str| {
        assert!(
            matches!(&result, Err(lagrange::Error::UnsuitableMethod { method: m, reason })
                if *m == method && reason.contains("unilateral")),
            "{method}: {result:?}"
        );
    };
    let mut s = s0;
    // A step on raw arrays has no contact mode to hold, so it refuses the declaration; the time
    // loops (`sys.step`, a `Stepper`) hold the mode over each step instead
    // (tests/contact_fixed_step.rs, tests/contact_implicit/).
    refused(
        GaussLegendre2::step_with_stats(&sys, &mut s, 1e-3).map(|_| ()),
        "Gauss-Legendre 2",
    );
    refused(
        ImplicitMidpoint::step_with_stats(&sys, &mut s, 1e-3).map(|_| ()),
        "implicit midpoint",
    );
    assert!(
        lagrange::integrate::Stepper::new(&sys, Radau5::new(1e-8, 1e-8), &s).is_ok(),
        "a Radau5 stepper holds the contact mode"
    );
    assert_eq!(s, s0, "a refused step changes nothing");
    let bilateral = bilateral::Sphere { m: M, r: R, g: G };
    let mut b = bilateral::State::new(
        0.0,
        bilateral::Coords { x, y },
        bilateral::Coords { x: vx, y: vy },
    );
    bilateral
        .step::<GaussLegendre2>(&mut b, 1e-3)
        .expect("the bilateral declaration steps");
}
