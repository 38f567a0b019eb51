//! A particle sliding off a sphere declared `#[unilateral]`, against the same sphere declared
//! `#[constraint]`; one interface for the contact solver.

use super::contact_scenes::{
    bilateral_release_in, check_integrate_takes_the_contact_solver, Start, G, M, R, STARTS,
};
use lagrange::constraints::{ContactOptions, RowMode};
use lagrange::integrate::Stats;
use lagrange::prelude::*;
use lagrange_gallery::scenes::sphere_release::sphere_release as unilateral;

/// The bilateral sphere in Radau5 from `start`, stopped where its multiplier falls through 0 (a
/// user event, located on the same collocation polynomials): the release time and the cost.
pub(super) fn bilateral_release(start: Start, tol: f64) -> (f64, Stats) {
    bilateral_release_in(start, |sys, s, events| {
        sys.integrate(Radau5::new(tol, tol), s, 10.0, events, |_| {})
    })
}

/// The unilateral sphere in [`ContactRadau5`] from `start` up to its release: the release time,
/// the cost and the longest step taken.
pub(super) fn unilateral_release(start: Start, tol: f64) -> (f64, Stats, f64) {
    use unilateral::{Coords, SphereRelease, State};
    let sys = SphereRelease { m: M, r: R, g: G };
    let ([x, y], [vx, vy]) = start.state();
    let state = State::new(0.0, Coords { x, y }, Coords { x: vx, y: vy });
    let mut solver = Stepper::new(&sys, Radau5::new(tol, tol), &state).expect("solver");
    assert_eq!(solver.contacts().mode().rows, [RowMode::Active]);
    let mut longest = 0.0f64;
    while solver.mode_changes().is_empty() {
        solver.step(10.0).expect("step");
        longest = longest.max(solver.dense().t_end() - solver.dense().t_start());
    }
    let change = solver.mode_changes()[0];
    assert_eq!(
        (change.constraint, change.from, change.to),
        ("surface", RowMode::Active, RowMode::Inactive)
    );
    (change.t, solver.stats(), longest)
}

#[test]
fn unilateral_sphere_in_radau5_releases_on_time_at_the_cost_of_the_bilateral_one() {
    let tol = 1e-13;
    for start in STARTS {
        let Start { theta0, v0, .. } = start;
        let (t_star, _) = start.release();
        let (t_u, uni, longest) = unilateral_release(start, tol);
        let (t_b, bil) = bilateral_release(start, tol);
        eprintln!(
            "θ₀ = {theta0}, v₀ = {v0}: released at t = {t_u:.15} (closed form {t_star:.15}, \
             {:+.1e}; bilateral {:+.1e}); longest step {longest:.1e} s\n    in contact, \
             unilateral: {uni:?}\n    bilateral: {bil:?}",
            t_u - t_star,
            t_b - t_star
        );
        // What bounds |t − t*|: the error of λ = m(g cos θ − v²/R) along the step's collocation
        // polynomial, divided by |λ̇| (a ratio |∇λ|₁/|λ̇| ≤ 0.34 s, tests/contact_adaptive.rs), plus
        // the root finder's 1e-13. That error has two parts: (i) the global error of the step
        // solution, which radau5.f's conversion of the tolerances keeps about proportional to
        // rtol (Hairer & Wanner, *Solving ODEs II*, §IV.8): a few 1e-13 here, grown by at most
        // e^{√(g/R) t*} ≤ 25 off the unstable top; (ii) the polynomial's own error inside a step,
        // O(h⁴) (the stage order 3; at the step's end it is the solution's), small with the steps
        // of at most 1e-2 s that tol = 1e-13 takes here (asserted). No a-priori constant of (ii)
        // is claimed: the bound is the requirement on a located release, 1e-10, which these
        // runs meet by an order of magnitude (the errors per tolerance are in BENCHMARKS.md,
        // §11); the bilateral declaration, whose event is located on the same polynomials by the
        // solvers' own event finder, agrees (asserted below).
        assert!(longest < 1e-2, "longest step {longest}");
        assert!(
            (t_u - t_star).abs() < 1e-10,
            "θ₀ = {theta0}, v₀ = {v0}: released at {t_u}, closed form {t_star}"
        );
        // The contact solver integrates the same field as the bilateral declaration while in
        // contact, with the same steps: both locate the release on the same polynomial, each
        // root finder to 1e-13.
        assert!((t_u - t_b).abs() < 2e-13, "{t_u} against bilateral {t_b}");
        // The cost in contact: within 2× of the bilateral declaration's (which stops at the same
        // instant by a user event on its multiplier).
        for (what, u, b) in [
            (
                "steps",
                uni.accepted + uni.rejected,
                bil.accepted + bil.rejected,
            ),
            (
                "Newton iterations",
                uni.newton_iterations,
                bil.newton_iterations,
            ),
            ("evaluations", uni.evaluations, bil.evaluations),
        ] {
            eprintln!(
                "    {what}: unilateral {u}, bilateral {b}, ratio {:.3}",
                u as f64 / b as f64
            );
            assert!(u <= 2 * b, "{what}: unilateral {u}, bilateral {b}");
        }
    }
}

/// One interface: `Radau5::integrate` and `sys.step::<Radau5>` on a declaration with a unilateral
/// row take the contact solver, so they are the same run as `Radau5::integrate_contacts`: same
/// steps, same evaluations, same end state, bit for bit.
#[test]
fn radau5_integrate_takes_the_contact_solver_on_a_unilateral_declaration() {
    use unilateral::{Coords, SphereRelease, State};
    let method = Radau5::new(1e-9, 1e-9);
    check_integrate_takes_the_contact_solver(
        |sys, s, t_end| sys.integrate(method, s, t_end, &mut [], |_| {}),
        |sys, s, t_end| {
            super::contact_scenes::integrate_contacts(
                sys,
                method,
                s,
                t_end,
                ContactOptions::default(),
                &mut [],
                |_| {},
            )
        },
    );
    let sys = SphereRelease { m: M, r: R, g: G };
    let start = State::new(0.0, Coords { x: 0.0, y: R }, Coords { x: 0.5, y: 0.0 });
    let t_end = 2.5;
    // `sys.step::<Radau5>` over [0, 2.5] with the default tolerances: the same as
    // `integrate_contacts` with `Radau5::default()`.
    let mut stepped = start;
    sys.step::<Radau5>(&mut stepped, t_end).expect("step");
    let mut direct = start;
    super::contact_scenes::integrate_contacts(
        &sys,
        Radau5::default(),
        &mut direct,
        t_end,
        ContactOptions::default(),
        &mut [],
        |_| {},
    )
    .expect("integrate_contacts");
    assert_eq!(stepped, direct);
    assert!(
        stepped.q.x.hypot(stepped.q.y) > R + 0.1,
        "it flew off the sphere"
    );
}
