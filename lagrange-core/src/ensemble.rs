//! Ensembles: one computation over many inputs — parameters, initial states, grid points — on every
//! core, with results in input order.
//!
//! [`sweep`] runs a closure on every input of a slice in parallel (on [rayon]'s thread pool) and
//! returns the results in the order of the inputs; [`Sweep`] is the same with options: a progress
//! bar for long sweeps ([`Sweep::progress`]) and an index range, to run one shard of a larger sweep
//! ([`Sweep::shard`]). [`grid2`] and [`linspace`] build the inputs of a two-parameter grid. What is
//! collected is whatever the closure returns: a final state, an event time, a whole trace, or a
//! `Result` of any of them (`results.into_iter().collect::<Result<Vec<_>>>()` turns a `Vec` of
//! results into the first error or every value).
//!
//! [`sweep`] and [`Sweep`] need the `sweeps` feature (on by default; it brings rayon and
//! indicatif); [`grid2`], [`linspace`] and [`shard_range`] are always there.
//!
//! A pendulum released from a list of angles, each simulated for one second:
//!
//! ```
//! use lagrange_core::{ensemble, impl_mechanism, vec2, Mechanism, Model, Rk4, Scalar, State};
//!
//! /// A pendulum of unit mass and length, written by hand (`#[mechanism]` writes the same).
//! #[derive(Clone, Copy)]
//! struct Pendulum { g: f64 }
//!
//! impl Model<1, 2> for Pendulum {
//!     type Coords = [f64; 1];
//!     const RHEONOMIC: bool = false;
//!     const HAS_POTENTIAL: bool = true;
//!     const HAS_FORCES: bool = false;
//!     fn validate(&self) -> lagrange_core::Result<()> { Ok(()) }
//!     fn masses(&self) -> [f64; 2] { [1.0, 1.0] }
//!     fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 1]) -> [D; 2] {
//!         vec2(q[0].sin(), -q[0].cos()).to_array()
//!     }
//!     fn potential<D: Scalar>(&self, _t: D, _q: &[D; 1], x: &[D; 2]) -> D { x[1] * self.g }
//! }
//! impl_mechanism!(Pendulum, 1, 2);
//!
//! # #[cfg(feature = "sweeps")]
//! # fn main() -> lagrange_core::Result<()> {
//! let sys = Pendulum { g: 9.81 }.validated()?;
//! let angles = ensemble::linspace(0.1, 3.0, 30);
//! let finals = ensemble::sweep(&angles, |&theta0| {
//!     let mut s = State::at_rest([theta0]);
//!     sys.simulate::<Rk4>(&mut s, 1e-3, 1000, |_| {})?;
//!     Ok(s.q[0])
//! });
//! let finals = finals.into_iter().collect::<lagrange_core::Result<Vec<f64>>>()?;
//! assert_eq!(finals.len(), 30);
//! // A swing never climbs above its release angle (energy is conserved).
//! assert!(finals.iter().zip(&angles).all(|(q, q0)| q.abs() <= q0 + 1e-9));
//! # Ok(())
//! # }
//! # #[cfg(not(feature = "sweeps"))]
//! # fn main() {}
//! ```
//!
//! # Determinism
//!
//! Result `k` is `run(&inputs[k])`, placed at index `k` whatever thread computed it and in
//! whatever order; each call runs from start to end on one thread, so no floating-point sum is
//! reordered by the scheduling. The output is therefore the same, bit for bit, with 1 thread or
//! 64, as long as `run` is a function of its input alone: no shared accumulator, no random numbers
//! drawn from a generator shared between calls or seeded per thread. For a Monte Carlo ensemble,
//! seed each run from its index with [`Sweep::run_indexed`].
//!
//! # Threads
//!
//! Sweeps run on the rayon pool they are called from: the global one (as many threads as cores, or
//! `RAYON_NUM_THREADS`), or one installed for the call,
//!
//! ```
//! # #[cfg(feature = "sweeps")]
//! # fn main() -> Result<(), lagrange_core::ensemble::rayon::ThreadPoolBuildError> {
//! use lagrange_core::ensemble::{self, rayon};
//!
//! let inputs: Vec<u64> = (0..100).collect();
//! let pool = rayon::ThreadPoolBuilder::new().num_threads(2).build()?;
//! let squares = pool.install(|| ensemble::sweep(&inputs, |&n| n * n));
//! assert_eq!(squares[7], 49);
//! # Ok(())
//! # }
//! # #[cfg(not(feature = "sweeps"))]
//! # fn main() {}
//! ```
//!
//! # Sharding: a sweep on many machines
//!
//! A sweep of `n` inputs splits into independent shards, contiguous index ranges
//! [a₀, a₁), [a₁, a₂), …, [aₖ₋₁, n) ([`shard_range`] computes k near-equal ones). Shard `i` is run on
//! its own — another process, another machine — as
//! `Sweep::new(&inputs).shard(ensemble::shard_range(n, i, k)).run(f)`, and the shards' results,
//! concatenated in shard order, are the full sweep's results, bit for bit (see Determinism). So:
//!
//! 1. every worker builds the same inputs (the same [`grid2`] or [`linspace`] call, or reads the
//!    same file) and knows its shard number `i` and the count `k` (command-line arguments, or the
//!    array index of a batch scheduler's job array);
//! 2. it runs its shard and writes the results in order to a file named by `i` (CSV, JSON, raw
//!    little-endian `f64` — anything that round-trips);
//! 3. once all are done, the files are concatenated in the order `0, 1, …, k − 1`.
//!
//! Nothing here launches workers or moves results between machines: that is the job scheduler's
//! and the file system's, which already do it well.

mod cells;
#[cfg(feature = "mpi")]
pub mod mpi;
#[cfg(feature = "parquet")]
mod part_error;
#[cfg(feature = "parquet")]
mod part_file;
#[cfg(feature = "parquet")]
pub mod parts;

pub use cells::Cells;
#[cfg(feature = "parquet")]
pub use parts::{PartError, Parts, Shard, ShardRun};

#[cfg(feature = "sweeps")]
use indicatif::{ProgressBar, ProgressStyle};
#[cfg(feature = "sweeps")]
use rayon::prelude::*;
use std::ops::Range;

/// The rayon crate the sweeps run on, to build a thread pool of a chosen size
/// (`rayon::ThreadPoolBuilder`) without depending on it separately.
#[cfg(feature = "sweeps")]
pub use rayon;

/// Runs `run` on every input, in parallel, and returns the results in the order of the inputs:
/// `sweep(inputs, run)[k] == run(&inputs[k])`. The same as [`Sweep::new`]`(inputs).run(run)`.
///
/// A panic in `run` stops the sweep and is propagated to the caller.
///
/// ```
/// use lagrange_core::ensemble;
///
/// // Periods of small oscillation 2π√(L/g) over a list of lengths.
/// let lengths = [0.25, 0.5, 1.0, 2.0];
/// let periods = ensemble::sweep(&lengths, |&l| 2.0 * std::f64::consts::PI * (l / 9.81f64).sqrt());
/// assert_eq!(periods.len(), 4);
/// assert!((periods[2] - 2.006_066_680_710_6).abs() < 1e-12);
/// assert!(periods.windows(2).all(|w| w[0] < w[1]));
/// ```
#[cfg(feature = "sweeps")]
pub fn sweep<I, R, F>(inputs: &[I], run: F) -> Vec<R>
where
    I: Sync,
    R: Send,
    F: Fn(&I) -> R + Sync,
{
    Sweep::new(inputs).run(run)
}

/// A sweep with options: the inputs, the index range to run (all of them unless
/// [`shard`](Sweep::shard) says otherwise) and whether to show a progress bar.
///
/// ```
/// use lagrange_core::ensemble::{self, Sweep};
///
/// let inputs = ensemble::linspace(0.0, 1.0, 11);
/// let all = Sweep::new(&inputs).progress(true).run(|x| x * x);
/// let part = Sweep::new(&inputs).shard(3..7).run(|x| x * x);
/// assert_eq!(part, all[3..7]);
/// ```
#[cfg(feature = "sweeps")]
#[derive(Clone, Debug)]
pub struct Sweep<'a, I> {
    inputs: &'a [I],
    range: Range<usize>,
    progress: bool,
}

#[cfg(feature = "sweeps")]
impl<'a, I: Sync> Sweep<'a, I> {
    /// A sweep over every input, without a progress bar.
    ///
    /// ```
    /// use lagrange_core::ensemble::Sweep;
    ///
    /// let sweep = Sweep::new(&[1, 2, 3]);
    /// assert_eq!(sweep.range(), 0..3);
    /// ```
    pub fn new(inputs: &'a [I]) -> Self {
        Sweep {
            inputs,
            range: 0..inputs.len(),
            progress: false,
        }
    }

    /// Runs only the inputs with index in `range` = [a, b): one shard of the sweep, whose results
    /// are those of the whole sweep at indices a..b (see [the module](self) for running a sweep as
    /// shards). The range is clipped to the inputs: an end past the last input stops there, a
    /// start at or past the end (or past the range's end) leaves nothing to run.
    ///
    /// ```
    /// use lagrange_core::ensemble::Sweep;
    ///
    /// let inputs: Vec<i32> = (0..10).collect();
    /// assert_eq!(Sweep::new(&inputs).shard(8..20).range(), 8..10);
    /// assert!(Sweep::new(&inputs).shard(12..20).run(|x| x + 1).is_empty());
    /// assert_eq!(Sweep::new(&inputs).shard(2..5).run(|x| x + 1), [3, 4, 5]);
    /// ```
    pub fn shard(mut self, range: Range<usize>) -> Self {
        let end = range.end.min(self.inputs.len());
        let start = range.start.min(end);
        self.range = start..end;
        self
    }

    /// Shows a progress bar on standard error while the sweep runs (inputs done, rate, time left),
    /// cleared when it ends. It is drawn only when standard error is a terminal; off by default.
    ///
    /// ```
    /// use lagrange_core::ensemble::Sweep;
    ///
    /// let inputs: Vec<u64> = (0..1000).collect();
    /// let sums = Sweep::new(&inputs).progress(true).run(|&n| (0..n).sum::<u64>());
    /// assert_eq!(sums[999], 999 * 998 / 2);
    /// ```
    pub fn progress(mut self, show: bool) -> Self {
        self.progress = show;
        self
    }

    /// The index range this sweep runs, after clipping to the inputs.
    ///
    /// ```
    /// use lagrange_core::ensemble::Sweep;
    ///
    /// assert_eq!(Sweep::new(&[0.5; 4]).shard(1..3).range(), 1..3);
    /// ```
    pub fn range(&self) -> Range<usize> {
        self.range.clone()
    }

    /// Runs `run` on every input of the range, in parallel, and returns the results in input
    /// order: result `j` is `run(&inputs[a + j])` for the range [a, b).
    ///
    /// ```
    /// use lagrange_core::ensemble::Sweep;
    ///
    /// let words = ["pendulum", "wedge", "hoop"];
    /// assert_eq!(Sweep::new(&words).run(|w| w.len()), [8, 5, 4]);
    /// ```
    pub fn run<R, F>(self, run: F) -> Vec<R>
    where
        R: Send,
        F: Fn(&I) -> R + Sync,
    {
        self.run_indexed(|_, input| run(input))
    }

    /// Like [`run`](Sweep::run), with the index of each input in the whole input slice (not in the
    /// shard) passed first: result `j` is `run(a + j, &inputs[a + j])`. A seed derived from that
    /// index gives a random ensemble that is the same whatever the threads and however it is
    /// sharded.
    ///
    /// ```
    /// use lagrange_core::ensemble::Sweep;
    ///
    /// let inputs = [10, 20, 30, 40];
    /// assert_eq!(Sweep::new(&inputs).shard(2..4).run_indexed(|k, x| k * x), [60, 120]);
    /// ```
    pub fn run_indexed<R, F>(self, run: F) -> Vec<R>
    where
        R: Send,
        F: Fn(usize, &I) -> R + Sync,
    {
        let Range { start, end } = self.range;
        let bar = if self.progress {
            let bar = ProgressBar::new((end - start) as u64);
            if let Ok(style) = ProgressStyle::with_template(
                "{elapsed_precise} [{wide_bar}] {pos}/{len} ({per_sec}, {eta} left)",
            ) {
                bar.set_style(style);
            }
            bar
        } else {
            ProgressBar::hidden()
        };
        let results = self.inputs[start..end]
            .par_iter()
            .enumerate()
            .map(|(j, input)| {
                let result = run(start + j, input);
                bar.inc(1);
                result
            })
            .collect();
        bar.finish_and_clear();
        results
    }
}

/// Every pair of a grid, x varying fastest: element `j * xs.len() + i` is `(xs[i], ys[j])`, so row
/// `j` of an image (constant y) is a contiguous run of `xs.len()` pairs.
///
/// ```
/// use lagrange_core::ensemble::grid2;
///
/// let grid = grid2(&[0.0, 1.0, 2.0], &[10.0, 20.0]);
/// assert_eq!(grid, [(0.0, 10.0), (1.0, 10.0), (2.0, 10.0), (0.0, 20.0), (1.0, 20.0), (2.0, 20.0)]);
/// assert_eq!(grid[3 + 2], (2.0, 20.0)); // j = 1, i = 2
/// ```
pub fn grid2<X: Clone, Y: Clone>(xs: &[X], ys: &[Y]) -> Vec<(X, Y)> {
    ys.iter()
        .flat_map(|y| xs.iter().map(move |x| (x.clone(), y.clone())))
        .collect()
}

/// `n` evenly spaced values from `start` to `end`, both included: `start + (end − start)·k/(n − 1)`
/// for k = 0, …, n − 1 (exactly `start` and `end` at the ends; `[start]` for n = 1, empty for
/// n = 0).
///
/// ```
/// use lagrange_core::ensemble::linspace;
///
/// assert_eq!(linspace(-1.0, 1.0, 5), [-1.0, -0.5, 0.0, 0.5, 1.0]);
/// assert_eq!(linspace(2.0, 3.0, 1), [2.0]);
/// assert!(linspace(2.0, 3.0, 0).is_empty());
/// ```
pub fn linspace(start: f64, end: f64, n: usize) -> Vec<f64> {
    match n {
        0 => Vec::new(),
        1 => vec![start],
        _ => {
            let last = (n - 1) as f64;
            (0..n)
                .map(|k| match k {
                    0 => start,
                    k if k == n - 1 => end,
                    k => start + (end - start) * (k as f64 / last),
                })
                .collect()
        }
    }
}

/// The index range of shard `shard` when `len` inputs are split into `shards` contiguous shards of
/// near-equal size (sizes differ by at most one): [⌊len·shard/shards⌋, ⌊len·(shard + 1)/shards⌋).
/// The ranges for shard = 0, …, shards − 1 cover 0..len in order without overlap. A shard number
/// at or past `shards` (or `shards` = 0) gives the empty range `len..len`.
///
/// ```
/// use lagrange_core::ensemble::shard_range;
///
/// assert_eq!(shard_range(10, 0, 3), 0..3);
/// assert_eq!(shard_range(10, 1, 3), 3..6);
/// assert_eq!(shard_range(10, 2, 3), 6..10);
///
/// // Three shards, run separately and concatenated, are the whole sweep.
/// let inputs: Vec<f64> = (0..10).map(f64::from).collect();
/// let mut merged = Vec::new();
/// for i in 0..3 {
///     merged.extend(inputs[shard_range(inputs.len(), i, 3)].iter().map(|x| x.sqrt()));
/// }
/// assert_eq!(merged, inputs.iter().map(|x| x.sqrt()).collect::<Vec<_>>());
/// ```
pub fn shard_range(len: usize, shard: usize, shards: usize) -> Range<usize> {
    if shard >= shards {
        return len..len;
    }
    let bound = |i: usize| (len as u128 * i as u128 / shards as u128) as usize;
    bound(shard)..bound(shard + 1)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[cfg(feature = "sweeps")]
    /// A chaotic iteration (the logistic map at r = 3.99): any difference in how a result was
    /// computed would show in the low bits.
    fn logistic(x0: &f64) -> f64 {
        let mut x = *x0;
        for _ in 0..10_000 {
            x = 3.99 * x * (1.0 - x);
        }
        x
    }

    #[cfg(feature = "sweeps")]
    fn inputs() -> Vec<f64> {
        linspace(0.01, 0.99, 1000)
    }

    #[cfg(feature = "sweeps")]
    fn with_threads<R: Send>(n: usize, f: impl FnOnce() -> R + Send) -> R {
        rayon::ThreadPoolBuilder::new()
            .num_threads(n)
            .build()
            .expect("thread pool")
            .install(f)
    }

    #[cfg(feature = "sweeps")]
    #[test]
    fn results_are_in_input_order() {
        let inputs: Vec<usize> = (0..10_000).rev().collect();
        let out = sweep(&inputs, |&k| k * 3);
        assert_eq!(out.len(), inputs.len());
        for (k, (x, y)) in inputs.iter().zip(&out).enumerate() {
            assert_eq!(*y, x * 3, "result {k} out of place");
        }
        let indexed = Sweep::new(&inputs).run_indexed(|k, &x| (k, x));
        assert!(indexed
            .iter()
            .enumerate()
            .all(|(k, &(i, x))| i == k && x == inputs[k]));
    }

    #[cfg(feature = "sweeps")]
    #[test]
    fn one_and_two_threads_agree_bit_for_bit() {
        let inputs = inputs();
        let one = with_threads(1, || sweep(&inputs, logistic));
        let two = with_threads(2, || sweep(&inputs, logistic));
        assert_eq!(
            with_threads(2, rayon::current_num_threads),
            2,
            "the pool has two threads"
        );
        let serial: Vec<f64> = inputs.iter().map(logistic).collect();
        let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<u64>>();
        assert_eq!(bits(&one), bits(&serial));
        assert_eq!(bits(&two), bits(&serial));
    }

    #[cfg(feature = "sweeps")]
    #[test]
    fn a_shard_is_the_slice_of_the_full_run() {
        let inputs = inputs();
        let full = sweep(&inputs, logistic);
        for (a, b) in [(0, 1000), (0, 0), (17, 18), (250, 731), (999, 1000)] {
            let shard = with_threads(2, || Sweep::new(&inputs).shard(a..b).run(logistic));
            assert_eq!(shard, full[a..b], "shard {a}..{b}");
        }
        let merged: Vec<f64> = (0..7)
            .flat_map(|i| {
                Sweep::new(&inputs)
                    .shard(shard_range(inputs.len(), i, 7))
                    .run(logistic)
            })
            .collect();
        assert_eq!(merged, full);
    }

    #[cfg(feature = "sweeps")]
    #[test]
    fn shard_ranges_are_clipped() {
        let inputs = [1, 2, 3];
        assert_eq!(Sweep::new(&inputs).shard(1..10).range(), 1..3);
        assert_eq!(Sweep::new(&inputs).shard(5..10).range(), 3..3);
        #[allow(clippy::reversed_empty_ranges)]
        let reversed = Sweep::new(&inputs).shard(2..1).range();
        assert!(reversed.is_empty());
        assert!(Sweep::new(&inputs).shard(5..10).run(|x| *x).is_empty());
    }

    #[test]
    fn shard_ranges_tile_the_inputs() {
        for len in [0, 1, 7, 100, 101] {
            for shards in 1..12 {
                let ranges: Vec<_> = (0..shards).map(|i| shard_range(len, i, shards)).collect();
                assert_eq!(ranges[0].start, 0);
                assert_eq!(ranges[shards - 1].end, len);
                for w in ranges.windows(2) {
                    assert_eq!(w[0].end, w[1].start);
                }
                let sizes: Vec<usize> = ranges.iter().map(|r| r.len()).collect();
                let (lo, hi) = (sizes.iter().min().unwrap(), sizes.iter().max().unwrap());
                assert!(hi - lo <= 1, "len {len}, {shards} shards: sizes {sizes:?}");
            }
        }
        assert_eq!(shard_range(10, 3, 3), 10..10);
        assert_eq!(shard_range(10, 0, 0), 10..10);
        assert_eq!(shard_range(usize::MAX, 1, 2).end, usize::MAX);
    }

    #[test]
    fn grid_order_is_x_fastest() {
        let xs = [1, 2, 3, 4];
        let ys = ['a', 'b', 'c'];
        let grid = grid2(&xs, &ys);
        assert_eq!(grid.len(), 12);
        for (j, y) in ys.iter().enumerate() {
            for (i, x) in xs.iter().enumerate() {
                assert_eq!(grid[j * xs.len() + i], (*x, *y));
            }
        }
        assert!(grid2::<i32, i32>(&[], &[1, 2]).is_empty());
    }

    #[test]
    fn linspace_hits_both_ends() {
        let v = linspace(-std::f64::consts::PI, std::f64::consts::PI, 101);
        assert_eq!(v.len(), 101);
        assert_eq!(v[0], -std::f64::consts::PI);
        assert_eq!(v[100], std::f64::consts::PI);
        assert_eq!(v[50], 0.0);
        assert!(v.windows(2).all(|w| w[0] < w[1]));
    }
}
