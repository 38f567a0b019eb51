//! Properties of the generated double pendulum over random states (proptest):
//! - q̈ equals the hand-written closed form to 1e-12 relative;
//! - the mass matrix is symmetric positive definite;
//! - ½ q̇ᵀ M q̇ equals the kinetic energy summed from the body velocities, ½ Σ mᵢ|ṙᵢ|².

use lagrange_gallery::scenes::double_pendulum as scene;

use lagrange::prelude::*;
use proptest::prelude::*;
use scene::double_pendulum::{Coords, DoublePendulum, State};

fn system() -> impl Strategy<Value = DoublePendulum> {
    (
        0.1..10.0f64,
        0.1..10.0f64,
        0.1..5.0f64,
        0.1..5.0f64,
        0.5..20.0f64,
    )
        .prop_map(|(m1, m2, l1, l2, g)| DoublePendulum { m1, m2, l1, l2, g })
}

fn state() -> impl Strategy<Value = State> {
    use std::f64::consts::PI;
    (-PI..PI, -PI..PI, -10.0..10.0f64, -10.0..10.0f64).prop_map(|(a, b, c, d)| {
        State::new(
            0.0,
            Coords {
                theta1: a,
                theta2: b,
            },
            Coords {
                theta1: c,
                theta2: d,
            },
        )
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(512))]

    #[test]
    fn accelerations_match_closed_form(sys in system(), s in state()) {
        let got = sys.accelerations(&s).unwrap();
        let want = scene::closed_form(&sys, [s.q.theta1, s.q.theta2], [s.v.theta1, s.v.theta2]);
        // Each side is O(30) flops on the same inputs, so they agree to a few ε relative to the
        // terms being summed: q̈ is a sum of terms of size g/l and θ̇² that cancel where q̈ ≈ 0, where
        // a bare relative error would be undefined. The error is therefore measured relative to
        // |q̈| + g/l_min + θ̇₁² + θ̇₂² + 1; 1e-12 of that leaves ~100 ε for the mass ratios (up to 100)
        // that scale the cancelling terms.
        let scale = 1.0 + want[0].abs().max(want[1].abs())
            + (sys.g / sys.l1.min(sys.l2)) + s.v.theta1.powi(2) + s.v.theta2.powi(2);
        prop_assert!((got.theta1 - want[0]).abs() <= 1e-12 * scale, "{got:?} vs {want:?}");
        prop_assert!((got.theta2 - want[1]).abs() <= 1e-12 * scale, "{got:?} vs {want:?}");
    }

    #[test]
    fn mass_matrix_is_symmetric_positive_definite(sys in system(), s in state()) {
        let m = sys.mass_matrix(&s).unwrap();
        // Assembled by rank-one updates μ g gᵀ: symmetric by construction up to round-off.
        prop_assert!((m[(0, 1)] - m[(1, 0)]).abs() <= 1e-14 * m.abs().max());
        // 2×2: positive definite iff the leading minors are positive. Analytically
        // det M = m2 l1² l2² (m1 + m2 sin²(θ1 − θ2)) ≥ m1 m2 l1² l2² > 0.
        let det = m[(0, 0)] * m[(1, 1)] - m[(0, 1)] * m[(1, 0)];
        let exact_det = sys.m2 * (sys.l1 * sys.l2).powi(2) * (sys.m1 + sys.m2 * (s.q.theta1 - s.q.theta2).sin().powi(2));
        prop_assert!(m[(0, 0)] > 0.0 && det > 0.0);
        prop_assert!((det - exact_det).abs() <= 1e-12 * exact_det.max(m[(0, 0)] * m[(1, 1)]));
    }

    #[test]
    fn quadratic_form_is_kinetic_energy_of_bodies(sys in system(), s in state()) {
        let m = sys.mass_matrix(&s).unwrap();
        let v = nalgebra::Vector2::new(s.v.theta1, s.v.theta2);
        let from_matrix = 0.5 * v.dot(&(m * v));
        let vel = sys.body_velocities(&s);
        let from_bodies = 0.5 * sys.m1 * vel.bob1.norm_squared() + 0.5 * sys.m2 * vel.bob2.norm_squared();
        // Two routes to the same sum of squares: a few ε relative.
        prop_assert!((from_matrix - from_bodies).abs() <= 1e-13 * from_bodies.max(1e-300) + 1e-300);
        prop_assert!((sys.kinetic_energy(&s).unwrap() - from_bodies).abs() <= 1e-13 * from_bodies.max(1e-300) + 1e-300);
    }
}
