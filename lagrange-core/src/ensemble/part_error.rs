//! Why a part of a sweep could not be run, read or merged.

use std::path::PathBuf;

/// Why a part could not be run, read or merged.
#[derive(Debug, thiserror::Error)]
pub enum PartError {
    /// A shard index at or past the shard count, or a count of zero.
    #[error("shard {index} of {count} does not exist (shards are numbered 0 to count − 1)")]
    ShardOutOfRange {
        /// The index asked for.
        index: usize,
        /// The shard count.
        count: usize,
    },
    /// A shard written as something other than `I/K`.
    #[error("`{0}` is not a shard: write it as INDEX/COUNT, e.g. 0/4")]
    BadShard(String),
    /// The column names do not match the cells of the inputs and results.
    #[error("{names} column names for {cells} cells ({what})")]
    Columns {
        /// Inputs or results.
        what: &'static str,
        /// How many names were given.
        names: usize,
        /// How many cells the type has.
        cells: usize,
    },
    /// A file system error.
    #[error("{path}: {source}")]
    Io {
        /// The file.
        path: PathBuf,
        /// The error.
        source: std::io::Error,
    },
    /// A part that is not a readable Parquet file of its sweep's shape (truncated, say).
    #[error("{path} is not a readable part: {reason}")]
    Unreadable {
        /// The file.
        path: PathBuf,
        /// What is wrong with it.
        reason: String,
    },
    /// A part of another sweep: its metadata, columns or inputs differ from this sweep's.
    #[error("{path} belongs to another sweep: {key} is `{found}`, this sweep's is `{expected}`")]
    Foreign {
        /// The file.
        path: PathBuf,
        /// What differs.
        key: String,
        /// This sweep's value.
        expected: String,
        /// The part's value.
        found: String,
    },
    /// A part that has not been computed.
    #[error("{path} is missing: run its shard first")]
    Missing {
        /// The file.
        path: PathBuf,
    },
}
