//! Friction rows: a block sent up a rough ramp, a puck on a rough plane (the friction cone).

use super::contact_scenes::{check_block_sent_up_the_rough_ramp, G};
use lagrange::constraints::{ContactOptions, ContactRadau5, RowMode};
use lagrange::prelude::*;

#[test]
fn block_sent_up_a_rough_ramp_stops_then_sticks_or_slides_back_in_radau5() {
    // Piecewise constant accelerations: each phase is a quadratic in t, integrated exactly (as
    // the ball's fall); the stop is located to the root finder's 1e-13 and round-off. Asserted to
    // 1e-12.
    check_block_sent_up_the_rough_ramp(|sys, start| {
        let mut solver = ContactRadau5::new(
            sys,
            Radau5::new(1e-10, 1e-10),
            start,
            ContactOptions::default(),
        )
        .expect("solver");
        assert_eq!(solver.mode().rows, [RowMode::Active, RowMode::SlipPositive]);
        let outcome = solver.integrate(1.5, &mut [], |_| {}).expect("integration");
        (solver.events().to_vec(), solver.state(), outcome.stats)
    });
}

#[test]
fn puck_on_a_rough_plane_stops_at_the_closed_form_point_in_radau5() {
    use lagrange_gallery::scenes::rough_plane::rough_plane::{Coords, RoughPlane, State};
    use lagrange_gallery::scenes::rough_plane::stop;
    // The friction cone (`#[friction]` with a `Vec2` slip velocity): the puck of the gallery's
    // `rough_plane` sent straight at 3 m/s decelerates at μₖg, a quadratic motion integrated
    // exactly; the stop is located to the root finder's 1e-13 and round-off. Asserted to 1e-12.
    let sys = RoughPlane {
        m: 1.5,
        g: G,
        mu_k: 0.5,
        mu_s: 0.6,
        push: 0.0,
    };
    let v0 = 3.0;
    let zero = Coords {
        x: 0.0,
        y: 0.0,
        z: 0.0,
    };
    let mut s = State::new(0.0, zero, Coords { x: v0, ..zero });
    let (outcome, changes) = Radau5::new(1e-10, 1e-10)
        .integrate_contacts(
            &sys,
            &mut s,
            1.5,
            ContactOptions::default(),
            &mut [],
            |_| {},
        )
        .expect("integration");
    let (t_s, x_s, y_s) = stop(&sys, v0);
    eprintln!(
        "stop at {:.15} ({:+.1e}), {:?}",
        changes[0].t,
        changes[0].t - t_s,
        outcome.stats
    );
    // One stop, decided once (no chattering), from sliding to sticking for good, at rest to
    // round-off (sticking is enforced as a velocity constraint).
    assert_eq!(changes.len(), 1, "{changes:?}");
    assert_eq!(
        (changes[0].from, changes[0].to),
        (RowMode::Sliding, RowMode::Stick)
    );
    assert!(s.v.x.hypot(s.v.y) < 1e-12, "{:?}", s.v);
    assert!((changes[0].t - t_s).abs() < 1e-12);
    assert!((s.q.x - x_s).abs() < 1e-12 && (s.q.y - y_s).abs() < 1e-12);
}

#[test]
fn pushed_puck_on_a_rough_plane_curves_and_stops_at_the_closed_form_point_in_radau5() {
    use lagrange_gallery::scenes::rough_plane::rough_plane::{Coords, RoughPlane, State};
    use lagrange_gallery::scenes::rough_plane::stop;
    // Pushed sideways (F < μmg) the path curves and the slip direction turns ever faster near the
    // stop: the errors are the integration's, which Radau5 keeps about proportional to the
    // tolerance (radau5.f's conversion of the tolerances, HW II §IV.8), plus the direction held
    // along the step's initial slip in the step that reaches the stop, O(h·θ(h)), which falls
    // faster than h. Asserted: each 100× smaller tolerance divides the errors of the stop time and
    // point by at least 30 (proportionality with a margin of 3 for its constant).
    let sys = RoughPlane {
        m: 1.5,
        g: G,
        mu_k: 0.5,
        mu_s: 0.6,
        push: 3.0,
    };
    let v0 = 3.0;
    let zero = Coords {
        x: 0.0,
        y: 0.0,
        z: 0.0,
    };
    let (t_s, x_s, y_s) = stop(&sys, v0);
    let mut previous: Option<[f64; 3]> = None;
    for tol in [1e-6, 1e-8, 1e-10] {
        let mut s = State::new(0.0, zero, Coords { x: v0, ..zero });
        let (outcome, changes) = Radau5::new(tol, tol)
            .integrate_contacts(
                &sys,
                &mut s,
                1.5,
                ContactOptions::default(),
                &mut [],
                |_| {},
            )
            .expect("integration");
        // One stop, decided once (no chattering), from sliding to sticking for good.
        assert_eq!(changes.len(), 1, "{changes:?}");
        assert_eq!(
            (changes[0].from, changes[0].to),
            (RowMode::Sliding, RowMode::Stick)
        );
        let errors = [
            (changes[0].t - t_s).abs(),
            (s.q.x - x_s).abs(),
            (s.q.y - y_s).abs(),
        ];
        eprintln!(
            "pushed, tol {tol:.0e}: stop time {:.1e}, point ({:.1e}, {:.1e}) off; {:?}",
            errors[0], errors[1], errors[2], outcome.stats
        );
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
