//! The gallery: every scene, simulated and printed against its closed form, with plots written to
//! `plots/` (or `$LAGRANGE_PLOTS`). Exits non-zero if any check fails.
//!
//! A binary of this crate rather than an example of `lagrange`, so that building it builds only
//! `lagrange` and its normal dependencies, not the root package's test and benchmark
//! dev-dependencies. The scenes themselves stay in `examples/`, each runnable alone.
//!
//! ```text
//! cargo run --release -p lagrange-gallery
//! ```

#[path = "../../examples/atwood.rs"]
mod atwood;
#[path = "../../examples/breathing_ellipse.rs"]
mod breathing_ellipse;
#[path = "../../examples/cartesian_pendulum.rs"]
mod cartesian_pendulum;
#[path = "../../examples/four_bar.rs"]
mod four_bar;
#[path = "../../examples/gyroscope.rs"]
mod gyroscope;
#[path = "../../examples/hoop_bifurcation.rs"]
mod hoop_bifurcation;
#[path = "../../examples/pendulum.rs"]
mod pendulum;
#[path = "../../examples/ramp.rs"]
mod ramp;
#[path = "../../examples/rigid_triangle.rs"]
mod rigid_triangle;
#[path = "../../examples/rolling_wheel.rs"]
mod rolling_wheel;
#[path = "../../examples/rough_ramp.rs"]
mod rough_ramp;
#[path = "../../examples/rough_wedge.rs"]
mod rough_wedge;
#[path = "../../examples/small_oscillations.rs"]
mod small_oscillations;
#[path = "../../examples/sphere_release.rs"]
mod sphere_release;
#[path = "../../examples/wedge_block.rs"]
mod wedge_block;

// These two scenes are loaded once, as the mechanisms the statics scenes analyse.
use hoop_bifurcation::scene as spinning_hoop;
use small_oscillations::scene as double_pendulum;

use lagrange_gallery::{plots_dir, table, Check};
use std::path::Path;

/// Every scene, in the order the README lists them.
pub const SCENES: &[fn(&Path) -> Vec<Check>] = &[
    wedge_block::run,
    ramp::run,
    breathing_ellipse::run,
    spinning_hoop::run,
    pendulum::run,
    double_pendulum::run,
    rigid_triangle::run,
    atwood::run,
    hoop_bifurcation::run,
    small_oscillations::run,
    sphere_release::run,
    rolling_wheel::run,
    four_bar::run,
    cartesian_pendulum::run,
    rough_ramp::run,
    rough_wedge::run,
    gyroscope::run,
    lagrange_gallery::scenes::rough_plane::run,
    lagrange_gallery::scenes::pushed_block::run,
];

fn main() {
    let plots = plots_dir();
    let checks: Vec<Check> = SCENES.iter().flat_map(|run| run(&plots)).collect();
    println!();
    print!("{}", table(&checks));
    let failed = checks.iter().filter(|c| !c.passed()).count();
    println!(
        "\n{} checks, {} failed; plots in {}",
        checks.len(),
        failed,
        plots.display()
    );
    if failed > 0 {
        std::process::exit(1);
    }
}
