//! The scenes the gallery prints and the tests assert: each declares its mechanism, simulates it and
//! returns its [`Check`](crate::Check)s against closed forms (`run`), with the tolerance argued from
//! the method's error next to each check.

pub mod atwood;
pub mod breathing_ellipse;
pub mod cartesian_pendulum;
pub mod computed_torque;
pub mod double_pendulum;
pub mod four_bar;
pub mod gyroscope;
pub mod hoop_bifurcation;
pub mod identify_pendulum;
pub mod pendulum;
pub mod pushed_block;
pub mod ramp;
pub mod rigid_triangle;
pub mod rolling_wheel;
pub mod rough_plane;
pub mod rough_ramp;
pub mod rough_wedge;
pub mod small_oscillations;
pub mod spatial_arm;
pub mod sphere_release;
pub mod spinning_hoop;
pub mod tumbling_body;
pub mod wedge_block;
