//! Sweeps over the ranks of an MPI communicator: rank r of s runs shard
//! [`shard_range`]`(n, r, s)` on all its cores (rayon), and either the results are gathered on
//! rank 0 in input order ([`sweep_gathered`]) or every rank writes its own part
//! ([`rank_shard`] with [`Parts`](super::Parts), with the `parquet` feature). Either way the result
//! is the single-process sweep's, bit for bit (see [Determinism](super#determinism)): a result is
//! computed by one call on one thread whatever the rank, and it travels as the bits of its `f64`
//! cells.
//!
//! A program started as `mpirun -np 4 ./sweep`:
//!
//! ```no_run
//! use lagrange_core::ensemble::{self, mpi};
//!
//! let universe = mpi::bindings::initialize().expect("MPI initialised once");
//! let world = universe.world();
//! let inputs = ensemble::linspace(0.0, 1.0, 1000);
//! let gathered = mpi::sweep_gathered(&world, &inputs, true, |x: &f64| x.sqrt()).unwrap();
//! if let Some(results) = gathered {
//!     // Rank 0: every result, in input order.
//!     assert_eq!(results.len(), 1000);
//! }
//! ```

use super::cells::{cells_to_rows, rows_to_cells, Cells};
use super::{shard_range, Sweep};
use ::mpi::datatype::PartitionMut;
use ::mpi::traits::{Communicator, Root};
use ::mpi::Count;

/// The `mpi` crate the sweeps run on: `bindings::initialize()` starts MPI and gives the world
/// communicator, without depending on the crate separately.
pub use ::mpi as bindings;

/// A sweep too large to gather: MPI counts message sizes in `i32`.
#[derive(Debug, thiserror::Error)]
#[error(
    "{cells} result cells do not fit one MPI gather (at most {} per sweep)",
    Count::MAX
)]
pub struct TooLarge {
    /// The number of result cells (inputs × cells per result).
    pub cells: usize,
}

/// The shard this rank runs: `rank` of `size` shards, for writing one part per rank with
/// [`Parts::run_shard`](super::Parts::run_shard).
#[cfg(feature = "parquet")]
pub fn rank_shard<C: Communicator>(comm: &C) -> super::Shard {
    let (rank, size) = (comm.rank() as usize, comm.size() as usize);
    super::Shard::new(rank, size).expect("an MPI rank is below the communicator's size")
}

/// Runs the sweep of `run` over `inputs` across the ranks of `comm` (each rank its shard, on all
/// its cores, with a progress bar per process if `progress`) and gathers the results on rank 0:
/// `Ok(Some(results))` there, in input order, `Ok(None)` on the other ranks. Every rank must call
/// it with the same inputs (a collective call).
pub fn sweep_gathered<C, I, R, F>(
    comm: &C,
    inputs: &[I],
    progress: bool,
    run: F,
) -> Result<Option<Vec<R>>, TooLarge>
where
    C: Communicator,
    I: Sync,
    R: Cells + Send,
    F: Fn(&I) -> R + Sync,
{
    let (rank, size) = (comm.rank() as usize, comm.size() as usize);
    let cells_total = inputs.len().saturating_mul(R::WIDTH);
    let count = |cells: usize| Count::try_from(cells).map_err(|_| TooLarge { cells: cells_total });
    count(cells_total)?;
    let mine = Sweep::new(inputs)
        .shard(shard_range(inputs.len(), rank, size))
        .progress(progress)
        .run(run);
    // A cell travels as its bits and a presence flag, so a result arrives bit for bit.
    let cells = rows_to_cells(&mine);
    let bits: Vec<u64> = cells.iter().map(|c| c.map_or(0, f64::to_bits)).collect();
    let present: Vec<u8> = cells.iter().map(|c| u8::from(c.is_some())).collect();
    let root = comm.process_at_rank(0);
    if rank != 0 {
        root.gather_varcount_into(&bits[..]);
        root.gather_varcount_into(&present[..]);
        return Ok(None);
    }
    let counts = (0..size)
        .map(|r| count(shard_range(inputs.len(), r, size).len() * R::WIDTH))
        .collect::<Result<Vec<Count>, _>>()?;
    let displs: Vec<Count> = counts
        .iter()
        .scan(0, |at, &c| {
            let d = *at;
            *at += c;
            Some(d)
        })
        .collect();
    let mut all_bits = vec![0u64; cells_total];
    let mut all_present = vec![0u8; cells_total];
    root.gather_varcount_into_root(
        &bits[..],
        &mut PartitionMut::new(&mut all_bits[..], &counts[..], &displs[..]),
    );
    root.gather_varcount_into_root(
        &present[..],
        &mut PartitionMut::new(&mut all_present[..], &counts[..], &displs[..]),
    );
    let cells: Vec<Option<f64>> = all_bits
        .iter()
        .zip(&all_present)
        .map(|(&b, &p)| (p == 1).then(|| f64::from_bits(b)))
        .collect();
    let results = cells_to_rows(&cells).expect("the cells were written by `Cells::write_cells`");
    Ok(Some(results))
}
