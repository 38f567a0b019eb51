//! The computed-torque scene: its checks, and the hold's error measured to be first order in h.

use lagrange_gallery::scenes::computed_torque::{self, Tracking};
use lagrange_gallery::{table, Check};

#[test]
fn the_scene_checks_pass() {
    let dir = std::env::temp_dir().join("lagrange-test-plots");
    std::fs::create_dir_all(&dir).unwrap();
    let checks = computed_torque::run(&dir);
    assert_eq!(checks.len(), 6);
    assert!(checks.iter().all(Check::passed), "\n{}", table(&checks));
}

/// max_t |e − e_cf| per joint.
fn departure(run: &Tracking) -> [f64; 3] {
    run.error
        .iter()
        .zip(&run.closed_form)
        .fold([0.0; 3], |m, (e, cf)| {
            std::array::from_fn(|j| m[j].max((e[j] - cf[j]).abs()))
        })
}

/// The hold's error is first order in h: its leading term, the response of the error equation to
/// the sawtooth's mean (h/2) M⁻¹u̇, is proportional to h, and the next is O(ωh) = 1 % of it at
/// h = 1 ms (see `computed_torque::hold_rate`). So halving h halves max |e − e_cf| to within a
/// few per cent: [1.9, 2.1] (an O(h²) error would give 4, RK4's own O(h⁴) 16). Over the first
/// second, where both the transient and the tracking are under way, to keep the debug run short.
#[test]
fn halving_the_hold_halves_the_departure_from_the_closed_form() {
    let (h, duration) = (computed_torque::STEP, 1.0);
    let coarse = departure(&computed_torque::track(h, duration).unwrap());
    let fine = departure(&computed_torque::track(h / 2.0, duration).unwrap());
    for j in 0..3 {
        let ratio = coarse[j] / fine[j];
        assert!(
            (1.9..=2.1).contains(&ratio),
            "joint {j}: max |e − e_cf| {:e} at h, {:e} at h/2: ratio {ratio}",
            coarse[j],
            fine[j]
        );
    }
}
