//! Five synthetic fixed-base robots declared with `#[mechanism]`: the lagrange side of the peer
//! benchmark `scripts/peers/robots.sh` (binary `robots` of `lagrange-bench`).
//!
//! Each module is written by `scripts/peers/robots.py` from the same table as
//! `scripts/peers/robots/<name>.urdf`: rigid links placed by their joint frames, with a full
//! inertia tensor about an offset centre of mass, a constant roll-pitch-yaw rotation between
//! joints and one revolute joint each; `g` is the one parameter. A cargo feature per robot lets
//! the release build of one declaration be timed alone.
//!
//! | module | joints | shape |
//! |---|---:|---|
//! | `arm3` | 3 | serial arm, axes z, y, z |
//! | `arm7` | 7 | serial arm, axes z, y, z, y, … |
//! | `arm14` | 14 | two 7-joint arms in series |
//! | `quadruped` | 12 | fixed torso, four legs of three joints: a tree |
//! | `humanoid` | 30 | fixed pelvis, legs of six, a two-joint waist, arms of seven and a two-joint head: a tree |
//!
//! With the feature `example-robot-data`, the module of that name holds five real robots read from
//! their URDF files by `#[lagrange::urdf]`.

#[cfg(feature = "arm3")]
include!("arm3.rs");
#[cfg(feature = "arm7")]
include!("arm7.rs");
#[cfg(feature = "arm14")]
include!("arm14.rs");
#[cfg(feature = "quadruped")]
include!("quadruped.rs");
#[cfg(feature = "humanoid")]
include!("humanoid.rs");
#[cfg(feature = "example-robot-data")]
pub mod example_robot_data;
