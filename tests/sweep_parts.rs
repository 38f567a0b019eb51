//! The flip-time map stored as Parquet parts (`lagrange::ensemble::Parts`, the `parquet`
//! feature): run as a job array of separate processes, resumed after a part is lost, and refused
//! when a part is truncated or belongs to another sweep — always merging to the single-process
//! map bit for bit.

use lagrange::ensemble::{shard_range, PartError, Shard, ShardRun};
use lagrange_gallery::flip_map::{flip_cell, flip_times, grid, parts, pendulum};
use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::atomic::{AtomicUsize, Ordering};

/// The test map: 8 × 8 releases, capped at 1 s (some flip, some do not: `tests/ensemble.rs`).
const N: usize = 8;
const T_MAX: f64 = 1.0;

fn single_process_map() -> Vec<Option<f64>> {
    flip_times(&pendulum(), &grid(N), 0..N * N, T_MAX, false).expect("flip map")
}

fn bits(map: &[Option<f64>]) -> Vec<Option<u64>> {
    map.iter().map(|t| t.map(f64::to_bits)).collect()
}

/// A fresh directory for one test's parts.
fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("lagrange-parts-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

fn merged(dir: &Path, count: usize) -> Result<Vec<Option<f64>>, PartError> {
    parts(dir, N, T_MAX, count)?.merge(&grid(N))
}

/// The worker of a job array, started as its own process by the test below with the shard and
/// the directory in the environment; ignored when the tests run normally.
#[test]
#[ignore = "a job-array worker, started by job_array_of_two_processes_merges_to_the_map"]
fn job_array_worker() {
    let shard: Shard = std::env::var("FLIP_SHARD").unwrap().parse().unwrap();
    let dir = PathBuf::from(std::env::var("FLIP_DIR").unwrap());
    let sys = pendulum();
    let parts = parts(&dir, N, T_MAX, shard.count()).unwrap();
    let run = parts.run_shard(&grid(N), shard, false, |&r| flip_cell(&sys, r, T_MAX));
    assert_eq!(run.unwrap(), ShardRun::Computed(shard.range(N * N).len()));
}

#[test]
fn job_array_of_two_processes_merges_to_the_map() {
    let dir = scratch("array");
    let workers: Vec<_> = ["0/2", "1/2"]
        .iter()
        .map(|shard| {
            Command::new(std::env::current_exe().unwrap())
                .args(["job_array_worker", "--exact", "--ignored", "--quiet"])
                .env("FLIP_SHARD", shard)
                .env("FLIP_DIR", &dir)
                .spawn()
                .expect("start a worker process")
        })
        .collect();
    for mut w in workers {
        assert!(w.wait().unwrap().success(), "a worker failed");
    }
    let map = merged(&dir, 2).unwrap();
    assert_eq!(bits(&map), bits(&single_process_map()));
    // The parts are Parquet files: "PAR1" at both ends.
    for i in 0..2 {
        let bytes = std::fs::read(parts(&dir, N, T_MAX, 2).unwrap().path(i)).unwrap();
        assert!(bytes.starts_with(b"PAR1") && bytes.ends_with(b"PAR1"));
    }
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn a_lost_part_is_recomputed_alone() {
    let dir = scratch("resume");
    let sys = pendulum();
    let inputs = grid(N);
    let calls = AtomicUsize::new(0);
    let run = |&r: &(f64, f64)| {
        calls.fetch_add(1, Ordering::Relaxed);
        flip_cell(&sys, r, T_MAX)
    };
    let parts = parts(&dir, N, T_MAX, 3).unwrap();
    assert_eq!(parts.run_missing(&inputs, false, run).unwrap(), 3);
    assert_eq!(calls.swap(0, Ordering::Relaxed), N * N);
    let kept = std::fs::read(parts.path(2)).unwrap();

    std::fs::remove_file(parts.path(1)).unwrap();
    assert!(matches!(
        parts.merge::<_, Option<f64>>(&inputs),
        Err(PartError::Missing { .. })
    ));
    assert_eq!(parts.run_missing(&inputs, false, run).unwrap(), 1);
    assert_eq!(
        calls.swap(0, Ordering::Relaxed),
        shard_range(N * N, 1, 3).len()
    );
    assert_eq!(
        std::fs::read(parts.path(2)).unwrap(),
        kept,
        "a present part was rewritten"
    );

    let map: Vec<Option<f64>> = parts.merge(&inputs).unwrap();
    assert_eq!(bits(&map), bits(&single_process_map()));
    // Nothing left to do.
    assert_eq!(parts.run_missing(&inputs, false, run).unwrap(), 0);
    assert_eq!(calls.load(Ordering::Relaxed), 0);
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn bad_parts_and_shards_are_clear_errors_and_nothing_is_overwritten() {
    let dir = scratch("bad");
    let sys = pendulum();
    let inputs = grid(N);
    let run = |&r: &(f64, f64)| flip_cell(&sys, r, T_MAX);
    let parts = parts(&dir, N, T_MAX, 2).unwrap();

    // A shard index out of range: refused before anything is computed or written.
    assert!(matches!(
        Shard::new(2, 2),
        Err(PartError::ShardOutOfRange { index: 2, count: 2 })
    ));
    assert!("2/2".parse::<Shard>().is_err() && "1/0".parse::<Shard>().is_err());
    assert!(matches!(
        "1-2".parse::<Shard>(),
        Err(PartError::BadShard(_))
    ));
    let other_count = Shard::new(2, 3).unwrap();
    let refused = parts.run_shard(&inputs, other_count, false, run);
    assert!(matches!(refused, Err(PartError::ShardOutOfRange { .. })));
    assert_eq!(
        std::fs::read_dir(&dir).unwrap().count(),
        0,
        "something was written"
    );

    assert_eq!(parts.run_missing(&inputs, false, run).unwrap(), 2);
    let part0 = std::fs::read(parts.path(0)).unwrap();

    // Parts of another sweep (another cap): the metadata differ; merge and run both refuse, and
    // the part is left as it was.
    let other = lagrange_gallery::flip_map::parts(&dir, N, 2.0, 2).unwrap();
    match other.merge::<_, Option<f64>>(&inputs) {
        Err(PartError::Foreign {
            key,
            expected,
            found,
            ..
        }) => {
            assert_eq!(
                (key.as_str(), expected.as_str(), found.as_str()),
                ("t_max", "2", "1")
            );
        }
        e => panic!("expected a metadata mismatch, got {e:?}"),
    }
    let rerun = other.run_shard(&inputs, Shard::new(0, 2).unwrap(), false, run);
    assert!(matches!(rerun, Err(PartError::Foreign { .. })));
    assert_eq!(std::fs::read(parts.path(0)).unwrap(), part0);

    // A truncated part: the merge names it and writes nothing; a rerun recomputes it.
    let path1 = parts.path(1);
    let whole = std::fs::read(&path1).unwrap();
    std::fs::write(&path1, &whole[..whole.len() / 2]).unwrap();
    match parts.merge::<_, Option<f64>>(&inputs) {
        Err(e @ PartError::Unreadable { .. }) => assert!(e.to_string().contains("part-00001")),
        e => panic!("expected an unreadable part, got {e:?}"),
    }
    assert_eq!(std::fs::read(&path1).unwrap().len(), whole.len() / 2);
    assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 2);
    assert_eq!(parts.run_missing(&inputs, false, run).unwrap(), 1);
    assert_eq!(
        std::fs::read(&path1).unwrap(),
        whole,
        "the recomputed part differs"
    );
    let map = merged(&dir, 2).unwrap();
    assert_eq!(bits(&map), bits(&single_process_map()));
    std::fs::remove_dir_all(&dir).ok();
}
