//! Friction rows: a block sent up a rough ramp, a puck on a rough plane (the friction cone).

use super::contact_scenes::{
    check_block_sent_up_the_rough_ramp, check_pushed_puck_errors_fall_with_the_tolerance,
    puck_stop_errors,
};
use lagrange::constraints::ModeChange;
use lagrange::constraints::{ContactOptions, RowMode};
use lagrange::integrate::Outcome;
use lagrange::prelude::*;
use lagrange_gallery::scenes::rough_plane::rough_plane::{self, RoughPlane};

#[test]
fn block_sent_up_a_rough_ramp_stops_then_sticks_or_slides_back_in_radau5() {
    // Piecewise constant accelerations: each phase is a quadratic in t, integrated exactly (as
    // the ball's fall); the stop is located to the root finder's 1e-13 and round-off. Asserted to
    // 1e-12.
    check_block_sent_up_the_rough_ramp(|sys, start| {
        let mut solver = Stepper::new(sys, Radau5::new(1e-10, 1e-10), start).expect("solver");
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

#[test]
fn puck_on_a_rough_plane_stops_at_the_closed_form_point_in_radau5() {
    // The friction cone (`#[friction]` with a `Vec2` slip velocity): the puck of the gallery's
    // `rough_plane` sent straight at 3 m/s decelerates at μₖg, a quadratic motion integrated
    // exactly; the stop is located to the root finder's 1e-13 and round-off. Asserted to 1e-12.
    let (errors, _) = puck_stop_errors(0.0, 1e-10, radau5_contacts);
    assert!(errors.iter().all(|e| *e < 1e-12), "{errors:?}");
}

#[test]
fn pushed_puck_on_a_rough_plane_curves_and_stops_at_the_closed_form_point_in_radau5() {
    // Pushed sideways (F < μmg) the path curves and the slip direction turns ever faster near the
    // stop: the errors are the integration's, which Radau5 keeps about proportional to the
    // tolerance (radau5.f's conversion of the tolerances, HW II §IV.8), plus the direction held
    // along the step's initial slip in the step that reaches the stop, O(h·θ(h)), which falls
    // faster than h. Asserted: each 100× smaller tolerance divides the errors of the stop time and
    // point by at least 30 (proportionality with a margin of 3 for its constant).
    check_pushed_puck_errors_fall_with_the_tolerance(radau5_contacts);
}

/// The puck to t = 1.5 in `Radau5::integrate_contacts` at tolerance `tol`.
fn radau5_contacts(
    sys: &RoughPlane,
    s: &mut rough_plane::State,
    tol: f64,
) -> lagrange::Result<(Outcome<rough_plane::Coords>, Vec<ModeChange>)> {
    super::contact_scenes::integrate_contacts(
        sys,
        Radau5::new(tol, tol),
        s,
        1.5,
        ContactOptions::default(),
        &mut [],
        |_| {},
    )
}
