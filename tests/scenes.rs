//! Every gallery scene against its closed form: the same `run` functions the gallery prints, each
//! check carrying the tolerance its scene file argues from the method's error.

#[path = "../examples/atwood.rs"]
#[allow(dead_code)]
mod atwood;
#[path = "../examples/breathing_ellipse.rs"]
#[allow(dead_code)]
mod breathing_ellipse;
#[path = "../examples/cartesian_pendulum.rs"]
#[allow(dead_code)]
mod cartesian_pendulum;
#[path = "../examples/four_bar.rs"]
#[allow(dead_code)]
mod four_bar;
#[path = "../examples/gyroscope.rs"]
#[allow(dead_code)]
mod gyroscope;
#[path = "../examples/hoop_bifurcation.rs"]
#[allow(dead_code)]
mod hoop_bifurcation;
#[path = "../examples/pendulum.rs"]
#[allow(dead_code)]
mod pendulum;
#[path = "../examples/ramp.rs"]
#[allow(dead_code)]
mod ramp;
#[path = "../examples/rigid_triangle.rs"]
#[allow(dead_code)]
mod rigid_triangle;
#[path = "../examples/rolling_wheel.rs"]
#[allow(dead_code)]
mod rolling_wheel;
#[path = "../examples/rough_ramp.rs"]
#[allow(dead_code)]
mod rough_ramp;
#[path = "../examples/rough_wedge.rs"]
#[allow(dead_code)]
mod rough_wedge;
#[path = "../examples/small_oscillations.rs"]
#[allow(dead_code)]
mod small_oscillations;
#[path = "../examples/sphere_release.rs"]
#[allow(dead_code)]
mod sphere_release;
#[path = "../examples/wedge_block.rs"]
#[allow(dead_code)]
mod wedge_block;

// Loaded once, as the mechanisms the statics scenes analyse.
use hoop_bifurcation::scene as spinning_hoop;
use small_oscillations::scene as double_pendulum;

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
    assert_scene(lagrange_gallery::scenes::rough_plane::run);
}

#[test]
fn block_pushed_sideways_on_a_rough_incline() {
    assert_scene(lagrange_gallery::scenes::pushed_block::run);
}
