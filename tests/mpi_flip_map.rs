//! The flip-time map over two MPI ranks (`lagrange::ensemble::mpi`, the `mpi` feature), against the
//! single-process map, bit for bit: once gathered on rank 0, once written as one Parquet part per
//! rank and merged.
//!
//! Run by `cargo test --features mpi --test mpi_flip_map`: started without MPI, the test starts
//! itself again as `mpirun -np 2` and passes if both ranks do; under mpirun, rank 0 checks.
//! Running as root (as CI does) needs Open MPI's `--allow-run-as-root` and the two
//! `OMPI_ALLOW_RUN_AS_ROOT*` variables, which are set here.

use lagrange::ensemble::mpi::{self, bindings::traits::*};
use lagrange_gallery::flip_map::{flip_cell, flip_times, grid, parts, pendulum};
use std::process::{Command, ExitCode};

/// The test map: 8 × 8 releases, capped at 1 s (some flip, some do not: `tests/ensemble.rs`).
const N: usize = 8;
const T_MAX: f64 = 1.0;
const RANKS: &str = "2";

fn main() -> ExitCode {
    if std::env::var_os("OMPI_COMM_WORLD_SIZE").is_some() || std::env::var_os("PMI_SIZE").is_some()
    {
        return rank();
    }
    let dir = std::env::temp_dir().join(format!("lagrange-mpi-parts-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let status = Command::new("mpirun")
        .args(["--allow-run-as-root", "--oversubscribe", "-np", RANKS])
        .arg(std::env::current_exe().expect("the test's own path"))
        .env("OMPI_ALLOW_RUN_AS_ROOT", "1")
        .env("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
        .env("FLIP_MPI_DIR", &dir)
        .status();
    std::fs::remove_dir_all(&dir).ok();
    match status {
        Ok(s) if s.success() => {
            println!("test result: ok. 1 passed; 0 failed; 0 ignored; 0 measured; 0 filtered out");
            ExitCode::SUCCESS
        }
        Ok(s) => {
            eprintln!("mpirun -np {RANKS}: {s}");
            println!(
                "test result: FAILED. 0 passed; 1 failed; 0 ignored; 0 measured; 0 filtered out"
            );
            ExitCode::FAILURE
        }
        Err(e) => {
            eprintln!("could not start mpirun (is Open MPI installed?): {e}");
            ExitCode::FAILURE
        }
    }
}

fn bits(map: &[Option<f64>]) -> Vec<Option<u64>> {
    map.iter().map(|t| t.map(f64::to_bits)).collect()
}

/// One rank: the gathered sweep, then one part per rank; rank 0 compares both with the map
/// computed in one process.
fn rank() -> ExitCode {
    let universe = mpi::bindings::initialize().expect("MPI starts");
    let world = universe.world();
    let sys = pendulum();
    let inputs = grid(N);
    let run = |&r: &(f64, f64)| flip_cell(&sys, r, T_MAX);

    let gathered = mpi::sweep_gathered(&world, &inputs, false, run).expect("gathered");
    let dir = std::env::var_os("FLIP_MPI_DIR").expect("the parts' directory");
    let parts = parts(dir.as_ref(), N, T_MAX, world.size() as usize).expect("parts");
    parts
        .run_shard(&inputs, mpi::rank_shard(&world), false, run)
        .expect("this rank's part");
    world.barrier();
    if world.rank() != 0 {
        assert!(
            gathered.is_none(),
            "results gathered on a rank other than 0"
        );
        return ExitCode::SUCCESS;
    }
    assert_eq!(world.size(), 2, "two ranks");
    let single = flip_times(&sys, &inputs, 0..N * N, T_MAX, false).expect("flip map");
    let gathered = gathered.expect("rank 0 gathers the results");
    let merged: Vec<Option<f64>> = parts.merge(&inputs).expect("merged parts");
    let ok = bits(&gathered) == bits(&single) && bits(&merged) == bits(&single);
    let flipped = single.iter().flatten().count();
    println!("rank 0 of 2: gathered and merged maps equal the one-process map: {ok} ({flipped} of {} flip)", N * N);
    if ok && 0 < flipped && flipped < N * N {
        ExitCode::SUCCESS
    } else {
        ExitCode::FAILURE
    }
}
