//! Every gallery scene against its closed form: the same `run` functions the gallery prints
//! (`lagrange_gallery::scenes`), each check carrying the tolerance its scene argues from the
//! method's error.

use lagrange_gallery::scenes::*;
use lagrange_gallery::{table, Check};
use std::path::PathBuf;

fn assert_scene(run: fn(&std::path::Path) -> Vec<Check>) {
    let dir: PathBuf = std::env::temp_dir().join("lagrange-test-plots");
    std::fs::create_dir_all(&dir).unwrap();
    let checks = run(&dir);
    assert!(!checks.is_empty(), "a scene must check something");
    assert!(checks.iter().all(Check::passed), "\n{}", table(&checks));
}

#[test]
fn wedge_and_block() {
    assert_scene(wedge_block::run);
}

#[test]
fn block_on_a_ramp() {
    assert_scene(ramp::run);
}

#[test]
fn bead_on_a_breathing_ellipse() {
    assert_scene(breathing_ellipse::run);
}

#[test]
fn bead_on_a_spinning_hoop() {
    assert_scene(spinning_hoop::run);
}

#[test]
fn large_amplitude_pendulum() {
    assert_scene(pendulum::run);
}

#[test]
fn double_pendulum_energy() {
    assert_scene(double_pendulum::run);
}

#[test]
fn three_particles_equal_one_rigid_body() {
    assert_scene(rigid_triangle::run);
}

#[test]
fn atwood_machine() {
    assert_scene(atwood::run);
}

#[test]
fn gyroscope_driven_by_a_torque() {
    assert_scene(gyroscope::run);
}

#[test]
fn hoop_bifurcation_statics() {
    assert_scene(hoop_bifurcation::run);
}

#[test]
fn double_pendulum_normal_modes() {
    assert_scene(small_oscillations::run);
}

#[test]
fn particle_leaves_a_sphere() {
    assert_scene(sphere_release::run);
}

#[test]
fn wheel_rolls_without_slipping() {
    assert_scene(rolling_wheel::run);
}

#[test]
fn four_bar_linkage_closed_loop() {
    assert_scene(four_bar::run);
}

#[test]
fn cartesian_pendulum_with_a_rod_constraint() {
    assert_scene(cartesian_pendulum::run);
}

#[test]
fn block_on_a_rough_ramp_sticks_or_slides_back() {
    assert_scene(rough_ramp::run);
}

#[test]
fn wedge_and_block_with_friction() {
    assert_scene(rough_wedge::run);
}

#[test]
fn puck_on_a_rough_plane_stops_where_the_closed_form_says() {
    assert_scene(rough_plane::run);
}

#[test]
fn block_pushed_sideways_on_a_rough_incline() {
    assert_scene(pushed_block::run);
}

#[test]
fn pendulum_length_and_friction_identified_by_gauss_newton() {
    assert_scene(identify_pendulum::run);
}

/// Quadratic convergence on a zero-residual problem: from 33 % off in L and 150 % in c, the
/// first iterations find the basin (the error in c grows before it shrinks), then the error
/// squares at each iteration down to rounding; the stopping test (a step below 1e-13 relative)
/// needs one iteration more. Eight are taken; ten bound it.
#[test]
fn gauss_newton_converges_in_a_handful_of_iterations() {
    use identify_pendulum::damped_pendulum::{Coords, DampedPendulum, State};
    let truth = DampedPendulum {
        m: 0.5,
        l: 0.75,
        g: 9.81,
        c: 0.04,
    };
    let s0 = State::at_rest(Coords { theta: 1.0 });
    let (measured, _) = identify_pendulum::trajectory(&truth, &s0).unwrap();
    let guess = DampedPendulum {
        l: 1.0,
        c: 0.1,
        ..truth
    };
    let fit = identify_pendulum::identify(guess, &s0, &measured).unwrap();
    eprintln!("{:?}", fit.history);
    assert!(fit.iterations() <= 10, "{} iterations", fit.iterations());
    let [l, c] = fit.parameters();
    assert!((l - truth.l).abs() < 1e-9 * truth.l);
    assert!((c - truth.c).abs() < 1e-9 * truth.c);
}

#[test]
fn spatial_arm_as_a_kinematic_tree() {
    assert_scene(spatial_arm::run);
}
