//! What the peer benchmarks' binaries (`robots`, `floating-check`) share with the C drivers of
//! `scripts/peers`: their timing loop (`timing.h`), their time lines (`robots_common.h`), and the
//! names `#[lagrange::urdf]` gives the joints of a URDF file.

use std::time::Instant;

/// The timing loop of the C drivers (`timing.h`): `batch` runs one call at each state; a warm-up
/// of at least 50 ms sizes a repetition to about 10 ms, then 21 repetitions; min and median of the
/// time per batch, in ns, and the batches per repetition.
pub fn time_batches(mut batch: impl FnMut()) -> (f64, f64, u64) {
    const REPS: usize = 21;
    const REP_NS: f64 = 10e6;
    const WARMUP_NS: f64 = 50e6;
    let run = |batch: &mut dyn FnMut(), iters: u64| {
        let t0 = Instant::now();
        for _ in 0..iters {
            batch();
        }
        t0.elapsed().as_nanos() as f64
    };
    let (mut iters, mut total) = (1u64, 0.0);
    let mut elapsed;
    loop {
        elapsed = run(&mut batch, iters);
        total += elapsed;
        if total >= WARMUP_NS && elapsed >= REP_NS / 4.0 {
            break;
        }
        if elapsed < REP_NS {
            iters *= 2;
        }
    }
    let iters = (iters as f64 * REP_NS / elapsed) as u64 + 1;
    let mut per: Vec<f64> = (0..REPS)
        .map(|_| run(&mut batch, iters) / iters as f64)
        .collect();
    per.sort_by(f64::total_cmp);
    (per[0], per[REPS / 2], iters)
}

/// Times `batch` (one call at each of `states` states) and prints the drivers' time line:
/// `lagrange robot label min_ns median_ns calls_per_rep`, per call.
pub fn print_time(robot: &str, label: &str, states: usize, batch: impl FnMut()) {
    let (min, median, iters) = time_batches(batch);
    let n = states as f64;
    println!(
        "lagrange\t{robot}\t{label}\t{:.1}\t{:.1}\t{}",
        min / n,
        median / n,
        iters * states as u64
    );
}

/// A URDF joint's name as `#[lagrange::urdf]` names its coordinate: lower case, every character
/// that cannot be in an identifier turned into `_` (the names of the peers' files need no other
/// rule).
pub fn as_coordinate(joint: &str) -> String {
    joint
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() {
                c.to_ascii_lowercase()
            } else {
                '_'
            }
        })
        .collect()
}
