//! The modes, by topic: each a function of the number of calls `n` (and, for those on a generated
//! mechanism, of the path its prefix picks) returning the number `main` prints.

pub mod accelerations;
pub mod arms;
pub mod chains;
pub mod closed_forms;
pub mod constrained;
pub mod contacts;
pub mod squeezer;
pub mod steps;
