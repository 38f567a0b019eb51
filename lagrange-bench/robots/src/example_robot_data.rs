//! Five robots of the `example-robot-data` package, read from their URDF files at compile time.
//!
//! The files are not part of the repository: `scripts/peers/example_robots.py` copies them
//! from the package into `example-robot-data/` beside this crate's manifest, with the mimic
//! joints (and the joints they follow) locked and joint damping and friction removed, the same
//! files the peers read (see that script).
//!
//! | module | joints | robot |
//! |---|---:|---|
//! | `ur5` | 6 | UR5 arm |
//! | `panda` | 7 | Franka Panda, fingers locked |
//! | `solo12` | 12 | Solo12 quadruped: a tree |
//! | `anymal` | 12 | ANYmal C quadruped: a tree |
//! | `talos` | 30 | Talos humanoid, whole, grippers locked: a tree |

#[lagrange::urdf("example-robot-data/ur5.urdf")]
pub mod ur5 {}

#[lagrange::urdf("example-robot-data/panda.urdf")]
pub mod panda {}

#[lagrange::urdf("example-robot-data/solo12.urdf")]
pub mod solo12 {}

#[lagrange::urdf("example-robot-data/anymal.urdf")]
pub mod anymal {}

#[lagrange::urdf("example-robot-data/talos.urdf")]
pub mod talos {}
