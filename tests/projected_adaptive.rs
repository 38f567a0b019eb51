//! The adaptive pairs on a constrained mechanism: every accepted step is projected onto the
//! constraints, and the step's last evaluation (at the end before the projection) is kept as the
//! next step's first stage, so a projected step costs the evaluations of an unconstrained one.
//! The projection moves the state by one step's drift, of the order of the local error, so
//! keeping that evaluation must not cost accuracy: the runs converge to the angle form's solution
//! as the tolerance falls.

use lagrange::integrate::{Dop853, Dopri5, Observation};
use lagrange::prelude::*;
use lagrange_gallery::scenes::cartesian_pendulum::angle_pendulum::{self, AnglePendulum};
use lagrange_gallery::scenes::cartesian_pendulum::cartesian_pendulum::{self, CartesianPendulum};

const ROD: CartesianPendulum = CartesianPendulum {
    m: 1.3,
    l: 0.8,
    g: 9.81,
};
const ANGLE: AnglePendulum = AnglePendulum {
    m: 1.3,
    l: 0.8,
    g: 9.81,
};
/// Starting angle and rate: a swing of about 70° (cos θ_max = cos θ₀ − ω₀² l / 2g), far from the
/// small-angle regime.
const THETA0: f64 = 1.2;
const OMEGA0: f64 = 0.5;
const T_END: f64 = 5.0;

fn cartesian_start() -> cartesian_pendulum::State {
    let (l, (s, c)) = (ROD.l, THETA0.sin_cos());
    cartesian_pendulum::State::new(
        0.0,
        cartesian_pendulum::Coords {
            x: l * s,
            y: -l * c,
        },
        cartesian_pendulum::Coords {
            x: l * OMEGA0 * c,
            y: l * OMEGA0 * s,
        },
    )
}

/// The bob's position at `T_END` from the angle form, integrated at tolerance 1e-13: its error is
/// far below the errors compared with it (tolerances ≥ 1e-10).
fn reference_position() -> [f64; 2] {
    let mut a = angle_pendulum::State::new(
        0.0,
        angle_pendulum::Coords { theta: THETA0 },
        angle_pendulum::Coords { theta: OMEGA0 },
    );
    ANGLE
        .integrate(Dop853::new(1e-13, 1e-13), &mut a, T_END, &mut [], |_| {})
        .expect("angle form");
    let (s, c) = a.q.theta.sin_cos();
    [ROD.l * s, -ROD.l * c]
}

/// A run of `$method` on the validated Cartesian pendulum to `T_END`: the end position, the
/// largest constraint residual ||r| − l| after any accepted step, and the statistics.
macro_rules! projected_run {
    ($method:expr) => {{
        let sys = ROD.validated().unwrap();
        let mut s = cartesian_start();
        let mut worst = 0.0f64;
        let out = sys
            .integrate($method, &mut s, T_END, &mut [], |o| {
                if let Observation::Step { state, .. } = o {
                    let [x, y] = state.q.to_array();
                    worst = worst.max(((x * x + y * y).sqrt() - ROD.l).abs());
                }
            })
            .expect("run");
        (s.q.to_array(), worst, out.stats)
    }};
}

#[test]
fn a_projected_step_costs_the_evaluations_of_an_unprojected_one() {
    // Dop853 without its dense output: 11 evaluations per attempted step and the FSAL one at the
    // end of an accepted step; Dopri5: 6 per attempted step, the FSAL one among them (its error
    // estimate uses it). The start costs 2 (q̈ at the start, and one for the first step's size,
    // HNW I §II.4). The projection adds none.
    let dop853 = Dop853 {
        dense: false,
        ..Dop853::new(1e-9, 1e-9)
    };
    let (_, _, stats) = projected_run!(dop853);
    assert_eq!(
        stats.evaluations,
        12 * stats.accepted + 11 * stats.rejected + 2,
        "{stats:?}"
    );
    let (_, _, stats) = projected_run!(Dopri5::new(1e-9, 1e-9));
    assert_eq!(
        stats.evaluations,
        6 * (stats.accepted + stats.rejected) + 2,
        "{stats:?}"
    );
}

#[test]
fn projected_runs_converge_to_the_angle_form() {
    let reference = reference_position();
    for tol in [1e-6, 1e-8, 1e-10] {
        for (name, (q, worst, _)) in [
            ("Dop853", projected_run!(Dop853::new(tol, tol))),
            ("Dopri5", projected_run!(Dopri5::new(tol, tol))),
        ] {
            // Every accepted step lands on the circle to round-off (a few ulps of l).
            assert!(
                worst < 1e-15,
                "{name} at tol {tol}: |r| − l up to {worst:e}"
            );
            // A tolerance-controlled run's global error is its tolerance times the growth of
            // local errors over the run, a constant of the problem and the interval (HNW I
            // §II.4, tolerance proportionality); over these 5 s (two and a half periods) it is of
            // order 1 for Dop853 and 10 for Dopri5, so 30 bounds it with room at every tolerance,
            // and an order lost to the kept evaluation would show as a ratio that grows as the
            // tolerance falls.
            let err = (q[0] - reference[0]).abs().max((q[1] - reference[1]).abs());
            assert!(err < 30.0 * tol, "{name} at tol {tol}: error {err:e}");
        }
    }
}
