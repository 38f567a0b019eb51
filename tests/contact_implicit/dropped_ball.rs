//! A ball dropped on a floor declared `#[unilateral]`: plastic and with restitution, and with
//! user events beside the contact events.

use super::contact_scenes::{ball, check_ball_dropped_on_the_floor, G};
use lagrange::integrate::{Direction, Event, StopReason};
use lagrange::prelude::*;

#[test]
fn ball_dropped_on_a_unilateral_floor_lands_at_the_closed_form_time_in_radau5() {
    // Free fall and flight are quadratic in t, which the collocation polynomial (cubic)
    // reproduces and the Newton iteration solves exactly (the stage equations are linear, the
    // Jacobian exact): the only errors are the root finder's 1e-13 and round-off over a few steps.
    // Asserted to 1e-12.
    check_ball_dropped_on_the_floor(|sys, s, options| {
        super::contact_scenes::integrate_contacts(
            sys,
            Radau5::new(1e-10, 1e-10),
            s,
            2.0,
            options,
            &mut [],
            |_| {},
        )
    });
}

#[test]
fn user_events_and_contact_events_together_in_radau5_integrate() {
    use ball::{Ball, Coords, State};
    let sys = Ball { m: 0.3, g: G };
    // `Radau5::integrate` on the ball (a unilateral floor, so the contact solver): a user event
    // when it falls through y = 0.65 m on the way down, non-terminal, and another, terminal, when
    // it rises through 0.1 m after bouncing (restitution is the default 0 here, so it never
    // does: the run reaches t_end). Free fall is a quadratic, which the collocation polynomial
    // reproduces: the crossing at √(2·0.65/g) to the root finder's 1e-13. Asserted to 1e-12.
    let mut s = State::new(0.0, Coords { x: 0.0, y: 1.3 }, Coords { x: 0.0, y: 0.0 });
    let half = |s: &State| s.q.y - 0.65;
    let rise = |s: &State| s.q.y - 0.1;
    let mut events = [
        Event::new(&half).direction(Direction::Falling),
        Event::new(&rise).direction(Direction::Rising).terminal(),
    ];
    let mut crossings = Vec::new();
    let outcome = sys
        .integrate(Radau5::new(1e-10, 1e-10), &mut s, 1.0, &mut events, |o| {
            if let lagrange::integrate::Observation::Event(hit) = o {
                crossings.push((hit.index, hit.state.t));
            }
        })
        .expect("integration");
    assert_eq!(outcome.reason, StopReason::Reached);
    assert_eq!(crossings.len(), 1, "{crossings:?}");
    let t_half = (2.0 * 0.65 / G).sqrt();
    assert!(
        (crossings[0].1 - t_half).abs() < 1e-12,
        "{crossings:?} against {t_half}"
    );
    assert!(s.q.y.abs() < 1e-12 && s.t == 1.0);
}
