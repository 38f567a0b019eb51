//! Coulomb friction in a tangent plane (a `#[friction]` with a `Vec2` slip velocity) against closed
//! forms: the puck on a rough plane and the block pushed sideways on a rough incline.

use lagrange::constraints::{constraint_forces, RowMode};
use lagrange_gallery::scenes::pushed_block::{self, pushed_block::PushedBlock};
use lagrange_gallery::scenes::rough_plane::{self, rough_plane::RoughPlane};

fn pushed_puck() -> RoughPlane {
    RoughPlane {
        m: 1.5,
        g: 9.81,
        mu_k: 0.5,
        mu_s: 0.6,
        push: 3.0,
    }
}

#[test]
fn curved_stop_time_converges_as_the_step_shrinks() {
    // The error in the stop time comes from the one step that reaches the stop, where the force is
    // held along the slip direction at the step's start: it must fall as h does.
    let sys = pushed_puck();
    let (t_s, x_s, y_s) = rough_plane::stop(&sys, 3.0);
    let errors: Vec<(f64, f64)> = [1e-3, 5e-4, 2.5e-4]
        .iter()
        .map(|&h| {
            let (s, stepper, _) = rough_plane::slide(&sys, 3.0, h, (0.8 / h) as usize);
            assert_eq!(stepper.mode_changes().len(), 1, "one stop, no chattering");
            let t = stepper.mode_changes()[0].t;
            ((t - t_s).abs() / t_s, (s.q.x - x_s).hypot(s.q.y - y_s))
        })
        .collect();
    for pair in errors.windows(2) {
        // Each halving at least halves both errors (measured: ×3.2 and ×7 in time).
        assert!(pair[1].0 < 0.5 * pair[0].0, "{errors:?}");
        assert!(pair[1].1 < 0.5 * pair[0].1, "{errors:?}");
    }
    // At h = 1e-3 the stop time is within 2e-6 and the stop point within 2e-7 m (measured 5.5e-7
    // and 2.2e-8 m).
    assert!(errors[0].0 < 2e-6 && errors[0].1 < 2e-7, "{errors:?}");
}

#[test]
fn sliding_friction_is_mu_k_n_against_the_slip_direction() {
    // While sliding, the friction force (f₁, f₂) = −μₖ N ŝ exactly (N = m g): a solve, round-off.
    let sys = pushed_puck();
    let (s, stepper, _) = rough_plane::slide(&sys, 3.0, 1e-3, 300);
    assert_eq!(stepper.contacts().mode().rows[1], RowMode::Sliding);
    let f = constraint_forces(&sys, &s).expect("forces");
    let normal = sys.m * sys.g;
    let speed = s.v.x.hypot(s.v.y);
    assert!((f.multipliers[0] - normal).abs() < 1e-12 * normal);
    assert!((f.multipliers[1] + sys.mu_k * normal * s.v.x / speed).abs() < 1e-12 * normal);
    assert!((f.multipliers[2] + sys.mu_k * normal * s.v.y / speed).abs() < 1e-12 * normal);
}

#[test]
fn stuck_friction_holds_the_push_within_the_cone() {
    // After the stop the push F < μₛ m g is held: the stick multipliers are (0, −F).
    let sys = pushed_puck();
    let (s, stepper, _) = rough_plane::slide(&sys, 3.0, 1e-3, 1000);
    assert_eq!(stepper.contacts().mode().rows[1], RowMode::Stick);
    let f = constraint_forces(&sys, &s).expect("forces");
    assert!(f.multipliers[1].abs() < 1e-12 && (f.multipliers[2] + sys.push).abs() < 1e-12);
}

#[test]
fn pushed_block_sticks_just_below_and_slides_just_above_the_cone() {
    // The resultant of the push and the downslope weight against μₛ N: at 0.999 and 1.001 of the
    // threshold push the outcomes differ, as the closed form says.
    let base = PushedBlock {
        m: 2.0,
        g: 9.81,
        alpha: 0.3,
        mu_k: 0.4,
        mu_s: 0.5,
        push: 0.0,
    };
    let normal = base.m * base.g * base.alpha.cos();
    let downslope = base.m * base.g * base.alpha.sin();
    let threshold = ((base.mu_s * normal).powi(2) - downslope.powi(2)).sqrt();
    for factor in [0.999, 1.001] {
        let sys = PushedBlock {
            push: factor * threshold,
            ..base
        };
        let (trace, stepper) = pushed_block::push(&sys, 1e-3, 500);
        let &(t, level, up) = trace.last().unwrap();
        match pushed_block::slides(&sys) {
            None => {
                assert!(factor < 1.0);
                assert_eq!(stepper.contacts().mode().rows[1], RowMode::Stick);
                assert!(level.hypot(up) < 1e-14);
            }
            Some((a, (e1, e2))) => {
                assert!(factor > 1.0);
                // Constant acceleration along a fixed direction: exact for RK4, round-off only.
                let d = 0.5 * a * t * t;
                assert!((level - d * e1).abs() < 1e-12 * d && (up - d * e2).abs() < 1e-12 * d);
            }
        }
    }
}

#[test]
fn a_cone_row_without_its_partner_is_refused() {
    // The runtime's declaration check: FrictionCone rows come in pairs pointing at each other.
    use lagrange::constraints::{check_declaration, ConstraintKind, Constraints};
    use rough_plane::rough_plane::RoughPlane as R;
    assert!(check_declaration::<R, 3, 3, 3>().is_ok());
    assert_eq!(
        <R as Constraints<3, 3, 3>>::KINDS[1],
        ConstraintKind::FrictionCone {
            normal: 0,
            partner: 2
        }
    );
    assert_eq!(
        <R as Constraints<3, 3, 3>>::NAMES,
        ["plane", "rub.x", "rub.y"]
    );
}
