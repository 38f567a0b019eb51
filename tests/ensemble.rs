//! Sweeps on the double pendulum's flip-time map (`lagrange_gallery::flip_map`, the `flip_map` example's): the same map whatever the
//! number of threads, shards that are slices of the whole, and flips where — and only where —
//! physics allows them.

use lagrange::ensemble::{rayon, shard_range};
use lagrange::integrate::{Direction, Event, StopReason};
use lagrange::{Dopri5, Mechanism};
use lagrange_gallery::flip_map::{
    can_flip, flip_time, flip_times, grid, pendulum, Coords, State, H,
};
use std::f64::consts::PI;
use std::sync::OnceLock;

/// The test map: 8 × 8 releases, capped at 1 s.
const N: usize = 8;
const T_MAX: f64 = 1.0;

fn map_on(threads: usize, range: std::ops::Range<usize>) -> Vec<Option<f64>> {
    let sys = pendulum();
    let grid = grid(N);
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("thread pool")
        .install(|| flip_times(&sys, &grid, range, T_MAX, false))
        .expect("flip map")
}

/// The whole test map on two threads, computed once for the tests that compare against it.
fn full_map() -> &'static [Option<f64>] {
    static MAP: OnceLock<Vec<Option<f64>>> = OnceLock::new();
    MAP.get_or_init(|| map_on(2, 0..N * N))
}

fn bits(map: &[Option<f64>]) -> Vec<Option<u64>> {
    map.iter().map(|t| t.map(f64::to_bits)).collect()
}

#[test]
fn the_map_is_the_same_bit_for_bit_on_one_and_two_threads() {
    let one = map_on(1, 0..N * N);
    let two = full_map();
    assert_eq!(one.len(), N * N);
    assert_eq!(bits(&one), bits(two));
    // Not a trivial map: some releases flip within the cap and some do not.
    let flipped = one.iter().flatten().count();
    assert!(
        0 < flipped && flipped < N * N,
        "{flipped} of {} flip",
        N * N
    );
}

#[test]
fn a_shard_equals_its_slice_of_the_map() {
    let full = full_map();
    let shard = map_on(2, 13..41);
    assert_eq!(bits(&shard), bits(&full[13..41]));
    // Three shards run one after the other, concatenated, are the map.
    let merged: Vec<Option<f64>> = (0..3)
        .flat_map(|i| map_on(2, shard_range(N * N, i, 3)))
        .collect();
    assert_eq!(bits(&merged), bits(full));
}

/// Energy argument (see `can_flip`): with unit masses and lengths and the pivot at the origin,
/// V = −m g l (2 cos θ₁ + cos θ₂), and E = V at rest. Since T ≥ 0 and E is conserved, the motion
/// stays where V ≤ E. Arm 1 upright (cos θ₁ = −1) needs V = m g l (2 − cos θ₂) ≥ m g l; arm 2
/// upright (cos θ₂ = −1) needs V = m g l (1 − 2 cos θ₁) ≥ −m g l. So a release with
/// E < −m g l, i.e. 2 cos θ₁ + cos θ₂ > 1, never flips. At θ₁ = θ₂ = 0.5,
/// 2 cos θ₁ + cos θ₂ = 3 cos 0.5 = 2.63: far below the threshold, and RK4's energy error at
/// h = 1e-3 (≈ 1e-8 of |V|) cannot close a gap of 1.63 m g l.
#[test]
fn small_angles_at_rest_never_flip() {
    let sys = pendulum();
    let (theta1, theta2): (f64, f64) = (0.5, 0.5);
    let e = sys
        .energy(&State::at_rest(Coords { theta1, theta2 }))
        .unwrap();
    let mgl = 9.81;
    assert!((e + mgl * (2.0 * theta1.cos() + theta2.cos())).abs() < 1e-12);
    assert!(e < -mgl);
    assert!(!can_flip(&sys, theta1, theta2));
    assert_eq!(flip_time(&sys, (theta1, theta2), H, 10.0).unwrap(), None);
}

/// Every release of the map without the energy to flip does not flip, and the threshold is where
/// the argument above puts it: `can_flip` is 2 cos θ₁ + cos θ₂ ≤ 1 for this pendulum.
#[test]
fn no_release_below_the_flip_energy_flips() {
    let sys = pendulum();
    let map = full_map();
    let mut forbidden = 0;
    for (&(theta1, theta2), t) in grid(N).iter().zip(map) {
        assert_eq!(
            can_flip(&sys, theta1, theta2),
            2.0 * theta1.cos() + theta2.cos() <= 1.0,
            "at ({theta1}, {theta2})"
        );
        if !can_flip(&sys, theta1, theta2) {
            forbidden += 1;
            assert_eq!(
                *t, None,
                "({theta1}, {theta2}) flipped below the flip energy"
            );
        }
    }
    assert!(
        forbidden >= N,
        "only {forbidden} releases below the flip energy"
    );
}

/// A release that flips early, before chaos amplifies the step's error: the flip time detected
/// between RK4 steps (the end of the step where |θ| passes π) against the crossing located on
/// Dopri5's dense output at tight tolerances. RK4's global error at h = 1e-3 over 1 s is ~1e-10 in
/// the angles, so the two crossings agree to well within a step; the RK4 time is at the end of the
/// step containing the crossing, so it lies in [t*, t* + h].
#[test]
fn an_early_flip_is_detected_within_one_step() {
    let sys = pendulum();
    let release = (1.5, -2.5);
    let rk4 = flip_time(&sys, release, H, T_MAX)
        .unwrap()
        .expect("this release flips");

    let mut s = State::at_rest(Coords {
        theta1: release.0,
        theta2: release.1,
    });
    let upright = |s: &State| PI - s.q.theta1.abs().max(s.q.theta2.abs());
    let mut events = [Event::new(&upright)
        .direction(Direction::Falling)
        .terminal()];
    let outcome = sys
        .integrate(
            Dopri5::new(1e-11, 1e-12),
            &mut s,
            T_MAX,
            &mut events,
            |_| {},
        )
        .unwrap();
    assert!(matches!(outcome.reason, StopReason::Event(_)));
    let located = s.t;
    assert!(
        located < rk4 + 1e-9 && rk4 <= located + H + 1e-9,
        "RK4 flip at {rk4}, located at {located}"
    );
}
