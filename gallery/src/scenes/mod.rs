//! The scenes the gallery prints and the tests assert: each declares its mechanism, simulates it and
//! returns its [`Check`](crate::Check)s against closed forms (`run`), with the tolerance argued from
//! the method's error next to each check.

pub mod rough_plane;
pub mod pushed_block;
