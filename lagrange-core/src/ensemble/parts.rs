//! A sweep split into parts on disk, one Parquet file per shard: for job arrays (k independent
//! processes, each running one shard), for MPI ranks that each write their own part, and for runs
//! that resume after an interruption.
//!
//! [`Parts`] names the sweep (a directory, a file stem, the shard count, the column names and the
//! metadata that say what was computed); [`Parts::run_shard`] computes one part unless a valid one
//! is already there; [`Parts::run_missing`] does that for every shard in turn; [`Parts::merge`]
//! reads them all back, checks that they belong to this sweep, and returns the results in input
//! order, bit for bit those of an uninterrupted single-process sweep (see
//! [Determinism](super#determinism)).
//!
//! A part is `STEM-part-I-of-K.parquet`: a column `index` (the input's index in the whole sweep),
//! one column per cell of the input and of the result ([`Cells`]), and the metadata as the file's
//! key–value metadata, with `lagrange.sweep` (the stem), `lagrange.inputs` (the input count),
//! `lagrange.shard` (`I/K`) added. Parts of one sweep share a schema, so any Parquet reader
//! (pandas, polars, DuckDB: `read_parquet('DIR/STEM-part-*.parquet')`) concatenates them.
//!
//! ```
//! use lagrange_core::ensemble::{self, Parts, Shard};
//!
//! # fn main() -> Result<(), lagrange_core::ensemble::PartError> {
//! let dir = std::env::temp_dir().join(format!("lagrange-parts-doc-{}", std::process::id()));
//! let inputs = ensemble::linspace(0.0, 1.0, 10);
//! let parts = Parts::new(&dir, "squares", 3)?
//!     .columns(&["x"], &["x_squared"])
//!     .metadata("what", "x²");
//! // Three workers (here one after the other), each with its shard.
//! for i in 0..3 {
//!     parts.run_shard(&inputs, Shard::new(i, 3)?, false, |x: &f64| x * x)?;
//! }
//! let squares: Vec<f64> = parts.merge(&inputs)?;
//! assert_eq!(squares, inputs.iter().map(|x| x * x).collect::<Vec<_>>());
//! // A rerun finds every part present and computes nothing.
//! assert_eq!(parts.run_missing(&inputs, false, |x: &f64| x * x)?, 0);
//! # std::fs::remove_dir_all(&dir).ok();
//! # Ok(())
//! # }
//! ```

use super::cells::{cells_to_rows, Cells};
pub use super::part_error::PartError;
use super::part_file::{self, PartData};
use super::{shard_range, Sweep};
use std::fmt;
use std::ops::Range;
use std::path::{Path, PathBuf};
use std::str::FromStr;

/// Shard `index` of `count` (numbered from 0): the inputs [`shard_range`]`(len, index, count)`.
/// Parsed from `I/K` (`"3/8".parse()`), the form the command line of a job-array worker takes.
///
/// ```
/// use lagrange_core::ensemble::Shard;
///
/// let s: Shard = "1/4".parse().unwrap();
/// assert_eq!((s.index(), s.count()), (1, 4));
/// assert_eq!(s.range(10), 2..5);
/// assert!("4/4".parse::<Shard>().is_err());
/// assert!("a/4".parse::<Shard>().is_err());
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Shard {
    index: usize,
    count: usize,
}

impl Shard {
    /// Shard `index` of `count`, or [`PartError::ShardOutOfRange`] unless `index < count`.
    pub fn new(index: usize, count: usize) -> Result<Self, PartError> {
        if index < count {
            Ok(Shard { index, count })
        } else {
            Err(PartError::ShardOutOfRange { index, count })
        }
    }

    /// The shard of a Slurm job array's task, from `SLURM_ARRAY_TASK_ID`, `SLURM_ARRAY_TASK_MIN`
    /// and `SLURM_ARRAY_TASK_COUNT` (`sbatch --array=0-7`: tasks 0…7 are shards 0…7 of 8);
    /// `None` outside a job array.
    pub fn from_slurm_array() -> Option<Result<Self, PartError>> {
        let var = |name: &str| std::env::var(name).ok();
        let id = var("SLURM_ARRAY_TASK_ID")?;
        let parse = |s: Option<String>| s.and_then(|s| s.parse::<usize>().ok());
        let (Some(id), Some(min), Some(count)) = (
            parse(Some(id.clone())),
            parse(var("SLURM_ARRAY_TASK_MIN")).or(Some(0)),
            parse(var("SLURM_ARRAY_TASK_COUNT")),
        ) else {
            return Some(Err(PartError::BadShard(format!(
                "SLURM_ARRAY_TASK_ID={id}"
            ))));
        };
        Some(Shard::new(id.wrapping_sub(min), count))
    }

    /// The shard's index, in 0..count.
    pub fn index(&self) -> usize {
        self.index
    }

    /// The number of shards.
    pub fn count(&self) -> usize {
        self.count
    }

    /// The index range of this shard of `len` inputs.
    pub fn range(&self, len: usize) -> Range<usize> {
        shard_range(len, self.index, self.count)
    }
}

impl fmt::Display for Shard {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}/{}", self.index, self.count)
    }
}

impl FromStr for Shard {
    type Err = PartError;

    fn from_str(s: &str) -> Result<Self, PartError> {
        let bad = || PartError::BadShard(s.to_owned());
        let (i, k) = s.split_once('/').ok_or_else(bad)?;
        let (i, k) = (
            i.trim().parse().map_err(|_| bad())?,
            k.trim().parse().map_err(|_| bad())?,
        );
        Shard::new(i, k)
    }
}

/// What [`Parts::run_shard`] did.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ShardRun {
    /// The part was computed and written; it holds this many rows.
    Computed(usize),
    /// A valid part of this sweep was already there; nothing was computed.
    Present,
}

/// A sweep stored as parts: see [the module](self).
#[derive(Clone, Debug)]
pub struct Parts {
    dir: PathBuf,
    stem: String,
    count: usize,
    inputs: Vec<String>,
    results: Vec<String>,
    metadata: Vec<(String, String)>,
}

impl Parts {
    /// The sweep `stem` in `dir` (created if missing), split into `count` shards, with one input
    /// column `input` and one result column `result` until [`columns`](Parts::columns) names them.
    pub fn new(dir: impl AsRef<Path>, stem: &str, count: usize) -> Result<Self, PartError> {
        if count == 0 {
            return Err(PartError::ShardOutOfRange { index: 0, count });
        }
        let dir = dir.as_ref().to_owned();
        std::fs::create_dir_all(&dir).map_err(|source| PartError::Io {
            path: dir.clone(),
            source,
        })?;
        Ok(Parts {
            dir,
            stem: stem.to_owned(),
            count,
            inputs: vec!["input".into()],
            results: vec!["result".into()],
            metadata: Vec::new(),
        })
    }

    /// Names the columns: one per cell of an input, then one per cell of a result.
    pub fn columns(mut self, inputs: &[&str], results: &[&str]) -> Self {
        self.inputs = inputs.iter().map(|s| s.to_string()).collect();
        self.results = results.iter().map(|s| s.to_string()).collect();
        self
    }

    /// Adds a key–value pair to the metadata every part carries (the mechanism, the integrator
    /// and its settings): parts whose metadata differ are of different sweeps and never merged.
    pub fn metadata(mut self, key: &str, value: impl ToString) -> Self {
        self.metadata.push((key.to_owned(), value.to_string()));
        self
    }

    /// The number of shards.
    pub fn count(&self) -> usize {
        self.count
    }

    /// The file of shard `index`.
    pub fn path(&self, index: usize) -> PathBuf {
        let k = self.count;
        self.dir
            .join(format!("{}-part-{index:05}-of-{k:05}.parquet", self.stem))
    }

    fn names(&self) -> Vec<String> {
        self.inputs.iter().chain(&self.results).cloned().collect()
    }

    /// This sweep's metadata for shard `index` of a sweep of `len` inputs.
    fn metadata_of(&self, index: usize, len: usize) -> Vec<(String, String)> {
        let mut m = vec![
            ("lagrange.sweep".to_owned(), self.stem.clone()),
            ("lagrange.inputs".to_owned(), len.to_string()),
            (
                "lagrange.shard".to_owned(),
                format!("{index}/{}", self.count),
            ),
        ];
        m.extend(self.metadata.iter().cloned());
        m
    }

    fn check_columns<I: Cells, R: Cells>(&self) -> Result<(), PartError> {
        for (what, names, cells) in [
            ("inputs", self.inputs.len(), I::WIDTH),
            ("results", self.results.len(), R::WIDTH),
        ] {
            if names != cells {
                return Err(PartError::Columns { what, names, cells });
            }
        }
        Ok(())
    }

    /// Reads shard `index` and checks it against this sweep: the metadata, the index range and
    /// the inputs (bit for bit). Its result cells, row after row.
    fn read_checked<I: Cells>(
        &self,
        inputs: &[I],
        index: usize,
    ) -> Result<Vec<Option<f64>>, PartError> {
        let path = self.path(index);
        if !path.exists() {
            return Err(PartError::Missing { path });
        }
        let part = part_file::read(&path, &self.names())?;
        let foreign = |key: &str, expected: String, found: String| PartError::Foreign {
            path: path.clone(),
            key: key.to_owned(),
            expected,
            found,
        };
        let expected = self.metadata_of(index, inputs.len());
        for (key, value) in &expected {
            let found = part
                .metadata
                .iter()
                .find(|(k, _)| k == key)
                .map(|(_, v)| v.clone());
            if found.as_ref() != Some(value) {
                return Err(foreign(
                    key,
                    value.clone(),
                    found.unwrap_or_else(|| "(none)".into()),
                ));
            }
        }
        let range = shard_range(inputs.len(), index, self.count);
        let width = self.inputs.len() + self.results.len();
        let rows = part.cells.len() / width.max(1);
        if part.first != range.start || rows != range.len() {
            let found = format!("{}..{}", part.first, part.first + rows);
            return Err(foreign("rows", format!("{range:?}"), found));
        }
        let stored = part.cells.chunks(width.max(1));
        let mut results = Vec::with_capacity(rows * self.results.len());
        for (k, row) in range.clone().zip(stored) {
            let (input, result) = row.split_at(self.inputs.len());
            let mut given = Vec::with_capacity(I::WIDTH);
            inputs[k].write_cells(&mut given);
            let bits =
                |c: &[Option<f64>]| c.iter().map(|x| x.map(f64::to_bits)).collect::<Vec<_>>();
            if bits(input) != bits(&given) {
                return Err(foreign(
                    &format!("input {k}"),
                    format!("{given:?}"),
                    format!("{input:?}"),
                ));
            }
            results.extend_from_slice(result);
        }
        Ok(results)
    }

    /// Runs `shard` of the sweep over `inputs` with `run` (on every core, with a progress bar if
    /// `progress`) and writes its part, unless a valid part of this sweep is already there.
    ///
    /// A part that cannot be read (a truncated file) is computed again and replaced; a readable
    /// part of another sweep is an error, [`PartError::Foreign`], and is left untouched, as is
    /// everything for a shard of a different count ([`PartError::ShardOutOfRange`]).
    pub fn run_shard<I, R, F>(
        &self,
        inputs: &[I],
        shard: Shard,
        progress: bool,
        run: F,
    ) -> Result<ShardRun, PartError>
    where
        I: Cells + Sync,
        R: Cells + Send,
        F: Fn(&I) -> R + Sync,
    {
        self.check_columns::<I, R>()?;
        if shard.count != self.count {
            return Err(PartError::ShardOutOfRange {
                index: shard.index,
                count: self.count,
            });
        }
        match self.read_checked(inputs, shard.index) {
            Ok(_) => return Ok(ShardRun::Present),
            Err(PartError::Missing { .. } | PartError::Unreadable { .. }) => {}
            Err(e) => return Err(e),
        }
        let range = shard.range(inputs.len());
        let results = Sweep::new(inputs)
            .shard(range.clone())
            .progress(progress)
            .run(run);
        let mut cells = Vec::with_capacity(range.len() * (I::WIDTH + R::WIDTH));
        for (input, result) in inputs[range.clone()].iter().zip(&results) {
            input.write_cells(&mut cells);
            result.write_cells(&mut cells);
        }
        let part = PartData {
            first: range.start,
            cells,
            metadata: self.metadata_of(shard.index, inputs.len()),
        };
        part_file::write(&self.path(shard.index), &self.names(), &part)?;
        Ok(ShardRun::Computed(range.len()))
    }

    /// Runs every shard whose part is missing or unreadable, one after the other, each on every
    /// core; returns how many were computed. The first error stops it.
    pub fn run_missing<I, R, F>(
        &self,
        inputs: &[I],
        progress: bool,
        run: F,
    ) -> Result<usize, PartError>
    where
        I: Cells + Sync,
        R: Cells + Send,
        F: Fn(&I) -> R + Sync,
    {
        let mut computed = 0;
        for index in 0..self.count {
            let shard = Shard::new(index, self.count)?;
            if let ShardRun::Computed(_) = self.run_shard(inputs, shard, progress, &run)? {
                computed += 1;
            }
        }
        Ok(computed)
    }

    /// Reads every part and returns the results in input order. Every part must be there,
    /// readable, and of this sweep (metadata, rows and inputs checked); nothing is written.
    pub fn merge<I: Cells, R: Cells>(&self, inputs: &[I]) -> Result<Vec<R>, PartError> {
        self.check_columns::<I, R>()?;
        let mut cells = Vec::with_capacity(inputs.len() * R::WIDTH);
        for index in 0..self.count {
            cells.extend(self.read_checked(inputs, index)?);
        }
        cells_to_rows(&cells).ok_or_else(|| PartError::Unreadable {
            path: self.dir.clone(),
            reason: "a result cell that must be a number is null".into(),
        })
    }
}
