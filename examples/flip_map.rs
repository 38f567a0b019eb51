//! The double pendulum's flip-time map: released at rest from every (θ₁, θ₂) of a grid, how long
//! until either arm first flips over (|θ| passes π)? Neighbouring releases that never flip form
//! smooth regions; where the motion is chaotic, flip times change from one pixel to the next and
//! the picture looks fractal.
//!
//! Each trajectory is RK4 at h = 1e-3 with the flip detected between steps (so a flip time is
//! known to one step), stopped at the cap `--t-max`. The map is drawn into `plots/flip_map.svg` (or
//! `$LAGRANGE_PLOTS`). One sweep, four ways to run it:
//!
//! ```text
//! # on this machine: once on one thread and once on two, checked equal bit for bit
//! cargo run --release --example flip_map -- --n 400 --t-max 30
//! # a job array: each process one shard, its Parquet part in --out (computed only if missing),
//! # then the parts merged (and any still missing computed) and drawn
//! cargo run --release --example flip_map -- --out parts --shard 0/2 &
//! cargo run --release --example flip_map -- --out parts --shard 1/2
//! cargo run --release --example flip_map -- --out parts --parts 2
//! # over MPI ranks, gathered on rank 0 (or, with --out, one part per rank)
//! cargo build --release --example flip_map --features mpi
//! mpirun -np 2 target/release/examples/flip_map --mpi --threads 1
//! # (Open MPI binds each rank to one core: threads beyond one per rank need `--bind-to none`)
//! ```
//!
//! Inside a Slurm job array `--shard` defaults to the task's (`SLURM_ARRAY_TASK_ID`). A release
//! whose energy is below the lowest configuration with an arm upright can never flip
//! ([`can_flip`]); those cells are still integrated, so that the throughput is that of the whole
//! grid and the picture shows what was simulated, not what was argued.

use clap::Parser;
use lagrange::ensemble::{rayon, Shard, ShardRun};
use lagrange_gallery::flip_map::{self, can_flip, draw, flip_cell, grid, pendulum, timed_map};
use std::path::PathBuf;
use std::time::Instant;

/// The double pendulum's flip-time map, on threads, as a job array, or over MPI ranks.
#[derive(Parser, Debug)]
struct Args {
    /// Releases per axis: the map is N × N.
    #[arg(long, default_value_t = flip_map::N, value_parser = clap::value_parser!(usize))]
    n: usize,
    /// The cap on simulated time, in seconds.
    #[arg(long, default_value_t = flip_map::T_MAX)]
    t_max: f64,
    /// Run only shard I of K (I/K, from 0) and write its part into --out: a job-array worker.
    #[arg(long, requires = "out")]
    shard: Option<Shard>,
    /// The directory of the Parquet parts. Without --shard: compute the parts still missing,
    /// merge them and draw the map.
    #[arg(long)]
    out: Option<PathBuf>,
    /// The number of parts when merging (without --shard).
    #[arg(long, default_value_t = 1)]
    parts: usize,
    /// Threads per process (default: every core).
    #[arg(long)]
    threads: Option<usize>,
    /// Run over the ranks of MPI's world communicator (start with mpirun; `--features mpi`).
    #[arg(long)]
    mpi: bool,
}

type Failure = Box<dyn std::error::Error + Send + Sync>;

fn main() {
    let args = Args::parse();
    if !(args.t_max > 0.0 && args.t_max.is_finite()) || args.n == 0 {
        eprintln!("error: --n must be at least 1 and --t-max positive and finite");
        std::process::exit(2);
    }
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(args.threads.unwrap_or(0))
        .build()
        .expect("thread pool");
    let outcome = pool.install(|| {
        if args.mpi {
            mpi_run(&args)
        } else if let Some(out) = &args.out {
            parts_run(&args, out)
        } else {
            threads_run(&args)
        }
    });
    if let Err(e) = outcome {
        eprintln!("error: {e}");
        std::process::exit(1);
    }
}

/// The whole map on 1 and on 2 threads: trajectories per second and the speed-up.
fn threads_run(args: &Args) -> Result<(), Failure> {
    let (n, t_max) = (args.n, args.t_max);
    let sys = pendulum();
    let cells = (n * n) as f64;
    println!(
        "flip map: {n}×{n} releases, RK4 h = {}, cap {t_max} s",
        flip_map::H
    );
    let (one, t1) = timed_map(&sys, n, t_max, 1);
    println!("1 thread:  {t1:7.2} s, {:9.0} trajectories/s", cells / t1);
    let (two, t2) = timed_map(&sys, n, t_max, 2);
    println!("2 threads: {t2:7.2} s, {:9.0} trajectories/s", cells / t2);
    println!("speed-up 1 → 2 threads: {:.2}", t1 / t2);
    let bits = |m: &[Option<f64>]| m.iter().map(|t| t.map(f64::to_bits)).collect::<Vec<_>>();
    if bits(&one) != bits(&two) {
        return Err("the maps on 1 and 2 threads differ".into());
    }
    println!("maps on 1 and 2 threads identical bit for bit");
    finish(n, t_max, &two)
}

/// A job-array worker (`--shard`) or the merge of the parts in `out`.
fn parts_run(args: &Args, out: &std::path::Path) -> Result<(), Failure> {
    let (n, t_max) = (args.n, args.t_max);
    let sys = pendulum();
    let grid = grid(n);
    let run = |&release: &(f64, f64)| flip_cell(&sys, release, t_max);
    let shard = match args.shard {
        Some(shard) => Some(shard),
        None => Shard::from_slurm_array().transpose()?,
    };
    if let Some(shard) = shard {
        let parts = flip_map::parts(out, n, t_max, shard.count())?;
        let start = Instant::now();
        match parts.run_shard(&grid, shard, true, run)? {
            ShardRun::Computed(rows) => {
                let secs = start.elapsed().as_secs_f64();
                let rate = rows as f64 / secs;
                println!("shard {shard}: {rows} trajectories in {secs:.2} s ({rate:.0}/s)");
            }
            ShardRun::Present => println!("shard {shard}: its part is already there"),
        }
        println!("{}", parts.path(shard.index()).display());
        return Ok(());
    }
    let parts = flip_map::parts(out, n, t_max, args.parts)?;
    let computed = parts.run_missing(&grid, true, run)?;
    println!(
        "{computed} of {} parts computed, the rest already there",
        parts.count()
    );
    let map: Vec<Option<f64>> = parts.merge(&grid)?;
    finish(n, t_max, &map)
}

/// The map over MPI ranks: gathered on rank 0, or (with `--out`) one part per rank merged by
/// rank 0.
#[cfg(feature = "mpi")]
fn mpi_run(args: &Args) -> Result<(), Failure> {
    use lagrange::ensemble::mpi::{self, bindings::traits::*};
    let universe = mpi::bindings::initialize().ok_or("MPI was already initialised")?;
    let world = universe.world();
    let (n, t_max) = (args.n, args.t_max);
    let sys = pendulum();
    let grid = grid(n);
    let run = |&release: &(f64, f64)| flip_cell(&sys, release, t_max);
    let start = Instant::now();
    let map = match &args.out {
        None => mpi::sweep_gathered(&world, &grid, true, run)?,
        Some(out) => {
            let parts = flip_map::parts(out, n, t_max, world.size() as usize)?;
            parts.run_shard(&grid, mpi::rank_shard(&world), true, run)?;
            world.barrier();
            (world.rank() == 0)
                .then(|| parts.merge(&grid))
                .transpose()?
        }
    };
    let Some(map) = map else { return Ok(()) };
    let secs = start.elapsed().as_secs_f64();
    let threads = rayon::current_num_threads();
    println!(
        "{} ranks × {threads} threads: {secs:.2} s, {:.0} trajectories/s",
        world.size(),
        (n * n) as f64 / secs
    );
    finish(n, t_max, &map)
}

#[cfg(not(feature = "mpi"))]
fn mpi_run(_: &Args) -> Result<(), Failure> {
    Err("--mpi needs the example built with `--features mpi`".into())
}

/// Prints how many releases flipped and draws the map.
fn finish(n: usize, t_max: f64, map: &[Option<f64>]) -> Result<(), Failure> {
    let sys = pendulum();
    let flipped = map.iter().flatten().count();
    let possible = grid(n)
        .iter()
        .filter(|&&(a, b)| can_flip(&sys, a, b))
        .count();
    println!(
        "{flipped} of {} releases flip within {t_max} s; {possible} have the energy to",
        n * n
    );
    let path = lagrange_gallery::plots_dir().join("flip_map.svg");
    draw(&path, n, t_max, map).map_err(|e| format!("could not draw {}: {e}", path.display()))?;
    println!("wrote {}", path.display());
    Ok(())
}
